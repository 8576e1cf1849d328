#!/usr/bin/env bash
# Synthesis handoff flow: per core variant, resources and Fmax.
#
# Usage: scripts/synth.sh [--variant NAME]... [--match REGEX] [--out DIR] [--generic-only]
#                         [--seeds "1 2 3"] [--freq MHZ] [--check-netlist | --no-check-netlist]
#                         [--commands N]
#
#   --variant NAME   a variant of <build>/generated/variants.txt (repeatable;
#                    default: all of them)
#   --match REGEX    only the variants whose name matches REGEX (bash =~),
#                    e.g. '_edge$': one narrow variant of every core (CI's
#                    netlist check)
#   --out DIR        output directory (default <build>/reports/synth)
#   --generic-only   only the Yosys generic synthesis (seconds; a quick check
#                    that the flow reads the RTL)
#   --seeds LIST     nextpnr seeds for the HX8K runs; the first one is the fixed
#                    seed, also used for UP5K (default "1 2 3")
#   --freq MHZ       nextpnr target frequency (default 12; the achieved Fmax is
#                    what the table reports)
#   --check-netlist  simulate the Yosys generic netlist against the RTL in
#                    lockstep (Verilator) on the input frames of a co-simulated
#                    random stream with aborts and feed holds; on by default
#                    except with --generic-only
#   --commands N     commands in that stream (default 1500)
#   --pnr-timeout S  give up a nextpnr run after S seconds (default 900): its
#                    router can circle for ever on one overused wire (seen on
#                    nextpnr-ice40 0.4); the table records the seed as not routed
#
# Per variant (parameters from variants.txt, the configure-time copy of
# cmake/cores.cmake; RTL files from rtl/<core>.f):
#   1. Yosys `synth -flatten -top <core>`: generic cells by type.
#   2. `synth_ice40 -top <core>`: LUT4 / SB_CARRY / flip-flops of the bare core.
#   3. `synth_ice40` of a pin harness generated for the core from its ports
#      (scripts/synth/make_harness.py: the core behind a few registered pins)
#      and nextpnr-ice40 --hx8k --package ct256 per seed: placed LUT/FF/LC and
#      "Max frequency for clock".
#   4. the same netlist with nextpnr-ice40 --up5k --package sg48: fits or not.
#   5. (--check-netlist) `hwinterp cosim --dump-frames` writes a random
#      stream's input frames and a replay testbench; with +define+NETLIST it
#      runs step 1's netlist beside the RTL and compares every output every
#      clock (needs the build's hwinterp; built here if missing).
# Writes <out>/synth.md, <out>/synth.json and prints the markdown table. Logs
# and intermediate files stay in <out>/<variant>/. Honours HWINTERP_BUILD_DIR.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
py=${HWINTERP_VENV:-$root/.venv}/bin/python3  # scripts/setup.sh makes it
build=${HWINTERP_BUILD_DIR:-$root/build}

die() { echo "synth: $*" >&2; exit 1; }
usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2; exit 2; }

variants=()
match=""
out=""
generic_only=0
seeds="1 2 3"
freq=12
check=""
commands=1500
pnr_timeout=900
while [ $# -gt 0 ]; do
  case "$1" in
    --variant) [ $# -ge 2 ] || usage; variants+=("$2"); shift 2 ;;
    --match) [ $# -ge 2 ] || usage; match=$2; shift 2 ;;
    --out) [ $# -ge 2 ] || usage; out=$2; shift 2 ;;
    --generic-only) generic_only=1; shift ;;
    --seeds) [ $# -ge 2 ] || usage; seeds=$2; shift 2 ;;
    --freq) [ $# -ge 2 ] || usage; freq=$2; shift 2 ;;
    --check-netlist) check=1; shift ;;
    --no-check-netlist) check=0; shift ;;
    --commands) [ $# -ge 2 ] || usage; commands=$2; shift 2 ;;
    --pnr-timeout) [ $# -ge 2 ] || usage; pnr_timeout=$2; shift 2 ;;
    -h|--help) usage ;;
    *) echo "synth: unknown argument '$1'" >&2; usage ;;
  esac
