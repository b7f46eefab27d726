#!/usr/bin/python3
"""Writes the resolution variants of the validation scenes (validation/scenes/<base>_<tag>.toml).

A variant is its base scene with another dx (and, where the nightly budget asks for it, another end time);
the header says which. Run after editing a base scene: /usr/bin/python3 validation/make_variants.py
The generated files are committed so that `sph run` needs no generator.
"""
import math
import re
import textwrap
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
    ("two_fluids_lid", "dx0.001", 0.001, None, "the paper's printed dx = 0.001 m"),
    ("two_fluids_rho1050", "dx0.006", 0.006, None, "quick tier: H/dx = 10"),
    ("two_fluids_rho1050", "dx0.0015", 0.0015, None, "H/dx = 40"),
    ("two_fluids_rho1050", "dx0.00075", 0.00075, None,
     "H/dx = 80: the named model's light front converges slowly (errors 0.35, 0.22, 0.12 at H/dx 10, 20, 40)"),
    ("spheric_dam_break", "dx0.08", 0.08, 0.6, "quick smoke test: the front reaches the box (P1 wets at 0.47 s), seconds of 2 cores"),
    ("spheric_dam_break", "dx0.02", 0.02, 1.0,
     "twice the resolution; to 1.0 s (the arrivals, the impact on the box and the wall, H1 wetting) for the nightly "
     "budget"),
]
# The named model (issue 31): every validation case also runs with it, at each resolution the matrix
# runs the paper's model at, as <scene>_named. It is the paper's model with two changes, the ones the tank at rest
# needs (verification/README.md, "The tank at rest with density diffusion"; verification/flows/TankAtRest.hpp):
# Fourtakas et al. (2019) density diffusion, delta = 0.1, and the Wendland C2 kernel at h/dx = 2. With them a tank
# at rest keeps max|u| / sqrt(gH) <= 0.004 and its bottom pressure within 0.73 % (the bars 0.01 and 1 %), where the
# paper's model reaches 0.18 and 55 %. In the two-fluid scenes the diffusion acts within each phase
# (terms/DensityDiffusionFourtakasPhases.hpp). There the kernel is what moves the fronts: the near-Boussinesq lock
# exchange at H/dx 20 runs at front Froude numbers 0.21 (heavy) and 0.33 (light) with the paper's quadratic kernel
# at h/dx 1.33 and 0.47 and 0.42 with Wendland at h/dx 2 (theory 0.5); Wendland without diffusion is stopped by the
# energy check at H/dx 40 (t = 0.62 s).
# No particle shifting: measured at the quick tier's resolutions (validate.py, named model alone / + lind /
# + delta_plus), shifting delays the dam break's front: wall-impact time error 0.026 / 0.093 / 0.109 at H/dx 10 and
# 0.013 / 0.098 / 0.100 at Lobovsky's H/dx 15, against the 10 % band. delta_plus holds the drop's walls (wall
# reflections 5 / 9 / 0; the paper's model 16) and Martin & Moyce's column at the wall (height RMS 0.25 / 0.22 /
# 0.027; paper 0.065), but raises the Lobovsky sensor-2 impulse (4.07 / 3.61 / 4.58; experiment band 2.17-3.12) and
# costs 2.2 times as much (drop: 5.9 / 11.4 / 13.3 s). At the paper's resolutions (named alone / + delta_plus;
# the paper's model in brackets) delta_plus loses on every count measured: dam break volume 0.26 % / 0.39 % (0.23 %,
# bar 0.3 %), onset error 0.037 / 0.087 (0.044), wall reflections 68 / 35 (98); Lobovsky impulse 3.79 / 4.78 (3.74);
# drop wall reflections 68 / 1452 (50). (Martin & Moyce's a/dx 10 height is a probe artifact: the column_height
# window x = 0.003429 m is 0.6 dx there, 1.2 dx at the paper's a/dx 20; with 1.2 dx at a/dx 10 both models pass the
# table's 1/18, paper 0.014, named 0.019.)
# SPHERIC test 2 runs it at the paper's model's three resolutions, dx 0.04 to 2 s and dx 0.02 to 1 s (h/dx 2 in 3-D
# costs (2/1.33)^3 = 3.4 times the paper's model a step: 1,648 s of one core at dx 0.02), and as the smoke run.
# h/dx 1.33 would be cheaper and its thinner front arrives sooner (dx 0.02: H2 +3.6 %, P1 +4.2 % against +5.1 % and
# +5.1 % at h/dx 2; measured 2026-12-06), but Wendland C2 at h/dx 1.33 does not hold a tank at rest: 2-D H/dx 20,
# bottom pressure 1.5 % (1:1) and max|u| 0.024 sqrt(gH) (4:1); 3-D 1:1:1 H/dx 20, max|u| 0.036 sqrt(gH) (the lattice
# gives way at t sqrt(g/H) = 8; tank_at_rest_study).
# Resolutions the named model alone runs at: the paper's model at H/dx 80 in the 1000/1050 lock exchange is stopped
# by the energy check at t = 0.586 s (its two-fluid scenes have beta = 0: nothing damps the step's oscillations;
# measured 2026-12-07), so it has no scene there.
NAMED_ONLY = {("two_fluids_rho1050", "dx0.00075")}
NAMED = [  # (base, resolution tag or None for the base scene itself, end time or None for the resolution's)
    ("dam_break", "dx0.025", None), ("dam_break", None, None), ("dam_break", "dx0.005", None),
    ("dam_break_lobovsky", "dx0.02", None), ("dam_break_lobovsky", None, None), ("dam_break_lobovsky", "dx0.005", None),
    ("martin_moyce", "a10", None), ("martin_moyce", None, None), ("martin_moyce", "a40", None),
    ("drop_into_pool", "dx0.002", None), ("drop_into_pool", None, None), ("drop_into_pool", "dx0.0005", None),
    ("spheric_dam_break", "dx0.08", None), ("spheric_dam_break", None, 2.0), ("spheric_dam_break", "dx0.02", None),
    ("two_fluids", "dx0.003", None), ("two_fluids", None, None), ("two_fluids", "dx0.001", None),
    ("two_fluids_lid", None, None), ("two_fluids_lid", "dx0.001", None),
    ("two_fluids_rho1050", "dx0.006", None), ("two_fluids_rho1050", None, None),
    ("two_fluids_rho1050", "dx0.0015", None), ("two_fluids_rho1050", "dx0.00075", None),
]
NAMED_WHY = ("the named model: the paper's model + Fourtakas et al. (2019) density diffusion (delta 0.1) + the "
             "Wendland C2 kernel at h/dx 2, which hold a tank at rest where the paper's model does not "
             "(verification/README.md: max|u|/sqrt(gH) 0.0038 against 0.18, bottom pressure 0.73 % against 55 %)")
