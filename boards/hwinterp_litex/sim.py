"""A board's gateware for simulation: everything but the pads, the PHY and the
PLL, as Verilog for Verilator (tb/board/, `hwinterp board-sim`).

The SoC is the board's own (BoardSoC with its configuration from
cmake/cores.cmake and its link); the sim platform gives it plain top-level
ports instead of pads:

    sys_clk, sys_rst                      the clock and a reset (no PLL)
    eth_sink_valid, eth_sink_data[8]      Etherbone boards: the Ethernet
    eth_source_valid, eth_source_data[8]  wire at the MAC's side of the PHY,
                                          a byte a clock with preamble, SFD
                                          and FCS (the MAC checks and adds
                                          them, as on the board)
    serial_rx, serial_tx                  UART boards: the UART's pins
    stepper<i>_step, stepper<i>_dir       the step outputs of each axis
    estop, probe                          the machine's inputs

Usage: python -m hwinterp_litex.sim --board NAME --out DIR [--sys-hz HZ] [--baud B]
writes DIR/<top>.v (the LiteX SoC) and DIR/<top>.files (the project's RTL it
instantiates, one path a line, in order).
"""

from __future__ import annotations

import argparse
import dataclasses
import os
import sys

from migen import Signal

from litex.build.generic_platform import Pins, Subsignal
from litex.build.sim import SimPlatform
from litex.build.io import CRG

from . import config as board_config
from .link import add_etherbone_link, add_uart_link
from .soc import BoardSoC

TOP = "board_sim"


def _io(cfg):
    io = [
        ("sys_clk", 0, Pins(1)),
        ("sys_rst", 0, Pins(1)),
        ("estop", 0, Pins(1)),
        ("probe", 0, Pins(1)),
    ]
    for i in range(cfg.axes):
        io.append(("stepper", i, Subsignal("step", Pins(1)), Subsignal("dir", Pins(1))))
    if cfg.link == "etherbone":
        io.append(("eth", 0,
                   Subsignal("source_valid", Pins(1)), Subsignal("source_data", Pins(8)),
                   Subsignal("sink_valid", Pins(1)), Subsignal("sink_data", Pins(8))))
    else:
        io.append(("serial", 0, Subsignal("rx", Pins(1)), Subsignal("tx", Pins(1))))
    return io


def sim_soc(cfg):
    """The board's SoC on the sim platform, its link on the sim's wire."""
    platform = SimPlatform("SIM", _io(cfg), name=TOP)
    crg = CRG(platform.request("sys_clk"), platform.request("sys_rst"))
    pins = {
        "steppers": [platform.request("stepper", i) for i in range(cfg.axes)],
        "estop": platform.request("estop"),
        "probe": platform.request("probe"),
    }
    soc = BoardSoC(platform, cfg, crg, pins)
    if cfg.link == "etherbone":
        from liteeth.phy.model import LiteEthPHYModel

        class WirePHY(LiteEthPHYModel):
            # The MAC adds and checks preamble and FCS, as with the board's PHY;
            # the sim's wire carries them.
            with_preamble_crc = True

        soc.ethphy = WirePHY(platform.request("eth"))
        add_etherbone_link(soc, soc.ethphy)
    else:
        add_uart_link(soc, platform.request("serial"), cfg.baud)
    return platform, soc


def write(cfg, out_dir):
    """Writes the SoC's Verilog and the list of the project's RTL files."""
    platform, soc = sim_soc(cfg)
    os.makedirs(out_dir, exist_ok=True)
    soc.finalize()
    verilog = platform.get_verilog(soc, name=TOP)
    # Memory contents (the identifier ROM) go beside the Verilog, read by an
    # absolute path, so the simulation runs from any directory.
    source = verilog.main_source
    for name, content in verilog.data_files.items():
        path = os.path.abspath(os.path.join(out_dir, name))
        with open(path, "w") as f:
            f.write(content)
        source = source.replace(f'"{name}"', f'"{path}"')
    with open(os.path.join(out_dir, TOP + ".v"), "w") as f:
        f.write(source)
    with open(os.path.join(out_dir, TOP + ".files"), "w") as f:
        for path, _language, _library, *_ in platform.sources:
            f.write(path + "\n")
    # The gateware's configuration, for the harness and the reports.
    with open(os.path.join(out_dir, TOP + ".cfg"), "w") as f:
        f.write(f"board {cfg.name}\nlink {cfg.link}\nsys_hz {cfg.sys_hz}\nbaud {cfg.baud}\n")
        for k, v in cfg.params.items():
            f.write(f"param {k} {v}\n")


def main(argv=None):
    ap = argparse.ArgumentParser(prog="python -m hwinterp_litex.sim", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--board", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--sys-hz", type=int, default=None,
                    help="the simulated clock (default: the board's)")
    ap.add_argument("--baud", type=int, default=None,
                    help="a UART board's rate (default: the board's)")
    args = ap.parse_args(argv)
    try:
        cfg = board_config.board(args.board)
    except ValueError as e:
        print(f"hwinterp_litex.sim: {e}", file=sys.stderr)
        return 2
    if args.sys_hz is not None:
        if args.sys_hz <= 0:
            print(f"hwinterp_litex.sim: --sys-hz {args.sys_hz} must be positive", file=sys.stderr)
            return 2
        cfg = dataclasses.replace(cfg, sys_hz=args.sys_hz)
    if args.baud is not None:
        if cfg.link != "uart" or args.baud <= 0:
            print(f"hwinterp_litex.sim: --baud {args.baud}: board {cfg.name} has "
                  f"{'no UART' if cfg.link != 'uart' else 'a UART, and a rate must be positive'}",
                  file=sys.stderr)
            return 2
        cfg = dataclasses.replace(cfg, baud=args.baud)
    write(cfg, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
