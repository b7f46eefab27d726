#!/usr/bin/python3
"""Submits the matrix's runs (validation/matrix/matrix.toml) as Slurm job arrays and a dependent gather job.

    scripts/slurm_submit.py --out DIR [--tier quick|nightly ...] [--run NAME ...] [--matrix M] [--sph BIN]
        [--partition P] [--account A] [--module M ...] [--sbatch-option OPT ...] [--no-report] [--dry-run] [--wait]
    scripts/slurm_submit.py --out DIR --resubmit [--wait]      # only the runs that failed or left no result

One array a thread count (--array=0-(N-1), --cpus-per-task = the runs' threads; array task K runs the K-th name of
its names file through validation/matrix/run.py, which takes its threads from SLURM_CPUS_PER_TASK), then a job
with --dependency=afterany on the arrays that gathers the results and builds the report
(validation/matrix/gather.py into DIR/gathered/). DIR must be on a file system that the compute nodes share with
this host (validation/matrix/CLUSTER.md says what to do without one). Files:
  DIR/runs/<tier>/<name>.h5, DIR/rows/<name>.json    each run's run file and JSON row
  DIR/slurm/selection.json                           the matrix and the runs selected by the first submission
  DIR/slurm/submit-<n>/                              each submission's names files, sbatch scripts, logs, job ids
  DIR/gathered/{results,report,gather.json}          the gather job's output
--wait polls squeue until the jobs have left the queue, prints each job's final state (scontrol) and exits 1 when
the gather job did not complete with exit 0. Exit 2: bad input (matrix, selection, no sbatch), with the reason.
"""
from __future__ import annotations

import argparse
import json
import math
import shlex
import shutil
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "validation" / "matrix"))
import matrix  # noqa: E402
import rows  # noqa: E402

PYTHON = "/usr/bin/python3"
SLURM_OPTIONS = ("partition", "account", "module", "sbatch_option", "no_report")
GATHER_MINUTES = 30  # the report of the whole nightly takes a few minutes on 2 cores


class SubmitError(Exception):
    pass


def header(job_name: str, minutes: int, cpus: int, log: Path, args, array: str | None = None) -> list:
    lines = ["#!/bin/bash", f"#SBATCH --job-name={job_name}", "#SBATCH --ntasks=1", f"#SBATCH --cpus-per-task={cpus}",
             f"#SBATCH --time={minutes}", f"#SBATCH --output={log}"]
    if array:
        lines.insert(2, f"#SBATCH --array={array}")
    if args.partition:
        lines.append(f"#SBATCH --partition={args.partition}")
    if args.account:
        lines.append(f"#SBATCH --account={args.account}")
    lines += [f"#SBATCH {opt}" for opt in args.sbatch_option]
    return lines


def prologue(args) -> list:
    # Environment modules first: Lmod's and Tcl module's shell functions are not written for `set -u`.
    lines = [f"module load {shlex.quote(m)}" for m in args.module]
    lines.append("set -euo pipefail")
    # Idle OpenMP threads sleep instead of spinning (scripts/test.sh): a node may be shared with other jobs.
    lines.append("export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}")
    return lines


def array_script(m, group, names_file: Path, out: Path, logs: Path, args) -> str:
    minutes = math.ceil(max(r.timeout_s for r in group) / 60) + 1
    threads = group[0].threads
    lines = header(f"sph-matrix-t{threads}", minutes, threads, logs / "run_%A_%a.out", args, f"0-{len(group) - 1}")
    lines.append(f"# Written by scripts/slurm_submit.py from {m.path}: array task K runs line K+1 of {names_file}.")
    lines += prologue(args)
    cmd = [PYTHON, str(matrix.HERE / "run.py"), "--matrix", str(m.path), "--index", "$SLURM_ARRAY_TASK_ID",
           "--names-file", str(names_file), "--sph", str(args.sph), "--runs", str(out / "runs"),
           "--rows", str(out / "rows")]
    lines.append("exec " + " ".join(c if c.startswith("$") else shlex.quote(c) for c in cmd))
    return "\n".join(lines) + "\n"


