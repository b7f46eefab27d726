"""Traceability: every criterion and every verification suite carries one requirement ID, none used twice."""
import json

import criteria
import traceability as T
import vv_report


def test_repository_criteria_and_suites_are_all_traced():
    table = criteria.load_criteria()
    reqs = T.load_requirements()
    suites = T.suites_in()
    assert len(suites) > 50  # the scan finds the suites (62 on 2026-12-02), not an empty directory
    assert T.problems(table, reqs, suites) == []


def test_a_missing_or_duplicated_id_is_a_problem():
    table = {"dam_break": [{"metric": "m", "comparison": "<", "threshold": 1, "source": "s"},
                           {"metric": "n", "comparison": "<", "threshold": 1, "source": "s", "id": "VAL-DB-1",
                            "requirement": "The solver shall x."}]}
    reqs = [{"id": "VAL-DB-1", "requirement": "The solver shall y.", "source": "s", "groups": ["A"]},
            {"id": "VER-B-1", "requirement": "It does z.", "source": "s", "groups": ["A"]}]
    found = T.problems(table, reqs, ["A", "B"])
    assert any("[[dam_break]] m: no requirement id" in p for p in found)
    assert any("id VAL-DB-1 also used" in p for p in found)
    assert any("VER-B-1" in p and "not VER-/VAL-" in p for p in found)  # one letter: not an area code
    assert any("does not read 'The solver shall" in p for p in found)
    assert any("suite B: in no" in p for p in found) and any("group A: in 2" in p for p in found)


def test_group_of_results():
    assert T.group_of("Kernels.NormalisedToOne") == "Kernels"
    assert T.group_of("validation.dam_break_quick") == "validation.dam_break"
    assert T.group_of("validation.two_fluids") == "validation.two_fluids"


def test_matrix_in_the_report(tmp_path, make_run, make_result):
    make_run(tmp_path / "runs" / "dam_break.h5", "dam_break", max_volume_variation=0.01)  # fails VAL-DB-1
    make_result(tmp_path / "results" / "Kernels.NormalisedToOne.json", test="Kernels.NormalisedToOne")
    make_result(tmp_path / "results" / "Nowhere.Test.json", test="Nowhere.Test")  # no requirement
    out = tmp_path / "out"
    vv_report.main(["--runs", str(tmp_path / "runs"), "--results", str(tmp_path / "results"), "--out", str(out),
                    "--quick"])
    summary = json.loads((out / "summary.json").read_text())
    rows = {r["id"]: r for r in summary["traceability"]["rows"]}
    assert rows["VAL-DB-1"]["verdict"] == "FAIL" and rows["VAL-DB-1"]["failed"] == 1
    assert rows["VER-KER-1"]["verdict"] == "PASS" and rows["VAL-RUN-1"]["passed"] == 1
    assert rows["VAL-DP-1"]["verdict"] == "NOT RUN" and rows["VER-NBR-1"]["verdict"] == "NO RECORD"
    assert len(summary["traceability"]["untraced"]) == 1
    assert summary["traceability"]["rows"][0]["verdict"] == "FAIL"  # failures first
