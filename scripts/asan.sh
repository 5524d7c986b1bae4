#!/usr/bin/env bash
# Builds the sanitizer preset (ASan + UBSan, build/asan) and runs the unit and e2e tests under it
# (the data tests run the real sequences and are left to the release suite: too slow under ASan).
# The output ends with ctest's summary line. Usage: scripts/asan.sh [ctest args...]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh >/dev/null
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=1
start=$SECONDS
cmake --preset asan >/dev/null
cmake --build --preset asan
built=$SECONDS
log=$(mktemp)
set +e
ctest --preset asan --timeout 1800 "$@" 2>&1 | tee "$log"
status=${PIPESTATUS[0]}
set -e
echo "asan: build $((built - start)) s, tests $((SECONDS - built)) s"
grep -E "tests passed|tests failed" "$log" | tail -n 1
rm -f "$log"
exit $status
