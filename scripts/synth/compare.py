#!/usr/bin/env python3
"""Before/after table of two published synthesis records (docs/synth.json).

    compare.py BEFORE AFTER [--variants build/generated/variants.txt]

BEFORE and AFTER: a synth.json file, or REV:PATH for the file as git holds
it at revision REV (e.g. f637dc3:docs/synth.json). Prints a markdown table:
per variant the iCE40 core LUT4 / carry / FF, the HX8K Fmax per seed, the
ECP5 and the Gowin Fmax per seed, before -> after ("-" where a record has none), then the
per-axis rows publish.py derives, before -> after. Variants in AFTER's order
(or the variants file's); a variant only in BEFORE is listed as removed.
Exit 2 on a file or revision that cannot be read.
"""
import argparse
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import publish  # noqa: E402  (seed_text)
import synth_report  # noqa: E402  (axis_pairs, per_axis)


def load(spec):
    try:
        if ":" in spec and not os.path.exists(spec):
            text = subprocess.run(["git", "show", spec], check=True, capture_output=True,
                                  text=True).stdout
        else:
            with open(spec) as f:
                text = f.read()
        return json.loads(text)["variants"]
    except (OSError, subprocess.CalledProcessError, ValueError, KeyError) as e:
        print("compare.py: cannot read '%s': %s" % (spec, e), file=sys.stderr)
        sys.exit(2)


def area(r):
    c = r.get("ice40_core")
    return "%d / %d / %d" % (c["lut4"], c["carry"], c["ff"]) if c else "-"


def fmax(r, family):
    runs = (r.get("harness", {}).get("hx8k") if family == "hx8k"
            else r.get(family, {}).get("runs"))
    return " / ".join(publish.seed_text(p) for p in runs) if runs else "-"


def per_axis(results):
    """{core: "LUT4 / carry / FF" per axis on iCE40}, as publish.py's per-axis rows."""
    return {core: " / ".join("%.0f" % v for v in
                             synth_report.per_axis(lo, hi, "ice40").values())
            for core, (lo, hi) in synth_report.axis_pairs(results).items()}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("before")
    ap.add_argument("after")
    ap.add_argument("--variants", help="variants.txt: list in its order")
    a = ap.parse_args()
    old, new = load(a.before), load(a.after)
    by_old = {r["variant"]: r for r in old}
    names = [r["variant"] for r in new]
    if a.variants:
        with open(a.variants) as f:
            order = [ln.split()[0] for ln in f if ln.strip()]
        names = [v for v in order if v in names] + [v for v in names if v not in order]
    by_new = {r["variant"]: r for r in new}
    print("| variant | iCE40 core LUT4 / carry / FF | HX8K Fmax per seed (MHz) |"
          " ECP5 Fmax per seed (MHz) | Gowin Fmax per seed (MHz) |")
    print("|---|---|---|---|---|")
    for v in names + [v for v in by_old if v not in by_new]:
        b, n = by_old.get(v, {}), by_new.get(v)
        if n is None:
            print("| `%s` | removed | | | |" % v)
            continue
        print("| `%s` | %s -> %s | %s -> %s | %s -> %s | %s -> %s |" % (
            v, area(b), area(n), fmax(b, "hx8k"), fmax(n, "hx8k"), fmax(b, "ecp5"),
            fmax(n, "ecp5"), fmax(b, "gowin"), fmax(n, "gowin")))
    pb, pn = per_axis(old), per_axis(new)
    if pn:
        print("\n| core | iCE40 LUT4 / carry / FF per axis |")
        print("|---|---|")
        for core, text in pn.items():
            print("| `%s` | %s -> %s |" % (core, pb.get(core, "-"), text))


if __name__ == "__main__":
    main()
