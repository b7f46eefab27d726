#!/usr/bin/python3
"""Mutation driver for `sph check` and `sph run` (issue 32): scenes that `sph check` accepts must
run to an end that the program names (exit 0 done, 2 bad input, 3 numerical failure, 4 output
error), never a crash (a signal, any other exit code) or a hang (no end within the time limit).

  run_mutants.py SPH --runs N [--seed S] [--out DIR] [--results DIR] [--keep DIR]
  run_mutants.py SPH --replay DIR      (every *.toml in DIR: the crashers kept as regressions;
                                        a line `# expect: END` names the end it must reach)

The seeds are the shipped run scenes (validation/scenes, verification/core/scenes), each first cut
to a short run (end_time a fiftieth, snapshots every tenth of it) so that an accepted mutant costs
seconds. A mutant changes one to three lines of its seed: a number replaced by an extreme one
(0, -1, 5e-324, 1e-300, 1e300, nan, inf, a huge integer) or scaled, a boolean flipped or made a
number, a value made a string or an array, a line deleted or duplicated, a table renamed. `sph
check --max-steps` refuses a mutant whose estimated steps exceed the cap, and a mutant whose estimated
work exceeds WORK_CAP_S is checked but not run (counted as "not run: above the work cap"), so that
what runs stays short; the run's time limit is far above what such a run takes (CHECK_LIMIT_S,
RUN_LIMIT_S). The work is `sph check`'s: the steps times the force evaluations a step times the
wall time of one evaluation of the start, timed on one thread as the run has, so it counts what a
particle costs (ghosts, wall particles, neighbours, dimension) and the machine's load at the time.
Prints the counts and writes them as a verification result (Fuzz.RunMutants.json) for the report; a crash or a hang
is copied to --keep and fails the driver.
"""
import argparse
import json
import os
import pathlib
import random
import re
import shutil
import subprocess
import sys
import tempfile

import fuzz_result

SOURCE = pathlib.Path(__file__).resolve().parent.parent
SEEDS = sorted(list((SOURCE / "validation" / "scenes").glob("*.toml")) +
               list((SOURCE / "verification" / "core" / "scenes").glob("*.toml")))
NAMED_ENDS = {0: "done", 2: "bad input", 3: "numerical failure", 4: "output error"}
MAX_STEPS = 3000     # refused beyond: a run of at most this many steps
CHECK_LIMIT_S = 60   # `sph check` builds the start and evaluates it once: seconds at most
RUN_LIMIT_S = 120    # 3000 steps of the largest seed (two_fluids_dx0.001, 1e5 particles) ~ 60 s
# The estimate is 0.4-0.75 of a run's time (measured 2026-12-03: the dam break, the SPHERIC case: its
# flow reaches more wall particles than its start, and lists are rebuilt, output written), so a run
# estimated at the cap ends within 30 / 0.4 = 75 s, below RUN_LIMIT_S.
WORK_CAP_S = 30
EXTREMES = ["0", "-1", "5e-324", "1e-300", "1e300", "nan", "inf", "-inf", "9223372036854775807",
            "1e-9", "1e9", "0.5", "2"]
NUMBER = re.compile(r"(?<![A-Za-z_\"])-?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?(?![A-Za-z_\"])")


def shortened(text):
    """The seed cut to a short run: end_time / 50, snapshots at a tenth of that."""
    end = re.search(r"^end_time\s*=\s*([0-9.eE+-]+)", text, re.M)
    if not end:
        return text
    t = float(end.group(1)) / 50
    text = re.sub(r"^end_time\s*=.*$", f"end_time = {t:.6g}", text, flags=re.M)
    text = re.sub(r"^snapshot_interval\s*=.*$", f"snapshot_interval = {t / 10:.6g}", text,
                  flags=re.M)
    return text


