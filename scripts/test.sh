#!/usr/bin/env bash
# The fast test tier: installs what is missing, builds, runs `ctest -L quick`.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
ctest --test-dir build/release -L quick --output-on-failure -j2 "$@"
