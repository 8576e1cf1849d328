#!/usr/bin/env bash
# LinuxCNC drives the simulated board (docs/linuxcnc.md): software in the
# loop. Installs LinuxCNC 2.9 from Debian on demand (scripts/linuxcnc/setup.sh),
# builds and installs the HAL component (halcompile --install
# sw/hal/hwinterp.comp), starts a board's gateware without the feed profile
# at a clock the simulation keeps up with in real time, runs LinuxCNC
# headless on the mill of sw/hal/config/ with the program to its end, and
# writes the report: following error at every period boundary, late
# commands, bursts, end positions, machining times, the board's step timing,
# plots.
#
# Usage: scripts/linuxcnc/sil.sh PROG.ngc [--out DIR] [--board B] [--clock-hz HZ]
#          [--baud BAUD] [--servo-period-us P] [--latency-ms L]
#          [--fault estop S | --fault kill S | --fault cut S,D] [--timeout S]
#   --out DIR       where everything goes (default out/linuxcnc/<program>,
#                   <program>-uart on the Tang Nano)
#   --board B       colorlight_5a_75b (Etherbone over UDP, the default) or
#                   tang_nano_20k (Etherbone over its UART)
#   --clock-hz HZ   the board's clock (default 250000 on the Colorlight: it
#                   keeps real time at it beside LinuxCNC on a 2-core machine,
#                   at 500000 it fell 9 % behind; 800000 on the Tang Nano, at
#                   1000000 it fell behind)
#   --baud BAUD     the Tang Nano's UART (default HZ / 8, the bridge's
#                   fastest)
#   --servo-period-us P  LinuxCNC's servo period (default 1000; on the Tang
#                   Nano the period that carries the bits 1 ms carries at the
#                   real board's 1 Mbaud: 1000 x 1000000 / BAUD)
#   --latency-ms L  the driver's latency (default 20: the jitter of a host
#                   without a realtime kernel; on the Tang Nano 4 periods
#                   more for the packets that wait for the UART)
#                   The board's watchdog: 20 ms, on the Tang Nano 20 periods
#                   (a packet goes every two or three periods there)
#   --fault estop S e-stop pressed S seconds into the program
#   --fault kill S  LinuxCNC killed (SIGKILL) S seconds into the program
#   --fault cut S,D the link cut S seconds into the program for D seconds
#                   (a UDP relay between LinuxCNC and the board drops
#                   everything; the Colorlight only), then LinuxCNC turned
#                   on again
#   --timeout S     LinuxCNC's whole run at most S seconds (default 900)
# Never in CI (LinuxCNC pulls about 380 packages): ctest -L linuxcnc runs it.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2; exit 2; }
[ $# -ge 1 ] || usage
case "$1" in -h|--help) usage ;; esac
program=$1
shift
out="" board=colorlight_5a_75b hz="" baud="" period_us="" latency_ms="" fault="" timeout=900
while [ $# -gt 0 ]; do
  case "$1" in
    --out) [ $# -ge 2 ] || usage; out=$2; shift 2 ;;
    --board) [ $# -ge 2 ] || usage; board=$2; shift 2 ;;
    --clock-hz) [ $# -ge 2 ] || usage; hz=$2; shift 2 ;;
    --baud) [ $# -ge 2 ] || usage; baud=$2; shift 2 ;;
    --servo-period-us) [ $# -ge 2 ] || usage; period_us=$2; shift 2 ;;
    --latency-ms) [ $# -ge 2 ] || usage; latency_ms=$2; shift 2 ;;
    --fault) [ $# -ge 3 ] || usage; fault="$2 $3"; shift 3 ;;
    --timeout) [ $# -ge 2 ] || usage; timeout=$2; shift 2 ;;
    *) echo "sil: unknown option '$1'" >&2; exit 2 ;;
  esac
done
[ -f "$program" ] || { echo "sil: program '$program' is not a file" >&2; exit 2; }
case "$board" in
  colorlight_5a_75b) hz=${hz:-250000} suffix="" ;;
  tang_nano_20k) hz=${hz:-800000} suffix=-uart ;;
  *) echo "sil: --board '$board': colorlight_5a_75b or tang_nano_20k" >&2; exit 2 ;;
