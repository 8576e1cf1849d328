# The link under faults the simulated board injects (docs/link.md): dropped,
# corrupted, duplicated and reordered Ethernet frames, dropped, corrupted and
# duplicated UART bytes, both ways. A part program streamed through them
# must still reach exactly the lockstep's lattice points, every command
# pushed once: nothing lost, nothing doubled. The program is many short
# moves, so that little board time takes many packets. The boards run at the
# slow clocks of their extra sim builds (cmake/cores.cmake) in the suite, and
# at their own clocks, the gateware as flashed, under the `long` mark (ctest
# label long: board_pytest_long). A UART fault rate is per byte: a packet of
# 200 stream words is about 1000 bytes, so 0.0007 of each kind spoils one
# attempt in four.
import json
import os

import pytest

from conftest import DATA, host
from test_stream import check_run

CASES = [
    # board, clock, machine, faults (per UDP frame / per UART byte), seed
    ("colorlight_5a_75b", 1000000, "machine_1mhz.json", "drop=0.08,corrupt=0.08,dup=0.08,reorder=0.08", 3),
    ("tang_nano_20k", 2000000, "machine_2mhz.json", "drop=0.0007,corrupt=0.0007,dup=0.0007", 5),
    pytest.param("colorlight_5a_75b", None, "machine_50mhz.json",
                 "drop=0.08,corrupt=0.08,dup=0.08,reorder=0.08", 3, marks=pytest.mark.long),
    pytest.param("tang_nano_20k", None, "machine_27mhz.json",
                 "drop=0.0007,corrupt=0.0007,dup=0.0007", 5, marks=pytest.mark.long),
]


@pytest.mark.parametrize("board,clock,machine,faults,seed", CASES)
def test_nothing_lost_nothing_doubled(tmp_path, board_sim, board, clock, machine, faults, seed):
    tmp = str(tmp_path)
    program = os.path.join(DATA, "many_short.ngc")
    mfile = os.path.join(DATA, machine)
    sim = board_sim(board, clock_hz=clock, faults=faults, seed=seed)
    report = os.path.join(tmp, "run.json")
    run = host("run", program, "--machine", mfile, "--board", sim.uri, "--json", report,
               "--progress", "0", "--timeout-ms", "60000", "--retry-ms", "300",
               "--watchdog-ms", "0")
    check_run(tmp, sim, program, mfile, run)
    with open(report) as f:
        r = json.load(f)["board"]
    link = sim.report["link"]
    # Every kind of fault asked for happened, both ways.
    for way in ("faults_to_board", "faults_to_host"):
        for kind, key in (("drop", "dropped"), ("corrupt", "corrupted"), ("dup", "duplicated"),
                          ("reorder", "reordered")):
            if kind + "=" in faults:
                assert link[way][key] > 0, (way, kind, link[way])
    # ... and the host's recovery shows: retransmits, and copies the guard refused.
    assert r["link_counts"]["retransmits"] > 0
    assert r["guard"]["stale"] > 0
    assert r["pushed"] == sim.report["commands_completed"]
