#!/usr/bin/python3
"""One run of the matrix and its JSON row: what ctest's run_<name> test and a Slurm array task both execute.

    run.py --matrix MATRIX (--name NAME | --index K [--names-file F]) --sph BIN --runs DIR --rows DIR

Runs `sph run SCENE --out DIR/<tier> --threads T --quiet` (the run file DIR/<tier>/<name>.h5) and writes
ROWS/<name>.json: the run's name, scene, tier, threads, sph arguments, the build's commit (from the run file),
exit code, wall time, host, Slurm job ids and the run file's key figures. Threads: SLURM_CPUS_PER_TASK inside a
Slurm job, else the matrix's. --index K picks the K-th line of --names-file (a Slurm array's SLURM_ARRAY_TASK_ID).
Exits with sph's exit code, or 1 when sph exited 0 but an output the matrix expects is missing.
"""
from __future__ import annotations

import argparse
import datetime
import json
import os
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

import matrix

sys.path.insert(0, str(matrix.HERE.parent.parent / "reports"))
from runfile import read_run  # noqa: E402  (the one run-file reader)

FIGURES = ("end_time", "steps", "particles", "max_volume_variation", "wall_reflections")
SLURM_IDS = ("SLURM_JOB_ID", "SLURM_ARRAY_JOB_ID", "SLURM_ARRAY_TASK_ID", "SLURM_JOB_NODELIST")


def threads_for(run: matrix.Run) -> int:
    """Inside Slurm the CPUs it gave the task (--cpus-per-task), else the matrix's threads."""
    given = os.environ.get("SLURM_CPUS_PER_TASK", "")
    return int(given) if given.isdigit() and int(given) > 0 else run.threads


def key_figures(h5: Path) -> dict:
    """Status, commit and the /metrics figures a reader wants at a glance (reports/SCHEMA.md)."""
    run = read_run(h5)
    if run.read_error:
        return {"read_error": run.read_error}
    out = {"status": run.attrs.get("status"), "commit": run.attrs.get("git_commit")}
    out.update({k: run.metrics[k] for k in FIGURES if k in run.metrics})
    return out


def execute(run: matrix.Run, sph: str, runs_dir: Path, rows_dir: Path) -> int:
    out = runs_dir / run.tier
    out.mkdir(parents=True, exist_ok=True)
    rows_dir.mkdir(parents=True, exist_ok=True)
    threads = threads_for(run)
    command = [sph, "run", str(run.scene), "--out", str(out), "--threads", str(threads), "--quiet", *run.args]
    started = datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds")
    t0 = time.monotonic()
    proc = subprocess.Popen(command)
    for sig in (signal.SIGTERM, signal.SIGINT):  # scancel, ctest's timeout: sph stops after its step (exit 143/130)
        signal.signal(sig, lambda s, _: proc.send_signal(s))
    code = proc.wait()
    wall = time.monotonic() - t0
    missing = [o for o in run.outputs if not (out / o).is_file()]
    h5 = out / f"{run.name}.h5"
    row = {"run": run.name, "scene": str(run.scene), "tier": run.tier, "threads": threads, "args": run.args,
           "command": command, "exit_code": code, "missing_outputs": missing, "wall_time_s": round(wall, 3),
           "started": started, "host": socket.gethostname(),
           "slurm": {k: os.environ[k] for k in SLURM_IDS if k in os.environ},
           "run_file": str(h5), "figures": key_figures(h5) if h5.is_file() else {}}
    row["commit"] = row["figures"].get("commit")
    tmp = rows_dir / f".{run.name}.json.partial"
    tmp.write_text(json.dumps(row, indent=1, default=str))
    tmp.replace(rows_dir / f"{run.name}.json")  # a reader never sees half a row
    if code == 0 and missing:
        print(f"{run.name}: sph exited 0 but left no {', '.join(missing)} in {out}", file=sys.stderr)
        return 1
    return code


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--matrix", type=Path, default=matrix.DEFAULT_MATRIX)
    pick = ap.add_mutually_exclusive_group(required=True)
    pick.add_argument("--name")
    pick.add_argument("--index", type=int)
    ap.add_argument("--names-file", type=Path, help="one run name a line (with --index)")
    ap.add_argument("--sph", required=True)
    ap.add_argument("--runs", type=Path, required=True, help="run files go to RUNS/<tier>/")
    ap.add_argument("--rows", type=Path, required=True, help="JSON rows go to ROWS/<name>.json")
    args = ap.parse_args(argv)
    try:
        m = matrix.load(args.matrix)
        name = args.name
        if name is None:
            if args.names_file is None:
                raise matrix.MatrixError("--index needs --names-file")
            names = args.names_file.read_text().split()
            if not 0 <= args.index < len(names):
                raise matrix.MatrixError(f"--index {args.index}: {args.names_file} has {len(names)} runs")
            name = names[args.index]
        run = m.run(name)
    except (matrix.MatrixError, OSError) as err:
        print(f"error: {err}", file=sys.stderr)
        return 2
    return execute(run, args.sph, args.runs, args.rows)


if __name__ == "__main__":
    sys.exit(main())
