#!/usr/bin/python3
"""V&V report of the SPH solver.

    /usr/bin/python3 reports/vv_report.py --runs RUNS --results RESULTS --out reports/out \
        [--quick] [--perf DIR] [--stability DIR] [--paraview DIR] [--criteria validation/criteria.toml]

Reads every *.h5 run file under --runs and every *.json verification result under --results (reports/SCHEMA.md),
decides the criteria (validation/criteria.toml, run status, the verification checks) with pytest
(reports/test_criteria.py -> junit.xml), and writes index.html, its PNG figures, junit.xml and summary.json to --out.
The verdict is about the named model's criteria and every verification test (criteria.judged, issue 31); the
paper's model's criteria are shown beside the named model's, and its failures are listed as findings.
Exit status: 0 when no judged criterion failed, 1 when one did (after writing everything).
"""
from __future__ import annotations

import argparse
import datetime
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import analysis  # noqa: E402
import paraview_view  # noqa: E402
import plots  # noqa: E402
import history  # noqa: E402
import report_site  # noqa: E402
import traceability  # noqa: E402
import uncertainty  # noqa: E402
from criteria import DEFAULT_CRITERIA, FAIL, NOT_RUN, collect, counts, findings, judged, load_criteria  # noqa: E402
from runfile import family, read_json_dir, read_results, read_runs  # noqa: E402

FIGURE_ERRORS = (ValueError, KeyError, TypeError, IndexError, OSError)


def run_pytest(runs: Path, results: Path, criteria_file: Path, junit: Path) -> tuple:
    """Decide the criteria with pytest in a child process; returns (exit code, output)."""
    env = dict(os.environ, VV_RUNS=str(runs), VV_RESULTS=str(results), VV_CRITERIA=str(criteria_file),
               PYTHONDONTWRITEBYTECODE="1")
    cmd = [sys.executable, "-m", "pytest", str(HERE / "test_criteria.py"), "-q", "-rN", "-p", "no:cacheprovider",
           f"--junitxml={junit}", "-o", "junit_suite_name=vv_criteria", "-o", "addopts=",
           "--rootdir", str(HERE)]
    proc = subprocess.run(cmd, env=env, capture_output=True, text=True, check=False)
    return proc.returncode, proc.stdout + proc.stderr


def junit_counts(junit: Path) -> dict:
    """Test cases of junit.xml: failed, skipped (not run), expected failures (the paper's model's findings,
    test_criteria.py marks them xfail) and passed."""
    root = ET.parse(junit).getroot()
    cases = root.iter("testcase")
    n = failed = skipped = xfailed = 0
    for case in cases:
        n += 1
        failed += case.find("failure") is not None or case.find("error") is not None
        skip = case.find("skipped")
        xfailed += skip is not None and skip.get("type") == "pytest.xfail"
        skipped += skip is not None and skip.get("type") != "pytest.xfail"
    return {"total": n, "failed": failed, "not_run": skipped, "findings": xfailed,
            "passed": n - failed - skipped - xfailed}


def expected_junit(found: list) -> dict:
    """What junit_counts should read for `found`: the paper's failures as expected failures."""
    every, paper = counts(found), counts(findings(found))
    return {"total": every["total"], "failed": every["failed"] - paper["failed"], "not_run": every["not_run"],
            "findings": paper["failed"], "passed": every["passed"]}


def _figure(notes: list, what: str, make, *args, **kwargs):
    """Make one figure; a figure that cannot be drawn from odd data becomes a note, not a crash."""
    try:
        return make(*args, **kwargs)
    except FIGURE_ERRORS as err:
        notes.append(f"{what}: figure not drawn ({type(err).__name__}: {err})")
        return None


def case_pages(runs, found, table, out: Path, quick: bool) -> list:
    pages = []
    for run in runs:
        notes, figures = [], []
        mine = [c for c in found if c.kind == "validation" and c.run == run.label]
        if not run.read_error:
            figures.append((_figure(notes, "snapshots", plots.snapshots, run, out, quick), "particle snapshots"))
            figures.append((_figure(notes, "volume", plots.volume, run, mine, out, quick), "volume variation"))
            for pr in run.probes:
                made = _figure(notes, f"probe {pr.name}", plots.probe, run, pr, out, quick)
                if made:
                    figures.append((made[0], f"probe {pr.name}"))
                    notes.extend(made[1])
        pages.append({"title": f"{family(run.scene_name, table)}: {run.label}", "path": str(run.path),
                      "attrs": run.attrs, "metrics": run.metrics, "read_error": run.read_error,
                      "figures": [f for f in figures if f[0]], "notes": notes})
    for case in sorted({c.case for c in found if c.outcome == NOT_RUN and c.kind == "validation"}):
        pages.append({"title": case, "not_run": True})
    return pages


