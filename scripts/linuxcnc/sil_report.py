#!/usr/bin/env python3
"""The report of one software-in-the-loop run (scripts/linuxcnc/sil.sh):
LinuxCNC's commanded joint positions, sampled each servo period with the
driver's boundary clock (samples.txt), against the board's own step pins
(steps.csv) and report (board.json).

- Following error at period boundaries: LinuxCNC's lattice point of period
  k (position x scale, rounded) against the board's position just before
  the boundary of period k + 1, where the driver's next command starts.
  Goal 0 on every boundary.
- Inside a period: the board's position at each of its steps against the
  straight line from one boundary's point to the next (LinuxCNC's motion
  between two samples), in steps.
- Late commands (the driver's late-count), missed slots, bursts and bytes.
- End positions: LinuxCNC's last commanded point against the board's.
- Machining times: LinuxCNC's (AUTO_RUN to the end, wall clock), the
  commanded motion's (first to last period that moves), the board's (first
  to last step, board clock).
- The board's step timing checks; for a fault run, what the board did.

Writes OUT/sil.json and OUT/sil_position.png, OUT/sil_ferror.png; exit 1
when a goal is missed (a normal run: any following error at a boundary, a
late command, end positions that differ, a timing violation, LinuxCNC's
errors; a fault run: steps after the stop).
"""
import argparse
import bisect
import configparser
import csv
import json
import os
import sys

# The columns of samples.txt after halsampler's sample number (sil_config.py's SAMPLED).
NAMES = ["j0", "j1", "j2", "j3", "boundary", "running", "late", "fifo", "missed", "berr", "fault",
         "retransmits", "rtt_us", "last_period"]


def read_ini(path):
    cp = configparser.ConfigParser(strict=False, interpolation=None, comment_prefixes=("#", ";"))
    with open(path) as f:
        cp.read_string(f.read())
    return cp


def samples(path):
    rows = []
    with open(path) as f:
        for line in f:
            v = line.split()
            if len(v) != len(NAMES) + 1:
                continue
            rows.append(dict(zip(NAMES, map(float, v[1:]))))
    return rows


def steps(path, axes):
    """Per axis: the step clocks and the position after each step."""
    ev = []
    with open(path) as f:
        for r in csv.DictReader(f):
            ev.append((int(r["clock"]), "XYZABC".index(r["axis"]), 1 if r["dir"] == "1" else -1))
    ev.sort()
    clocks = [[] for _ in range(axes)]
    pos = [[] for _ in range(axes)]
    p = [0] * axes
    for c, a, d in ev:
        if a < axes:
            p[a] += d
            clocks[a].append(c)
            pos[a].append(p[a])
    return clocks, pos


def position_before(clocks, pos, clock):
    """An axis's position just before `clock` (0 before its first step)."""
    i = bisect.bisect_left(clocks, clock)
    return pos[i - 1] if i else 0


