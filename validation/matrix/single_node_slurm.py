#!/usr/bin/python3
"""Issue 34's Slurm test: a small matrix as a job array on a single-node Slurm cluster started here, against the
local runner (ctest's run_<name> tests).

    single_node_slurm.py --sph BIN --runs RUNS --rows ROWS --work DIR

RUNS/ROWS are where ctest's local runner wrote the quick runs (the test requires their fixtures). Steps:
 1. the report of the local runner's files: gather.py over RUNS/ROWS into DIR/local;
 2. a single-node cluster (slurm_cluster.py) and a copy of the matrix's four quick runs in which one scene has a
    bad key, so that its array task fails (sph exit 2);
 3. scripts/slurm_submit.py --wait: three runs done, one failed, the gather job ran after the array (afterany);
 4. the scene repaired, scripts/slurm_submit.py --resubmit --wait: an array of exactly that run; the other rows
    and run files untouched (same Slurm job id, same file times); all four done;
 5. every Slurm run file bit-identical to the local one (perf/compare_runs.py), the same key figures in the rows,
    and the two reports' figures equal: every criterion's measured value, threshold and outcome, every
    convergence entry, the counts.
The daemons are stopped in every case (SIGTERM and SIGINT included). Exit 0 when all holds, 1 with the reason.
"""
from __future__ import annotations

import argparse
import json
import shutil
import signal
import subprocess
import sys
from pathlib import Path

import matrix
import rows
from slurm_cluster import ClusterError, SingleNodeCluster

ROOT = matrix.HERE.parent.parent
PYTHON = "/usr/bin/python3"
RUNS = ["dam_break_dx0.025", "dam_break_lobovsky_dx0.02", "martin_moyce_a10", "drop_into_pool_dx0.002"]
BROKEN = "martin_moyce_a10"
WAIT_LIMIT_S = 400  # an upper bound only (each wait took 30-40 s on a loaded 2-core machine); two fit in ctest's 1200 s


class Failed(Exception):
    pass


def expect(ok: bool, what: str) -> None:
    print(f"{'ok  ' if ok else 'FAIL'} {what}", flush=True)
    if not ok:
        raise Failed(what)


def sh(cmd, env=None) -> int:
    print("+ " + " ".join(str(c) for c in cmd), flush=True)
    return subprocess.run([str(c) for c in cmd], env=env).returncode


def write_matrix(path: Path, m: matrix.Matrix, selection, scene_of: dict) -> None:
    """A matrix of `selection` (scene paths replaced by scene_of) and its checks, in the matrix's format."""
    lines = [f"# The test's matrix: {len(selection)} runs of {m.path}.", "[defaults]", "threads = 2", ""]
    for r in selection:
        lines += ["[[run]]", f"scene = {json.dumps(str(scene_of.get(r.name, r.scene)))}", f"tier = \"{r.tier}\"",
                  f"threads = {r.threads}", f"timeout_s = {r.timeout_s}", ""]
    for c in m.checks_over(selection):
        lines += ["[[check]]", f"name = \"{c.name}\"", f"case = \"{c.case}\"", f"tier = \"{c.tier}\"",
                  f"runs = {json.dumps(c.runs)}", ""]
    path.write_text("\n".join(lines))


def report_figures(report_dir: Path) -> dict:
    """What must agree between two reports of the same runs: no times, dates or paths."""
    s = json.loads((report_dir / "summary.json").read_text())
    keep = ("case", "run", "metric", "comparison", "threshold", "measured", "outcome", "kind", "id")
    return {"counts": s["counts"], "criteria": [{k: c.get(k) for k in keep} for c in s["criteria"]],
            "convergence": [{k: v for k, v in e.items() if k != "figure"} for e in s["convergence"]]}


