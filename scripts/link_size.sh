#!/usr/bin/env bash
# Size and fit of the host link's gateware (rtl/link/, docs/link.md): per
# block, Debian Yosys `synth_ice40` of the bare block (LUT4, SB_CARRY,
# flip-flops, SB_RAM40_4K: the figures docs/link.md gives), then the block
# behind scripts/synth/make_harness.py's pin harness (a few registered pins;
# the harness adds its own flip-flops and about one LUT an output bit) placed
# and routed by nextpnr-ice40 --hx8k --package ct256 (seed 1, 50 MHz asked):
# the placed logic cells and nextpnr's "Max frequency for clock".
#   link_guard      at its default WIN_BASE (the board's 0x0008_0000)
#   uart_etherbone  at its defaults: 50 MHz, 115200 baud, 1024-byte buffer,
#                   16-bit counters
# uart_etherbone is also mapped without flattening: LUT4 / carry / FF per
# block of it.
# Usage: scripts/link_size.sh [--out DIR] [--no-pnr] [--json FILE]
#   --out DIR    reports (default <build>/reports/link-size)
#   --json FILE  write the figures there with the date and the HEAD commit
#                (docs/data/link_size.json, which docs/link.md renders:
#                scripts/docs/render.py)
# Runs under nice; about 15 s on 2 cores.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
py=${HWINTERP_VENV:-$root/.venv}/bin/python3
build=${HWINTERP_BUILD_DIR:-$root/build}
out=""
pnr=1
json=
while [ $# -gt 0 ]; do
  case "$1" in
    --out) [ $# -ge 2 ] || { echo "link_size: --out needs a directory" >&2; exit 2; }; out=$2; shift 2 ;;
    --no-pnr) pnr=0; shift ;;
    --json) [ $# -ge 2 ] || { echo "link_size: --json needs a file" >&2; exit 2; }; json=$2; shift 2 ;;
    *) echo "link_size: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
out=${out:-$build/reports/link-size}
mkdir -p "$out"
for t in yosys nextpnr-ice40 "$py"; do
  command -v "$t" >/dev/null || { echo "link_size: $t not found" >&2; exit 1; }
done

