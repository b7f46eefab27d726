"""Pass/fail criteria: built from validation/criteria.toml, the run files and the verification JSON, and decided.

One criterion is one line of the report, one pytest test (reports/test_criteria.py) and one JUnit testcase.
"""
from __future__ import annotations

import math
import operator
import tomllib
from dataclasses import asdict, dataclass
from pathlib import Path

from runfile import NAMED, family, in_verdict, model_of, read_results, read_runs

COMPARISONS = {"<": operator.lt, "<=": operator.le, ">": operator.gt, ">=": operator.ge, "==": operator.eq}
PASS, FAIL, NOT_RUN = "pass", "fail", "not run"
DEFAULT_CRITERIA = Path(__file__).resolve().parent.parent / "validation" / "criteria.toml"
STATUS_SOURCE = "every run must reach its end time: run file attribute `status` (reports/SCHEMA.md)"


@dataclass
class Criterion:
    case: str  # scene family (dam_break) or verification test (Poiseuille.SteadyProfile)
    run: str  # run label (file path under --runs) or result file name; "" when not run
    metric: str
    comparison: str
    threshold: object
    source: str
    measured: object = None
    outcome: str = NOT_RUN
    message: str = ""
    run_time_s: float | None = None
    kind: str = "validation"  # or "verification"
    id: str = ""
    model: str = ""  # PAPER or NAMED for a validation run or validate.py check; "" for a verification test
    family: str = ""  # the validation case (dam_break, ..., two_fluids) of a run or validate.py check

    def as_dict(self) -> dict:
        return asdict(self)

    def describe(self) -> str:
        return f"{self.metric} {self.comparison} {self.threshold}"


def load_criteria(path: Path = DEFAULT_CRITERIA) -> dict:
    """{scene name: [ {metric, comparison, threshold, source}, ... ]}; raises ValueError on a malformed file."""
    with open(path, "rb") as f:
        table = tomllib.load(f)
    for scene, entries in table.items():
        if not isinstance(entries, list):
            raise ValueError(f"{path}: [{scene}] must be an array of tables ([[{scene}]])")
        for e in entries:
            missing = {"metric", "comparison", "threshold", "source"} - set(e)
            if missing:
                raise ValueError(f"{path}: a [[{scene}]] entry lacks {sorted(missing)}")
            if e["comparison"] not in COMPARISONS:
                raise ValueError(f"{path}: [[{scene}]] {e['metric']}: unknown comparison {e['comparison']!r}")
    return table


def compare(measured, comparison: str, threshold) -> bool:
    """measured <comparison> threshold; a missing or non-finite number never passes."""
    if comparison == "==":
        return measured == threshold
    if isinstance(measured, bool) or not isinstance(measured, (int, float)) or not math.isfinite(measured):
        return False
    return bool(COMPARISONS[comparison](measured, threshold))


def _decide(c: Criterion, extra: str = "") -> Criterion:
    ok = compare(c.measured, c.comparison, c.threshold)
    c.outcome = PASS if ok else FAIL
    verdict = "holds" if ok else "does not hold"
    c.message = f"measured {c.measured!r} {c.comparison} {c.threshold!r} {verdict} (source: {c.source}){extra}"
    return c


def run_criteria(runs: list, table: dict) -> list:
    out = []
    seen_cases = set()
    for run in runs:
        case = family(run.scene_name, table)
        seen_cases.add(case)
        wall = run.metrics.get("wall_time_s")
        common = dict(case=case, run=run.label, run_time_s=wall if isinstance(wall, (int, float)) else None,
                      model=model_of(run.scene_name), family=case)
        if run.read_error:
            c = Criterion(metric="run file readable", comparison="==", threshold=True, source="reports/SCHEMA.md",
                          measured=False, **common)
            out.append(_decide(c, f"; {run.read_error}"))
            continue
        status = run.attrs.get("status")
        why = "; ".join(str(run.attrs[k]) for k in ("failure_cause", "failure") if run.attrs.get(k))
        out.append(_decide(Criterion(metric="status", comparison="==", threshold="stable", source=STATUS_SOURCE,
                                     measured=status, **common), f"; {why}" if why else ""))
        for e in table.get(case, []):
            measured = run.metrics.get(e["metric"])
            c = Criterion(metric=e["metric"], comparison=e["comparison"], threshold=e["threshold"],
                          source=e["source"], measured=measured, **common)
            out.append(_decide(c, "" if measured is not None else "; metric missing from /metrics"))
    for case in sorted(set(table) - seen_cases):
        for e in table[case]:
            out.append(Criterion(case=case, run="", metric=e["metric"], comparison=e["comparison"],
                                 threshold=e["threshold"], source=e["source"], family=case,
                                 message="not run: no run file of this scene"))
    return out


