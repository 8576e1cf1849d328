#!/usr/bin/env python3
"""The host link's throughput on the simulated boards (docs/boards.md).

Usage: scripts/board_link_bench.py [--cases LIST] [--moves N] [--json FILE]
                                   [--hwinterp PATH]

  --cases LIST  comma-separated BOARD@HZ[/noprofile], builds `hwinterp
                board-sim --list` holds (default: the slow builds without
                the profile, colorlight_5a_75b@1000000/noprofile,
                tang_nano_20k@2000000/noprofile)
  --moves N     the program's moves (default 2000)
  --json FILE   write the figures there (docs/data/board_link.json)

For each case: `hwinterp board-sim` serves the board's gateware, and
`hwinterp-host run` streams a program of N collinear X moves at F3000
(50 mm/s) planned for a machine file at the board's clock, twice: moves of
0.05 mm (a move each 1 ms: the FIFO consumes 1000 commands a second of
machine time) and of 0.005 mm (0.1 ms: 10000 a second, more than a link
carries, so the machine time shows what the link delivered).
Without the profile FEED drives the feed and the moves run at F back to
back; with it, today's planner takes each of these short moves nearly from
rest (docs/boards.md), so the machine, not the link, sets the pace. The
figures come from the host's report and the board's: commands pushed,
packets, words and link bytes, the machine time from the board's TIME
against the plan's, the polls that found the FIFO full (the link ahead of the
machine), and the simulator's speed. From them, what the link could carry:

  UART      bytes on the wire each way per command (the host's transport
            counts) at the board's baud rate, 10 bits a byte: the rate the
            wire allows, each packet's reply included;
  Etherbone commands per packet (at most 248 words a record) times the
            packets a second one exchange a packet allows: on the simulated
            board the exchange is the host's turnaround in wall time plus
            the board's clocks, which is no figure for a real network; it is
            given per packet, in board clocks, for the board's side.

A board's own clock simulates slowly (a few hundred thousand clocks a
second): a case takes minutes. Exit 1 when a run did not pass.
"""

from __future__ import annotations

import argparse
import datetime
import json
import os
import signal
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MACHINE = {
    "axes": ["X", "Y", "Z", "A"],
    "steps_per_unit": {"X": 1000, "Y": 1000, "Z": 1000, "A": 100},
    "timing_clocks": {"step_len": 2, "step_space": 2, "dir_setup": 3, "dir_hold": 3},
    "max_velocity": {"X": 100, "Y": 100, "Z": 50, "A": 360},
    "max_accel": {"X": 2000, "Y": 2000, "Z": 1000, "A": 3600},
    "max_jerk": {"X": 200000, "Y": 200000, "Z": 100000, "A": 360000},
    "profile": "scurve",
}
FEED = 3000
MOVE_S = (1e-3, 1e-4)


def usage(msg):
    sys.stderr.write(f"board_link_bench: {msg}\n")
    sys.exit(2)


def parse_cases(text):
    cases = []
    for item in text.split(","):
        spec, slash, flag = item.partition("/")
        if slash and flag != "noprofile":
            usage(f"--cases: '{item}': '/{flag}' is not /noprofile")
        board, sep, hz = spec.partition("@")
        if not sep or not board:
            usage(f"--cases: '{item}' is not BOARD@HZ")
        try:
            hz_i = int(hz)
        except ValueError:
            usage(f"--cases: '{item}': the clock '{hz}' is not an integer")
        if hz_i <= 0:
            usage(f"--cases: '{item}': the clock must be positive")
        cases.append((board, hz_i, bool(slash)))
    return cases


def git_head():
    r = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True,
                       text=True)
    return r.stdout.strip() or "unknown"


