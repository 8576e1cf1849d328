#!/usr/bin/python3
"""Plot the lattice path of `hwinterp gcode` coloured by contour error.

usage: scripts/plot_gcode.py POINTS_CSV -o OUT_PNG [--title TEXT]

POINTS_CSV is what `hwinterp gcode --plot OUT.png` writes beside the PNG
(OUT.png.points.csv: move, x_mm, y_mm, z_mm, error_mm per visited lattice
point) and hands to this script. The XY view shows every visited point,
coloured by its distance to the programmed path of its move (micrometres);
a second panel shows the error along the run. Runs with Debian's
/usr/bin/python3 (python3-matplotlib).
"""
import argparse
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("csv")
    ap.add_argument("-o", "--out", required=True)
    ap.add_argument("--title", default=None)
    a = ap.parse_args()

    xs, ys, errs = [], [], []
    with open(a.csv, newline="") as f:
        reader = csv.DictReader(f)
        need = {"x_mm", "y_mm", "error_mm"}
        if not reader.fieldnames or not need <= set(reader.fieldnames):
            sys.exit(f"{a.csv}: not an hwinterp gcode points file (needs {sorted(need)})")
        for r in reader:
            xs.append(float(r["x_mm"]))
            ys.append(float(r["y_mm"]))
            errs.append(1e3 * float(r["error_mm"]))  # micrometres
    if not xs:
        sys.exit(f"{a.csv}: no visited points")
    # Thin very long runs for the scatter (every point still counts in the max).
    stride = max(1, len(xs) // 400000)

    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(13, 6), gridspec_kw={"width_ratios": [3, 2]})
    sc = ax.scatter(xs[::stride], ys[::stride], c=errs[::stride], s=1.5, cmap="viridis",
                    vmin=0, vmax=max(errs) or 1)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("X (mm)")
    ax.set_ylabel("Y (mm)")
    fig.colorbar(sc, ax=ax, label="contour error (µm)")
    ax2.plot(range(0, len(errs), stride), errs[::stride], lw=0.5)
    ax2.set_xlabel("visited lattice point")
    ax2.set_ylabel("contour error (µm)")
    ax2.set_title(f"max {max(errs):.3f} µm over {len(errs)} points")
    if a.title:
        fig.suptitle(a.title)
    fig.tight_layout()
    fig.savefig(a.out, dpi=120)


if __name__ == "__main__":
    main()
