#!/usr/bin/env bash
# The main job: installs what is missing, builds, runs the verification and validation tiers and
# writes the V&V report to reports/out/ (index.html, junit.xml, summary.json).
#   scripts/vv-report.sh            nightly tier (quick + nightly tests, then the report)
#   scripts/vv-report.sh --quick    the CI tier only (a couple of minutes)
# Exits non-zero when a test or a report criterion fails, after writing the report.
set -uo pipefail
cd "$(dirname "$0")/.."
# Idle OpenMP threads sleep instead of spinning: on a shared 2-core machine spinning cost up to 20x.
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
tier="quick|nightly"
report_flags=()
if [ "${1:-}" = "--quick" ]; then
  tier="quick"
  report_flags+=(--quick)
fi
if [ "$tier" = "quick" ]; then scripts/install-deps.sh || exit 1; else scripts/install-deps.sh --report || exit 1; fi
scripts/build.sh || exit 1
build=build/release
rm -rf "$build/runs" "$build/matrix-rows" "$build/results" "$build/stability" "$build/paraview"
start=$(date +%s)
ctest --test-dir "$build" -L "$tier" --output-on-failure -j2 --output-junit ctest-junit.xml
tests=$?
echo "tests took $(( $(date +%s) - start )) s"
extra=()
[ -d "$build/perf-results" ] && extra+=(--perf "$build/perf-results")
[ -d "$build/stability" ] && extra+=(--stability "$build/stability")
[ -d "$build/paraview" ] && extra+=(--paraview "$build/paraview")
/usr/bin/python3 reports/vv_report.py --runs "$build/runs" --results "$build/results" \
  --out reports/out "${report_flags[@]}" "${extra[@]}"
report=$?
if [ "$tier" != "quick" ]; then
  # The report as a reader sees it: rendered by headless Chromium, images checked, and a screenshot.
  REPORT_DIR=reports/out /usr/bin/python3 -m pytest -q -p no:cacheprovider reports/browser || report=1
  chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
    --disable-background-networking --disable-component-update --disable-sync --hide-scrollbars \
    --user-data-dir="$(mktemp -d)" --screenshot="$PWD/reports/out/screenshot.png" \
    --window-size=1280,1800 "file://$PWD/reports/out/index.html" >/dev/null 2>&1
fi
echo "report: reports/out/index.html (tests exit $tests, report exit $report)"
[ $tests -eq 0 ] && [ $report -eq 0 ]