def gather_script(m, selection, out: Path, logs: Path, args) -> str:
    lines = header("sph-matrix-gather", GATHER_MINUTES, 1, logs / "gather_%j.out", args)
    lines.append("# Written by scripts/slurm_submit.py: runs after the arrays end (afterany), whatever their exit.")
    lines += prologue(args)
    cmd = [PYTHON, str(matrix.HERE / "gather.py"), "--matrix", str(m.path)]
    for r in selection:
        cmd += ["--run", r.name]
    cmd += ["--runs", str(out / "runs"), "--rows", str(out / "rows"), "--out", str(out / "gathered")]
    if args.no_report:
        cmd.append("--no-report")
    lines.append("exec " + " ".join(shlex.quote(c) for c in cmd))
    return "\n".join(lines) + "\n"


def sbatch(script: Path, dependency: str | None = None) -> str:
    cmd = ["sbatch", "--parsable"] + ([f"--dependency={dependency}"] if dependency else []) + [str(script)]
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        raise SubmitError(f"{' '.join(cmd)}: exit {done.returncode}: {done.stderr.strip()}")
    return done.stdout.strip().split(";")[0]


def queued(job_ids) -> list:
    """Lines `id state` of the jobs (array tasks each) still in squeue; [] once they have all left it."""
    done = subprocess.run(["squeue", "-h", "-o", "%i %T", "-j", ",".join(job_ids)], capture_output=True, text=True)
    return done.stdout.split("\n")[:-1] if done.returncode == 0 else []


def final_states(job_ids) -> list:
    """`scontrol show job -o` lines cut to id, array task, state and exit code, one per job or array task."""
    out = []
    for j in job_ids:
        done = subprocess.run(["scontrol", "show", "job", "-o", j], capture_output=True, text=True)
        for line in done.stdout.splitlines():
            f = dict(kv.split("=", 1) for kv in line.split() if "=" in kv)
            out.append({k: f.get(k) for k in ("JobId", "ArrayJobId", "ArrayTaskId", "JobName", "JobState",
                                               "ExitCode", "RunTime")})
    return out


def wait(jobs: dict, poll_s: float, limit_s: float | None) -> int:
    ids = [j for v in jobs.values() for j in (v if isinstance(v, list) else [v])]
    start, last = time.monotonic(), None
    while True:
        now = queued(ids)
        if now != last:
            print(f"[{time.monotonic() - start:6.1f} s] squeue: " + ("; ".join(now) or "(empty)"), flush=True)
            last = now
        if not now:
            break
        if limit_s is not None and time.monotonic() - start > limit_s:
            print(f"jobs still queued after {limit_s} s", file=sys.stderr)
            return 1
        time.sleep(poll_s)
    states = final_states(ids)
    for s in states:
        print("  ".join(f"{k}={v}" for k, v in s.items() if v is not None), flush=True)
    gather = [s for s in states if s["JobId"] == jobs["gather"]]
    return 0 if gather and gather[0]["JobState"] == "COMPLETED" and gather[0]["ExitCode"] == "0:0" else 1


