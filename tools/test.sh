#!/bin/bash
# Builds everything and runs every test (README's second command; .ci/run).
#   bash tools/test.sh            build dir: build/
# Environment: POLYDEM_BUILD_DIR, POLYDEM_JOBS, POLYDEM_CMAKE_ARGS (extra args).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
BUILD=${POLYDEM_BUILD_DIR:-build}
JOBS=${POLYDEM_JOBS:-$(nproc)}
start=$(date +%s)
# shellcheck disable=SC2086
cmake -S . -B "$BUILD" ${POLYDEM_CMAKE_ARGS:-}
cmake --build "$BUILD" -j"$JOBS"
echo "test.sh: build took $(( $(date +%s) - start )) s"
ctest --test-dir "$BUILD" --output-on-failure -j"$JOBS"
echo "test.sh: build + tests took $(( $(date +%s) - start )) s"
