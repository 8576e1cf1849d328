#!/usr/bin/env python3
"""Collects the results of scripts/synth.sh into synth.json and synth.md.

Usage: synth_report.py OUT_DIR VARIANT...

Reads, per variant, OUT_DIR/<variant>/: info.tsv and times.tsv (written by
synth.sh), the Yosys `stat -json` files, the nextpnr logs (the last "Max
frequency for clock" line is the Fmax; the packer lines give the placed LUTs
and flip-flops) and nextpnr --report files (utilisation, critical path).
Writes OUT_DIR/synth.json and OUT_DIR/synth.md and prints the markdown.
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
    return dict(sorted(st["design"]["num_cells_by_type"].items()))


def ice40(by_type):
    return {
        "lut4": by_type.get("SB_LUT4", 0),
        "carry": by_type.get("SB_CARRY", 0),
        "ff": sum(n for t, n in by_type.items() if t.startswith("SB_DFF")),
        "bram": sum(n for t, n in by_type.items() if t.startswith("SB_RAM40")),
    }


def pnr(log_path, report_path):
    """Fmax, packed LUT/FF and utilisation of one nextpnr run."""
    with open(log_path) as f:
        log = f.read()
    r = {}
    fm = FMAX.findall(log)
    if fm:  # the last one is after routing; the first is the placer's estimate
        clk, mhz, verdict, target = fm[-1]
        r.update(clock=clk, fmax_mhz=float(mhz), target_mhz=float(target), met=verdict == "PASS")
    pk = {k: int(m.group(1)) for k, rx in PACK.items() for m in [rx.search(log)] if m}
    if {"lut_only", "lut_dff", "dff_only"} <= pk.keys():
        r["lut4"] = pk["lut_only"] + pk["lut_dff"]
        r["ff"] = pk["lut_dff"] + pk["dff_only"]
    # Utilisation from the log (also there when placement failed), then the report.
    util = re.search(r"Device utilisation:\n((?:Info:.*\n)+)", log)
    for name, used, avail in re.findall(r"(\w+):\s*(\d+)/\s*(\d+)", util.group(1) if util else ""):
        short = {"ICESTORM_LC": "lc", "SB_IO": "io", "SB_GB": "gb"}.get(name)
        if short:
            r[short + "_used"], r[short + "_available"] = int(used), int(avail)
    if os.path.exists(report_path):
        with open(report_path) as f:
            rep = json.load(f)
        u = rep.get("utilization", {})
        for key, name in (("ICESTORM_LC", "lc"), ("SB_IO", "io"), ("SB_GB", "gb")):
            if key in u:
                r[name + "_used"] = u[key]["used"]
                r[name + "_available"] = u[key]["available"]
        for cp in rep.get("critical_paths", []):
            if cp.get("from") == cp.get("to"):  # the register-to-register path of the clock
                segs = cp.get("path", [])
                routing = [s for s in segs if s.get("type") == "routing"]
                logic = [s for s in segs if s.get("type") == "logic"]
                r["critical_path"] = {
                    "from_net": routing[0].get("net", "") if routing else "",
                    "to_cell": segs[-1]["to"]["cell"] if segs else "",
                    "lut_levels": sum(1 for s in logic if s["to"]["port"] == "O"),
                    "carry_steps": sum(1 for s in logic if s["to"]["port"] == "COUT"),
                    "logic_ns": round(sum(s["delay"] for s in segs if s.get("type") != "routing"), 2),
                    "routing_ns": round(sum(s["delay"] for s in routing), 2),
                }
                break
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
    """SHA-256 over the RTL files of rtl/<core>.f, in list order (names and contents).

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