def run_case(exe, board, hz, no_profile, moves, move_s, tmp):
    step_mm = FEED / 60.0 * move_s
    program = os.path.join(tmp, "collinear.ngc")
    with open(program, "w") as f:
        f.write(f"%\n(collinear X moves, {move_s * 1e3:g} ms each at F{FEED})\nG21 G91 G17\n")
        f.writelines(f"G1 X{step_mm:.4f} F{FEED}\n" for _ in range(moves))
        f.write("M2\n%\n")
    machine = os.path.join(tmp, "machine.json")
    with open(machine, "w") as f:
        json.dump(dict(MACHINE, clock_hz=hz, profile="off" if no_profile else "scurve"), f)
    uri_file = os.path.join(tmp, f"{board}.uri")
    sim_json = os.path.join(tmp, f"{board}.sim.json")
    run_json = os.path.join(tmp, f"{board}.run.json")
    log = open(os.path.join(tmp, f"{board}.sim.log"), "w")
    sim = subprocess.Popen([exe, "board-sim", "--board", board, "--clock-hz", str(hz),
                            "--uri-file", uri_file, "--json", sim_json, "--progress", "60"]
                           + (["--no-profile"] if no_profile else []),
                           stdout=log, stderr=subprocess.STDOUT)
    try:
        deadline = time.time() + 60
        while not (os.path.exists(uri_file) and open(uri_file).read().strip()):
            if sim.poll() is not None or time.time() > deadline:
                raise RuntimeError(f"{board}: board-sim did not start (see {log.name})")
            time.sleep(0.05)
        uri = open(uri_file).read().strip()
        env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "sw", "host"), HWINTERP=exe)
        t0 = time.time()
        host = subprocess.run([sys.executable, "-m", "hwinterp_host", "run", program, "--machine",
                               machine, "--board", uri, "--json", run_json, "--progress", "0",
                               "--timeout-ms", "120000"], capture_output=True, text=True, env=env)
        wall = time.time() - t0
    finally:
        if sim.poll() is None:
            sim.send_signal(signal.SIGTERM)
        sim.wait(timeout=120)
        log.close()
    if host.returncode != 0:
        sys.stderr.write(host.stdout + host.stderr)
    with open(run_json) as f:
        run = json.load(f)
    with open(sim_json) as f:
        simr = json.load(f)
    b = run["board"]
    tc = b.get("transport_counts", {})
    out = {
        "board": board, "sys_hz": hz, "profile": not no_profile, "link": "uart" if uri.startswith("serial:") else "etherbone",
        "moves": moves, "move_s": move_s,
        "passed": bool(run["passed"]) and host.returncode == 0 and simr.get("timing_violations") == 0,
        "pushed": b["pushed"], "packets": b["packets"], "full_polls": b["full_polls"],
        "refills": b["refills"], "machine_time_s": b["time_s"],
        "planned_time_s": run["programmed_time_s"],
        "commands_per_machine_s": b["pushed"] / b["time_s"] if b["time_s"] else 0.0,
        "transport_counts": tc, "link_counts": b.get("link_counts", {}),
        "sim_clocks_per_s": simr["clocks_per_second"], "wall_s": wall,
        "baud": None,
    }
    if uri.startswith("serial:"):
        baud = int(uri.rsplit("@", 1)[1]) if "@" in uri else None
        out["baud"] = baud
        sent, received = tc.get("bytes_sent", 0), tc.get("bytes_received", 0)
        if baud and b["pushed"]:
            per_cmd = max(sent, received) / b["pushed"]
            out["bytes_per_command"] = per_cmd
            out["wire_commands_per_s"] = baud / 10.0 / per_cmd
    else:
        out["commands_per_packet"] = b["pushed"] / b["packets"] if b["packets"] else 0.0
    return out


def main(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--cases", default="colorlight_5a_75b@1000000/noprofile,"
                                      "tang_nano_20k@2000000/noprofile")
    p.add_argument("--moves", type=int, default=2000)
    p.add_argument("--json")
    p.add_argument("--hwinterp", default=os.environ.get(
        "HWINTERP", os.path.join(os.environ.get("HWINTERP_BUILD_DIR", os.path.join(ROOT, "build")),
                                 "tb", "hwinterp")))
    a = p.parse_args(argv)
    if a.moves < 1:
        usage(f"--moves {a.moves}: must be >= 1")
    if not os.path.exists(a.hwinterp):
        usage(f"no hwinterp at {a.hwinterp}: build it (scripts/build.sh) or give --hwinterp")
    cases = parse_cases(a.cases)
    results = []
    with tempfile.TemporaryDirectory(prefix="board_link_bench.") as tmp:
        for board, hz, no_profile in cases:
            for move_s in MOVE_S:
                d = os.path.join(tmp, f"{board}_{hz}_{int(no_profile)}_{move_s:g}")
                os.makedirs(d)
                sys.stderr.write(f"board_link_bench: {board} at {hz} Hz"
                                 f"{' without the profile' if no_profile else ''}, {a.moves} moves "
                                 f"of {move_s * 1e3:g} ms ...\n")
                r = run_case(a.hwinterp, board, hz, no_profile, a.moves, move_s, d)
                results.append(r)
                sys.stderr.write(json.dumps(r) + "\n")
    doc = {
        "what": "the host link streaming 1 ms moves into the simulated boards",
        "command": "scripts/board_link_bench.py" + ("" if a.cases == p.get_default("cases")
                                                    else f" --cases {a.cases}")
                   + (f" --moves {a.moves}" if a.moves != 2000 else "")
                   + (f" --json {a.json}" if a.json else ""),
        "date": datetime.date.today().isoformat(),
        "commit": git_head(),
        "cases": results,
    }
    if a.json:
        with open(a.json, "w") as f:
            json.dump(doc, f, indent=1)
            f.write("\n")
    else:
        json.dump(doc, sys.stdout, indent=1)
        print()
    return 0 if all(r["passed"] for r in results) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
