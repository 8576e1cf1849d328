#!/usr/bin/env bash
# What a user should know before a long run, measured:
#  - per core (its first variant) and lockstep mode, a seeded random stream of
#    about --clocks clocks (default 10^8): wall time, clocks per second and
#    peak memory (maximum resident set of the hwinterp process);
#  - trace size: one 4-axis dda_line stream of about 10^6 clocks written as
#    VCD and as FST: MB per million clocks.
# Usage: scripts/bench_memory.sh [--clocks N] [--no-build]
# Output: table on stdout, <build>/reports/bench_memory/bench_memory.json.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
py=${HWINTERP_VENV:-$root/.venv}/bin/python3  # scripts/setup.sh makes it
build=${HWINTERP_BUILD_DIR:-$root/build}
clocks=100000000 do_build=1
while [ $# -gt 0 ]; do
  case "$1" in
    --clocks) clocks=$2; shift 2 ;;
    --no-build) do_build=0; shift ;;
    *) echo "bench_memory.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
[ "$do_build" = 1 ] && "$root/scripts/build.sh"
out=$build/reports/bench_memory
mkdir -p "$out"
exec "$py" - "$build/tb/hwinterp" "$out" "$clocks" <<'PY'
import json, os, resource, subprocess, sys, time

hw, out, target = sys.argv[1], sys.argv[2], int(sys.argv[3])

def run(args):
    """Runs hwinterp in a child; returns (seconds, peak RSS MiB, JSON report)."""
    report = os.path.join(out, "run.json")
    code = ("import resource, subprocess, sys, time; t = time.time(); "
            "r = subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL); "
            "print(time.time() - t, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss, r.returncode)")
    res = subprocess.run([sys.executable, "-c", code, hw, *args, "--json", report],
                         capture_output=True, text=True, check=True)
    seconds, rss_kib, rc = res.stdout.split()
    if int(rc) != 0:
        sys.exit(f"bench_memory.sh: hwinterp {' '.join(args)} failed (exit {rc})")
    return float(seconds), int(rss_kib) / 1024, json.load(open(report))

# Every core and its first variant, from a short regression's report.
listing = os.path.join(out, "cores.json")
subprocess.run([hw, "regress", "--random", "10", "--modes", "direct", "--progress", "0",
                "--json", listing], stdout=subprocess.DEVNULL, check=True)
first = {}
for r in json.load(open(listing))["runs"]:
    first.setdefault(r["core"], r["variant"])
rows, results = [], []
print(f"{'core':9} {'variant':14} {'mode':8} {'clocks':>12} {'seconds':>8} {'clocks/s':>10} {'peak MiB':>9}")
for core, variant in first.items():
    base = ["cosim", "--core", core, "--variant", variant, "--seed", "1"]
    # Clocks per random command, from a short stream.
    _, _, cal = run(base + ["--random", "200", "--mode", "direct"])
    commands = max(200, round(200 * target / cal["cycles"]))
    for mode in ("direct", "systemc"):
        sec, mib, rep = run(base + ["--random", str(commands), "--mode", mode])
        rate = rep["cycles"] / sec
        print(f"{core:9} {variant:14} {mode:8} {rep['cycles']:>12,} {sec:8.1f} {rate:10.3g} {mib:9.1f}")
        results.append({"core": core, "variant": variant, "mode": mode, "commands": commands,
                        "clocks": rep["cycles"], "seconds": sec, "clocks_per_second": rate,
                        "peak_rss_mib": mib, "passed": rep["passed"]})
# Trace sizes per million clocks.
base = ["cosim", "--core", "dda_line", "--variant", "dda_line_n4", "--seed", "1", "--mode", "direct"]
_, _, cal = run(base + ["--random", "200"])
commands = max(200, round(200 * 1e6 / cal["cycles"]))
traces = {}
for kind in ("vcd", "fst"):
    path = os.path.join(out, "trace." + kind)
    sec, mib, rep = run(base + ["--random", str(commands), "--" + kind, path])
    size = os.path.getsize(path)
    traces[kind] = {"clocks": rep["cycles"], "bytes": size,
                    "mb_per_million_clocks": size / 1e6 / (rep["cycles"] / 1e6), "seconds": sec}
    os.remove(path)
    print(f"trace {kind}: {size / 1e6:.1f} MB for {rep['cycles']:,} clocks: "
          f"{traces[kind]['mb_per_million_clocks']:.1f} MB per million clocks ({sec:.1f} s)")
json.dump({"target_clocks": target, "runs": results, "traces": traces},
          open(os.path.join(out, "bench_memory.json"), "w"), indent=2)
PY
