"""The matrix's reader, its ctest generator, run.py's row and scripts/slurm_submit.py's scripts (issue 34).

No Slurm here: the submission is written with --dry-run; the real cluster is the nightly matrix_slurm_single_node.
"""
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
import matrix  # noqa: E402
import rows  # noqa: E402
import to_ctest  # noqa: E402

ROOT = HERE.parent.parent.parent
SUBMIT = ROOT / "scripts" / "slurm_submit.py"
SCENE = ROOT / "validation" / "scenes" / "martin_moyce_a10.toml"


def write(tmp_path, text: str) -> Path:
    p = tmp_path / "m.toml"
    p.write_text(text)
    return p


def test_every_validation_scene_is_a_run_of_the_matrix():
    m = matrix.load()
    scenes = sorted(p.resolve() for p in (ROOT / "validation" / "scenes").glob("*.toml"))
    assert sorted(r.scene for r in m.runs) == scenes
    assert {r.tier for r in m.runs} == {"quick", "nightly"}
    for c in m.checks:  # a check's runs exist (load raises otherwise) and the quick ones use quick runs only
        if c.tier == "quick":
            assert all(m.run(n).tier == "quick" for n in c.runs), c.name


@pytest.mark.parametrize("text, words", [
    ('[[run]]\nscene = "S"\ntier = "quick"\ntimeout_s = 1\ntiers = 2\n', ["[[run]] #1", "tiers"]),
    ('[[run]]\nscene = "S"\ntier = "weekly"\ntimeout_s = 1\n', ["[[run]] #1", "tier", "weekly"]),
    ('[[run]]\nscene = "S"\ntier = "quick"\n', ["[[run]] #1", "missing key `timeout_s`"]),
    ('[[run]]\nscene = "S"\ntier = "quick"\ntimeout_s = 0\n', ["timeout_s", "at least 1"]),
    ('[[run]]\nscene = "S"\ntier = "quick"\ntimeout_s = 1\nthreads = "2"\n', ["threads", "not of type int"]),
    ('[[run]]\nscene = "nowhere.toml"\ntier = "quick"\ntimeout_s = 1\n', ["nowhere.toml"]),
    ('[[run]]\nscene = "S"\ntier = "quick"\ntimeout_s = 1\n[[run]]\nscene = "S"\ntier = "quick"\ntimeout_s = 1\n',
     ["[[run]] #2", "second run named `martin_moyce_a10`"]),
    ('[[run]]\nscene = "S"\ntier = "quick"\ntimeout_s = 1\n[[check]]\nname = "c"\ncase = "x"\ntier = "quick"\n'
     'runs = ["dam_break"]\n', ["[[check]] #1", "dam_break"]),
    ('[[runs]]\nscene = "S"\n', ["unknown table", "runs"]),
])
def test_a_bad_matrix_names_the_entry_and_key(tmp_path, text, words):
    path = write(tmp_path, text.replace('"S"', json.dumps(str(SCENE))))
    with pytest.raises(matrix.MatrixError) as err:
        matrix.load(path)
    assert str(path) in str(err.value)
    for w in words:
        assert w in str(err.value)


def test_to_ctest_writes_one_call_a_run_recover_and_check(tmp_path):
    m = matrix.load()
    text = to_ctest.cmake_text(m)
    assert text.count("sph_matrix_run(") == len(m.runs) > 0
    assert "sph_matrix_run(dam_break quick" not in text and "sph_matrix_run(dam_break nightly 1500 1)" in text
    assert "sph_matrix_run(spheric_dam_break nightly 7200 1)" in text  # 3-D too: one thread
    assert text.count("sph_validation_recover(") == sum(1 for r in m.runs if r.recover_timeout_s)
    assert "sph_validation_check(two_fluids_quick two_fluids quick two_fluids_dx0.003 two_fluids_rho1050_dx0.006)" \
        in text
    out = tmp_path / "t.cmake"
    assert to_ctest.main([str(write(tmp_path, "[[run]]\n")), str(out)]) == 2 and not out.exists()