def trace(run, target, clocks, pos, hz, series, joints, points=48):
    """The run in `points` samples for the docs' charts: at evenly spaced
    boundaries, the board time (s from the first), LinuxCNC's X and Y lattice
    points and the board's, and the largest |following error| of any joint
    at the boundaries since the sample before."""
    if len(run) < 2 or not series:
        return None
    b0 = run[0]["boundary"]
    ks = sorted({round(i * (len(run) - 2) / (points - 1)) for i in range(points)})
    out = {"t_s": [], "x_cmd": [], "x_board": [], "y_cmd": [], "y_board": [], "ferror_max": []}
    s, last_t = 0, None
    for k in ks:
        b = run[k + 1]["boundary"]
        out["t_s"].append(round((b - b0) / hz, 3))
        for j, name in zip(range(min(2, joints)), "xy"):
            out[f"{name}_cmd"].append(target[k][j])
            out[f"{name}_board"].append(position_before(clocks[j], pos[j], b))
        worst = 0
        while s < len(series) and series[s][0] <= b / hz:
            worst = max(worst, max(abs(e) for e in series[s][1]))
            s += 1
        out["ferror_max"].append(worst)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--out", required=True)
    ap.add_argument("--linuxcnc-rc", type=int, default=0)
    ap.add_argument("--wall-s", type=float, default=0)
    a = ap.parse_args()
    out = a.out
    ini = read_ini(os.path.join(out, "config", "hwinterp_mill.ini"))
    joints = int(ini["KINS"]["JOINTS"])
    scale = [float(ini[f"JOINT_{j}"]["SCALE"]) for j in range(joints)]
    period_s = float(ini["EMCMOT"]["SERVO_PERIOD"]) * 1e-9
    with open(os.path.join(out, "board.json")) as f:
        board = json.load(f)
    hz = board["sys_hz"]
    lc_path = os.path.join(out, "linuxcnc.json")
    lc = json.load(open(lc_path)) if os.path.exists(lc_path) else {}
    fault = (lc.get("fault") or "").split()
    rows = samples(os.path.join(out, "samples.txt"))
    clocks, pos = steps(os.path.join(out, "steps.csv"), joints)

    # Periods the driver ran, and each boundary's check. A stop (e-stop, a
    # killed LinuxCNC) drops the commands queued ahead of it: boundaries after
    # the board's last step are counted apart, not checked.
    run = [r for r in rows if r["running"] >= 0.5]
    all_clocks = sorted(c for cs in clocks for c in cs)
    target = [[int(r[f"j{j}"]) for j in range(joints)] for r in run]  # the driver's own steps
    ferr_max = [0] * joints
    nonzero = 0
    checked = 0
    series = []  # (board seconds, ferror steps of each joint)
    inside_max = 0.0
    # Segments: runs of periods between restarts; the last step of each.
    seg_last_step, seg = [], 0
    bounds = [int(r["boundary"]) for r in run]
    seg_of = []
    for k in range(len(run)):
        if k and (bounds[k] <= bounds[k - 1] or bounds[k] - bounds[k - 1] > 100 * hz * period_s):
            seg += 1
        seg_of.append(seg)
    for g in range(seg + 1):
        ks = [k for k in range(len(run)) if seg_of[k] == g]
        lo, hi = bounds[ks[0]], (bounds[ks[-1]] if g == seg else bounds[ks[-1] + 1])
        in_seg = [c for c in all_clocks if lo <= c < hi + int(hz * 0.2)]
        seg_last_step.append(in_seg[-1] if in_seg else lo)
    dropped = 0
    for k in range(len(run) - 1):
        b0, b1 = bounds[k], bounds[k + 1]
        if seg_of[k + 1] != seg_of[k]:  # a restart: not one run
            continue
        if fault and b1 > seg_last_step[seg_of[k]]:
            # After a stop: the commands queued ahead of it were dropped (or,
            # the link cut, never arrived).
            e = [position_before(clocks[j], pos[j], b1) - target[k][j] for j in range(joints)]
            if any(e):
                dropped += 1
                continue
        checked += 1
        e = [position_before(clocks[j], pos[j], b1) - target[k][j] for j in range(joints)]
        for j in range(joints):
            ferr_max[j] = max(ferr_max[j], abs(e[j]))
        nonzero += any(e)
        series.append((b1 / hz, e))
        # Inside the period: each step between the boundaries against the line.
        if k > 0:
            for j in range(joints):
                lo = bisect.bisect_left(clocks[j], b0)
                hi = bisect.bisect_left(clocks[j], b1)
                p0, p1 = target[k - 1][j], target[k][j]
                for i in range(lo, hi):
                    ideal = p0 + (p1 - p0) * (clocks[j][i] - b0) / (b1 - b0)
                    inside_max = max(inside_max, abs(pos[j][i] - ideal))
    moving = [k for k in range(1, len(rows)) if any(rows[k][f"j{j}"] != rows[k - 1][f"j{j}"]
                                                    for j in range(joints))]
    all_steps = [c for cs in clocks for c in cs]
    driver = lc.get("driver", {})
    end_lc = target[-1] if target else None
    end_board = board["position"][:joints]
    report = {
        "program": lc.get("program"),
        "fault": lc.get("fault", ""),
        "ended": lc.get("ended"),
        "linuxcnc_errors": lc.get("errors", []),
        "linuxcnc_rc": a.linuxcnc_rc,
        "board": board.get("board"),
        "link": ini["HWINTERP"]["BOARD"],
        "board_clock_hz": hz,
        "servo_period_s": period_s,
        "periods_run": len(run),
        "boundaries_checked": checked,
        "boundaries_with_error": nonzero,
        "boundaries_dropped_by_stop": dropped,
        "ferror_at_boundaries_max_steps": ferr_max,
        "ferror_inside_period_max_steps": round(inside_max, 3),
        "late_commands": int(run[-1]["late"]) if run else None,
        "missed_slots": int(run[-1]["missed"]) if run else None,
        "fifo_max": int(max((r["fifo"] for r in run), default=0)),
        "driver": {k.replace("hwinterp.", ""): v for k, v in driver.items()
                   if not k.startswith("hwinterp.stepgen")},
        "end_linuxcnc_steps": end_lc,
        "end_board_steps": end_board,
        "end_equal": end_lc == end_board,
        "machining_s_linuxcnc": lc.get("machining_s"),
        "motion_s_commanded": (moving[-1] - moving[0] + 1) * period_s if moving else 0,
        "motion_s_board": (max(all_steps) - min(all_steps)) / hz if all_steps else 0,
        "wall_s": a.wall_s,
        "board_seconds": board["clocks"] / hz,
        "board_clocks_per_s": board["clocks_per_second"],
        "timing_violations": board["timing_violations"],
        "watchdog_bites": board["watchdog_bites"],
        "board_passed": board["passed"],
    }
    if "sends" not in report["driver"] and driver:
        pass
    # A fault: the stop, and the steps after it.
    ok = True
    if fault:
        last_step = max(all_steps) if all_steps else 0
        report["last_step_s"] = last_step / hz
        if fault[0] == "kill":
            bites = board["watchdog_bites"]
            report["stopped_by_watchdog"] = bool(bites)
            if bites:
                bite = bites[0]["bite_clock"]
                report["bite_s"] = bite / hz
                # The last packet's commands ran until the bite; none after.
                report["steps_after_bite"] = sum(1 for c in all_steps if c >= bite)
                report["last_boundary_s"] = max((r["boundary"] for r in run), default=0) / hz
            ok = (bool(bites) and report.get("steps_after_bite") == 0 and len(bites) == 1 and
                  nonzero == 0)
        elif fault[0] == "cut":
            # The link cut: the driver's fault, the board's watchdog, then a
            # restart from the board's true position, every boundary exact.
            report["fault_seen_s"] = lc.get("fault_seen_s")
            report["on_attempts"] = lc.get("on_attempts")
            report["restarted"] = lc.get("ended") == "restarted"
            report["link_errors"] = driver.get("hwinterp.link-errors")
            bites = board["watchdog_bites"]
            report["watchdog_bites"] = len(bites)
            restarts = sum(1 for k in range(len(run) - 1)
                           if int(run[k + 1]["boundary"]) <= int(run[k]["boundary"]) or
                           run[k + 1]["boundary"] - run[k]["boundary"] > 100 * hz * period_s)
            report["runs"] = restarts + 1 if run else 0
            ok = (report["restarted"] and len(bites) >= 1 and nonzero == 0 and
                  report["end_equal"] and board["timing_violations"] == 0)
        elif fault[0] == "estop":
            # The stop: the first period the driver no longer runs.
            off = next((k for k in range(1, len(rows)) if rows[k - 1]["running"] >= 0.5 and
                        rows[k]["running"] < 0.5), None)
            report["stopped"] = off is not None
            if off is not None:
                stop_clock = int(rows[off - 1]["boundary"])
                report["steps_after_stop_boundary"] = sum(1 for c in all_steps if c > stop_clock)
            ok = (report["stopped"] and board["timing_violations"] == 0 and nonzero == 0 and
                  report.get("steps_after_stop_boundary") == 0)
    else:
        ok = (nonzero == 0 and report["late_commands"] == 0 and report["end_equal"] and
              board["timing_violations"] == 0 and not report["linuxcnc_errors"] and
              lc.get("ended") == "program end" and checked > 0)
    report["passed"] = ok
    report["trace"] = trace(run, target, clocks, pos, hz, series, joints)
    with open(os.path.join(out, "sil.json"), "w") as f:
        json.dump(report, f, indent=2)
    plot(out, run, scale, clocks, pos, hz, series, joints)
    print(json.dumps({k: report[k] for k in ("program", "fault", "periods_run", "boundaries_checked",
                                            "boundaries_with_error", "ferror_at_boundaries_max_steps",
                                            "ferror_inside_period_max_steps", "late_commands",
                                            "end_equal", "machining_s_linuxcnc", "motion_s_board",
                                            "passed")}))
    return 0 if ok else 1


