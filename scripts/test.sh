#!/usr/bin/env bash
# Builds and runs the whole test suite: the GoogleTest/CTest suite on the Release
# build, the validation table, then the sanitizer pass (scripts/sanitize.sh).
#   scripts/test.sh           everything
#   scripts/test.sh --fast    skip the sanitizer build
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
# The programs the suite runs (the benchmarks are built by scripts/build.sh alone).
scripts/build.sh heavesim heavesim_tests
(cd build && ctest --output-on-failure -j "$(nproc)")
build/heavesim validate
if [[ "${1:-}" != "--fast" ]]; then
  scripts/sanitize.sh
fi
echo "test: all passed"
