#!/usr/bin/env bash
# The main regression as a Slurm job array of N shards, then merged:
#   scripts/slurm/submit.sh N OUT [regress args]
# Waits for the array (sbatch --wait), then writes OUT/regress.json and
# OUT/regress.xml with `hwinterp merge`. Exit 0 when every case passed.
# Extra sbatch options: SBATCH_OPTS="--partition=big --time=2:00:00".
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
[ $# -ge 2 ] || { echo "usage: scripts/slurm/submit.sh N OUT [regress args]" >&2; exit 2; }
n=$1 out=$2
shift 2
[[ $n =~ ^[1-9][0-9]*$ ]] || { echo "submit.sh: N: '$n' is not a positive integer" >&2; exit 2; }
hw=${HWINTERP:-$root/build/tb/hwinterp}
[ -x "$hw" ] || { echo "submit.sh: $hw not built (scripts/build.sh)" >&2; exit 2; }
mkdir -p "$out"
out=$(cd "$out" && pwd)
rm -f "$out"/shard_*.json
# shellcheck disable=SC2086
HWINTERP=$hw sbatch --wait --array="1-$n" --chdir="$out" ${SBATCH_OPTS:-} \
  "$root/scripts/slurm/regress.sbatch" "$out" "$@" || true  # a failed check still wrote its shard
"$hw" merge "$out"/shard_*.json --json "$out/regress.json" --junit "$out/regress.xml"
