"""The SoC every board builds: motion_soc on the bus, a host link in front of
it, the machine's pins.

A target (hwinterp_litex/targets/<board>.py) supplies the platform, the clock
and reset generator, the link's physical side and the pins; `BoardSoC` does
the rest the same way on every board, in hardware and in simulation
(hwinterp_litex/sim.py swaps the platform, the clock generator and the PHY).
"""

from __future__ import annotations

from migen import Signal

from litex.soc.integration.soc import SoCRegion
from litex.soc.integration.soc_core import SoCMini

from .config import BoardConfig
from .motion_soc import MotionSoC
from .rtl import board_map


class BoardSoC(SoCMini):
    """motion_soc (its parameters and clock from `cfg`) at the board map's
    base, without a CPU: the link's guarded master is the only bus master.

    Pins (`pins`, a dict of platform records/signals; a missing one is left
    unconnected): `steppers` a list of records with `step` and `dir` (or the
    two pins of any STEP_TYPE), one per axis; `estop` (high stops: wire it
    so that an open switch or a broken wire reads high), `probe`, `led` (lit
    while EVENTS & IRQ_EN is non-zero).
    """

    def __init__(self, platform, cfg: BoardConfig, crg, pins: dict, **kwargs):
        kwargs.setdefault("ident", f"hwinterp {cfg.name}")
        kwargs.setdefault("ident_version", False)
        SoCMini.__init__(self, platform, clk_freq=cfg.sys_hz, **kwargs)
        self.cfg = cfg
        self.crg = crg

        bm = board_map()
        self.motion = MotionSoC(platform, cfg.params, cfg.sys_hz)
        self.bus.add_slave("motion", self.motion.bus,
                           SoCRegion(origin=bm.motion_base, size=bm.motion_size, cached=False))

        steppers = pins.get("steppers", [])
        if len(steppers) != cfg.axes:
            raise ValueError(f"{cfg.name}: {len(steppers)} stepper pin pairs for {cfg.axes} axes")
        for i, pads in enumerate(steppers):
            self.comb += [pads.step.eq(self.motion.out_a[i]), pads.dir.eq(self.motion.out_b[i])]
        for name in ("estop", "probe"):
            pad = pins.get(name)
            self.comb += getattr(self.motion, name).eq(pad if pad is not None else 0)
        led = pins.get("led")
        if led is not None:
            self.comb += led.eq(self.motion.irq)
        self.irq_out = Signal()
        self.comb += self.irq_out.eq(self.motion.irq)
