#!/usr/bin/env bash
# LinuxCNC drives the simulated board (docs/linuxcnc.md): software in the
# loop. Installs LinuxCNC 2.9 from Debian on demand (scripts/linuxcnc/setup.sh),
# builds and installs the HAL component (halcompile --install
# sw/hal/hwinterp.comp), starts the Colorlight's gateware without the feed
# profile at a clock the simulation keeps up with in real time, runs LinuxCNC
# headless on the mill of sw/hal/config/ with the program to its end, and
# writes the report: following error at every period boundary, late
# commands, bursts, end positions, machining times, the board's step timing,
# plots.
#
# Usage: scripts/linuxcnc/sil.sh PROG.ngc [--out DIR] [--clock-hz HZ]
#          [--fault estop S | --fault kill S | --fault cut S,D] [--timeout S]
#   --out DIR       where everything goes (default out/linuxcnc/<program>)
#   --clock-hz HZ   the board's clock (default 250000: the simulated
#                   Colorlight keeps real time at it beside LinuxCNC on a
#                   2-core machine; at 500000 it fell 9 % behind)
#   --fault estop S e-stop pressed S seconds into the program
#   --fault kill S  LinuxCNC killed (SIGKILL) S seconds into the program
#   --fault cut S,D the link cut S seconds into the program for D seconds
#                   (a UDP relay between LinuxCNC and the board drops
#                   everything), then LinuxCNC turned on again
#   --timeout S     LinuxCNC's whole run at most S seconds (default 900)
# Never in CI (LinuxCNC pulls about 380 packages): ctest -L linuxcnc runs it.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2; exit 2; }
[ $# -ge 1 ] || usage
case "$1" in -h|--help) usage ;; esac
program=$1
shift
out="" hz=250000 fault="" timeout=900
while [ $# -gt 0 ]; do
  case "$1" in
    --out) [ $# -ge 2 ] || usage; out=$2; shift 2 ;;
    --clock-hz) [ $# -ge 2 ] || usage; hz=$2; shift 2 ;;
    --fault) [ $# -ge 3 ] || usage; fault="$2 $3"; shift 3 ;;
    --timeout) [ $# -ge 2 ] || usage; timeout=$2; shift 2 ;;
    *) echo "sil: unknown option '$1'" >&2; exit 2 ;;
  esac
done
[ -f "$program" ] || { echo "sil: program '$program' is not a file" >&2; exit 2; }
[[ "$hz" =~ ^[1-9][0-9]*$ ]] || { echo "sil: --clock-hz '$hz' is not a clock in Hz" >&2; exit 2; }
[[ "$timeout" =~ ^[1-9][0-9]*$ ]] || { echo "sil: --timeout '$timeout' is not whole seconds" >&2; exit 2; }
case "$fault" in
  "" ) ;;
  estop\ *|kill\ *) [[ "${fault#* }" =~ ^[0-9]+(\.[0-9]+)?$ ]] || { echo "sil: --fault '$fault': give seconds" >&2; exit 2; } ;;
  cut\ *) [[ "${fault#* }" =~ ^[0-9]+(\.[0-9]+)?,[0-9]+(\.[0-9]+)?$ ]] || { echo "sil: --fault '$fault': give S,D seconds" >&2; exit 2; } ;;
  *) echo "sil: --fault '${fault%% *}': estop, kill or cut" >&2; exit 2 ;;
esac
program=$(cd "$(dirname "$program")" && pwd)/$(basename "$program")
name=$(basename "$program" .ngc)
out=${out:-$root/out/linuxcnc/$name${fault:+-${fault%% *}}}
mkdir -p "$out"
out=$(cd "$out" && pwd)
py=$root/.venv/bin/python3

