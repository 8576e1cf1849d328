"""`hwinterp-host run`: a planned part program (program.Program) streamed to
a board (docs/host.md).

1. The board is checked against the plan before anything moves
   (check_board): ID_MAGIC, the major version, axes, every width, ID_CLOCK
   against the machine's clock, the profile and its widths when the plan
   has one. A mismatch is bad input (exit 2), named in one line.
2. Set-up, one guarded packet: the step timing, FIFO_LOW, the feed (FEED
   full without the profile; PROF_Q, PROF_LEN and PROF_CTRL with it), every
   EVENTS bit cleared, WDOG_PERIOD (which also kicks), and a snapshot of the
   start position.
3. Streaming: one packet in flight; every packet kicks the watchdog and
   reads FIFO_LEVEL, EVENTS, STATUS and TIME. When the FIFO's level is at
   most FIFO_LOW the host refills it: as many commands as FIFO_LEVEL.room
   allows (never a push without room) and as fit a packet's 254 stream
   words, packet after packet until the room or the program is used up;
   between refills it polls. Feed hold, override and abort from the keyboard
   and from signals go into the next packet. A position snapshot rides along
   every so often for the progress line.
4. The end: the FIFO drains and the core goes idle (STATUS.busy,
   fifo_empty, prof_busy all clear), a final snapshot, the watchdog off;
   the run passed when the position moved by exactly the program's lattice
   end, no EVENTS overflow/refused/wdog/estop was set and the guard counted
   no bus error.
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Callable, List, Optional, Tuple

from .board import Board, BoardId, Snapshot, Stager, bit, fields
from .gen.regs import link as G
from .gen.regs import motion as M
from .link import MAX_STREAM, LinkDead, LinkError, chunks_of
from .program import Program

# EVENTS bits that end a run: a command not taken, or the motion stopped.
FATAL_EVENTS = ("overflow", "refused", "wdog", "estop")
OVR_UNITY = M.PROF_CTRL.f.ovr.reset          # 128: 100 %
OVR_MAX = 2 * OVR_UNITY                      # 200 %
STEP_REGS = (("step_len", M.STEP_LEN), ("step_space", M.STEP_SPACE),
             ("dir_setup", M.DIR_SETUP), ("dir_hold", M.DIR_HOLD))


class BoardMismatch(ValueError):
    """The board is not the one the program was planned for (exit 2)."""


def check_board(ident: BoardId, prog: Program, uri) -> None:
    """BoardMismatch naming the first value that differs."""
    why = ident.problem()
    if why:
        raise BoardMismatch(f"{uri}: {why}")
    w = prog.widths
    pairs = [("ID_BUILD.axes", ident.axes, w.get("axes", prog.axes), "axes"),
             ("ID_WIDTHS.acc_w", ident.acc_w, w["acc_w"], "ACC_W"),
             ("ID_WIDTHS.coord_w", ident.coord_w, w["coord_w"], "COORD_W"),
             ("ID_WIDTHS.ops_w", ident.ops_w, w["ops_w"], "OPS_W"),
             ("ID_WIDTHS.pos_w", ident.pos_w, w["pos_w"], "POS_W"),
             ("ID_WIDTHS2.tim_w", ident.tim_w, w["tim_w"], "TIM_W"),
             ("ID_WIDTHS2.feed_w", ident.feed_w, w["feed_w"], "FEED_W")]
    variant = prog.raw.get("variant", "?")
    for reg, have, want, name in pairs:
        if have != want:
            raise BoardMismatch(f"{uri}: {reg} {have}, the program was compiled for {want} "
                                f"({name} of {variant}; pick the variant with --variant)")
    if ident.clock_hz != prog.clock_hz:
        raise BoardMismatch(f"{uri}: ID_CLOCK {ident.clock_hz} Hz, the machine file says clock_hz "
                            f"{prog.clock_hz}")
    if prog.profiled:
        if not ident.profile:
            raise BoardMismatch(f"{uri}: ID_BUILD.profile 0: the board has no feed profile "
                                f"(--profile {prog.profile['kind']} needs one; give --profile off)")
        for name in ("spd_w", "tick_w", "len_w", "lvl_w"):
            if getattr(ident, name) != prog.profile[name]:
                raise BoardMismatch(f"{uri}: ID_PROFILE.{name} {getattr(ident, name)}, the profile "
                                    f"was planned for {prog.profile[name]}")


@dataclass
class RunOptions:
    watchdog_ms: float = 500.0     # WDOG_PERIOD; 0: off
    fifo_low: Optional[int] = None  # FIFO_LOW; None: half the FIFO's depth
    poll_s: float = 0.005          # between polls while the FIFO is above its low-water mark
    snapshot_s: float = 1.0        # a position snapshot for the progress this often (0: never)
    stop_timeout_s: float = 5.0    # abort with the profile: the wait for rest before CTRL.abort


@dataclass
class RunResult:
    passed: bool = False
    completed: bool = False        # every command pushed and the core idle
    aborted: bool = False
    failure: str = ""
    pushed: int = 0
    packets: int = 0
    refills: int = 0
    full_polls: int = 0            # polls that found no room
    start: Optional[Snapshot] = None
    end: Optional[Snapshot] = None
    moved: Optional[List[int]] = None
    time0: int = 0
    time1: int = 0
    events: int = 0
    guard_start: dict = field(default_factory=dict)
    guard_end: dict = field(default_factory=dict)
    holds: int = 0
    overrides: List[Tuple[float, int]] = field(default_factory=list)  # (seconds, percent)


class Controls:
    """What the keyboard and the signals ask for, polled by the run."""

    def __init__(self):
        self.abort = False
        self.abort_why = ""
        self.toggle_hold = 0
        self.ovr_steps = 0      # +1 / -1 per key

    def request_abort(self, why: str):
        if not self.abort:
            self.abort, self.abort_why = True, why


def wrap_diff(a: int, b: int, bits: int) -> int:
    """a - b on a POS_W-bit wrapping counter, as a signed value."""
    m = 1 << bits
    d = (a - b) % m
    return d - m if d >= m // 2 else d


class Runner:
    def __init__(self, board: Board, prog: Program, opts: RunOptions,
                 controls: Optional[Controls] = None,
                 progress: Optional[Callable[[dict], None]] = None,
                 poll_input: Optional[Callable[[float], None]] = None,
                 clock=time.monotonic):
        self.b, self.p, self.o = board, prog, opts
        self.ctl = controls or Controls()
        self.progress = progress or (lambda info: None)
        # waits up to s seconds (reading the keyboard meanwhile)
        self.wait = poll_input or time.sleep
        self.clock = clock
        self.stager = Stager(prog.axes, prog.profiled)
        depth = board.id.fifo_depth
        self.fifo_low = opts.fifo_low if opts.fifo_low is not None else max(1, depth // 2)
        self.full_feed = 1 << prog.widths["feed_w"]
        self.res = RunResult()
        self.hold = False
        self.ovr = OVR_UNITY
        self.move_of = prog.move_of_command()
        self.move_last = [m.first_command + m.commands - 1 for m in prog.moves]

    # -- the pieces of a packet
    def base_reads(self) -> List[int]:
        return [M.FIFO_LEVEL.addr, M.EVENTS.addr, M.STATUS.addr, M.TIME_LO.addr, M.TIME_HI.addr]

    def decode_base(self, w: List[int]) -> dict:
        lvl = fields(M.FIFO_LEVEL, w[0])
        return {"fill": lvl["fill"], "room": lvl["room"], "events": w[1], "status": w[2],
                "time": w[3] | w[4] << 32}

    def setup_writes(self) -> List[Tuple[int, int]]:
        t = self.p.timing
        out = [(r.addr, int(t[k])) for k, r in STEP_REGS]
        out.append((M.FIFO_LOW.addr, M.FIFO_LOW.f.mark.put(self.fifo_low)))
        if self.p.profiled:
            q = int(self.p.profile["q"])
            out += [(M.PROF_Q.word_addrs[0], q & 0xFFFFFFFF), (M.PROF_Q.word_addrs[1], q >> 32),
                    (M.PROF_LEN.addr, int(self.p.profile["len"]))]
        out += self.b.hold_writes(False, OVR_UNITY, self.full_feed)
        out.append((M.EVENTS.addr, sum(f.mask for f in M.EVENTS.fields)))
        period = int(round(self.o.watchdog_ms * 1e-3 * self.p.clock_hz))
        out.append((M.WDOG_PERIOD.addr, min(period, 0xFFFFFFFF)))
        return out

    def fatal(self, events: int) -> List[str]:
        return [n for n in FATAL_EVENTS if events & bit(M.EVENTS, n)]

    def guard(self) -> dict:
        w = self.b.read([r.addr for r in (G.ACCEPTED, G.STALE, G.DROPPED, G.ERRORS)])
        return dict(zip(("accepted", "stale", "dropped", "errors"), w))

    def moves_done(self, taken: int) -> int:
        """Moves whose commands have all left the FIFO (taken by the core)."""
        # moves with no command count as done once the commands before them are
        lo, hi = 0, len(self.move_last)
        while lo < hi:
            mid = (lo + hi) // 2
            if self.move_last[mid] < taken:
                lo = mid + 1
            else:
                hi = mid
        return lo

    # -- controls
    def control_writes(self) -> List[Tuple[int, int]]:
        changed = False
        if self.ctl.toggle_hold:
            if self.ctl.toggle_hold % 2:
                self.hold = not self.hold
                self.res.holds += int(self.hold)
                changed = True
            self.ctl.toggle_hold = 0
        if self.ctl.ovr_steps:
            if self.p.profiled:
                pct = round(self.ovr * 100 / OVR_UNITY) + 10 * self.ctl.ovr_steps
                pct = max(0, min(200, pct))
                ovr = min(OVR_MAX, round(pct * OVR_UNITY / 100))
                if ovr != self.ovr:
                    self.ovr = ovr
                    changed = True
                    self.res.overrides.append((self.clock() - self.t_start, pct))
            self.ctl.ovr_steps = 0
        return self.b.hold_writes(self.hold, self.ovr, self.full_feed) if changed else []

    # -- the run
    def run(self) -> RunResult:
        res = self.res
        self.t_start = self.clock()
        b, p = self.b, self.p
        try:
            res.guard_start = self.guard()
            # the board must be at rest: an earlier run still moving is not ours to join
            st = b.read([M.STATUS.addr, M.FIFO_LEVEL.addr])
            s = fields(M.STATUS, st[0])
            if s["busy"] or not s["fifo_empty"] or s["prof_busy"]:
                res.failure = (f"{b.s.uri}: the board is busy (STATUS 0x{st[0]:x}): wait for it, "
                               f"or stop it with hwinterp-host abort {b.s.uri}")
                return res
            words = b.packet(self.setup_writes() + b.snap_arm_writes(),
                             self.base_reads() + b.snap_reads())
            base = self.decode_base(words)
            res.time0 = base["time"]
            snap = b.snap_decode(words[len(self.base_reads()):])
            res.start = snap or b.snapshot()
            self._stream(base)
        except LinkDead as e:
            res.failure = (f"{e}; the board's watchdog ({self.o.watchdog_ms:g} ms) stops the motion"
                           if self.o.watchdog_ms else str(e))
            return res
        except LinkError as e:
            res.failure = str(e)
            return res
        res.passed = res.completed and not res.failure and not res.aborted
        return res

    def _stream(self, base: dict) -> None:
        res, b, p = self.res, self.b, self.p
        n_cmds = len(p.commands)
        i = 0                 # next command to push
        refilling = True
        snap_pending = False
        last_snap_t = self.clock()
        pos = list(res.start.pos)
        kick = b.kick_writes()
        while True:
            if self.ctl.abort:
                self._abort(self.ctl.abort_why)
                return
            writes = list(kick) + self.control_writes()
            stream = chunks_of(writes)
            reads = self.base_reads()
            want_snap = (self.o.snapshot_s > 0 and self.clock() - last_snap_t >= self.o.snapshot_s)
            if want_snap and not snap_pending:
                stream += chunks_of(b.snap_arm_writes())
                snap_pending = True
                last_snap_t = self.clock()
            if snap_pending:
                reads = reads + b.snap_reads()
            # the refill: commands while the room and the packet allow
            credit = base["room"]
            batch = []
            if refilling:
                while i + len(batch) < n_cmds and len(batch) < credit:
                    cmd = p.commands[i + len(batch)]
                    cw = chunks_of(self.stager.writes(cmd))
                    if len(stream) + len(cw) > MAX_STREAM:
                        break
                    stream += cw
                    self.stager.commit(cmd)   # the packet runs once, or the link is dead
                    batch.append(cmd)
            words = self.b.s.transact(stream, reads)
            res.packets += 1
            if batch:
                res.refills += 1
            i += len(batch)
            res.pushed = i
            base = self.decode_base(words)
            if snap_pending:
                snap = b.snap_decode(words[len(self.base_reads()):])
                if snap is not None:
                    pos, snap_pending = snap.pos, False
            res.time1 = base["time"]
            res.events = base["events"]
            bad = self.fatal(base["events"])
            if bad:
                res.failure = (f"{b.s.uri}: {' and '.join('EVENTS.' + x for x in bad)} set after {i} of {n_cmds} "
                               f"commands pushed" + self._event_note(bad))
                if "wdog" not in bad and "estop" not in bad:
                    self._abort(res.failure, failed=True)
                return
            taken = i - base["fill"]
            st = fields(M.STATUS, base["status"])
            idle = not st["busy"] and st["fifo_empty"] and not st["prof_busy"]
            self.progress({"moves": self.moves_done(taken) if i < n_cmds or not idle else len(p.moves),
                           "total": len(p.moves), "pushed": i, "commands": n_cmds,
                           "fill": base["fill"], "time_s": (base["time"] - res.time0) / p.clock_hz,
                           "pos": [wrap_diff(a, s0, b.id.pos_w) for a, s0 in zip(pos, res.start.pos)],
                           "hold": self.hold, "ovr_pct": round(self.ovr * 100 / OVR_UNITY),
                           "profile": p.profiled, "final": False})
            if i >= n_cmds and idle and not snap_pending:
                break
            # refill again at once while there is room, else wait for the low-water mark
            if i < n_cmds:
                if base["room"] == 0:
                    res.full_polls += 1
                refilling = base["room"] > 0 and (
                    (refilling and len(batch) > 0) or base["fill"] <= self.fifo_low)
            if not (refilling and i < n_cmds):
                self.wait(self.o.poll_s)
        # the end: the final position, the watchdog off
        words = b.packet(list(kick) + b.snap_arm_writes(), b.snap_reads())
        snap = b.snap_decode(words) or b.snapshot(kick=kick)
        res.end = snap
        res.moved = [wrap_diff(a, s0, b.id.pos_w) for a, s0 in zip(snap.pos, res.start.pos)]
        off = b.packet([(M.WDOG_PERIOD.addr, 0)], [M.EVENTS.addr])
        res.events = off[0]
        res.guard_end = self.guard()
        res.completed = True
        bad = self.fatal(res.events)
        if bad:
            res.failure = f"{b.s.uri}: {' and '.join('EVENTS.' + x for x in bad)} set at the end"
        elif res.moved != p.end:
            res.failure = (f"{b.s.uri}: the axes moved {res.moved} steps, the program's lattice "
                           f"end is {p.end}")
        elif res.guard_end["errors"] != res.guard_start["errors"]:
            res.failure = (f"{b.s.uri}: the guard counted "
                           f"{res.guard_end['errors'] - res.guard_start['errors']} bus errors")
        self.progress({"moves": len(p.moves), "total": len(p.moves), "pushed": i,
                       "commands": n_cmds, "fill": 0, "time_s": (res.time1 - res.time0) / p.clock_hz,
                       "pos": res.moved, "hold": self.hold,
                       "ovr_pct": round(self.ovr * 100 / OVR_UNITY), "profile": p.profiled,
                       "final": True})

    @staticmethod
    def _event_note(bad: List[str]) -> str:
        if "wdog" in bad:
            return " (the watchdog bit: packets came further apart than its period)"
        if "estop" in bad:
            return " (estop_i)"
        return " (a command was not taken)"

    def _abort(self, why: str, failed: bool = False) -> None:
        """With the profile: a feed hold first (a controlled stop along the
        path), CTRL.abort_motion once the speed is 0 (or after
        stop_timeout_s); without it CTRL.abort_motion at once. Then the
        watchdog off."""
        b, res = self.b, self.res
        res.aborted = True
        if not failed:
            res.failure = why
        kick = b.kick_writes()
        if self.p.profiled:
            b.packet(kick + b.hold_writes(True, self.ovr, self.full_feed))
            end = self.clock() + self.o.stop_timeout_s
            while self.clock() < end:
                w = b.packet(kick, list(M.PROF_SPEED.word_addrs) + list(M.PROF_SPEED.word_addrs))
                if w[0] == w[2] == 0 and w[1] == w[3] == 0:
                    break
                self.wait(self.o.poll_s)
        b.packet(kick + [(M.CTRL.addr, bit(M.CTRL, "abort_motion"))])
        w = b.packet(b.hold_writes(False, self.ovr, self.full_feed) + [(M.WDOG_PERIOD.addr, 0)],
                     [M.EVENTS.addr])
        res.events = w[0]
        self.stager.forget()
