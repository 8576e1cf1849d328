"""Reading the soc-writes file (sw/host/hwinterp_host/program.py): the full
staging values rebuilt from the changed-register writes, each move's
lattice end the sum of its commands' displacements, bad files refused by
name; and the file `hwinterp gcode --soc-writes --plan-only` writes (the
executable from $HWINTERP, as ctest gives it)."""
import json
import os
import subprocess

import pytest

import progs
from hwinterp_host.program import ProgramError, STAGING, displacement, read

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DATA = os.path.join(ROOT, "tests", "data", "gcode")


def hwinterp():
    exe = os.environ.get("HWINTERP", os.path.join(ROOT, "build", "tb", "hwinterp"))
    assert os.access(exe, os.X_OK), f"no hwinterp at {exe} (build it, or set HWINTERP)"
    return exe


def test_full_values_rebuilt(tmp_path):
    j = progs.make([[progs.line(10, 0, -3)], [progs.line(10, 5, -3), progs.line(0, 5, 0)]])
    p = read(progs.write(tmp_path, j))
    idx = {n: i for i, n in enumerate(STAGING)}
    assert len(p.commands) == 3
    # the second command's file entry writes only CMD_DELTA1; its full values keep the others
    assert [w[0] for w in j["commands"][1]] == ["CMD_DELTA1", "CMD_PUSH"]
    c = p.commands[1]
    assert (c[idx["CMD_DELTA0"]], c[idx["CMD_DELTA1"]], c[idx["CMD_DELTA2"]]) == (10, 5, 0xFFFFFFFD)
    assert p.end == [20, 10, -6] and p.move_of_command() == [0, 1, 1]


def test_arc_displacement_on_its_plane(tmp_path):
    # ZX plane: engine x is Z, y is X; Y slaved
    j = progs.make([[progs.arc(1, end=(7, -4), center=(3, 0), ops=20, slaved=[(1, 2)])]])
    p = read(progs.write(tmp_path, j))
    assert displacement(p.commands[0], 3) == [-4, 2, 7]
    assert p.moves[0].end_steps == [-4, 2, 7]


@pytest.mark.parametrize("mutate,msg", [
    (lambda j: j["moves"][1]["end_steps"].__setitem__(0, 99), "move 2 (line 20) ends at"),
    (lambda j: j["moves"][1].__setitem__("first_command", 2), "move 2 starts at command 2"),
    (lambda j: j["commands"][0].pop(), "command 0 has no CMD_PUSH"),
    (lambda j: j["commands"][0].insert(0, ["STATUS", 1]), "writes STATUS, not a staging register"),
    (lambda j: j.pop("widths"), "no 'widths'"),
    (lambda j: j.__setitem__("end", [0, 0, 0]), "the commands end at"),
])
def test_bad_files_are_named(tmp_path, mutate, msg):
    j = progs.make([[progs.line(1, 2, 3)], [progs.line(4, 5, 6)]])
    mutate(j)
    path = progs.write(tmp_path, j)
    with pytest.raises(ProgramError) as e:
        read(path)
    assert msg in str(e.value) and path in str(e.value)


def test_not_json(tmp_path):
    path = tmp_path / "x.json"
    path.write_text("{")
    with pytest.raises(ProgramError, match="not JSON"):
        read(str(path))


def plan_file(tmp_path, program, *args):
    out = str(tmp_path / "w.json")
    r = subprocess.run([hwinterp(), "gcode", os.path.join(DATA, program), *args,
                        "--soc-writes", out, "--plan-only"], capture_output=True, text=True)
    assert r.returncode == 0, r.stdout + r.stderr
    return out


def test_hwinterp_file_arcs(tmp_path):
    """arcs.ngc (lines, arcs in three planes, a helix): every move's lattice
    end is the sum of its commands' displacements (read() checks it), and
    the file says what it was planned for."""
    p = read(plan_file(tmp_path, "arcs.ngc", "--machine", os.path.join(DATA, "machine_default.json")))
    j = p.raw
    assert p.axes == j["widths"]["axes"] and p.widths["pos_w"] > 0 and p.clock_hz > 0
    assert sum(m.commands for m in p.moves) == len(p.commands) == j["totals"]["commands"]
    assert len(p.moves) == j["totals"]["moves"]
    assert any(c[STAGING.index("CMD_FLAGS")] & 1 for c in p.commands)      # arcs among them
    assert not p.profiled


def test_hwinterp_file_with_the_profile(tmp_path):
    p = read(plan_file(tmp_path, "corners.ngc", "--machine",
                       os.path.join(DATA, "machine_profile.json"), "--profile", "scurve"))
    pr = p.profile
    assert pr["kind"] == "scurve" and pr["q"] > 0 and pr["len"] >= 1
    assert (pr["spd_w"], pr["tick_w"], pr["len_w"], pr["lvl_w"]) == (48, 10, 10, 16)
    ops, feed = STAGING.index("CMD_MV_OPS"), STAGING.index("CMD_FEED")
    assert all(c[ops] >= 1 for c in p.commands) and all(c[feed] == 0 for c in p.commands)
    assert p.commands[-1][STAGING.index("CMD_MV_END")] == 0      # the program ends at rest