def stability_items(directory, out: Path, quick: bool) -> list:
    items = []
    for k, (path, obj) in enumerate(read_json_dir(directory)):
        points = obj.get("points") if isinstance(obj, dict) else None
        ok = isinstance(points, list) and all(isinstance(p, dict) and {"x", "y", "outcome"} <= set(p) and
                                              p["outcome"] in plots.OUTCOME_STYLE for p in points)
        if not ok:
            why = obj if isinstance(obj, str) else 'expected {"sweep", "x_label", "y_label", "points": [{"x", "y", ' \
                                                   '"outcome": "stable|unstable|inaccurate", "cause"}]}'
            items.append({"path": str(path), "error": why})
            continue
        notes = []
        fig = _figure(notes, "stability", plots.stability, obj, out, k, quick)
        tally = {o: sum(p["outcome"] == o for p in points) for o in plots.OUTCOME_STYLE}
        items.append({"path": str(path), "sweep": obj.get("sweep", path.stem), "x_label": obj.get("x_label"),
                      "y_ticks": obj.get("y_ticks"),
                      "y_label": obj.get("y_label"), "points": points, "counts": tally, "figure": fig,
                      "error": "; ".join(notes)})
    return items


def perf_items(directory, out: Path, quick: bool) -> list:
    items = []
    for k, (path, obj) in enumerate(read_json_dir(directory)):
        if isinstance(obj, dict) and isinstance(obj.get("series"), list):
            notes = []
            fig = _figure(notes, "performance", plots.perf_series, obj, out, k, quick)
            items.append({"path": str(path), "title": obj.get("benchmark", path.stem), "figure": fig,
                          "source": obj.get("source", ""), "data": obj, "error": "; ".join(notes)})
        elif isinstance(obj, dict) and isinstance(obj.get("benchmarks"), list):  # Google Benchmark --benchmark_out
            columns = ["name", "real_time", "cpu_time", "time_unit", "iterations", "items_per_second"]
            items.append({"path": str(path), "title": path.name, "columns": columns,
                          "rows": [b for b in obj["benchmarks"] if isinstance(b, dict)],
                          "context": {k: v for k, v in obj.get("context", {}).items()
                                      if k in ("date", "host_name", "num_cpus", "mhz_per_cpu", "library_build_type",
                                               "core_round_trip_ns")}})
        else:
            why = obj if isinstance(obj, str) else \
                'expected {"benchmark", "x_label", "y_label", "series": [{"label", "x", "y"}]} or Google Benchmark JSON'
            items.append({"path": str(path), "error": why})
    return items


TRENDS_DRAWN = 12  # trend figures on the history page: the flagged ones first, then the V&V 20 errors


