#!/usr/bin/python3
"""Stability sweeps (issue 8): run scene variants across a parameter and classify each run.

Outcome of a run (reports/SCHEMA.md run-file attributes):
  unstable    the solver stopped it (status "unstable"; its failure_cause is kept);
  inaccurate  it ran to the end but broke the case's figure of merit;
  stable      otherwise.
Figures of merit: dam break, volume variation above the paper's 0.3 % (Lobovsky & Kren, section 3);
tank at rest, final max|u| above 0.05 sqrt(gH) (our threshold: a tank at rest whose spurious currents
reach 5 % of the gravity-wave speed is not at rest; the packing paper reports ~0.1 sqrt(gH) at
t sqrt(g/H) = 10 from a Cartesian start near sloping walls, so it separates that level from rest).

Known failure modes, each from a small scene of its own:
  tensile instability  closed box (closed_box.toml.in) with the background pressure p0 setting the sign of
                       p: clumping when the smallest particle distance of the final state is below dx/2
                       (a lattice has dx; clumped pairs measured here sit at 0.05-0.08 dx, an intact
                       Wendland lattice at 0.99 dx);
  wall penetration     block thrown at a wall (block_impact.toml.in): the solver's wall_penetration, or any
                       particle that ended a step beyond the wall and was reflected back (wall_reflections);
  packing              Cartesian against packed start of Monaghan's elliptical drop (elliptical_drop.toml.in):
                       inaccurate when a semi-axis is off the ODE by more than 1 % at t A0 = 0.76 (our
                       threshold; the tests measure 1.3 % Cartesian and 0.3 % packed with Wendland); the
                       ODE's solution is the C++ one the tests use (the tool elliptical_drop_ode);
  high-Mach density    the same impact: max |rho/rho0 - 1| above 1 %, the density variation that the
                       c0 >= 10 max|v| rule is chosen to keep (Monaghan 1994).

Usage: sweep.py --sph BIN --out DIR [--sweep NAME ...] [--jobs 2] [--drop-ode BIN]
Writes DIR/<sweep>.json in the report's stability format and prints a table. --drop-ode (default: the build tree's
verification/flows/elliptical_drop_ode beside BIN's solver/) is needed by the elliptical-drop sweep only.
Run files are read with reports/runfile.py, and rho0, g and the scene's parameters are taken from them or, before
a run, from the filled template; the numbers here are the swept settings and the thresholds.
"""
import argparse
import concurrent.futures
import json
import math
import subprocess
import sys
import tempfile
import tomllib
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent.parent / "reports"))
from runfile import read_run  # noqa: E402  (the one run-file reader)

KERNELS = ["quadratic", "cubic_spline", "wendland_c2"]
# The paper's dam break: c0 = 24.4 m/s, beta = 1, h = 1.33 dx, CFL 0.25 (Morris et al. 1997).
BASE = dict(c0=24.4, beta=1.0, variable_h="true", kernel="quadratic", dx=0.02, h_over_dx=1.33,
            cfl=0.25, cfl_force=0.25, end_time=0.8, p0=0.0, initial="lattice", packing="",
            integrator="predictor_corrector", delta=0.0)
# The time integrators (solver/SCENES.md, [numerics] integrator): the paper's first.
INTEGRATORS = ["predictor_corrector", "position_verlet", "velocity_verlet"]


def template_scene(template: str, **params) -> dict:
    """The scene a template gives with BASE and `params` filled in, parsed: where the sweeps take the templates'
    fixed parameters (rho0, g, the block's size and speed) from."""
    return tomllib.loads((HERE / f"{template}.toml.in").read_text().format(**dict(BASE, name=template, **params)))


def gravity(scene: dict) -> float:
    """|g| of a scene's [physics] gravity (zero when the scene has none)."""
    return math.hypot(*scene.get("physics", {}).get("gravity", [0.0]))


def block_height(scene: dict, k: int = 0) -> float:
    """Height of the scene's k-th [[fluid]] rectangle [m]."""
    b = scene["fluid"][k]
    return float(b["upper"][1] - b["lower"][1])


