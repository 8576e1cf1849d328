"""cocotb tests of motion_soc (rtl/motion_soc.sv) through its bus: AXI4-Lite
(cocotbext-axi's AxiLiteMaster) or Wishbone (the classic-cycle master below),
as SOC_BUS says; tests/cocotb/run.py builds and runs them.

The register map comes from rtl/regs/motion_soc.rdl itself (systemrdl-compiler),
so the reset and access tests cover every register the description has.
"""
import json
import os
import random
import subprocess
import tempfile

import cocotb
from cocotb.clock import Clock
from cocotb.triggers import ClockCycles, ReadOnly, RisingEdge, with_timeout

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BUS = os.environ.get("SOC_BUS", "axil")
FIFO_DEPTH = 8  # tb_motion_soc_*.sv's
CLK_HZ = 50_000_000
FULL_FEED = 1 << 16  # FEED_W = 16


# ---------------------------------------------------------------- the map
def load_map():
    """{name: word} for every 32-bit word of the map; name is REG, REG[i],
    REG.hi for a 64-bit register's upper word."""
    from systemrdl import RDLCompiler
    from systemrdl.node import RegNode
    from systemrdl.rdltypes import OnWriteType
    from peakrdl_regblock.udps import ALL_UDPS
    rdlc = RDLCompiler()
    for udp in ALL_UDPS:
        rdlc.register_udp(udp)
    rdlc.compile_file(os.path.join(ROOT, "rtl", "regs", "motion_soc.rdl"))
    top = rdlc.elaborate().top
    words = {}
    for reg in top.descendants(unroll=True):
        if not isinstance(reg, RegNode):
            continue
        name = reg.inst_name.upper() + ("" if reg.current_idx is None else f"[{reg.current_idx[0]}]")
        for w in range(reg.get_property("regwidth") // 32):
            word = {"addr": reg.absolute_address + 4 * w, "r": reg.has_sw_readable,
                    "w": reg.has_sw_writable, "reset": 0, "rw_mask": 0, "hw": False,
                    "special": False}
            for f in reg.fields():
                lo, hi = max(f.lsb, 32 * w), min(f.msb, 32 * w + 31)
                if lo > hi:
                    continue
                bits = ((1 << (hi - lo + 1)) - 1) << (lo - 32 * w)
                reset = f.get_property("reset") or 0
                word["reset"] |= ((reset >> (lo - f.lsb)) << (lo - 32 * w)) & bits
                if f.is_hw_writable:
                    word["hw"] = True
                if (f.get_property("onwrite") == OnWriteType.woclr or f.get_property("singlepulse")
                        or f.get_property("swmod")):
                    word["special"] = True
                if f.is_sw_readable and f.is_sw_writable and not f.is_hw_writable:
                    word["rw_mask"] |= bits
            words[name + (".hi" if w else "")] = word
    return words


MAP = load_map()


def A(name):
    return MAP[name]["addr"]


# What the hardware drives after reset (AXES 3, the default widths).
def hw_after_reset():
    return {
        "ID_BUILD": 3 | 1 << 4 | (0 if BUS == "axil" else 1) << 8 | 7 << 12 | FIFO_DEPTH << 16,
        "ID_WIDTHS": 32 | 24 << 8 | 28 << 16 | 32 << 24,
        "ID_WIDTHS2": 16 | 16 << 8,
        "ID_CLOCK": CLK_HZ,
        "STATUS": 1 << 1 | 1 << 3,  # fifo_empty, low (level 0 <= FIFO_LOW 0)
        "EVENTS": 1 << 6,  # low_water, set on every clock the level is <= FIFO_LOW
        "FIFO_LEVEL": FIFO_DEPTH << 16,
    }


EV = {"overflow": 0, "refused": 1, "late": 2, "wdog": 3, "snap": 4, "latch": 5,
      "low_water": 6, "estop": 7, "done": 8}
ST = {"busy": 0, "fifo_empty": 1, "fifo_full": 2, "low": 3, "probe": 4, "wdog_run": 5,
      "stopped": 6, "snap_armed": 7, "latch_armed": 8, "waiting": 9}


# ---------------------------------------------------------------- the buses
class WishboneMaster:
    """Classic Wishbone B4 cycles, one access a cycle; `gap` idle clocks
    between accesses (0: back to back in one held cyc)."""

    def __init__(self, dut):
        self.dut = dut
        dut.wb_cyc_i.value = 0
        dut.wb_stb_i.value = 0
        dut.wb_we_i.value = 0
        dut.wb_adr_i.value = 0
        dut.wb_dat_i.value = 0
        dut.wb_sel_i.value = 0

    async def access(self, addr, we, data=0, sel=0xF, gap=0, timeout=50):
        d = self.dut
        d.wb_cyc_i.value = 1
        d.wb_stb_i.value = 1
        d.wb_we_i.value = int(we)
        d.wb_adr_i.value = addr >> 2
        d.wb_dat_i.value = data
        d.wb_sel_i.value = sel
        for _ in range(timeout):
            await ReadOnly()
            ack, err, stall = int(d.wb_ack_o.value), int(d.wb_err_o.value), int(d.wb_stall_o.value)
            rdata = int(d.wb_dat_o.value)
            await RisingEdge(d.clk_i)
            if (ack or err) and not stall:
                break
        else:
            raise AssertionError(f"wishbone: no ack or err in {timeout} clocks at 0x{addr:03x}")
        assert not (ack and err), "wishbone: ack and err together"
        d.wb_stb_i.value = 0
        if gap:
            d.wb_cyc_i.value = 0
            await ClockCycles(d.clk_i, gap)
        return rdata, bool(err)


class Bus:
    """read(addr) -> (data, err), write(addr, data) -> err, on either bus."""

    def __init__(self, dut):
        self.dut = dut
        self.gap = 0
        if BUS == "axil":
            from cocotbext.axi import AxiLiteBus, AxiLiteMaster
            # Verilator 5.006's VPI: a handle first found by cocotb-bus's
            # lookup (hasattr over the optional signals) takes no writes
            # (verilator/verilator#4618, fixed upstream after 5.006: see
            # cocotb/cocotb#3431); found by name
            # first, as here, it does.
            for sig in ("awvalid", "awready", "awaddr", "awprot", "wvalid", "wready", "wdata",
                        "wstrb", "bvalid", "bready", "bresp", "arvalid", "arready", "araddr",
                        "arprot", "rvalid", "rready", "rdata", "rresp"):
                getattr(dut, f"s_axil_{sig}")
            # Made after the reset (start()): no reset input to follow.
            self.m = AxiLiteMaster(AxiLiteBus.from_prefix(dut, "s_axil"), dut.clk_i)
        else:
            self.m = WishboneMaster(dut)

    def wait_states(self, rng):
        """Random wait states: AXI valid and ready pauses, Wishbone idle gaps."""
        if BUS == "axil":
            def pauses():
                while True:
                    yield rng.random() < 0.3
            for ch in (self.m.write_if.aw_channel, self.m.write_if.w_channel,
                       self.m.write_if.b_channel, self.m.read_if.ar_channel,
                       self.m.read_if.r_channel):
                ch.set_pause_generator(pauses())
        self.rng = rng

    async def read(self, addr):
        if BUS == "axil":
            r = await with_timeout(self.m.read(addr, 4), 20, "us")
            return int.from_bytes(r.data, "little"), int(r.resp) != 0
        gap = self.rng.randrange(3) if getattr(self, "rng", None) else 0
        return await with_timeout(self.m.access(addr, False, gap=gap), 20, "us")

    async def write(self, addr, data, strb=0xF):
        if BUS == "axil":
            # cocotbext-axi derives WSTRB from the address and length: a
            # contiguous run of enabled bytes.
            lanes = [i for i in range(4) if strb >> i & 1]
            first, n = lanes[0], len(lanes)
            assert lanes == list(range(first, first + n)), "non-contiguous byte strobes"
            payload = (data & 0xFFFFFFFF).to_bytes(4, "little")[first:first + n]
            r = await with_timeout(self.m.write(addr + first, payload), 20, "us")
            return int(r.resp) != 0
        gap = self.rng.randrange(3) if getattr(self, "rng", None) else 0
        _, err = await with_timeout(self.m.access(addr, True, data & 0xFFFFFFFF, sel=strb,
                                                  gap=gap), 20, "us")
        return err

    async def rd(self, name):
        data, err = await self.read(A(name))
        assert not err, f"read {name}: error response"
        return data

    async def wr(self, name, value):
        err = await self.write(A(name), value)
        assert not err, f"write {name}: error response"


async def start(dut):
    cocotb.start_soon(Clock(dut.clk_i, 10, units="ns").start())
    dut.rst_ni.value = 0
    dut.probe_i.value = 0
    dut.estop_i.value = 0
    for s in ("awvalid", "wvalid", "arvalid", "bready", "rready"):  # both buses idle
        getattr(dut, f"s_axil_{s}").value = 0
    for s in ("cyc", "stb", "we"):
        getattr(dut, f"wb_{s}_i").value = 0
    await ClockCycles(dut.clk_i, 3)
    dut.rst_ni.value = 1
    await ClockCycles(dut.clk_i, 2)
    return Bus(dut)


def soc(dut):
    """The instance under test's motion_soc."""
    return (dut.u_axil if BUS == "axil" else dut.u_wb).u_soc


def pin(dut, name):
    """The instance under test's output out_a_o, out_b_o or irq_o."""
    return getattr(dut, f"{BUS}_{name}")


async def push_line(bus, deltas, feed=FULL_FEED, at=None):
    for i, dv in enumerate(deltas):
        await bus.wr(f"CMD_DELTA{i}", dv & 0xFFFFFFFF)
    await bus.wr("CMD_FEED", feed)
    flags = 0
    if at is not None:
        await bus.wr("CMD_AT", at & 0xFFFFFFFF)
        await bus.wr("CMD_AT.hi", at >> 32)
        flags |= 1 << 4
    await bus.wr("CMD_FLAGS", flags)
    await bus.wr("CMD_PUSH", 1)


async def snapshot_pos(bus):
    """Arms a snapshot at TIME 0 (passed: taken at once) and reads it."""
    await bus.wr("SNAP_AT", 0)
    await bus.wr("SNAP_AT.hi", 0)
    await bus.wr("EVENTS", 1 << EV["snap"])
    await bus.wr("SNAP_CTRL", 1)
    for _ in range(10):  # EVENTS.snap says the snapshot is there
        if (await bus.rd("EVENTS")) & 1 << EV["snap"]:
            break
    else:
        raise AssertionError("no snapshot")
    out = []
    for i in range(3):
        lo = await bus.rd(f"SNAP_POS{i}")
        hi = await bus.rd(f"SNAP_POS{i}.hi")
        v = hi << 32 | lo
        out.append(v - (1 << 64) if v >> 63 else v)
    return out


async def wait_idle(bus, limit=200):
    for _ in range(limit):
        st = await bus.rd("STATUS")
        if not st & 1 << ST["busy"] and st & 1 << ST["fifo_empty"]:
            return
    raise AssertionError("motion_soc did not become idle")


# ---------------------------------------------------------------- tests
@cocotb.test()
async def reset_values_and_access(dut):
    """Every word's reset value; read-only words refuse writes (and keep their
    value), write-only words refuse reads, read-write words keep what is
    written in their fields' bits."""
    bus = await start(dut)
    hw = hw_after_reset()
    checked = 0
    for name, w in MAP.items():
        data, err = await bus.read(w["addr"])
        if not w["r"]:
            assert err, f"{name}: a read of a write-only register must answer an error"
            continue
        assert not err, f"{name}: read error"
        if name in ("TIME_LO",):
            continue
        want = hw.get(name, w["reset"])
        assert data == want, f"{name}: reads 0x{data:08x} after reset, expected 0x{want:08x}"
        checked += 1
    dut._log.info(f"{checked} readable words at their reset values")
    # Access rights.
    for name, w in MAP.items():
        if w["w"] and not w["r"]:
            continue  # write-only: actions and the command window (tested below)
        if not w["w"]:
            before, _ = await bus.read(w["addr"])
            err = await bus.write(w["addr"], 0xFFFFFFFF)
            assert err, f"{name}: a write of a read-only register must answer an error"
            after, _ = await bus.read(w["addr"])
            if not name.startswith("TIME") and name not in ("EVENTS", "STATUS", "WDOG_LEFT"):
                assert after == before, f"{name}: read-only word changed by a write"
            continue
        if w["special"] or w["hw"] or name.startswith("WDOG"):
            continue
        for pattern in (0xFFFFFFFF, 0xA5A5A5A5, 0x0):
            assert not await bus.write(w["addr"], pattern), f"{name}: write error"
            data, err = await bus.read(w["addr"])
            assert not err and data & w["rw_mask"] == pattern & w["rw_mask"], \
                f"{name}: wrote 0x{pattern:08x}, reads 0x{data:08x}"
        assert not await bus.write(w["addr"], w["reset"])
    # Byte strobes: one byte of FIFO_LOW.
    await bus.wr("FIFO_LOW", 0x1234)
    await bus.write(A("FIFO_LOW"), 0xFFFF_FF56, strb=0x1)
    assert await bus.rd("FIFO_LOW") == 0x1256
    await bus.wr("FIFO_LOW", 0)


@cocotb.test()
async def unmapped_address_errors(dut):
    """Every word address the map does not use answers an error, on read and
    write, and the bus keeps working after each."""
    bus = await start(dut)
    used = {w["addr"] for w in MAP.values()}
    n = 0
    for addr in range(0, 0x400, 4):
        if addr in used:
            continue
        data, err = await bus.read(addr)
        assert err, f"read of unmapped 0x{addr:03x} answered OKAY"
        assert await bus.write(addr, 0xDEADBEEF), f"write of unmapped 0x{addr:03x} answered OKAY"
        n += 1
    assert await bus.rd("ID_MAGIC") == 0x484D5331
    dut._log.info(f"{n} unmapped word addresses answered errors")


@cocotb.test()
async def fifo_backpressure_and_overflow(dut):
    """With the feed held, pushes fill the FIFO to FIFO_DEPTH; the next push is
    refused with EVENTS.overflow; the low-water interrupt follows the level;
    released, every taken command runs and no refused one does."""
    bus = await start(dut)
    await bus.wr("FEED", 0)  # feed hold: the core takes commands but does not run them
    await bus.wr("EVENTS", 0xFFFFFFFF)
    total = [0, 0, 0]
    pushes = 0
    while not (await bus.rd("STATUS")) & 1 << ST["fifo_full"]:
        d = [pushes + 1, -(pushes + 2), 3]
        await push_line(bus, d)
        for i in range(3):
            total[i] += d[i]
        pushes += 1
        assert pushes < 3 * FIFO_DEPTH, "the FIFO never reported full"
    lvl = await bus.rd("FIFO_LEVEL")
    assert lvl & 0xFFFF == FIFO_DEPTH and lvl >> 16 == 0, f"FIFO_LEVEL 0x{lvl:08x} when full"
    assert not (await bus.rd("EVENTS")) & 1 << EV["overflow"]
    await push_line(bus, [1000, 1000, 1000])  # refused: full
    ev = await bus.rd("EVENTS")
    assert ev & 1 << EV["overflow"], "a push to a full FIFO did not set EVENTS.overflow"
    assert (await bus.rd("FIFO_LEVEL")) & 0xFFFF == FIFO_DEPTH
    # Overflow is sticky until written 1; irq_o follows IRQ_EN.
    await bus.wr("IRQ_EN", 1 << EV["overflow"])
    await ClockCycles(dut.clk_i, 1)
    assert pin(dut, "irq_o").value == 1
    await bus.wr("EVENTS", 1 << EV["overflow"])
    assert not (await bus.rd("EVENTS")) & 1 << EV["overflow"]
    await ClockCycles(dut.clk_i, 1)
    assert pin(dut, "irq_o").value == 0
    # Low water at 2: the interrupt once the level drains to 2.
    await bus.wr("FIFO_LOW", 2)
    await bus.wr("EVENTS", 1 << EV["low_water"])
    await bus.wr("IRQ_EN", 1 << EV["low_water"])
    assert pin(dut, "irq_o").value == 0
    await bus.wr("FEED", FULL_FEED)
    for _ in range(2000):
        await RisingEdge(dut.clk_i)
        if pin(dut, "irq_o").value == 1:
            break
    assert pin(dut, "irq_o").value == 1, "no low-water interrupt"
    assert int(soc(dut).cnt_q.value) + int(soc(dut).head_q.value) <= 2
    await bus.wr("IRQ_EN", 0)
    await wait_idle(bus, 2000)
    pos = await snapshot_pos(bus)
    assert pos == total, f"positions {pos} after {pushes} commands, expected {total}"
    dut._log.info(f"{pushes} pushes filled the FIFO (depth {FIFO_DEPTH}, 3 more in the core)")


@cocotb.test()
async def apply_at_time(dut):
    """A timed command starts (the core takes it) at the clock TIME == CMD_AT;
    one whose time has passed starts late and sets EVENTS.late."""
    bus = await start(dut)
    took = []

    async def watch():
        s = soc(dut)
        while True:
            await RisingEdge(dut.clk_i)
            await ReadOnly()
            if s.cmd_take.value == 1:
                took.append(int(s.time_q.value))

    cocotb.start_soon(watch())
    now = await bus.rd("TIME_LO")
    at = now + 300
    await push_line(bus, [5, 0, 0], at=at)
    await ClockCycles(dut.clk_i, 20)
    st = await bus.rd("STATUS")
    assert st & 1 << ST["waiting"], "the timed command is not waiting"
    assert not took
    await wait_idle(bus, 500)
    assert took == [at], f"taken at TIME {took}, CMD_AT {at}"
    assert not (await bus.rd("EVENTS")) & 1 << EV["late"]
    # A time in the past: late.
    await push_line(bus, [0, 4, 0], at=5)
    await wait_idle(bus, 500)
    assert len(took) == 2 and took[1] > 5
    assert (await bus.rd("EVENTS")) & 1 << EV["late"], "a late command was not flagged"
    assert await snapshot_pos(bus) == [5, 4, 0]
    # TIME_LO then TIME_HI read one 64-bit value.
    lo = await bus.rd("TIME_LO")
    hi = await bus.rd("TIME_HI")
    assert hi == 0 and lo > at


@cocotb.test()
async def watchdog_stop(dut):
    """Without a kick the watchdog bites WDOG_PERIOD + 1 clocks after the
    last kick's write: the core's abort_i for one clock, the FIFO dropped,
    EVENTS.wdog sticky, pushes refused until it is cleared."""
    bus = await start(dut)
    period = 400
    bites = []

    async def watch():
        s = soc(dut)
        while True:
            await RisingEdge(dut.clk_i)
            await ReadOnly()
            if s.bite.value == 1:
                bites.append(int(s.time_q.value))
            if s.wdog_kick.value == 1:
                kicks.append(int(s.time_q.value))

    kicks = []
    cocotb.start_soon(watch())
    await bus.wr("FEED", 1 << 10)  # slow: the moves outlive the watchdog
    await bus.wr("WDOG_PERIOD", period)
    for _ in range(4):
        await push_line(bus, [100, 50, 0])
        await bus.wr("WDOG_KICK", 1)
    await ClockCycles(dut.clk_i, period + 50)
    assert len(bites) == 1, f"bites at {bites}"
    assert bites[0] == kicks[-1] + period + 1, f"bit at {bites[0]}, last kick {kicks[-1]}, period {period}"
    after = bites[0] - kicks[-1]
    ev = await bus.rd("EVENTS")
    st = await bus.rd("STATUS")
    assert ev & 1 << EV["wdog"] and st & 1 << ST["stopped"] and not st & 1 << ST["wdog_run"]
    assert st & 1 << ST["fifo_empty"] and not st & 1 << ST["busy"], f"STATUS 0x{st:x} after the bite"
    pos = await snapshot_pos(bus)
    assert 0 < pos[0] < 400, f"positions {pos}: the motion did not stop"
    await push_line(bus, [1, 1, 1])
    assert (await bus.rd("EVENTS")) & 1 << EV["refused"]
    assert (await bus.rd("FIFO_LEVEL")) & 0xFFFF == 0
    # Cleared: runs again (with the watchdog off).
    await bus.wr("WDOG_PERIOD", 0)
    await bus.wr("EVENTS", 0xFFFFFFFF)
    await bus.wr("FEED", FULL_FEED)
    await push_line(bus, [1, 1, 1])
    await wait_idle(bus)
    assert await snapshot_pos(bus) == [pos[0] + 1, pos[1] + 1, 1]
    dut._log.info(f"watchdog period {period}: bit {after} clocks after the last kick")


@cocotb.test()
async def abort_and_estop(dut):
    """CTRL.abort_motion ends the move and drops the FIFO, once; estop_i stops
    the motion, sets EVENTS.estop and refuses pushes until it is cleared."""
    bus = await start(dut)
    await bus.wr("FEED", 1 << 12)
    for _ in range(3):
        await push_line(bus, [300, 0, 0])
    await ClockCycles(dut.clk_i, 200)
    await bus.wr("CTRL", 1)
    await ClockCycles(dut.clk_i, 5)
    st = await bus.rd("STATUS")
    assert st & 1 << ST["fifo_empty"] and not st & 1 << ST["busy"], f"STATUS 0x{st:x} after abort"
    assert not st & 1 << ST["stopped"]
    pos = (await snapshot_pos(bus))[0]
    assert 0 < pos < 300
    await push_line(bus, [2, 0, 0])  # taken: an abort does not stop
    await wait_idle(bus, 500)
    assert (await snapshot_pos(bus))[0] == pos + 2
    # estop_i while a move runs.
    await push_line(bus, [300, 0, 0])
    await ClockCycles(dut.clk_i, 100)
    dut.estop_i.value = 1
    await ClockCycles(dut.clk_i, 3)
    dut.estop_i.value = 0
    await ClockCycles(dut.clk_i, 5)
    ev, st = await bus.rd("EVENTS"), await bus.rd("STATUS")
    assert ev & 1 << EV["estop"] and st & 1 << ST["stopped"] and not st & 1 << ST["busy"]
    stop_pos = (await snapshot_pos(bus))[0]
    assert pos + 2 < stop_pos < pos + 302
    await push_line(bus, [1, 0, 0])
    assert (await bus.rd("EVENTS")) & 1 << EV["refused"]
    await bus.wr("EVENTS", 0xFFFFFFFF)
    await push_line(bus, [1, 0, 0])
    await wait_idle(bus, 500)
    assert (await snapshot_pos(bus))[0] == stop_pos + 1


@cocotb.test()
async def snapshot_and_probe_latch(dut):
    """A snapshot armed for a future TIME is taken at that clock; the probe
    latch takes TIME and the positions at the filtered edge."""
    bus = await start(dut)
    await bus.wr("FEED", 1 << 12)
    await push_line(bus, [200, 0, 0])
    now = await bus.rd("TIME_LO")
    await bus.wr("SNAP_AT", now + 200)
    await bus.wr("SNAP_AT.hi", 0)
    await bus.wr("SNAP_CTRL", 1)
    assert (await bus.rd("STATUS")) & 1 << ST["snap_armed"]
    await ClockCycles(dut.clk_i, 250)
    assert (await bus.rd("EVENTS")) & 1 << EV["snap"]
    assert await bus.rd("SNAP_TIME") == now + 200
    p = await bus.rd("SNAP_POS0")
    assert 0 < p < 200
    sp = await bus.rd("SNAP_SPEED0")
    assert 0 < (sp & 0x7FFFFFFF) < 100 and not sp >> 31, f"SNAP_SPEED 0x{sp:x}"
    # Probe: filter 5 clocks, rising edge.
    await bus.wr("PROBE_CFG", 5)
    await bus.wr("LATCH_CTRL", 1)
    dut.probe_i.value = 1
    await ClockCycles(dut.clk_i, 3)
    dut.probe_i.value = 0  # a glitch shorter than the filter: ignored
    await ClockCycles(dut.clk_i, 20)
    assert not (await bus.rd("EVENTS")) & 1 << EV["latch"]
    dut.probe_i.value = 1
    t0 = int(soc(dut).time_q.value)
    await ClockCycles(dut.clk_i, 20)
    assert (await bus.rd("EVENTS")) & 1 << EV["latch"]
    lt = await bus.rd("LATCH_TIME")
    # Two synchronizer clocks, the filter's 5 and the edge's: about 8.
    assert 7 <= lt - t0 <= 9, f"latched {lt - t0} clocks after the pin rose"
    dut._log.info(f"probe latch: {lt - t0} clocks after the pin rose (filter 5)")
    assert 0 < await bus.rd("LATCH_POS0") < 200
    await wait_idle(bus, 2000)


@cocotb.test()
async def step_types(dut):
    """up/down on axis 0 and quadrature on axis 1 over a move forward and back:
    the pulse counts, each up/down pulse STEP_LEN clocks long, the quadrature
    states in order, each held at least STEP_LEN + STEP_SPACE clocks."""
    bus = await start(dut)
    step_len, step_space = 3, 2
    await bus.wr("STEP_LEN", step_len)
    await bus.wr("STEP_SPACE", step_space)
    await bus.wr("STEP_TYPE", 1 | 2 << 2)  # axis 0 up/down, axis 1 quadrature
    edges = {"up": 0, "down": 0, "quad": [], "widths": [], "holds": []}

    async def watch():
        pa = pb = 0
        last = (0, 0)
        clk = since_q = 0
        high = None
        while True:
            await RisingEdge(dut.clk_i)
            await ReadOnly()
            clk += 1
            a, b = int(pin(dut, "out_a_o").value), int(pin(dut, "out_b_o").value)
            edges["up"] += (a & 1) and not (pa & 1)
            edges["down"] += (b & 1) and not (pb & 1)
            ud = (a | b) & 1
            if ud and high is None:
                high = clk
            if not ud and high is not None:
                edges["widths"].append(clk - high)
                high = None
            q = ((a >> 1) & 1, (b >> 1) & 1)
            if q != last:
                if edges["quad"]:
                    edges["holds"].append(clk - since_q)
                edges["quad"].append(q)
                last, since_q = q, clk
            pa, pb = a, b

    cocotb.start_soon(watch())
    await push_line(bus, [7, 6, 0])
    await push_line(bus, [-3, -2, 0])
    await wait_idle(bus, 2000)
    await ClockCycles(dut.clk_i, 5)
    assert edges["up"] == 7 and edges["down"] == 3, edges
    assert edges["widths"] == [step_len] * 10, edges["widths"]
    # (A, B) for the phase 0..3: A leads B going forward.
    out = [(0, 0), (1, 0), (1, 1), (0, 1)]
    want = [out[p % 4] for p in range(1, 7)] + [out[p % 4] for p in (5, 4)]
    assert edges["quad"] == want, edges["quad"]
    assert min(edges["holds"]) >= step_len + step_space, edges["holds"]
    dut._log.info(f"step types: up/down pulses {step_len} clocks; quadrature states held "
                  f"{min(edges['holds'])} to {max(edges['holds'])} clocks")


@cocotb.test()
async def gcode_program(dut):
    """A part program written through the bus: `hwinterp gcode --soc-writes`
    compiles tests/data/gcode/modal.ngc (a 3-axis machine, 100 steps/mm, at
    motion_top_n3's widths, which are motion_soc's but for FEED_W) into each
    command's staging writes and CMD_PUSH, made by the host of the C++ bus run
    (tb/bus/soc_host.h). They are written here in order, a push only when
    FIFO_LEVEL says there is room; every command runs at full feed (CMD_FEED
    1 << 16: this build's FEED_W is 16, the compile's 24). The step pulses on
    the pins and the snapshot reach the program's end point exactly."""
    exe = os.environ.get("HWINTERP_EXE", os.path.join(ROOT, "build", "tb", "hwinterp"))
    assert os.access(exe, os.X_OK), f"no hwinterp at {exe} (set HWINTERP_EXE)"
    tmp = tempfile.mkdtemp(prefix="cocotb_gcode_")
    machine = os.path.join(tmp, "m3.json")
    with open(machine, "w") as f:
        json.dump({"axes": ["X", "Y", "Z"], "steps_per_unit": {"X": 100, "Y": 100, "Z": 100}}, f)
    writes = os.path.join(tmp, "writes.json")
    r = subprocess.run([exe, "gcode", os.path.join(ROOT, "tests", "data", "gcode", "modal.ngc"),
                        "--machine", machine, "--variant", "motion_top_n3", "--mode", "direct",
                        "--progress", "0", "--soc-writes", writes],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr
    with open(writes) as f:
        prog = json.load(f)
    assert prog["axes"] == 3 and len(prog["commands"]) > 10

    bus = await start(dut)
    await bus.wr("FEED", FULL_FEED)
    steps = [0, 0, 0]

    async def count_steps():
        prev = 0
        while True:
            await RisingEdge(dut.clk_i)
            await ReadOnly()
            a, b = int(pin(dut, "out_a_o").value), int(pin(dut, "out_b_o").value)
            for i in range(3):
                if a >> i & 1 and not prev >> i & 1:
                    steps[i] += -1 if b >> i & 1 else 1
            prev = a

    counter = cocotb.start_soon(count_steps())
    room_lsb = prog["fifo_level_room_lsb"]
    for cmd in prog["commands"]:
        for reg, value in cmd:
            if reg == "CMD_FEED":
                value = FULL_FEED
            if reg == "CMD_PUSH":
                while (await bus.rd("FIFO_LEVEL")) >> room_lsb == 0:
                    await ClockCycles(dut.clk_i, 20)
            await bus.wr(reg, value)
    for _ in range(400):  # at most 400 000 clocks
        st = await bus.rd("STATUS")
        if not st & 1 << ST["busy"] and st & 1 << ST["fifo_empty"]:
            break
        await ClockCycles(dut.clk_i, 1000)
    else:
        raise AssertionError(f"motion_soc still busy, steps so far {steps} of {prog['end']}")
    await ClockCycles(dut.clk_i, 20)
    counter.kill()
    ev = await bus.rd("EVENTS")
    assert not ev & (1 << EV["overflow"] | 1 << EV["refused"]), f"EVENTS 0x{ev:x}"
    assert steps == prog["end"], f"steps {steps}, program end {prog['end']}"
    assert await snapshot_pos(bus) == prog["end"]


@cocotb.test()
async def random_traffic(dut):
    """Random legal and illegal accesses with random wait states: every
    response is the one the map predicts, no read-write register is
    corrupted, and every command the FIFO took runs (the final positions are
    the sum of the taken commands)."""
    bus = await start(dut)
    rng = random.Random(int(os.environ.get("RANDOM_SEED", "1")))
    bus.wait_states(rng)
    used = {w["addr"]: n for n, w in MAP.items()}
    rw = [n for n, w in MAP.items() if w["r"] and w["w"] and not w["special"] and not w["hw"]
          and not n.startswith("WDOG") and n not in ("FEED", "STEP_TYPE")]
    model = {n: MAP[n]["reset"] for n in rw}
    total = [0, 0, 0]
    counts = {"read": 0, "write": 0, "illegal": 0, "push": 0, "refused": 0}
    await bus.wr("EVENTS", 0xFFFFFFFF)
    for _ in range(1000):
        op = rng.random()
        if op < 0.04:  # feed hold on or off: with it on, pushes meet a full FIFO
            await bus.wr("FEED", 0 if rng.random() < 0.7 else FULL_FEED)
        elif op < 0.15:  # push a short line
            d = [rng.randrange(-6, 7) for _ in range(3)]
            await push_line(bus, d)
            ev = await bus.rd("EVENTS")
            if ev & 1 << EV["overflow"]:
                await bus.wr("EVENTS", 1 << EV["overflow"])
                counts["refused"] += 1
            else:
                total = [t + x for t, x in zip(total, d)]
                counts["push"] += 1
        elif op < 0.35:  # unmapped or wrong-direction access
            addr = rng.randrange(0, 0x400, 4)
            name = used.get(addr)
            w = MAP[name] if name else None
            if rng.random() < 0.5:
                _, err = await bus.read(addr)
                assert err == (w is None or not w["r"]), f"read 0x{addr:03x} ({name}): err {err}"
            elif w is None or not w["w"]:
                assert await bus.write(addr, rng.getrandbits(32)), f"write 0x{addr:03x}: no error"
            else:
                continue
            counts["illegal"] += 1
        elif op < 0.7:
            n = rng.choice(rw)
            v = rng.getrandbits(32)
            if n == "FIFO_LOW":
                v &= 0x7
            if n in ("STEP_LEN", "STEP_SPACE", "DIR_SETUP", "DIR_HOLD"):
                v &= 0x3  # short pulses: the pushed moves finish in the test's time
            await bus.wr(n, v)
            model[n] = v & MAP[n]["rw_mask"]
            counts["write"] += 1
        else:
            n = rng.choice(rw)
            got = await bus.rd(n)
            assert got & MAP[n]["rw_mask"] == model[n], f"{n}: 0x{got:08x}, expected 0x{model[n]:08x}"
            counts["read"] += 1
    for n in rw:
        got = await bus.rd(n)
        assert got & MAP[n]["rw_mask"] == model[n], f"{n}: 0x{got:08x}, expected 0x{model[n]:08x}"
    await bus.wr("FEED", FULL_FEED)
    await wait_idle(bus, 5000)
    assert await snapshot_pos(bus) == total, "a committed command was lost or changed"
    dut._log.info(f"random traffic: {counts}")
