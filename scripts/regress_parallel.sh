#!/usr/bin/env bash
# The main regression sharded over the cores of one workstation with GNU
# parallel: N shards (`hwinterp regress --shard K/N`) run side by side, then
# `hwinterp merge` joins their reports into the unsharded run's (timings
# aside). Extra arguments go to every shard.
# Usage: scripts/regress_parallel.sh [-j N] [-o NAME] [regress args]
#   -j N     shards and parallel jobs (default: the number of cores)
#   -o NAME  report name (default regress)
# Reports: <build>/reports/NAME-shards/ (one JSON and log per shard),
# <build>/reports/NAME.json and NAME.xml (merged).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
jobs=$(nproc) name=regress
while [ $# -gt 0 ]; do
  case "$1" in
    -j) jobs=$2; shift 2 ;;
    -o) name=$2; shift 2 ;;
    *) break ;;
  esac
done
[[ $jobs =~ ^[1-9][0-9]*$ ]] || { echo "regress_parallel.sh: -j: '$jobs' is not a positive integer" >&2; exit 2; }
"$root/scripts/build.sh"
build=${HWINTERP_BUILD_DIR:-$root/build}
out=$build/reports/$name-shards
rm -rf "$out"
mkdir -p "$out"
command -v parallel >/dev/null || { echo "regress_parallel.sh: GNU parallel not found (scripts/setup.sh installs it)" >&2; exit 2; }
echo "regress_parallel: $jobs shards with GNU parallel; logs in $out" >&2
status=0
seq 1 "$jobs" | parallel --will-cite --halt never -j "$jobs" \
  "$build/tb/hwinterp" regress --shard "{}/$jobs" --progress 0 --json "$out/shard_{}.json" "$@" \
  '>' "$out/shard_{}.log" 2'>&'1 || status=$?
# A shard that failed a check still wrote its report: merge shows which cases.
"$build/tb/hwinterp" merge "$out"/shard_*.json --json "$build/reports/$name.json" \
  --junit "$build/reports/$name.xml" || status=1
exit $status
