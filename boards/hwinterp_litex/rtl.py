"""The project's RTL and register descriptions, as the board designs use them.

The gateware instantiates the repository's SystemVerilog (rtl/), listed by its
file lists (rtl/<name>.f, the same lists CMake, synthesis and the formal flow
read), and places its blocks at the addresses rtl/regs/board.rdl gives (the
description the host package and the docs derive from too).
"""

from __future__ import annotations

import functools
import os
from dataclasses import dataclass

# boards/hwinterp_litex/rtl.py -> the repository root.
ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
RTL = os.path.join(ROOT, "rtl")
REGS = os.path.join(RTL, "regs")


def file_list(name: str) -> list[str]:
    """The absolute paths of rtl/<name>.f, in order (comments skipped; each
    path relative to the list's own folder); a block without a list is
    rtl/<name>.sv alone (as scripts/formal.sh takes it)."""
    path = os.path.join(RTL, name + ".f")
    if not os.path.exists(path):
        single = os.path.join(RTL, name + ".sv")
        if os.path.exists(single):
            return [single]
        raise FileNotFoundError(f"no RTL file list {path} (nor {single})")
    with open(path) as f:
        names = [line.strip() for line in f if line.strip() and not line.startswith("#")]
    here = os.path.dirname(path)
    return [os.path.normpath(os.path.join(here, n)) for n in names]


@dataclass(frozen=True)
class BoardMap:
    """Byte addresses of the blocks on a board's bus (rtl/regs/board.rdl)."""

    motion_base: int  # motion_soc's register map
    motion_size: int  # its span, rounded up to a power of two
    link_base: int  # the link guard's window
    link_size: int


@functools.lru_cache(maxsize=None)
def board_map() -> BoardMap:
    """Compiles rtl/regs/board.rdl (with the maps it places) and reads the bases."""
    from systemrdl import RDLCompiler  # the venv's systemrdl-compiler (PeakRDL)

    rdlc = RDLCompiler()
    for name in ("motion_soc.rdl", "link_guard.rdl", "board.rdl"):
        rdlc.compile_file(os.path.join(REGS, name))
    top = rdlc.elaborate(top_def_name="hwinterp_board").top

    def span(node) -> int:
        return 1 << (node.size - 1).bit_length()

    motion = top.get_child_by_name("motion")
    link = top.get_child_by_name("link")
    return BoardMap(
        motion_base=motion.absolute_address,
        motion_size=span(motion),
        link_base=link.absolute_address,
        link_size=span(link),
    )
