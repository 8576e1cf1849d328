#!/usr/bin/env python3
"""Our planner against LinuxCNC's on the same programs and the same machine
(docs/linuxcnc.md): each program of docs/data/linuxcnc_sil.json run by
`hwinterp gcode` on tests/data/linuxcnc/machine_mill.json (the mill of
sw/hal/config/: steps, limits, the board's 250 kHz) with the feed profile as
a trapezoid (LinuxCNC's planner has no jerk limit) and as the S-curve; the
machining times beside LinuxCNC's (the board's steps, first to last, in the
software-in-the-loop run).

usage: scripts/linuxcnc/planner_compare.py [--json docs/data/linuxcnc_planner.json]
"""
import argparse
import datetime
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--json", default=os.path.join(ROOT, "docs", "data", "linuxcnc_planner.json"))
    ap.add_argument("--hwinterp", default=os.path.join(ROOT, "build", "tb", "hwinterp"))
    a = ap.parse_args()
    with open(os.path.join(ROOT, "docs", "data", "linuxcnc_sil.json")) as f:
        sil = json.load(f)
    machine = os.path.join(ROOT, "tests", "data", "linuxcnc", "machine_mill.json")
    rows = []
    for r in sil["runs"]:
        if r.get("fault") or r.get("missing"):
            continue
        prog = r["program"]
        row = {"program": os.path.relpath(prog, ROOT), "linuxcnc_s": r["motion_s_board"],
               "linuxcnc_machining_s": r["machining_s_linuxcnc"]}
        for profile in ("trapezoid", "scurve"):
            with tempfile.TemporaryDirectory() as tmp:
                out = os.path.join(tmp, "r.json")
                p = subprocess.run([a.hwinterp, "gcode", prog, "--machine", machine, "--profile",
                                    profile, "--feed", "programmed", "--progress", "0", "--json", out],
                                   capture_output=True, text=True)
                if p.returncode != 0:
                    # The message without this tree's root: the same in any clone.
                    row[profile] = {"passed": False,
                                    "error": (p.stdout + p.stderr)[-400:].replace(ROOT + "/", "")}
                    continue
                with open(out) as f:
                    d = json.load(f)
                row[profile] = {"passed": d["passed"], "s": d["simulated_time_s"],
                                "programmed_s": d["programmed_time_s"]}
        print(json.dumps(row), flush=True)
        rows.append(row)
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip()
    data = {"command": "scripts/linuxcnc/planner_compare.py", "commit": commit,
            "date": datetime.date.today().isoformat(),
            "linuxcnc_from": "docs/data/linuxcnc_sil.json", "programs": rows}
    with open(a.json + ".tmp", "w") as f:
        json.dump(data, f, indent=1)
    os.replace(a.json + ".tmp", a.json)
    return 0


if __name__ == "__main__":
    sys.exit(main())
