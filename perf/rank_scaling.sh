#!/usr/bin/env bash
# Weak and strong scaling of the dam break over MPI processes on this machine (issue 35), the runs
# alternated in rounds so that a change of the machine's load hits every case alike:
#   weak    1 process with N particles, 2 processes with 2N (N a process)
#   strong  2N on 1 process, on 2 processes of 1 thread, and on 1 process of 2 threads (OpenMP)
# Prints the JSON lines (perf/rank_scaling.cpp) and a table of medians: particle-steps per second,
# efficiency (weak: t1/t2; strong: t1/(2 t2)), halo and migration seconds a step. Runs with more
# processes x threads than cores are flagged "oversubscribed" in the JSON.
# usage: perf/rank_scaling.sh [--build DIR] [--per-process N] [--steps S] [--rounds R] [--scene F]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="$here/../build/release" per=200000 steps=100 rounds=3 scene="$here/../validation/scenes/dam_break.toml"
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --per-process) per="$2"; shift 2 ;;
    --steps) steps="$2"; shift 2 ;;
    --rounds) rounds="$2"; shift 2 ;;
    --scene) scene="$2"; shift 2 ;;
    *) echo "rank_scaling.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done
exe="$build/perf/rank_scaling"
[ -x "$exe" ] || { echo "rank_scaling.sh: $exe not built (needs MPI)" >&2; exit 2; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_WAIT_POLICY=active
out=$(mktemp)
trap 'rm -f "$out"' EXIT
run() {  # case processes threads particles mode
  OMP_NUM_THREADS=$3 mpirun -n "$2" --oversubscribe --bind-to none "$exe" "$scene" "$4" "$steps" "$5" |
    sed "s/^{/{\"case\": \"$1\", /" | tee -a "$out"
}
for r in $(seq "$rounds"); do
  run weak_1 1 1 "$per" weak
  run weak_2 2 1 "$per" weak
  run strong_1 1 1 $((2 * per)) strong
  run strong_2 2 1 $((2 * per)) strong
  run strong_omp2 1 2 $((2 * per)) strong
done
/usr/bin/python3 - "$out" <<'PY'
import json, statistics, sys
rows = [json.loads(l) for l in open(sys.argv[1]) if l.startswith("{")]
med = lambda c, k: statistics.median(r[k] for r in rows if r["case"] == c)
print("\n| case | processes x threads | particles | particle-steps/s | efficiency | halo s/step | migration s/step |")
print("|---|---|---|---|---|---|---|")
base = {"weak": med("weak_1", "wall_s"), "strong": med("strong_1", "wall_s")}
for c in ["weak_1", "weak_2", "strong_1", "strong_2", "strong_omp2"]:
    r = next(x for x in rows if x["case"] == c)
    kind, width = c.split("_")[0], r["processes"] * r["threads"]
    eff = base[kind] / med(c, "wall_s") / (width if kind == "strong" else 1)
    print(f"| {c} | {r['processes']} x {r['threads']} | {r['particles']} | {med(c, 'particle_steps_per_s'):.3g} | "
          f"{eff:.2f} | {med(c, 'halo_s_per_step'):.2e} | {med(c, 'migration_s_per_step'):.2e} |")
PY
