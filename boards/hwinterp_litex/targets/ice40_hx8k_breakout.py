"""Lattice iCE40-HX8K Breakout Board (ICE40HX8K-CT256): motion_soc with the
feed profile behind the UART Etherbone bridge on the board's FT2232H
(channel B), at its 12 MHz oscillator (no PLL).

Pins from the user guide (hwinterp_litex/platforms/ice40_hx8k_breakout.py):
on the bank-0 header J2, step/dir X A5/A6, Y B7/B8, Z A9/A10, estop A11,
probe B9 (pins the LEDs and the FTDI do not use); LED D2 (B5) lights while an
enabled event is pending (irq).
"""

from migen import Signal

from litex.build.generic_platform import IOStandard, Pins, Subsignal
from litex.build.io import CRG

from ..link import add_uart_link
from ..platforms.ice40_hx8k_breakout import Platform
from ..soc import BoardSoC

FLOW = {"family": "ice40", "device": "hx8k", "package": "ct256"}

STEP_DIR = [("A5", "A6"), ("B7", "B8"), ("A9", "A10")]
ESTOP, PROBE = "A11", "B9"


def make_soc(cfg, **_):
    if cfg.link != "uart":
        raise ValueError(f"{cfg.name}: the breakout board's link is its UART")
    if cfg.axes > len(STEP_DIR):
        raise ValueError(f"{cfg.name}: {cfg.axes} axes, the header pins chosen serve {len(STEP_DIR)}")
    if cfg.sys_hz != 12_000_000:
        raise ValueError(f"{cfg.name}: SYS_HZ {cfg.sys_hz}: this target runs at the 12 MHz oscillator")
    platform = Platform()
    platform.add_extension([
        ("stepper", i, Subsignal("step", Pins(s)), Subsignal("dir", Pins(d)), IOStandard("LVCMOS33"))
        for i, (s, d) in enumerate(STEP_DIR[:cfg.axes])
    ] + [
        ("estop", 0, Pins(ESTOP), IOStandard("LVCMOS33")),
        ("probe", 0, Pins(PROBE), IOStandard("LVCMOS33")),
    ])
    crg = CRG(platform.request("clk12"))
    led = Signal()
    pins = {
        "steppers": [platform.request("stepper", i) for i in range(cfg.axes)],
        "estop": platform.request("estop"),
        "probe": platform.request("probe"),
        "led": led,
    }
    # No identifier ROM and no SoC controller (its reset, scratch and
    # bus-error CSRs): the fit is tight.
    soc = BoardSoC(platform, cfg, crg, pins, ident="", with_ctrl=False)
    soc.comb += platform.request("user_led", 0).eq(led)
    add_uart_link(soc, platform.request("serial"), cfg.baud)
    return platform, soc
