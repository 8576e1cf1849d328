#!/usr/bin/env bash
# Every LinuxCNC software-in-the-loop run the docs report (docs/linuxcnc.md):
# the committed programs (tests/data/gcode/*.ngc, tests/data/linuxcnc/*.ngc)
# to their end, and the three faults on corners.ngc (LinuxCNC killed, e-stop,
# the link cut), each by scripts/linuxcnc/sil.sh; then the same over the
# Tang Nano's UART for the programs of UART_PROGRAMS and two faults (kill,
# e-stop); their reports gathered into one JSON (default
# docs/data/linuxcnc_sil.json) that scripts/docs/render.py renders. About 30
# minutes (the programs run in real time). Never in CI.
#
# Usage: scripts/linuxcnc/sil_all.sh [--json FILE] [--out DIR] [--update PROG.ngc ...]
#          [--uart]
#   --update PROG...  run only these programs (no faults) and replace their
#                     rows in the existing JSON (the update is recorded in it)
#   --uart            run only the UART's runs and replace those rows
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
json=$root/docs/data/linuxcnc_sil.json
out=$root/out/linuxcnc
programs=()
update=""
uart_only=""
UART_PROGRAMS=(corners helix words)
while [ $# -gt 0 ]; do
  case "$1" in
    --uart) uart_only=1; update=uart; shift ;;
    --json) json=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --update) update=1; shift ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2; exit 2 ;;
    *) programs+=("$1"); shift ;;
  esac
done
if [ ${#programs[@]} -eq 0 ]; then
  programs=("$root"/tests/data/gcode/*.ngc "$root"/tests/data/linuxcnc/*.ngc)
fi
runs=()
[ -z "$uart_only" ] || programs=()
for p in "${programs[@]}"; do
  d=$out/$(basename "$p" .ngc)
  "$root/scripts/linuxcnc/sil.sh" "$p" --out "$d" || true
  runs+=("$d/sil.json")
done
faults=("kill 3" "estop 3" "cut 3,0.5")
[ -z "$update" ] || faults=()
for f in "${faults[@]}"; do
  d=$out/corners-${f%% *}
  "$root/scripts/linuxcnc/sil.sh" "$root/tests/data/gcode/corners.ngc" --out "$d" --fault $f || true
  runs+=("$d/sil.json")
done
if [ -z "$update" ] || [ -n "$uart_only" ]; then
  for p in "${UART_PROGRAMS[@]}"; do
    d=$out/$p-uart
    "$root/scripts/linuxcnc/sil.sh" "$root/tests/data/gcode/$p.ngc" --board tang_nano_20k --out "$d" || true
    runs+=("$d/sil.json")
  done
  for f in "kill 3" "estop 3"; do
    d=$out/corners-uart-${f%% *}
    "$root/scripts/linuxcnc/sil.sh" "$root/tests/data/gcode/corners.ngc" --board tang_nano_20k \
      --out "$d" --fault $f || true
    runs+=("$d/sil.json")
  done
fi
"$root/.venv/bin/python3" - "$json" "$update" "${runs[@]}" <<'PY'
import json, os, subprocess, sys, datetime, platform
out, update, runs = sys.argv[1], sys.argv[2], sys.argv[3:]
root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(out))))  # docs/data/X.json
commit = subprocess.run(["git", "-C", root, "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
new = []
for r in runs:
    if os.path.exists(r):
        with open(r) as f:
            new.append(json.load(f))
    else:
        new.append({"program": r, "passed": False, "missing": True})
if update == "uart":
    with open(out) as f:
        data = json.load(f)
    data["runs"] = [r for r in data["runs"] if not r.get("link", "").startswith("serial:")] + new
    data.setdefault("updates", []).append({"programs": ["the UART's runs"], "commit": commit,
                                           "date": datetime.date.today().isoformat(),
                                           "command": "scripts/linuxcnc/sil_all.sh --uart"})
elif update:
    with open(out) as f:
        data = json.load(f)
    names = {os.path.basename(r["program"]) for r in new}
    paths = sorted(os.path.relpath(r["program"], root) for r in new)
    data["runs"] = [r if r.get("fault") or r.get("link", "").startswith("serial:") or
                    os.path.basename(r["program"]) not in names else
                    next(n for n in new if os.path.basename(n["program"]) == os.path.basename(r["program"]))
                    for r in data["runs"]]
    data.setdefault("updates", []).append({"programs": sorted(names), "commit": commit,
                                           "date": datetime.date.today().isoformat(),
                                           "command": "scripts/linuxcnc/sil_all.sh --update " +
                                           " ".join(paths)})
else:
    data = {"command": "scripts/linuxcnc/sil_all.sh", "commit": commit,
            "date": datetime.date.today().isoformat(),
            "machine": "LinuxCNC 2.9.0~pre1 (Debian 12, POSIX non-realtime), 2 cores",
            "runs": new}
with open(out + ".tmp", "w") as f:
    json.dump(data, f, indent=1)
os.replace(out + ".tmp", out)
print("wrote", out, sum(1 for r in data["runs"] if r.get("passed")), "of", len(data["runs"]), "passed")
PY