declare -A files=(
  [link_guard]="$root/rtl/link/link_guard.sv"
  [uart_etherbone]="$(sed -n "/^[^#]/s|^|$root/rtl/link/|p" "$root/rtl/link/uart_etherbone.f" | paste -sd ' ')"
)
for b in link_guard uart_etherbone; do
  d=$out/$b
  mkdir -p "$d"
  nice -n 19 yosys -q -l "$d/synth.log" -p "read_verilog -sv ${files[$b]}; synth_ice40 -top $b;
    tee -q -o $d/stat.txt stat" >/dev/null
  cells=$(awk '/SB_LUT4|SB_CARRY|SB_DFF|SB_RAM40_4K/ {printf "%s %s, ", $1, $2}' "$d/stat.txt")
  echo "link_size: $b synth_ice40: ${cells%, }"
  if [ $b = uart_etherbone ]; then
    nice -n 19 yosys -q -p "read_verilog -sv ${files[$b]}; hierarchy -top $b;
      synth_ice40 -top $b -noflatten; tee -q -o $d/stat_blocks.txt stat" >/dev/null
  fi
  [ $pnr -eq 1 ] || continue
  nice -n 19 yosys -q -p "read_verilog -sv ${files[$b]}; hierarchy -top $b; proc; write_json $d/ports.json" >/dev/null
  "$py" "$root/scripts/synth/make_harness.py" "$d/ports.json" "$b" >"$d/harness.sv"
  nice -n 19 yosys -q -l "$d/harness_synth.log" -p "read_verilog -sv ${files[$b]} $d/harness.sv;
    synth_ice40 -top ${b}_harness -json $d/harness.json" >/dev/null
  nice -n 19 nextpnr-ice40 --hx8k --package ct256 --json "$d/harness.json" --freq 50 --seed 1 \
    --timing-allow-fail >"$d/pnr.log" 2>&1 || { echo "link_size: nextpnr-ice40 failed for $b; see $d/pnr.log" >&2; exit 1; }
  lc=$(grep -oE 'ICESTORM_LC: +[0-9]+/ *[0-9]+' "$d/pnr.log" | tail -n1 | tr -s ' ')
  ram=$(grep -oE 'ICESTORM_RAM: +[0-9]+/ *[0-9]+' "$d/pnr.log" | tail -n1 | tr -s ' ')
  fmax=$(grep -oE "Max frequency for clock '[^']+': [0-9.]+ MHz" "$d/pnr.log" | tail -n1 | grep -oE '[0-9.]+ MHz')
  echo "link_size: $b in the pin harness on the HX8K (ct256): $lc, $ram, $fmax"
done
[ -n "$json" ] || exit 0
[ $pnr -eq 1 ] || { echo "link_size: --json needs the place and route (no --no-pnr)" >&2; exit 2; }
"$py" - "$out" "$json" "$(git -C "$root" rev-parse --short HEAD)" "$(yosys -V | cut -d' ' -f1-2)" \
  "$(nextpnr-ice40 --version 2>&1 | head -n1 | grep -oE '[0-9]+\.[0-9]+' | head -n1)" <<'PY'
import datetime, json, re, sys
out, path, commit, yosys, pnr = sys.argv[1:6]

def cells(f):
    c = {}
    for line in open(f):
        m = re.match(r"\s+(SB_\w+)\s+(\d+)$", line)
        if m:
            c[m.group(1)] = c.get(m.group(1), 0) + int(m.group(2))
    return c

def counts(c):
    return {"lut4": c.get("SB_LUT4", 0), "carry": c.get("SB_CARRY", 0),
            "ff": sum(v for k, v in c.items() if k.startswith("SB_DFF")),
            "bram": c.get("SB_RAM40_4K", 0)}

blocks = []
for b, params in (("link_guard", "WIN_BASE = 0x0002_0000 (words: byte 0x0008_0000)"),
                  ("uart_etherbone", "CLK_HZ = 50 MHz, BAUD = 115200, BUF_BYTES = 1024, CNT_W = 16")):
    e = {"block": b, "params": params}
    e.update(counts(cells(f"{out}/{b}/stat.txt")))
    log = open(f"{out}/{b}/pnr.log").read()
    e["hx8k_lc"] = int(re.findall(r"ICESTORM_LC: +(\d+)/", log)[-1])
    e["hx8k_ram"] = int(re.findall(r"ICESTORM_RAM: +(\d+)/", log)[-1])
    e["fmax_mhz"] = float(re.findall(r"Max frequency for clock '[^']+': ([0-9.]+) MHz", log)[-1])
    blocks.append(e)
mods = []
cur = None
for line in open(f"{out}/uart_etherbone/stat_blocks.txt"):
    m = re.match(r"=== (.+) ===", line)
    if m:
        parts = m.group(1).split(chr(92))  # $paramod\uart_rx\DIV=..., $paramod$<hash>\etherbone_engine
        name = parts[1] if parts[0] == "$paramod" else parts[-1]
        cur = None if name in ("uart_etherbone", "design hierarchy") else {"module": name, "c": {}}
        if cur:
            mods.append(cur)
        continue
    m = re.match(r"\s+(SB_\w+)\s+(\d+)$", line)
    if m and cur:
        cur["c"][m.group(1)] = int(m.group(2))
modules = [dict(module=m["module"], **counts(m["c"])) for m in mods if m["c"]]
d = {"what": "the host link's blocks (rtl/link/) mapped to iCE40 by synth_ice40, and placed "
             "in the pin harness of scripts/synth/make_harness.py on the HX8K (ct256, seed 1, "
             "50 MHz asked)",
     "command": "scripts/link_size.sh --json docs/data/link_size.json",
     "date": datetime.date.today().isoformat(), "commit": commit,
     "tool": f"{yosys}, nextpnr-ice40 {pnr}", "blocks": blocks,
     "uart_etherbone_blocks": modules}
with open(path, "w") as f:
    json.dump(d, f, indent=1)
    f.write("\n")
print(f"link_size: wrote {path}")
PY