def verification_criteria(results: list) -> list:
    out = []
    for res in results:
        name = res.path.name
        if res.read_error:
            c = Criterion(case=res.path.stem, run=name, metric="result file readable", comparison="==",
                          threshold=True, source="reports/SCHEMA.md", measured=False, kind="verification")
            out.append(_decide(c, f"; {res.read_error}"))
            continue
        validation = res.test.startswith("validation.")  # validate.py's checks: a model and a case each
        for check in res.data.get("checks", []):
            comparison = check.get("comparison", "<=")
            metric = str(check.get("name", "?"))
            model = str(check.get("model") or model_of(metric.split(": ", 1)[0])) if validation else ""
            c = Criterion(case=res.test, run=name, metric=metric, comparison=comparison,
                          threshold=check.get("threshold"), source=str(check.get("source", "")),
                          measured=check.get("measured"), kind="verification", model=model,
                          family=str(res.data.get("case") or "") if validation else "")
            if comparison not in COMPARISONS:
                c.outcome, c.message = FAIL, f"unknown comparison {comparison!r}"
                out.append(c)
                continue
            _decide(c)
            asserted = check.get("pass")
            if asserted is not None and bool(asserted) != (c.outcome == PASS):
                c.outcome = FAIL
                c.message += f"; the test recorded pass={asserted}, the re-check disagrees"
            out.append(c)
    return out


def _order(c: Criterion):
    return ({FAIL: 0, NOT_RUN: 1, PASS: 2}[c.outcome], c.kind != "validation", c.case, c.run, c.metric)


def collect(runs_dir, results_dir, criteria_file: Path = DEFAULT_CRITERIA, runs=None, results=None) -> list:
    """Every criterion, decided, failures first, each with a unique readable id (threshold and source in it)."""
    runs = read_runs(runs_dir) if runs is None else runs
    results = read_results(results_dir) if results is None else results
    table = load_criteria(criteria_file)
    found = sorted(run_criteria(runs, table) + verification_criteria(results), key=_order)
    used = set()
    for c in found:
        base = f"{c.run or c.case} | {c.describe()} | {c.source}"
        c.id, n = base, 2
        while c.id in used:
            c.id, n = f"{base} #{n}", n + 1
        used.add(c.id)
    return found


def counts(found: list) -> dict:
    return {"total": len(found), "passed": sum(c.outcome == PASS for c in found),
            "failed": sum(c.outcome == FAIL for c in found), "not_run": sum(c.outcome == NOT_RUN for c in found)}


def judged(found: list) -> list:
    """The criteria the verdict is about (issue 31): every verification test, and of each validation case the
    named model's criteria; where a case has no named-model criterion its paper's criteria, the model that case
    runs. A case's named-model check
    that lost its runs still records a failed criterion (validate.py: "run file present"), so a missing named run
    never hands the verdict back to the paper's rows. validate.py's exit code follows the same rule
    (runfile.in_verdict), its named cases read from the run files the report reads."""
    named_cases = {c.family for c in found if c.model == NAMED}
    return [c for c in found if in_verdict(c.model, c.family, named_cases)]


def findings(found: list) -> list:
    """The paper's model's criteria in the cases the named model runs: shown beside the named model's, every
    failure listed, none of them in the verdict."""
    kept = {id(c) for c in judged(found)}
    return [c for c in found if id(c) not in kept]