def variant_result(out, variant):
    vdir = os.path.join(out, variant)
    info = read_tsv(os.path.join(vdir, "info.tsv"))
    res = {
        "variant": variant,
        "core": info["core"],
        "params": dict(kv.split("=", 1) for kv in info["params"].split()),
        "tools": {"yosys": info.get("yosys", ""), "nextpnr": info.get("nextpnr", "")},
        "times_s": read_times(os.path.join(vdir, "times.tsv")),
        "rtl_sha256": rtl_digest(info["core"]),
        "date": info.get("date", ""),
        "git": info.get("git", ""),
    }
    g = cells(os.path.join(vdir, "generic_stat.json"))
    res["generic"] = {
        "cells": sum(g.values()),
        "ff": sum(n for t, n in g.items() if "DFF" in t),
        "cells_by_type": g,
    }
    res["core_io_bits"] = port_bits(os.path.join(vdir, "%s_net.v" % info["core"]))
    if info.get("generic_only") == "0":
        core = ice40(cells(os.path.join(vdir, "ice40_core_stat.json")))
        hnet = ice40(cells(os.path.join(vdir, "harness_stat.json")))
        runs = []
        for s in info["seeds"].split():
            r = pnr(os.path.join(vdir, "pnr_hx8k_seed%s.log" % s),
                    os.path.join(vdir, "pnr_hx8k_seed%s.json" % s))
            r["seed"] = int(s)
            if "hx8k_timeout_seed%s" % s in info:
                r = {"seed": int(s), "timeout_s": int(info["hx8k_timeout_seed%s" % s])}
            runs.append(r)
        fmaxes = [r["fmax_mhz"] for r in runs if "fmax_mhz" in r]
        res["ice40_core"] = core
        res["harness"] = {
            "netlist": hnet,
            "overhead": {k: hnet[k] - core[k] for k in core},
            "hx8k": runs,
            "fmax_min_mhz": min(fmaxes) if fmaxes else None,
            "fmax_max_mhz": max(fmaxes) if fmaxes else None,
        }
        s0 = info["seeds"].split()[0]
        res["harness"]["hx8k_package_pins"] = package_pins("8k", "ct256")
        up = {"fits": info.get("up5k_fit") == "yes", "seed": int(s0),
              "package_pins": package_pins("5k", "sg48")}
        up.update(pnr(os.path.join(vdir, "pnr_up5k_seed%s.log" % s0),
                      os.path.join(vdir, "pnr_up5k_seed%s.json" % s0)))
        if not up["fits"]:
            up["reason"] = info.get("up5k_reason", "")
        res["up5k"] = up
    chk = os.path.join(vdir, "netlist_check.log")
    if info.get("check") == "1" and os.path.exists(chk):
        with open(chk) as f:
            m = re.search(r"netlist matches RTL: .*", f.read())
        res["netlist_check"] = m.group(0) if m else "FAILED"
    elif info.get("check") not in ("0", "1"):
        res["netlist_check"] = info.get("check")
    return res


def markdown(results):
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
                        ", ".join("%.2f (%d)" % (p["fmax_mhz"], p["seed"]) if "fmax_mhz" in p
                                  else "no route in %s s (%d)" % (p.get("timeout_s", "?"), p["seed"])
                                  for p in h["hx8k"]),
                        "%.2f-%.2f" % (h["fmax_min_mhz"], h["fmax_max_mhz"])
                        if h["fmax_min_mhz"] is not None else "?"]
                u = r["up5k"]
                if u["fits"]:
                    row.append("yes: %s LUT4, %s/%s LC, %s/%s pins, %.2f MHz (seed %d)" % (
                        u.get("lut4"), u.get("lc_used"), u.get("lc_available"), u.get("io_used"),
                        u.get("package_pins") or u.get("io_available"), u.get("fmax_mhz", 0),
                        u["seed"]))
                else:
                    row.append("no, %s LUT4: %s" % (u.get("lut4"), u.get("reason", "")))
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
    notes = ["", "Notes:", ""]
    r0 = results[0]
    notes.append("- %s; %s." % (r0["tools"]["yosys"], r0["tools"]["nextpnr"] or "nextpnr not run"))
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
                     "target %s MHz. UP5K: the same netlist, --up5k --package sg48, first seed." %
                     r0["harness"]["hx8k"][0].get("target_mhz", "?") if "harness" in r0 else "")
    return "\n".join(md + notes) + "\n"


def main(argv):
    if len(argv) < 3:
        sys.stderr.write(__doc__)
        return 2
    out = argv[1]
    results = [variant_result(out, v) for v in argv[2:]]
    with open(os.path.join(out, "synth.json"), "w") as f:
        json.dump({"variants": results}, f, indent=2)
        f.write("\n")
    md = markdown(results)
    with open(os.path.join(out, "synth.md"), "w") as f:
        f.write(md)
    sys.stdout.write(md)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
