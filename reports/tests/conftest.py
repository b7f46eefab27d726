"""Small run files and results written with h5py exactly as reports/SCHEMA.md lays them out."""
import json
import sys
from pathlib import Path

import h5py
import numpy as np
import pytest

REPORTS = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(REPORTS))

# The synthetic runs' body acceleration and first rest density: written into each file (root attributes
# `gravity`, `rho0` and the scene text), which is where the code under test must take them from.
GRAVITY = 9.81
RHO0 = 1000.0


def scene_text(scene_name: str, phases, dx: float, gravity: float, rho0: float, kernel: str) -> str:
    """A scene file as `sph run` stores it in /scene (solver/SCENES.md), with the keys the readers use."""
    lines = [f'name = "{scene_name}"', "dimension = 2", ""]
    for k, ph in enumerate(phases):
        lines += ["[[phase]]", f'name = "{ph}"', f"rho0 = {rho0 * (1 + 0.5 * k)!r}", "c0 = 24.4", ""]
    lines += ["[physics]", f"gravity = [0.0, {-gravity!r}]", "", "[numerics]", f'kernel = "{kernel}"',
              f"dx = {dx!r}", "h_over_dx = 1.33", "end_time = 0.4", ""]
    return "\n".join(lines)


def write_run(path: Path, scene_name: str, *, status="stable", max_volume_variation=0.001, phases=("water",),
              kernel="cubic_spline", wall_time_s=12.5, n=120, dx=0.01, probes=(), snapshots=3,
              gravity=GRAVITY, rho0=RHO0):
    """A run file following reports/SCHEMA.md. `probes`: (name, values-function of t, extra attributes).
    `gravity` or `rho0` None leaves that root attribute out (a file that breaks the schema)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    rng = np.random.default_rng(7)
    nt = 41
    t = np.linspace(0.0, 0.4, nt)
    with h5py.File(path, "w") as f:
        for key, value in {"format": "sph-run-1", "sph_version": "0.1.0", "git_commit": "abc1234",
                           "compiler": "GCC 12.2",
                           "cxx_flags": "-O3 -march=native", "build_type": "Release", "machine": "test-host",
                           "date": "2024-01-01T00:00:00Z", "scene_name": scene_name,
                           "scene_file": f"validation/scenes/{scene_name}.toml", "kernel": kernel,
                           "terms": "continuity,pressure_gradient,artificial_viscosity,body_force,ghost_walls",
                           "status": status, "failure_cause": "" if status == "stable" else "nan",
                           "failure": "" if status == "stable" else "step 40, t = 0.39 s, particle 7: density is nan",
                           }.items():
            f.attrs[key] = value
        f.attrs["threads"] = np.int64(4)
        f.attrs["dimension"] = np.int64(2)
        if gravity is not None:
            f.attrs["gravity"] = float(gravity)
        if rho0 is not None:
            f.attrs["rho0"] = float(rho0)
        g0, r0 = GRAVITY if gravity is None else gravity, RHO0 if rho0 is None else rho0
        f.create_dataset("scene", data=scene_text(scene_name, phases, dx, g0, r0, kernel))
        s = f.create_group("series")
        s["time"] = t
        s["dt"] = np.full(nt, 1e-4)
        s["step"] = np.arange(nt, dtype=np.int64) * 100
        s["dt_limiter"] = np.zeros(nt, dtype=np.int32)
        s["kinetic_energy"] = t ** 2
        s["max_speed"] = 2.0 * t
        s["rho_min"] = np.full(nt, 0.995 * r0)
        s["rho_max"] = np.full(nt, 1.005 * r0)
        s["volume_error"] = max_volume_variation * np.sin(np.linspace(0, np.pi / 2, nt))
        if len(phases) > 1:
            for k, ph in enumerate(phases):
                s[f"volume_error_{ph}"] = (k + 1) / len(phases) * np.asarray(s["volume_error"])
        for name, fn, attrs in probes:
            d = s.create_dataset(f"probe_{name}", data=fn(t))
            for key, value in attrs.items():
                d.attrs[key] = value
        snaps = f.create_group("snapshots")
        for k in range(snapshots):
            g = snaps.create_group(f"{k:05d}")
            g.attrs["time"] = float(t[-1] * k / max(snapshots - 1, 1))
            g.attrs["step"] = np.int64(1000 * k)
            if status != "stable" and k == snapshots - 1:
                g.attrs["last_good"] = np.int64(1)
            pos = np.zeros((n, 3))
            pos[:, 0] = (np.arange(n) % 12) * dx + k * 0.002 * rng.random(n)
            pos[:, 1] = (np.arange(n) // 12) * dx
            g["position"] = pos
            g["velocity"] = np.zeros((n, 3))
            g["density"] = np.full(n, r0)
            g["pressure"] = r0 * g0 * (pos[:, 1].max() - pos[:, 1])
            g["h"] = np.full(n, 1.33 * dx)
            g["mass"] = np.full(n, r0 * dx * dx)
            g["phase"] = (np.arange(n) % 12 >= 6).astype(np.int32) if len(phases) > 1 else np.zeros(n, np.int32)
        m = f.create_group("metrics")
        m.attrs["wall_time_s"] = float(wall_time_s)
        m.attrs["steps"] = np.int64(4000)
        m.attrs["particles"] = np.int64(n)
        m.attrs["end_time"] = float(t[-1])
        m.attrs["max_volume_variation"] = float(max_volume_variation)
        for k, ph in enumerate(phases if len(phases) > 1 else ()):
            m.attrs[f"max_volume_variation_{ph}"] = float((k + 1) / len(phases) * max_volume_variation)
        m.attrs["force_evaluations"] = np.int64(4000)
        m.attrs["particle_evaluations_per_s"] = float(n * 4000 / wall_time_s)
    return path


def write_result(path: Path, test="Poiseuille.SteadyProfile", measured=0.012, threshold=0.03, passed=True,
                 convergence=True):
    path.parent.mkdir(parents=True, exist_ok=True)
    data = {"test": test, "issue": 3,
            "checks": [{"name": "L2 error / v_max at dx = L/20", "measured": measured, "threshold": threshold,
                        "comparison": "<=", "source": "measured convergence study, see test", "pass": passed}]}
    if convergence:
        data["convergence"] = [{"name": "Poiseuille L2 error", "x_label": "dx [m]", "x": [1e-4, 5e-5, 2.5e-5],
                                "error": [0.08, 0.02, 0.005], "observed_order": 2.0, "theory_order": 2.0,
                                "source": "Morris, Fox & Zhu 1997"}]
    path.write_text(json.dumps(data))
    return path


@pytest.fixture
def make_run():
    return write_run


@pytest.fixture
def make_result():
    return write_result
