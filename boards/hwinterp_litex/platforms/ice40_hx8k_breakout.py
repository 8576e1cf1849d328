"""Lattice iCE40-HX8K Breakout Board (ICE40HX8K-CT256), a LiteX platform:
litex-boards has none for it. Pins from the board's user guide (Lattice
EB85, "iCE40HX-8K Breakout Board User's Guide"): the 12 MHz oscillator on
J3, the FT2232H's channel B as the UART (RS232_Rx_TTL on B10 into the FPGA,
RS232_Tx_TTL on B12 out of it), the eight LEDs D2-D9 (B5 B4 A2 A1 C5 C4 B3
C3, lit high), and the bank-0 header J2 for the machine's pins.
"""

from litex.build.generic_platform import IOStandard, Pins, Subsignal
from litex.build.lattice import LatticeiCE40Platform

_io = [
    ("clk12", 0, Pins("J3"), IOStandard("LVCMOS33")),
    ("serial", 0,
        Subsignal("rx", Pins("B10")),
        Subsignal("tx", Pins("B12")),
        IOStandard("LVCMOS33")),
    ("user_led", 0, Pins("B5"), IOStandard("LVCMOS33")),
    ("user_led", 1, Pins("B4"), IOStandard("LVCMOS33")),
    ("user_led", 2, Pins("A2"), IOStandard("LVCMOS33")),
    ("user_led", 3, Pins("A1"), IOStandard("LVCMOS33")),
    ("user_led", 4, Pins("C5"), IOStandard("LVCMOS33")),
    ("user_led", 5, Pins("C4"), IOStandard("LVCMOS33")),
    ("user_led", 6, Pins("B3"), IOStandard("LVCMOS33")),
    ("user_led", 7, Pins("C3"), IOStandard("LVCMOS33")),
]


class Platform(LatticeiCE40Platform):
    default_clk_name = "clk12"
    default_clk_period = 1e9 / 12e6

    def __init__(self, toolchain="icestorm"):
        LatticeiCE40Platform.__init__(self, "ice40-hx8k-ct256", _io, toolchain=toolchain)

    def do_finalize(self, fragment):
        LatticeiCE40Platform.do_finalize(self, fragment)
        self.add_period_constraint(self.lookup_request("clk12", loose=True), 1e9 / 12e6)
