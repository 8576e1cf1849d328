#!/usr/bin/python3
"""Writes the FuseSoC core files (rtl/<core>.core, CAPI 2) from the RTL file
lists (rtl/<core>.f), or checks that the committed ones are what they give.

usage: scripts/fusesoc_cores.py [--check]

One core file per list: hwinterp:cores:<core> for every core,
hwinterp:soc:motion_soc for motion_soc behind its register blocks, and
hwinterp:blocks:feed_profile for the feed profile and
hwinterp:blocks:motion_profile for motion_top behind it. Targets:

  default  the RTL files, in the list's order
  lint     Verilator --lint-only -Wall at the core's default parameters
           (motion_soc: behind AXI4-Lite; the generated register blocks'
           waivers, rtl/regs/lint.vlt)
  synth    Yosys synth_ice40 (edalize's yosys tool, a JSON netlist) at the
           default parameters; the project's published figures come from
           scripts/synth.sh (place and route, 3 seeds, two families)
  sim      motion_soc only: the cocotb tests (tests/cocotb/run.py) through
           both buses, run as a hook after the lint build; they need the
           project's Python environment (scripts/setup.sh)

`fusesoc core list` from the project root lists them (fusesoc.conf names the
project root as a library). --check exits 1 naming every stale or missing
core file, or a core `fusesoc core list` (the venv's FuseSoC, from the
project root) does not list; 0 when all are what the lists give and listed.
"""
import argparse
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RTL = os.path.join(ROOT, "rtl")
VERSION = "0.1.0"  # the project's (CMakeLists.txt)
ME = "scripts/fusesoc_cores.py"

DESCRIPTIONS = {
    "dda_line": "hwinterp dda_line: N-axis DDA line interpolator, step/dir outputs",
    "ppc_line": "hwinterp ppc_line: 2-axis point-by-point comparison line interpolator, step/dir outputs",
    "ppc_arc": "hwinterp ppc_arc: 2-axis point-by-point comparison arc interpolator, step/dir outputs",
    "fixed_ratio": "hwinterp fixed_ratio: N-axis fixed-ratio (velocity synthesis) line generator, step/dir outputs",
    "log_stepper": "hwinterp log_stepper: third-order logarithmic-curve stepper, 4 axes, step/dir outputs",
    "motion_top": "hwinterp motion_top: lines, arcs and helices in one core, step/dir outputs",
    "motion_soc": "hwinterp motion_soc: motion_top behind a PeakRDL register block "
                  "(AXI4-Lite or Wishbone), command FIFO, timebase, watchdog",
    "feed_profile": "hwinterp feed_profile: jerk-limited feed profile (S-curve or trapezoid) "
                    "for a core's feed input",
    "motion_profile": "hwinterp motion_profile: motion_top behind the jerk-limited feed profile",
}
# The library part of each VLNV (hwinterp:<library>:<core>); cores by default.
LIBRARY = {"motion_soc": "soc", "feed_profile": "blocks", "motion_profile": "blocks"}


def vlnv_of(core):
    return f"hwinterp:{LIBRARY.get(core, 'cores')}:{core}:{VERSION}"


def files_of(core):
    with open(os.path.join(RTL, f"{core}.f")) as f:
        return [l.strip() for l in f if l.strip() and not l.lstrip().startswith("#")]


def core_file(core):
    soc = core == "motion_soc"
    top = "motion_soc_axil" if soc else core
    vlnv = vlnv_of(core)
    L = [
        "CAPI=2:",
        f"# Generated from rtl/{core}.f by {ME}; do not edit.",
        f"name: {vlnv}",
        f"description: \"{DESCRIPTIONS[core]}\"",
        "",
        "filesets:",
        "  rtl:",
        "    file_type: systemVerilogSource",
        "    files:",
    ]
    L += [f"      - {f}" for f in files_of(core)]
    if soc:
        L += [
            "  waivers:",
            "    files:",
            "      - regs/lint.vlt: {file_type: vlt}",
        ]
    L += [
        "",
        "targets:",
        "  default: &default",
        "    filesets: [rtl]",
        f"    toplevel: {top}",
        "",
        "  lint:",
        "    <<: *default",
        f"    filesets: [rtl{', waivers' if soc else ''}]",
        "    default_tool: verilator",
        "    tools:",
        "      verilator:",
        "        mode: lint-only",
        "        verilator_options: [-Wall]",
    ]
    if soc:
        L += [
            "",
            "  sim:",
            "    <<: *default",
            "    filesets: [rtl, waivers]",
            "    default_tool: verilator",
            "    hooks:",
            "      post_build: [cocotb]",
            "    tools:",
            "      verilator:",
            "        mode: lint-only",
            "        verilator_options: [-Wall]",
        ]
    else:
        L += [
            "",
            "  synth:",
            "    <<: *default",
            "    default_tool: yosys",
            "    tools:",
            "      yosys:",
            "        arch: ice40",
            "        output_format: json",
        ]
    if soc:
        L += [
            "",
            "scripts:",
            "  cocotb:",
            "    cmd:",
            "      - sh",
            "      - -c",
            "      - >-",
            "        \"${HWINTERP_PYTHON:-$FILES_ROOT/../.venv/bin/python3}\"",
            "        \"$FILES_ROOT/../tests/cocotb/run.py\" --build-dir cocotb",
        ]
    return "\n".join(L) + "\n"


def cores():
    return sorted(n[:-2] for n in os.listdir(RTL) if n.endswith(".f"))


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--check", action="store_true")
    a = ap.parse_args(argv)
    stale = []
    for core in cores():
        if core not in DESCRIPTIONS:
            print(f"fusesoc_cores.py: rtl/{core}.f has no description here", file=sys.stderr)
            return 2
        path = os.path.join(RTL, f"{core}.core")
        text = core_file(core)
        if a.check:
            old = open(path).read() if os.path.exists(path) else None
            if old != text:
                stale.append(f"rtl/{core}.core")
        else:
            with open(path, "w") as f:
                f.write(text)
            print(f"wrote rtl/{core}.core")
    for s in stale:
        print(f"{s}: stale or missing: run {ME} and commit")
    if a.check:
        fusesoc = os.path.join(os.path.dirname(sys.executable), "fusesoc")
        out = subprocess.run([fusesoc, "core", "list"], cwd=ROOT, capture_output=True,
                             text=True).stdout
        for core in cores():
            vlnv = vlnv_of(core)
            if vlnv not in out:
                stale.append(vlnv)
                print(f"{vlnv}: not in `fusesoc core list`")
    if a.check and not stale:
        print(f"fusesoc_cores: {len(cores())} core files are what rtl/*.f give, "
              "and `fusesoc core list` lists them")
    return 1 if stale else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
