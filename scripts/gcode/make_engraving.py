#!/usr/bin/env python3
"""Writes tests/data/gcode/engraving.ngc: a CAM-style engraving program.

What a CAM post-processor writes for V-bit engraving: per stroke a rapid to
its start, a plunge, short G1 segments and G2/G3 arcs with incremental IJK at
a cutting feed, and a retract. Every coordinate is rounded to 0.001 mm as
CAM output is, so arc ends sit up to about 0.0007 mm off their circles (well
inside LinuxCNC's 0.0283 mm). Deterministic: no randomness, the same file on
every run. The shapes, all within +-100 mm:
  - block letters "HWINTERP" (G1 strokes; arcs in P and R),
  - a two-centre spiral of half turns, each cut as three 60-degree arcs,
  - a rosette of sixteen small circles, each as eight 45-degree arcs,
  - a wave of alternating G2/G3 half circles.

Usage: scripts/gcode/make_engraving.py [OUT]   (default: the file above)
Regenerate the canon file after changing it:
  rs274 -g tests/data/gcode/engraving.ngc tests/data/gcode/engraving.canon </dev/null
"""
import math
import os
import sys

SAFE_Z = 2.0
CUT_Z = -0.2
PLUNGE_F = 150
CUT_F = 600


def num(v):
    """A coordinate as CAM writes it: 0.001 mm, no trailing zeros."""
    s = "%.3f" % v
    s = s.rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


class Program:
    def __init__(self):
        self.lines = []
        self.x = 0.0
        self.y = 0.0

    def emit(self, text):
        self.lines.append(text)

    def stroke(self, x, y):
        """Rapid above (x, y) and plunge: the start of a stroke."""
        self.emit("G0 Z%s" % num(SAFE_Z))
        self.emit("G0 X%s Y%s" % (num(x), num(y)))
        self.emit("G1 Z%s F%d" % (num(CUT_Z), PLUNGE_F))
        self.x, self.y = round(x, 3), round(y, 3)
        self.first_cut = True

    def feed_word(self):
        if self.first_cut:
            self.first_cut = False
            return " F%d" % CUT_F
        return ""

    def line(self, x, y):
        self.emit("G1 X%s Y%s%s" % (num(x), num(y), self.feed_word()))
        self.x, self.y = round(x, 3), round(y, 3)

    def arc(self, ccw, cx, cy, x, y):
        """An arc to (x, y) about (cx, cy): IJK relative to the start."""
        i, j = cx - self.x, cy - self.y
        self.emit("%s X%s Y%s I%s J%s%s" % ("G3" if ccw else "G2", num(x), num(y), num(i),
                                           num(j), self.feed_word()))
        self.x, self.y = round(x, 3), round(y, 3)

    def arc_to_angle(self, ccw, cx, cy, r, angle_deg):
        a = math.radians(angle_deg)
        self.arc(ccw, cx, cy, cx + r * math.cos(a), cy + r * math.sin(a))


# Block letters on a 6 x 10 cell: polylines, and arcs for P and R.
def letter(p, ch, ox, oy, s):
    P = lambda u, v: (ox + u * s, oy + v * s)
    if ch == "H":
        for a, b in (((0, 0), (0, 10)), ((6, 0), (6, 10)), ((0, 5), (6, 5))):
            p.stroke(*P(*a))
            p.line(*P(*b))
    elif ch == "W":
        p.stroke(*P(0, 10))
        for u, v in ((1.5, 0), (3, 6), (4.5, 0), (6, 10)):
            p.line(*P(u, v))
    elif ch == "I":
        for a, b in (((3, 0), (3, 10)), ((1, 0), (5, 0)), ((1, 10), (5, 10))):
            p.stroke(*P(*a))
            p.line(*P(*b))
    elif ch == "N":
        p.stroke(*P(0, 0))
        for u, v in ((0, 10), (6, 0), (6, 10)):
            p.line(*P(u, v))
    elif ch == "T":
        for a, b in (((3, 0), (3, 10)), ((0, 10), (6, 10))):
            p.stroke(*P(*a))
            p.line(*P(*b))
    elif ch == "E":
        p.stroke(*P(6, 10))
        for u, v in ((0, 10), (0, 0), (6, 0)):
            p.line(*P(u, v))
        p.stroke(*P(0, 5))
        p.line(*P(4.5, 5))
    elif ch in "PR":
        # Stem, then a bowl of two quarter arcs and a half circle.
        p.stroke(*P(0, 0))
        p.line(*P(0, 10))
        p.line(*P(3, 10))
        cx, cy = P(3, 7.5)
        p.arc_to_angle(False, cx, cy, 2.5 * s, 0)
        p.arc_to_angle(False, cx, cy, 2.5 * s, -90)
        p.line(*P(0, 5))
        if ch == "R":
            p.stroke(*P(3, 5))
            p.line(*P(6, 0))


def spiral(p, cx, cy, r0, d, half_turns):
    """Half circles about two centres d apart: the radius grows by d each
    half turn; each half circle is cut as three 60-degree arcs."""
    p.stroke(cx + r0, cy)
    r = r0
    for k in range(half_turns):
        c = (cx, cy) if k % 2 == 0 else (cx + d, cy)
        start = 0 if k % 2 == 0 else 180
        for step in (60, 120, 180):
            p.arc_to_angle(True, c[0], c[1], r, start + step)
        r += d


def rosette(p, cx, cy, ring, r, count):
    for n in range(count):
        a = 2 * math.pi * n / count
        ox, oy = cx + ring * math.cos(a), cy + ring * math.sin(a)
        # Start on the circle at the angle facing away from the centre.
        p.stroke(ox + r * math.cos(a), oy + r * math.sin(a))
        ccw = n % 2 == 0
        deg = math.degrees(a)
        for q in range(1, 9):
            p.arc_to_angle(ccw, ox, oy, r, deg + (45 * q if ccw else -45 * q))


def wave(p, x0, y0, r, halves):
    p.stroke(x0, y0)
    x = x0
    for k in range(halves):
        # Alternate below and above the axis: G2 then G3.
        p.arc(k % 2 == 1, x + r, y0, x + 2 * r, y0)
        x += 2 * r
    p.line(x + r, y0)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests", "data", "gcode",
        "engraving.ngc")
    p = Program()
    p.emit("%")
    p.emit("(engraving.ngc: written by scripts/gcode/make_engraving.py; do not edit)")
    p.emit("(V-bit engraving: letters, a spiral of arcs, a rosette, a wave)")
    p.emit("G21 G90 G17 G94")
    for n, ch in enumerate("HWINTERP"):
        letter(p, ch, -95 + n * 11.5, 60, 1.0)
    spiral(p, -50, 0, 2.0, 1.5, 24)
    rosette(p, 40, 10, 22, 6, 16)
    wave(p, -90, -70, 1.8, 48)
    p.emit("G0 Z%s" % num(SAFE_Z))
    p.emit("G0 X0 Y0")
    p.emit("M2")
    p.emit("%")
    with open(out, "w") as f:
        f.write("\n".join(p.lines) + "\n")


if __name__ == "__main__":
    main()
