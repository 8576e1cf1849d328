"""cocotb tests of motion_soc built with the feed profile (PROFILE=1,
rtl/motion_soc.sv; tests/cocotb/run.py builds it with ticks of 2^8 clocks):
the profile's registers, the feed hold and its release, the feed override,
and the watchdog's controlled stop, through the bus SOC_BUS names.

The moves: a line of 4000 steps along X (4096 engine operations), cruise
level 16 with q = 2^39 and L = 8 ticks: 0.25 operations a clock at level 16;
per tick the speed changes by at most q L (the acceleration limit) and the
change changes by at most q (the jerk limit).
"""
import cocotb
from cocotb.triggers import ClockCycles, ReadOnly, RisingEdge

import test_motion_soc as base

TICK = 1 << 8  # tb_motion_soc's TICK_W for this build
SPD_W = 48
Q = 1 << 39
L = 8
TARGET = 16
DX = 4000
OPS = 4096  # 2^bits(4000): the line's engine operations (models::motion_operations)
OVR_ONE = 128
CTRL_OVR_LSB = 16
ST_PROF_BUSY, ST_WDOG_STOPPING = 10, 11


async def setup_profile(bus):
    await bus.wr("PROF_Q", Q & 0xFFFFFFFF)
    await bus.wr("PROF_Q.hi", Q >> 32)
    await bus.wr("PROF_LEN", L)


async def push_move(bus, dx=DX, ops=OPS, target=TARGET, end=0, cap=0):
    """A line along X with its profile move (feed word 0: the profile's)."""
    await bus.wr("CMD_MV_OPS", ops)
    await bus.wr("CMD_MV_TARGET", target)
    await bus.wr("CMD_MV_END", end)
    await bus.wr("CMD_MV_MAX", cap)
    await base.push_line(bus, [dx, 0, 0], feed=0)


class Watch:
    """Every clock: the profile's speed and level, TIME, and the rising steps
    of X (the pins)."""

    def __init__(self, dut):
        self.dut = dut
        self.speed = []  # (time, v)
        self.level_max = 0
        self.steps = []  # times of X's rising steps
        self.bite = None
        self.abort = None
        cocotb.start_soon(self.run())

    async def run(self):
        s = base.soc(self.dut)
        out_a = base.pin(self.dut, "out_a_o")
        prev = 0
        while True:
            await RisingEdge(self.dut.clk_i)
            await ReadOnly()
            t = int(s.time_q.value)
            v = int(s.prof_speed.value)
            if not self.speed or self.speed[-1][1] != v:
                self.speed.append((t, v))
            self.level_max = max(self.level_max, int(s.prof_level.value))
            a = int(out_a.value) & 1
            if a and not prev:
                self.steps.append(t)
            prev = a
            if int(s.bite.value) and self.bite is None:
                self.bite = t
            if int(s.wstop_done.value) and self.abort is None:
                self.abort = t

    def speed_at(self, t):
        v = 0
        for tt, vv in self.speed:
            if tt > t:
                break
            v = vv
        return v


def check_limits(w, t0, t1):
    """Per tick from t0 to t1: |dv| <= q L, |d2v| <= q (the profile's
    acceleration and jerk limits). The speed changes on tick boundaries only:
    sample it a tick apart from its first change."""
    changes = [t for t, _ in w.speed[1:] if t0 <= t <= t1]  # [0]: the first clock watched
    assert changes, "the speed did not change"
    phase = changes[0] % TICK
    assert all(t % TICK == phase for t in changes), "the speed changed off its tick boundary"
    ts = list(range(changes[0] - TICK, t1 + TICK, TICK))
    vs = [w.speed_at(t) for t in ts]
    dv = [b - a for a, b in zip(vs, vs[1:])]
    d2v = [b - a for a, b in zip(dv, dv[1:])]
    assert max(abs(x) for x in dv) <= Q * L, f"|dv| {max(abs(x) for x in dv)} above q L {Q * L}"
    assert max(abs(x) for x in d2v) <= Q, f"|d2v| {max(abs(x) for x in d2v)} above q {Q}"
    return max(abs(x) for x in dv), max(abs(x) for x in d2v)


async def wait_speed(w, pred, limit):
    for _ in range(limit):
        await ClockCycles(w.dut.clk_i, 64)
        if w.speed and pred(w.speed[-1][1]):
            return
    raise AssertionError("the speed did not get there")


async def position_x(bus):
    return (await base.snapshot_pos(bus))[0]