def sweeps():
    """name -> (template, x label, y label, list of (x, y, parameters), y axis): the y axis is a list of
    category labels (y is their index), None (y is the volume variation in %), or the name of a result
    field plotted as y."""
    out = {}
    cfls = [0.1, 0.25, 0.4, 0.6, 0.8, 1.0, 1.3, 1.6]
    for case in ("dam_break", "hydrostatic_tank"):
        pts = [(c, k, dict(cfl=c, kernel=kern, end_time=0.8 if case == "dam_break" else 1.0))
               for c in cfls for k, kern in enumerate(KERNELS)]
        out[f"cfl_acoustic_{case}"] = (case, "acoustic CFL factor (Morris 1997: 0.25)", "kernel", pts, KERNELS)
    # The same tank at rest to 4 s (t sqrt(g/H) = 25), at and below the Morris CFL: Heun's step amplifies an
    # undamped oscillation a little every step, and at 0.25 the tank's energy grows after about 2 s with
    # Wendland and the cubic spline even with beta = 1 (the energy check stops such a run).
    out["cfl_acoustic_long_hydrostatic_tank"] = (
        "hydrostatic_tank", "acoustic CFL factor, tank at rest to 4 s", "kernel",
        [(c, k, dict(cfl=c, kernel=kern, end_time=4.0)) for c in (0.1, 0.15, 0.2, 0.25)
         for k, kern in enumerate(KERNELS)], KERNELS)
    # Each integrator with each kernel (issue 31): the acoustic CFL at which each stops working.
    pairs = [(i, k) for i in INTEGRATORS for k in KERNELS]
    labels = [f"{i}, {k}" for i, k in pairs]
    out["cfl_acoustic_integrators_dam_break"] = (
        "dam_break", "acoustic CFL factor (Morris 1997: 0.25)", "integrator, kernel",
        [(c, y, dict(cfl=c, integrator=i, kernel=k)) for c in cfls for y, (i, k) in enumerate(pairs)], labels)
    out["cfl_acoustic_integrators_long_hydrostatic_tank"] = (
        "hydrostatic_tank", "acoustic CFL factor, tank at rest to 4 s", "integrator, kernel",
        [(c, y, dict(cfl=c, integrator=i, kernel=k, end_time=4.0)) for c in (0.1, 0.15, 0.2, 0.25, 0.4)
         for y, (i, k) in enumerate(pairs)], labels)
    # CFL x density diffusion (Molteni & Colagrossi 2009 delta) for each integrator, Wendland C2 at h/dx 2.
    deltas = [0.0, 0.05, 0.1, 0.2]
    for integ in INTEGRATORS:
        out[f"cfl_delta_{integ}_long_hydrostatic_tank"] = (
            "hydrostatic_tank", f"acoustic CFL factor, tank at rest to 4 s, {integ}", "density diffusion delta",
            [(c, y, dict(cfl=c, delta=d, integrator=integ, kernel="wendland_c2", h_over_dx=2.0, end_time=4.0))
             for c in (0.1, 0.2, 0.25, 0.4, 0.6) for y, d in enumerate(deltas)], [str(d) for d in deltas])
    # CFL x artificial viscosity beta (eq. 10) and CFL x h/dx for each integrator: the dam break with the paper's
    # kernel for beta (the impact is where beta works), the tank at rest to 4 s with Wendland C2 for h/dx (the
    # named model's kernel; h/dx sets how many neighbours damp the lattice's modes).
    for integ in INTEGRATORS:
        few_betas = [0.0, 0.25, 1.0, 2.0]
        out[f"cfl_beta_{integ}_dam_break"] = (
            "dam_break", f"acoustic CFL factor, {integ}", "artificial viscosity beta",
            [(c, y, dict(cfl=c, beta=b, integrator=integ)) for c in (0.1, 0.25, 0.4, 0.6, 1.0)
             for y, b in enumerate(few_betas)], [str(b) for b in few_betas])
        ratios = [1.33, 1.5, 2.0, 2.5]
        out[f"cfl_h_over_dx_{integ}_long_hydrostatic_tank"] = (
            "hydrostatic_tank", f"acoustic CFL factor, tank at rest to 4 s, {integ}", "h/dx",
            [(c, y, dict(cfl=c, h_over_dx=r, integrator=integ, kernel="wendland_c2", end_time=4.0))
             for c in (0.1, 0.2, 0.25, 0.4) for y, r in enumerate(ratios)], [str(r) for r in ratios])
    betas = [0.0, 0.1, 0.25, 0.5, 1.0, 1.5, 2.0]
    out["beta_dam_break"] = ("dam_break", "artificial viscosity beta (paper: 1)", "kernel",
                             [(b, k, dict(beta=b, kernel=kern)) for b in betas for k, kern in enumerate(KERNELS)],
                             KERNELS)
    ratios = [1.0, 1.2, 1.33, 1.5, 1.75, 2.0]
    out["h_over_dx_hydrostatic_tank"] = (
        "hydrostatic_tank", "h/dx", "kernel",
        [(r, k, dict(h_over_dx=r, kernel=kern, end_time=1.0)) for r in ratios
         for k, kern in enumerate(["quadratic", "wendland_c2"])], ["quadratic", "wendland_c2"])
    dam = template_scene("dam_break")
    vmax = math.sqrt(2 * gravity(dam) * block_height(dam))  # free-fall speed over the column height
    mults = [3, 5, 7, 10, 14, 20]
    out["mach_dam_break"] = ("dam_break", "c0 / sqrt(2 g H)", "max volume variation [%]",
                             [(m, None, dict(c0=round(m * vmax, 4))) for m in mults], None)
    out["variable_h_dam_break"] = ("dam_break", "variable h (0 off, 1 on)", "kernel",
                                   [(v, k, dict(variable_h="true" if v else "false", kernel=kern))
                                    for v in (0, 1) for k, kern in enumerate(KERNELS)], KERNELS)
    # Cartesian against packed start (solver/SCENES.md, initial = "packed") on a free-surface drop: a
    # rectangle's lattice closed by its layers or mirror walls is already packed (grad Gamma = 0), so
    # the drop is where packing can matter (Colagrossi et al. 2012, section 3.4).
    packing = "[fluid.packing]\nalpha = 5e-3\nmax_iterations = 4000\n"
    out["initial_particles_elliptical_drop"] = (
        "elliptical_drop", "initial particles (0 Cartesian lattice, 1 packed)", "kernel",
        [(i, k, dict(initial=init, kernel=kern, h_over_dx=2.0, packing=packing if init == "packed" else ""))
         for i, init in enumerate(("lattice", "packed")) for k, kern in enumerate(KERNELS)], KERNELS)
    box = template_scene("closed_box")
    rho_g_box = box["phase"][0]["rho0"] * gravity(box) * block_height(box)  # hydrostatic p at the bottom [Pa]
    out["tensile_instability_closed_box"] = (
        "closed_box", "p0 / (rho0 g H)   (p < 0 everywhere below -1)", "kernel",
        [(r, k, dict(p0=round(r * rho_g_box, 3), kernel=kern, c0=20.0, beta=0.1, variable_h="false", dx=0.01,
                     end_time=1.0))
         for r in (-2.0, -1.0, -0.5, 0.0, 0.5, 1.0, 2.0) for k, kern in enumerate(KERNELS)], KERNELS)
    machs = [0.01, 0.02, 0.05, 0.1, 0.2, 0.4, 0.8]
    impact_speed = math.hypot(*template_scene("block_impact")["fluid"][0]["velocity"])  # [m/s]
    impact = [(m, b, dict(c0=round(impact_speed / m, 4), beta=b, variable_h="false", dx=0.005, end_time=0.075))
              for m in machs for b in (0.0, 1.0)]
    out["wall_penetration_block_impact"] = ("block_impact", "impact Mach number U / c0", "artificial viscosity beta",
                                            impact, None)
    out["high_mach_density_block_impact"] = ("block_impact", "impact Mach number U / c0 (beta 0 and 1)",
                                             "max |rho/rho0 - 1| [%]", impact, "density_error_pct")
    return out


