#!/usr/bin/python3
"""Draws the lattice paths of a co-simulation of any core, like Fig. 3 of
004_dc68f1177cad466f.txt: each command's ideal path (its reference model's:
a line, an arc, a spiral), the band of the core's path-error bound around it,
and the points the core visited. One panel per case, first two axes; with
--errors a second row per case plots each move's deviation against its bound.

    hwinterp cosim --core dda_line --paper-lines --path-csv paths.csv
    hwinterp cosim --core ppc_arc --arc 0,0,40,0,0,-40,ccw --path-csv arc.csv
    scripts/plot_paths.py paths.csv -o paths.png [--errors]

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
    """Per case: start, command targets, ideal polylines, moves with errors."""
    cases = OrderedDict()
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            c = cases.setdefault(row["case"], {"start": None, "targets": [], "ideal": [],
                                               "pending": [], "moves": [], "errors": [],
                                               "bound": 0.0})
            p = (float(row["p0"]), float(row["p1"]))
            kind = row["kind"]
            if kind == "start":
                c["start"] = p
            elif kind == "ideal":  # the vertices of a command's ideal path, then its target
                c["pending"].append(p)
            elif kind == "target":
                c["targets"].append(p)
                c["ideal"].append(c["pending"])
                c["pending"] = []
            elif kind == "move":
                c["moves"].append(p)
                c["errors"].append(float(row["error"]))
                c["bound"] = max(c["bound"], float(row["bound"]))
            else:
                sys.exit(f"plot_paths.py: unknown kind '{kind}' in {path}")
    return cases


def band(a, b, d):
    """Corners of the strip of half-width d around segment a-b."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    n = math.hypot(dx, dy)
    if n == 0:
        return None
    ux, uy = -dy / n * d, dx / n * d
    return [(a[0] + ux, a[1] + uy), (b[0] + ux, b[1] + uy), (b[0] - ux, b[1] - uy),
            (a[0] - ux, a[1] - uy)]


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("csv", help="file written by hwinterp cosim --path-csv")
    ap.add_argument("--errors", action="store_true", help="also plot each move's deviation")
    ap.add_argument("-o", "--output", default="paths.png", help="PNG to write")
    args = ap.parse_args()
    cases = read_cases(args.csv)
    if not cases:
        sys.exit(f"plot_paths.py: no cases in {args.csv}")
    cols = min(4, len(cases))
    rows = math.ceil(len(cases) / cols) * (2 if args.errors else 1)
    fig, axes = plt.subplots(rows, cols, figsize=(4 * cols, 4 * rows), squeeze=False)
    for k, (name, c) in enumerate(cases.items()):
        r, col = divmod(k, cols)
        ax = axes[r * (2 if args.errors else 1)][col]
        for line in c["ideal"]:
            for a, b in zip(line, line[1:]):
                corners = band(a, b, c["bound"])
                if corners:
                    ax.fill(*zip(*corners), color="tab:green", alpha=0.12, lw=0)
            ax.plot([p[0] for p in line], [p[1] for p in line], color="tab:green", lw=1.2)
        path = [c["start"]] + c["moves"]
        # Straight between visited points: axes that step together move diagonally.
        ax.plot([p[0] for p in path], [p[1] for p in path], "-o", color="tab:red", lw=0.8, ms=2)
        ax.set_title(f"{name}: {len(c['moves'])} moves, bound {c['bound']:.3g}", fontsize=9)
        ax.set_aspect("equal", adjustable="datalim")
        ax.grid(True, lw=0.3)
        if args.errors:
            ex = axes[r * 2 + 1][col]
            ex.plot(range(1, len(c["errors"]) + 1), c["errors"], color="tab:red", lw=0.8)
            ex.axhline(c["bound"], color="tab:green", ls="--", lw=1)
            ex.set_xlabel("move")
            ex.set_ylabel("deviation, steps")
            ex.set_ylim(bottom=0)
            ex.grid(True, lw=0.3)
    for ax in axes.flat:
        if not ax.has_data():
            ax.axis("off")
    fig.suptitle("visited lattice points (red), ideal path (green) and the error-bound band")
    fig.tight_layout()
    fig.savefig(args.output, dpi=110)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
