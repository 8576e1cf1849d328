"""motion_soc on a board, over the guarded link (docs/soc.md's bring-up,
docs/host.md). Every address and field comes from the generated map
(gen/regs.py).

- BoardId: the ID registers decoded (read with plain reads).
- Stager: the command window's staging registers as the board holds them;
  a command's writes are the registers that differ (all of them the first
  time: what an earlier run left there is not known), then CMD_PUSH.
- Board: status, snapshot, abort, watchdog, feed hold and override, as
  guarded packets (every packet also kicks the watchdog once it runs).
"""
from __future__ import annotations

import time
from dataclasses import asdict, dataclass
from typing import Dict, List, Optional, Sequence, Tuple

from .gen.regs import link as G
from .gen.regs import motion as M
from .link import Session, chunks_of
from .program import PROFILE_STAGING, STAGING

MAGIC = M.ID_MAGIC.f.magic.reset
MAJOR = M.ID_VERSION.f.major.reset
ALL_EVENTS = sum(f.mask for f in M.EVENTS.fields)
ID_REGS = (M.ID_MAGIC, M.ID_VERSION, M.ID_BUILD, M.ID_WIDTHS, M.ID_WIDTHS2, M.ID_CLOCK,
           M.ID_PROFILE)
GUARD_COUNTERS = (G.ACCEPTED, G.STALE, G.DROPPED, G.ERRORS)
CORES = {1: "motion_top"}
BUSES = {0: "AXI4-Lite", 1: "Wishbone"}
STEP_TYPES = ("step/dir", "up/down", "quadrature")


def fields(reg, word: int) -> Dict[str, int]:
    """Every field of a register's value, by name."""
    return {f.name: f.get(word) for f in reg.fields}


def bit(reg, name: str) -> int:
    return getattr(reg.f, name).mask


def s64(v: int) -> int:
    v &= (1 << 64) - 1
    return v - (1 << 64) if v >> 63 else v


@dataclass
class BoardId:
    magic: int
    major: int
    minor: int
    axes: int
    core: int
    bus: int
    profile: bool
    step_types: int
    fifo_depth: int
    acc_w: int
    coord_w: int
    ops_w: int
    pos_w: int
    tim_w: int
    feed_w: int
    clock_hz: int
    spd_w: int
    tick_w: int
    len_w: int
    lvl_w: int

    @classmethod
    def from_words(cls, words: Sequence[int]) -> "BoardId":
        w = dict(zip((r.name for r in ID_REGS), words))
        b, wd, wd2, p = (fields(M.ID_BUILD, w["ID_BUILD"]), fields(M.ID_WIDTHS, w["ID_WIDTHS"]),
                         fields(M.ID_WIDTHS2, w["ID_WIDTHS2"]), fields(M.ID_PROFILE, w["ID_PROFILE"]))
        v = fields(M.ID_VERSION, w["ID_VERSION"])
        return cls(magic=w["ID_MAGIC"], major=v["major"], minor=v["minor"], axes=b["axes"],
                   core=b["core"], bus=b["bus"], profile=bool(b["profile"]),
                   step_types=b["step_types"], fifo_depth=b["fifo_depth"], acc_w=wd["acc_w"],
                   coord_w=wd["coord_w"], ops_w=wd["ops_w"], pos_w=wd["pos_w"],
                   tim_w=wd2["tim_w"], feed_w=wd2["feed_w"], clock_hz=fields(M.ID_CLOCK, w["ID_CLOCK"])["hz"],
                   spd_w=p["spd_w"], tick_w=p["tick_w"], len_w=p["len_w"], lvl_w=p["lvl_w"])

    @property
    def is_motion_soc(self) -> bool:
        return self.magic == MAGIC

    def problem(self) -> Optional[str]:
        """Why the host cannot drive this board at all (None: it can)."""
        if self.magic != MAGIC:
            return f"ID_MAGIC 0x{self.magic:08x}, not 0x{MAGIC:08x} (\"HMS1\"): not a hwinterp motion_soc"
        if self.major != MAJOR:
            return f"ID_VERSION {self.major}.{self.minor}: this host speaks major version {MAJOR}"
        return None

    def step_type_names(self) -> List[str]:
        return [n for i, n in enumerate(STEP_TYPES) if self.step_types >> i & 1]

    def to_json(self) -> dict:
        d = asdict(self)
        d["core_name"] = CORES.get(self.core, f"core {self.core}")
        d["bus_name"] = BUSES.get(self.bus, f"bus {self.bus}")
        d["step_type_names"] = self.step_type_names()
        return d


