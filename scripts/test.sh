#!/usr/bin/env bash
# Set-up + build + the test suite CI runs (everything but the `long`, `bench`,
# `board_build` and `linuxcnc` labels). JUnit lands in build/reports/ctest-junit.xml.
# Extra arguments go to ctest, e.g. scripts/test.sh -R dda_line.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/build.sh"
build=${HWINTERP_BUILD_DIR:-$root/build}
mkdir -p "$build/reports"
cd "$build"
ctest -j "${HWINTERP_JOBS:-2}" --output-on-failure -LE 'long|bench|board_build|linuxcnc' \
  --output-junit "$build/reports/ctest-junit.xml" "$@"
