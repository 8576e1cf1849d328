#!/usr/bin/env python3
"""Collects the results of scripts/synth.sh into synth.json and synth.md.

Usage: synth_report.py OUT_DIR VARIANT...

Reads, per variant (or peer), OUT_DIR/<variant>/: info.tsv and times.tsv
(written by synth.sh), the Yosys `stat -json` files, the nextpnr logs (the last
"Max frequency for clock" line is the Fmax; the packer lines give the placed
LUTs and flip-flops) and nextpnr --report files (utilisation, critical path).
Writes OUT_DIR/synth.json ({"variants": [...], "peers": [...]}: the peers,
named peer_*, apart, so that a consumer of "variants" sees only hwinterp's
cores) and OUT_DIR/synth.md, and prints the markdown.

JSON keys per record (besides the iCE40 ones: ice40_core, harness, up5k):
  block, filelist         (blocks only: hwinterp_synth_block in cmake/cores.cmake)
                          true, and the RTL file list rtl/<filelist>.f; "core"
                          is then the block's top module, and rtl_sha256 is
                          over that list
  tools.yosys_generic     the Yosys of the generic step (Debian's)
  ecp5                    the ECP5 flow (synth.sh --family ecp5):
    device, package, speed, tools {yosys, nextpnr}
    core                  synth_ecp5 of the bare core: lut4 (LUT4 cells), carry
                          (CCU2C cells, 2 bits each), ff (TRELLIS_FF), dsp
                          (MULT18X18D), alu54 (ALU54B), bram (DP16KD), lutram
                          (TRELLIS_DPR16X4), widemux (PFUMX + L6MUX21),
                          lut4_total (lut4 + 2 carry + 2 lutram: LUT4 sites),
                          cells_by_type
    harness               {netlist: the same counts for core + pin harness,
                          overhead: netlist - core}
    runs                  per seed: seed, fmax_mhz, target_mhz, met, clock,
                          comb_used/_available (TRELLIS_COMB: LUT4 sites),
                          ff_used/_available, io_used/_available, dsp_used,
                          bram_used, critical_path {from_reg, to_reg (the
                          first and last flip-flop's register name), from_src,
                          to_src (its declaration, file:line), from_net,
                          to_cell (Yosys' automatic names cut before the first
                          cell-type part), lut_levels, carry_steps, mux_levels,
                          logic_ns, routing_ns}; or {seed, timeout_s}; or
                          {seed, no_fit: "does not fit: ..."} (the only run)
    fmax_min_mhz, fmax_max_mhz
    date, git, command, times_s, rtl_sha256 (source_sha256 for a peer)
                          the run these figures come from (publish.py --family
                          ecp5 merges them into a record another run measured)
  gowin                   the Gowin flow (synth.sh --family gowin):
    device, family        (GW2AR-LV18QN88C8/I7, GW2A-18C: the nextpnr device and
                          chip database), board, cst (the harness's pin file),
                          tools {yosys, nextpnr}
    core                  synth_gowin -family gw2a -noiopads of the bare core:
                          lut4 (LUT1-LUT4 cells), alu (ALU cells, one bit and one
                          LUT4 site each), ff (DFF*), bram (BSRAM modes: SP, SDPB,
                          DPB, ...), dsp (MULT9X9, MULT18X18, ... cells), lutram
                          (RAM16S*/RAM16SDP*), widemux (MUX2_LUT5-8), lut4_total
                          (lut4 + alu), cells_by_type
    harness               {netlist, overhead} as for ECP5
    runs                  per seed: seed, fmax_mhz, target_mhz, met, clock,
                          lut4_used/_available (LUT4 sites: logic and ALU),
                          alu_used, ff_used, io_used, bram_used, lutram_used,
                          bufg_used (each with _available), dsp_used (the DSP
                          primitives summed; dsp_by_type), critical_path (as
                          ECP5's; carry_steps: ALU carry-outs, mux_levels:
                          MUX2_LUT5-8, lut_levels: LUT and ALU sum outputs);
                          or {seed, timeout_s}; or {seed, no_fit}
    fmax_min_mhz, fmax_max_mhz
    date, git, command, times_s, rtl_sha256 (source_sha256 for a peer)
                          the run these figures come from (publish.py --family
                          gowin merges them into a record another run measured)
  command                 the synth.sh command line of the run (from runs that
                          record it)
  peer                    (peers only) how the peer was elaborated: package and
                          versions, module, configuration, what was replaced,
                          its ports (scripts/synth/peers/*.py --info)
  source_sha256           (peers only) SHA-256 of the generated Verilog (peers
                          have no rtl_sha256)

For scripts/synth/publish.py: render_ecp5_table(records), render_gowin_table(records) and
render_peer_rows(variants, peers) return the ECP5 table and the peers' table with
the rows "ours / peer" as lists of markdown lines (empty without ECP5 or Gowin
results or peers).
"""
import hashlib
import json
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

FMAX = re.compile(r"Max frequency for clock '([^']*)': ([0-9.]+) MHz \((PASS|FAIL) at ([0-9.]+) MHz\)")
PACK = {
    "lut_only": re.compile(r"(\d+) LCs used as LUT4 only"),
    "lut_dff": re.compile(r"(\d+) LCs used as LUT4 and DFF"),
    "dff_only": re.compile(r"(\d+) LCs used as DFF only"),
    "carry_only": re.compile(r"(\d+) LCs used as CARRY only"),
}


def read_tsv(path):
    d = {}
    if os.path.exists(path):
        with open(path) as f:
            for line in f:
                line = line.rstrip("\n")
                if "\t" in line:
                    k, v = line.split("\t", 1)
                    d[k] = v
    return d


def read_times(path):
    times = {}
    if os.path.exists(path):
        with open(path) as f:
            for line in f:
                k, v = line.rstrip("\n").split("\t")
                times[k] = float(v)
    return times


