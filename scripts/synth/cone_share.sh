#!/usr/bin/env bash
# The share of a block inside a core: iCE40 cells (LUT4, carry, FF) of the
# named registers and of the combinational logic in their input cones, beside
# the whole core's, from one `synth_ice40 -top <core>` of a variant (the
# parameters from <build>/generated/variants.txt, the files from
# rtl/<core>.f, as scripts/synth.sh reads them).
#
# Usage: scripts/synth/cone_share.sh VARIANT LABEL PATTERN...
#   PATTERN  a Yosys wire pattern naming the block's registers, e.g.
#            '*rem_q*' (flattened names keep the RTL's, g_axis[0].rem_q)
# Example (fixed_ratio's rate dividers: remainders, quotients, M and the
# divider's clock counter):
#   scripts/synth/cone_share.sh fixed_ratio_n4 divider '*rem_q*' '*quot_q*' '*buf_max_q*' '*div_left_q*'
#
# A cone stops at flip-flops, so logic shared with the rest of the core (here
# the magnitude compares that also find M) counts in both: the block's share
# is an upper bound of what removing it would save.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${HWINTERP_BUILD_DIR:-$root/build}
die() { echo "cone_share: $*" >&2; exit 2; }
[ $# -ge 3 ] || die "usage: scripts/synth/cone_share.sh VARIANT LABEL PATTERN..."
variant=$1 label=$2
shift 2
vfile=$build/generated/variants.txt
[ -f "$vfile" ] || die "$vfile missing: configure the build first (scripts/build.sh)"
line=$(awk -v v="$variant" '$1 == v' "$vfile")
[ -n "$line" ] || die "unknown variant '$variant' (variants.txt has: $(cut -d' ' -f1 "$vfile" | tr '\n' ' '))"
read -r _ core params <<<"$line"
[ -f "$root/rtl/$core.f" ] || die "no RTL file list rtl/$core.f"
files=$(grep -v '^#' "$root/rtl/$core.f" | sed "s|^|$root/rtl/|" | tr '\n' ' ')
chparam="chparam"
for kv in $params; do chparam+=" -set ${kv%%=*} ${kv#*=}"; done
wires="w:$1"  # one set on Yosys's selection stack: the union of the patterns
for p in "${@:2}"; do wires+=" w:$p %u"; done
ffs=SB_DFF,SB_DFFE,SB_DFFR,SB_DFFER,SB_DFFS,SB_DFFES,SB_DFFSR,SB_DFFESR,SB_DFFSS,SB_DFFESS
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# The block's flip-flops are the ones driving the named wires; one step back
# gives their D/E inputs, from which the cone grows through every cell but a
# flip-flop.
yosys -q -l "$tmp/yosys.log" -p "read_verilog -sv $files; $chparam $core; synth_ice40 -top $core;
  tee -q -o $tmp/core.txt stat;
  select -set regs $wires %ci1 t:SB_DFF* %i;
  select -set cone @regs %ci1 %ci*:-$ffs @regs %u;
  tee -q -o $tmp/block.txt stat @cone" >/dev/null 2>&1 || {
  tail -n 20 "$tmp/yosys.log" >&2
  die "yosys failed"
}
count() { # count FILE KIND: LUT4, carry or FF cells in a `stat` output
  case $2 in
    lut) awk '$1 == "SB_LUT4" {n += $2} END {print n + 0}' "$1" ;;
    carry) awk '$1 == "SB_CARRY" {n += $2} END {print n + 0}' "$1" ;;
    ff) awk '$1 ~ /^SB_DFF/ {n += $2} END {print n + 0}' "$1" ;;
  esac
}
printf '%-16s %-10s %8s %8s %8s\n' variant block LUT4 carry FF
for what in "$label:$tmp/block.txt" "core:$tmp/core.txt"; do
  f=${what#*:}
  printf '%-16s %-10s %8s %8s %8s\n' "$variant" "${what%%:*}" "$(count "$f" lut)" \
    "$(count "$f" carry)" "$(count "$f" ff)"
done
