"""hwinterp-host's command line (sw/host/hwinterp_host/cli.py): bad input
exits 2 with one line naming the value; a link that does not answer exits
1 naming the URI and the time waited; and a whole `run` of a program
planned by the real hwinterp against the board stand-in on a UDP socket,
its moves CSV the same rows as `hwinterp gcode --moves-csv` gives."""
import csv
import json
import os
import socket
import subprocess
import sys
import threading

import pytest

from fake_board import FakeBoard
from hwinterp_host import framing
from hwinterp_host.cli import main
from hwinterp_host.gen.regs import motion as M

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DATA = os.path.join(ROOT, "tests", "data", "gcode")
NGC = os.path.join(DATA, "modal.ngc")
MACHINE = os.path.join(DATA, "machine_default.json")


def hwinterp():
    exe = os.environ.get("HWINTERP", os.path.join(ROOT, "build", "tb", "hwinterp"))
    assert os.access(exe, os.X_OK), f"no hwinterp at {exe} (build it, or set HWINTERP)"
    return exe


def dead_port():
    s = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    s.bind(("127.0.0.1", 0))
    port = s.getsockname()[1]
    return s, port     # bound, never read: nothing answers


def one_line(err):
    lines = [l for l in err.splitlines() if l.strip()]
    assert len(lines) == 1, err
    return lines[0]


@pytest.mark.parametrize("argv,msg", [
    (["info", "bogus"], "link URI 'bogus': no scheme"),
    (["status", "udp:host:99999"], "port '99999' is not 1..65535"),
    (["run", NGC, "--machine", MACHINE, "--board", "tcp:x"], "unknown scheme 'tcp'"),
    (["run", "/no/such.ngc", "--machine", MACHINE, "--board", "udp:h"], "PROG: no file '/no/such.ngc'"),
    (["run", NGC, "--machine", "/no/m.json", "--board", "udp:h"], "--machine: no file '/no/m.json'"),
    (["run", NGC, "--machine", MACHINE, "--board", "udp:h", "--profile", "jerky"],
     "argument --profile: invalid choice: 'jerky'"),
    (["run", NGC, "--board", "udp:h"], "the following arguments are required: --machine"),
    (["run", NGC, "--machine", MACHINE, "--board", "udp:h", "--hwinterp", "/no/hwinterp"],
     "no hwinterp executable at /no/hwinterp"),
    (["run", NGC, "--machine", MACHINE, "--board", "udp:h", "--json", "/no/dir/r.json"],
     "--json: cannot write '/no/dir/r.json'"),
    (["frobnicate"], "invalid choice: 'frobnicate'"),
    (["info", "udp:h", "--timeout-ms", "0"], "--timeout-ms 0"),
])
def test_bad_input_exits_2_with_one_line(argv, msg, capsys):
    assert main(argv) == 2
    line = one_line(capsys.readouterr().err)
    assert msg in line and line.startswith("hwinterp-host: ")


@pytest.mark.parametrize("cmd", ["info", "status", "abort"])
def test_dead_link_exits_1_naming_uri_and_time(cmd, capsys):
    sock, port = dead_port()
    try:
        assert main([cmd, f"udp:127.0.0.1:{port}", "--timeout-ms", "200", "--retry-ms", "20"]) == 1
    finally:
        sock.close()
    line = one_line(capsys.readouterr().err)
    assert f"udp:127.0.0.1:{port}: no reply for 0.2" in line and "the link is dead" in line


def test_run_on_a_dead_link_exits_1(capsys):
    sock, port = dead_port()
    try:
        rc = main(["run", NGC, "--machine", MACHINE, "--board", f"udp:127.0.0.1:{port}",
                   "--hwinterp", "/bin/true", "--timeout-ms", "200", "--retry-ms", "20"])
    finally:
        sock.close()
    assert rc == 1
    assert "no reply for 0.2" in one_line(capsys.readouterr().err)


