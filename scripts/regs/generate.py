#!/usr/bin/python3
"""Compiles the SoC's register map (rtl/regs/motion_soc.rdl) with PeakRDL into
every file that depends on it, or checks that the committed ones are what it
gives.

usage: scripts/regs/generate.py [--check] [--rdl FILE]

Writes (each starts with a line naming this script; never edit them):
  rtl/regs/gen/motion_soc_regs_pkg.sv   the hwif types (PeakRDL-regblock)
  rtl/regs/gen/motion_soc_regs_axil.sv  the register block, AXI4-Lite (regblock --cpuif axi4-lite-flat)
  rtl/regs/gen/motion_soc_regs_wb.sv    the register block, Wishbone (regblock --cpuif wishbone-flat)
  sw/motion_soc_regs.h                  the C header (PeakRDL-cheader)
  docs/soc_regs.md                      the register page (PeakRDL-markdown)
  hls/gen/motion_soc_regs.h             the C++ register model of the HLS face (scripts/regs/cpp_model.py)

and from the board's map (rtl/regs/board.rdl, compiled with motion_soc.rdl
and link_guard.rdl: motion_soc and the link's sequence guard on a board's
bus):
  sw/host/hwinterp_host/gen/regs.py     the host package's register map (scripts/regs/py_model.py)
  sw/board_regs.h                       the board's C header (PeakRDL-cheader: the HAL driver's addresses)
  docs/board_regs.md                    the board's register page (PeakRDL-markdown)

Both register blocks: asynchronous active-low reset, an error response on an
unmapped address and on a read of a write-only or a write to a read-only
register (regblock's err_if_bad_addr and err_if_bad_rw), no retiming.

One post-processing step, the same for both: every `struct {` of regblock's
output becomes `struct packed {` (and every unpacked array member `T x[N];`
of a struct the packed `T [N-1:0] x;`), because Yosys reads only packed
structs; Verilator reads both. Nothing else is touched.

--check generates into a temporary directory and compares: exit 1 naming
every stale or missing file (run the script without --check and commit),
0 when every file is what the description gives.
"""
import argparse
import filecmp
import os
import re
import shutil
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

RDL = "rtl/regs/motion_soc.rdl"
# The board's map: these files in order, its top addrmap.
BOARD_RDL = ("rtl/regs/motion_soc.rdl", "rtl/regs/link_guard.rdl", "rtl/regs/board.rdl")
BOARD_TOP = "hwinterp_board"
OUTPUTS = {
    "pkg": "rtl/regs/gen/motion_soc_regs_pkg.sv",
    "axil": "rtl/regs/gen/motion_soc_regs_axil.sv",
    "wb": "rtl/regs/gen/motion_soc_regs_wb.sv",
    "cheader": "sw/motion_soc_regs.h",
    "markdown": "docs/soc_regs.md",
    "cpp": "hls/gen/motion_soc_regs.h",
    "py": "sw/host/hwinterp_host/gen/regs.py",
    "board_markdown": "docs/board_regs.md",
    "board_cheader": "sw/board_regs.h",
}
ME = "scripts/regs/generate.py"


def stamp(comment, rdl):
    return f"{comment} Generated from {rdl} by {ME}; do not edit.\n"


def packed(sv):
    """regblock's unpacked structs as packed ones (Yosys reads only these)."""
    sv = sv.replace("struct {", "struct packed {")
    out, depth = [], 0
    for line in sv.split("\n"):
        depth += line.count("struct packed {")
        if depth > 0:
            # A member `T name[N];` (T: a type name, or `logic [..]`) or the
            # close of a nested struct `} name[N];`: the array dimension
            # becomes the outermost packed one, so name[i] is still element i.
            m = re.match(r"^(\s*)(\}|logic|[\w:]+)((?:\s*\[[^\]]+\])*)\s+(\w+)\[(\d+)\];\s*$", line)
            if m:
                ind, base, dims, name, n = m.groups()
                line = f"{ind}{base} [{int(n) - 1}:0]{dims.strip()} {name};"
            if re.match(r"^\s*\}", line):
                depth -= 1
        out.append(line)
    return "\n".join(out)


def compile_rdl(rdl_path, *more, top=None):
    from systemrdl import RDLCompiler
    from peakrdl_regblock.udps import ALL_UDPS
    rdlc = RDLCompiler()
    for udp in ALL_UDPS:  # regblock's own properties, as `peakrdl regblock` registers them
        rdlc.register_udp(udp)
    for path in (rdl_path,) + more:
        rdlc.compile_file(path)
    return rdlc.elaborate(top_def_name=top).top