def min_pair_distance(positions):
    """Smallest distance between two particles (O(N^2); the failure-mode scenes have a few hundred)."""
    import numpy as np
    d2 = ((positions[:, None, :] - positions[None, :, :]) ** 2).sum(-1)
    np.fill_diagonal(d2, np.inf)
    return float(np.sqrt(d2.min()))


def drop_ode(tool, A0: float, R: float, t: float) -> tuple:
    """Semi-axes (a, b) of Monaghan's (1994) drop at t, from verification/flows/EllipticalDropOde.hpp (GSL rk8pd,
    the solution the GoogleTest cases use and check) through its tool. Why the tool and not a Python solver
    (a hand-written RK4 was here; scipy's solve_ivp would do): either is a second solution of the same ODE that
    nothing checks against the first, and scipy a dependency for one ODE; the tool keeps one."""
    proc = subprocess.run([str(tool), repr(A0), repr(R), repr(t)], capture_output=True, text=True, timeout=60)
    if proc.returncode != 0:
        raise RuntimeError(f"{tool}: {proc.stderr.strip()}")
    header, line = proc.stdout.split()[:2]
    row = dict(zip(header.split(","), map(float, line.split(","))))
    return row["a"], row["b"]


def semi_axis_error(x, volume, ode_axes):
    """max |a/a_ode - 1|, |b/b_ode - 1| with a = 2 sqrt(<x^2>) about the centroid, volume-weighted (a uniform
    ellipse has <x^2> = a^2/4), as verification/flows/EllipticalDrop*.cpp measure it."""
    w = volume / volume.sum()
    c = (w[:, None] * x).sum(axis=0)
    a = 2 * math.sqrt((w * (x[:, 0] - c[0]) ** 2).sum())
    b = 2 * math.sqrt((w * (x[:, 1] - c[1]) ** 2).sum())
    a_ode, b_ode = ode_axes
    return max(abs(a / a_ode - 1), abs(b / b_ode - 1))


