"""The table of perf/threads_under_load.sh: for each load and scene, the median wall time on 1 and
2 threads and their ratio, with the range of the ratios of the alternated pairs (pair k: the 2-thread
run over the 1-thread run), against issue 37's bars: 2 threads at most 0.65 of one thread's time on
an idle machine, at most 1.1 with a busy process on one core or on both. The last column: the
cores that work other than the benchmark's took while it ran (median and largest over the runs),
for a machine shared with others is never quite idle."""

import csv
import statistics
import sys

BARS = {"idle": 0.65, "one": 1.1, "both": 1.1}  # issue 37
LOADS = {"idle": "idle", "one": "one core busy", "both": "both cores busy"}


def main(path):
    walls = {}  # (load, scene) -> {threads: {repeat: wall}}
    others = {}  # (load, scene) -> the other work's cores, by run
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            key = (row["load"], row["scene"])
            walls.setdefault(key, {}).setdefault(int(row["threads"]), {})[int(row["repeat"])] = float(
                row["wall_s"]
            )
            others.setdefault(key, []).append(float(row["other_cores"]))
    print(
        "| load | scene | 1 thread [s] | 2 threads [s] | 2 / 1 (medians) | 2 / 1 by pair | bar "
        "| other work [cores] |"
    )
    print("|---|---|---|---|---|---|---|---|")
    for (load, scene), by in walls.items():
        one, two = by.get(1, {}), by.get(2, {})
        if not one or not two:
            continue
        m1, m2 = statistics.median(one.values()), statistics.median(two.values())
        pairs = sorted(two[r] / one[r] for r in one if r in two)
        bar = BARS.get(load)
        ok = bar is None or m2 / m1 <= bar
        print(
            f"| {LOADS.get(load, load)} | {scene} | {fmt(one.values())} | {fmt(two.values())} | "
            f"{m2 / m1:.2f} | {pairs[0]:.2f}-{pairs[-1]:.2f} | {'<= ' + str(bar) if bar else ''}"
            f"{'' if ok else ' MISSED'} | {statistics.median(others[(load, scene)]):.2f} "
            f"(max {max(others[(load, scene)]):.2f}) |"
        )
    return 0  # a benchmark: it reports, the bars are read from the table


def fmt(values):
    v = sorted(values)
    return f"{statistics.median(v):.2f} ({v[0]:.2f}-{v[-1]:.2f})"


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
