"""A unit fixture, not the board: an in-process stand-in for a board's bus
behind Etherbone, enough to exercise the host package's session, stager,
credit and run logic (the simulated board, Verilated gateware, is the
end-to-end test). It models:

- the sequence guard of docs/link.md: SEQ/EXPECT, the stream of chunks,
  ACCEPTED/STALE/DROPPED/ERRORS, writes outside the window passed through;
- a small motion_soc: ID registers, the command window's staging registers
  and CMD_PUSH into a FIFO of `depth` (a push to a full FIFO sets
  EVENTS.overflow, a push while EVENTS.wdog/estop is set EVENTS.refused),
  a core that takes the head command and completes it after `cmd_clocks`
  clocks (adding its displacement to the position; a line's deltas, an
  arc's end on its plane's axes), FEED 0 or PROF_CTRL.hold holding it,
  TIME (TIME_LO latching TIME_HI), the watchdog, CTRL.abort_motion,
  snapshots at once (SNAP_AT in the past), EVENTS write-1-to-clear;
- time: `clocks_per_packet` clocks pass with every packet served.

Addresses come from the generated map, as the host's do; the behaviour is
written here from docs/soc.md and docs/link.md, not from the host's code.
"""
from __future__ import annotations

import struct
from collections import deque

from hwinterp_host.gen.regs import link as G
from hwinterp_host.gen.regs import motion as M

MASK = 0xFFFFFFFF


def _bits(reg, **values):
    v = 0
    for name, x in values.items():
        f = getattr(reg.f, name)
        v |= (x & ((1 << f.width) - 1)) << f.lsb
    return v


def _ev(name):
    return getattr(M.EVENTS.f, name).mask


def _s32(v):
    v &= MASK
    return v - (1 << 32) if v >> 31 else v


