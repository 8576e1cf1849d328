"""`hwinterp-host run`'s outputs in the formats `hwinterp gcode` writes
(tb/gcode/part_program.cpp): the moves CSV's columns, and the JSON report's
keys where they mean the same on a board (docs/host.md lists them), with
the board's own figures under "board".

Moves CSV: move,line,kind,x_mm,y_mm,z_mm,a_deg,<axis>_steps...,commands,
chords,programmed_s,feed_words_s,max_contour_mm. A move's <axis>_steps is
its lattice end: the sum of its commands' displacements and all before
(the board steps each command exactly; the run's final snapshot checks the
whole). max_contour_mm stays empty: the board reports no visited points.
"""
from __future__ import annotations

import json
from typing import IO

from .board import BoardId
from .program import Program
from .run import RunResult

AXIS_NAMES = "xyzabc"
# The `hwinterp gcode --json` keys the plan gives (the soc-writes file's "totals").
TOTALS = ("moves", "traverses", "feeds", "arcs", "commands", "line_commands", "arc_commands",
          "chord_arcs", "chords", "split_arcs", "programmed_time_s", "feed_word_time_s")
PROFILE_KEYS = ("q", "len", "level_speed", "max_level", "accel", "jerk", "window")


def num(v) -> str:
    """A number as C++'s ostream writes a double by default (%g, 6 digits)."""
    if isinstance(v, int):
        return str(v)
    return f"{v:g}"


def moves_csv_header(axes: int) -> str:
    return ("move,line,kind,x_mm,y_mm,z_mm,a_deg"
            + "".join(f",{AXIS_NAMES[i]}_steps" for i in range(axes))
            + ",commands,chords,programmed_s,feed_words_s,max_contour_mm\n")


def write_moves_csv(f: IO[str], prog: Program, complete: bool) -> int:
    """The header, and a row per move when the run completed (an aborted or
    failed run: the header only). The rows written."""
    f.write(moves_csv_header(prog.axes))
    if not complete:
        return 0
    for m in prog.moves:
        f.write(",".join([str(m.move), str(m.line), m.kind] + [num(x) for x in m.end_mm[:4]]
                         + [str(x) for x in m.end_steps]
                         + [str(m.commands), str(m.chords), num(m.programmed_s),
                            num(m.feed_words_s), ""]) + "\n")
    return len(prog.moves)


def report(prog: Program, ident: BoardId, res: RunResult, uri, link_counts, transport_counts,
           extra: dict | None = None) -> dict:
    j = {"program": prog.raw.get("program", ""), "canon": prog.raw.get("canon", False),
         "variant": prog.raw.get("variant", ""), "feed_mode": prog.raw.get("feed_mode", "")}
    for k in TOTALS:
        if k in prog.totals:
            j[k] = prog.totals[k]
    j["clock_hz"] = prog.clock_hz
    j["end_position"] = res.moved if res.moved is not None else []
    j["expected_end_position"] = prog.end
    prof = {"kind": prog.profile.get("kind", "off")}
    if prog.profiled:
        for k in PROFILE_KEYS:
            prof[k] = prog.profile.get(k)
    j["profile"] = prof
    clocks = res.time1 - res.time0
    board = {
        "uri": str(uri),
        "link": "udp" if str(uri).startswith("udp:") else "serial",
        "id": ident.to_json(),
        "completed": res.completed,
        "aborted": res.aborted,
        "failure": res.failure,
        "pushed": res.pushed,
        "packets": res.packets,
        "refills": res.refills,
        "full_polls": res.full_polls,
        "clocks": clocks,
        "time_s": clocks / prog.clock_hz if prog.clock_hz else 0.0,
        "start_position": res.start.pos if res.start else [],
        "final_position": res.end.pos if res.end else [],
        "events": res.events,
        "holds": res.holds,
        "overrides": [{"at_s": t, "percent": p} for t, p in res.overrides],
        "guard": {k: res.guard_end.get(k, 0) - res.guard_start.get(k, 0)
                  for k in ("accepted", "stale", "dropped", "errors")} if res.guard_end else {},
        "link_counts": dict(vars(link_counts)),
        "transport_counts": dict(vars(transport_counts)),
    }
    if extra:
        board.update(extra)
    j["board"] = board
    j["passed"] = res.passed
    return j


def write_json(path: str, j: dict) -> None:
    with open(path, "w") as f:
        json.dump(j, f, indent=2)
        f.write("\n")

