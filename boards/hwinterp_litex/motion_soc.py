"""motion_soc as a LiteX peripheral.

`MotionSoC` instantiates the Wishbone top of motion_soc (rtl/motion_soc_wb.sv:
motion_top behind PeakRDL's Wishbone register block, the command FIFO,
timebase, watchdog, snapshot, probe latch, step output types and, with
PROFILE = 1, the jerk-limited feed profile) in any LiteX SoC. Its register
map is rtl/regs/motion_soc.rdl (docs/soc_regs.md); its 1 KiB Wishbone region
goes where the board map puts it:

    from hwinterp_litex.motion_soc import MotionSoC
    from hwinterp_litex.rtl import board_map

    soc.motion = MotionSoC(platform, params=dict(AXES=3, ...), clk_hz=sys_clk_freq)
    soc.bus.add_slave("motion", soc.motion.bus,
                      SoCRegion(origin=board_map().motion_base, size=board_map().motion_size))
    soc.comb += [step_pads.eq(soc.motion.out_a), dir_pads.eq(soc.motion.out_b)]
    # with a CPU: an interrupt from irq (EVENTS & IRQ_EN), e.g.
    # soc.motion.add_event_manager(); soc.irq.add("motion")

The parameters are motion_soc_wb's (rtl/motion_soc_wb.sv states each, with
its range): a motion_top variant's widths from cmake/cores.cmake
(hwinterp_litex.config), FIFO_DEPTH, PROFILE and the profile's widths.
"""

from __future__ import annotations

from migen import ClockSignal, If, Instance, ResetSignal, Signal

from litex.gen import LiteXModule

from litex.soc.interconnect import wishbone
from litex.soc.interconnect.csr_eventmanager import EventManager, EventSourceLevel

from . import rtl

# motion_soc_wb's parameters a board may set (CLK_HZ comes from clk_hz).
PARAMS = ("AXES", "ACC_W", "COORD_W", "OPS_W", "POS_W", "TIM_W", "FEED_W", "FIFO_DEPTH",
          "PROFILE", "SPD_W", "TICK_W", "LEN_W", "PROF_LVL_W", "MV_OPS_W")
# motion_soc_wb's word address: the register map's 10 byte-address bits.
ADR_BITS = 8


class MotionSoC(LiteXModule):
    """motion_soc_wb on a 32-bit Wishbone (word addresses, as LiteX's).

    bus      the Wishbone slave (add it to the SoC's bus)
    out_a    per axis: step, up or phase A (STEP_TYPE)
    out_b    per axis: dir, down or phase B
    probe    the probe/index input (asynchronous; synchronized inside)
    estop    1 stops the machine (asynchronous; synchronized inside)
    irq      EVENTS & IRQ_EN, OR-ed
    """

    def __init__(self, platform, params: dict, clk_hz: int):
        unknown = set(params) - set(PARAMS)
        if unknown:
            raise ValueError(f"MotionSoC: unknown parameter(s) {sorted(unknown)}; "
                             f"motion_soc_wb takes {', '.join(PARAMS)}")
        if "AXES" not in params:
            raise ValueError("MotionSoC: AXES is required")
        axes = int(params["AXES"])
        self.axes = axes
        self.params = dict(params)
        self.clk_hz = int(clk_hz)

        self.bus = wishbone.Interface(data_width=32, adr_width=30)
        self.out_a = Signal(axes)
        self.out_b = Signal(axes)
        self.probe = Signal()
        self.estop = Signal()
        self.irq = Signal()

        # An access takes three clocks, each stage from a flip-flop:
        # 1. the master's request (address, data, select, write) is latched;
        # 2. motion_soc_wb gets it from those registers for one clock and
        #    answers (ack or err, and the read data) in that clock;
        # 3. the answer, registered, is on the bus.
        # Registering the request keeps LiteX's bus (on the Colorlight: the
        # Etherbone record FIFO's block RAM through the record sender and the
        # decoder) out of motion_soc_wb's request-to-core-enable logic: in one
        # clock the two made the board's critical path (42.6-43.3 MHz at
        # 50 MHz, docs/synthesis.md). Registering the answer is needed anyway:
        # LiteX's SoC registers its decoder's slave select
        # (interconnect_register=True: wishbone.Decoder takes a slave's dat_r
        # with the select of the clock before), so an answer in the request's
        # own clock would reach the master masked. A request the master drops
        # before its ack (a classic-cycle master does not) still happens.
        take = Signal()  # the request is latched in this clock
        req = Signal()  # motion_soc_wb's access happens in this clock
        answer = Signal()  # the registered answer is on the bus
        we_q, sel_q = Signal(), Signal(4)
        adr_q = Signal(ADR_BITS)
        dat_w_q = Signal(32)
        ack, err, stall = Signal(), Signal(), Signal()
        dat = Signal(32)
        ack_q, err_q = Signal(), Signal()
        dat_q = Signal(32)
        self.comb += [
            take.eq(self.bus.cyc & self.bus.stb & ~req & ~answer),
            self.bus.ack.eq(answer & ack_q),
            self.bus.err.eq(answer & err_q),
            self.bus.dat_r.eq(dat_q),
        ]
        self.sync += [
            req.eq(take),
            If(take, we_q.eq(self.bus.we), sel_q.eq(self.bus.sel),
               adr_q.eq(self.bus.adr[:ADR_BITS]), dat_w_q.eq(self.bus.dat_w)),
            answer.eq(req),
            If(req, ack_q.eq(ack), err_q.eq(err), dat_q.eq(dat)),
        ]
        self.specials += Instance(
            "motion_soc_wb",
            name="motion_soc",
            **{f"p_{k}": _param(v) for k, v in params.items()},
            p_CLK_HZ=_param(self.clk_hz),
            i_clk_i=ClockSignal("sys"),
            i_rst_ni=~ResetSignal("sys"),
            i_wb_cyc_i=req,
            i_wb_stb_i=req,
            i_wb_we_i=we_q,
            i_wb_adr_i=adr_q,
            i_wb_dat_i=dat_w_q,
            i_wb_sel_i=sel_q,
            o_wb_dat_o=dat,
            o_wb_ack_o=ack,
            o_wb_err_o=err,
            o_wb_stall_o=stall,  # always 0 (classic cycles)
            i_probe_i=self.probe,
            i_estop_i=self.estop,
            o_out_a_o=self.out_a,
            o_out_b_o=self.out_b,
            o_irq_o=self.irq,
        )
        for path in rtl.file_list("motion_soc"):
            platform.add_source(path)

    def add_event_manager(self):
        """An EventManager with one level event (EVENTS & IRQ_EN), for a CPU's
        interrupt controller (soc.irq.add)."""
        self.ev = EventManager()
        self.ev.motion = EventSourceLevel()
        self.ev.finalize()
        self.comb += self.ev.motion.trigger.eq(self.irq)



def _param(value) -> Instance.PreformattedParam:
    """An integer parameter as plain decimal text: Migen would write a sized
    constant (3'd4), which SystemVerilog's int parameters take with a width
    warning."""
    return Instance.PreformattedParam(str(int(value)))
