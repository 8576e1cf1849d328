"""Sipeed Tang Nano 20K (Gowin GW2AR-LV18QN88C8/I7): motion_soc behind the
UART Etherbone bridge on its USB serial port (the BL616 on the board: pins
69/70), at its 27 MHz oscillator (no PLL).

Pins and clocks from litex-boards' platform (sipeed_tang_nano_20k). The
release on PyPI (2023.12) lists no connectors; the step/dir, estop and probe
pins are on the header litex-boards lists as J5 in later releases
("- - - 76 80 42 41 56 54 51 48 55 49 86 79 - - 72 71 53 52"), avoiding pin 80
(the SD card's DAT2) and 79 (the RGB LED): X 76/42, Y 41/56, Z 54/51,
A 48/49 (step/dir), estop 72, probe 71. LED 0 (pin 15) lights while an
enabled event is pending (irq).
"""

from migen import Signal

from litex.build.generic_platform import IOStandard, Misc, Pins, Subsignal
from litex.build.io import CRG

from ..link import add_uart_link
from ..soc import BoardSoC

FLOW = {"family": "gowin", "device": "GW2AR-LV18QN88C8/I7", "family_name": "GW2A-18C"}

STEP_DIR = [("76", "42"), ("41", "56"), ("54", "51"), ("48", "49")]
ESTOP, PROBE = "72", "71"


def make_soc(cfg, **_):
    from litex_boards.platforms.sipeed_tang_nano_20k import Platform

    if cfg.link != "uart":
        raise ValueError(f"{cfg.name}: the Tang Nano 20K's link is its UART")
    if cfg.axes > len(STEP_DIR):
        raise ValueError(f"{cfg.name}: {cfg.axes} axes, the header pins chosen serve {len(STEP_DIR)}")
    platform = Platform(toolchain="apicula")
    platform.add_extension([
        ("stepper", i, Subsignal("step", Pins(s)), Subsignal("dir", Pins(d)), IOStandard("LVCMOS33"))
        for i, (s, d) in enumerate(STEP_DIR[:cfg.axes])
    ] + [
        ("estop", 0, Pins(ESTOP), IOStandard("LVCMOS33"), Misc("PULL_MODE=UP")),
        ("probe", 0, Pins(PROBE), IOStandard("LVCMOS33"), Misc("PULL_MODE=DOWN")),
    ])
    if cfg.sys_hz != 27_000_000:
        raise ValueError(f"{cfg.name}: SYS_HZ {cfg.sys_hz}: this target runs at the 27 MHz oscillator")
    crg = CRG(platform.request("clk27"))
    led = Signal()
    pins = {
        "steppers": [platform.request("stepper", i) for i in range(cfg.axes)],
        "estop": platform.request("estop"),
        "probe": platform.request("probe"),
        "led": led,
    }
    soc = BoardSoC(platform, cfg, crg, pins)
    soc.comb += platform.request("led_n", 0).eq(~led)
    add_uart_link(soc, platform.request("serial"), cfg.baud)
    return platform, soc
