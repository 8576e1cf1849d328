#!/usr/bin/env python3
"""The LinuxCNC configuration of one software-in-the-loop run
(scripts/linuxcnc/sil.sh): sw/hal/config/ copied, the board's link (and,
when given, the servo period, the latency and the watchdog) set, the
headless display (scripts/linuxcnc/headless.py) and the run's [SIL] section
added, and sil.hal, which samples each servo period: the joints' commanded
positions, the driver's boundary clock, running, late count, FIFO level,
missed slots and boundary errors (halsampler writes them, one line a
period)."""
import argparse
import configparser
import os
import shutil

SAMPLED = [  # HAL pin or signal (a name without a dot: a signal of hwinterp_mill.hal), type
    ("hwinterp.stepgen.00.steps-cmd", "s"), ("hwinterp.stepgen.01.steps-cmd", "s"),
    ("hwinterp.stepgen.02.steps-cmd", "s"), ("hwinterp.stepgen.03.steps-cmd", "s"),
    ("hwinterp.boundary-clock", "f"), ("hwinterp.running", "b"), ("hwinterp.late-count", "u"),
    ("hwinterp.fifo-level", "u"), ("hwinterp.stats.missed-slots", "u"),
    ("hwinterp.stats.boundary-errors", "u"), ("board-fault", "b"),
    ("hwinterp.stats.retransmits", "u"), ("hwinterp.rtt-us", "f"),
    ("motion.servo.last-period", "u"),
]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--config", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--board", required=True, help="the board's link URI ([HWINTERP]BOARD)")
    ap.add_argument("--servo-period-ns", type=int, default=0, help="[EMCMOT]SERVO_PERIOD (0: kept)")
    ap.add_argument("--latency-ns", type=int, default=0, help="[HWINTERP]LATENCY_NS (0: kept)")
    ap.add_argument("--watchdog-ns", type=int, default=0, help="[HWINTERP]WATCHDOG_NS (0: kept)")
    ap.add_argument("--program", required=True)
    ap.add_argument("--display", required=True)
    ap.add_argument("--fault", default="")
    ap.add_argument("--timeout", type=float, default=900)
    ap.add_argument("--relay-cut", default="")
    a = ap.parse_args()
    if os.path.exists(a.out):
        shutil.rmtree(a.out)
    shutil.copytree(a.config, a.out)
    ini_path = os.path.join(a.out, "hwinterp_mill.ini")
    # LinuxCNC's INI allows repeated keys (HALFILE); configparser does not:
    # the few edits are made on the lines.
    lines = open(ini_path).read().split("\n")
    out, section = [], None
    for line in lines:
        s = line.strip()
        if s.startswith("[") and s.endswith("]"):
            section = s[1:-1]
        key = s.split("=", 1)[0].strip() if "=" in s and not s.startswith("#") else None
        if section == "DISPLAY" and key == "DISPLAY":
            line = f"DISPLAY = {a.display}"
        elif section == "HWINTERP" and key == "BOARD":
            line = f"BOARD = {a.board}"
        elif section == "HWINTERP" and key == "LATENCY_NS" and a.latency_ns:
            line = f"LATENCY_NS = {a.latency_ns}"
        elif section == "HWINTERP" and key == "WATCHDOG_NS" and a.watchdog_ns:
            line = f"WATCHDOG_NS = {a.watchdog_ns}"
        elif section == "EMCMOT" and key == "SERVO_PERIOD" and a.servo_period_ns:
            line = f"SERVO_PERIOD = {a.servo_period_ns}"
        out.append(line)
        if section == "HAL" and key == "HALFILE":
            out.append("HALFILE = sil.hal")
    samples = os.path.join(os.path.dirname(a.out), "samples.txt")
    out += ["", "[SIL]", f"PROGRAM = {a.program}", f"RESULT = {os.path.join(os.path.dirname(a.out), 'linuxcnc.json')}",
            f"SAMPLES = {samples}", f"FAULT = {a.fault}", f"TIMEOUT = {a.timeout}",
            f"RELAY_CUT = {a.relay_cut}", ""]
    with open(ini_path, "w") as f:
        f.write("\n".join(out))
    cfg = "".join(t for _, t in SAMPLED)
    hal = [f"# sampled each servo period for scripts/linuxcnc/sil_report.py, in this order:",
           "# " + " ".join(n for n, _ in SAMPLED),
           f"loadrt sampler depth=16000 cfg={cfg}", "addf sampler.0 servo-thread"]
    for i, (name, _) in enumerate(SAMPLED):
        if "." not in name:
            hal.append(f"net {name} => sampler.0.pin.{i}")
        else:
            hal.append(f"net sil-{i} {name} => sampler.0.pin.{i}")
    with open(os.path.join(a.out, "sil.hal"), "w") as f:
        f.write("\n".join(hal) + "\n")


if __name__ == "__main__":
    main()
