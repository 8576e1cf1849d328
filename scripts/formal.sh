#!/usr/bin/env bash
# Formal checks with Yosys (read_verilog -formal) and yosys-smtbmc + z3: per
# block a bounded model check from reset and a k-induction proof (which, when
# it succeeds, proves the properties for every depth).
#
#   stepdir_axis  rtl/stepdir_axis.sv against rtl/formal/stepdir_axis_props.sv
#                 (the step/dir timing promises of its header)
#   step_stage    rtl/step_stage.sv against rtl/formal/step_stage_props.sv
#                 (positions are the integral of the step/dir wires)
#   dda_line ppc_line ppc_arc fixed_ratio motion_top log_stepper
#                 the core in rtl/formal/<core>_props.sv (narrow parameters,
#                 every input free): the port contract every core shares
#                 (rtl/formal/core_contract.sv: no command dropped, busy_o and
#                 done_o exact, abort reaches idle within the pulse's length)
#                 and the engine's progress (rtl/formal/core_checks.sv),
#                 attached by the props file or instantiated in the RTL's
#                 `ifdef FORMAL` block, and the invariants in those blocks
#   feed_profile  rtl/feed_profile.sv (a block, not a core) against
#                 rtl/formal/feed_profile_props.sv: reset state, the level
#                 and the speed change only on a tick boundary (the level by
#                 one), the feed word, the move handshake (a taken move is
#                 never lost or overwritten)
#   step_encode   rtl/step_encode.sv against rtl/formal/step_encode_props.sv:
#                 each step output type is what its header says; quadrature
#                 is the Gray state of the step count, one bit a step
#   link_guard    rtl/link/link_guard.sv against rtl/formal/link_guard_props.sv:
#                 the host link's sequence guard (docs/link.md) against a
#                 model of its window, stream and counters; Wishbone rules,
#                 transparency outside the window, downstream writes only
#                 from an open guard's data words, to the header's address
#                 plus the word's index
#   etherbone_engine  rtl/link/etherbone_engine.f against
#                 rtl/formal/etherbone_engine_props.sv: nothing of a frame
#                 runs (no bus access, no reply) unless the frame was whole
#                 and its CRC right (an account of the frame kept by the
#                 props file); Wishbone rules; the buffer written only while
#                 idle, read only while busy
#   slip_rx uart_tx uart_rx  rtl/link/<block>.sv against its props: the
#                 SLIP decoder's escape rule; the UART transmitter's bit
#                 timing (DIV = 5); the receiver (DIV = 8) takes every
#                 character of an ideal sender once, right, at a fixed clock
#
# Usage: scripts/formal.sh [--blocks LIST] [--depth N] [--tim-w "W..."] [--out DIR]
#   --blocks LIST  blocks to check (default "stepdir_axis step_stage", the
#                 shared output stage); "cores" every core, "all" every
#                 block. On 2 idle cores the stage takes about 120 s,
#                 log_stepper 27 s (its coarse engine), each other core 2-5 s.
#   --depth N     BMC depth and maximum induction length (default 40 for the
#                 stage blocks, 8 for the cores: their induction closes at 5)
#   --tim-w LIST  TIM_W values of the stage blocks (default "3 4"). The proof
#                 is per width: induction needs about 2^TIM_W steps (the
#                 saturating counters), so the design's TIM_W=16 is not
#                 checked directly; the stage is the same RTL for every width.
#                 The cores are checked at TIM_W = 2 (their props files).
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

stage_blocks=(stepdir_axis step_stage)
core_blocks=(dda_line ppc_line ppc_arc fixed_ratio motion_top log_stepper)
other_blocks=(feed_profile step_encode)  # rtl/<block>.f (or rtl/<block>.sv alone), no core contract
link_blocks=(link_guard etherbone_engine slip_rx uart_tx uart_rx)  # the host link's blocks: rtl/link/<block>.f (or rtl/link/<block>.sv alone)
all_blocks=("${stage_blocks[@]}" "${core_blocks[@]}" "${other_blocks[@]}" "${link_blocks[@]}")

