"""A part program as `hwinterp gcode --soc-writes FILE --plan-only` compiles
it (tb/gcode/soc_writes.h): the board's staging writes per command, the
moves they belong to, the widths, clock, step timing and feed profile it
was planned for. The planning is hwinterp's (plan() runs it); this module
only reads its file.

Each command is rebuilt here as its full set of staging registers (the
file gives only the registers that change from the command before, from
the reset values), so that the host's own stager (board.Stager) can write
what differs from what the board holds, whatever an earlier run left there.
A command's displacement on the lattice: a line's CMD_DELTA per axis; an
arc's CMD_END0/1 on its plane's two axes (XY: X, Y; ZX: Z, X; YZ: Y, Z)
and CMD_DELTA on the others. A move's lattice end is the sum of the
displacements of its commands and all before (read() checks it against
the file's end_steps).
"""
from __future__ import annotations

import json
import os
import shutil
import subprocess
import tempfile
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Sequence, Tuple

from .gen.regs import motion as M


class ProgramError(ValueError):
    """A program, a machine file or a soc-writes file that cannot be used (exit 2)."""


# The staging registers of the command window, in the order the stager
# writes them (address order; CMD_AT is never written: no timed commands).
STAGING = tuple(r.name for r in M.regs
                if r.name.startswith("CMD_") and r.name not in ("CMD_PUSH", "CMD_AT"))
PROFILE_STAGING = tuple(n for n in STAGING if n.startswith("CMD_MV_"))
FLAGS = M.CMD_FLAGS.f
# Engine x, y of each plane (CMD_FLAGS.plane): XY, ZX, YZ.
PLANE_AXES = ((0, 1), (2, 0), (1, 2))


def s32(v: int) -> int:
    v &= 0xFFFFFFFF
    return v - (1 << 32) if v >> 31 else v


@dataclass
class Move:
    move: int
    line: int
    kind: str
    end_mm: List[float]
    end_steps: List[int]
    first_command: int
    commands: int
    chords: int
    programmed_s: float
    feed_words_s: float


@dataclass
class Program:
    path: str
    raw: dict
    axes: int
    widths: Dict[str, int]
    clock_hz: int
    timing: Dict[str, int]
    profile: Dict[str, object]
    commands: List[Tuple[int, ...]]     # the full staging values, in STAGING order
    moves: List[Move]
    end: List[int]
    totals: Dict[str, object] = field(default_factory=dict)

    @property
    def profiled(self) -> bool:
        return self.profile.get("kind", "off") != "off"

    def displacement(self, cmd: Sequence[int]) -> List[int]:
        return displacement(cmd, self.axes)

    def move_of_command(self) -> List[int]:
        """For each command, the index into moves of the move it belongs to."""
        out = []
        for i, m in enumerate(self.moves):
            out += [i] * m.commands
        return out


def displacement(cmd: Sequence[int], axes: int) -> List[int]:
    v = dict(zip(STAGING, cmd))
    d = [s32(v[f"CMD_DELTA{i}"]) for i in range(axes)]
    flags = v["CMD_FLAGS"]
    if FLAGS.arc.get(flags):
        x, y = PLANE_AXES[FLAGS.plane.get(flags) % 3]
        if x < axes:
            d[x] = s32(v["CMD_END0"])
        if y < axes:
            d[y] = s32(v["CMD_END1"])
    return d


def _need(j: dict, key: str, path: str):
    if key not in j:
        raise ProgramError(f"{path}: no '{key}': not a soc-writes file of this hwinterp "
                           "(hwinterp gcode --soc-writes FILE --plan-only)")
    return j[key]