def generate(out_dir, rdl_rel):
    from peakrdl_regblock import RegblockExporter
    from peakrdl_regblock.cpuif.axi4lite import AXI4Lite_Cpuif_flattened
    from peakrdl_regblock.cpuif.wishbone import Wishbone_Cpuif_flattened
    from peakrdl_cheader.exporter import CHeaderExporter
    from peakrdl_markdown.exporter import MarkdownExporter
    from cpp_model import CppModelExporter

    rdl = os.path.join(ROOT, rdl_rel)
    files = {}
    with tempfile.TemporaryDirectory() as tmp:
        for bus, cpuif in (("axil", AXI4Lite_Cpuif_flattened), ("wb", Wishbone_Cpuif_flattened)):
            top = compile_rdl(rdl)
            RegblockExporter().export(
                top, os.path.join(tmp, bus), cpuif_cls=cpuif,
                module_name=f"motion_soc_regs_{bus}", package_name="motion_soc_regs_pkg",
                default_reset_activelow=True, default_reset_async=True,
                err_if_bad_addr=True, err_if_bad_rw=True)
            with open(os.path.join(tmp, bus, f"motion_soc_regs_{bus}.sv")) as f:
                files[bus] = stamp("//", rdl_rel) + packed(f.read())
            with open(os.path.join(tmp, bus, "motion_soc_regs_pkg.sv")) as f:
                files[f"pkg_{bus}"] = f.read()
        # One package for both blocks: they differ only in the localparams
        # named after each module, which are all kept.
        pa, pw = files.pop("pkg_axil"), files.pop("pkg_wb")
        wb_params = [l for l in pw.split("\n") if "localparam MOTION_SOC_REGS_WB_" in l]
        if re.sub(r"localparam MOTION_SOC_REGS_\w+_(\w+)", r"\1", pa) != \
           re.sub(r"localparam MOTION_SOC_REGS_\w+_(\w+)", r"\1", pw):
            raise SystemExit("generate.py: the two register blocks' packages differ beyond their names")
        last = max(i for i, l in enumerate(pa.split("\n")) if "localparam MOTION_SOC_REGS_AXIL_" in l)
        lines = pa.split("\n")
        lines[last + 1:last + 1] = wb_params
        files["pkg"] = stamp("//", rdl_rel) + packed("\n".join(lines))

        top = compile_rdl(rdl)
        hpath = os.path.join(tmp, "motion_soc_regs.h")
        CHeaderExporter().export(top, hpath)
        with open(hpath) as f:
            files["cheader"] = stamp("//", rdl_rel) + f.read()

        mpath = os.path.join(tmp, "regs.md")
        MarkdownExporter().export(top, mpath, input_files=[rdl_rel])
        with open(mpath) as f:
            md = f.read()
        files["markdown"] = (
            f"<!-- Generated from {rdl_rel} by {ME}; do not edit. -->\n\n"
            "# motion_soc registers\n\n"
            "The register map of [motion_soc](soc.md), as PeakRDL-markdown writes it from the\n"
            "SystemRDL description. Byte addresses; 32-bit accesses.\n\n" + md)

        cpath = os.path.join(tmp, "regs_cpp.h")
        CppModelExporter().export(top, cpath, namespace="hwinterp::hls::motion_soc_regs",
                                  source=rdl_rel, generator=f"{ME} (scripts/regs/cpp_model.py)")
        with open(cpath) as f:
            files["cpp"] = f.read()

        # The board's map: the host package's module and the register page.
        from py_model import PyModelExporter
        board = compile_rdl(*(os.path.join(ROOT, p) for p in BOARD_RDL), top=BOARD_TOP)
        ppath = os.path.join(tmp, "regs.py")
        PyModelExporter().export(board, ppath, source=", ".join(BOARD_RDL),
                                 generator=f"{ME} (scripts/regs/py_model.py)")
        with open(ppath) as f:
            files["py"] = f.read()
        bhpath = os.path.join(tmp, "board_regs.h")
        CHeaderExporter().export(board, bhpath)
        with open(bhpath) as f:
            files["board_cheader"] = stamp("//", ", ".join(BOARD_RDL)) + f.read()
        bpath = os.path.join(tmp, "board.md")
        MarkdownExporter().export(board, bpath, input_files=list(BOARD_RDL))
        with open(bpath) as f:
            md = f.read()
        files["board_markdown"] = (
            f"<!-- Generated from {', '.join(BOARD_RDL)} by {ME}; do not edit. -->\n\n"
            "# Board registers\n\n"
            "A board's bus as its host link sees it ([link.md](link.md), [host.md](host.md)):\n"
            "[motion_soc](soc.md) and the link's sequence guard, as PeakRDL-markdown writes it\n"
            "from the SystemRDL description. Absolute byte addresses; 32-bit accesses.\n\n" + md)

    for key, rel in OUTPUTS.items():
        path = os.path.join(out_dir, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write(files[key])


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--check", action="store_true", help="compare with the committed files")
    ap.add_argument("--rdl", default=RDL, help=argparse.SUPPRESS)
    a = ap.parse_args(argv)
    if not a.check:
        generate(ROOT, a.rdl)
        for rel in OUTPUTS.values():
            print(f"wrote {rel}")
        return 0
    with tempfile.TemporaryDirectory() as tmp:
        generate(tmp, a.rdl)
        stale = []
        for rel in OUTPUTS.values():
            mine = os.path.join(ROOT, rel)
            if not os.path.exists(mine) or not filecmp.cmp(mine, os.path.join(tmp, rel), shallow=False):
                stale.append(rel)
    for rel in stale:
        print(f"{rel}: stale or missing: run {ME} and commit")
    if not stale:
        print(f"regs: {len(OUTPUTS)} files are what {RDL} and the board map ({BOARD_RDL[-1]}) give")
    return 1 if stale else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
