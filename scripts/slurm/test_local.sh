#!/usr/bin/env bash
# Tests the Slurm job array on a real single-node Slurm on localhost: a
# private munged, slurmctld and slurmd (own key, socket, configuration,
# state and logs under a temporary folder, stopped on exit), the regression
# submitted as an array of N shards (scripts/slurm/submit.sh), and the merged
# report compared, case for case, with the unsharded run's (timings aside).
# Needs root (the daemons) and Debian's slurm-wlm and munge, which it
# installs when missing (never in CI: ctest label `long`).
# Usage: scripts/slurm/test_local.sh [--shards N] [regress args]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
py=${HWINTERP_VENV:-$root/.venv}/bin/python3  # scripts/setup.sh makes it
build=${HWINTERP_BUILD_DIR:-$root/build}
hw=$build/tb/hwinterp
shards=2
if [ "${1:-}" = "--shards" ]; then shards=$2; shift 2; fi
args=("$@")
[ ${#args[@]} -gt 0 ] || args=(--random 20 --seed 5)

[ "$(id -u)" -eq 0 ] || { echo "test_local.sh: needs root (slurmctld, slurmd, munged)" >&2; exit 2; }
[ -x "$hw" ] || { echo "test_local.sh: $hw not built (scripts/build.sh)" >&2; exit 2; }
for p in slurm-wlm munge; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    echo "test_local.sh: installing slurm-wlm munge" >&2
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends slurm-wlm munge >/dev/null
    break
  fi
done

tmp=$(mktemp -d /tmp/hwinterp-slurm.XXXXXX)
host=$(hostname -s)
cpus=$(nproc)
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
  wait 2>/dev/null || true
}
trap cleanup EXIT
echo "test_local.sh: single-node Slurm on $host ($cpus CPUs) in $tmp" >&2

mkdir -p "$tmp/state" "$tmp/spool" "$tmp/out"
dd if=/dev/urandom of="$tmp/munge.key" bs=1024 count=1 status=none
chmod 400 "$tmp/munge.key"
/usr/sbin/munged --force --foreground --key-file="$tmp/munge.key" --socket="$tmp/munge.sock" \
  --pid-file="$tmp/munged.pid" --log-file="$tmp/munged.log" --seed-file="$tmp/munge.seed" \
  >"$tmp/munged.out" 2>&1 &
pids+=($!)
cat >"$tmp/slurm.conf" <<CONF
ClusterName=hwinterp
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
AuthType=auth/munge
AuthInfo=socket=$tmp/munge.sock
CredType=cred/munge
StateSaveLocation=$tmp/state
SlurmdSpoolDir=$tmp/spool
SlurmctldPidFile=$tmp/slurmctld.pid
SlurmdPidFile=$tmp/slurmd.pid
SlurmctldLogFile=$tmp/slurmctld.log
SlurmdLogFile=$tmp/slurmd.log
SlurmctldPort=16817
SlurmdPort=16818
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$tmp/slurm.conf
for i in $(seq 50); do [ -S "$tmp/munge.sock" ] && break; sleep 0.1; done
/usr/sbin/slurmctld -D -f "$SLURM_CONF" >"$tmp/slurmctld.out" 2>&1 &
pids+=($!)
/usr/sbin/slurmd -D -f "$SLURM_CONF" >"$tmp/slurmd.out" 2>&1 &
pids+=($!)
for i in $(seq 100); do
  state=$(sinfo -h -n "$host" -o %t 2>/dev/null || true)
  [ "$state" = "idle" ] && break
  sleep 0.2
done
[ "${state:-}" = "idle" ] || { echo "test_local.sh: the node did not come up (state '${state:-}'); logs in $tmp" >&2; exit 1; }
echo "test_local.sh: node $host idle; submitting $shards shards: regress ${args[*]}" >&2

t0=$(date +%s.%N)
HWINTERP=$hw "$root/scripts/slurm/submit.sh" "$shards" "$tmp/out" "${args[@]}" >"$tmp/submit.log" 2>&1 ||
  { echo "test_local.sh: the array or the merge failed; see $tmp/submit.log" >&2; tail -n 20 "$tmp/submit.log" >&2; exit 1; }
t1=$(date +%s.%N)
jobs_run=$(grep -c . < <(ls "$tmp/out"/shard_*.json))
"$hw" regress "${args[@]}" --progress 0 --json "$tmp/unsharded.json" >"$tmp/unsharded.log" 2>&1 ||
  { echo "test_local.sh: the unsharded run failed; see $tmp/unsharded.log" >&2; exit 1; }
"$py" - "$tmp/out/regress.json" "$tmp/unsharded.json" <<'PY'
import json, sys
def strip(j):
    if isinstance(j, dict):
        return {k: strip(v) for k, v in j.items() if k not in ("seconds", "cycles_per_second", "shards")}
    if isinstance(j, list):
        return [strip(x) for x in j]
    return j
merged, full = (json.load(open(p)) for p in sys.argv[1:])
if strip(merged) != strip(full):
    sys.exit("test_local.sh: the merged shards differ from the unsharded run")
cases = sum(len(r["cases"]) for r in full["runs"])
print(f"test_local.sh: PASS: {cases} cases in the merged Slurm shards equal the unsharded run")
PY
echo "test_local.sh: $jobs_run array tasks ran; array + merge took $(awk -v a="$t0" -v b="$t1" 'BEGIN{printf "%.1f", b-a}') s" >&2
