# The simulated boards' end-to-end tests (docs/boards.md): `hwinterp
# board-sim` serving a board's gateware on this machine, the host package
# (sw/host) streaming part programs into it, and what the board's pins did
# compared with `hwinterp gcode --mode direct` on the same program.
import json
import os
import signal
import subprocess
import sys
import time

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DATA = os.path.join(ROOT, "tests", "data", "board")
sys.path.insert(0, os.path.join(ROOT, "sw", "host"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))


def hwinterp_exe():
    exe = os.environ.get("HWINTERP", os.path.join(ROOT, "build", "tb", "hwinterp"))
    if not os.path.exists(exe):
        pytest.fail(f"no hwinterp at {exe}: build it (scripts/build.sh) or set HWINTERP")
    return exe


class BoardSim:
    """`hwinterp board-sim` in the background: start, its URI, stop, its report."""

    def __init__(self, tmp, board, clock_hz=None, faults=None, seed=1, no_profile=False,
                 max_clocks=None):
        self.tmp = tmp
        self.uri_file = os.path.join(tmp, f"{board}.uri")
        self.json = os.path.join(tmp, f"{board}.sim.json")
        self.steps = os.path.join(tmp, f"{board}.steps.csv")
        self.commands = os.path.join(tmp, f"{board}.commands.csv")
        cmd = [hwinterp_exe(), "board-sim", "--board", board, "--uri-file", self.uri_file,
               "--json", self.json, "--steps-csv", self.steps, "--commands-csv", self.commands,
               "--progress", "0", "--fault-seed", str(seed)]
        if clock_hz:
            cmd += ["--clock-hz", str(clock_hz)]
        if faults:
            cmd += ["--faults", faults]
        if no_profile:
            cmd += ["--no-profile"]
        if max_clocks:
            cmd += ["--max-clocks", str(max_clocks)]
        self.log = open(os.path.join(tmp, f"{board}.sim.log"), "w")
        self.proc = subprocess.Popen(cmd, stdout=self.log, stderr=subprocess.STDOUT)
        deadline = time.time() + 30
        while not (os.path.exists(self.uri_file) and open(self.uri_file).read().strip()):
            if self.proc.poll() is not None or time.time() > deadline:
                self.log.flush()
                raise RuntimeError("board-sim did not start: " +
                                   open(os.path.join(tmp, f"{board}.sim.log")).read())
            time.sleep(0.05)
        self.uri = open(self.uri_file).read().strip()
        self.report = None

    def run_for(self, seconds):
        time.sleep(seconds)

    def stop(self):
        """SIGTERM, then its report (and exit code: 0 passed, 1 a check failed)."""
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGTERM)
        rc = self.proc.wait(timeout=60)
        self.log.close()
        with open(self.json) as f:
            self.report = json.load(f)
        return rc


def pytest_configure(config):
    config.addinivalue_line("markers", "long: a board at its own clock (minutes): "
                            "ctest -L long runs them, scripts/test.sh does not")


@pytest.fixture
def board_sim(tmp_path):
    sims = []

    def start(board, **kw):
        s = BoardSim(str(tmp_path), board, **kw)
        sims.append(s)
        return s

    yield start
    for s in sims:
        if s.proc.poll() is None:
            s.proc.kill()
            s.proc.wait()


def host(*args, timeout=600):
    """hwinterp-host (the package from this tree) with its output."""
    cmd = [sys.executable, "-m", "hwinterp_host", *args]
    env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "sw", "host"), HWINTERP=hwinterp_exe())
    return subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, env=env)


def gcode_direct(tmp, program, machine):
    """`hwinterp gcode --mode direct`: its step times and moves."""
    steps = os.path.join(tmp, "lockstep.steps.csv")
    moves = os.path.join(tmp, "lockstep.moves.csv")
    r = subprocess.run([hwinterp_exe(), "gcode", program, "--machine", machine, "--mode", "direct",
                        "--feed", "programmed", "--progress", "0", "--step-times", steps,
                        "--moves-csv", moves], capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stdout + r.stderr
    return steps, moves
