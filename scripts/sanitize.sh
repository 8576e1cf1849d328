#!/usr/bin/env bash
# The whole build with AddressSanitizer + UndefinedBehaviorSanitizer (gcc;
# `cmake --preset asan`, in build-asan/), then the unit tests under it:
# every label but long, bench, synth, formal and fuzz (those run tools, not
# our code, or are the clang fuzz build). Any sanitizer report fails the test
# it happens in. Extra arguments go to ctest.
# Usage: scripts/sanitize.sh [ctest args]   (HWINTERP_ASAN_BUILD_DIR changes the folder)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${HWINTERP_ASAN_BUILD_DIR:-$root/build-asan}
"$root/scripts/setup.sh"
mkdir -p "$build"
echo "sanitize: building with ASan + UBSan in $build (log: $build/build.log)" >&2
{ cmake --preset asan -S "$root" -B "$build" && cmake --build "$build" -j "${HWINTERP_JOBS:-2}"; } \
  >"$build/build.log" 2>&1 || { echo "sanitize: build failed; see $build/build.log" >&2; tail -n 20 "$build/build.log" >&2; exit 1; }
# halt_on_error: the first report fails the test. detect_leaks: the Verilated
# models' and SystemC's process-lifetime allocations are freed at exit.
export ASAN_OPTIONS=${ASAN_OPTIONS:-halt_on_error=1:detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
cd "$build"
ctest -j "${HWINTERP_JOBS:-2}" --output-on-failure -LE 'long|bench|synth|formal|fuzz' "$@"
