#!/usr/bin/env bash
# The main job: set-up + build, then the dda_line co-simulation regression
# (the eight test lines of 004_dc68f1177cad466f.txt with plain and half
# preload, and a seeded random stream, on every variant, in the direct and the
# SystemC lockstep modes). Prints the summary table; the JSON report lands in
# build/reports/regress.json. Extra arguments go to `hwinterp regress`, e.g.
#   scripts/regress.sh --random 2000 --seed 7
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/build.sh"
build=${HWINTERP_BUILD_DIR:-$root/build}
mkdir -p "$build/reports"
exec "$build/tb/hwinterp" regress --json "$build/reports/regress.json" "$@"