"$root/scripts/linuxcnc/setup.sh"
# The HAL component, installed where rtapi_app loads modules from (again
# only when its sources changed).
stamp_want=$(cat "$root"/sw/hal/hwinterp.comp "$root"/sw/hal/hwinterp_*.[ch] "$root"/sw/board_regs.h | sha256sum | cut -d' ' -f1)
rtlib=$(dirname "$(find /usr/lib/linuxcnc/modules -name motmod.so | head -1)")
if [ "$(cat "$rtlib/.hwinterp.sha256" 2>/dev/null)" != "$stamp_want" ]; then
  echo "sil: building and installing the HAL component (scripts/linuxcnc/build_comp.sh --install)" >&2
  "$root/scripts/linuxcnc/build_comp.sh" --install >"$out/halcompile.log" 2>&1 ||
    { cat "$out/halcompile.log" >&2; exit 1; }
  sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
  echo "$stamp_want" | "${sudo_cmd[@]}" tee "$rtlib/.hwinterp.sha256" >/dev/null
fi

# The board (scripts/board_sim.sh builds the tree first, and this board at
# this clock without the profile when the build does not hold it).
rm -f "$out/board.uri"
"$root/scripts/board_sim.sh" colorlight_5a_75b --clock-hz "$hz" --no-profile --realtime \
  --uri-file "$out/board.uri" --json "$out/board.json" --steps-csv "$out/steps.csv" \
  --commands-csv "$out/commands.csv" --progress 0 >"$out/board.log" 2>&1 &
sim=$!
relay=""
cleanup() {
  [ -n "$relay" ] && kill "$relay" 2>/dev/null || true
  kill -TERM "$sim" 2>/dev/null || true
  wait "$sim" 2>/dev/null || true
}
trap cleanup EXIT
for _ in $(seq 3600); do
  [ -s "$out/board.uri" ] && break
  kill -0 "$sim" 2>/dev/null || { cat "$out/board.log" >&2; echo "sil: board-sim did not start" >&2; exit 1; }
  sleep 0.5
done
[ -s "$out/board.uri" ] || { echo "sil: board-sim did not serve within 30 minutes" >&2; exit 1; }
port=$(sed 's/.*://' "$out/board.uri")
if [ "${fault%% *}" = cut ]; then
  # LinuxCNC talks to the relay; the relay cuts the link for the time asked.
  rm -f "$out/relay.port"
  "$py" "$root/scripts/linuxcnc/udp_relay.py" --board-port "$port" --port-file "$out/relay.port" \
    --cut-file "$out/relay.cut" >"$out/relay.log" 2>&1 &
  relay=$!
  for _ in $(seq 100); do [ -s "$out/relay.port" ] && break; sleep 0.1; done
  port=$(cat "$out/relay.port")
fi

# LinuxCNC's configuration for this run: the mill, the board's port, the
# headless display, the sampler.
"$py" "$root/scripts/linuxcnc/sil_config.py" --config "$root/sw/hal/config" --out "$out/config" \
  --port "$port" --program "$program" --display "$root/scripts/linuxcnc/headless.py" \
  --fault "$fault" --timeout "$timeout" --relay-cut "$out/relay.cut"
# LinuxCNC's realtime refuses to run as root without a user to fall back to.
if [ "$(id -u)" -eq 0 ]; then
  mkdir -p "$out/rtapi" && chmod 1777 "$out/rtapi"
  export RTAPI_UID=$(id -u nobody) RTAPI_FIFO_PATH=$out/rtapi/fifo
fi
echo "sil: LinuxCNC runs $name against the board at $hz Hz (udp:127.0.0.1:$port); $out/linuxcnc.log" >&2
start=$(date +%s.%N)
set +e
(cd "$out/config" && timeout --kill-after=30 "$timeout" linuxcnc hwinterp_mill.ini) >"$out/linuxcnc.log" 2>&1
rc=$?
set -e
end=$(date +%s.%N)
# A killed LinuxCNC leaves its realtime behind: clear it.
if [ "${fault%% *}" = kill ]; then
  sleep 1
  halrun -U >/dev/null 2>&1 || true
fi
# The board's watchdog, and what it did after: a second of board time more.
sleep 1.5
cleanup
trap - EXIT
"$py" "$root/scripts/linuxcnc/sil_report.py" --out "$out" --linuxcnc-rc "$rc" \
  --wall-s "$(echo "$end - $start" | bc)"
