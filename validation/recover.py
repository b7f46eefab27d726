#!/usr/bin/python3
"""Issue 32's recover check (ctest label `recover`, as MOOSE's --recover mode): a validation scene
stopped at half its end time (`sph run --stop-at`, on THREADS threads) and continued from the
checkpoint that the stop wrote (`sph run --restart`, on 1 thread) must give the run file of the run
that did not stop, bit for bit (perf/compare_runs.py: every dataset, the physics attributes, the
/metrics counters). THREADS is the run's own (validation/matrix/matrix.toml), so that a 1-thread
run's check holds one core; a restart on another thread count is the quick tier's Restart tests'.

    recover.py SPH SCENE.toml REFERENCE.h5 OUT_DIR THREADS
"""
import os
import shutil
import subprocess
import sys
import tomllib

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "perf"))
import compare_runs  # noqa: E402


def run(command):
    print("+", " ".join(command), flush=True)
    done = subprocess.run(command)
    if done.returncode != 0:
        sys.exit(f"exit {done.returncode}: {' '.join(command)}")


def main(sph, scene_path, reference, out, threads):
    with open(scene_path, "rb") as f:
        scene = tomllib.load(f)
    half = 0.5 * scene["numerics"]["end_time"]
    shutil.rmtree(out, ignore_errors=True)
    run([sph, "run", scene_path, "--out", out, "--threads", threads, "--stop-at", repr(half), "--quiet"])
    checkpoint = os.path.join(out, scene["name"] + ".checkpoint.h5")
    run([sph, "run", "--restart", checkpoint, "--threads", "1", "--quiet"])
    compare_runs.main(reference, os.path.join(out, scene["name"] + ".h5"))


if __name__ == "__main__":
    if len(sys.argv) != 6 or not sys.argv[5].isdigit():
        sys.exit(__doc__)
    main(*sys.argv[1:])
