#!/usr/bin/python3
"""Draws the lattice paths of a dda_line co-simulation, like Fig. 3 of
004_dc68f1177cad466f.txt: the ideal line of every command, the points the
core visited (as a staircase), and the band of the documented path-error
bound around the ideal line. One panel per case, first two axes.

    hwinterp cosim --core dda_line --paper-lines --path-csv paths.csv
    scripts/plot_dda_paths.py paths.csv --bound 1.0 -o paths.png

Uses Debian's python3-matplotlib (run it with /usr/bin/python3)."""
import argparse
import csv
import math
import sys
from collections import OrderedDict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_cases(path):
    cases = OrderedDict()
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            c = cases.setdefault(row["case"], {"start": None, "targets": [], "moves": []})
            p = (int(row["p0"]), int(row["p1"]))
            if row["kind"] == "start":
                c["start"] = p
            elif row["kind"] == "target":
                c["targets"].append(p)
            elif row["kind"] == "move":
                c["moves"].append(p)
            else:
                sys.exit(f"plot_dda_paths.py: unknown kind '{row['kind']}' in {path}")
    return cases


def band(a, b, d):
    """Corners of the strip of half-width d around segment a-b."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    n = math.hypot(dx, dy)
    if n == 0:
        return None
    ux, uy = -dy / n * d, dx / n * d
    return [(a[0] + ux, a[1] + uy), (b[0] + ux, b[1] + uy), (b[0] - ux, b[1] - uy), (a[0] - ux, a[1] - uy)]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("csv", help="file written by hwinterp cosim --path-csv")
    ap.add_argument("--bound", type=float, default=1.0, help="half-width of the error band, steps (default 1)")
    ap.add_argument("-o", "--output", default="dda_paths.png", help="PNG to write")
    args = ap.parse_args()
    cases = read_cases(args.csv)
    if not cases:
        sys.exit(f"plot_dda_paths.py: no cases in {args.csv}")
    cols = min(4, len(cases))
    rows = math.ceil(len(cases) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(4 * cols, 4 * rows), squeeze=False)
    for ax, (name, c) in zip(axes.flat, cases.items()):
        points = [c["start"]] + c["targets"]
        for a, b in zip(points, points[1:]):
            corners = band(a, b, args.bound)
            if corners:
                ax.fill(*zip(*corners), color="tab:green", alpha=0.12, lw=0)
            ax.plot([a[0], b[0]], [a[1], b[1]], color="tab:green", lw=1.2)
        path = [c["start"]] + c["moves"]
        # Straight between visited points: axes that step together move diagonally.
        ax.plot([p[0] for p in path], [p[1] for p in path], "-o", color="tab:red", lw=0.8, ms=2)
        ax.set_title(f"{name}: {len(c['moves'])} moves", fontsize=9)
        ax.set_aspect("equal", adjustable="datalim")
        ax.grid(True, lw=0.3)
    for ax in list(axes.flat)[len(cases):]:
        ax.axis("off")
    fig.suptitle(f"dda_line: visited lattice points (red), ideal line (green), +-{args.bound:g} step band")
    fig.tight_layout()
    fig.savefig(args.output, dpi=110)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
