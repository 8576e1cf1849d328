#!/usr/bin/python3
"""Plot the odd-even log interpolation error ErPA along X.

Reads the CSV of `hwinterp log --csv FILE` (index, parity, x, y, z, a, pa,
error) and draws two panels: every point's ErPA (odd and even points marked
apart), and the even points alone, whose error is about two orders smaller
and drifts one way. With --exact CSV (a run with --exact-even) the exact
even step's even points are drawn beside, to show the drift going away.

Usage:
  hwinterp log --csv paper.csv
  hwinterp log --exact-even --csv exact.csv
  /usr/bin/python3 scripts/plot_log_error.py paper.csv --exact exact.csv -o log_error.png

Debian's python3-matplotlib is used, hence /usr/bin/python3.
"""
import argparse
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_run(path):
    """Returns {'odd': (xs, errs), 'even': (xs, errs)} from a `hwinterp log` CSV."""
    out = {"odd": ([], []), "even": ([], [])}
    try:
        with open(path, newline="") as f:
            rows = csv.DictReader(f)
            missing = {"parity", "x", "error"} - set(rows.fieldnames or [])
            if missing:
                sys.exit(f"{path}: not a `hwinterp log --csv` file (missing {sorted(missing)})")
            for row in rows:
                if row["parity"] in out:
                    xs, es = out[row["parity"]]
                    xs.append(float(row["x"]))
                    es.append(float(row["error"]))
    except OSError as e:
        sys.exit(f"{path}: {e.strerror}")
    if not out["odd"][0]:
        sys.exit(f"{path}: no points")
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("csv", help="CSV from `hwinterp log --csv` (paper even step)")
    ap.add_argument("--exact", metavar="CSV", help="CSV from `hwinterp log --exact-even --csv`")
    ap.add_argument("-o", "--output", default="log_error.png", help="PNG to write")
    ap.add_argument("--title", default="Odd-even third-order log interpolation: ErPA = a ln(1+bX) - A")
    args = ap.parse_args()

    run = read_run(args.csv)
    exact = read_run(args.exact) if args.exact else None

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(9, 7), sharex=True,
                                      gridspec_kw={"height_ratios": [1, 1]})
    fig.suptitle(args.title, fontsize=11)

    ox, oe = run["odd"]
    ex, ee = run["even"]
    top.plot(ox, [e * 1e5 for e in oe], "o", ms=3, color="tab:red", label="odd points (tangent step)")
    top.plot(ex, [e * 1e5 for e in ee], "s", ms=3, color="tab:blue", label="even points (Eqs. 14/15)")
    top.axhline(0, color="0.6", lw=0.8)
    top.set_ylabel("ErPA (1e-5 rad)")
    top.legend(loc="lower right", fontsize=9)
    top.grid(alpha=0.3)

    bottom.plot(ex, [e * 1e7 for e in ee], "s-", ms=3, lw=0.8, color="tab:blue",
                label="even points, Eqs. 14/15 (drift)")
    if exact:
        xx, xe = exact["even"]
        bottom.plot(xx, [e * 1e7 for e in xe], "^-", ms=3, lw=0.8, color="tab:green",
                    label="even points, exact even step (circle cut)")
    bottom.axhline(0, color="0.6", lw=0.8)
    bottom.set_ylabel("ErPA at even points (1e-7 rad)")
    bottom.set_xlabel("X (mm)")
    bottom.legend(loc="lower left", fontsize=9)
    bottom.grid(alpha=0.3)

    fig.tight_layout()
    fig.savefig(args.output, dpi=120)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