def run_history(path, report: dict, load_start: float, out: Path, quick: bool) -> dict:
    """Append this run to the results database (when one is named) and reduce its trends."""
    this = history.record(report, load_start, history.load_average())
    entries, problems = history.read(path)
    entries.append(this)
    if path is not None:
        history.append(path, this)
    trends = history.trends(entries)
    drawn = [t for t in trends if t["flagged"]] + [t for t in trends if not t["flagged"] and t["key"].startswith("V&V")]
    for k, t in enumerate(drawn[:TRENDS_DRAWN]):
        t["figure"] = _figure(problems, "trend", plots.trend, t, entries, out, k, quick)
    return {"path": str(path) if path else None, "this": {k: v for k, v in this.items() if k != "figures"},
            "entries": entries, "trends": trends, "problems": problems,
            "runs": [{k: v for k, v in e.items() if k != "figures"} for e in entries]}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--runs", type=Path, required=True, help="directory searched recursively for *.h5 run files")
    ap.add_argument("--results", type=Path, required=True, help="directory of verification *.json results")
    ap.add_argument("--out", type=Path, default=HERE / "out", help="output directory (default reports/out)")
    ap.add_argument("--quick", action="store_true", help="fewer snapshots, lower resolution figures")
    ap.add_argument("--perf", type=Path, help="directory of performance *.json results")
    ap.add_argument("--stability", type=Path, help="directory of stability-sweep *.json results")
    ap.add_argument("--criteria", type=Path, default=DEFAULT_CRITERIA, help="criteria TOML")
    ap.add_argument("--requirements", type=Path, default=traceability.DEFAULT_REQUIREMENTS,
                    help="requirements of the verification groups (traceability matrix)")
    ap.add_argument("--history", type=Path, help="results database (JSON lines) this run appends to, and whose "
                                                  "trends the report shows (scripts/vv-report.sh: the build tree's)")
    ap.add_argument("--load-start", type=float, help="1-minute load average when the tests started (default: when "
                                                     "the report starts)")
    ap.add_argument("--paraview", type=Path, help="directory of paraview.json and its picture (the dam break "
                                                   "opened in pvpython, validation/paraview)")
    args = ap.parse_args(argv)
    load_start = history.load_average() if args.load_start is None else args.load_start
    out = args.out
    out.mkdir(parents=True, exist_ok=True)

    runs, results = read_runs(args.runs), read_results(args.results)
    table = load_criteria(args.criteria)
    found = collect(args.runs, args.results, args.criteria, runs=runs, results=results)
    tally = counts(judged(found))  # the verdict's criteria: the named model's and the verification tests'
    paper = counts(findings(found))  # the paper's model's, where a case runs the named model too

    problems = []
    junit = out / "junit.xml"
    rc, log = run_pytest(args.runs, args.results, args.criteria, junit)
    if rc not in (0, 1, 5) or not junit.exists():
        problems.append(f"pytest on test_criteria.py ended with exit code {rc}: {log.strip()[-600:]}")
    elif found and junit_counts(junit) != expected_junit(found):
        problems.append(f"pytest decided {junit_counts(junit)}, the direct evaluation {expected_junit(found)}")

    conv = analysis.convergence_entries(results)
    for k, entry in enumerate(conv):
        notes = []
        entry["figure"] = _figure(notes, "convergence", plots.convergence, entry, out, k, args.quick)
    vv20 = uncertainty.table(results)
    for k, row in enumerate(vv20):
        if not row.get("error"):
            row["figure"] = _figure([], "V&V 20", plots.vv20, row, out, k, args.quick)
    hist = analysis.recorded_histories(results)
    for k, group in enumerate(hist):
        group["figure"] = _figure([], "history", plots.history, group, out, k, args.quick)
    stability = stability_items(args.stability, out, args.quick)
    speed = analysis.speed_accuracy(runs)
    speed.update(analysis.sweep_speed_accuracy([s for s in stability if not s.get("error")]))
    for case, data in speed.items():
        data["figure"] = _figure([], "speed/accuracy", plots.speed_accuracy, case, data, out, args.quick)

    report = {
        "generated": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
        "inputs": {"runs": str(args.runs), "results": str(args.results), "criteria": str(args.criteria),
                   "run_files": len(runs), "result_files": len(results),
                   "perf": str(args.perf) if args.perf else None,
                   "stability": str(args.stability) if args.stability else None},
        "counts": tally, "counts_paper": paper, "problems": problems, "criteria": found,
        "findings": [c for c in findings(found) if c.outcome == FAIL],
        "environment": analysis.environment(runs),
        "cases": case_pages(runs, found, table, out, args.quick),
        "traceability": traceability.matrix(found, table, traceability.load_requirements(args.requirements)),
        "convergence": conv, "uncertainty": vv20, "speed_accuracy": speed, "figures": analysis.recorded_figures(results),
        "histories": hist, "stability": stability,
        "performance": perf_items(args.perf, out, args.quick),
        "paraview": paraview_view.read(args.paraview, out),
    }
    word = "FAIL" if tally["failed"] or problems else ("PASS" if tally["passed"] else "NOT RUN")
    report["verdict"] = word
    report["history"] = run_history(args.history, report, load_start, out, args.quick)
    for name, html in report_site.pages(report).items():
        (out / name).write_text(html, encoding="utf-8")
    summary = {k: report[k] for k in ("generated", "verdict", "inputs", "counts", "counts_paper", "problems", "environment",
                                      "convergence", "uncertainty", "traceability", "speed_accuracy", "figures",
                                      "paraview")}
    summary["history"] = {k: v for k, v in report["history"].items() if k != "entries"}
    summary["criteria"] = [c.as_dict() for c in found]
    summary["findings"] = [c.id for c in report["findings"]]
    summary["stability"] = [{k: v for k, v in s.items() if k != "points"} for s in report["stability"]]
    summary["performance"] = [{k: v for k, v in p.items() if k not in ("data", "rows")} for p in report["performance"]]
    (out / "summary.json").write_text(json.dumps(summary, indent=1, default=str), encoding="utf-8")

    print(f"{word}: {tally['passed']} passed, {tally['failed']} failed, {tally['not_run']} not run"
          f" -> {out / 'index.html'}")
    if paper["total"]:
        print(f"the paper's model (findings, not in the verdict): {paper['passed']} passed, {paper['failed']} "
              f"failed, {paper['not_run']} not run")
    for p in problems:
        print(f"problem: {p}", file=sys.stderr)
    return 1 if tally["failed"] or problems else 0


if __name__ == "__main__":
    sys.exit(main())