def read_id(session: Session) -> BoardId:
    return BoardId.from_words(session.read([r.addr for r in ID_REGS]))


class Stager:
    """The staging registers as the board holds them (None: not known)."""

    def __init__(self, axes: int, profile: bool):
        names = [n for n in STAGING if not n.startswith("CMD_DELTA") or int(n[9:]) < axes]
        if not profile:
            names = [n for n in names if n not in PROFILE_STAGING]
        self.names = names
        self._index = [STAGING.index(n) for n in names]
        self._addr = [M.reg(n).addr for n in names]
        self.staged: List[Optional[int]] = [None] * len(names)

    def writes(self, cmd: Sequence[int]) -> List[Tuple[int, int]]:
        """The command's writes (byte address, value): what differs, then CMD_PUSH."""
        out = []
        for k, (i, a) in enumerate(zip(self._index, self._addr)):
            if self.staged[k] != cmd[i]:
                out.append((a, cmd[i]))
        out.append((M.CMD_PUSH.addr, M.CMD_PUSH.f.push.put(1)))
        return out

    def commit(self, cmd: Sequence[int]) -> None:
        """The board took the writes: it holds the command."""
        for k, i in enumerate(self._index):
            self.staged[k] = cmd[i]

    def forget(self) -> None:
        self.staged = [None] * len(self.names)


@dataclass
class Snapshot:
    time: int
    pos: List[int]


