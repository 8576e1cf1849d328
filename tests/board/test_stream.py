# Part programs streamed by hwinterp-host into the simulated boards reach the
# lattice points hwinterp gcode --mode direct visits, move by move: over
# Etherbone/UDP (the Colorlight 5A-75B's gateware at 1 MHz) and over the
# UART (the Tang Nano 20K's at 2 MHz, 250 kbaud).
import json
import os

import pytest

from conftest import DATA, gcode_direct, host
from lattice import board_move_ends, first_difference, move_ends, points

CASES = [
    ("colorlight_5a_75b", 1_000_000, "machine_1mhz.json", False),
    ("tang_nano_20k", 2_000_000, "machine_2mhz.json", False),
    # the HX8K's kind of build: FEED drives the feed (no profile on the board)
    ("colorlight_5a_75b", 1_000_000, "machine_1mhz.json", True),
]


def check_run(tmp, sim, program, machine, run):
    """The host's run passed and the board's pins visited the lockstep's points."""
    assert run.returncode == 0, run.stdout + run.stderr
    assert sim.stop() == 0, sim.report
    axes = len(sim.report["steps"])
    steps, moves_csv = gcode_direct(tmp, program, machine)
    lock = points(steps, axes)
    board = points(sim.steps, axes)
    assert len(lock) > 10
    d = first_difference(lock, board)
    assert d is None, (f"lattice points differ at {d}: lockstep {lock[d:d + 3]}, "
                       f"board {board[d:d + 3]} ({len(lock)} against {len(board)})")
    moves = move_ends(moves_csv, axes)
    ends = board_move_ends(sim.commands, moves, axes)
    assert sim.report["commands_completed"] == sum(n for n, _ in moves)
    for i, ((_, want), got) in enumerate(zip(moves, ends)):
        assert got == want, f"move {i + 1}: the board ended at {got}, the lockstep at {want}"
    assert sim.report["timing_violations"] == 0
    return moves


@pytest.mark.parametrize("board,clock,machine,no_profile", CASES)
def test_program_reaches_the_lockstep_lattice(tmp_path, board_sim, board, clock, machine,
                                              no_profile):
    tmp = str(tmp_path)
    program = os.path.join(DATA, "lines_arcs.ngc")
    mfile = os.path.join(DATA, machine)
    if no_profile:
        with open(mfile) as f:
            m = json.load(f)
        m["profile"] = "off"
        mfile = os.path.join(tmp, "machine_off.json")
        with open(mfile, "w") as f:
            json.dump(m, f)
    sim = board_sim(board, clock_hz=clock, no_profile=no_profile)
    report = os.path.join(tmp, "run.json")
    run = host("run", program, "--machine", mfile, "--board", sim.uri, "--json", report,
               "--moves-csv", os.path.join(tmp, "run.moves.csv"), "--progress", "0",
               "--timeout-ms", "30000", "--retry-ms", "500")
    moves = check_run(tmp, sim, program, mfile, run)
    with open(report) as f:
        r = json.load(f)
    assert r["passed"] and r["board"]["completed"]
    assert r["end_position"] == list(moves[-1][1])
    # The host's moves CSV has hwinterp gcode's columns and the same lattice ends.
    with open(os.path.join(tmp, "run.moves.csv")) as f:
        head = f.readline().strip().split(",")
    assert head[:7] == ["move", "line", "kind", "x_mm", "y_mm", "z_mm", "a_deg"]
