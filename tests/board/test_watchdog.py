# The watchdog on the simulated board (docs/boards.md): the host dies in the
# middle of a long move at cruise; the board stops by itself (the bite P+1
# clocks after the last kick is rtl/formal's proof, not this test's): the feed
# profile brings the axes to rest in a controlled stop bounded by an S-curve
# stop from the move's feed at the profile's limits, no step comes after the
# rest, and the bite does not re-arm by itself (LiteX-CNC #119): the board
# stays at rest.
import json
import os
import signal
import subprocess
import sys
import time

from conftest import DATA, ROOT, hwinterp_exe


def test_host_killed_mid_move_the_board_stops(tmp_path, board_sim):
    tmp = str(tmp_path)
    program = os.path.join(DATA, "long_line.ngc")      # G1 X400 F3000: 8 s at cruise
    mfile = os.path.join(DATA, "machine_1mhz.json")
    with open(mfile) as f:
        machine = json.load(f)
    hz = machine["clock_hz"]
    # The board runs 4 s of board time, then stops by itself: the checks
    # below count board clocks, not wall time (a loaded machine simulates
    # slower).
    sim = board_sim("colorlight_5a_75b", clock_hz=hz, max_clocks=4 * hz)
    wd_ms = 20.0
    env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "sw", "host"), HWINTERP=hwinterp_exe())
    proc = subprocess.Popen([sys.executable, "-m", "hwinterp_host", "run", program, "--machine",
                             mfile, "--board", sim.uri, "--progress", "0",
                             "--watchdog-ms", str(wd_ms)],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    # Wait until the board is moving (its steps CSV grows), then a while at cruise.
    deadline = time.time() + 60
    while not (os.path.exists(sim.steps) and os.path.getsize(sim.steps) > 20000):
        assert proc.poll() is None, "the host ended before the board moved"
        assert time.time() < deadline, "the board did not move"
        time.sleep(0.05)
    time.sleep(0.5)
    proc.send_signal(signal.SIGKILL)
    proc.wait()
    # The board goes on to its 4 s: the bite, the stop and well after it.
    sim.proc.wait(timeout=600)
    assert sim.stop() == 0, sim.report
    r = sim.report
    assert r["timing_violations"] == 0
    bites = r["watchdog_bites"]
    assert len(bites) == 1, bites                    # bitten once, never re-armed
    b = bites[0]
    assert b["rest_clock"] is not None, b            # it came to rest
    assert b["steps_after_rest"] == 0, b             # ... and stayed there
    assert b["steps_to_rest"] > 0, b                 # it was moving when bitten
    assert r["last_step_clock"] <= b["rest_clock"]
    assert r["clocks"] > b["rest_clock"] + hz        # a second of board time at rest, watched
    # The stop, against an S-curve stop from F3000 (50 mm/s) at the profile's
    # acceleration and jerk (the plan's, in steps: 0.8 of X's limits, the jerk
    # tick-quantized), v/a + a/j: never faster (no limit broken), and at most
    # a quarter longer plus two ticks (the hold ruling from the next tick
    # boundary). Measured: 49985 clocks against 41490 (1.20), see docs/boards.md.
    plan = subprocess.run([sys.executable, "-m", "hwinterp_host", "plan", program, "--machine",
                           mfile, "--json"], capture_output=True, text=True, env=env, check=True)
    prof = json.loads(plan.stdout)["profile"]
    v = 3000 / 60.0 * machine["steps_per_unit"]["X"]
    ideal = (v / prof["accel"] + prof["accel"] / prof["jerk"]) * hz
    tick = 1 << prof["tick_w"]
    assert ideal - tick <= b["stop_clocks"] <= 1.25 * ideal + 2 * tick, (b, ideal)