def run_point(sph, template, params, workdir, drop_tool=None):
    p = dict(BASE, **params)
    # Short words where the full ones would pass the 100 characters a scene name may have.
    short = {"integrator": "", "end_time": "T", "h_over_dx": "hdx", "predictor_corrector": "pc",
             "position_verlet": "pv", "velocity_verlet": "vv"}
    name = template + "_" + "_".join(f"{short.get(k, k)}{short.get(v, v) if isinstance(v, str) else v}"
                                     for k, v in sorted(params.items()) if k != "packing")
    p["name"] = name
    scene = Path(workdir) / f"{name}.toml"
    scene.write_text((HERE / f"{template}.toml.in").read_text().format(**p))
    proc = subprocess.run([sph, "run", str(scene), "--out", str(workdir), "--threads", "1", "--quiet"],
                          capture_output=True, text=True, timeout=600)
    h5 = Path(workdir) / f"{name}.h5"
    if proc.returncode == 2 or not h5.exists():
        return dict(outcome="unstable", cause="rejected", message=proc.stderr.strip())
    run = read_run(h5)
    if run.read_error:
        return dict(outcome="unstable", cause="unreadable run file", message=run.read_error)
    status, cause, m = run.attrs["status"], run.attrs.get("failure_cause", ""), run.metrics
    res = dict(wall_time=float(m["wall_time_s"]), steps=int(m["steps"]),
               volume_variation=float(m["max_volume_variation"]),
               wall_reflections=int(m.get("wall_reflections", 0)), end_time=float(m["end_time"]))
    speed = run.series["max_speed"]
    res["final_max_speed"] = float(speed[-1]) if len(speed) else float("nan")
    rho_min, rho_max = run.series["rho_min"], run.series["rho_max"]
    if len(rho_min):
        res["density_error_pct"] = 100 * max(abs(rho_min.min() / run.rho0 - 1), abs(rho_max.max() / run.rho0 - 1))
    if template == "elliptical_drop" and run.snapshots:
        last = run.snapshots[-1]
        f = run.snapshot_fields(last, ("position", "mass", "density"))
        drop = run.scene["fluid"][0]
        axes = drop_ode(drop_tool, float(drop["velocity_gradient"][0][0]), float(drop["radius"]), last.time)
        res["semi_axis_error"] = semi_axis_error(f["position"][:, :2], f["mass"] / f["density"], axes)
    if template == "closed_box" and run.snapshots:
        pos = run.snapshot_fields(run.snapshots[-1], ("position",))["position"]
        res["min_pair_distance_dx"] = min_pair_distance(pos[:, :2]) / run.dx
    if status != "stable":
        res.update(outcome="unstable", cause=cause)
    elif template == "dam_break" and res["volume_variation"] > 0.003:  # paper: < 0.3 %
        res.update(outcome="inaccurate", cause="volume variation above 0.3 %")
    elif template == "hydrostatic_tank" and \
            res["final_max_speed"] > 0.05 * math.sqrt(run.gravity * block_height(run.scene)):
        res.update(outcome="inaccurate", cause="spurious currents above 0.05 sqrt(gH)")
    elif template == "elliptical_drop" and res["semi_axis_error"] > 0.01:
        res.update(outcome="inaccurate", cause="semi-axes off the ODE by more than 1 %")
    elif template == "closed_box" and res["min_pair_distance_dx"] < 0.5:
        res.update(outcome="inaccurate", cause="particle clumping (closest pair below dx/2)")
    elif template == "block_impact" and res["wall_reflections"] > 0:
        res.update(outcome="inaccurate", cause="particles reached the wall (reflected back)")
    else:
        res.update(outcome="stable", cause="")
    return res


