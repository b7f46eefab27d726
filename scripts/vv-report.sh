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
load_start=$(cut -d' ' -f1 /proc/loadavg)  # the report marks a run on a loaded machine (reports/history.py)
ctest --test-dir "$build" -L "$tier" --output-on-failure -j2 --output-junit ctest-junit.xml
tests=$?
echo "tests took $(( $(date +%s) - start )) s"
extra=()
[ -d "$build/perf-results" ] && extra+=(--perf "$build/perf-results")
[ -d "$build/stability" ] && extra+=(--stability "$build/stability")
[ -d "$build/paraview" ] && extra+=(--paraview "$build/paraview")
/usr/bin/python3 reports/vv_report.py --runs "$build/runs" --results "$build/results" \
  --out reports/out --history "$build/vv-history.jsonl" --load-start "$load_start" \
  "${report_flags[@]}" "${extra[@]}"
report=$?
if [ "$tier" != "quick" ]; then
  # The report as a reader sees it: every page rendered by headless Chromium at 1280 px, no page wider than the
  # window, no image that fails to load, a screenshot of each page (reports/browser/render.py).
  REPORT_DIR=reports/out SCREENSHOT_DIR=reports/out/screenshots \
    /usr/bin/python3 -m pytest -q -p no:cacheprovider reports/browser || report=1
fi
echo "report: reports/out/index.html (tests exit $tests, report exit $report)"
[ $tests -eq 0 ] && [ $report -eq 0 ]
