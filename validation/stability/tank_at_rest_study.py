#!/usr/bin/python3
"""The tank-at-rest study of issue 31: models x kernels x aspects x resolutions, one tank_at_rest_study call
each (verification/flows/TankAtRest.hpp), JOBS at a time on one thread each; writes a CSV and prints a
Markdown table of max|u|/sqrt(gH) and the bottom-pressure error over the second half of the run.

  /usr/bin/python3 validation/stability/tank_at_rest_study.py --tool build/release/verification/flows/tank_at_rest_study \
      --models paper,mc,fourtakas --kernels quadratic,cubic_spline,wendland_c2 --aspects 1,4 --cells 20,40 \
      --horizon 100 --jobs 2 --out tank_at_rest.csv
"""
import argparse
import concurrent.futures
import os
import subprocess
import sys

FIELDS = ["model", "kernel", "aspect", "cells", "horizon", "ran", "stopped_at", "speed", "bottom", "seconds",
          "verdict"]


def one(tool, model, kernel, aspect, cells, horizon, h_over_dx, cfl, dimension):
    env = dict(os.environ, OMP_NUM_THREADS="1", OMP_WAIT_POLICY="passive")
    r = subprocess.run([tool, model, kernel, str(aspect), str(cells), str(horizon), h_over_dx or "-", str(cfl),
                        str(dimension)], capture_output=True, text=True, env=env)
    if r.returncode != 0:
        sys.exit(f"tank_at_rest_study {model} {kernel} {aspect} {cells}: exit {r.returncode}: {r.stderr}")
    return r.stdout.strip()


def main():
    a = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    a.add_argument("--tool", required=True)
    a.add_argument("--models", default="paper,mc,fourtakas")
    a.add_argument("--kernels", default="quadratic,cubic_spline,wendland_c2")
    a.add_argument("--aspects", default="1,4")
    a.add_argument("--cells", default="20")
    a.add_argument("--horizon", type=float, default=100.0)
    a.add_argument("--h-over-dx", default=None, help="h/dx for every kernel (default: each kernel's own)")
    a.add_argument("--cfl", type=float, default=0.25, help="acoustic CFL number")
    a.add_argument("--dimension", type=int, default=2, choices=(2, 3), help="3: tanks ASPECT x 1 x 1 H")
    a.add_argument("--jobs", type=int, default=2)
    a.add_argument("--out", default="tank_at_rest.csv")
    o = a.parse_args()
    cases = [(m, k, float(asp), int(n)) for n in o.cells.split(",") for asp in o.aspects.split(",")
             for k in o.kernels.split(",") for m in o.models.split(",")]
    # the largest first, so that the pool ends together
    cases.sort(key=lambda c: -c[2] * c[3] ** (o.dimension + 1))
    with concurrent.futures.ThreadPoolExecutor(o.jobs) as pool:
        lines = list(pool.map(lambda c: one(o.tool, *c, o.horizon, o.h_over_dx, o.cfl, o.dimension), cases))
    rows = [dict(zip(FIELDS, line.split(","))) for line in lines]
    with open(o.out, "w") as f:
        f.write(",".join(FIELDS) + "\n" + "\n".join(lines) + "\n")
    rows.sort(key=lambda r: (int(r["cells"]), float(r["aspect"]), r["kernel"], r["model"]))
    print("| H/dx | aspect | kernel | model | reached t sqrt(g/H) | max\\|u\\|/sqrt(gH) | bottom p error | "
          "wall s | verdict |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['cells']} | {r['aspect']}:1 | {r['kernel']} | {r['model']} | {r['stopped_at']} | "
              f"{float(r['speed']):.2e} | {float(r['bottom']):.2e} | {r['seconds']} | {r['verdict']} |")


if __name__ == "__main__":
    main()