done
[ -n "$check" ] || check=$((1 - generic_only))
read -r -a seed_list <<<"$seeds"
[ ${#seed_list[@]} -ge 1 ] || die "--seeds needs at least one seed"
for s in "${seed_list[@]}"; do
  [[ $s =~ ^[0-9]+$ ]] || die "--seeds: '$s' is not a non-negative integer"
done
[[ $freq =~ ^[0-9]+([.][0-9]+)?$ ]] || die "--freq: '$freq' is not a frequency in MHz"
[[ $commands =~ ^[1-9][0-9]*$ ]] || die "--commands: '$commands' is not a positive integer"
[[ $pnr_timeout =~ ^[1-9][0-9]*$ ]] || die "--pnr-timeout: '$pnr_timeout' is not a positive number of seconds"

"$root/scripts/setup.sh"

# Fail early and by name rather than halfway through a variant.
need=(yosys "$py")
[ $generic_only -eq 1 ] || need+=(nextpnr-ice40)
[ "$check" -eq 0 ] || need+=(verilator)
for t in "${need[@]}"; do
  command -v "$t" >/dev/null || die "$t not found (scripts/setup.sh installs it)"
done

out=${out:-$build/reports/synth}
mkdir -p "$out"
out=$(cd "$out" && pwd)

# variants.txt is written at configure time; configure if it is missing or
# older than the file it comes from, so a changed variant is never synthesized
# with stale parameters.
vfile=$build/generated/variants.txt
if [ ! -f "$vfile" ] || [ "$root/cmake/cores.cmake" -nt "$vfile" ]; then
  for t in cmake ninja; do
    command -v "$t" >/dev/null || die "$t not found (scripts/setup.sh installs it)"
  done
  echo "synth: configuring $build for $vfile (log: $out/configure.log)" >&2
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >"$out/configure.log" 2>&1 ||
    die "step 'cmake configure' failed; see $out/configure.log"
  [ -f "$vfile" ] || die "configure did not write $vfile; see $out/configure.log"
fi

# The netlist check replays co-simulation frames: it needs hwinterp.
hw=$build/tb/hwinterp
if [ "$check" -eq 1 ]; then
  echo "synth: building hwinterp for the netlist check (log: $out/build.log)" >&2
  cmake --build "$build" -j "${HWINTERP_JOBS:-2}" --target hwinterp >"$out/build.log" 2>&1 ||
    die "step 'build hwinterp' failed; see $out/build.log"
fi

declare -A vline=()
all=()
while read -r name rest; do
  [ -n "$name" ] || continue
  vline[$name]=$rest
  all+=("$name")
done <"$vfile"
[ ${#all[@]} -gt 0 ] || die "$vfile lists no variant"
if [ ${#variants[@]} -eq 0 ]; then
  variants=("${all[@]}")
else
  for v in "${variants[@]}"; do
    [ -n "${vline[$v]+x}" ] || die "unknown variant '$v' (variants.txt has: ${all[*]})"
  done
fi
if [ -n "$match" ]; then
  kept=()
  for v in "${variants[@]}"; do [[ $v =~ $match ]] && kept+=("$v"); done
  [ ${#kept[@]} -gt 0 ] || die "--match '$match' matches no variant (of: ${variants[*]})"
  variants=("${kept[@]}")
fi

# The RTL files of a core, from rtl/<core>.f (the list Verilator gets too).
rtl_files() {
  local list=$root/rtl/$1.f
  [ -f "$list" ] || die "no RTL file list $list for core $1"
  grep -v '^#' "$list" | sed "s|^|$root/rtl/|"
}

# run_step STEP LOG CMD...: runs CMD with its output in LOG, appends the wall
# time to $vdir/times.tsv, and stops the script naming the step and the log.
run_step() {
  local step=$1 log=$2 t0 t1
  shift 2
  t0=$(date +%s.%N)
  if ! "$@" >"$log" 2>&1; then
    echo "synth: step '$step' failed for $variant; see $log" >&2
    grep -m5 -E 'ERROR|Error|error:' "$log" >&2 || tail -n 5 "$log" >&2
    exit 1
  fi
  t1=$(date +%s.%N)
  awk -v s="$step" -v a="$t0" -v b="$t1" 'BEGIN { printf "%s\t%.2f\n", s, b - a }' >>"$vdir/times.tsv"
}

# Per core: the RTL files, checked once. Yosys reads them as they are: a
# construct it does not support stops it with an error naming the line (the
# RTL is never rewritten here), and yosys_compat.py refuses the constructs
# Yosys 0.23 reads wrongly without any message.
declare -A yfiles=()
prepare_core() {
  local core=$1 srcdir files
  srcdir=$out/src/$core
  mapfile -t files < <(rtl_files "$core")
  [ ${#files[@]} -gt 0 ] || die "rtl/$core.f lists no file"
  for f in "${files[@]}"; do [ -f "$f" ] || die "RTL file $f (rtl/$core.f) not found"; done
  mkdir -p "$srcdir"
  "$py" "$root/scripts/synth/yosys_compat.py" "${files[@]}" 2>"$srcdir/compat_check.log" ||
    die "the $core RTL has constructs Yosys 0.23 misreads; see $srcdir/compat_check.log:
$(cat "$srcdir/compat_check.log")"
  yosys -q -l "$srcdir/read.log" -p "read_verilog -sv ${files[*]}" >/dev/null 2>&1 ||
    die "step 'read' failed: Yosys $(yosys -V | awk '{print $2}') cannot read the $core RTL" \
      "as it is; see $srcdir/read.log:
$(grep -m3 'ERROR' "$srcdir/read.log" || tail -n 3 "$srcdir/read.log")"
  yfiles[$core]="${files[*]}"
}

t_start=$(date +%s)
for variant in "${variants[@]}"; do
  read -r core params_kv <<<"${vline[$variant]}"
  [ -n "${yfiles[$core]+x}" ] || prepare_core "$core"
  vdir=$out/$variant
  rm -rf "$vdir"
  mkdir -p "$vdir"
  : >"$vdir/times.tsv"
  read -r -a kvs <<<"$params_kv"
  chparam="chparam"
  for kv in "${kvs[@]}"; do chparam+=" -set ${kv%%=*} ${kv#*=}"; done
  read_rtl="read_verilog -sv ${yfiles[$core]}"
  {
    printf 'variant\t%s\ncore\t%s\nparams\t%s\n' "$variant" "$core" "$params_kv"
    printf 'generic_only\t%s\nseeds\t%s\nfreq\t%s\ncheck\t%s\n' "$generic_only" "${seed_list[*]}" "$freq" "$check"
    printf 'date\t%s\ngit\t%s\n' "$(date -u +%Y-%m-%d)" \
      "$(git -C "$root" describe --always --dirty 2>/dev/null || echo unknown)"
    printf 'yosys\t%s\nnextpnr\t%s\n' "$(yosys -V)" \
      "$(nextpnr-ice40 --version 2>&1 | head -n1 || true)"
  } >"$vdir/info.tsv"
  echo "synth: $variant ($core $params_kv)" >&2

  # 1. Generic synthesis. -flatten: one figure for the whole core, as the
  #    iCE40 flow (which flattens by default) gives.
  run_step generic "$vdir/generic.log" yosys -p "$read_rtl; $chparam $core;
    synth -flatten -top $core; tee -q -o $vdir/generic_stat.json stat -json;
    rename -top ${core}_net; write_verilog -noattr $vdir/${core}_net.v"

  if [ $generic_only -eq 0 ]; then
    # 2. The bare core mapped to iCE40 cells (not placed: too many ports).
    run_step ice40_core "$vdir/ice40_core.log" yosys -p "$read_rtl; $chparam $core;
      synth_ice40 -top $core; tee -q -o $vdir/ice40_core_stat.json stat -json"

    # 3. The harness, generated from the core's ports, mapped once and placed per seed.
    #    (rename -top: chparam may leave the top as $paramod$<hash>\<core>.)
    run_step ports "$vdir/ports.log" yosys -p "$read_rtl; $chparam $core; hierarchy -top $core; proc;
      rename -top $core;
      write_json $vdir/ports.json"
    run_step make_harness "$vdir/make_harness.log" sh -c \
      '"$1" "$2" "$3" "$4" $5 >"$6"' _ "$py" "$root/scripts/synth/make_harness.py" "$vdir/ports.json" \
      "$core" "$params_kv" "$vdir/${core}_harness.sv"
    run_step ice40_harness "$vdir/ice40_harness.log" yosys -p "$read_rtl $vdir/${core}_harness.sv;
      synth_ice40 -top ${core}_harness -json $vdir/harness.json;
      tee -q -o $vdir/harness_stat.json stat -json"
    for s in "${seed_list[@]}"; do
      plog=$vdir/pnr_hx8k_seed$s.log
      t0=$(date +%s.%N)
      rc=0
      timeout "$pnr_timeout" nextpnr-ice40 --hx8k --package ct256 --json "$vdir/harness.json" \
        --seed "$s" --freq "$freq" --timing-allow-fail --report "$vdir/pnr_hx8k_seed$s.json" \
        >"$plog" 2>&1 || rc=$?
      if [ $rc -eq 124 ]; then
        printf 'hx8k_timeout_seed%s\t%s\n' "$s" "$pnr_timeout" >>"$vdir/info.tsv"
        echo "synth: $variant: nextpnr seed $s did not finish routing in $pnr_timeout s (recorded as not routed; $plog)" >&2
      elif [ $rc -ne 0 ]; then
        echo "synth: step 'pnr_hx8k_seed$s' failed for $variant; see $plog" >&2
        grep -m5 -E 'ERROR|Error|error:' "$plog" >&2 || tail -n 5 "$plog" >&2
        exit 1
      fi
      awk -v s="pnr_hx8k_seed$s" -v a="$t0" -v b="$(date +%s.%N)" \
        'BEGIN { printf "%s\t%.2f\n", s, b - a }' >>"$vdir/times.tsv"
    done

    # 4. UP5K: not fitting is a result, not a failure; any other error is.
    s=${seed_list[0]}
    ulog=$vdir/pnr_up5k_seed$s.log
    t0=$(date +%s.%N)
    if nextpnr-ice40 --up5k --package sg48 --json "$vdir/harness.json" --seed "$s" --freq "$freq" \
      --timing-allow-fail --report "$vdir/pnr_up5k_seed$s.json" >"$ulog" 2>&1; then
      printf 'up5k_fit\tyes\n' >>"$vdir/info.tsv"
    elif over=$(awk '/Device utilisation/ { u = 1; next } u && !NF { exit }
        u && match($0, /[A-Z_0-9]+: *[0-9]+\/ *[0-9]+/) {
          split(substr($0, RSTART, RLENGTH), f, /[:\/ ]+/)
          if (f[2] + 0 > f[3] + 0) printf "%s %s/%s ", f[1], f[2], f[3]
        }' "$ulog") && [ -n "$over" ]; then
      printf 'up5k_fit\tno\nup5k_reason\tdoes not fit: %s\n' "${over% }" >>"$vdir/info.tsv"
    else
      echo "synth: step 'pnr_up5k_seed$s' failed for $variant; see $ulog" >&2
      grep -m5 'ERROR' "$ulog" >&2 || tail -n 5 "$ulog" >&2
      exit 1
    fi
    awk -v s="pnr_up5k_seed$s" -v a="$t0" -v b="$(date +%s.%N)" \
      'BEGIN { printf "%s\t%.2f\n", s, b - a }' >>"$vdir/times.tsv"
  fi

  # 5. The generic netlist against the RTL as Verilator reads it, on the
  #    frames of a co-simulated random stream (with aborts and feed holds).
  if [ "$check" -eq 1 ]; then
    mapfile -t rtl < <(rtl_files "$core")
    run_step netlist_frames "$vdir/netlist_frames.log" "$hw" cosim --core "$core" --variant "$variant" \
      --random "$commands" --seed 1 --with-aborts --with-holds --mode direct \
      --dump-frames "$vdir/frames.hex"
    run_step netlist_build "$vdir/netlist_build.log" verilator --binary -j "${HWINTERP_JOBS:-2}" \
      -Wno-fatal -Wno-lint -Wno-style --x-assign unique --x-initial unique -DNETLIST \
      --Mdir "$vdir/netlist_obj" --top-module replay_tb "${rtl[@]}" "$vdir/${core}_net.v" \
      "$vdir/frames.hex.sv" -o tb
    run_step netlist_check "$vdir/netlist_check.log" "$vdir/netlist_obj/tb" +frames="$vdir/frames.hex"
    grep -q 'netlist matches RTL' "$vdir/netlist_check.log" ||
      die "step 'netlist_check' did not report a match for $variant; see $vdir/netlist_check.log"
  fi
done

"$py" "$root/scripts/synth/synth_report.py" "$out" "${variants[@]}" ||
  die "step 'report' failed (scripts/synth/synth_report.py)"
echo "synth: done in $(($(date +%s) - t_start)) s; $out/synth.md, $out/synth.json" >&2
