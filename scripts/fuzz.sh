#!/usr/bin/env bash
# Fuzzes every input the testbench reads with libFuzzer (clang, ASan + UBSan):
# tests/fuzz/fuzz_*.cpp, each for --seconds S, starting from its committed
# corpus (tests/fuzz/corpus/<target>/, read only; what the run finds goes to
# <build-fuzz>/corpus/<target>/). A crash, a sanitizer report, a leak or a
# timeout stops with exit 1 and leaves the input in <build-fuzz>/artifacts/;
# copy it into tests/fuzz/corpus/<target>/ once fixed, where the normal
# build's <target>_replay test keeps it as a regression.
#
# Usage: scripts/fuzz.sh [--seconds S] [--target NAME]... [--no-build]
#   --seconds S   run each target this long (default 30)
#   --target NAME only this target (repeatable; default: every fuzz_*.cpp)
# Builds with `cmake --preset fuzz` in build-fuzz/ (HWINTERP_FUZZ_BUILD_DIR
# changes it); only the fuzz targets are built there.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${HWINTERP_FUZZ_BUILD_DIR:-$root/build-fuzz}
seconds=30 do_build=1
targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    --seconds) seconds=$2; shift 2 ;;
    --target) targets+=("$2"); shift 2 ;;
    --no-build) do_build=0; shift ;;
    *) echo "fuzz.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
[[ $seconds =~ ^[1-9][0-9]*$ ]] || { echo "fuzz.sh: --seconds: '$seconds' is not a positive integer" >&2; exit 2; }
if [ ${#targets[@]} -eq 0 ]; then
  for f in "$root"/tests/fuzz/fuzz_*.cpp; do targets+=("$(basename "$f" .cpp)"); done
fi

"$root/scripts/setup.sh"
if [ "$do_build" = 1 ]; then
  echo "fuzz: building ${targets[*]} with clang in $build (log: $build/build.log)" >&2
  mkdir -p "$build"
  { cmake --preset fuzz -S "$root" -B "$build" &&
    cmake --build "$build" -j "${HWINTERP_JOBS:-2}" --target "${targets[@]}"; } >"$build/build.log" 2>&1 ||
    { echo "fuzz: build failed; see $build/build.log" >&2; tail -n 20 "$build/build.log" >&2; exit 1; }
fi

status=0
for t in "${targets[@]}"; do
  work=$build/corpus/$t
  mkdir -p "$work" "$build/artifacts"
  log=$build/$t.log
  echo "fuzz: $t for $seconds s (corpus $work, seeds tests/fuzz/corpus/$t)" >&2
  if "$build/tests/fuzz/$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -print_final_stats=1 -artifact_prefix="$build/artifacts/$t-" \
      "$work" "$root/tests/fuzz/corpus/$t" >"$log" 2>&1; then
    runs=$(grep -oE 'stat::number_of_executed_units: *[0-9]+' "$log" | grep -oE '[0-9]+$' || echo "?")
    cov=$(grep -oE 'cov: [0-9]+' "$log" | tail -n1 || echo "cov: ?")
    echo "fuzz: $t clean: $runs inputs in $seconds s, $cov, corpus $(ls "$work" | wc -l) files" >&2
  else
    echo "fuzz: $t FOUND A FAILURE; see $log and $build/artifacts/$t-*" >&2
    grep -E 'ERROR|SUMMARY|deadly|Test unit written' "$log" | head -n 8 >&2 || true
    status=1
  fi
done
exit $status
