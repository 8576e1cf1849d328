#!/usr/bin/python3
"""Plot the normal interpolation error along a contour, like the OLI paper's
error curves (Fig. 6 and 8), from `hwinterp plan --error-csv FILE`.

usage: scripts/plot_contour_error.py ERROR_CSV OUT_PNG [--title TEXT] [--by position]

The x axis is the curve parameter of each sample's foot on the contour (x in
mm for a translating cam, theta in degrees for a rotating one), or with
--by position the length along the contour. Dashed lines mark +-E.
Runs with Debian's /usr/bin/python3 (python3-matplotlib).
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
    ap.add_argument("png")
    ap.add_argument("--title", default=None)
    ap.add_argument("--by", choices=["parameter", "position"], default="parameter")
    a = ap.parse_args()

    with open(a.csv, newline="") as f:
        reader = csv.DictReader(f)
        param = [c for c in reader.fieldnames if c in ("x_mm", "theta_deg")]
        if not param or "error_mm" not in reader.fieldnames:
            sys.exit(f"{a.csv}: not an hwinterp plan --error-csv file")
        rows = list(reader)
    if not rows:
        sys.exit(f"{a.csv}: no samples")
    key = "position_mm" if a.by == "position" else param[0]
    xs = [float(r[key]) for r in rows]
    ys = [1e3 * float(r["error_mm"]) for r in rows]  # micrometres
    tol = 1e3 * float(rows[0]["tol_mm"])
    # The last sample of a segment is its end vertex: mark the joints.
    joints = [(xs[i - 1], ys[i - 1]) for i in range(1, len(rows))
              if rows[i]["segment"] != rows[i - 1]["segment"]]

    fig, ax = plt.subplots(figsize=(10, 4.2), dpi=120)
    ax.plot(xs, ys, lw=0.8, color="tab:blue", label="normal error of the polyline")
    if len(joints) <= 400:
        ax.plot([j[0] for j in joints], [j[1] for j in joints], ".", ms=3, color="tab:red",
                label="segment joints")
    for s in (1, -1):
        ax.axhline(s * tol, ls="--", lw=0.8, color="gray")
    ax.axhline(0, lw=0.5, color="black")
    ax.text(xs[-1], tol, f" +E = {tol:g} µm", va="bottom", ha="right", fontsize=8, color="gray")
    ax.text(xs[-1], -tol, f" -E = {-tol:g} µm", va="top", ha="right", fontsize=8, color="gray")
    labels = {"x_mm": "x (mm)", "theta_deg": "cam angle θ (deg)",
              "position_mm": "length along the contour (mm)"}
    ax.set_xlabel(labels[key])
    ax.set_ylabel("interpolation error (µm), + away from the cam body")
    ax.set_ylim(-1.35 * tol, 1.35 * tol)
    ax.set_xlim(min(xs), max(xs))
    segments = int(rows[-1]["segment"]) + 1
    ax.set_title(a.title or f"Interpolation error along the contour: {segments} segments, "
                 f"E = ±{tol:g} µm")
    ax.legend(loc="lower left", fontsize=8)
    ax.grid(True, lw=0.3)
    fig.tight_layout()
    fig.savefig(a.png)


if __name__ == "__main__":
    main()
