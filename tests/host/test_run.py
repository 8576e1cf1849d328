"""The stager (only the registers that change; all of them first) and the
run (sw/host/hwinterp_host/run.py) against the board stand-in
(fake_board.FakeBoard) through the scripted transport: never a push
without room, the FIFO refilled at its low-water mark, the final position
checked, aborts, watchdog bites, a busy board, the board checks."""
import random

import pytest

import progs
from fake_board import FakeBoard
from hwinterp_host.board import Board, Stager, read_id
from hwinterp_host.gen.regs import motion as M
from hwinterp_host.link import Session
from hwinterp_host.program import STAGING, read
from hwinterp_host.run import BoardMismatch, Controls, RunOptions, Runner, check_board
from scripted import ScriptedTransport

STAGE_ADDRS = {M.reg(n).addr for n in STAGING}


def program(tmp_path, n=40, axes=3, **kw):
    rng = random.Random(n)
    moves = []
    for k in range(n):
        if k % 7 == 3:
            moves.append([progs.arc(0, end=(rng.randrange(-50, 50), rng.randrange(-50, 50)),
                                    center=(20, 0), ops=80, slaved=[(2, rng.randrange(-5, 6))])])
        else:
            moves.append([progs.line(*[rng.choice([0, 0, rng.randrange(-300, 300)]) for _ in range(axes)])
                          for _ in range(rng.choice([1, 1, 2]))])
    return read(progs.write(tmp_path, progs.make(moves, axes=axes, **kw)))


def setup(tmp_path, script=(), board=None, prog=None, controls=None, **opts):
    board = board or FakeBoard(depth=8, cmd_clocks=300, clocks_per_packet=100)
    t = ScriptedTransport(board, script)
    s = Session(t, retry_s=0.05, dead_after_s=1.0, rng=random.Random(3), clock=t.clock)
    ident = read_id(s)
    prog = prog or program(tmp_path)
    o = RunOptions(**opts)
    r = Runner(Board(s, ident), prog, o, controls, poll_input=lambda sec: None, clock=t.clock)
    return r, board, t, prog


def test_stager_writes_what_changed_and_everything_first():
    st = Stager(3, profile=False)
    assert not any(n.startswith("CMD_MV_") for n in st.names) and "CMD_DELTA3" not in st.names
    cmd = [0] * len(STAGING)
    cmd[STAGING.index("CMD_DELTA0")] = 5
    first = st.writes(cmd)
    assert [a for a, _ in first] == [M.reg(n).addr for n in st.names] + [M.CMD_PUSH.addr]
    st.commit(cmd)
    cmd2 = list(cmd)
    cmd2[STAGING.index("CMD_DELTA2")] = 7
    assert st.writes(cmd2) == [(M.CMD_DELTA2.addr, 7), (M.CMD_PUSH.addr, 1)]
    st.commit(cmd2)
    assert st.writes(cmd2) == [(M.CMD_PUSH.addr, 1)]          # the same command again: a push alone
    st.forget()
    assert len(st.writes(cmd2)) == len(st.names) + 1
    assert {"CMD_MV_OPS", "CMD_MV_MAX"} <= set(Stager(3, profile=True).names)


def test_run_reaches_the_end_without_a_push_beyond_the_room(tmp_path):
    r, board, t, prog = setup(tmp_path)
    res = r.run()
    assert res.passed, res.failure
    assert board.pushes == len(prog.commands) == res.pushed
    assert board.events & M.EVENTS.f.overflow.mask == 0
    assert board.pos == prog.end and res.moved == prog.end
    # the FIFO (8) refilled at its mark (4): far fewer refills than commands
    assert 1 < res.refills < len(prog.commands)
    # the stager wrote each staging register only when its value changed
    staging_writes = [(a, v) for a, v in board.bus_writes if a in STAGE_ADDRS]
    held = {}
    for a, v in staging_writes:
        assert held.get(a) != v
        held[a] = v
    # every packet kicked the watchdog, and it is off at the end
    assert board.regs[M.WDOG_PERIOD.addr] == 0
    kicks = sum(1 for a, _ in board.bus_writes if a == M.WDOG_KICK.addr)
    assert kicks >= res.packets


def test_an_earlier_runs_staging_is_overwritten(tmp_path):
    """The board's staging registers hold what a previous run left: the
    first command writes every one of them."""
    board = FakeBoard(depth=8, cmd_clocks=300, clocks_per_packet=100)
    for i in range(3):
        board.regs[M.CMD_DELTA[i].addr] = 12345
    board.regs[M.CMD_FLAGS.addr] = 1
    r, board, t, prog = setup(tmp_path, board=board)
    res = r.run()
    assert res.passed, res.failure
    assert board.pos == prog.end


def test_run_with_lost_and_late_packets(tmp_path):
    rng = random.Random(5)
    script = ["ok"] * 3 + [rng.choice(["ok"] * 5 + ["drop_request", "drop_reply", "dup", "late"])
                           for _ in range(3000)]
    r, board, t, prog = setup(tmp_path, script)
    res = r.run()
    assert res.passed, res.failure
    assert board.pushes == len(prog.commands) and board.pos == prog.end
    assert r.b.s.counts.retransmits > 0


def test_small_room_big_packets(tmp_path):
    """A FIFO of 2: every refill limited by the room, never beyond it."""
    board = FakeBoard(depth=2, cmd_clocks=150, clocks_per_packet=100)
    r, board, t, prog = setup(tmp_path, board=board, fifo_low=0)
    res = r.run()
    assert res.passed, res.failure
    assert board.events & M.EVENTS.f.overflow.mask == 0 and res.full_polls > 0