class UdpBoard:
    """FakeBoard served on a UDP socket in a thread."""

    def __init__(self, board):
        self.board = board
        self.sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.sock.bind(("127.0.0.1", 0))
        self.sock.settimeout(0.02)
        self.uri = f"udp:127.0.0.1:{self.sock.getsockname()[1]}"
        self.stop = threading.Event()
        self.th = threading.Thread(target=self.serve, daemon=True)

    def serve(self):
        while not self.stop.is_set():
            try:
                data, peer = self.sock.recvfrom(4096)
            except socket.timeout:
                continue
            reply = self.board.serve(data)
            if reply:
                self.sock.sendto(reply, peer)

    def __enter__(self):
        self.th.start()
        return self

    def __exit__(self, *exc):
        self.stop.set()
        self.th.join()
        self.sock.close()


class PtyBoard:
    """FakeBoard behind SLIP + CRC-32 frames on a pty (the host opens its other end)."""

    def __init__(self, board):
        import pty
        import tty
        self.board = board
        self.master, self.slave = pty.openpty()
        tty.setraw(self.slave)
        self.uri = f"serial:{os.ttyname(self.slave)}@1000000"
        self.stop = threading.Event()
        self.th = threading.Thread(target=self.serve, daemon=True)

    def serve(self):
        import select
        d = framing.Deframer()
        while not self.stop.is_set():
            r, _, _ = select.select([self.master], [], [], 0.02)
            if r:
                for pkt in d.feed(os.read(self.master, 4096)):
                    reply = self.board.serve(pkt)
                    if reply:
                        os.write(self.master, framing.frame(reply))

    def __enter__(self):
        self.th.start()
        return self

    def __exit__(self, *exc):
        self.stop.set()
        self.th.join()
        os.close(self.master)
        os.close(self.slave)


def test_run_over_a_uart_on_a_pty(tmp_path, capsys):
    board = FakeBoard(axes=4, depth=16, cmd_clocks=400, clocks_per_packet=200)
    with PtyBoard(board) as b:
        rc = main(["run", NGC, "--machine", MACHINE, "--board", b.uri, "--hwinterp", hwinterp(),
                   "--json", str(tmp_path / "r.json"), "--progress", "0", "--poll-ms", "1"])
    out = capsys.readouterr()
    assert rc == 0, out.out + out.err
    r = json.loads((tmp_path / "r.json").read_text())
    assert r["board"]["link"] == "serial" and r["end_position"] == board.pos == r["expected_end_position"]
    assert r["board"]["transport_counts"]["malformed"] == 0


def test_info_and_status_words(capsys):
    with UdpBoard(FakeBoard(axes=4, depth=16)) as b:
        assert main(["info", b.uri]) == 0
        out = capsys.readouterr().out
        assert "4 axes" in out and "clock 50000000 Hz" in out and "command FIFO 16" in out
        assert main(["info", b.uri, "--json"]) == 0
        j = json.loads(capsys.readouterr().out)
        assert j["id"]["axes"] == 4 and j["guard"]["expect"] == 0
        assert main(["status", b.uri]) == 0
        out = capsys.readouterr().out
        assert "FIFO 0 of 16" in out and "position (snapshot" in out
        assert b.board.expect == 0            # status writes nothing through the guard
        assert main(["abort", b.uri]) == 0
        assert b.board.expect == 1 and (M.CTRL.addr, 1) in b.board.bus_writes