def cells(path):
    """Cells by type of the (single, flattened) top module of a Yosys stat -json."""
    with open(path) as f:
        st = json.load(f)
    # $scopeinfo: newer Yosys (the YoWASP one) keeps a record of each flattened
    # instance; not a cell of the circuit.
    return dict(sorted((t, n) for t, n in st["design"]["num_cells_by_type"].items()
                       if t != "$scopeinfo"))


def ice40(by_type):
    return {
        "lut4": by_type.get("SB_LUT4", 0),
        "carry": by_type.get("SB_CARRY", 0),
        "ff": sum(n for t, n in by_type.items() if t.startswith("SB_DFF")),
        "bram": sum(n for t, n in by_type.items() if t.startswith("SB_RAM40")),
    }


def ecp5(by_type):
    """LUT4 / carry / FF / DSP / BRAM of a synth_ecp5 netlist."""
    n = by_type.get
    r = {
        "lut4": n("LUT4", 0),
        "carry": n("CCU2C", 0),  # two bits (two LUT4 sites) each
        "ff": n("TRELLIS_FF", 0),
        "dsp": n("MULT18X18D", 0),
        "alu54": n("ALU54B", 0),
        "bram": n("DP16KD", 0),
        "lutram": n("TRELLIS_DPR16X4", 0),
        "widemux": n("PFUMX", 0) + n("L6MUX21", 0),
    }
    r["lut4_total"] = r["lut4"] + 2 * r["carry"]
    return r


# Gowin (synth_gowin): the cells by role. BSRAM: the 18-kbit block RAM in each
# of its modes; DSP: every multiplier, pre-adder and accumulator primitive of
# the GW1N/GW2A DSP block; LUT RAM: the shadow-SRAM modes of a CLU.
GOWIN_BSRAM = ("SP", "SPX9", "SDP", "SDPB", "SDPX9", "SDPX9B", "DP", "DPB", "DPX9", "DPX9B",
               "ROM", "ROMX9", "pROM", "pROMX9")
GOWIN_DSP = ("MULT9X9", "MULT18X18", "MULT36X36", "MULTALU18X18", "MULTALU36X18",
             "MULTADDALU18X18", "ALU54D", "PADD9", "PADD18")
GOWIN_LUTRAM = ("RAM16S1", "RAM16S2", "RAM16S4", "RAM16SDP1", "RAM16SDP2", "RAM16SDP4")


def gowin(by_type):
    """LUT4 / ALU / FF / BSRAM / DSP of a synth_gowin netlist."""
    n = by_type.get
    r = {
        "lut4": sum(n("LUT%d" % k, 0) for k in range(1, 5)),  # LUT1-LUT4: one LUT4 site each
        "alu": n("ALU", 0),  # one bit, one LUT4 site of a CLU in ALU mode, each
        "ff": sum(c for t, c in by_type.items() if t.startswith("DFF")),
        "bram": sum(n(t, 0) for t in GOWIN_BSRAM),
        "dsp": sum(n(t, 0) for t in GOWIN_DSP),
        "lutram": sum(n(t, 0) for t in GOWIN_LUTRAM),
        "widemux": sum(n("MUX2_LUT%d" % k, 0) for k in range(5, 9)),
    }
    r["lut4_total"] = r["lut4"] + r["alu"]
    return r


# The cell types Yosys' autoname appends to a name it derives from a neighbour.
AUTONAME_CUT = re.compile(r"_(?:LUT4|TRELLIS_FF|TRELLIS_COMB|CCU2C|PFUMX|L6MUX21|DP16KD|MULT18X18D|"
                          r"ALU54B|TRELLIS_DPR16X4)_.*$")
GOWIN_AUTONAME_CUT = re.compile(r"_(?:LUT[1-4]|DFF[A-Z]*|ALU|MUX2_LUT[5-8]|IBUF|OBUF|RAM16S\w*|"
                                r"SDPB|DPB|SDPX9B|DPX9B|pROM|MULT\w*|ALU54D|PADD\w*)_.*$")
ECP5_PRE = {
    "lut4_total": re.compile(r"Total LUT4s:\s*(\d+)/"),
    "lut4_logic": re.compile(r"logic LUTs:\s*(\d+)/"),
    "lut4_carry": re.compile(r"carry LUTs:\s*(\d+)/"),
    "lut4_ram": re.compile(r"RAM LUTs:\s*(\d+)/"),
    "dff_total": re.compile(r"Total DFFs:\s*(\d+)/"),
}


def reg_at(cell):
    """('file.sv:LINE', name) of a flip-flop, from its src attribute: synth.sh copies the
    declaration of the flip-flop's output wire there (file:line.col-line.col of the name,
    which is read back from the file); ('', '') when there is none."""
    src = (cell or {}).get("attributes", {}).get("src", "").split("|")[0]
    m = re.match(r"(.*):(\d+)\.(\d+)-(\d+)\.(\d+)$", src)
    if not m:
        return "", ""
    path, line, c0, line1, c1 = m.group(1), int(m.group(2)), int(m.group(3)), int(m.group(4)), \
        int(m.group(5))
    name = ""
    try:
        with open(path) as f:
            text = f.readlines()[line - 1]
        if line1 == line and re.fullmatch(r"[A-Za-z_]\w*", text[c0 - 1:c1 - 1]):
            name = text[c0 - 1:c1 - 1]
    except (OSError, IndexError):
        pass
    return "%s:%d" % (os.path.basename(path), line), name


def fmax(log):
    """The routed Fmax of a nextpnr log (the last report; the first is the placer's estimate)."""
    fm = FMAX.findall(log)
    if not fm:
        return {}
    clk, mhz, verdict, target = fm[-1]
    return dict(clock=clk, fmax_mhz=float(mhz), target_mhz=float(target), met=verdict == "PASS")