def test_abort_from_the_controls(tmp_path):
    ctl = Controls()
    r, board, t, prog = setup(tmp_path, controls=ctl)
    calls = {"n": 0}

    def progress(info):
        calls["n"] += 1
        if calls["n"] == 5:
            ctl.request_abort("SIGINT")
    r.progress = progress
    res = r.run()
    assert res.aborted and not res.passed and res.failure == "SIGINT"
    assert any(a == M.CTRL.addr for a, _ in board.bus_writes)
    assert not board.fifo and board.current is None
    assert board.pushes < len(prog.commands)


def test_watchdog_bite_fails_the_run_naming_it(tmp_path):
    # a watchdog of 0.004 ms = 200 clocks at 50 MHz, packets 500 clocks apart
    board = FakeBoard(depth=8, cmd_clocks=300, clocks_per_packet=500)
    r, board, t, prog = setup(tmp_path, board=board, watchdog_ms=0.004)
    res = r.run()
    assert not res.passed and "EVENTS.wdog" in res.failure


def test_a_busy_board_is_not_joined(tmp_path):
    board = FakeBoard(depth=8, cmd_clocks=10**9)
    board.regs[M.CMD_DELTA0.addr] = 1
    board.bus_write(M.CMD_PUSH.addr, 1)
    r, board, t, prog = setup(tmp_path, board=board)
    res = r.run()
    assert not res.passed and "the board is busy" in res.failure and "hwinterp-host abort" in res.failure


def test_final_position_off_fails(tmp_path):
    r, board, t, prog = setup(tmp_path)
    orig = board.displacement
    board.displacement = lambda c: [d + 1 for d in orig(c)]   # a board that steps one too far
    res = r.run()
    assert res.completed and not res.passed and "the program's lattice end" in res.failure


def test_hold_and_override_writes(tmp_path):
    ctl = Controls()
    board = FakeBoard(depth=8, cmd_clocks=300, clocks_per_packet=100, profile=True)
    prof = {"kind": "scurve", "q": 1 << 40, "len": 8, "spd_w": 48, "tick_w": 10, "len_w": 10, "lvl_w": 16}
    prog = program(tmp_path, profile=prof)
    r, board, t, prog = setup(tmp_path, board=board, prog=prog, controls=ctl)
    seen = []

    def progress(info):
        seen.append(info)
        if len(seen) == 3:
            ctl.toggle_hold += 1
            ctl.ovr_steps += 2
        if len(seen) == 30:
            ctl.toggle_hold += 1
    r.progress = progress
    res = r.run()
    assert res.passed, res.failure
    prof_ctrl = [v for a, v in board.bus_writes if a == M.PROF_CTRL.addr]
    f = M.PROF_CTRL.f
    assert (f.hold.get(prof_ctrl[1]), f.ovr.get(prof_ctrl[1])) == (1, round(120 * 128 / 100))
    assert (f.hold.get(prof_ctrl[2]), f.ovr.get(prof_ctrl[2])) == (0, round(120 * 128 / 100))
    assert res.holds == 1 and res.overrides and res.overrides[0][1] == 120
    assert board.regs[M.PROF_Q.addr] == 0 and board.regs[M.PROF_Q.addr + 4] == 1 << 8
    assert board.regs[M.PROF_LEN.addr] == 8


@pytest.mark.parametrize("change,msg", [
    (dict(axes=4), "ID_BUILD.axes 4, the program was compiled for 3"),
    (dict(widths=dict(acc_w=15, coord_w=24, ops_w=28, pos_w=32, tim_w=16, feed_w=24)), "ID_WIDTHS.acc_w 15"),
    (dict(widths=dict(acc_w=32, coord_w=24, ops_w=28, pos_w=32, tim_w=16, feed_w=16)), "ID_WIDTHS2.feed_w 16"),
    (dict(clock_hz=25_000_000), "ID_CLOCK 25000000 Hz, the machine file says clock_hz 50000000"),
])
def test_board_checks_name_the_value(tmp_path, change, msg):
    board = FakeBoard(**change)
    t = ScriptedTransport(board)
    ident = read_id(Session(t, clock=t.clock))
    with pytest.raises(BoardMismatch) as e:
        check_board(ident, program(tmp_path, n=3), "udp:fake:1234")
    assert msg in str(e.value) and "udp:fake:1234" in str(e.value)


def test_board_checks_profile(tmp_path):
    prof = {"kind": "scurve", "q": 1, "len": 1, "spd_w": 48, "tick_w": 10, "len_w": 10, "lvl_w": 16}
    p = program(tmp_path, n=3, profile=prof)
    for board, msg in ((FakeBoard(profile=False), "ID_BUILD.profile 0"),):
        t = ScriptedTransport(board)
        with pytest.raises(BoardMismatch, match=msg):
            check_board(read_id(Session(t, clock=t.clock)), p, "udp:x")
    t = ScriptedTransport(FakeBoard(profile=True))
    check_board(read_id(Session(t, clock=t.clock)), p, "udp:x")
    p.profile["tick_w"] = 8
    with pytest.raises(BoardMismatch, match="ID_PROFILE.tick_w 10, the profile was planned for 8"):
        check_board(read_id(Session(t, clock=t.clock)), p, "udp:x")