depth=""
widths="3 4"
out=""
blocks_arg="${stage_blocks[*]}"
while [ $# -gt 0 ]; do
  case "$1" in
    --blocks) [ $# -ge 2 ] || usage; blocks_arg=$2; shift 2 ;;
    --depth) [ $# -ge 2 ] || usage; depth=$2; shift 2 ;;
    --tim-w) [ $# -ge 2 ] || usage; widths=$2; shift 2 ;;
    --out) [ $# -ge 2 ] || usage; out=$2; shift 2 ;;
    -h|--help) usage ;;
    *) echo "formal: unknown argument '$1'" >&2; usage ;;
  esac
done
[ -z "$depth" ] || [[ $depth =~ ^[1-9][0-9]*$ ]] || die "--depth: '$depth' is not a positive integer"
read -r -a width_list <<<"$widths"
[ ${#width_list[@]} -ge 1 ] || die "--tim-w needs at least one width"
for w in "${width_list[@]}"; do
  [[ $w =~ ^[1-9][0-9]*$ ]] || die "--tim-w: '$w' is not a positive integer"
done
blocks=()
for b in $blocks_arg; do
  case "$b" in
    cores) blocks+=("${core_blocks[@]}") ;;
    all) blocks+=("${all_blocks[@]}") ;;
    *)
      [[ " ${all_blocks[*]} " == *" $b "* ]] ||
        { echo "formal: --blocks: '$b' is not a block (${all_blocks[*]}, cores, all)" >&2; exit 2; }
      blocks+=("$b") ;;
  esac