NAMED_PHASES_WHY = ("with several phases, Colagrossi & Landrini's (2003) pair: the continuity equation by volume "
                    "and the pressure gradient that conserves energy with it; across an interface eq. (11) weighs "
                    "the other phase by its density ratio (validation/README.md: the lid's light phase volume "
                    "0.097 % against 0.27 % at H/dx 40)")
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
    return text


def drop_start(scene: dict, dx: float) -> tuple:
    """Centre height and speed of the drop: lowest point `gap` above the pool's surface, speed such that it
    reaches the surface at DROP_IMPACT_SPEED (free fall over the gap). The pool's surface (the top of the first
    [[fluid]] block), the drop's radius (the circle block) and g come from the base scene."""
    pool = next(b for b in scene["fluid"] if b.get("shape", "rectangle") == "rectangle")
    drop = next(b for b in scene["fluid"] if b.get("shape") == "circle")
    g = math.hypot(*scene["physics"]["gravity"])
    # The smallest whole number of dx that keeps the drop's particles beyond the kernel's support 2h of the pool's
    # (their centres are gap + dx apart): 2 dx at h/dx 1.33 (3 dx > 2.66 dx), 4 dx at h/dx 2 (5 dx > 4 dx).
    gap = math.floor(2 * scene["numerics"]["h_over_dx"]) * dx
    return pool["upper"][1] + gap + drop["radius"], math.sqrt(DROP_IMPACT_SPEED**2 - 2 * g * gap)


def named_model(text: str) -> str:
    """The scene with the named model's kernel, h/dx and density diffusion (NAMED above), and with several
    phases Colagrossi & Landrini's pair (NAMED_PHASES_WHY)."""
    physics = 'variable_h = true\ndensity_diffusion = 0.1\ndensity_diffusion_form = "fourtakas"'
    if len(tomllib.loads(text)["phase"]) > 1:
        physics += '\ncontinuity_form = "colagrossi_landrini"'
    for pattern, new in ((r'^kernel = ".*"$', 'kernel = "wendland_c2"'), (r"^h_over_dx = .*$", "h_over_dx = 2.0"),
                         (r"^variable_h = true$", physics)):
        text, n = re.subn(pattern, new, text, count=1, flags=re.M)
        if n != 1:
            raise ValueError(f"named model: no line matches {pattern!r}")
    return text


def variant(base: str, tag: str, dx: float, end, why: str, named: bool = False) -> str:
    text = (SCENES / f"{base}.toml").read_text()
    if named:
        text = named_model(text)
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
            + "".join(f"# {line}\n" for line in textwrap.wrap(f"Variant {tag}: dx = {dx:g} m; {why}.",
                                                                 114 if named else 10**6)))
    return head + text


def main():
    for base, tag, dx, end, why in VARIANTS:
        if (base, tag) not in NAMED_ONLY:
            (SCENES / f"{base}_{tag}.toml").write_text(variant(base, tag, dx, end, why))
    resolutions = {(base, tag): (dx, end, why) for base, tag, dx, end, why in VARIANTS}
    for base, tag, end_time in NAMED:
        if tag is None:
            dx = tomllib.loads((SCENES / f"{base}.toml").read_text())["numerics"]["dx"]
            name, end = "named", None
            why = "H/dx = 20 (the paper has no such case)" if base == "two_fluids_rho1050" else "the paper's resolution"
        else:
            dx, end, why = resolutions[(base, tag)]
            name = f"{tag}_named"
        if end_time is not None:
            end, why = end_time, f"{why}; to {end_time:g} s for the nightly budget"
        why = f"{why}; {NAMED_WHY}"
        if base.startswith("two_fluids"):
            why = f"{why}; {NAMED_PHASES_WHY}"
        (SCENES / f"{base}_{name}.toml").write_text(variant(base, name, dx, end, why, named=True))


if __name__ == "__main__":
    main()