def mutate(text, rng):
    lines = text.split("\n")
    # Mostly one change, mostly to a number: the structural breaks (types, tables, truncated lines)
    # are refused by the reader, which the libFuzzer target covers far faster; a run needs a scene
    # that passes it (about 1 mutant in 4 with these weights, against 1 in 10 with uniform ones).
    for _ in range(rng.choice([1, 1, 1, 2, 3])):
        candidates = [i for i, l in enumerate(lines) if l.strip() and not l.lstrip().startswith("#")]
        if not candidates:
            break
        i = rng.choice(candidates)
        line = lines[i]
        op = rng.choices(range(7), weights=[3, 2, 6, 1, 1, 0.5, 0.5])[0]
        numbers = list(NUMBER.finditer(line.split("#")[0]))
        if op <= 2 and numbers:
            m = rng.choice(numbers)
            value = rng.choice(EXTREMES) if op < 2 else repr(float(m.group(0)) * rng.choice(
                [1e-3, 0.1, 0.5, 2, 10, 1e3, -1]))
            lines[i] = line[:m.start()] + value + line[m.end():]
        elif op == 3 and "=" in line:
            key, value = line.split("=", 1)
            if value.strip() in ("true", "false"):
                value = rng.choice([" 1", " 0", ' "true"', " false" if "true" in value else " true"])
            else:
                value = rng.choice([' "x"', " []", " [1, 2]", " {}", ' "../x"', " true"])
            lines[i] = key + "=" + value
        elif op == 4:
            del lines[i]
        elif op == 5:
            lines.insert(i, line)
        elif line.lstrip().startswith("["):
            lines[i] = line.replace("]", "x]", 1)
        else:
            lines[i] = line[: max(1, len(line) // 2)]
    return "\n".join(lines)


def outcome(cmd, limit, output=None):
    """The named end of `cmd` and its stderr; its stdout appended to `output` (a list) if given."""
    try:
        # (one thread: `sph run --threads 1`, and `sph check` times its evaluation on as many)
        done = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=limit,
                              env=dict(os.environ, OMP_WAIT_POLICY="passive", OMP_NUM_THREADS="1"))
    except subprocess.TimeoutExpired:
        return "hang", ""
    if output is not None:
        output.append(done.stdout.decode(errors="replace"))
    if done.returncode in NAMED_ENDS:
        return NAMED_ENDS[done.returncode], done.stderr.decode(errors="replace")
    return f"crash (exit {done.returncode})", done.stderr.decode(errors="replace")


WORK = re.compile(r"so about ([0-9.e+-]+) s of force evaluations")


def work_of(check_output: str) -> float:
    """The seconds of force evaluations of `sph check`'s estimate (0 where it gives none)."""
    m = WORK.search(check_output)
    return float(m.group(1)) if m else 0.0


def trial(sph, scene, work):
    """The ends of `sph check` and, if it accepts and the run is within WORK_CAP, `sph run`."""
    said = []
    check, why = outcome([sph, "check", str(scene), "--out", str(work), "--max-steps",
                          str(MAX_STEPS), "--max-memory", "4G"], CHECK_LIMIT_S, said)
    if check != "done":
        return check, None, why
    if work_of("".join(said)) > WORK_CAP_S:
        return check, ABOVE_CAP, ""
    ran, why = outcome([sph, "run", str(scene), "--out", str(work), "--threads", "1", "--quiet",
                        "--max-steps", str(MAX_STEPS), "--max-memory", "4G"], RUN_LIMIT_S)
    return check, ran, why


ABOVE_CAP = "not run: above the work cap"


def bad(end):
    return end is not None and (end.startswith("crash") or end == "hang")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("sph")
    ap.add_argument("--runs", type=int, default=0, help="mutants to run through `sph run`")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--replay", type=pathlib.Path)
    ap.add_argument("--results", type=pathlib.Path)
    ap.add_argument("--keep", type=pathlib.Path, default=pathlib.Path("fuzz-crashers"))
    a = ap.parse_args()
    work = pathlib.Path(tempfile.mkdtemp(prefix="sph-mutants-"))
    counts = {"checked": 0, "accepted": 0, "ran": 0, "crashes": 0, "hangs": 0, "ends": {}}
    failures = []
    try:
        if a.replay:
            scenes = [(p, p.read_text()) for p in sorted(a.replay.glob("*.toml"))]
        else:
            rng = random.Random(a.seed)
            seeds = [(p, shortened(p.read_text())) for p in SEEDS]
            scenes = []
        k = 0
        while (a.replay and k < len(scenes)) or (not a.replay and counts["ran"] < a.runs):
            if a.replay:
                origin, text = scenes[k]
            else:
                origin, seed = rng.choice(seeds)
                text = mutate(seed, rng)
            k += 1
            scene = work / f"mutant{k}.toml"
            scene.write_text(text)
            check, ran, why = trial(a.sph, scene, work / "out")
            counts["checked"] += 1
            for end in (check, ran):
                if end is not None:
                    counts["ends"][end] = counts["ends"].get(end, 0) + 1
            if check == "done":
                counts["accepted"] += 1
                counts["ran"] += ran != ABOVE_CAP
            if bad(check) or bad(ran):
                counts["hangs" if "hang" in (check, ran) else "crashes"] += 1
                failures.append((origin, text, check, ran, why))
            elif a.replay:
                expected = re.search(r"^# expect: (.*)$", text, re.M)
                end = ran if ran is not None else check
                if expected and expected.group(1).strip() != end:
                    counts["unexpected"] = counts.get("unexpected", 0) + 1
                    failures.append((origin, text, check, ran, f"expected {expected.group(1)}\n" + why))
            shutil.rmtree(work / "out", ignore_errors=True)
            if not a.replay and k > 200 * max(1, a.runs):
                break  # the mutants are refused far more often than expected: stop and say so
    finally:
        shutil.rmtree(work, ignore_errors=True)
    if failures:
        a.keep.mkdir(parents=True, exist_ok=True)
        for n, (origin, text, check, ran, why) in enumerate(failures):
            (a.keep / f"crasher{n}.toml").write_text(
                f"# from {origin.name}: check {check}, run {ran}\n" + text)
            print(f"{origin.name}: check {check}, run {ran}\n{why[-2000:]}", file=sys.stderr)
    print(json.dumps(counts, indent=1))
    if a.results:
        a.results.mkdir(parents=True, exist_ok=True)
        name = "Replay" if a.replay else "RunMutants"
        (a.results / f"Fuzz.{name}.json").write_text(json.dumps(fuzz_result.result(
            f"Fuzz.{name}", "accepted mutants through sph run", counts["ran"], 0 if a.replay else a.runs,
            counts["crashes"], counts["hangs"], counts)))
    if not a.replay and counts["ran"] < a.runs:
        print(f"only {counts['ran']} of {a.runs} mutants were accepted", file=sys.stderr)
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
