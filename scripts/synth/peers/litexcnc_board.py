#!/usr/bin/env python3
"""Generates LiteX-CNC's own firmware for a board (a peer of the board
builds, scripts/board.sh peer_litexcnc_5a_75b): LiteX-CNC's `build_firmware`
command, unchanged, on a configuration file of ours, without running the
tool chain (the gateware Verilog and the constraints, as LiteX's Builder
writes them with run=False).

Usage: litexcnc_board.py CONFIG.json --out DIR
  writes DIR/<config name>/gateware/ (colorlight_5a_75b.v, .lpf, .ys, ...)

Nothing of LiteX-CNC is kept in this repository: the code is the `litexcnc`
package pinned in scripts/requirements.txt. One thing is supplied around it:
litex_boards.targets.colorlight_5a_75x, whose clock generator LiteX-CNC's
Colorlight board takes, imports LiteDRAM's SDRAM module and PHY names at
import time; the board uses no SDRAM, and LiteDRAM is not among the
requirements, so when it is not installed those names are given as empty
placeholders (never used: an SDRAM would fail to elaborate).
"""
import sys
import types


def _litedram_placeholders():
    try:
        import litedram  # noqa: F401
        return
    except ImportError:
        pass
    for name, attrs in {"litedram": [], "litedram.modules": ["M12L16161A", "M12L64322A"],
                        "litedram.phy": ["GENSDRPHY", "HalfRateGENSDRPHY"]}.items():
        module = types.ModuleType(name)
        for a in attrs:
            setattr(module, a, None)
        sys.modules[name] = module


def main(argv):
    if len(argv) != 3 or argv[1] != "--out":
        sys.stderr.write("usage: litexcnc_board.py CONFIG.json --out DIR\n")
        return 2
    _litedram_placeholders()
    from litexcnc.cli.build_firmware import cli  # LiteX-CNC's own command

    cli([argv[0], "-o", argv[2]], standalone_mode=False)  # Builder.build(run=False)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
