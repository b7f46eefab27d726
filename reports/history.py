"""The results database: each report run appends one JSON line with its figures, commit, build and machine, and
the report shows each figure's trend over the stored runs and flags a change beyond its noise.

Noise of a figure (NOISE_SIGMAS, the floors): three standard deviations of its earlier values on unloaded runs, but
at least a floor. The solver's results are bitwise reproducible on a given code (README: any thread count, restart),
so a figure of merit that moves at all has changed: its floor is a relative 1e-9 (round-off in the JSON's decimal
form). Wall times move 5-20 % from run to run on the shared 2-core machine (perf/README.md): their floor is 20 %.
A run is "loaded" when the 1-minute load average at its start or end exceeds half the processor count: then two
runs of the tests at a time (ctest -j2) already compete with something else for the cores.
"""
from __future__ import annotations

import datetime
import json
import math
import os
import socket
import statistics
import subprocess
from pathlib import Path

NOISE_SIGMAS = 3.0
FIGURE_FLOOR = 1e-9  # relative, figures of merit
TIME_FLOOR = 0.2  # relative, wall times
TIME_PREFIX = "wall time [s] | "


def load_average() -> float:
    try:
        return float(os.getloadavg()[0])
    except OSError:
        return float("nan")


def loaded(load_start: float, load_end: float, nproc: int) -> bool:
    return any(math.isfinite(x) and x > nproc / 2 for x in (load_start, load_end))


def _commit(environment: dict) -> str:
    values = {r["attribute"]: r["value"] for r in environment.get("rows", [])}
    if values.get("git_commit"):
        return str(values["git_commit"])
    try:
        return subprocess.run(["git", "-C", str(Path(__file__).resolve().parent), "rev-parse", "--short", "HEAD"],
                              capture_output=True, text=True, check=False, timeout=10).stdout.strip() or "unknown"
    except (OSError, subprocess.SubprocessError):
        return "unknown"


def figures_of(report: dict) -> dict:
    """{key: number}: every criterion's numeric measurement, the V&V 20 comparison errors, the runs' wall times."""
    out = {}
    for c in report["criteria"]:
        if isinstance(c.measured, (int, float)) and not isinstance(c.measured, bool) and math.isfinite(c.measured):
            out.setdefault(f"{c.run or c.case} | {c.metric}", float(c.measured))
        if isinstance(c.run_time_s, (int, float)) and c.kind == "validation":
            out.setdefault(TIME_PREFIX + c.run, float(c.run_time_s))
    for u in report.get("uncertainty", []):
        if u.get("E") is not None:
            out[f"V&V 20 | {u['name']} | E"] = float(u["E"])
    return out


def record(report: dict, load_start: float, load_end: float) -> dict:
    env = report["environment"]
    build = {r["attribute"]: r["value"] for r in env.get("rows", [])}.get("build_type") or "unknown"
    nproc = os.cpu_count() or 1
    return {"date": report["generated"], "commit": _commit(env), "build_type": str(build),
            "hostname": socket.gethostname(), "nproc": nproc, "load_start": load_start, "load_end": load_end,
            "loaded": loaded(load_start, load_end, nproc), "verdict": report["verdict"],
            "figures": figures_of(report)}


def append(path: Path, entry: dict) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "a", encoding="utf-8") as f:
        f.write(json.dumps(entry, sort_keys=True) + "\n")


def read(path: Path | None) -> tuple:
    """(entries, problems): one entry per readable line; a line that is not a JSON object is a problem."""
    if path is None or not Path(path).exists():
        return [], []
    entries, problems = [], []
    for n, line in enumerate(Path(path).read_text(encoding="utf-8").splitlines(), 1):
        if not line.strip():
            continue
        try:
            e = json.loads(line)
            if not isinstance(e, dict) or not isinstance(e.get("figures"), dict):
                raise ValueError("not an object with `figures`")
            entries.append(e)
        except ValueError as err:
            problems.append(f"{path}:{n}: {err}")
    return entries, problems


def trends(entries: list) -> list:
    """Per figure key with two or more stored values: its series, the noise and whether the latest run's value
    departs from the mean of the earlier unloaded ones by more than the noise. Flagged first."""
    if len(entries) < 2:
        return []
    keys = sorted({k for e in entries for k in e["figures"]})
    out = []
    for key in keys:
        series = [(i, e["figures"][key], bool(e.get("loaded"))) for i, e in enumerate(entries) if key in e["figures"]]
        if len(series) < 2 or series[-1][0] != len(entries) - 1:
            continue
        earlier = [v for i, v, ld in series[:-1] if not ld] or [v for _, v, _ in series[:-1]]
        mean = statistics.fmean(earlier)
        spread = statistics.stdev(earlier) if len(earlier) > 1 else 0.0
        floor = (TIME_FLOOR if key.startswith(TIME_PREFIX) else FIGURE_FLOOR) * abs(mean)
        noise = max(NOISE_SIGMAS * spread, floor, 1e-300)
        latest = series[-1][1]
        out.append({"key": key, "runs": [i for i, _, _ in series], "values": [v for _, v, _ in series],
                    "loaded": [ld for _, _, ld in series], "mean": mean, "noise": noise, "latest": latest,
                    "change": latest - mean, "flagged": abs(latest - mean) > noise})
    out.sort(key=lambda t: (not t["flagged"], t["key"]))
    return out


def now() -> str:
    return datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds")
