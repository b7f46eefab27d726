#!/usr/bin/python3
"""Gathers a matrix's results and builds the V&V report from them: the Slurm array's dependent job, and the same
step over the local runner's files.

    gather.py --matrix MATRIX [--tier T ...] [--run NAME ...] --runs DIR --rows DIR --out DIR [--no-report]

For the selected runs (all of the matrix without --tier/--run) reads their rows (rows.py) and links their run
files into OUT/runs/<tier>/, so the report sees exactly the selection whichever runner wrote it and wherever;
runs validation/validate.py for each check whose runs are all selected (OUT/results/validation.<check>.json) and
reports/vv_report.py over OUT/runs and OUT/results (OUT/report/, --quick when only quick runs are selected).
Writes OUT/gather.json (each run's state, each check's exit code, the report's) and prints a table. Exit 0 when
every run is done and the report passed, 1 otherwise (after writing everything), 2 on a bad matrix.
"""
from __future__ import annotations

import argparse
import json
import shutil
import subprocess
import sys
from pathlib import Path

import matrix
import rows

VALIDATION = matrix.HERE.parent
REPORTS = VALIDATION.parent / "reports"
PYTHON = "/usr/bin/python3"


def link_runs(selection, runs_dir: Path, states: dict, out: Path) -> None:
    """OUT/runs/<tier>/<name>.h5 -> the run file of each done run (a fresh directory each time)."""
    if out.exists():
        shutil.rmtree(out)
    for r in selection:
        if states[r.name] == "done":
            (out / r.tier).mkdir(parents=True, exist_ok=True)
            (out / r.tier / f"{r.name}.h5").symlink_to((runs_dir / r.tier / f"{r.name}.h5").resolve())


def gather(m: matrix.Matrix, selection, runs_dir: Path, rows_dir: Path, out: Path, report: bool) -> int:
    out.mkdir(parents=True, exist_ok=True)
    states = rows.states(selection, rows_dir, runs_dir)
    linked = out / "runs"
    link_runs(selection, runs_dir, states, linked)
    results = out / "results"
    if results.exists():
        shutil.rmtree(results)
    checks = {}
    for c in m.checks_over(selection):
        cmd = [PYTHON, str(VALIDATION / "validate.py"), c.case, *c.runs, "--runs", str(linked / "quick"),
               "--runs", str(linked / "nightly"), "--results", str(results), "--name", c.name]
        checks[c.name] = subprocess.run(cmd, stdout=subprocess.DEVNULL).returncode
    report_code = None
    if report:
        cmd = [PYTHON, str(REPORTS / "vv_report.py"), "--runs", str(linked), "--results", str(results),
               "--out", str(out / "report")]
        if all(r.tier == "quick" for r in selection):
            cmd.append("--quick")
        report_code = subprocess.run(cmd).returncode
    summary = {"matrix": str(m.path), "runs": [{"run": r.name, "tier": r.tier, "state": states[r.name]}
                                               for r in selection],
               "checks": checks, "report_exit_code": report_code}
    (out / "gather.json").write_text(json.dumps(summary, indent=1))
    for r in selection:
        print(f"{states[r.name]:8s} {r.name}")
    for name, code in checks.items():
        print(f"check {name}: exit {code}")
    undone = [n for n, s in states.items() if s != "done"]
    if undone:
        print(f"not done: {', '.join(undone)} (scripts/slurm_submit.py --resubmit reruns them)", file=sys.stderr)
    return 0 if not undone and report_code in (0, None) else 1


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--matrix", type=Path, default=matrix.DEFAULT_MATRIX)
    ap.add_argument("--tier", action="append", default=[], choices=matrix.TIERS)
    ap.add_argument("--run", action="append", default=[], help="a run's name (repeat)")
    ap.add_argument("--runs", type=Path, required=True, help="where the runner wrote RUNS/<tier>/<name>.h5")
    ap.add_argument("--rows", type=Path, required=True, help="where the runner wrote ROWS/<name>.json")
    ap.add_argument("--out", type=Path, required=True)
    ap.add_argument("--no-report", action="store_true")
    args = ap.parse_args(argv)
    try:
        m = matrix.load(args.matrix)
        selection = m.select(args.tier, args.run)
    except matrix.MatrixError as err:
        print(f"error: {err}", file=sys.stderr)
        return 2
    return gather(m, selection, args.runs, args.rows, args.out, not args.no_report)


if __name__ == "__main__":
    sys.exit(main())