done
[ ${#blocks[@]} -ge 1 ] || die "--blocks needs at least one block"

"$root/scripts/setup.sh"
for t in yosys yosys-smtbmc z3 "$py"; do
  command -v "$t" >/dev/null || die "$t not found (scripts/setup.sh installs it)"
done

out=${out:-$build/reports/formal}
mkdir -p "$out"
# Each block: its RTL files (dependencies first). A core: rtl/<core>.f and
# the shared checkers (rtl/formal/core_contract.sv, which some cores
# instantiate in their `ifdef FORMAL` block, and rtl/formal/core_checks.sv,
# which the others' props files attach).
declare -A block_files=(
  [stepdir_axis]="$root/rtl/stepdir_timing.sv $root/rtl/stepdir_axis.sv"
  [step_stage]="$root/rtl/stepdir_timing.sv $root/rtl/stepdir_axis.sv $root/rtl/step_stage.sv"
)
for core in "${core_blocks[@]}"; do
  block_files[$core]="$(sed -n "/^[^#]/s|^|$root/rtl/|p" "$root/rtl/$core.f" | tr '\n' ' ')$root/rtl/formal/core_contract.sv $root/rtl/formal/core_checks.sv"
done
for b in "${other_blocks[@]}"; do
  if [ -f "$root/rtl/$b.f" ]; then
    block_files[$b]="$(sed -n "/^[^#]/s|^|$root/rtl/|p" "$root/rtl/$b.f" | paste -sd ' ')"
  else
    block_files[$b]="$root/rtl/$b.sv"
  fi
done
for b in "${link_blocks[@]}"; do
  if [ -f "$root/rtl/link/$b.f" ]; then
    block_files[$b]="$(sed -n "/^[^#]/s|^|$root/rtl/link/|p" "$root/rtl/link/$b.f" | paste -sd ' ')"
  else
    block_files[$b]="$root/rtl/link/$b.sv"
  fi
done
# Signals a proof links across the hierarchy after flattening (Yosys 0.23 has
# neither `bind` nor hierarchical references): each `// link: A=B ...` line of
# a block's props file connects wire A to B (e.g. the props file's checker
# inputs to the core's registers; log_stepper's tags against the segments its
# fine stage holds).
declare -A block_links=()
for b in "${all_blocks[@]}"; do
  block_links[$b]=$(sed -n 's|^// link: ||p' "$root/rtl/formal/${b}_props.sv" | tr '\n' ' ')
done

# Yosys 0.23 silently misreads some SystemVerilog literals; a proof about the
# misread design would prove nothing about the RTL.
mapfile -t compat_files < <(for b in "${blocks[@]}"; do tr ' ' '\n' <<<"${block_files[$b]}"; done | sort -u)
"$py" "$root/scripts/synth/yosys_compat.py" "${compat_files[@]}" "$root"/rtl/formal/*.sv 2>"$out/compat_check.log" ||
  die "Yosys 0.23 would misread the RTL; see $out/compat_check.log"

# run LOG DEPTH CMD...: runs CMD into LOG, prints the verdict line (with the
# induction length k when it succeeds), fails by name.
run() {
  local log=$1 d=$2 name
  name=$(basename "$log" .log)
  shift 2
  local t0=$SECONDS
  if "$@" >"$log" 2>&1 && grep -q 'Status: PASSED' "$log"; then
    local what
    if grep -q 'Temporal induction successful' "$log"; then
      local last
      last=$(grep -oE 'Trying induction in step [0-9]+' "$log" | tail -n1 | grep -oE '[0-9]+$')
      what="induction length $((d - last))"
    else
      what="BMC depth $d"
    fi
    echo "formal: $name: PASSED ($what; $((SECONDS - t0)) s)"
  else
    echo "formal: $name: FAILED; see $log" >&2
    grep -E 'Assert failed|failed|ERROR' "$log" | head -n 5 >&2 || true
    return 1
  fi
}

jobs=${HWINTERP_JOBS:-2}
status=0
# One run per stage block, width and (stepdir_axis only) ready_o mode, and
# one per core: "block w mode" (w, mode "-" for a core).
runs=()
for block in "${blocks[@]}"; do
  case "$block" in
    stepdir_axis | step_stage)
      for w in "${width_list[@]}"; do runs+=("$block $w 0"); done
      [ "$block" = stepdir_axis ] && runs+=("stepdir_axis ${width_list[0]} 1") ;;
    *) runs+=("$block - -") ;;
  esac
done
for r in "${runs[@]}"; do
  read -r block w rq <<<"$r"
  props=$root/rtl/formal/${block}_props.sv
  d=${depth:-40}
  if [ "$w" = - ]; then
    tag=$block
    chp=""
    d=${depth:-8}
  elif [ "$rq" = 1 ]; then
    tag=${block}_readyq_w$w
    chp="chparam -set TIM_W $w -set READY_Q 1 ${block}_props;"
  else
    tag=${block}_w$w
    chp="chparam -set TIM_W $w ${block}_props;"
  fi
  link=""
  if [ -n "${block_links[$block]:-}" ]; then
    # Before any optimisation, so that every signal named is still there
    # and no link wire has become an alias of another.
    link="hierarchy -check -top ${block}_props; proc; flatten;"
    for l in ${block_links[$block]}; do link+=" connect -nounset -set ${l%%=*} ${l#*=};"; done
  fi
  smt=$out/$tag.smt2
  # The links; prep; memory_map (a case the proc pass turns into a ROM would
  # be a memory whose contents induction leaves free); check -assert (no
  # undriven wire: a misread reference or a missing link fails here); then
  # async2sync (the asynchronous reset as logic on the flip-flop outputs,
  # which smtbmc can step) and dffunmap (plain $dff for write_smt2).
  yosys -q -l "$out/prep_$tag.log" -p "read_verilog -sv -formal ${block_files[$block]} $props;
    $chp $link prep -top ${block}_props; memory_map; opt_clean; check -assert;
    async2sync; dffunmap; write_smt2 -wires $smt" >/dev/null 2>&1 ||
    die "step 'yosys prep' failed for $tag; see $out/prep_$tag.log"
  # --unroll: with the default encoding, z3 4.8.12 spends ~80 s on the very
  # first query (measured: `-t 1` alone took 81 s); unrolled, BMC to depth 30
  # takes ~30 s and induction ~2 s, and the same mutants fail.
  bmc=(run "$out/bmc_${tag}_d$d.log" "$d" yosys-smtbmc -s z3 --unroll -t "$d"
    --dump-vcd "$out/bmc_${tag}_d$d.vcd" "$smt")
  ind=(run "$out/induction_${tag}_d$d.log" "$d" yosys-smtbmc -s z3 --unroll -i -t "$d"
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
echo "formal: all properties of ${blocks[*]} hold (BMC and induction; logs in $out)"