class Board:
    """motion_soc's operations as guarded packets on a session."""

    def __init__(self, session: Session, ident: BoardId):
        self.s = session
        self.id = ident
        self.axes = ident.axes

    # -- packets
    def packet(self, writes: Sequence[Tuple[int, int]] = (), reads: Sequence[int] = (),
               stream: Sequence[int] = ()) -> List[int]:
        """One guarded packet: `stream` words, then `writes` as chunks; the
        words read at `reads`."""
        return self.s.transact(list(stream) + chunks_of(writes), reads)

    def read(self, addrs: Sequence[int]) -> List[int]:
        return self.s.read(addrs)

    # -- decoded reads
    @staticmethod
    def status_reads(axes: int) -> List[int]:
        return ([M.STATUS.addr, M.EVENTS.addr, M.FIFO_LEVEL.addr, M.FIFO_LOW.addr, M.TIME_LO.addr,
                 M.TIME_HI.addr, M.WDOG_PERIOD.addr, M.WDOG_LEFT.addr, M.FEED.addr, M.PROF_CTRL.addr]
                + [r.addr for r in GUARD_COUNTERS])

    def status(self) -> dict:
        """STATUS, EVENTS, FIFO level, time, watchdog, feed and the guard's
        counters (plain reads: nothing changes on the board)."""
        w = self.read(self.status_reads(self.axes))
        names = ["STATUS", "EVENTS", "FIFO_LEVEL", "FIFO_LOW", "TIME_LO", "TIME_HI", "WDOG_PERIOD",
                 "WDOG_LEFT", "FEED", "PROF_CTRL"] + [r.name for r in GUARD_COUNTERS]
        v = dict(zip(names, w))
        lvl = fields(M.FIFO_LEVEL, v["FIFO_LEVEL"])
        return {
            "status": fields(M.STATUS, v["STATUS"]),
            "events": fields(M.EVENTS, v["EVENTS"]),
            "fifo": {"fill": lvl["fill"], "room": lvl["room"], "low": v["FIFO_LOW"],
                     "depth": self.id.fifo_depth},
            "time": v["TIME_LO"] | v["TIME_HI"] << 32,
            "watchdog": {"period": v["WDOG_PERIOD"], "left": v["WDOG_LEFT"]},
            "feed": v["FEED"],
            "prof_ctrl": fields(M.PROF_CTRL, v["PROF_CTRL"]),
            "guard": {r.name.lower(): v[r.name] for r in GUARD_COUNTERS},
            "raw": {k: v[k] for k in ("STATUS", "EVENTS", "FIFO_LEVEL")},
        }

    # -- snapshot
    def snap_arm_writes(self) -> List[Tuple[int, int]]:
        """Clear EVENTS.snap, SNAP_AT = 0 (passed: taken at once), arm."""
        return ([(M.EVENTS.addr, bit(M.EVENTS, "snap"))]
                + [(a, 0) for a in M.SNAP_AT.word_addrs]
                + [(M.SNAP_CTRL.addr, bit(M.SNAP_CTRL, "arm"))])

    def snap_reads(self) -> List[int]:
        """EVENTS first (its snap bit says the rest are valid), then SNAP_TIME
        and SNAP_POS of each axis."""
        out = [M.EVENTS.addr] + list(M.SNAP_TIME.word_addrs)
        for r in M.SNAP_POS[:self.axes]:
            out += r.word_addrs
        return out

    def snap_decode(self, words: Sequence[int]) -> Optional[Snapshot]:
        if not words[0] & bit(M.EVENTS, "snap"):
            return None
        t = words[1] | words[2] << 32
        pos = [s64(words[3 + 2 * i] | words[4 + 2 * i] << 32) for i in range(self.axes)]
        return Snapshot(t, pos)

    def snapshot(self, timeout_s: float = 2.0, kick: Sequence[Tuple[int, int]] = ()) -> Snapshot:
        """Arms a snapshot at once and waits for EVENTS.snap."""
        words = self.packet(list(kick) + self.snap_arm_writes(), self.snap_reads())
        end = time.monotonic() + timeout_s
        while True:
            snap = self.snap_decode(words)
            if snap is not None:
                return snap
            if time.monotonic() > end:
                raise TimeoutError(f"{self.s.uri}: no snapshot within {timeout_s:.1f} s (EVENTS.snap)")
            time.sleep(0.002)
            words = self.read(self.snap_reads())

    def snapshot_plain(self, timeout_s: float = 2.0) -> Snapshot:
        """A snapshot with writes outside the guard (no SEQ: another host's
        run is not disturbed). Clearing EVENTS.snap and arming again are the
        same when repeated, so a retried packet does no harm."""
        self.s.write_plain(M.EVENTS.addr, [bit(M.EVENTS, "snap")])
        assert M.SNAP_CTRL.addr == M.SNAP_AT.addr + 8, "SNAP_AT and SNAP_CTRL are no longer adjacent"
        words = self.s.write_plain(M.SNAP_AT.addr, [0, 0, bit(M.SNAP_CTRL, "arm")], self.snap_reads())
        end = time.monotonic() + timeout_s
        while True:
            snap = self.snap_decode(words)
            if snap is not None:
                return snap
            if time.monotonic() > end:
                raise TimeoutError(f"{self.s.uri}: no snapshot within {timeout_s:.1f} s (EVENTS.snap)")
            time.sleep(0.002)
            words = self.read(self.snap_reads())

    # -- actions
    def abort(self) -> None:
        self.packet([(M.CTRL.addr, bit(M.CTRL, "abort_motion"))])

    def kick_writes(self) -> List[Tuple[int, int]]:
        return [(M.WDOG_KICK.addr, M.WDOG_KICK.f.kick.put(1))]

    def hold_writes(self, hold: bool, ovr: int, full_feed: int) -> List[Tuple[int, int]]:
        """Feed hold and override: PROF_CTRL with the profile (hold along the
        path, override ovr/128), FEED without (0 holds at once; no override)."""
        if self.id.profile:
            return [(M.PROF_CTRL.addr, M.PROF_CTRL.f.hold.put(int(hold)) | M.PROF_CTRL.f.ovr.put(ovr))]
        return [(M.FEED.addr, 0 if hold else full_feed)]
