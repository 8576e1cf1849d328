#!/usr/bin/env bash
# Formal check of the output stage every core shares: rtl/stepdir_axis.sv
# against rtl/formal/stepdir_axis_props.sv (the step/dir timing promises of
# its header) and rtl/step_stage.sv against rtl/formal/step_stage_props.sv
# (positions are the integral of the step/dir wires): a bounded model check
# and a k-induction proof each, with Yosys (read_verilog -formal) and
# yosys-smtbmc + z3.
#
# Usage: scripts/formal.sh [--depth N] [--tim-w "W..."] [--out DIR]
#   --depth N     BMC depth and maximum induction length (default 40)
#   --tim-w LIST  TIM_W values to check (default "3 4"). The proof is per
#                 width: induction needs about 2^TIM_W steps (the saturating
#                 counters), so the design's TIM_W=16 is not checked directly;
#                 the stage is the same RTL for every width.
#   --out DIR     output directory (default <build>/reports/formal)
# stepdir_axis is checked in both ready_o modes: READY_Q=0 at every width,
# READY_Q=1 (ready_o a register, decided from want_dir_next_i) at the first.
# Runs BMC and induction side by side when HWINTERP_JOBS (default 2) allows.
# Exits non-zero, naming the step and log, when a property fails or a tool
# is missing; a failing BMC leaves a counterexample trace (.vcd) in DIR.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
py=${HWINTERP_VENV:-$root/.venv}/bin/python3  # scripts/setup.sh makes it
build=${HWINTERP_BUILD_DIR:-$root/build}

die() { echo "formal: $*" >&2; exit 1; }
usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2; exit 2; }

depth=40
widths="3 4"
out=""
while [ $# -gt 0 ]; do
  case "$1" in
    --depth) [ $# -ge 2 ] || usage; depth=$2; shift 2 ;;
    --tim-w) [ $# -ge 2 ] || usage; widths=$2; shift 2 ;;
    --out) [ $# -ge 2 ] || usage; out=$2; shift 2 ;;
    -h|--help) usage ;;
    *) echo "formal: unknown argument '$1'" >&2; usage ;;
  esac
done
[[ $depth =~ ^[1-9][0-9]*$ ]] || die "--depth: '$depth' is not a positive integer"
read -r -a width_list <<<"$widths"
[ ${#width_list[@]} -ge 1 ] || die "--tim-w needs at least one width"
for w in "${width_list[@]}"; do
  [[ $w =~ ^[1-9][0-9]*$ ]] || die "--tim-w: '$w' is not a positive integer"
done

"$root/scripts/setup.sh"
for t in yosys yosys-smtbmc z3 "$py"; do
  command -v "$t" >/dev/null || die "$t not found (scripts/setup.sh installs it)"
done

out=${out:-$build/reports/formal}
mkdir -p "$out"
# Each block: its RTL files (dependencies first).
declare -A block_files=(
  [stepdir_axis]="$root/rtl/stepdir_timing.sv $root/rtl/stepdir_axis.sv"
  [step_stage]="$root/rtl/stepdir_timing.sv $root/rtl/stepdir_axis.sv $root/rtl/step_stage.sv"
)
blocks=(stepdir_axis step_stage)

# Yosys 0.23 silently misreads some SystemVerilog literals; a proof about the
# misread design would prove nothing about the RTL.
"$py" "$root/scripts/synth/yosys_compat.py" "$root/rtl/stepdir_timing.sv" "$root/rtl/stepdir_axis.sv" "$root/rtl/step_stage.sv" \
  "$root"/rtl/formal/*_props.sv 2>"$out/compat_check.log" ||
  die "Yosys 0.23 would misread the RTL; see $out/compat_check.log"

# run LOG CMD...: runs CMD into LOG, prints the verdict line, fails by name.
run() {
  local log=$1 name
  name=$(basename "$log" .log)
  shift
  local t0=$SECONDS
  if "$@" >"$log" 2>&1 && grep -q 'Status: PASSED' "$log"; then
    echo "formal: $name: PASSED ($(grep -oE 'Temporal induction successful|Checking assertions in step [0-9]+' "$log" |
      tail -n1 || true); $((SECONDS - t0)) s)"
  else
    echo "formal: $name: FAILED; see $log" >&2
    grep -E 'Assert failed|failed|ERROR' "$log" | head -n 5 >&2 || true
    return 1
  fi
}

jobs=${HWINTERP_JOBS:-2}
status=0
# One run per block, width and (stepdir_axis only) ready_o mode: "block w mode".
runs=()
for block in "${blocks[@]}"; do
  for w in "${width_list[@]}"; do runs+=("$block $w 0"); done
done
runs+=("stepdir_axis ${width_list[0]} 1")
for r in "${runs[@]}"; do
  read -r block w rq <<<"$r"
  props=$root/rtl/formal/${block}_props.sv
  tag=${block}_w$w
  chp="chparam -set TIM_W $w ${block}_props"
  if [ "$rq" = 1 ]; then
    tag=${block}_readyq_w$w
    chp="chparam -set TIM_W $w -set READY_Q 1 ${block}_props"
  fi
  smt=$out/$tag.smt2
  # prep, then async2sync (the asynchronous reset as logic on the flip-flop
  # outputs, which smtbmc can step) and dffunmap (plain $dff for write_smt2).
  yosys -q -l "$out/prep_$tag.log" -p "read_verilog -sv -formal ${block_files[$block]} $props;
    $chp; prep -top ${block}_props;
    async2sync; dffunmap; write_smt2 -wires $smt" >/dev/null 2>&1 ||
    die "step 'yosys prep' failed for $block TIM_W=$w READY_Q=$rq; see $out/prep_$tag.log"
  # --unroll: with the default encoding, z3 4.8.12 spends ~80 s on the very
  # first query (measured: `-t 1` alone took 81 s); unrolled, BMC to depth 30
  # takes ~30 s and induction ~2 s, and the same mutants fail.
  bmc=(run "$out/bmc_${tag}_d$depth.log" yosys-smtbmc -s z3 --unroll -t "$depth"
    --dump-vcd "$out/bmc_${tag}_d$depth.vcd" "$smt")
  ind=(run "$out/induction_${tag}_d$depth.log" yosys-smtbmc -s z3 --unroll -i -t "$depth"
    "$smt")
  if [ "$jobs" -ge 2 ]; then
    "${bmc[@]}" &
    p1=$!
    "${ind[@]}" &
    p2=$!
    wait "$p1" || status=1
    wait "$p2" || status=1
  else
    "${bmc[@]}" || status=1
    "${ind[@]}" || status=1
  fi
done
[ $status -eq 0 ] || die "a property failed or a run did not finish; logs in $out"
echo "formal: all properties of ${blocks[*]} hold (BMC depth $depth and induction, TIM_W ${width_list[*]}; stepdir_axis with READY_Q=1 at TIM_W ${width_list[0]}); logs in $out"