def plot(out, run, scale, clocks, pos, hz, series, joints):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    if not run:
        return
    t = [r["boundary"] / hz for r in run]
    fig, ax = plt.subplots(2, 1, figsize=(10, 6), sharex=True)
    for j, name in zip(range(min(2, joints)), "XY"):
        ax[j].plot(t, [r[f"j{j}"] for r in run], lw=1, label="LinuxCNC commanded (at its boundary)")
        ax[j].step([c / hz for c in clocks[j]], pos[j], where="post", lw=0.8, label="board (step pins)")
        ax[j].set_ylabel(f"{name} (steps)")
        ax[j].legend(loc="upper right", fontsize=8)
    ax[1].set_xlabel("board time (s)")
    fig.suptitle(os.path.basename(str(run and out)) + ": commanded and actual position")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "sil_position.png"), dpi=90)
    plt.close(fig)
    fig, ax = plt.subplots(figsize=(10, 3))
    for j in range(joints):
        ax.plot([s for s, _ in series], [e[j] for _, e in series], lw=0.8, label=f"joint {j}")
    ax.set_xlabel("board time (s)")
    ax.set_ylabel("following error at boundaries (steps)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "sil_ferror.png"), dpi=90)
    plt.close(fig)


if __name__ == "__main__":
    sys.exit(main())
