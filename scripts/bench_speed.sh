#!/usr/bin/env bash
# Lockstep speed, side by side in one run, on one 4-axis random stream:
#   direct   hwinterp cosim --mode direct  (HLS tick() + verilator --cc, every check)
#   systemc  hwinterp cosim --mode systemc (SC_MODULE + verilator --sc, every check)
#   icarus   Icarus Verilog running rtl/dda_line.sv alone, replaying the very
#            same input frames (the replay testbench `--dump-frames` writes)
# Each is timed best-of-R (wall clock, whole process); Icarus's cycle count,
# steps, positions and done pulses are checked against the co-simulation, so
# all three provably ran the same workload. Ratios are against Icarus.
#
# Usage: scripts/bench_speed.sh [--commands N] [--seed S] [--repeat R] [--no-build]
# Output: table on stdout; logs and bench_speed.json in <build>/reports/bench_speed/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
py=${HWINTERP_VENV:-$root/.venv}/bin/python3  # scripts/setup.sh makes it
build=${HWINTERP_BUILD_DIR:-$root/build}
commands=100 seed=1 repeat=3 do_build=1
while [ $# -gt 0 ]; do
  case "$1" in
    --commands) commands=$2; shift 2 ;;
    --seed) seed=$2; shift 2 ;;
    --repeat) repeat=$2; shift 2 ;;
    --no-build) do_build=0; shift ;;
    *) echo "bench_speed.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
[ "$do_build" = 1 ] && "$root/scripts/build.sh"
hw=$build/tb/hwinterp
out=$build/reports/bench_speed
mkdir -p "$out"
for tool in iverilog vvp "$py"; do
  command -v "$tool" >/dev/null || { echo "bench_speed.sh: $tool not found (scripts/setup.sh installs it)" >&2; exit 2; }
done

stim=(--core dda_line --variant dda_line_n4 --random "$commands" --seed "$seed")

echo "bench_speed: dda_line_n4, random stream of $commands commands, seed $seed, best of $repeat"
"$hw" cosim "${stim[@]}" --mode direct --dump-frames "$out/frames.hex" --json "$out/reference.json" >"$out/reference.log"

# best_of NAME CMD...: runs CMD $repeat times, prints the fastest wall time (s).
best_of() {
  local name=$1 best="" t0 t1 dt
  shift
  for _ in $(seq "$repeat"); do
    t0=$(date +%s.%N)
    "$@" >"$out/$name.log" 2>&1 || { echo "bench_speed.sh: $name failed, see $out/$name.log" >&2; exit 1; }
    t1=$(date +%s.%N)
    dt=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.4f", b - a }')
    best=$(awk -v a="$best" -v b="$dt" 'BEGIN { print (a == "" || b < a) ? b : a }')
  done
  echo "$best"
}

t_direct=$(best_of direct "$hw" cosim "${stim[@]}" --mode direct --json "$out/direct.json")
t_systemc=$(best_of systemc "$hw" cosim "${stim[@]}" --mode systemc --json "$out/systemc.json")
mapfile -t rtl < <(sed "s|^|$root/rtl/|" "$root/rtl/dda_line.f")
t_compile=$(best_of icarus_compile iverilog -g2012 -o "$out/replay.vvp" -s replay_tb \
  "$out/frames.hex.sv" "${rtl[@]}")
t_icarus=$(best_of icarus vvp -n "$out/replay.vvp" +frames="$out/frames.hex")

"$py" - "$out" "$t_direct" "$t_systemc" "$t_icarus" "$t_compile" <<'PY'
import json, sys
out, t_direct, t_systemc, t_icarus, t_compile = sys.argv[1], *map(float, sys.argv[2:])
ref = json.load(open(f"{out}/reference.json"))
runs = {m: json.load(open(f"{out}/{m}.json")) for m in ("direct", "systemc")}
ica = {}
for line in open(f"{out}/icarus.log"):
    w = line.split()
    if w and w[0] == "cycles": ica["cycles"] = int(w[1])
    if w and w[0] == "done_pulses": ica["done"] = int(w[1])
    if w and w[0] == "axis": ica.setdefault("steps", []).append(int(w[3])); ica.setdefault("pos", []).append(int(w[5]))
same = (ica.get("cycles") == ref["cycles"] and ica.get("steps") == ref["steps"] and
        ica.get("pos") == ref["end_position"] and ica.get("done") == ref["commands"])
for m, r in runs.items():
    if r["cycles"] != ref["cycles"] or not r["passed"]:
        sys.exit(f"bench_speed.sh: {m} run differs from the reference run or failed")
if not same:
    sys.exit(f"bench_speed.sh: Icarus replay differs from the co-simulation: {ica} vs "
             f"cycles {ref['cycles']} steps {ref['steps']} end {ref['end_position']}")
cycles = ref["cycles"]
rows = [("direct", "HLS tick() + verilator --cc, lockstep + checks", t_direct),
        ("systemc", "SC_MODULE + verilator --sc, lockstep + checks", t_systemc),
        ("icarus", "rtl/dda_line.sv alone, frame replay", t_icarus)]
print(f"\n{'mode':8} {'what':48} {'cycles':>8} {'seconds':>8} {'cycles/s':>10} {'x icarus':>9}")
print("-" * 96)
report = {"cycles": cycles, "icarus_compile_seconds": t_compile, "runs": []}
for name, what, t in rows:
    rate = cycles / t
    print(f"{name:8} {what:48} {cycles:8d} {t:8.3f} {rate:10.3g} {rate / (cycles / t_icarus):9.1f}")
    report["runs"].append({"mode": name, "seconds": t, "cycles_per_second": rate,
                           "ratio_to_icarus": rate / (cycles / t_icarus)})
print(f"(wall time of the whole process, best of the runs; Icarus compile {t_compile:.2f} s not included;\n"
      f" Icarus replayed the same {cycles} frames and reproduced steps, positions and done pulses)")
json.dump(report, open(f"{out}/bench_speed.json", "w"), indent=2)
PY
