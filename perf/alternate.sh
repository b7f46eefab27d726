#!/usr/bin/env bash
# Alternated timing of two builds of this project (perf/README.md, "Comparing two versions"):
#   perf/alternate.sh BASE_BUILD NEW_BUILD [ROUNDS]
# e.g. perf/alternate.sh ../base/build/release build/release 3. Each round runs, for each build in
# turn, the force evaluation at 1e4 and 1e6 particles (micro_benchmarks, 1 and 2 threads) and the
# dam break at dx 0.01 and 0.005 end to end (`sph run --fixed-threads`, 1 and 2 threads), and
# prints one line per measurement: round, build, case, seconds. Summarise with the medians per
# build and case; compare only figures of the same round set.
set -euo pipefail
base=$1 new=$2 rounds=${3:-3}
src=$(cd "$(dirname "$0")/.." && pwd)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
export OMP_WAIT_POLICY=active
for round in $(seq "$rounds"); do
  for which in base new; do
    build=$base
    [ "$which" = new ] && build=$new
    "$build/perf/micro_benchmarks" --benchmark_filter='BM_ForceEvaluation/(10000|1000000)/(1|2)/' \
      --benchmark_min_time=0.5 --benchmark_format=csv 2>/dev/null |
      awk -F, -v r="$round" -v w="$which" '/^"BM_/ {gsub(/"/, "", $1); print r, w, $1, $3 / 1e6}'
    for scene in dam_break dam_break_dx0.005; do
      for t in 1 2; do
        "$build/solver/sph" run "$src/validation/scenes/$scene.toml" --out "$out/$which" --threads "$t" \
          --fixed-threads >/dev/null
        name=$(sed -n '0,/^name *= *"\(.*\)"/s//\1/p' "$src/validation/scenes/$scene.toml")
        /usr/bin/python3 -c "import h5py,sys; print(sys.argv[1], sys.argv[2], sys.argv[3], h5py.File(sys.argv[4])['metrics'].attrs['wall_time_s'])" \
          "$round" "$which" "$scene/$t" "$out/$which/$name.h5"
      done
    done
  done
done