def clock_path(rep, lut, carry, mux=None):
    """The register-to-register critical path of a nextpnr report: its segments, the levels
    of logic by the output port they end on (lut, carry, mux), the logic and routing ns."""
    luts = lut if isinstance(lut, tuple) else (lut,)
    for cp in rep.get("critical_paths", []):
        if cp.get("from") != cp.get("to"):
            continue
        segs = cp.get("path", [])
        routing = [s for s in segs if s.get("type") == "routing"]
        ports = [s["to"]["port"] for s in segs if s.get("type") == "logic"]
        counts = {"lut_levels": sum(ports.count(p) for p in luts),
                  "carry_steps": ports.count(carry)}
        if mux:
            counts["mux_levels"] = ports.count(mux)
        counts["logic_ns"] = round(sum(s["delay"] for s in segs if s.get("type") != "routing"), 2)
        counts["routing_ns"] = round(sum(s["delay"] for s in routing), 2)
        return segs, (routing[0].get("net", "") if routing else ""), counts
    return None


def pnr(log_path, report_path, family="ice40", netlist=None):
    """Fmax, packed LUT/FF and utilisation of one nextpnr run.

    family: "ice40", "ecp5" or "gowin"; netlist (ECP5, Gowin): the cells of the placed
    Yosys JSON, for the RTL lines of the critical path's flip-flops."""
    with open(log_path) as f:
        log = f.read()
    r = {}
    if family == "ecp5":
        return pnr_ecp5(log, report_path, netlist or {})
    if family == "gowin":
        return pnr_gowin(log, report_path, netlist or {})
    r.update(fmax(log))
    pk = {k: int(m.group(1)) for k, rx in PACK.items() for m in [rx.search(log)] if m}
    if {"lut_only", "lut_dff", "dff_only"} <= pk.keys():
        r["lut4"] = pk["lut_only"] + pk["lut_dff"]
        r["ff"] = pk["lut_dff"] + pk["dff_only"]
    # Utilisation from the log (also there when placement failed), then the report.
    util = re.search(r"Device utilisation:\n((?:Info:.*\n)+)", log)
    for name, used, avail in re.findall(r"(\w+):\s*(\d+)/\s*(\d+)", util.group(1) if util else ""):
        short = {"ICESTORM_LC": "lc", "SB_IO": "io", "SB_GB": "gb",
                 "ICESTORM_DSP": "dsp"}.get(name)
        if short:
            r[short + "_used"], r[short + "_available"] = int(used), int(avail)
    if os.path.exists(report_path):
        with open(report_path) as f:
            rep = json.load(f)
        u = rep.get("utilization", {})
        for key, name in (("ICESTORM_LC", "lc"), ("SB_IO", "io"), ("SB_GB", "gb"),
                          ("ICESTORM_DSP", "dsp")):
            if key in u:
                r[name + "_used"] = u[key]["used"]
                r[name + "_available"] = u[key]["available"]
        path = clock_path(rep, "O", "COUT")
        if path:
            segs, from_net, counts = path
            r["critical_path"] = dict(from_net=from_net,
                                      to_cell=segs[-1]["to"]["cell"] if segs else "", **counts)
    return r


def pnr_ecp5(log, report_path, netlist):
    r = fmax(log)
    for k, rx in ECP5_PRE.items():
        m = rx.search(log)
        if m:
            r[k] = int(m.group(1))
    names = {"TRELLIS_COMB": "comb", "TRELLIS_FF": "ff", "TRELLIS_IO": "io", "DCCA": "dcca",
             "MULT18X18D": "dsp", "ALU54B": "alu54", "DP16KD": "bram", "TRELLIS_RAMW": "ramw"}
    util = re.search(r"Device utilisation:\n((?:Info:.*\n)+)", log)
    for name, used, avail in re.findall(r"(\w+):\s*(\d+)/\s*(\d+)", util.group(1) if util else ""):
        if name in names:
            r[names[name] + "_used"], r[names[name] + "_available"] = int(used), int(avail)
    if os.path.exists(report_path):
        with open(report_path) as f:
            rep = json.load(f)
        for key, name in names.items():
            u = rep.get("utilization", {}).get(key)
            if u:
                r[name + "_used"], r[name + "_available"] = u["used"], u["available"]
        path = named_path(rep, netlist, AUTONAME_CUT, "F", "FCO", "OFX")
        if path:
            r["critical_path"] = path
    return r


def named_path(rep, netlist, cut, lut, carry, mux):
    """The critical path of a nextpnr report with its end registers named from the netlist
    (reg_at) and Yosys' automatic names cut by `cut`; None without a clock path."""
    path = clock_path(rep, lut, carry, mux)
    if not path:
        return None
    segs, from_net, counts = path
    src = segs[0]["from"]["cell"] if segs else ""
    dst = segs[-1]["to"]["cell"] if segs else ""
    (from_src, from_reg), (to_src, to_reg) = reg_at(netlist.get(src)), reg_at(netlist.get(dst))
    return dict(from_reg=from_reg, from_src=from_src, to_reg=to_reg, to_src=to_src,
                from_net=cut.sub("", from_net), to_cell=cut.sub("", dst), **counts)


GOWIN_UTIL = {"LUT4": "lut4", "ALU": "alu", "DFF": "ff", "IOB": "io", "BSRAM": "bram",
              "RAM16SDP4": "lutram", "BUFG": "bufg"}


def pnr_gowin(log, report_path, netlist):
    """Fmax, utilisation (LUT4 sites: logic and ALU; the DSP primitives summed) and the
    critical path of one nextpnr-himbaechel-gowin run."""
    r = fmax(log)
    util = re.search(r"Device utilisation:\n((?:Info:.*\n)+)", log)
    used = {name: (int(u), int(a)) for name, u, a in
            re.findall(r"(\w+):\s*(\d+)/\s*(\d+)", util.group(1) if util else "")}
    if os.path.exists(report_path):
        with open(report_path) as f:
            rep = json.load(f)
        used.update({k: (u["used"], u["available"]) for k, u in rep.get("utilization", {}).items()})
    else:
        rep = {}
    for key, name in GOWIN_UTIL.items():
        if key in used:
            r[name + "_used"], r[name + "_available"] = used[key]
    dsp = {k: used[k][0] for k in GOWIN_DSP if k in used and used[k][0]}
    if any(k in used for k in GOWIN_DSP):
        r["dsp_used"] = sum(dsp.values())
    if dsp:
        r["dsp_by_type"] = dsp
    path = named_path(rep, netlist, GOWIN_AUTONAME_CUT, ("F", "SUM"), "COUT", "O")
    if path:
        r["critical_path"] = path
    return r