def submit(args) -> int:
    out = args.out.resolve()
    slurm_dir = out / "slurm"
    selection_file = slurm_dir / "selection.json"
    if args.resubmit:
        if not selection_file.is_file():
            raise SubmitError(f"--resubmit: {selection_file} not found (no earlier submission into {out})")
        chosen = json.loads(selection_file.read_text())
        m = matrix.load(Path(chosen["matrix"]))
        selection = m.select((), chosen["runs"])
        args.sph = Path(chosen["sph"])
        for key in SLURM_OPTIONS:  # the first submission's cluster options, unless given again
            if not getattr(args, key):
                setattr(args, key, chosen.get(key, getattr(args, key)))
        busy = [line for n in sorted(slurm_dir.glob("submit-*/jobs.json"))
                for line in queued([j for v in json.loads(n.read_text()).values()
                                    for j in (v if isinstance(v, list) else [v])])]
        if busy:
            raise SubmitError(f"--resubmit: earlier jobs are still queued ({'; '.join(busy)}); wait or scancel them")
        states = rows.states(selection, out / "rows", out / "runs")
        todo = [r for r in selection if states[r.name] != "done"]
        print("resubmitting " + (", ".join(f"{r.name} ({states[r.name]})" for r in todo) or "nothing: all done"))
    else:
        m = matrix.load(args.matrix)
        selection = m.select(args.tier, args.run)
        if not selection:
            raise SubmitError("the selection (--tier, --run) holds no run")
        todo = selection
    if not todo:
        return 0
    if not args.dry_run and shutil.which("sbatch") is None:
        raise SubmitError("sbatch not found on PATH (Debian: slurm-client; scripts/install-deps.sh --report)")
    slurm_dir.mkdir(parents=True, exist_ok=True)
    if not args.resubmit:
        chosen = {"matrix": str(m.path), "runs": [r.name for r in selection], "sph": str(Path(args.sph).resolve())}
        chosen.update({key: getattr(args, key) for key in SLURM_OPTIONS})
        selection_file.write_text(json.dumps(chosen, indent=1))
        args.sph = Path(args.sph).resolve()
    n = 1 + len(list(slurm_dir.glob("submit-*")))
    sub = slurm_dir / f"submit-{n}"
    logs = sub / "logs"
    logs.mkdir(parents=True)
    jobs = {"arrays": []}
    for threads in sorted({r.threads for r in todo}):
        group = [r for r in todo if r.threads == threads]
        names = sub / f"names-t{threads}.txt"
        names.write_text("".join(f"{r.name}\n" for r in group))
        script = sub / f"array-t{threads}.sbatch"
        script.write_text(array_script(m, group, names, out, logs, args))
        if not args.dry_run:
            jobs["arrays"].append(sbatch(script))
            (sub / "jobs.json").write_text(json.dumps(jobs, indent=1))  # what --resubmit must find queued
            print(f"submitted {script.name}: job {jobs['arrays'][-1]}, {len(group)} tasks", flush=True)
    gather = sub / "gather.sbatch"
    gather.write_text(gather_script(m, selection, out, logs, args))
    if args.dry_run:
        print(f"wrote {sub} (not submitted)")
        return 0
    jobs["gather"] = sbatch(gather, "afterany:" + ":".join(jobs["arrays"]))
    print(f"submitted {gather.name}: job {jobs['gather']} after {', '.join(jobs['arrays'])}", flush=True)
    (sub / "jobs.json").write_text(json.dumps(jobs, indent=1))
    return wait(jobs, args.poll_s, args.wait_limit_s) if args.wait else 0


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", type=Path, required=True)
    ap.add_argument("--matrix", type=Path, default=matrix.DEFAULT_MATRIX)
    ap.add_argument("--tier", action="append", default=[], choices=matrix.TIERS)
    ap.add_argument("--run", action="append", default=[], help="a run's name (repeat)")
    ap.add_argument("--sph", type=Path, default=ROOT / "build" / "release" / "solver" / "sph")
    ap.add_argument("--partition")
    ap.add_argument("--account")
    ap.add_argument("--module", action="append", default=[], help="`module load` it in each job (repeat)")
    ap.add_argument("--sbatch-option", action="append", default=[], help="one more #SBATCH line, e.g. --qos=long")
    ap.add_argument("--resubmit", action="store_true", help="only the runs of DIR's selection not done")
    ap.add_argument("--no-report", action="store_true", help="the gather job checks but builds no report")
    ap.add_argument("--dry-run", action="store_true", help="write the scripts, submit nothing")
    ap.add_argument("--wait", action="store_true")
    ap.add_argument("--poll-s", type=float, default=5.0)
    ap.add_argument("--wait-limit-s", type=float)
    args = ap.parse_args(argv)
    if args.resubmit and (args.tier or args.run):
        print("error: --resubmit takes the selection of the first submission; no --tier/--run", file=sys.stderr)
        return 2
    try:
        return submit(args)
    except (matrix.MatrixError, SubmitError) as err:
        print(f"error: {err}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
