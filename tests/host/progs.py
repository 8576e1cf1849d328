"""Soc-writes files made by hand for the run's unit tests (the real ones
come from `hwinterp gcode --soc-writes --plan-only`: test_program.py).
Each command is given as its full staging values; the file holds what a
stager starting from the reset values (0) writes: the registers that
change, in STAGING order, then CMD_PUSH."""
import json

from hwinterp_host.gen.regs import motion as M
from hwinterp_host.program import STAGING


def line(*d, feed=1 << 24):
    c = {f"CMD_DELTA{i}": v & 0xFFFFFFFF for i, v in enumerate(d)}
    c["CMD_FEED"] = feed
    return c


def arc(plane, end, center, ops, slaved=(), ccw=True, feed=1 << 24):
    c = {"CMD_END0": end[0] & 0xFFFFFFFF, "CMD_END1": end[1] & 0xFFFFFFFF,
         "CMD_CENTER0": center[0] & 0xFFFFFFFF, "CMD_CENTER1": center[1] & 0xFFFFFFFF,
         "CMD_OPS": ops, "CMD_FEED": feed,
         "CMD_FLAGS": M.CMD_FLAGS.f.arc.put(1) | M.CMD_FLAGS.f.plane.put(plane) | M.CMD_FLAGS.f.ccw.put(int(ccw))}
    for i, v in slaved:
        c[f"CMD_DELTA{i}"] = v & 0xFFFFFFFF
    return c


def make(moves, axes=3, clock_hz=50_000_000, profile=None, widths=None):
    """moves: list of lists of commands (dicts of the staging values that are
    not 0). Returns the file's JSON."""
    staged = {n: 0 for n in STAGING}
    commands, mv, at, first = [], [], [0] * axes, 0
    for k, cmds in enumerate(moves, 1):
        for c in cmds:
            full = {n: c.get(n, 0) for n in STAGING}
            w = [[n, full[n]] for n in STAGING if full[n] != staged[n]]
            staged = full
            commands.append(w + [["CMD_PUSH", 1]])
            # displacement, independently of the package
            d = [(full[f"CMD_DELTA{i}"] ^ 0x80000000) - 0x80000000 for i in range(axes)]
            if full["CMD_FLAGS"] & 1:
                x, y = [(0, 1), (2, 0), (1, 2)][(full["CMD_FLAGS"] >> 1) & 3]
                d[x] = (full["CMD_END0"] ^ 0x80000000) - 0x80000000
                d[y] = (full["CMD_END1"] ^ 0x80000000) - 0x80000000
            at = [a + b for a, b in zip(at, d)]
        mv.append({"move": k, "line": 10 * k, "kind": "feed", "end_mm": [a / 1000 for a in (at + [0])[:4]],
                   "end_steps": list(at), "first_command": first, "commands": len(cmds), "chords": 0,
                   "programmed_s": 0.5 * k, "feed_words_s": 0.25 * k})
        first += len(cmds)
    w = dict(acc_w=32, coord_w=24, ops_w=28, pos_w=32, tim_w=16, feed_w=24)
    w.update(widths or {})
    return {"program": "hand.ngc", "canon": False, "variant": "motion_top_n3", "feed_mode": "full",
            "axes": axes, "feed_w": w["feed_w"], "widths": dict(axes=axes, **w), "clock_hz": clock_hz,
            "timing": {"step_len": 2, "step_space": 3, "dir_setup": 4, "dir_hold": 5},
            "fifo_level_room_lsb": 16, "profile": profile or {"kind": "off"},
            "commands": commands, "moves": mv,
            "totals": {"moves": len(moves), "commands": len(commands)}, "end": at}


def write(tmp_path, j, name="prog.json"):
    p = tmp_path / name
    p.write_text(json.dumps(j))
    return str(p)
