#!/usr/bin/env bash
# The quick tier again, built with AddressSanitizer and UndefinedBehaviorSanitizer (the asan preset:
# -O1, every test's time limit x10). A sanitizer report fails its test. Run by CI after test.sh.
# Built without MPI (the preset's SPH_MPI OFF): OpenMPI's runtime is not built with the
# sanitizers; the runs over several processes (verification/mpi) are tested in test.sh's tier.
set -euo pipefail
cd "$(dirname "$0")/.."
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
# Leaks are reported at exit (LeakSanitizer); an UBSan finding stops the process (the preset's
# -fno-sanitize-recover), and prints its stack.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0:strict_string_checks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
scripts/install-deps.sh
cmake --preset asan >/dev/null
cmake --build --preset asan -j2
start=$(date +%s)
# Not here: the two tests that cap the address space with `ulimit -v` (RunBudget.AddressSpaceLimitIsRefused,
# OutOfMemoryHasItsOwnExitCode): ASan reserves terabytes of shadow memory at start and aborts under any such cap.
# They run in the release tier (scripts/test.sh).
ctest --test-dir build/asan -L quick --output-on-failure -j2 \
  -E 'RunBudget\.(AddressSpaceLimitIsRefused|OutOfMemoryHasItsOwnExitCode)' "$@"
echo "asan quick tier: $(( $(date +%s) - start )) s"
