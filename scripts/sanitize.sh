#!/usr/bin/env bash
# AddressSanitizer + UndefinedBehaviorSanitizer pass: builds heavesim and the tests
# that read, write or buffer (every malformed case and data file, the result file,
# hull clipping, radiation memory, the validation table that runs every algorithm;
# the list is in tests/CMakeLists.txt) with -fsanitize=address,undefined in
# build-sanitize/ and runs them, with the no-allocation tests: this build is also the
# checked one (Eigen's allocation check and assertions on in every source; top
# CMakeLists.txt). Any sanitizer report, Eigen assertion or allocation fails the run.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=build-sanitize
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
if [[ ! -f "$build_dir/CMakeCache.txt" ]]; then
  cmake -S . -B "$build_dir" "${generator[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHEAVESIM_SANITIZE=ON \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
    -DHEAVESIM_BUILD_BENCH=OFF
fi
cmake --build "$build_dir" -j "$(nproc)"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
(cd "$build_dir" && ctest --output-on-failure -j "$(nproc)")
echo "sanitize: no sanitizer reports"