@cocotb.test()
async def profile_registers(dut):
    """The profile's ID and registers after reset, and their access: PROF_Q,
    PROF_LEN and PROF_CTRL keep what is written in their fields, PROF_LEVEL
    and PROF_SPEED refuse writes, the move words refuse reads."""
    bus = await base.start(dut)
    idb = await bus.rd("ID_BUILD")
    assert idb >> 10 & 1, f"ID_BUILD 0x{idb:08x}: no profile bit"
    assert await bus.rd("ID_PROFILE") == SPD_W | 8 << 8 | 10 << 16 | 16 << 24
    want = {"PROF_Q": 0, "PROF_Q.hi": 0, "PROF_LEN": 1, "PROF_CTRL": OVR_ONE << CTRL_OVR_LSB,
            "PROF_LEVEL": 0, "PROF_SPEED": 0, "PROF_SPEED.hi": 0}
    for name, v in want.items():
        got = await bus.rd(name)
        assert got == v, f"{name}: 0x{got:08x} after reset, expected 0x{v:08x}"
    assert not (await bus.rd("STATUS")) >> ST_PROF_BUSY & 3
    masks = {"PROF_Q": 0xFFFFFFFF, "PROF_Q.hi": 0xFFFFFFFF, "PROF_LEN": 0xFFFFFFFF,
             "PROF_CTRL": 1 | 0x1FF << CTRL_OVR_LSB}
    for name, mask in masks.items():
        for pattern in (0xFFFFFFFF, 0xA5A5A5A5, 0):
            await bus.wr(name, pattern)
            got = await bus.rd(name)
            assert got == pattern & mask, f"{name}: wrote 0x{pattern:08x}, reads 0x{got:08x}"
    for name in ("PROF_LEVEL", "PROF_SPEED"):
        assert await bus.write(base.A(name), 1), f"{name}: a write must answer an error"
    for name in ("CMD_MV_OPS", "CMD_MV_TARGET", "CMD_MV_END", "CMD_MV_MAX"):
        _, err = await bus.read(base.A(name))
        assert err, f"{name}: a read must answer an error"


@cocotb.test()
async def move_runs_to_its_end(dut):
    """A move pushed with its profile words: the speed rises to the cruise
    level and comes down within the limits, the line ends on its point, the
    profile is at rest at the end (STATUS.prof_busy low)."""
    bus = await base.start(dut)
    w = Watch(dut)
    await setup_profile(bus)
    await push_move(bus)
    await wait_speed(w, lambda v: v > 0, 100)
    await wait_speed(w, lambda v: v == 0, 1000)
    await ClockCycles(dut.clk_i, (L + 2) * TICK)
    assert not (await bus.rd("STATUS")) >> ST_PROF_BUSY & 1
    assert w.level_max == TARGET, f"level peaked at {w.level_max}"
    dv, d2v = check_limits(w, 0, w.speed[-1][0])
    assert len(w.steps) == DX and await position_x(bus) == DX
    dut._log.info(f"move: {DX} steps, {w.speed[-1][0] - w.speed[0][0]} clocks of motion, "
                  f"max |dv| {dv / Q} q, max |d2v| {d2v / Q} q a tick")


@cocotb.test()
async def timed_push_is_refused(dut):
    """A build with the profile has no timed moves: a push with
    CMD_FLAGS.timed is not taken (FIFO_LEVEL stays 0) and sets
    EVENTS.refused; the next untimed push is taken and runs."""
    bus = await base.start(dut)
    await setup_profile(bus)
    await bus.wr("CMD_MV_OPS", OPS)
    await bus.wr("CMD_MV_TARGET", TARGET)
    await base.push_line(bus, [DX, 0, 0], feed=0, at=1000)
    assert (await bus.rd("FIFO_LEVEL")) & 0xFFFF == 0, "a timed push was taken"
    assert (await bus.rd("EVENTS")) & 1 << base.EV["refused"], "EVENTS.refused not set"
    await bus.wr("EVENTS", 1 << base.EV["refused"])
    await push_move(bus, dx=15, ops=16)  # 2^bits(15) operations
    for _ in range(200):
        if await position_x(bus) == 15:
            break
        await ClockCycles(dut.clk_i, TICK)
    assert await position_x(bus) == 15
    assert not (await bus.rd("EVENTS")) & 1 << base.EV["refused"]


@cocotb.test()
async def hold_and_resume(dut):
    """PROF_CTRL.hold: a controlled stop along the path within the limits, no
    step while held at rest; release resumes the planned profile and the line
    ends on its point."""
    bus = await base.start(dut)
    w = Watch(dut)
    await setup_profile(bus)
    await push_move(bus)
    await wait_speed(w, lambda v: v == Q * L * TARGET, 400)
    t_hold = int(base.soc(dut).time_q.value)
    await bus.wr("PROF_CTRL", OVR_ONE << CTRL_OVR_LSB | 1)
    await wait_speed(w, lambda v: v == 0, 1000)
    t_rest = w.speed[-1][0]
    check_limits(w, t_hold, t_rest)
    n = len(w.steps)
    await ClockCycles(dut.clk_i, 4 * TICK)
    assert len(w.steps) <= n + 1, "steps while held at rest"  # a pulse under way may finish
    n = len(w.steps)
    await ClockCycles(dut.clk_i, 4 * TICK)
    assert len(w.steps) == n, "steps while held at rest"
    assert (await bus.rd("STATUS")) >> ST_PROF_BUSY & 1, "the move is still queued"
    await bus.wr("PROF_CTRL", OVR_ONE << CTRL_OVR_LSB)
    await wait_speed(w, lambda v: v > 0, 100)
    await wait_speed(w, lambda v: v == 0, 1000)
    await ClockCycles(dut.clk_i, 64)
    check_limits(w, t_rest, w.speed[-1][0])
    assert len(w.steps) == DX and await position_x(bus) == DX