def read(path: str) -> Program:
    """The soc-writes file; ProgramError naming the file and what is wrong."""
    try:
        with open(path) as f:
            j = json.load(f)
    except OSError as e:
        raise ProgramError(f"{path}: {e.strerror}") from None
    except json.JSONDecodeError as e:
        raise ProgramError(f"{path}: not JSON ({e.msg} at line {e.lineno})") from None
    for key in ("axes", "widths", "clock_hz", "timing", "profile", "commands", "moves", "end"):
        _need(j, key, path)
    axes = int(j["axes"])
    staged = {n: 0 for n in STAGING}   # the reset values the C++ stager starts from
    commands = []
    for i, writes in enumerate(j["commands"]):
        pushed = False
        for reg, value in writes:
            if reg == "CMD_PUSH":
                pushed = True
                continue
            if reg not in staged:
                raise ProgramError(f"{path}: command {i} writes {reg}, not a staging register")
            if pushed:
                raise ProgramError(f"{path}: command {i} writes {reg} after CMD_PUSH")
            staged[reg] = int(value) & 0xFFFFFFFF
        if not pushed:
            raise ProgramError(f"{path}: command {i} has no CMD_PUSH")
        commands.append(tuple(staged[n] for n in STAGING))
    moves = [Move(move=int(m["move"]), line=int(m["line"]), kind=str(m["kind"]),
                  end_mm=[float(x) for x in m["end_mm"]], end_steps=[int(x) for x in m["end_steps"]],
                  first_command=int(m["first_command"]), commands=int(m["commands"]),
                  chords=int(m["chords"]), programmed_s=float(m["programmed_s"]),
                  feed_words_s=float(m["feed_words_s"])) for m in j["moves"]]
    prog = Program(path=path, raw=j, axes=axes, widths={k: int(v) for k, v in j["widths"].items()},
                   clock_hz=int(j["clock_hz"]), timing={k: int(v) for k, v in j["timing"].items()},
                   profile=dict(j["profile"]), commands=commands, moves=moves,
                   end=[int(x) for x in j["end"]], totals=dict(j.get("totals", {})))
    check(prog)
    return prog


def check(prog: Program) -> None:
    """The moves cover the commands in order, and each move's lattice end is
    the sum of the displacements of the commands up to its last."""
    at = [0] * prog.axes
    nxt = 0
    for m in prog.moves:
        if m.first_command != nxt:
            raise ProgramError(f"{prog.path}: move {m.move} starts at command {m.first_command}, "
                               f"not {nxt}")
        for c in prog.commands[m.first_command:m.first_command + m.commands]:
            at = [a + d for a, d in zip(at, prog.displacement(c))]
        nxt += m.commands
        if m.end_steps != at:
            raise ProgramError(f"{prog.path}: move {m.move} (line {m.line}) ends at {m.end_steps}, "
                               f"its commands at {at}")
    if nxt != len(prog.commands):
        raise ProgramError(f"{prog.path}: the moves hold {nxt} commands, the file {len(prog.commands)}")
    if at != prog.end:
        raise ProgramError(f"{prog.path}: the commands end at {at}, the file says {prog.end}")


def find_hwinterp(given: Optional[str] = None) -> str:
    """--hwinterp PATH, else $HWINTERP, else the repository's build/tb/hwinterp
    (this package sits in sw/host of the repository), else `hwinterp` on PATH."""
    if given:
        cands = [given]
    elif os.environ.get("HWINTERP"):
        cands = [os.environ["HWINTERP"]]
    else:
        here = os.path.dirname(os.path.abspath(__file__))
        repo = os.path.dirname(os.path.dirname(os.path.dirname(here)))
        build = os.environ.get("HWINTERP_BUILD_DIR", os.path.join(repo, "build"))
        cands = [os.path.join(build, "tb", "hwinterp")]
        on_path = shutil.which("hwinterp")
        if on_path:
            cands.append(on_path)
    for c in cands:
        if os.path.isfile(c) and os.access(c, os.X_OK):
            return c
    raise ProgramError(f"no hwinterp executable at {cands[0]} (give --hwinterp PATH or set HWINTERP)")


def plan(hwinterp: str, program: str, machine: Optional[str], profile: Optional[str] = None,
         variant: Optional[str] = None, feed: Optional[str] = None,
         extra: Sequence[str] = (), canon: bool = False) -> Program:
    """Runs `hwinterp gcode ... --soc-writes TMP --plan-only` and reads the
    file. Its bad-input message (exit 2) becomes a ProgramError."""
    with tempfile.TemporaryDirectory(prefix="hwinterp_host_") as tmp:
        out = os.path.join(tmp, "soc_writes.json")
        cmd = [hwinterp, "gcode"] + (["--canon", program] if canon else [program])
        if machine:
            cmd += ["--machine", machine]
        if profile:
            cmd += ["--profile", profile]
        if variant:
            cmd += ["--variant", variant]
        if feed:
            cmd += ["--feed", feed]
        cmd += list(extra) + ["--soc-writes", out, "--plan-only"]
        try:
            r = subprocess.run(cmd, capture_output=True, text=True)
        except OSError as e:
            raise ProgramError(f"{hwinterp}: {e.strerror}") from None
        if r.returncode != 0:
            lines = [l for l in (r.stderr + r.stdout).splitlines() if l.strip()]
            msg = lines[-1] if lines else f"exit {r.returncode}"
            if r.returncode == 2:
                raise ProgramError(msg)
            raise RuntimeError(f"hwinterp gcode --plan-only failed (exit {r.returncode}): {msg}")
        return read(out)