def test_a_paper_check_starts_after_the_named_runs_of_its_case():
    """validate.py counts a paper check's failures as findings when a named-model run file of its case is there
    (issue 31), so the check is ordered after those runs (DEPENDS: it pulls none of them into a selection)."""
    m = matrix.load()
    after = {line.split("(")[1].split()[0]: line.rstrip(")").split()[1:]
             for line in to_ctest.cmake_text(m).splitlines() if line.startswith("sph_validation_after(")}
    named = {c.case: set() for c in m.checks}
    for c in m.checks:
        named[c.case] |= {r for r in c.runs if r.endswith("_named")}
    for c in m.checks:
        paper = not any(r.endswith("_named") for r in c.runs)
        if paper and named[c.case]:
            assert set(after[c.name]) == named[c.case], c.name
        else:
            assert c.name not in after, c.name
    assert "two_fluids_named" in after["two_fluids_quick"] and "two_fluids_quick_named" not in after
    assert "dam_break_quick_named" not in after and "dam_break_lobovsky_named" in after["dam_break_quick"]


def fake_sph(tmp_path, body: str) -> Path:
    p = tmp_path / "sph"
    p.write_text("#!/bin/sh\n" + body + "\n")
    p.chmod(0o755)
    return p


def run_py(tmp_path, sph, env_extra=None):
    env = {k: v for k, v in os.environ.items() if not k.startswith("SLURM_")}
    env.update(env_extra or {})
    return subprocess.run([sys.executable, str(HERE.parent / "run.py"), "--name", "martin_moyce_a10", "--sph",
                           str(sph), "--runs", str(tmp_path / "runs"), "--rows", str(tmp_path / "rows")],
                          env=env, capture_output=True, text=True)


def test_run_writes_its_row_with_sph_exit_code_and_slurm_threads(tmp_path):
    done = run_py(tmp_path, fake_sph(tmp_path, 'echo "$@" > "$(dirname "$0")/args"; exit 3'),
                  {"SLURM_CPUS_PER_TASK": "5", "SLURM_JOB_ID": "41"})
    assert done.returncode == 3
    row = json.loads((tmp_path / "rows" / "martin_moyce_a10.json").read_text())
    assert row["exit_code"] == 3 and row["threads"] == 5 and row["slurm"]["SLURM_JOB_ID"] == "41"
    assert row["missing_outputs"] == ["martin_moyce_a10.h5", "martin_moyce_a10.xdmf"]
    assert "--threads 5" in (tmp_path / "args").read_text()
    m = matrix.load()
    assert rows.states([m.run("martin_moyce_a10"), m.run("dam_break")], tmp_path / "rows", tmp_path / "runs") == \
        {"martin_moyce_a10": "failed", "dam_break": "missing"}


def test_run_fails_when_sph_exits_0_without_its_outputs(tmp_path):
    done = run_py(tmp_path, fake_sph(tmp_path, "exit 0"))
    assert done.returncode == 1 and "left no martin_moyce_a10.h5" in done.stderr
    threads = matrix.load(matrix.DEFAULT_MATRIX).run("martin_moyce_a10").threads
    assert json.loads((tmp_path / "rows" / "martin_moyce_a10.json").read_text())["threads"] == threads


def submit(*args):
    return subprocess.run([sys.executable, str(SUBMIT), *map(str, args)], capture_output=True, text=True)