@cocotb.test()
async def feed_override(dut):
    """PROF_CTRL.ovr scales the cruise level (ceil(target * ovr / 128)), capped
    at CMD_MV_MAX (0: the target itself): 50 % gives level 8; 200 % with a cap
    of 20 gives 20; 200 % without a cap 16. Every line ends on its point."""
    bus = await base.start(dut)
    w = Watch(dut)
    await setup_profile(bus)
    x = 0
    for ovr, cap, want in ((64, 0, 8), (256, 20, 20), (256, 0, 16)):
        await bus.wr("PROF_CTRL", ovr << CTRL_OVR_LSB)
        w.level_max = 0
        t0 = int(base.soc(dut).time_q.value)
        await push_move(bus, cap=cap)
        await wait_speed(w, lambda v: v > 0, 100)
        await wait_speed(w, lambda v: v == 0, 2000)
        await ClockCycles(dut.clk_i, (L + 2) * TICK)
        x += DX
        assert w.level_max == want, f"override {ovr}, cap {cap}: level peaked at {w.level_max}"
        check_limits(w, t0, w.speed[-1][0])
        assert await position_x(bus) == x


@cocotb.test()
async def watchdog_controlled_stop(dut):
    """With the profile the bite is a controlled stop: EVENTS.wdog at once,
    STATUS.wdog_stopping while the speed falls to 0 within the limits, pushes
    refused; at rest the FIFO is dropped and motion_top aborted, no step after
    it; pushes refused until EVENTS.wdog is cleared, then the SoC runs again."""
    bus = await base.start(dut)
    w = Watch(dut)
    await setup_profile(bus)
    await push_move(bus)
    await push_move(bus)  # queued behind: dropped by the stop
    await wait_speed(w, lambda v: v == Q * L * TARGET, 400)
    await bus.wr("WDOG_PERIOD", 200)
    await wait_speed(w, lambda v: v < Q * L * TARGET, 100)
    assert w.bite is not None
    ev = await bus.rd("EVENTS")
    st = await bus.rd("STATUS")
    assert ev >> base.EV["wdog"] & 1 and st >> ST_WDOG_STOPPING & 1 and st >> base.ST["stopped"] & 1
    await push_move(bus)  # while stopping: refused
    assert (await bus.rd("EVENTS")) >> base.EV["refused"] & 1
    await wait_speed(w, lambda v: v == 0, 1000)
    await ClockCycles(dut.clk_i, 64)
    assert w.abort is not None, "no abort after the stop"
    v0 = w.speed_at(w.bite)
    t_rest = w.speed[-1][0]
    dv, d2v = check_limits(w, w.bite, t_rest)
    stop_steps = sum(1 for t in w.steps if t > w.bite)
    assert not any(t > w.abort for t in w.steps), "a step after the abort"
    st = await bus.rd("STATUS")
    assert not st >> ST_WDOG_STOPPING & 1 and st >> base.ST["fifo_empty"] & 1
    assert not st >> base.ST["busy"] & 1 and not st >> ST_PROF_BUSY & 1, f"STATUS 0x{st:x}"
    x = await position_x(bus)
    assert 0 < x < DX, f"X at {x}: the stop did not stop the line"
    await bus.wr("EVENTS", 1 << base.EV["refused"])
    await push_move(bus)
    assert (await bus.rd("EVENTS")) >> base.EV["refused"] & 1, "a push before the clear"
    await ClockCycles(dut.clk_i, 2 * TICK)
    assert await position_x(bus) == x, "motion after the stop"
    # Cleared (watchdog off): a new move runs to its end from where the stop left X.
    await bus.wr("WDOG_PERIOD", 0)
    await bus.wr("EVENTS", 0xFFFFFFFF)
    await push_move(bus)
    await wait_speed(w, lambda v: v > 0, 100)
    await wait_speed(w, lambda v: v == 0, 1000)
    await ClockCycles(dut.clk_i, 64)
    assert await position_x(bus) == x + DX
    ops_per_clock = v0 / (1 << SPD_W)
    dut._log.info(
        f"watchdog stop from {ops_per_clock} operations/clock (level {TARGET}, q 2^39, L {L}, "
        f"ticks of {TICK} clocks): speed 0 {t_rest - w.bite} clocks after the bite, abort "
        f"{w.abort - w.bite} clocks after it, {stop_steps} X steps ({DX}/{OPS} a operation) on the "
        f"way; max |dv| {dv / Q} q, max |d2v| {d2v / Q} q a tick")