def test_run_a_program_end_to_end_on_the_stand_in(tmp_path, capsys):
    """modal.ngc planned by hwinterp, streamed to the stand-in: exit 0, the
    final position the program's lattice end, the moves CSV the rows of
    `hwinterp gcode --moves-csv` (the lockstep run) but for the contour
    column, the JSON with hwinterp gcode's keys."""
    board = FakeBoard(axes=4, depth=16, cmd_clocks=400, clocks_per_packet=200)
    with UdpBoard(board) as b:
        rc = main(["run", NGC, "--machine", MACHINE, "--board", b.uri, "--hwinterp", hwinterp(),
                   "--feed", "full", "--json", str(tmp_path / "r.json"),
                   "--moves-csv", str(tmp_path / "m.csv"), "--progress", "0", "--poll-ms", "1"])
    out = capsys.readouterr()
    assert rc == 0, out.out + out.err
    assert "PASS" in out.out
    r = json.loads((tmp_path / "r.json").read_text())
    assert r["passed"] and r["end_position"] == r["expected_end_position"] == board.pos
    assert r["board"]["pushed"] == r["commands"] == board.pushes
    lock = subprocess.run([hwinterp(), "gcode", NGC, "--machine", MACHINE, "--mode", "direct",
                           "--progress", "0", "--moves-csv", str(tmp_path / "l.csv"),
                           "--json", str(tmp_path / "l.json")], capture_output=True, text=True)
    assert lock.returncode == 0, lock.stdout
    mine = list(csv.reader(open(tmp_path / "m.csv")))
    theirs = list(csv.reader(open(tmp_path / "l.csv")))
    assert mine[0] == theirs[0]
    assert [row[:-1] for row in mine] == [row[:-1] for row in theirs]
    assert all(row[-1] == "" for row in mine[1:])
    lj = json.loads((tmp_path / "l.json").read_text())
    for k in ("program", "variant", "moves", "commands", "arcs", "programmed_time_s", "clock_hz"):
        assert r[k] == lj[k], k
    assert r["end_position"] == lj["end_position"]


def test_plan_without_a_board(capsys):
    """`plan`: hwinterp's plan of modal.ngc, its commands and stream words."""
    assert main(["plan", NGC, "--machine", MACHINE, "--hwinterp", hwinterp(), "--json"]) == 0
    j = json.loads(capsys.readouterr().out)
    assert j["commands"] > 0 and j["moves"] >= j["commands"] // 4
    # a push is a chunk header and a word at least: 2 words a command, and a first command
    # that writes every staging register (4 axes: 4 deltas, 2 centre, 2 end, ops, feed, flags)
    assert j["stream_words"] >= 2 * j["commands"] and j["max_words"] >= 1 + 11 + 1
    assert j["packets_unlimited_fifo"] >= 1 and j["widths"]["axes"] == 4
    assert main(["plan", "/no/such.ngc", "--machine", MACHINE]) == 2


def test_signals_hold_then_abort(tmp_path):
    """A real `hwinterp-host run` process: SIGUSR1 holds (FEED 0 without the
    profile), SIGINT aborts (CTRL.abort_motion, the watchdog off) and the
    command exits 1 naming it; progress lines go to stderr."""
    import signal
    import time
    board = FakeBoard(axes=4, depth=16, cmd_clocks=10 ** 9, clocks_per_packet=50)
    env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "sw", "host"))
    with UdpBoard(board) as b:
        p = subprocess.Popen([sys.executable, "-m", "hwinterp_host", "run", NGC, "--machine", MACHINE,
                              "--board", b.uri, "--hwinterp", hwinterp(), "--progress", "0.05",
                              "--json", str(tmp_path / "r.json")],
                             env=env, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True)
        try:
            t0 = time.monotonic()
            while board.pushes == 0 and time.monotonic() - t0 < 30:
                time.sleep(0.02)
            assert board.pushes > 0
            p.send_signal(signal.SIGUSR1)
            t0 = time.monotonic()
            while board.regs.get(M.FEED.addr) != 0 and time.monotonic() - t0 < 10:
                time.sleep(0.02)
            assert board.regs[M.FEED.addr] == 0            # held
            time.sleep(0.3)                                 # a progress line or more while held
            p.send_signal(signal.SIGINT)
            out, err = p.communicate(timeout=30)
        finally:
            if p.poll() is None:
                p.kill()
    assert p.returncode == 1, out + err
    assert "FAIL: SIGINT" in out
    assert (M.CTRL.addr, 1) in board.bus_writes and not board.fifo and board.current is None
    assert board.regs[M.WDOG_PERIOD.addr] == 0
    assert "moves " in err and "HOLD" in err
    r = json.loads((tmp_path / "r.json").read_text())
    assert r["board"]["aborted"] and r["board"]["holds"] == 1 and not r["passed"]
