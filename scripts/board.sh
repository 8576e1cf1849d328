#!/usr/bin/env bash
# A board's bitstream from this clone: set-up as every script does
# (scripts/setup.sh: the Debian packages and .venv), then
# boards/hwinterp_litex/build.py: the gateware from LiteX (the target's
# pins and clocks), synthesis, place and route at each seed, the packer.
#
# Usage: scripts/board.sh BOARD [--seeds '1 2 3'] [--out DIR] [--json FILE] [--reuse]
#   BOARD       colorlight_5a_75b, tang_nano_20k, ice40_hx8k_breakout
#               (hwinterp_board in cmake/cores.cmake), or
#               peer_litexcnc_5a_75b (LiteX-CNC's own 5A-75B firmware, 4
#               stepgens, through the same ECP5 flow)
#   --seeds S   nextpnr seeds (default '1')
#   --out DIR   default build/boards/BOARD: gateware/ (LiteX's Verilog and
#               constraints, synth.log; the peer's in litexcnc_5a_75b/gateware/),
#               seed<N>/ (nextpnr.log, report.json,
#               the bitstream), BOARD's bitstream of the first seed
#               (.bit ECP5, .fs Gowin, .bin iCE40), result.json
#   --json FILE merge the figures into FILE (docs/data/boards.json, which
#               docs/synthesis.md's Boards section renders:
#               scripts/docs/render.py), after every seed
#   --reuse     keep the netlist, and each seed whose files in DIR are newer,
#               when the gateware (LiteX's output, the RTL, the constraints)
#               is the same: a stopped run goes on where it stopped
# Every seed must reach 1.15 x the board's system clock (57.5 MHz for the
# Colorlight's 50, 31.05 for the Tang Nano's 27, 13.8 for the HX8K's 12).
# Exit status: 0 built, every seed fast enough; 1 a seed does not fit or is
# too slow (named), or a tool failed; 2 bad input.
# Runs under nice. Measured on 2 cores shared with other jobs (load 5 to 8):
# the Colorlight 9 min of synthesis and 20 to 27 min a seed, the Tang Nano
# 2 min and 71 min a seed, LiteX-CNC's firmware 4 min and 7 to 9 min a
# seed, the HX8K under 2 min (its placement stops at once: it does not fit).
# Example: scripts/board.sh colorlight_5a_75b --seeds '1 2 3'
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2; exit 2; }
[ $# -ge 1 ] || usage
case "$1" in -h|--help) usage ;; -*) echo "board: '$1' is not a board" >&2; exit 2 ;; esac
board=$1
shift
seeds=1
out=""
json=""
reuse=()
while [ $# -gt 0 ]; do
  case "$1" in
    --seeds) [ $# -ge 2 ] || { echo "board: --seeds needs a list" >&2; exit 2; }; seeds=$2; shift 2 ;;
    --out) [ $# -ge 2 ] || { echo "board: --out needs a directory" >&2; exit 2; }; out=$2; shift 2 ;;
    --json) [ $# -ge 2 ] || { echo "board: --json needs a file" >&2; exit 2; }; json=$2; shift 2 ;;
    --reuse) reuse=(--reuse); shift ;;
    *) echo "board: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
"$root/scripts/setup.sh"
venv=${HWINTERP_VENV:-$root/.venv}
export YOWASP_CACHE_DIR=${YOWASP_CACHE_DIR:-$venv/yowasp-cache}
# This clone's board package (not another clone's editable install).
export PYTHONPATH="$root/boards${PYTHONPATH:+:$PYTHONPATH}"
out=${out:-${HWINTERP_BUILD_DIR:-$root/build}/boards/$board}
cmd="scripts/board.sh $board --seeds '$seeds'"
exec "$venv/bin/python3" -m hwinterp_litex.build --board "$board" --seeds "$seeds" --out "$out" \
  ${json:+--json "$json"} --command "$cmd" "${reuse[@]}"
