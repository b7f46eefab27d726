#!/usr/bin/env bash
# The fast test tier: installs what is missing, builds, runs `ctest -L quick`.
set -euo pipefail
cd "$(dirname "$0")/.."
# Idle OpenMP threads sleep instead of spinning: on a shared 2-core machine spinning cost up to 20x.
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}
scripts/install-deps.sh
scripts/build.sh
ctest --test-dir build/release -L quick --output-on-failure -j2 "$@"
