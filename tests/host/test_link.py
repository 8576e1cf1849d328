"""The guarded session (sw/host/hwinterp_host/link.py) against a scripted
in-process transport that loses, duplicates, delays and mangles packets and
replies (scripted.py), the board's guard modelled by fake_board.FakeBoard:
every guarded packet's writes run exactly once, in order."""
import random

import pytest

from fake_board import FakeBoard
from hwinterp_host import etherbone as eb
from hwinterp_host.gen.regs import link as G
from hwinterp_host.gen.regs import motion as M
from hwinterp_host.link import (LinkDead, OutOfStep, Session, chunk, chunks_of)
from scripted import ScriptedTransport

FIFO_LOW = M.FIFO_LOW.addr


def session(script=(), retry_s=0.05, dead_after_s=1.0, board=None, seed=1, late_s=0.3):
    board = board or FakeBoard()
    t = ScriptedTransport(board, script, late_s=late_s)
    s = Session(t, retry_s=retry_s, dead_after_s=dead_after_s, rng=random.Random(seed), clock=t.clock)
    return s, t, board


def sent_tags(t):
    return [eb.decode(p).record.ret_base for p in t.sent]


def writes_to(board, addr):
    return [v for a, v in board.bus_writes if a == addr]


def test_chunks():
    assert chunk(0x40034, [7]) == [(1 << 24) | (0x40034 >> 2), 7]
    # consecutive addresses share a chunk, a gap starts another
    w = chunks_of([(0x40200, 1), (0x40204, 2), (0x4020C, 3)])
    assert w == [(2 << 24) | 0x10080, 1, 2, (1 << 24) | 0x10083, 3]
    with pytest.raises(ValueError, match="not word aligned"):
        chunk(0x40002, [1])
    with pytest.raises(ValueError, match="64 MiB"):
        chunk(1 << 26, [1])


def test_open_and_packets_carry_seq_and_tags():
    s, t, board = session()
    board.expect = 41
    assert s.open() == 41
    s.transact(chunks_of([(FIFO_LOW, 3)]))
    assert s.seq == 42 and board.expect == 42 and board.accepted == 1
    rec = eb.decode(t.sent[-1]).record
    assert rec.write_base == G.SEQ.addr and rec.writes[0] == 41
    assert rec.reads[0] == G.SEQ.addr                     # EXPECT first
    assert rec.ret_base == s.tag(41, 0)
    assert writes_to(board, FIFO_LOW) == [3]


def test_tags_differ_by_packet_attempt_kind_and_session():
    s, _, _ = session(seed=1)
    tags = {s.tag(n, a, g) for n in (0, 1) for a in (0, 1) for g in (True, False)}
    assert len(tags) == 8
    others = {session(seed=k)[0].session for k in range(40)}
    assert len(others) > 1                              # the session number varies


def test_lost_packet_is_sent_again_and_runs_once():
    s, t, board = session(["ok", "drop_request"])
    s.open()
    s.transact(chunks_of([(FIFO_LOW, 5)]))
    assert t.actions == ["ok", "drop_request", "ok"]
    assert sent_tags(t)[1:] == [s.tag(0, 0), s.tag(0, 1)]
    assert board.accepted == 1 and board.stale == 0
    assert writes_to(board, FIFO_LOW) == [5]
    assert s.counts.retransmits == 1


def test_lost_reply_the_copy_is_refused_and_the_reply_says_taken():
    s, t, board = session(["ok", "drop_reply"])
    s.open()
    s.transact(chunks_of([(FIFO_LOW, 5), (FIFO_LOW + 4, 9)]))
    assert board.accepted == 1 and board.stale == 1
    assert board.dropped == 2                             # the refused copy's two data words
    assert writes_to(board, FIFO_LOW) == [5]              # once
    assert s.seq == 1 and s.counts.retransmits == 1


def test_duplicated_packet_runs_once_and_the_second_reply_is_dropped_later():
    s, t, board = session(["ok", "dup"])
    s.open()
    s.transact(chunks_of([(FIFO_LOW, 1)]))
    assert board.accepted == 1 and board.stale == 1
    s.transact(chunks_of([(FIFO_LOW, 2)]))
    assert writes_to(board, FIFO_LOW) == [1, 2]
    assert s.counts.stale_replies == 1 and s.counts.retransmits == 0


def test_late_reply_is_dropped_and_the_retry_is_taken():
    # attempt 0's reply comes 80 ms late: after the host's 50 ms, during the next packet's wait
    s, t, board = session(["ok", "late", "ok", "drop_request"], late_s=0.08)
    s.open()
    s.transact(chunks_of([(FIFO_LOW, 1)]))       # attempt 0 answered late, attempt 1 on time
    assert s.counts.retransmits == 1 and board.stale == 1
    s.transact(chunks_of([(FIFO_LOW, 2)]))       # its first copy lost: the host waits, the late reply comes
    assert s.counts.stale_replies == 1
    assert writes_to(board, FIFO_LOW) == [1, 2]


def test_mangled_reply_is_counted_and_the_packet_sent_again():
    s, t, board = session(["ok", "mangle"])
    s.open()
    s.transact(chunks_of([(FIFO_LOW, 4)]))
    assert s.counts.malformed == 1 and s.counts.retransmits == 1
    assert writes_to(board, FIFO_LOW) == [4]


def test_a_reply_of_another_session_is_dropped():
    s, t, board = session()
    s.open()
    other = Session(t, rng=random.Random(99))
    while other.session == s.session:
        other = Session(t, rng=random.Random(random.randrange(1000)))
    # a stray reply with the other session's tag for the same n and attempt
    t.queue.append((0.0, eb.encode_reply(other.tag(0, 0), [1])))
    s.transact([])
    assert s.counts.stale_replies == 1 and s.seq == 1


def test_dead_link_names_the_uri_and_the_time_within_the_bound():
    s, t, board = session(["ok"] + ["drop_request"] * 1000, retry_s=0.05, dead_after_s=1.0)
    s.open()
    start = t.clock.now
    with pytest.raises(LinkDead) as e:
        s.transact([])
    waited = t.clock.now - start
    assert 1.0 <= waited <= 1.0 + 0.05 + 1e-9          # dead_after, plus at most one attempt
    assert "udp:fake:1234" in str(e.value) and "no reply for 1.00 s" in str(e.value)
    assert e.value.attempts == 20


def test_out_of_step_when_another_host_took_the_seq():
    s, t, board = session()
    s.open()
    board.expect = 7                                    # another host, or a reset board
    with pytest.raises(OutOfStep, match="expects SEQ 7 after packet 0"):
        s.transact([])


@pytest.mark.parametrize("seed", range(8))
def test_random_faults_every_write_once_in_order(seed):
    rng = random.Random(seed)
    acts = ["ok"] * 6 + ["drop_request", "drop_reply", "dup", "late", "mangle"]
    script = ["ok"] + [rng.choice(acts) for _ in range(600)]
    s, t, board = session(script, seed=seed)
    s.open()
    values = list(range(1, 201))
    for v in values:
        s.transact(chunks_of([(FIFO_LOW, v)]), [M.FIFO_LOW.addr])
    assert writes_to(board, FIFO_LOW) == values
    assert board.accepted == len(values)
    # every copy that reached the board was taken (the first) or refused
    reached = sum({"drop_request": 0, "dup": 2}.get(a, 1) for a in t.actions[1:])
    assert board.accepted + board.stale == reached
    assert s.counts.retransmits > 0 and s.counts.stale_replies > 0
    assert s.counts.packets == len(values)