def test_dry_run_writes_one_array_a_thread_count_and_a_gather_job(tmp_path):
    # The matrix's own runs all take one thread; a matrix of three quick runs, one of them on two.
    runs = [("dam_break_dx0.025", 1), ("martin_moyce_a10", 1), ("spheric_dam_break_dx0.08", 2)]
    m = write(tmp_path, f'base = "{ROOT / "validation"}"\n' + "".join(
        f'[[run]]\nscene = "scenes/{n}.toml"\ntier = "quick"\ntimeout_s = 300\nthreads = {t}\n' for n, t in runs))
    done = submit("--out", tmp_path, "--matrix", m, "--tier", "quick", "--dry-run", "--partition", "batch",
                  "--account", "proj7", "--module", "hdf5/1.14", "--sph", "/opt/sph")
    assert done.returncode == 0, done.stderr
    sub = tmp_path / "slurm" / "submit-1"
    selected = matrix.load(m).select(["quick"])
    quick = [r.name for r in selected]
    one = [r.name for r in selected if r.threads == 1]  # one array a thread count
    assert 0 < len(one) < len(quick)
    assert (sub / "names-t1.txt").read_text().split() == one
    assert (sub / "names-t2.txt").read_text().split() == [r.name for r in selected if r.threads == 2]
    script = (sub / "array-t1.sbatch").read_text()
    for line in (f"#SBATCH --array=0-{len(one) - 1}", "#SBATCH --cpus-per-task=1", "#SBATCH --partition=batch",
                 "#SBATCH --account=proj7", "module load hdf5/1.14", "--index $SLURM_ARRAY_TASK_ID", "--sph /opt/sph",
                 "#SBATCH --time=6"):  # 300 s -> 5 min, and one to start
        assert line in script, line
    assert "#SBATCH --cpus-per-task=2" in (sub / "array-t2.sbatch").read_text()
    gather = (sub / "gather.sbatch").read_text()
    assert all(f"--run {n}" in gather for n in quick) and "#SBATCH --partition=batch" in gather


def test_resubmit_takes_only_the_failed_and_the_missing_runs(tmp_path):
    assert submit("--out", tmp_path, "--tier", "quick", "--dry-run").returncode == 0
    quick = matrix.load().select(["quick"])
    for k, r in enumerate(quick[:4]):  # four done, one failed, the rest without a row
        (tmp_path / "runs" / "quick").mkdir(parents=True, exist_ok=True)
        (tmp_path / "runs" / "quick" / f"{r.name}.h5").write_text("")
    (tmp_path / "rows").mkdir()
    for r, code in zip(quick[:5], (0, 0, 0, 0, 3)):
        (tmp_path / "rows" / f"{r.name}.json").write_text(json.dumps({"run": r.name, "exit_code": code}))
    done = submit("--out", tmp_path, "--resubmit", "--dry-run")
    assert done.returncode == 0, done.stderr
    again = [r.name for r in quick[4:] if r.threads == 1]  # the failed one and those without a row, on 1 thread
    assert (tmp_path / "slurm" / "submit-2" / "names-t1.txt").read_text().split() == again
    assert f"#SBATCH --array=0-{len(again) - 1}" in (tmp_path / "slurm" / "submit-2" / "array-t1.sbatch").read_text()
    # the gather job still gathers the whole selection
    assert all(f"--run {r.name}" in (tmp_path / "slurm" / "submit-2" / "gather.sbatch").read_text() for r in quick)


def test_resubmit_without_a_first_submission_is_bad_input(tmp_path):
    done = submit("--out", tmp_path, "--resubmit")
    assert done.returncode == 2 and "selection.json not found" in done.stderr


def test_a_runs_args_and_outputs_reach_sph_and_the_row(tmp_path):
    m = write(tmp_path, f'base = "{ROOT / "validation"}"\n[[run]]\nscene = "scenes/martin_moyce_a10.toml"\n'
                        'tier = "nightly"\ntimeout_s = 9\nthreads = 3\nargs = ["--fixed-threads"]\n'
                        'outputs = ["martin_moyce_a10.h5"]\n')
    sph = fake_sph(tmp_path, 'echo "$@" > "$(dirname "$0")/args"; exit 4')
    done = subprocess.run([sys.executable, str(HERE.parent / "run.py"), "--matrix", str(m), "--name",
                           "martin_moyce_a10", "--sph", str(sph), "--runs", str(tmp_path / "runs"), "--rows",
                           str(tmp_path / "rows")], capture_output=True, text=True,
                          env={k: v for k, v in os.environ.items() if not k.startswith("SLURM_")})
    assert done.returncode == 4
    args = (tmp_path / "args").read_text()
    assert f"--out {tmp_path / 'runs' / 'nightly'} --threads 3 --quiet --fixed-threads" in args
    row = json.loads((tmp_path / "rows" / "martin_moyce_a10.json").read_text())
    assert row["missing_outputs"] == ["martin_moyce_a10.h5"] and row["tier"] == "nightly"
