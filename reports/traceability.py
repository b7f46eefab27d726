"""Requirement -> criteria -> verdict: the traceability matrix of the report.

Requirements come from two files: each [[scene]] entry of validation/criteria.toml carries its own `id` and
`requirement`, and verification/requirements.toml gives the requirements of the verification tests' groups (the
GoogleTest suite, the part of a test's name before the dot, or "validation.<case>" for validate.py's results).
The run-status criterion the report adds itself has STATUS_REQUIREMENT.
"""
from __future__ import annotations

import re
import tomllib
from pathlib import Path

from criteria import FAIL, NOT_RUN, PASS
from runfile import family

ROOT = Path(__file__).resolve().parent.parent
DEFAULT_REQUIREMENTS = ROOT / "verification" / "requirements.toml"
STATUS_REQUIREMENT = {"id": "VAL-RUN-1", "requirement": "The solver shall run every validation scene to its end time "
                      "without a numerical failure (run file status stable).", "source": "reports/SCHEMA.md, status"}
ID_PATTERN = re.compile(r"^(VER|VAL)-[A-Z]{2,4}-[0-9]+$")
VALIDATION_CASES = ("dam_break", "martin_moyce", "drop_into_pool", "two_fluids", "spheric_dam_break")


def load_requirements(path: Path = DEFAULT_REQUIREMENTS) -> list:
    """[{id, requirement, source, groups}]; ValueError naming the file and the entry when one is malformed."""
    with open(path, "rb") as f:
        table = tomllib.load(f)
    out = []
    for k, e in enumerate(table.get("requirement", [])):
        missing = {"id", "requirement", "source", "groups"} - set(e)
        if missing:
            raise ValueError(f"{path}: [[requirement]] number {k + 1} ({e.get('id', 'no id')}) lacks {sorted(missing)}")
        out.append(e)
    return out


def group_of(test: str) -> str:
    """The group of a verification result's test name: "Kernels.NormalisedToOne" -> "Kernels",
    "validation.dam_break_quick" -> "validation.dam_break"."""
    if test.startswith("validation."):
        return "validation." + family(test[len("validation."):].removesuffix("_quick"), VALIDATION_CASES)
    return test.split(".", 1)[0]


def requirement_index(requirements: list) -> dict:
    """{group: requirement}."""
    return {g: r for r in requirements for g in r["groups"]}


def criterion_requirement(c, table: dict, by_group: dict) -> str:
    """The requirement ID of one decided criterion ("" when none traces it)."""
    if c.kind == "verification":
        r = by_group.get(group_of(c.case))
        return r["id"] if r else ""
    if c.metric in ("status", "run file readable"):
        return STATUS_REQUIREMENT["id"]
    for e in table.get(c.case, []):
        if e["metric"] == c.metric and e["comparison"] == c.comparison and e["threshold"] == c.threshold:
            return str(e.get("id", ""))
    return ""


def matrix(found: list, table: dict, requirements: list) -> dict:
    """{"rows": [{id, requirement, source, passed, failed, not_run, verdict, criteria: [criterion ids]}],
    "untraced": [criterion ids without a requirement]}; failing requirements first."""
    reqs = {STATUS_REQUIREMENT["id"]: dict(STATUS_REQUIREMENT)}
    for scene, entries in table.items():
        for e in entries:
            reqs[str(e.get("id", ""))] = {"id": str(e.get("id", "")), "requirement": str(e.get("requirement", "")),
                                          "source": e["source"]}
    for r in requirements:
        reqs[r["id"]] = {"id": r["id"], "requirement": r["requirement"], "source": r["source"]}
    by_group = requirement_index(requirements)
    tally = {rid: {PASS: 0, FAIL: 0, NOT_RUN: 0, "criteria": []} for rid in reqs}
    untraced = []
    for c in found:
        rid = criterion_requirement(c, table, by_group)
        if rid not in tally:
            untraced.append(c.id)
            continue
        tally[rid][c.outcome] += 1
        tally[rid]["criteria"].append(c.id)
    rows = []
    for rid, r in reqs.items():
        t = tally[rid]
        # NO RECORD: no criterion reached the report; the group's tests may still have run in ctest, which decides
        # them by exit code, but they write no result file (SCHEMA.md) the report could re-check.
        verdict = "FAIL" if t[FAIL] else ("PASS" if t[PASS] else ("NOT RUN" if t[NOT_RUN] else "NO RECORD"))
        rows.append(dict(r, passed=t[PASS], failed=t[FAIL], not_run=t[NOT_RUN], verdict=verdict,
                         criteria=t["criteria"]))
    order = {"FAIL": 0, "PASS": 1, "NOT RUN": 2, "NO RECORD": 3}
    rows.sort(key=lambda r: (order[r["verdict"]], r["id"]))
    return {"rows": rows, "untraced": untraced}


def problems(table: dict, requirements: list, suites: list) -> list:
    """What breaks traceability: a criterion without an ID or sentence, an ID used twice or malformed, a suite of
    `suites` in no group or in two."""
    out, seen = [], {}
    entries = [(f"validation/criteria.toml [[{scene}]] {e['metric']}", e) for scene, es in table.items() for e in es]
    entries += [(f"verification/requirements.toml {r['groups']}", r) for r in requirements]
    entries.append(("reports/traceability.py STATUS_REQUIREMENT", STATUS_REQUIREMENT))
    for where, e in entries:
        rid = str(e.get("id", ""))
        if not rid:
            out.append(f"{where}: no requirement id")
            continue
        if not ID_PATTERN.match(rid):
            out.append(f"{where}: id {rid!r} is not VER-/VAL-<area>-<n>")
        if not str(e.get("requirement", "")).startswith("The solver shall "):
            out.append(f"{where}: requirement of {rid} does not read 'The solver shall ...'")
        if rid in seen:
            out.append(f"{where}: id {rid} also used by {seen[rid]}")
        seen.setdefault(rid, where)
    count = {}
    for r in requirements:
        for g in r["groups"]:
            count[g] = count.get(g, 0) + 1
    for s in suites:
        if count.get(s, 0) == 0:
            out.append(f"verification suite {s}: in no [[requirement]] group of verification/requirements.toml")
    out += [f"group {g}: in {n} requirements" for g, n in count.items() if n > 1]
    return out


_SUITE = re.compile(r"^\s*(?:TEST|TEST_F|TEST_P|TYPED_TEST)\(\s*([A-Za-z0-9_]+)\s*,", re.M)


def suites_in(directory: Path = ROOT / "verification") -> list:
    """Every GoogleTest suite named in the C++ sources under `directory`."""
    names = set()
    for p in Path(directory).rglob("*.cpp"):
        names.update(_SUITE.findall(p.read_text(encoding="utf-8", errors="replace")))
    return sorted(names)
