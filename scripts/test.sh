#!/usr/bin/env bash
# Sets up a fresh machine, builds dynanav and runs every test (unit, e2e, data).
# Tests that need ../shared (real sequences, models) skip with a message when it is absent.
# Usage: scripts/test.sh [ctest args...]     e.g. scripts/test.sh -L unit
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/setup.sh
# ccache keys on paths relative to the checkout, so a fresh clone reuses earlier compilations.
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
cmake --preset release >/dev/null
cmake --build --preset release

log=$(mktemp)
set +e
ctest --preset release --timeout 900 "$@" 2>&1 | tee "$log"
status=${PIPESTATUS[0]}
set -e
# ctest's verdict, once more as the very last line.
grep -E "tests passed|tests failed" "$log" | tail -n 1
rm -f "$log"
exit $status