class FakeBoard:
    def __init__(self, axes=3, depth=16, profile=False, clock_hz=50_000_000, cmd_clocks=1000,
                 clocks_per_packet=200, widths=None):
        self.axes, self.depth, self.profile = axes, depth, profile
        self.clock_hz, self.cmd_clocks, self.clocks_per_packet = clock_hz, cmd_clocks, clocks_per_packet
        self.widths = widths or dict(acc_w=32, coord_w=24, ops_w=28, pos_w=32, tim_w=16, feed_w=24)
        # guard
        self.expect = 0
        self.accepted = self.stale = self.dropped = self.errors = 0
        # motion_soc
        self.regs = {}
        for r in M.regs:
            for i, a in enumerate(r.word_addrs):
                self.regs[a] = (r.reset >> (32 * i)) & MASK
        self.events = 0
        self.fifo = deque()
        self.current = None      # [command, clocks left]
        self.pos = [0] * axes
        self.time = 0
        self.time_hi_latch = 0
        self.wdog_left = 0
        self.snap_time = 0
        self.snap_pos = [0] * axes
        self.pushes = 0
        self.completed = 0
        self.bus_writes = []     # every write that reached motion_soc: (addr, value)

    # ---------------------------------------------------------------- Etherbone
    def serve(self, packet: bytes):
        """One Etherbone packet in, its reply (or None: no reads) out."""
        magic, vf, sizes, _ = struct.unpack_from(">HBBI", packet, 0)
        assert magic == 0x4E6F and vf >> 4 == 1 and sizes == 0x44
        _, be, nw, nr = struct.unpack_from(">BBBB", packet, 8)
        off = 12
        if nw:
            base = struct.unpack_from(">I", packet, off)[0]
            words = struct.unpack_from(f">{nw}I", packet, off + 4)
            off += 4 + 4 * nw
            self._writes(base, words)
        out = None
        if nr:
            ret = struct.unpack_from(">I", packet, off)[0]
            addrs = struct.unpack_from(f">{nr}I", packet, off + 4)
            data = [self.bus_read(a) for a in addrs]
            out = struct.pack(">HBBI", 0x4E6F, 0x10, 0x44, 0) + struct.pack(">BBBB", 0, 0x0F, nr, 0)
            out += struct.pack(">I", ret) + struct.pack(f">{nr}I", *data)
        self.advance(self.clocks_per_packet)
        return out

    def _writes(self, base, words):
        if base != G.SEQ.addr:     # outside the window (or not from SEQ): passed through
            for i, w in enumerate(words):
                self.bus_write(base + 4 * i, w)
            return
        # an Etherbone record from WIN_BASE: SEQ, then the stream
        seq = words[0]
        if seq == self.expect:
            open_ = True
            self.expect = (self.expect + 1) & MASK
            self.accepted += 1
        else:
            open_ = False
            self.stale += 1
        left, addr = 0, 0
        for w in words[1:]:
            if left == 0:
                left, addr = w >> 24, (w & 0xFFFFFF) << 2
                continue
            if open_:
                self.bus_write(addr, w)
            else:
                self.dropped += 1
            addr += 4
            left -= 1

    # ---------------------------------------------------------------- the bus
    def bus_read(self, a):
        if a == G.SEQ.addr:
            return self.expect
        g = {G.ACCEPTED.addr: self.accepted, G.STALE.addr: self.stale,
             G.DROPPED.addr: self.dropped, G.ERRORS.addr: self.errors}
        if a in g:
            return g[a] & MASK
        if a == M.ID_BUILD.addr:
            return _bits(M.ID_BUILD, axes=self.axes, core=1, bus=1, profile=int(self.profile),
                         step_types=7, fifo_depth=self.depth)
        if a == M.ID_WIDTHS.addr:
            w = self.widths
            return _bits(M.ID_WIDTHS, acc_w=w["acc_w"], coord_w=w["coord_w"], ops_w=w["ops_w"],
                         pos_w=w["pos_w"])
        if a == M.ID_WIDTHS2.addr:
            return _bits(M.ID_WIDTHS2, tim_w=self.widths["tim_w"], feed_w=self.widths["feed_w"])
        if a == M.ID_CLOCK.addr:
            return self.clock_hz
        if a == M.ID_PROFILE.addr:
            return _bits(M.ID_PROFILE, spd_w=48, tick_w=10, len_w=10, lvl_w=16) if self.profile else 0
        if a == M.STATUS.addr:
            return _bits(M.STATUS, busy=int(self.current is not None), fifo_empty=int(not self.fifo),
                         fifo_full=int(len(self.fifo) >= self.depth),
                         low=int(len(self.fifo) <= self.regs[M.FIFO_LOW.addr]),
                         wdog_run=int(self.regs[M.WDOG_PERIOD.addr] != 0 and not self.events & _ev("wdog")),
                         stopped=int(bool(self.events & (_ev("wdog") | _ev("estop")))),
                         prof_busy=int(self.profile and (self.current is not None or bool(self.fifo))))
        if a == M.EVENTS.addr:
            return self.events
        if a == M.FIFO_LEVEL.addr:
            return _bits(M.FIFO_LEVEL, fill=len(self.fifo), room=self.depth - len(self.fifo))
        if a == M.TIME_LO.addr:
            self.time_hi_latch = self.time >> 32
            return self.time & MASK
        if a == M.TIME_HI.addr:
            return self.time_hi_latch
        if a == M.WDOG_LEFT.addr:
            return self.wdog_left
        if a in M.SNAP_TIME.word_addrs:
            return (self.snap_time >> (32 * M.SNAP_TIME.word_addrs.index(a))) & MASK
        for i, r in enumerate(M.SNAP_POS[:self.axes]):
            if a in r.word_addrs:
                return (self.snap_pos[i] >> (32 * r.word_addrs.index(a))) & MASK
        if a in M.PROF_SPEED.word_addrs:
            return 0
        return self.regs.get(a, 0)

    def bus_write(self, a, v):
        self.bus_writes.append((a, v))
        if a == M.EVENTS.addr:
            self.events &= ~v
            return
        if a == M.CTRL.addr:
            if v & M.CTRL.f.abort_motion.mask:
                self.fifo.clear()
                self.current = None
            return
        if a == M.CMD_PUSH.addr:
            if self.events & (_ev("wdog") | _ev("estop")):
                self.events |= _ev("refused")
            elif len(self.fifo) >= self.depth:
                self.events |= _ev("overflow")
            else:
                self.fifo.append(self.staged())
                self.pushes += 1
                self._start()
            return
        if a == M.SNAP_CTRL.addr:
            if v & M.SNAP_CTRL.f.arm.mask:
                self.snap_time, self.snap_pos = self.time, list(self.pos)
                self.events |= _ev("snap")
            return
        if a in (M.WDOG_PERIOD.addr, M.WDOG_KICK.addr):
            if a == M.WDOG_PERIOD.addr:
                self.regs[a] = v
            self.wdog_left = self.regs[M.WDOG_PERIOD.addr]
            return
        self.regs[a] = v

    def staged(self):
        return {r.name: self.regs[r.addr] for r in M.regs if r.name.startswith("CMD_")}

    def displacement(self, c):
        d = [_s32(c[f"CMD_DELTA{i}"]) for i in range(self.axes)]
        flags = c["CMD_FLAGS"]
        if flags & M.CMD_FLAGS.f.arc.mask:
            x, y = [(0, 1), (2, 0), (1, 2)][M.CMD_FLAGS.f.plane.get(flags)]
            d[x], d[y] = _s32(c["CMD_END0"]), _s32(c["CMD_END1"])
        return d

    def held(self):
        if self.profile:
            return bool(self.regs[M.PROF_CTRL.addr] & M.PROF_CTRL.f.hold.mask)
        return self.regs[M.FEED.addr] == 0

    def _start(self):
        if self.current is None and self.fifo:
            self.current = [self.fifo.popleft(), self.cmd_clocks]

    def advance(self, clocks):
        for _ in range(clocks):
            self.time += 1
            if self.regs[M.WDOG_PERIOD.addr] and not self.events & _ev("wdog"):
                self.wdog_left -= 1
                if self.wdog_left < 0:
                    self.events |= _ev("wdog")
                    self.fifo.clear()
                    self.current = None
            if self.current is None or self.held():
                continue
            self.current[1] -= 1
            if self.current[1] <= 0:
                for i, d in enumerate(self.displacement(self.current[0])):
                    self.pos[i] += d
                self.completed += 1
                self.events |= _ev("done")
                self.current = None
                self._start()
            if len(self.fifo) <= self.regs[M.FIFO_LOW.addr]:
                self.events |= _ev("low_water")
