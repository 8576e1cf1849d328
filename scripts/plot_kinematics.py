#!/usr/bin/python3
"""Plot speed, acceleration and jerk over time, for the path and each axis.

usage: scripts/plot_kinematics.py SERIES_CSV UNITS_JSON -o OUT_PNG [--title TEXT]

`hwinterp gcode --plot-kinematics OUT.png` writes SERIES_CSV beside the PNG
(OUT.png.csv: one row per estimator window, tb/monitor/kinematics.h: the
clock the window ends on, then speed, acceleration and jerk of the path in
mm per clock^k and of each axis in steps per clock^k) and UNITS_JSON
(OUT.png.json: clock_hz, and per axis its units per step, unit name and the
machine file's limits), and hands both to this script. Each panel is one
quantity in units per s^k; a machine limit is a dashed line in its axis's
colour.
"""
import argparse
import csv
import json
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

QUANTITIES = [("speed", 1, "/s"), ("accel", 2, "/s²"), ("jerk", 3, "/s³")]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("series")
    ap.add_argument("units")
    ap.add_argument("-o", "--out", required=True)
    ap.add_argument("--title", default=None)
    a = ap.parse_args()

    with open(a.units) as f:
        units = json.load(f)
    hz = float(units["clock_hz"])
    axes = units["axes"]  # {"X": {"unit_per_step": .., "unit": "mm", "limits": {...}}, ...}
    with open(a.series, newline="") as f:
        reader = csv.DictReader(f)
        rows = list(reader)
        names = reader.fieldnames or []
    if "clock" not in names or not rows:
        sys.exit(f"{a.series}: no kinematics windows (a run shorter than one window?)")
    t = [float(r["clock"]) / hz for r in rows]

    fig, panels = plt.subplots(3, 1, figsize=(10, 9), sharex=True)
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    series = [("path", 1.0, "mm", {})] + [
        (n, float(v["unit_per_step"]), v["unit"], v.get("limits", {})) for n, v in axes.items()]
    for (q, order, per), ax in zip(QUANTITIES, panels):
        for k, (name, unit, unit_name, limits) in enumerate(series):
            col = f"{name}_{q}"
            if col not in names:
                continue
            scale = unit * hz ** order
            ys = [float(r[col]) * scale if r[col] != "" else math.nan for r in rows]
            colour = colours[k % len(colours)]
            ax.plot(t, ys, color=colour, lw=1.2 if name == "path" else 0.9,
                    label=f"{name} ({unit_name}{per})")
            limit = limits.get(q)
            if limit is not None:
                ax.axhline(limit, color=colour, ls="--", lw=0.8)
        ax.set_ylabel(f"|{q}| (units{per})")
        ax.grid(alpha=0.3)
        ax.legend(loc="upper right", fontsize=8)
    panels[-1].set_xlabel("time (s)")
    window = units.get("window_s")
    panels[0].set_title((a.title + ": " if a.title else "") +
                        "magnitudes over windows of " +
                        (f"{window * 1e3:g} ms" if window else "the estimator") +
                        "; dashed: the machine's limits")
    fig.tight_layout()
    fig.savefig(a.out, dpi=110)


if __name__ == "__main__":
    main()
