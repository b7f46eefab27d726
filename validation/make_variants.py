#!/usr/bin/python3
"""Writes the resolution variants of the validation scenes (validation/scenes/<base>_<tag>.toml).

A variant is its base scene with another dx (and, where the nightly budget asks for it, another end time);
the header says which. Run after editing a base scene: /usr/bin/python3 validation/make_variants.py
The generated files are committed so that `sph run` needs no generator.
"""
import math
import re
import tomllib
from pathlib import Path

SCENES = Path(__file__).resolve().parent / "scenes"
# Lobovsky & Kren (2008), section 3, Fig. 4: the drop hits the pool at 2 m/s (drop_into_pool.toml's header).
DROP_IMPACT_SPEED = 2.0

# (base, tag, dx, end_time or None, why)
VARIANTS = [
    ("dam_break", "dx0.025", 0.025, None, "quick tier: H/dx = 10 (0.02 m does not divide H = 0.25 m)"),
    ("dam_break", "dx0.005", 0.005, 0.6,
     "twice the paper's resolution; to 0.6 s (front at the wall, impact and run-up) for the nightly budget"),
    ("dam_break_lobovsky", "dx0.02", 0.02, None, "quick tier: H/dx = 15"),
    ("dam_break_lobovsky", "dx0.005", 0.005, None, "H/dx = 60"),
    ("martin_moyce", "a10", 0.005715, None, "quick tier: a/dx = 10"),
    ("martin_moyce", "a40", 0.00142875, None, "a/dx = 40"),
    ("drop_into_pool", "dx0.002", 0.002, None, "quick tier: half the paper's resolution"),
    ("drop_into_pool", "dx0.0005", 0.0005, 0.033,
     "twice the paper's resolution; to the paper's frame at 0.033 s for the nightly budget"),
    ("two_fluids", "dx0.003", 0.003, None, "quick tier: H/dx = 20"),
    ("two_fluids", "dx0.001", 0.001, None, "the paper's printed dx = 0.001 m (7200 particles, not 3200)"),
    ("two_fluids_rho1050", "dx0.006", 0.006, None, "quick tier: H/dx = 10"),
    ("two_fluids_rho1050", "dx0.0015", 0.0015, None, "H/dx = 40"),
    ("spheric_dam_break", "dx0.08", 0.08, 0.6, "quick smoke test: the front reaches the box (P1 wets at 0.47 s), seconds of 2 cores"),
    ("spheric_dam_break", "dx0.02", 0.02, 1.0,
     "twice the resolution; to 1.0 s (the arrivals, the impact on the box and the wall, H1 wetting) for the nightly "
     "budget"),
    ("spheric_dam_break", "wendland", 0.04, 2.0,
     "the named model of the tank-at-rest study (verification/flows/TankAtRest.hpp): paper + Fourtakas delta 0.1, "
     "Wendland C2 at h/dx 2; to 2 s for the nightly budget"),
]
# SPHERIC test 2 (spheric_dam_break.toml): the experiment's column, 1.228 long and 0.55 deep against the tank's
# far wall x = 3.22, on the lattice nearest it (whole numbers of dx, so that N dx^3 is the column's volume).
SPHERIC_COLUMN = (3.22, 1.228, 0.55)
SPHERIC_SERIES_DX = 0.04  # series_every = 3 there (~1 ms, the experiment's sampling); scaled with dx


def spheric(text: str, tag: str, dx: float) -> str:
    wall, length, depth = SPHERIC_COLUMN
    lo, hi = wall - round(length / dx) * dx, round(depth / dx) * dx
    text = re.sub(r"^lower = \[1\.98, 0\.0, 0\.0\]$", f"lower = [{lo:.6g}, 0.0, 0.0]", text, count=1, flags=re.M)
    text = re.sub(r"^upper = \[3\.22, 1\.0, 0\.56\]$", f"upper = [3.22, 1.0, {hi:.6g}]", text, count=1, flags=re.M)
    every = max(1, round(3 * SPHERIC_SERIES_DX / dx))
    text = re.sub(r"^series_every = .*$", f"series_every = {every}", text, count=1, flags=re.M)
    if tag == "wendland":
        text = re.sub(r'^kernel = ".*"$', 'kernel = "wendland_c2"', text, count=1, flags=re.M)
        text = re.sub(r"^h_over_dx = .*$", "h_over_dx = 2.0", text, count=1, flags=re.M)
        text = re.sub(r"^variable_h = true$", 'variable_h = true\ndensity_diffusion = 0.1\n'
                      'density_diffusion_form = "fourtakas"', text, count=1, flags=re.M)
    return text


def drop_start(scene: dict, dx: float) -> tuple:
    """Centre height and speed of the drop: lowest point 2 dx above the pool's surface, speed such that it
    reaches the surface at DROP_IMPACT_SPEED (free fall over 2 dx). The pool's surface (the top of the first
    [[fluid]] block), the drop's radius (the circle block) and g come from the base scene."""
    pool = next(b for b in scene["fluid"] if b.get("shape", "rectangle") == "rectangle")
    drop = next(b for b in scene["fluid"] if b.get("shape") == "circle")
    g = math.hypot(*scene["physics"]["gravity"])
    gap = 2 * dx
    return pool["upper"][1] + gap + drop["radius"], math.sqrt(DROP_IMPACT_SPEED**2 - 2 * g * gap)


def variant(base: str, tag: str, dx: float, end, why: str) -> str:
    text = (SCENES / f"{base}.toml").read_text()
    name = f"{base}_{tag}"
    text = re.sub(r'^name = ".*"$', f'name = "{name}"', text, count=1, flags=re.M)
    text = re.sub(r"^dx = .*$", f"dx = {dx:g}", text, count=1, flags=re.M)
    if end is not None:
        text = re.sub(r"^end_time = .*$", f"end_time = {end:g}", text, count=1, flags=re.M)
    if base == "spheric_dam_break":
        text = spheric(text, tag, dx)
    if base == "drop_into_pool":
        y, v = drop_start(tomllib.loads(text), dx)
        text = re.sub(r"^center = .*$", f"center = [0.06, {y:.6g}]", text, count=1, flags=re.M)
        text = re.sub(r"^velocity = \[0.0, -.*\]$", f"velocity = [0.0, -{v:.6g}]", text, count=1, flags=re.M)
    head = (f"# GENERATED by validation/make_variants.py from {base}.toml: edit that file and re-run the script.\n"
            f"# Variant {tag}: dx = {dx:g} m; {why}.\n")
    return head + text


def main():
    for base, tag, dx, end, why in VARIANTS:
        (SCENES / f"{base}_{tag}.toml").write_text(variant(base, tag, dx, end, why))


if __name__ == "__main__":
    main()
