"""validate.py's exit code and the report's verdict follow one rule (runfile.in_verdict, issue 31): a failed check of
the paper's model in a case the named model runs too is a finding, printed and recorded, failing nothing; a failed
check of the named model, or of the paper's model in a case without named runs, fails."""
import json
import sys
from pathlib import Path

import pytest

import criteria
from runfile import NAMED, PAPER, in_verdict

sys.path.insert(0, str(Path(__file__).resolve().parent.parent.parent / "validation"))
import validate  # noqa: E402


def recorded(results: Path, name: str) -> list:
    return [(c["name"], c["pass"], c["model"])
            for c in json.loads((results / f"validation.{name}.json").read_text())["checks"]]


@pytest.mark.parametrize("model, case, named, counts", [
    (PAPER, "dam_break", {"dam_break"}, False),  # the named model runs the case: a finding
    (PAPER, "dam_break", set(), True),  # no named run: the paper's model is the case's model
    (PAPER, "two_fluids", {"dam_break", "drop_into_pool"}, True),  # other cases' named runs change nothing
    (NAMED, "dam_break", {"dam_break"}, True),
    ("", "Poiseuille.SteadyProfile", {"dam_break"}, True),  # a verification test
])
def test_in_verdict(model, case, named, counts):
    assert in_verdict(model, case, named) is counts


def test_results_fail_on_the_verdicts_checks_only(tmp_path, capsys):
    res = validate.Results("dam_break", "dam_break", named_cases={"dam_break"})
    res.check("dam_break_lobovsky", "sensor-2 impulse", 3.74, "<=", 3.123, "Lobovsky et al. 2014, 97.5 %")
    res.check("dam_break_lobovsky_named", "sensor-2 impulse", 3.0, "<=", 3.123, "Lobovsky et al. 2014, 97.5 %")
    assert res.write(tmp_path)  # the paper's failure is a finding: exit 0
    out = capsys.readouterr().out
    assert "FINDING  dam_break_lobovsky: sensor-2 impulse: 3.74 <= 3.123" in out and "\nFAIL" not in out
    assert "the paper's model fails it; the named model decides case dam_break" in out
    # The results file records it failed, as before: the report lists it among its findings.
    assert recorded(tmp_path, "dam_break") == [("dam_break_lobovsky: sensor-2 impulse", False, PAPER),
                                               ("dam_break_lobovsky_named: sensor-2 impulse", True, NAMED)]
    res.check("dam_break_lobovsky_named", "sensor-2 impulse", 3.79, "<=", 3.123, "Lobovsky et al. 2014, 97.5 %")
    assert not res.write(tmp_path)  # a named failure fails
    assert "FAIL  dam_break_lobovsky_named: sensor-2 impulse: 3.79" in capsys.readouterr().out

    two = validate.Results("two_fluids", "two_fluids", named_cases={"dam_break", "drop_into_pool"})
    two.check("two_fluids", "heavy front speed / light front speed", 0.739, ">", 1.0, "Lowe et al. 2005")
    assert not two.write(tmp_path)  # no named twin: the paper's failure is the verdict's
    assert "FAIL  two_fluids: heavy front speed" in capsys.readouterr().out


def test_validate_exit_code_agrees_with_the_report(tmp_path, make_run, capsys):
    """validate.py over run directories, then the report's criteria over the same runs and results."""
    runs, results = tmp_path / "runs", tmp_path / "results"
    (runs / "quick").mkdir(parents=True)
    where = ["--runs", str(runs / "quick"), "--runs", str(runs / "nightly"), "--results", str(results)]
    # The paper's run file missing and no named run of the case: a failure of the paper's model, in the verdict.
    assert validate.main(["dam_break", "dam_break_dx0.025", *where, "--name", "dam_break_quick"]) == 1
    assert "FAIL  dam_break_dx0.025: run file present" in capsys.readouterr().out
    # With a named-model run of the case the same failure is a finding.
    make_run(runs / "quick" / "dam_break_dx0.025_named.h5", "dam_break_dx0.025_named", kernel="wendland_c2")
    assert validate.main(["dam_break", "dam_break_dx0.025", *where, "--name", "dam_break_quick"]) == 0
    assert "FINDING  dam_break_dx0.025: run file present" in capsys.readouterr().out
    assert recorded(results, "dam_break_quick") == [("dam_break_dx0.025: run file present", False, PAPER)]
    # The named model's check fails on its own missing run; the two-fluid check has no named twin and fails.
    assert validate.main(["dam_break", "dam_break_named", *where, "--name", "dam_break_named"]) == 1
    assert validate.main(["two_fluids", "two_fluids", *where, "--name", "two_fluids"]) == 1
    out = capsys.readouterr().out
    assert "FAIL  dam_break_named: run file present" in out and "FAIL  two_fluids: run file present" in out

    found = criteria.collect(runs, results)
    assert {c.metric for c in criteria.findings(found) if c.outcome == criteria.FAIL} == \
        {"dam_break_dx0.025: run file present"}
    assert {c.metric for c in criteria.judged(found) if c.outcome == criteria.FAIL} == \
        {"dam_break_named: run file present", "two_fluids: run file present"}
