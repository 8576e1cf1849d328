"""Colorlight 5A-75B v8.0 (Lattice ECP5 LFE5U-25F-6BG256C): motion_soc behind
Etherbone over its Gigabit Ethernet PHY (RGMII, LiteEth), 50 MHz from its
25 MHz oscillator.

Pins and clocks from litex-boards' platform (colorlight_5a_75b, revision 8.0).
The step/dir pins are the HUB75 connector pins LiteX-CNC's own 5A-75B v8.0
example configuration gives its first four stepgens (j7:0/j7:1, j7:2/j7:4,
j7:5/j7:6, j8:0/j8:1: step/dir of axis 0..3), estop and probe its first two
inputs (j1:0, j1:1). The connectors' buffers on this card drive outward:
check your card before wiring inputs (LiteX-CNC's documentation says the
same).
"""

from migen import ClockDomain, Signal

from litex.build.generic_platform import IOStandard, Misc, Pins, Subsignal
from litex.gen import LiteXModule
from litex.soc.cores.clock import ECP5PLL

from ..link import add_etherbone_link
from ..soc import BoardSoC

# sys_ref: the port whose clock the system clock's PLL multiplies (the
# build asks nextpnr for the margin on sys through it).
FLOW = {"family": "ecp5", "device": "25k", "package": "CABGA256", "speed": "6", "sys_ref": "clk25"}

STEP_DIR = [("j7:0", "j7:1"), ("j7:2", "j7:4"), ("j7:5", "j7:6"), ("j8:0", "j8:1")]
ESTOP, PROBE = "j1:0", "j1:1"


class _CRG(LiteXModule):
    """sys from the 25 MHz oscillator through the PLL; the user button resets."""

    def __init__(self, platform, sys_hz):
        self.rst = Signal()
        self.cd_sys = ClockDomain()
        rst_n = platform.request("user_btn_n", 0)
        self.pll = pll = ECP5PLL()
        self.comb += pll.reset.eq(~rst_n | self.rst)
        pll.register_clkin(platform.request("clk25"), 25e6)
        pll.create_clkout(self.cd_sys, sys_hz)


def make_soc(cfg, ip_address="192.168.1.50", mac_address=0x10E2D5000000, **_):
    from litex_boards.platforms.colorlight_5a_75b import Platform
    from liteeth.phy.ecp5rgmii import LiteEthPHYRGMII

    if cfg.axes > len(STEP_DIR):
        raise ValueError(f"{cfg.name}: {cfg.axes} axes, the card's step/dir pins serve {len(STEP_DIR)}")
    platform = Platform(revision="8.0", toolchain="trellis")
    platform.add_extension([
        ("stepper", i, Subsignal("step", Pins(s)), Subsignal("dir", Pins(d)), IOStandard("LVCMOS33"))
        for i, (s, d) in enumerate(STEP_DIR[:cfg.axes])
    ] + [
        ("estop", 0, Pins(ESTOP), IOStandard("LVCMOS33"), Misc("PULLMODE=UP")),
        ("probe", 0, Pins(PROBE), IOStandard("LVCMOS33"), Misc("PULLMODE=DOWN")),
    ])
    crg = _CRG(platform, cfg.sys_hz)
    led_n = platform.request("user_led_n", 0)
    led = Signal()
    pins = {
        "steppers": [platform.request("stepper", i) for i in range(cfg.axes)],
        "estop": platform.request("estop"),
        "probe": platform.request("probe"),
        "led": led,
    }
    soc = BoardSoC(platform, cfg, crg, pins)
    soc.comb += led_n.eq(~led)
    soc.ethphy = LiteEthPHYRGMII(clock_pads=platform.request("eth_clocks"),
                                 pads=platform.request("eth"), tx_delay=0)
    add_etherbone_link(soc, soc.ethphy, mac_address=mac_address, ip_address=ip_address)
    eth_rx = soc.ethphy.crg.cd_eth_rx.clk
    eth_tx = soc.ethphy.crg.cd_eth_tx.clk
    platform.add_period_constraint(eth_rx, 1e9 / 125e6)
    platform.add_period_constraint(eth_tx, 1e9 / 125e6)
    platform.add_false_path_constraints(crg.cd_sys.clk, eth_rx, eth_tx)
    return platform, soc