PORT = re.compile(r"^\s*(input|output|inout)\s+(?:\[(\d+):(\d+)\]\s*)?\\?[\w$]+\s*;", re.M)
CHIPDB = "/usr/share/fpga-icestorm/chipdb/chipdb-%s.txt"


def port_bits(netlist):
    """I/O bits of the bare core, from the ports of its Yosys netlist."""
    with open(netlist) as f:
        text = f.read()
    return sum(abs(int(m.group(2)) - int(m.group(3))) + 1 if m.group(2) else 1
               for m in PORT.finditer(text))


def package_pins(device, package):
    """Bonded I/O pins of a package, counted in the icestorm chip database."""
    try:
        with open(CHIPDB % device) as f:
            lines = f.read().split("\n")
    except OSError:
        return None
    n, inside = 0, False
    for line in lines:
        if line.startswith("."):
            inside = line.split()[:2] == [".pins", package]
        elif inside and line.strip():
            n += 1
    return n or None


def rtl_digest(core, root=ROOT):
    """SHA-256 over the RTL files of rtl/<core>.f, in list order (names and contents); for
    a block, `core` is its file list's name.

    Recorded with every result, so a published figure can be told apart from the RTL it
    no longer describes (scripts/synth/publish.py --check)."""
    h = hashlib.sha256()
    with open(os.path.join(root, "rtl", core + ".f")) as f:
        names = [l.strip() for l in f if l.strip() and not l.startswith("#")]
    for name in names:
        h.update(name.encode() + b"\0")
        with open(os.path.join(root, "rtl", name), "rb") as g:
            h.update(g.read())
    return h.hexdigest()


