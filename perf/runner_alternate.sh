#!/usr/bin/env bash
# The matrix's local runner against the way the runs were scheduled before it (issue 34), in one build tree:
#   perf/runner_alternate.sh BUILD [TIER] [REGEX] [ROUNDS] [EXCLUDE]
# e.g. perf/runner_alternate.sh build/release nightly '^(run|recover|validate)_' 2 spheric
# Each round runs `ctest -L TIER -R REGEX -j<cores>` twice, from no run files (as scripts/vv-report.sh does):
#   matrix: the build's resource spec (the host's cores as cpu slots; each run takes its threads' slots) and the
#           matrix's threads;
#   before: every run on 2 threads (run.py takes SLURM_CPUS_PER_TASK=2 as given CPUs) and a spec of twice as many
#           slots, so that ctest admits two 2-thread runs at once on a 2-core machine, as it did when each run was a
#           plain `sph run --threads 2` test with no resource group.
# The runs and run.py are otherwise the same in both; run.py's own cost is printed apart from the rows' wall times.
# Prints: round, scheduling, seconds. Only meaningful on a machine that nothing else uses.
set -euo pipefail
build=$(realpath "$1") tier=${2:-nightly} regex=${3:-'^(run|recover|validate)_'} rounds=${4:-2} exclude=${5:-^$}
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
cores=$(nproc)
spec=$(mktemp --suffix=.json)
trap 'rm -f "$spec"' EXIT
printf '{"version": {"major": 1, "minor": 0}, "local": [{"cpus": [{"id": "0", "slots": %d}]}]}\n' \
  $((2 * (cores < 2 ? 2 : cores))) >"$spec"
for round in $(seq "$rounds"); do
  for which in matrix before; do
    extra=() given=()
    [ "$which" = before ] && extra=(--resource-spec-file "$spec") given=(SLURM_CPUS_PER_TASK=2)
    rm -rf "$build/runs" "$build/matrix-rows" "$build/results"
    start=$(date +%s.%N)
    env "${given[@]}" ctest --test-dir "$build" -L "$tier" -R "$regex" -E "$exclude" -j"$cores" "${extra[@]}" \
      >"$build/runner_alternate_$which.log" || true
    end=$(date +%s.%N)
    # run.py's cost: ctest's time for the run_ tests against the wall time their rows give sph.
    wrapper=$(/usr/bin/python3 - "$build" "$build/runner_alternate_$which.log" <<'EOF'
import json, re, sys
from pathlib import Path
build, log = Path(sys.argv[1]), Path(sys.argv[2])
tests = {m.group(1): float(m.group(2))
         for m in re.finditer(r"Test +#\d+: (run_\S+) \.+.*?([\d.]+) sec", log.read_text())}
rows = {p.stem: json.loads(p.read_text())["wall_time_s"] for p in (build / "matrix-rows").glob("*.json")}
both = [n for n in rows if f"run_{n}" in tests]
print(f"{len(both)} runs: ctest {sum(tests[f'run_{n}'] for n in both):.1f} s, sph {sum(rows[n] for n in both):.1f} s")
EOF
    )
    awk -v r="$round" -v w="$which" -v a="$start" -v b="$end" -v x="$wrapper" 'BEGIN { print r, w, b - a, "(" x ")" }'
  done
done