esac
[[ "$hz" =~ ^[1-9][0-9]*$ ]] || { echo "sil: --clock-hz '$hz' is not a clock in Hz" >&2; exit 2; }
sim_link=()
if [ "$board" = tang_nano_20k ]; then
  baud=${baud:-$((hz / 8))}
  [[ "$baud" =~ ^[1-9][0-9]*$ ]] && [ $((hz / baud)) -ge 8 ] ||
    { echo "sil: --baud '$baud' is not a rate of at least 8 clocks a bit at $hz Hz" >&2; exit 2; }
  period_us=${period_us:-$((1000 * 1000000 / baud))}
  sim_link=(--baud "$baud")
  [ "${fault%% *}" != cut ] || { echo "sil: --fault cut relays UDP: the Colorlight only" >&2; exit 2; }
else
  [ -z "$baud" ] || { echo "sil: --baud is the Tang Nano's (a UART board)" >&2; exit 2; }
fi
period_us=${period_us:-1000}
[[ "$period_us" =~ ^[1-9][0-9]*$ ]] && [ "$period_us" -ge 250 ] && [ "$period_us" -le 20000 ] ||
  { echo "sil: --servo-period-us '$period_us' is not 250..20000" >&2; exit 2; }
if [ -z "$latency_ms" ]; then
  latency_ms=20
  [ "$board" = colorlight_5a_75b ] || latency_ms=$((20 + 4 * period_us / 1000))
fi
[[ "$latency_ms" =~ ^[1-9][0-9]*$ ]] || { echo "sil: --latency-ms '$latency_ms' is not whole ms" >&2; exit 2; }
watchdog_ns=20000000
[ "$board" = colorlight_5a_75b ] || watchdog_ns=$((20 * period_us * 1000))
[[ "$timeout" =~ ^[1-9][0-9]*$ ]] || { echo "sil: --timeout '$timeout' is not whole seconds" >&2; exit 2; }
case "$fault" in
  "" ) ;;
  estop\ *|kill\ *) [[ "${fault#* }" =~ ^[0-9]+(\.[0-9]+)?$ ]] || { echo "sil: --fault '$fault': give seconds" >&2; exit 2; } ;;
  cut\ *) [[ "${fault#* }" =~ ^[0-9]+(\.[0-9]+)?,[0-9]+(\.[0-9]+)?$ ]] || { echo "sil: --fault '$fault': give S,D seconds" >&2; exit 2; } ;;
  *) echo "sil: --fault '${fault%% *}': estop, kill or cut" >&2; exit 2 ;;
esac
program=$(cd "$(dirname "$program")" && pwd)/$(basename "$program")
name=$(basename "$program" .ngc)
out=${out:-$root/out/linuxcnc/$name$suffix${fault:+-${fault%% *}}}
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
"$root/scripts/board_sim.sh" "$board" --clock-hz "$hz" "${sim_link[@]}" --no-profile --realtime \
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
uri=$(cat "$out/board.uri")
if [ "${fault%% *}" = cut ]; then
  port=${uri##*:}
  # LinuxCNC talks to the relay; the relay cuts the link for the time asked.
  rm -f "$out/relay.port"
  "$py" "$root/scripts/linuxcnc/udp_relay.py" --board-port "$port" --port-file "$out/relay.port" \
    --cut-file "$out/relay.cut" >"$out/relay.log" 2>&1 &
  relay=$!
  for _ in $(seq 100); do [ -s "$out/relay.port" ] && break; sleep 0.1; done
  uri=udp:127.0.0.1:$(cat "$out/relay.port")
fi

# LinuxCNC's configuration for this run: the mill, the board's port, the
# headless display, the sampler.
"$py" "$root/scripts/linuxcnc/sil_config.py" --config "$root/sw/hal/config" --out "$out/config" \
  --board "$uri" --servo-period-ns $((period_us * 1000)) --latency-ns $((latency_ms * 1000000)) \
  --watchdog-ns "$watchdog_ns" \
  --program "$program" --display "$root/scripts/linuxcnc/headless.py" \
  --fault "$fault" --timeout "$timeout" --relay-cut "$out/relay.cut"
# LinuxCNC's realtime refuses to run as root without a user to fall back to
# (nobody, who must then be able to open the board's pseudo terminal).
if [ "$(id -u)" -eq 0 ]; then
  mkdir -p "$out/rtapi" && chmod 1777 "$out/rtapi"
  export RTAPI_UID=$(id -u nobody) RTAPI_FIFO_PATH=$out/rtapi/fifo
  case "$uri" in serial:*) dev=${uri#serial:}; chmod a+rw "${dev%@*}" ;; esac
fi
echo "sil: LinuxCNC runs $name against $board at $hz Hz ($uri, servo period $period_us us, latency $latency_ms ms); $out/linuxcnc.log" >&2
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
