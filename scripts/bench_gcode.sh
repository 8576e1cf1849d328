#!/usr/bin/env bash
# hwinterp gcode end to end at scale: a generated part program of --moves
# motion moves (default 100000: CAM-style strokes of short G1 lines and G2/G3
# arcs with IJK, rapids and plunges between them, repeated over a 40 mm
# field) through motion_top_n4 in direct mode, and the same program at a
# tenth of the moves. Reports per run: wall time, steps per second end to end
# (reading, compiling, lockstep, contour error), clocks per second, and peak
# memory (maximum resident set of the hwinterp process): memory must not grow
# with the program (the moves, commands and checks stream).
# Usage: scripts/bench_gcode.sh [--moves N] [--no-build]
# Output: table on stdout, <build>/reports/bench_gcode/bench_gcode.json.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
py=${HWINTERP_VENV:-$root/.venv}/bin/python3  # scripts/setup.sh makes it
build=${HWINTERP_BUILD_DIR:-$root/build}
moves=100000 do_build=1
while [ $# -gt 0 ]; do
  case "$1" in
    --moves)
      moves=$2
      [[ "$moves" =~ ^[0-9]+$ ]] && [ "$moves" -ge 100 ] ||
        { echo "bench_gcode.sh: --moves '$moves' is not a whole number >= 100" >&2; exit 2; }
      shift 2 ;;
    --no-build) do_build=0; shift ;;
    *) echo "bench_gcode.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
[ "$do_build" = 1 ] && "$root/scripts/build.sh"
out=$build/reports/bench_gcode
mkdir -p "$out"
exec "$py" - "$build/tb/hwinterp" "$out" "$moves" <<'PY'
import json, os, subprocess, sys, time

hw, out, moves = sys.argv[1], sys.argv[2], int(sys.argv[3])

def program(path, n):
    """n motion moves: strokes of 6 lines and arcs each, 0.001 mm coordinates."""
    lines = ["G21 G90 G17 F800"]
    count, k = 0, 0
    while count < n:
        cx, cy = (k % 20) * 2.0 - 20.0, ((k // 20) % 20) * 2.0 - 20.0
        lines.append(f"G0 Z1 X{cx:.3f} Y{cy:.3f}")
        lines.append("G1 Z-0.1 F200")
        lines.append(f"G1 X{cx + 0.8:.3f} F800")
        lines.append(f"G3 X{cx + 0.8:.3f} Y{cy + 0.8:.3f} I0 J0.4")
        lines.append(f"G1 X{cx:.3f}")
        lines.append(f"G2 X{cx:.3f} Y{cy:.3f} I0 J-0.4")
        count += 6
        k += 1
    lines.append("G0 Z1")
    lines.append("M2")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return count + 1

def run(path):
    """Runs hwinterp gcode; returns (seconds, its peak RSS MiB, JSON report)."""
    t0 = time.monotonic()
    rep = os.path.join(out, os.path.basename(path) + ".json")
    log = os.path.join(out, os.path.basename(path) + ".log")
    with open(log, "w") as f:
        p = subprocess.run([hw, "gcode", path, "--mode", "direct", "--progress", "0", "--json", rep],
                           stdout=f, stderr=subprocess.STDOUT)
    wall = time.monotonic() - t0
    if p.returncode != 0:
        sys.exit(f"bench_gcode: {path} failed; see {log}")
    j = json.load(open(rep))
    # The report's own peak (VmHWM, since exec): a child's rusage would count
    # the Python process it was forked from.
    return wall, j["peak_rss_kib"] / 1024.0, j

rows = []
for n in (max(moves // 10, 10), moves):
    path = os.path.join(out, f"program_{n}.ngc")
    m = program(path, n)
    print(f"bench_gcode: {m} moves ({path}) ...", file=sys.stderr, flush=True)
    wall, peak, j = run(path)
    steps = sum(j["steps"])
    rows.append({"moves": j["moves"], "commands": j["commands"], "steps": steps,
                 "clocks": j["simulated_clocks"], "wall_s": round(wall, 2),
                 "steps_per_s": round(steps / wall), "clocks_per_s": round(j["simulated_clocks"] / wall),
                 "peak_rss_mib": round(peak, 1),
                 "max_contour_error_steps": j["max_contour_error_steps"]})
print(f"{'moves':>8} {'commands':>9} {'steps':>10} {'clocks':>11} {'wall s':>7} "
      f"{'steps/s':>9} {'clocks/s':>10} {'peak MiB':>9} {'contour':>8}")
for r in rows:
    print(f"{r['moves']:>8} {r['commands']:>9} {r['steps']:>10} {r['clocks']:>11} {r['wall_s']:>7} "
          f"{r['steps_per_s']:>9} {r['clocks_per_s']:>10} {r['peak_rss_mib']:>9} "
          f"{r['max_contour_error_steps']:>8.3f}")
print("peak MiB: the run's maximum resident set (its report's peak_rss_kib); the same figure at both sizes"
      " means memory did not grow with the program.")
json.dump(rows, open(os.path.join(out, "bench_gcode.json"), "w"), indent=1)
PY
