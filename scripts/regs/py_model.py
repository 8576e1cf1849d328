"""A PeakRDL-style exporter: the host package's register map
(sw/host/hwinterp_host/gen/regs.py) from the board's SystemRDL description
(rtl/regs/board.rdl with motion_soc.rdl and link_guard.rdl), so that no
address or field of the host is typed by hand.

    PyModelExporter().export(board_addrmap_node, "gen/regs.py", source=..., generator=...)

It writes one module of data built from hwinterp_host.regmap's types: per
addrmap of the board (motion, link) a Block with its base, size, every
register at its absolute byte address (offset, 32 or 64 bits, software
access, external or not) with every field's position, width, access, reset
value and write-1-to-clear / single-pulse properties, the memories (the
guard's STREAM), and the numbered copies (snap_pos0 ... snap_pos5) as lists
named after their stem (SNAP_POS). Registers are listed in address order.
It refuses what it does not describe, by name: nested addrmaps below a
block, register files, arrays, msb0 fields, accesses other than 32 bits.
"""
import re

from systemrdl.node import AddrmapNode, FieldNode, MemNode, RegfileNode, RegNode
from systemrdl.rdltypes import OnWriteType


class UnsupportedError(Exception):
    pass


def _sw(node):
    r, w = node.is_sw_readable, node.is_sw_writable
    return "rw" if r and w else ("r" if r else "w")


def _reg_sw(reg):
    r, w = reg.has_sw_readable, reg.has_sw_writable
    return "rw" if r and w else ("r" if r else "w")


def _blocks(top):
    """The board's blocks: its addrmap children (or the top itself if it has
    registers directly)."""
    kids = list(top.children())
    if all(isinstance(k, AddrmapNode) for k in kids):
        return kids
    return [top]


def _check(block):
    for node in block.descendants(unroll=False):
        p = node.get_path()
        if isinstance(node, (RegfileNode, AddrmapNode)):
            raise UnsupportedError(f"{p}: only registers and memories directly in a block")
        if isinstance(node, RegNode):
            if node.is_array:
                raise UnsupportedError(f"{p}: register arrays are not described (use numbered copies)")
            if node.get_property("accesswidth") != 32 or node.get_property("regwidth") not in (32, 64):
                raise UnsupportedError(f"{p}: only 32-bit accesses to 32- or 64-bit registers")
        if isinstance(node, FieldNode) and node.msb < node.lsb:
            raise UnsupportedError(f"{p}: msb0 fields are not described")


def _arrays(names):
    """Numbered copies: stems with instances stem0 ... stemN-1 (N > 1)."""
    stems = {}
    for n in names:
        m = re.fullmatch(r"(.*?[A-Z_])(\d+)", n)
        if m:
            stems.setdefault(m.group(1), []).append(int(m.group(2)))
    out = {}
    for stem, idx in sorted(stems.items()):
        if len(idx) > 1 and sorted(idx) == list(range(len(idx))):
            out[stem] = tuple(f"{stem}{i}" for i in range(len(idx)))
    return out


class PyModelExporter:
    def export(self, top, path, source, generator, package="hwinterp_host"):
        L = []
        w = L.append
        w(f'"""Generated from {source} by {generator}; do not edit.')
        w("")
        w(f"The register map of {top.inst_name} ({top.get_property('name') or top.inst_name}):")
        w(f"{top.get_property('desc') or ''}")
        w("")
        w("Blocks (absolute byte addresses):")
        blocks = _blocks(top)
        for b in blocks:
            w(f"  {b.inst_name:8s} 0x{b.raw_absolute_address:08x}, {b.size} bytes ({b.type_name})")
        w('"""')
        w(f"from {package}.regmap import Block, Field, Mem, Reg")
        w("")
        w(f'MAP = "{top.inst_name}"')
        for b in blocks:
            _check(b)
            w(f"{b.inst_name.upper()}_BASE = 0x{b.raw_absolute_address:08x}")
        for b in blocks:
            regs = sorted((n for n in b.children() if isinstance(n, RegNode)),
                          key=lambda r: r.raw_absolute_address)
            mems = sorted((n for n in b.children() if isinstance(n, MemNode)),
                          key=lambda m: m.raw_absolute_address)
            w("")
            w(f"{b.inst_name} = Block(")
            w(f'    "{b.inst_name}", "{b.type_name}", base=0x{b.raw_absolute_address:08x}, '
              f"size=0x{b.size:x},")
            w("    regs=(")
            for r in regs:
                w(f'        Reg("{r.inst_name.upper()}", 0x{r.raw_absolute_address:08x}, '
                  f"0x{r.raw_address_offset:03x}, {r.get_property('regwidth')}, "
                  f'"{_reg_sw(r)}", {bool(r.external)}, (')
                for f in sorted(r.fields(), key=lambda f: f.lsb):
                    reset = f.get_property("reset")
                    reset = reset if isinstance(reset, int) else 0
                    w(f'            Field("{f.inst_name}", {f.lsb}, {f.width}, "{_sw(f)}", '
                      f"0x{reset:x}, {bool(f.is_hw_writable)}, "
                      f"{f.get_property('onwrite') == OnWriteType.woclr}, "
                      f"{bool(f.get_property('singlepulse'))}),")
                w("        )),")
            w("    ),")
            w("    mems=(")
            for m in mems:
                w(f'        Mem("{m.inst_name.upper()}", 0x{m.raw_absolute_address:08x}, '
                  f"0x{m.raw_address_offset:03x}, {m.get_property('mementries')}, "
                  f"{m.get_property('memwidth')}, \"{_sw(m)}\"),")
            w("    ),")
            arrays = _arrays([r.inst_name.upper() for r in regs])
            w("    arrays={")
            for stem, names in arrays.items():
                w(f'        "{stem}": (' + ", ".join(f'"{n}"' for n in names) + "),")
            w("    },")
            w(")")
        w("")
        w("BLOCKS = (" + ", ".join(b.inst_name for b in blocks) + ",)")
        with open(path, "w") as f:
            f.write("\n".join(L) + "\n")
