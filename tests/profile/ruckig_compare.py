#!/usr/bin/env python3
"""The feed profile against Ruckig, the time-optimal jerk-limited generator.

Seeded random single moves, each run through `hwinterp profile` (the block's
cycle-accurate face, clock by clock) and through Ruckig (PyPI `ruckig`) with
the same limits:
  * rest to rest: our time to rest against Ruckig's duration;
  * to a given end speed: our time to the move's last operation against
    Ruckig's duration from rest to (N, end speed).
Ours may never be shorter (one tick of slack: our speed is a staircase of
ticks): a shorter move would mean a limit was broken. Over the moves of at
least 1000 steps the gap must stay within --max-gap (issue 25's aim: 1 %).
Prints the distribution; --json writes it.

Limits are drawn where A/J fits the harness's build (L <= 1024 ticks of 1024
clocks, 21 ms at 50 MHz): velocity 5e3..5e4 steps/s, acceleration 1e5..1e6
steps/s^2, jerk from max(1e7, A / 0.02 s) to 1e8 steps/s^3.
"""
import argparse
import json
import random
import os
import subprocess
import sys
import tempfile

from ruckig import InputParameter, Result, Ruckig, Trajectory

CLOCK_HZ = 50e6
TICK_S = 1024 / CLOCK_HZ
# Ruckig 0.19 converges on long moves in step units only when scaled down.
SCALE = 1e-3


def ruckig_time(n, v, a, j, end_speed):
    inp = InputParameter(1)
    inp.current_position = [0.0]
    inp.current_velocity = [0.0]
    inp.current_acceleration = [0.0]
    inp.target_position = [n * SCALE]
    inp.target_velocity = [end_speed * SCALE]
    inp.target_acceleration = [0.0]
    inp.max_velocity = [v * SCALE]
    inp.max_acceleration = [a * SCALE]
    inp.max_jerk = [j * SCALE]
    traj = Trajectory(1)
    result = Ruckig(1).calculate(inp, traj)
    if result not in (Result.Working, Result.Finished):
        raise RuntimeError(f"ruckig: {result} for n={n} v={v} a={a} j={j} end={end_speed}")
    return traj.duration


def ours(exe, n, v, a, j, end_speed):
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "profile.json")
        subprocess.run(
            [exe, "profile", "--max-velocity", repr(v), "--max-accel", repr(a), "--max-jerk",
             repr(j), "--clock-hz", repr(CLOCK_HZ), "--ops", str(n), "--end-speed",
             repr(end_speed), "--json", path],
            check=True, capture_output=True, text=True)
        with open(path) as f:
            report = json.load(f)
    return report


def quantiles(gaps):
    g = sorted(gaps)
    pick = lambda p: g[min(len(g) - 1, int(p * len(g)))]
    return {"n": len(g), "min": g[0], "median": pick(0.5), "p90": pick(0.9), "max": g[-1]}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--hwinterp", required=True)
    ap.add_argument("--moves", type=int, default=30, help="moves of each kind")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--max-ops", type=int, default=30000)
    ap.add_argument("--max-gap", type=float, default=0.01)
    ap.add_argument("--json")
    args = ap.parse_args()
    rng = random.Random(args.seed)
    failures = []
    result = {}
    for kind in ("rest_to_rest", "end_speed"):
        gaps = []
        for k in range(args.moves):
            v = rng.uniform(5e3, 5e4)
            a = rng.uniform(1e5, 1e6)
            j = rng.uniform(max(1e7, a / 0.02), 1e8)
            n = rng.randint(1000, args.max_ops)
            end = 0.0 if kind == "rest_to_rest" else rng.uniform(0.05, 0.5) * v
            try:
                ref = ruckig_time(n, v, a, j, end)
            except RuntimeError as e:
                print(f"skip ({e})")
                continue
            report = ours(args.hwinterp, n, v, a, j, end)
            t = report["seconds_at_rest"] if end == 0 else report["seconds_last_op"]
            peak = report["peak"]
            gap = t / ref - 1
            gaps.append(gap)
            line = f"{kind} {k}: n {n} v {v:.0f} a {a:.0f} j {j:.3g} end {end:.0f}: ours {t:.6f} s, ruckig {ref:.6f} s, gap {gap:+.5f}"
            if t < ref - TICK_S:
                failures.append(line + " (shorter than Ruckig: a limit was broken)")
            # The limits, as the block's own ticks see them (1e-9: printing).
            for what, lim in (("speed", v), ("accel", a), ("jerk", j)):
                if peak[what] > lim * (1 + 1e-9):
                    failures.append(line + f" (peak {what} {peak[what]:.6g} above {lim:.6g})")
            # At the last operation: at most the end speed, plus one level to rest
            # (a move to rest travels at least its ops: the last one may come
            # while the speed is still within a level of 0).
            level = report["registers"]["level_speed"]
            allowed = end if end > 0 else level
            if report["move_end_speeds"][-1] > allowed * (1 + 1e-9):
                failures.append(line + f" (speed {report['move_end_speeds'][-1]:.6g} at the last "
                                f"operation, above {allowed:.6g})")
            if kind == "rest_to_rest" and gap > args.max_gap:
                failures.append(line + f" (gap above {args.max_gap})")
        q = quantiles(gaps)
        result[kind] = q
        print(f"{kind}: {q['n']} moves, gap to Ruckig min {q['min']:+.5f} median {q['median']:+.5f} "
              f"p90 {q['p90']:+.5f} max {q['max']:+.5f}")
    result["seed"] = args.seed
    result["max_ops"] = args.max_ops
    if args.json:
        with open(args.json, "w") as f:
            json.dump(result, f, indent=1)
    for f in failures:
        print("FAIL", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
