#!/usr/bin/env bash
# Alternated wall time of a whole ctest tier in two build trees (issue 34: the matrix's local runner against the
# runs' direct ctest tests before it):
#   perf/tier_alternate.sh BASE_BUILD NEW_BUILD [TIER] [ROUNDS]
# e.g. perf/tier_alternate.sh ../base/build/release build/release nightly 2. Each round runs `ctest -L TIER -j2`
# in each tree in turn, from no run files (as scripts/vv-report.sh does), and prints: round, build, seconds.
# Only meaningful on a machine that nothing else uses; compare medians of the same rounds.
set -euo pipefail
base=$1 new=$2 tier=${3:-quick} rounds=${4:-2}
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
for round in $(seq "$rounds"); do
  for which in base new; do
    build=$base
    [ "$which" = new ] && build=$new
    rm -rf "$build/runs" "$build/matrix-rows" "$build/results" "$build/stability" "$build/paraview"
    start=$(date +%s.%N)
    ctest --test-dir "$build" -L "$tier" -j2 >/dev/null || true
    awk -v r="$round" -v w="$which" -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { print r, w, b - a }'
  done
done