def density_view(res):
    """The high-Mach map's outcome: the solver's own, else the 1 % density criterion (Monaghan 1994)."""
    if res["outcome"] == "unstable":
        return res
    bad = res.get("density_error_pct", 0.0) > 1.0
    return dict(res, outcome="inaccurate" if bad else "stable", cause="density error above 1 %" if bad else "")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--sph", required=True)
    ap.add_argument("--out", required=True, type=Path)
    ap.add_argument("--sweep", nargs="*", help="sweeps to run (default: all)")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--drop-ode", type=Path, help="the elliptical_drop_ode tool (verification/flows)")
    args = ap.parse_args()
    all_sweeps = sweeps()
    names = args.sweep or list(all_sweeps)
    unknown = [n for n in names if n not in all_sweeps]
    if unknown:
        ap.error(f"unknown sweep(s) {unknown}; known: {sorted(all_sweeps)}")
    # The build tree puts the tool at <build>/verification/flows/ and sph at <build>/solver/.
    drop_tool = args.drop_ode or Path(args.sph).resolve().parent.parent / "verification/flows/elliptical_drop_ode"
    if any(all_sweeps[n][0] == "elliptical_drop" for n in names) and not Path(drop_tool).is_file():
        ap.error(f"the elliptical-drop sweep needs the tool elliptical_drop_ode: no {drop_tool} (give --drop-ode)")
    args.out.mkdir(parents=True, exist_ok=True)
    done = {}  # sweeps that share their runs (the two block-impact maps) run them once
    for name in names:
        template, xl, yl, pts, yticks = all_sweeps[name]
        key = (template, json.dumps([pt[2] for pt in pts], sort_keys=True))
        if key not in done:
            with tempfile.TemporaryDirectory() as work, concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
                done[key] = list(pool.map(lambda pt: run_point(args.sph, template, pt[2], work, drop_tool), pts))
        results = done[key]
        points = []
        for (x, y, params), res in zip(pts, results):
            if yticks == "density_error_pct":
                res = density_view(res)
                y = res.get("density_error_pct", float("nan"))
            elif y is None:  # the Mach sweep plots the volume variation itself
                y = 100 * res.get("volume_variation", float("nan"))
            points.append(dict(x=x, y=y, params=params, **res))
        yticks = None if isinstance(yticks, str) else yticks
        doc = dict(sweep=name, case=template, x_label=xl, y_label=yl, points=points)
        if "Mach number" in xl:  # 0.01 to 0.8, density errors from 1 % to 80 %
            doc["x_log"] = True
            doc["y_log"] = yl.startswith("max |rho")
        if yticks:
            doc["y_ticks"] = dict(values=list(range(len(yticks))), labels=yticks)
        (args.out / f"{name}.json").write_text(json.dumps(doc, indent=1))
        print(f"{name}:")
        for p in points:
            print(f"  x={p['x']:<6} y={p['y']!s:<8} {p['outcome']:<10} {p.get('cause', ''):<22} "
                  f"vol {100 * p.get('volume_variation', float('nan')):.3f} %  wall {p.get('wall_time', 0):.2f} s "
                  f"refl {p.get('wall_reflections', '-')}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