def slurm_ids(rows_dir: Path) -> dict:
    return {n: (r.get("slurm", {}).get("SLURM_JOB_ID"), r.get("started")) for n, r in rows.read_rows(rows_dir).items()}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--sph", required=True)
    ap.add_argument("--runs", type=Path, required=True)
    ap.add_argument("--rows", type=Path, required=True)
    ap.add_argument("--work", type=Path, required=True)
    args = ap.parse_args(argv)
    work = args.work.resolve()
    if work.exists():
        shutil.rmtree(work)
    work.mkdir(parents=True)
    m = matrix.load()
    selection = m.select((), RUNS)
    names = [a for r in selection for a in ("--run", r.name)]

    # 1. the local runner's report
    sh([PYTHON, matrix.HERE / "gather.py", *names, "--runs", args.runs, "--rows", args.rows, "--out", work / "local"])
    local = json.loads((work / "local" / "gather.json").read_text())
    expect(all(r["state"] == "done" for r in local["runs"]), f"the local runner's {len(RUNS)} runs are done")

    # 2. the test's matrix, one scene broken
    good_scene = m.run(BROKEN).scene
    broken_scene = work / "scenes" / good_scene.name
    broken_scene.parent.mkdir()
    broken_scene.write_text("no_such_key = 1\n" + good_scene.read_text())
    test_matrix = work / "matrix.toml"
    write_matrix(test_matrix, m, selection, {BROKEN: broken_scene})
    print(test_matrix.read_text())

    signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))  # ctest's timeout: leave through `finally`
    out = work / "slurm"
    submit = [PYTHON, ROOT / "scripts" / "slurm_submit.py", "--out", out, "--wait", "--poll-s", "1",
              "--wait-limit-s", str(WAIT_LIMIT_S)]
    try:
        with SingleNodeCluster(work / "cluster") as cluster:
            print(f"cluster up: {cluster.env['SLURM_CONF']}, {cluster.cpus} cpus", flush=True)
            # 3. the array with one task failing
            sh([*submit, "--matrix", test_matrix, *names, "--sph", args.sph], cluster.env)
            script = out / "slurm" / "submit-1" / f"array-t{m.run(BROKEN).threads}.sbatch"  # one array a thread count
            print(f"--- {script}\n{script.read_text()}---", flush=True)
            states = rows.states(selection, out / "rows", out / "runs")
            expect(states == {r.name: ("failed" if r.name == BROKEN else "done") for r in selection},
                   f"first array: {BROKEN} failed, the others done ({states})")
            expect(rows.read_rows(out / "rows")[BROKEN]["exit_code"] == 2, f"{BROKEN}: sph exit 2 (bad input)")
            first = json.loads((out / "gathered" / "gather.json").read_text())
            expect([r["state"] for r in first["runs"]] == [states[r.name] for r in selection],
                   "the gather job ran after the array and saw the same states")
            before = slurm_ids(out / "rows")
            times = {r.name: (out / "runs" / r.tier / f"{r.name}.h5").stat().st_mtime_ns
                     for r in selection if r.name != BROKEN}

            # 4. repaired, resubmitted: only that run reruns
            broken_scene.write_text(good_scene.read_text())
            sh([*submit, "--resubmit"], cluster.env)
            again = (out / "slurm" / "submit-2" / f"names-t{m.run(BROKEN).threads}.txt").read_text().split()
            expect(again == [BROKEN], f"the resubmitted array holds {again} (only {BROKEN})")
            after = slurm_ids(out / "rows")
            expect(all(after[n] == before[n] for n in times), "the other rows are untouched (same job ids, starts)")
            expect(all((out / "runs" / m.run(n).tier / f"{n}.h5").stat().st_mtime_ns == t for n, t in times.items()),
                   "the other run files are untouched")
            expect(after[BROKEN][0] != before[BROKEN][0], f"{BROKEN} ran again (job {after[BROKEN][0]})")
            for log in sorted((out / "slurm").glob("submit-*/logs/*.out")):
                print(f"--- {log.relative_to(out)}\n{log.read_text().strip()}", flush=True)
    except ClusterError as err:
        print(f"FAIL the single-node cluster: {err}", flush=True)
        return 1
    except Failed:
        return 1
    print("cluster stopped", flush=True)

    # 5. the same results
    try:
        final = json.loads((out / "gathered" / "gather.json").read_text())
        expect(all(r["state"] == "done" for r in final["runs"]), "after the resubmission all runs are done")
        local_rows, slurm_rows = rows.read_rows(args.rows), rows.read_rows(out / "rows")
        for r in selection:
            a, b = out / "runs" / r.tier / f"{r.name}.h5", args.runs / r.tier / f"{r.name}.h5"
            same = subprocess.run([PYTHON, ROOT / "perf" / "compare_runs.py", a, b], capture_output=True, text=True)
            expect(same.returncode == 0, f"{r.name}: Slurm's run file against the local one: "
                                         f"{(same.stdout + same.stderr).strip()}")
            fa, fb = slurm_rows[r.name]["figures"], local_rows[r.name]["figures"]
            expect(fa == fb, f"{r.name}: the rows' key figures agree ({fa})")
        ra, rb = report_figures(out / "gathered" / "report"), report_figures(work / "local" / "report")
        expect(ra == rb, f"the two reports' figures agree: {len(ra['criteria'])} criteria ({ra['counts']}), "
                         f"{len(ra['convergence'])} convergence entries")
        expect(final["checks"] == local["checks"], f"the checks' exit codes agree ({final['checks']})")
    except Failed:
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