def file_digest(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def seed_runs(vdir, info, family, netlist=None):
    """The per-seed nextpnr results of one family (hx8k or ecp5)."""
    runs = []
    for s in info["seeds"].split():
        if "%s_timeout_seed%s" % (family, s) in info:
            runs.append({"seed": int(s), "timeout_s": int(info["%s_timeout_seed%s" % (family, s)])})
            continue
        if "%s_nofit_seed%s" % (family, s) in info:
            # synth.sh runs no other seed of the family: the netlist is the same.
            runs.append({"seed": int(s), "no_fit": info["%s_nofit_seed%s" % (family, s)]})
            break
        r = pnr(os.path.join(vdir, "pnr_%s_seed%s.log" % (family, s)),
                os.path.join(vdir, "pnr_%s_seed%s.json" % (family, s)),
                family if family in ("ecp5", "gowin") else "ice40", netlist)
        r["seed"] = int(s)
        runs.append(r)
    return runs


def fmax_range(runs):
    fmaxes = [r["fmax_mhz"] for r in runs if "fmax_mhz" in r]
    return (min(fmaxes) if fmaxes else None), (max(fmaxes) if fmaxes else None)


def provenance(res, info, family):
    """Where a family's figures come from (date, git, command, its steps' times, the RTL's
    or peer source's digest): kept with them when publish.py --family merges them into a
    record another run measured."""
    p = {"date": res["date"], "git": res["git"], "command": info.get("command", ""),
         "times_s": {k: v for k, v in res["times_s"].items() if family in k}}
    for key in ("rtl_sha256", "source_sha256"):
        if key in res:
            p[key] = res[key]
    return p


def variant_result(out, variant):
    vdir = os.path.join(out, variant)
    info = read_tsv(os.path.join(vdir, "info.tsv"))
    # Results of a synth.sh from before --family: iCE40 unless --generic-only.
    families = info.get("families", "ice40" if info.get("generic_only") == "0" else "")
    families = [f for f in families.split(",") if f]
    res = {
        "variant": variant,
        "core": info["core"],
        "params": dict(kv.split("=", 1) for kv in info["params"].split()),
        "families": families,
        "tools": {"yosys": info.get("yosys", ""), "nextpnr": info.get("nextpnr", ""),
                  "yosys_generic": info.get("yosys_generic", info.get("yosys", ""))},
        "times_s": read_times(os.path.join(vdir, "times.tsv")),
        "date": info.get("date", ""),
        "git": info.get("git", ""),
    }
    if "command" in info:
        res["command"] = info["command"]
    if "peer" in info:
        with open(info["peer"]) as f:
            res["peer"] = json.load(f)
        res["source_sha256"] = file_digest(info["peer_source"])
    else:
        if info.get("block") == "1":
            res["block"] = True
            res["filelist"] = info["filelist"]
        res["rtl_sha256"] = rtl_digest(info.get("filelist", info["core"]))
    g = cells(os.path.join(vdir, "generic_stat.json"))
    res["generic"] = {
        "cells": sum(g.values()),
        "ff": sum(n for t, n in g.items() if "DFF" in t),
        "cells_by_type": g,
    }
    res["core_io_bits"] = port_bits(os.path.join(vdir, "%s_net.v" % info["core"]))
    if "ice40" in families:
        core = ice40(cells(os.path.join(vdir, "ice40_core_stat.json")))
        hnet = ice40(cells(os.path.join(vdir, "harness_stat.json")))
        runs = seed_runs(vdir, info, "hx8k")
        lo, hi = fmax_range(runs)
        res["ice40_core"] = core
        res["harness"] = {
            "netlist": hnet,
            "overhead": {k: hnet[k] - core[k] for k in core},
            "hx8k": runs,
            "fmax_min_mhz": lo,
            "fmax_max_mhz": hi,
        }
        s0 = info["seeds"].split()[0]
        res["harness"]["hx8k_package_pins"] = package_pins("8k", "ct256")
        up = {"fits": info.get("up5k_fit") == "yes", "seed": int(s0),
              "package_pins": package_pins("5k", "sg48")}
        up.update(pnr(os.path.join(vdir, "pnr_up5k_seed%s.log" % s0),
                      os.path.join(vdir, "pnr_up5k_seed%s.json" % s0)))
        if not up["fits"]:
            up["reason"] = info.get("up5k_reason", "")
        if "up5k_netlist" in info:  # a core that multiplies: mapped again for the SB_MAC16
            up["netlist"] = info["up5k_netlist"]
        res["up5k"] = up
    if "ecp5" in families:
        by_type = cells(os.path.join(vdir, "ecp5_core_stat.json"))
        core = ecp5(by_type)
        hnet = ecp5(cells(os.path.join(vdir, "harness_ecp5_stat.json")))
        with open(os.path.join(vdir, "harness_ecp5.json")) as f:
            mods = json.load(f)["modules"]
        top = mods.get("%s_harness" % info["core"], {})
        runs = seed_runs(vdir, info, "ecp5", top.get("cells", {}))
        del mods, top
        lo, hi = fmax_range(runs)
        res["ecp5"] = {
            "device": "LFE5U-25F", "package": "CABGA256", "speed": 6,
            "tools": {"yosys": info.get("ecp5_yosys", ""), "nextpnr": info.get("ecp5_nextpnr", "")},
            "core": dict(core, cells_by_type=by_type),
            "harness": {"netlist": hnet, "overhead": {k: hnet[k] - core[k] for k in core}},
            "runs": runs,
            "fmax_min_mhz": lo,
            "fmax_max_mhz": hi,
        }
        res["ecp5"].update(provenance(res, info, "ecp5"))
    if "gowin" in families:
        by_type = cells(os.path.join(vdir, "gowin_core_stat.json"))
        core = gowin(by_type)
        hnet = gowin(cells(os.path.join(vdir, "harness_gowin_stat.json")))
        with open(os.path.join(vdir, "harness_gowin.json")) as f:
            mods = json.load(f)["modules"]
        top = mods.get("%s_harness" % info["core"], {})
        runs = seed_runs(vdir, info, "gowin", top.get("cells", {}))
        del mods, top
        lo, hi = fmax_range(runs)
        res["gowin"] = {
            "device": "GW2AR-LV18QN88C8/I7", "family": "GW2A-18C", "board": "Sipeed Tang Nano 20K",
            "tools": {"yosys": info.get("gowin_yosys", ""), "nextpnr": info.get("gowin_nextpnr", "")},
            "cst": info.get("gowin_cst", ""),
            "core": dict(core, cells_by_type=by_type),
            "harness": {"netlist": hnet, "overhead": {k: hnet[k] - core[k] for k in core}},
            "runs": runs,
            "fmax_min_mhz": lo,
            "fmax_max_mhz": hi,
        }
        res["gowin"].update(provenance(res, info, "gowin"))
    chk = os.path.join(vdir, "netlist_check.log")
    if info.get("check") == "1" and os.path.exists(chk):
        with open(chk) as f:
            m = re.search(r"netlist matches RTL: .*", f.read())
        res["netlist_check"] = m.group(0) if m else "FAILED"
    elif info.get("check") not in ("0", "1"):
        res["netlist_check"] = info.get("check")
    return res


def run_text(p):
    """One seed's result: its Fmax, no route (timed out), or does not fit."""
    if "fmax_mhz" in p:
        return "%.2f" % p["fmax_mhz"]
    return p["no_fit"] if "no_fit" in p else "no route in %s s" % p.get("timeout_s", "?")


def seeds_text(runs):
    return ", ".join("%s (%d)" % (run_text(p), p["seed"]) for p in runs)


def short_name(name):
    """A register or cell name without the pin harness's u_core. prefix and iCE40's _SB_ suffix."""
    return re.sub(r"_SB_\w+.*$", "", re.sub(r"^u_core\.", "", name))


def ecp5_path_text(cp):
    """The ECP5 critical path, as publish.py writes the iCE40 one (plus RTL lines)."""
    if not cp:
        return "-"
    steps = "%d LUT" % cp["lut_levels"]
    if cp.get("mux_levels"):
        steps += " + %d mux" % cp["mux_levels"]
    if cp["carry_steps"]:
        steps += " + %d carry" % cp["carry_steps"]
    def end(reg, src, auto):
        if reg:
            return "`%s` (%s)" % (reg, src)
        return src or "`%s`" % short_name(auto)
    return "%s -> %s (%s; %.1f ns logic, %.1f ns routing)" % (
        end(cp.get("from_reg"), cp.get("from_src"), cp["from_net"]),
        end(cp.get("to_reg"), cp.get("to_src"), cp["to_cell"]), steps, cp["logic_ns"],
        cp["routing_ns"])


def render_ecp5_table(results):
    """Markdown: the ECP5 table (one row per record with ECP5 results), for synth.md and
    for scripts/synth/publish.py to call. Returns [] when no record has ECP5 results."""
    rs = [r for r in results if "ecp5" in r]
    if not rs:
        return []
    e0 = rs[0]["ecp5"]
    seeds = "/".join(str(p["seed"]) for p in e0["runs"])
    md = ["| variant | ECP5 core LUT4 / CCU2C / FF / DSP / BRAM | harness placed LUT4 sites / FF "
          "of %s | Fmax %s-%s, seeds %s (MHz) | Fmax min-max | critical path, first seed: "
          "from -> to |" % (e0["runs"][0].get("comb_available", "?"), e0["device"], e0["speed"],
                            seeds),
          "|---|---|---|---|---|---|"]
    for r in rs:
        e = r["ecp5"]
        c, p0 = e["core"], e["runs"][0]
        md.append("| `%s` | %d / %d / %d / %d / %d | %s / %s | %s | %s | %s |" % (
            r["variant"], c["lut4"], c["carry"], c["ff"], c["dsp"], c["bram"],
            p0.get("comb_used", "?"), p0.get("ff_used", "?"), seeds_text(e["runs"]),
            "%.2f-%.2f" % (e["fmax_min_mhz"], e["fmax_max_mhz"])
            if e["fmax_min_mhz"] is not None else "?",
            ecp5_path_text(p0.get("critical_path"))))
    return md


def render_gowin_table(results):
    """Markdown: the Gowin table (one row per record with Gowin results), for synth.md and
    for scripts/synth/publish.py to call. Returns [] when no record has Gowin results."""
    rs = [r for r in results if "gowin" in r]
    if not rs:
        return []
    placed = [p for r in rs for p in r["gowin"]["runs"] if "lut4_available" in p]
    avail = " / ".join(str(placed[0].get(k + "_available", "?")) if placed else "?"
                       for k in ("lut4", "alu", "ff"))
    md = ["| variant | Gowin core LUT4 / ALU / FF / BSRAM / DSP / LUT RAM | harness placed LUT4 / "
          "ALU / FF of %s | Fmax %s per seed (MHz) | Fmax min-max | critical path, first seed: "
          "from -> to |" % (avail, rs[0]["gowin"]["family"]),
          "|---|---|---|---|---|---|"]
    for r in rs:
        g = r["gowin"]
        c, p0 = g["core"], g["runs"][0]
        md.append("| `%s` | %d / %d / %d / %d / %d / %d | %s | %s | %s | %s |" % (
            r["variant"], c["lut4"], c["alu"], c["ff"], c["bram"], c["dsp"], c["lutram"],
            " / ".join(str(p0[k + "_used"]) for k in ("lut4", "alu", "ff"))
            if "lut4_used" in p0 else "-", seeds_text(g["runs"]),
            "%.2f-%.2f" % (g["fmax_min_mhz"], g["fmax_max_mhz"])
            if g["fmax_min_mhz"] is not None else "-",
            p0.get("no_fit") or ecp5_path_text(p0.get("critical_path"))))
    return md


def axes_of(r):
    if "peer" in r:
        return int(r["peer"]["axes"])
    return int(r["params"].get("AXES", 0)) or None


def family_counts(r, family):
    """LUT4 / carry / FF of the bare core in a family (carry: SB_CARRY or CCU2C cells)."""
    if family == "ice40":
        return r.get("ice40_core")
    if family == "gowin":
        c = (r.get("gowin") or {}).get("core")
        return dict(c, carry=c["alu"]) if c else None  # carry: ALU cells, one bit each
    return (r.get("ecp5") or {}).get("core")


def family_fmin(r, family):
    if family == "ice40":
        return (r.get("harness") or {}).get("fmax_min_mhz")
    return (r.get(family) or {}).get("fmax_min_mhz")


def design_key(r):
    """(design, its parameters but the axes): two records with the same key differ only in
    their number of axes."""
    if "peer" in r:
        return r["peer"]["module"], json.dumps(r["peer"]["config"], sort_keys=True)
    return r["core"], json.dumps({k: v for k, v in r["params"].items() if k != "AXES"},
                                 sort_keys=True)


def axis_pairs(results):
    """Per design (core, or peer module), the two records that differ only in their number of
    axes, with the widest span of axes: {name: (fewer axes, more axes)}."""
    best = {}
    for i, a in enumerate(results):
        for b in results[i + 1:]:
            if design_key(a) != design_key(b) or not axes_of(a) or not axes_of(b) or \
                    axes_of(a) == axes_of(b):
                continue
            lo, hi = (a, b) if axes_of(a) < axes_of(b) else (b, a)
            name = a["core"] if "peer" not in a else a["peer"]["module"].rsplit(".", 1)[-1]
            if name not in best or axes_of(hi) - axes_of(lo) > \
                    axes_of(best[name][1]) - axes_of(best[name][0]):
                best[name] = (lo, hi)
    return best


def tool_text(version):
    """A tool's version line without the build details YoWASP's Yosys prints."""
    return re.sub(r", Release, .*\)$", ")", version.replace('"', ""))


def per_axis(lo, hi, family):
    """(hi - lo) / (axes of hi - axes of lo) of LUT4, carry, FF; None if a family is missing."""
    a, b = family_counts(lo, family), family_counts(hi, family)
    if not a or not b:
        return None
    d = axes_of(hi) - axes_of(lo)
    return {k: (b[k] - a[k]) / d for k in ("lut4", "carry", "ff")}


def ratio(x, y):
    return "%.2f" % (x / y) if x is not None and y else "-"


def render_peer_rows(results, peers):
    """Markdown: the peers' figures per family, their cost per axis, and the rows 'ours / peer'
    (area per axis, and whole design and Fmax at the peer's axis count), for synth.md and for
    scripts/synth/publish.py to call. Returns [] without peers."""
    if not peers:
        return []
    fams = [f for f in ("ice40", "ecp5", "gowin") if any(family_counts(p, f) for p in peers)]
    names = {"ice40": "iCE40 (HX8K)", "ecp5": "ECP5 (LFE5U-25F-6)", "gowin": "Gowin (GW2AR-18C)"}
    md = ["| peer | axes | family | core LUT4 / carry / FF / DSP / BRAM | Fmax per seed (MHz) "
          "| critical path, first seed |", "|---|---|---|---|---|---|"]
    for p in peers:
        for f in fams:
            c = family_counts(p, f)
            if not c:
                continue
            if f == "ice40":
                runs = p["harness"]["hx8k"]
                cpt = p["harness"]["hx8k"][0].get("critical_path")
                path = "`%s` -> `%s` (%d LUT + %d carry; %.1f ns logic, %.1f ns routing)" % (
                    short_name(cpt["from_net"]), short_name(cpt["to_cell"]), cpt["lut_levels"],
                    cpt["carry_steps"], cpt["logic_ns"], cpt["routing_ns"]) if cpt else "-"
            else:
                runs = p[f]["runs"]
                path = runs[0].get("no_fit") or ecp5_path_text(runs[0].get("critical_path"))
            md.append("| `%s` | %d | %s | %d / %d / %d / %d / %d | %s | %s |" % (
                p["variant"], axes_of(p), names[f], c["lut4"], c["carry"], c["ff"],
                c.get("dsp", 0), c.get("bram", 0), seeds_text(runs), path))
    ppair = axis_pairs(peers)
    ours_pairs = axis_pairs(results)
    md += ["", "Ours / peer (carry: SB_CARRY cells on iCE40, CCU2C cells of two bits on ECP5, "
           "ALU cells of one bit on Gowin; "
           "per axis = (bigger - smaller variant) / (difference in axes), as for the per-axis "
           "rows; Fmax: the lowest of the seeds):", "",
           "| ours | peer | family | what | ours LUT4 / carry / FF | peer LUT4 / carry / FF | "
           "ratio LUT4 / carry / FF | Fmax ours / peer (MHz) | ratio Fmax |",
           "|---|---|---|---|---|---|---|---|---|"]
    for pcore, (plo, phi) in sorted(ppair.items()):
        for f in fams:
            pa = per_axis(plo, phi, f)
            if not pa:
                continue
            for core, (lo, hi) in sorted(ours_pairs.items()):
                oa = per_axis(lo, hi, f)
                if not oa:
                    continue
                md.append("| `%s` (`%s` - `%s`) | `%s` - `%s` | %s | per axis | %s | %s | %s | "
                          "- | - |" % (
                              core, hi["variant"], lo["variant"], phi["variant"], plo["variant"],
                              names[f], " / ".join("%.0f" % oa[k] for k in ("lut4", "carry", "ff")),
                              " / ".join("%.0f" % pa[k] for k in ("lut4", "carry", "ff")),
                              " / ".join(ratio(oa[k], pa[k]) for k in ("lut4", "carry", "ff"))))
        # Whole designs at the axis count of the bigger peer.
        n = axes_of(phi)
        for f in fams:
            pc = family_counts(phi, f)
            for r in results:
                c = family_counts(r, f)
                if not c or axes_of(r) != n:
                    continue
                fo, fp = family_fmin(r, f), family_fmin(phi, f)
                md.append("| `%s` | `%s` | %s | whole, %d axes | %d / %d / %d | %d / %d / %d | %s "
                          "| %s / %s | %s |" % (
                              r["variant"], phi["variant"], names[f], n, c["lut4"], c["carry"],
                              c["ff"], pc["lut4"], pc["carry"], pc["ff"],
                              " / ".join(ratio(c[k], pc[k]) for k in ("lut4", "carry", "ff")),
                              "%.2f" % fo if fo is not None else "-",
                              "%.2f" % fp if fp is not None else "-", ratio(fo, fp)))
    if not md[-1].startswith("| `"):
        md[-4:] = ["No ratio: this run has no two variants of a core that differ only in AXES, and "
                   "none with as many axes as the bigger peer."]
    return md


def rs_cst(results):
    return ", ".join(sorted({r["gowin"].get("cst", "?") for r in results if "gowin" in r}))


def markdown(results, peers=()):
    ours = results
    results = list(results) + list(peers)
    full = [r for r in results if "harness" in r]
    md = ["# Synthesis results (scripts/synth.sh)", ""]
    head = ["variant", "parameters", "core I/O bits", "generic cells (FF)"]
    if full:
        head += ["iCE40 core LUT4 / CARRY / FF", "harness HX8K LUT4 / FF / LC",
                 "harness overhead LUT4 / FF", "Fmax HX8K MHz (seeds)", "Fmax min-max",
                 "UP5K (sg48)"]
    head.append("netlist vs RTL")
    md += ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for r in results:
        params = " ".join("%s=%s" % kv for kv in r["params"].items())
        row = [r["variant"], params, str(r["core_io_bits"]),
               "%d (%d)" % (r["generic"]["cells"], r["generic"]["ff"])]
        if full:
            if "harness" in r:
                c, h = r["ice40_core"], r["harness"]
                p0 = h["hx8k"][0]
                row += ["%d / %d / %d" % (c["lut4"], c["carry"], c["ff"]),
                        "%s / %s / %s of %s" % (p0.get("lut4", "?"), p0.get("ff", "?"),
                                                p0.get("lc_used", "?"), p0.get("lc_available", "?")),
                        "%d / %d" % (h["overhead"]["lut4"], h["overhead"]["ff"]),
                        seeds_text(h["hx8k"]),
                        "%.2f-%.2f" % (h["fmax_min_mhz"], h["fmax_max_mhz"])
                        if h["fmax_min_mhz"] is not None else "?"]
                u = r["up5k"]
                mac = ", %d SB_MAC16" % u["dsp_used"] if u.get("dsp_used") else ""
                if u["fits"]:
                    row.append("yes: %s LUT4%s, %s/%s LC, %s/%s pins, %.2f MHz (seed %d)" % (
                        u.get("lut4"), mac, u.get("lc_used"), u.get("lc_available"),
                        u.get("io_used"), u.get("package_pins") or u.get("io_available"),
                        u.get("fmax_mhz", 0), u["seed"]))
                else:
                    row.append("no, %s LUT4%s: %s" % (u.get("lut4"), mac, u.get("reason", "")))
            else:
                row += ["-"] * 6
        chk = r.get("netlist_check", "not run")
        row.append("match, " + chk.split(": ", 1)[1] if chk.startswith("netlist matches") else chk)
        md.append("| " + " | ".join(row) + " |")

    types = sorted({t for r in results for t in r["generic"]["cells_by_type"]})
    md += ["", "Generic cells by type (Yosys `synth -flatten`):", "",
           "| cell | " + " | ".join(r["variant"] for r in results) + " |",
           "|---|" + "---|" * len(results)]
    for t in types:
        md.append("| `%s` | " % t + " | ".join(str(r["generic"]["cells_by_type"].get(t, 0))
                                              for r in results) + " |")
    if full:
        md += ["", "Critical paths (first seed):", "",
               "| variant | device | from net | to cell | LUTs | carry steps | logic ns | routing ns |",
               "|---|---|---|---|---|---|---|---|"]
        for r in full:
            for dev, run in (("HX8K", r["harness"]["hx8k"][0]), ("UP5K", r["up5k"])):
                cp = run.get("critical_path")
                if cp:
                    md.append("| %s | %s | `%s` | `%s` | %d | %d | %.2f | %.2f |" % (
                        r["variant"], dev, cp["from_net"], cp["to_cell"], cp["lut_levels"],
                        cp["carry_steps"], cp["logic_ns"], cp["routing_ns"]))
    steps = []
    for r in results:
        for s in r["times_s"]:
            if s not in steps:
                steps.append(s)
    md += ["", "Run times, seconds (wall clock; the machine may be shared):", "",
           "| step | " + " | ".join(r["variant"] for r in results) + " |",
           "|---|" + "---|" * len(results)]
    for s in steps:
        md.append("| %s | " % s + " | ".join("%.1f" % r["times_s"][s] if s in r["times_s"] else "-"
                                            for r in results) + " |")
    ecp5_md = render_ecp5_table(results)
    if ecp5_md:
        md += ["", "## ECP5", ""] + ecp5_md
    gowin_md = render_gowin_table(results)
    if gowin_md:
        md += ["", "## Gowin", ""] + gowin_md
    peer_md = render_peer_rows(ours, peers)
    if peer_md:
        md += ["", "## Peers", ""] + peer_md
    notes = ["", "Notes:", ""]
    r0 = results[0]
    sets = {}
    for r in results:
        t = r["tools"]
        key = ("generic: " + tool_text(t.get("yosys_generic") or t["yosys"])) + \
            ("; iCE40: %s, %s" % (tool_text(t["yosys"]), tool_text(t["nextpnr"]))
             if "ice40_core" in r else "") + \
            ("; ECP5: %s, %s" % (tool_text(r["ecp5"]["tools"]["yosys"]),
                                 tool_text(r["ecp5"]["tools"]["nextpnr"])) if "ecp5" in r else "") + \
            ("; Gowin: %s, %s" % (tool_text(r["gowin"]["tools"]["yosys"]),
                                  tool_text(r["gowin"]["tools"]["nextpnr"])) if "gowin" in r else "")
        sets.setdefault(key, []).append(r["variant"])
    for key, vs in sets.items():
        notes.append("- Tools: %s (%s)." % (key, "every row" if len(sets) == 1 else ", ".join(vs)))
    notes.append("- Netlist vs RTL: the Yosys generic netlist and the RTL side by side in Verilator "
                 "on the input frames of a co-simulated random stream with aborts and feed holds "
                 "(`hwinterp cosim --dump-frames`), every output compared on every clock.")
    if full:
        notes.append("- iCE40 core: `synth_ice40` of the bare core (not placed). Harness: the core "
                     "plus the pin harness scripts/synth/make_harness.py generates for it, mapped by `synth_ice40` and placed by "
                     "nextpnr-ice40 --hx8k --package ct256; its LUT4/FF are the packed counts of "
                     "the placed design, LC the logic cells used. Overhead = harness netlist - "
                     "bare core.")
        notes.append("- Fmax: the last \"Max frequency for clock\" line of nextpnr (after routing), "
                     "target %s MHz. UP5K: --up5k --package sg48, first seed, the same netlist, "
                     "except for a core that multiplies: `synth_ice40 -dsp` maps its products "
                     "to SB_MAC16." %
                     r0["harness"]["hx8k"][0].get("target_mhz", "?") if "harness" in r0 else "")
    if ecp5_md:
        notes.append("- ECP5: YoWASP Yosys `synth_ecp5` of the bare core (core columns; DSP = "
                     "MULT18X18D, BRAM = DP16KD) and of the same pin harness, placed by "
                     "nextpnr-ecp5 --25k --package CABGA256 --speed 6 (LFE5U-25F-6BG256C, the "
                     "Colorlight 5A-75B's part) per seed; placed LUT4 sites = TRELLIS_COMB "
                     "(logic, carry and wide-function LUT4s). Critical path ends: the register "
                     "of the first and last flip-flop and the line that declares it (synth.sh "
                     "copies it onto the flip-flop before abc9, which keeps no register names); "
                     "mux = PFUMX/L6MUX21 steps of a wide function.")
    if gowin_md:
        notes.append("- Gowin: YoWASP Yosys `synth_gowin -family gw2a` of the bare core "
                     "(-noiopads; core columns: LUT4 = LUT1-LUT4 cells, ALU = one-bit carry "
                     "cells, each also a LUT4 site; BSRAM = 18-kbit block RAMs; DSP = the "
                     "multiplier primitives; LUT RAM = RAM16SDP4 cells) and of the "
                     "same pin harness, placed by nextpnr-himbaechel-gowin --device "
                     "GW2AR-LV18QN88C8/I7 --vopt family=GW2A-18C (the Tang Nano 20K's part) per "
                     "seed, the harness's pins from %s; harness placed: nextpnr's report of the "
                     "routed first seed. Critical "
                     "path ends named as on ECP5; mux = MUX2_LUT5-8 steps of a wide function, "
                     "carry = ALU carry-outs." % rs_cst(results))
    if peer_md:
        notes.append("- Peers: elaborated from the pinned PyPI packages by their own generator "
                     "(%s), synthesized and placed by the same steps; never part of hwinterp. "
                     "%s" % (", ".join(sorted({p["peer"]["package"] for p in peers})),
                             peers[0]["peer"].get("replaced", "")))
    return "\n".join(md + notes) + "\n"


def main(argv):
    if len(argv) < 3:
        sys.stderr.write(__doc__)
        return 2
    out = argv[1]
    records = [variant_result(out, v) for v in argv[2:]]
    results = [r for r in records if "peer" not in r]
    peers = [r for r in records if "peer" in r]
    if not results:
        sys.stderr.write("synth_report: no variant of hwinterp among %s\n" % " ".join(argv[2:]))
        return 2
    doc = {"variants": results}
    if peers:
        doc["peers"] = peers
    with open(os.path.join(out, "synth.json"), "w") as f:
        json.dump(doc, f, indent=2)
        f.write("\n")
    md = markdown(results, peers)
    with open(os.path.join(out, "synth.md"), "w") as f:
        f.write(md)
    sys.stdout.write(md)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
