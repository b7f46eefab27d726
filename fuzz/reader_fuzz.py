#!/usr/bin/python3
"""Runs the libFuzzer scene-reader target and writes its counts as a verification result for the report.

  reader_fuzz.py RESULTS_DIR REQUIRED_INPUTS -- FUZZER [libFuzzer arguments...]

The fuzzer's own exit decides the test (libFuzzer exits non-zero on a crash, a leak, a timeout or an out-of-memory,
and leaves the input as crash-/timeout-/oom-* beside its artifact prefix). The inputs tried come from its
-print_final_stats line `stat::number_of_executed_units: N`; a timeout or out-of-memory counts as a hang, any other
non-zero exit as a crash.
"""
import json
import pathlib
import re
import subprocess
import sys

import fuzz_result


def main(argv) -> int:
    if len(argv) < 4 or argv[2] != "--":
        print(__doc__, file=sys.stderr)
        return 2
    results, required, command = pathlib.Path(argv[0]), int(float(argv[1])), argv[3:]
    done = subprocess.run(command, stderr=subprocess.PIPE, text=True, errors="replace")
    sys.stderr.write(done.stderr[-20000:])
    units = re.findall(r"stat::number_of_executed_units:\s*(\d+)", done.stderr)
    inputs = int(units[-1]) if units else 0
    hang = done.returncode != 0 and re.search(r"ALARM: working on the last Unit|out-of-memory", done.stderr)
    crashes = 1 if done.returncode != 0 and not hang else 0
    counts = {"inputs": inputs, "exit": done.returncode}
    results.mkdir(parents=True, exist_ok=True)
    (results / "Fuzz.SceneReader.json").write_text(json.dumps(fuzz_result.result(
        "Fuzz.SceneReader", "inputs through the scene reader", inputs, required, crashes, 1 if hang else 0, counts)))
    print(f"scene reader fuzz: {inputs} inputs, exit {done.returncode}")
    return done.returncode if done.returncode else (0 if inputs >= required else 1)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
