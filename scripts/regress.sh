#!/usr/bin/env bash
# The main job: set-up + build, then the co-simulation regression of every
# core and variant in cmake/cores.cmake (each core's regression cases: the
# papers' figures, a seeded random stream, and the same stream with aborts and
# feed holds), in the direct and the SystemC lockstep modes. Prints the summary
# tables; the JSON report lands in build/reports/regress.json. Extra arguments
# go to `hwinterp regress`, e.g.
#   scripts/regress.sh --random 2000 --seed 7 --cores ppc_arc
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/build.sh"
build=${HWINTERP_BUILD_DIR:-$root/build}
mkdir -p "$build/reports"
exec "$build/tb/hwinterp" regress --json "$build/reports/regress.json" "$@"
