#!/usr/bin/env bash
# A simulated board, serving its host link on this machine: set-up and
# build as scripts/build.sh does, then `hwinterp board-sim`. Prints the URI
# to give hwinterp-host (udp:127.0.0.1:PORT for the Colorlight's Etherbone,
# serial:/dev/pts/N@BAUD for a UART board) and runs until Ctrl-C.
#
# Usage: scripts/board_sim.sh BOARD [--clock-hz HZ [--baud B]] [hwinterp board-sim options]
#   BOARD          colorlight_5a_75b, tang_nano_20k, ice40_hx8k_breakout
#                  (hwinterp_board in cmake/cores.cmake)
#   --clock-hz HZ  simulate the board's gateware at HZ instead of its own
#                  clock (a slower clock simulates more board time a second);
#                  a clock the build does not hold yet is added to it
#                  (HWINTERP_EXTRA_BOARD_SIMS) and built first: about ten
#                  minutes on 2 cores, since the board models share their
#                  library with the cores' and most of the tree recompiles
#   --baud B       with --clock-hz on a UART board: its rate (at least 8
#                  clocks a bit; default the board's)
#   --no-profile   the build without the feed profile (added, as above, when
#                  the build does not hold it at that clock)
# Other options go to hwinterp board-sim (--faults, --json, --steps-csv,
# --realtime, ...; `hwinterp board-sim --help`).
# Example: scripts/board_sim.sh colorlight_5a_75b --clock-hz 1000000
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${HWINTERP_BUILD_DIR:-$root/build}
usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2; exit 2; }
[ $# -ge 1 ] || usage
case "$1" in -h|--help) usage ;; esac
board=$1
shift
hz=""
baud=""
noprofile=""
rest=()
while [ $# -gt 0 ]; do
  case "$1" in
    --clock-hz) [ $# -ge 2 ] || usage; hz=$2; shift 2 ;;
    --baud) [ $# -ge 2 ] || usage; baud=$2; shift 2 ;;
    --no-profile) noprofile=1; rest+=("$1"); shift ;;
    *) rest+=("$1"); shift ;;
  esac
done
if [ -n "$hz" ] && ! [[ "$hz" =~ ^[1-9][0-9]*$ ]]; then
  echo "board_sim: --clock-hz '$hz' is not a clock in Hz" >&2; exit 2
fi
if [ -n "$baud" ] && { [ -z "$hz" ] || ! [[ "$baud" =~ ^[1-9][0-9]*$ ]]; }; then
  echo "board_sim: --baud '$baud' needs --clock-hz and a rate in bits a second" >&2; exit 2
fi
"$root/scripts/build.sh"
hwinterp=$build/tb/hwinterp
# A build at that clock (without the profile, with --no-profile) not held yet is added.
held() {
  local builds
  builds=$("$hwinterp" board-sim --list | grep "^$board $hz " || true)
  if [ -n "$noprofile" ]; then
    grep -q " no-profile$" <<<"$builds"
  else
    grep -q -v " no-profile$" <<<"$builds"
  fi
}
if [ -n "$hz" ] && ! held; then
  extra=$(cmake -L -N "$build" 2>/dev/null | sed -n 's/^HWINTERP_EXTRA_BOARD_SIMS:STRING=//p')
  entry="$board:$hz${baud:+:$baud}${noprofile:+:noprofile}"
  extra="${extra:+$extra;}$entry"
  echo "board_sim: adding $board at $hz Hz to the build (HWINTERP_EXTRA_BOARD_SIMS=$extra)" >&2
  "$root/scripts/build.sh" "-DHWINTERP_EXTRA_BOARD_SIMS=$extra"
fi
exec "$hwinterp" board-sim --board "$board" ${hz:+--clock-hz "$hz"} "${rest[@]}"
