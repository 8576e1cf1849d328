"""Link URIs (transport.parse_uri), and the two transports against a board
stand-in on a real UDP socket and a real pty (fake_board.FakeBoard)."""
import os
import pty
import socket
import threading
import tty

import pytest

from fake_board import FakeBoard
from hwinterp_host import framing
from hwinterp_host.board import read_id
from hwinterp_host.link import Session
from hwinterp_host.transport import (SerialTransport, SerialUri, UdpTransport, UdpUri, UriError,
                                     parse_uri)


@pytest.mark.parametrize("text,want", [
    ("udp:127.0.0.1", UdpUri("127.0.0.1", 1234)),
    ("udp:board.local:4321", UdpUri("board.local", 4321)),
    ("udp:[::1]:99", UdpUri("::1", 99)),
    ("udp:[fe80::1]", UdpUri("fe80::1", 1234)),
    ("serial:/dev/ttyUSB0", SerialUri("/dev/ttyUSB0", 1000000)),
    ("serial:/dev/ttyUSB0@115200", SerialUri("/dev/ttyUSB0", 115200)),
    ("serial:/dev/ttyUSB0@1000000", SerialUri("/dev/ttyUSB0", 1000000)),
    ("serial:/dev/pts/3@9600", SerialUri("/dev/pts/3", 9600)),
])
def test_good_uris(text, want):
    assert parse_uri(text) == want


@pytest.mark.parametrize("text,why", [
    ("127.0.0.1", "no scheme"),
    ("tcp:host:1", "unknown scheme 'tcp'"),
    ("udp:", "no host"),
    ("udp::1234", "no host"),
    ("udp:host:0", "port '0' is not 1..65535"),
    ("udp:host:70000", "port '70000' is not 1..65535"),
    ("udp:host:x", "port 'x'"),
    ("udp:fe80::1", "brackets"),
    ("udp:[::1", "unclosed"),
    ("serial:", "no device"),
    ("serial:/dev/ttyUSB0@", "baud rate ''"),
    ("serial:/dev/ttyUSB0@fast", "baud rate 'fast'"),
    ("serial:/dev/ttyUSB0@0", "baud rate '0'"),
])
def test_bad_uris_name_the_uri(text, why):
    with pytest.raises(UriError) as e:
        parse_uri(text)
    msg = str(e.value)
    assert f"'{text}'" in msg and why in msg and "\n" not in msg


def test_udp_transport_to_a_board_on_a_socket():
    board = FakeBoard(axes=4, depth=32)
    srv = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    srv.bind(("127.0.0.1", 0))
    port = srv.getsockname()[1]
    stop = threading.Event()

    def serve():
        srv.settimeout(0.05)
        while not stop.is_set():
            try:
                data, peer = srv.recvfrom(4096)
            except socket.timeout:
                continue
            reply = board.serve(data)
            if reply:
                srv.sendto(reply, peer)

    th = threading.Thread(target=serve, daemon=True)
    th.start()
    try:
        s = Session(UdpTransport(parse_uri(f"udp:127.0.0.1:{port}")), dead_after_s=2.0)
        ident = read_id(s)
        assert (ident.axes, ident.fifo_depth, ident.clock_hz) == (4, 32, 50_000_000)
        assert s.open() == 0
        s.transact([], [])
        assert board.expect == 1 and s.seq == 1
    finally:
        stop.set()
        th.join()
        srv.close()


def test_serial_transport_to_a_board_on_a_pty():
    board = FakeBoard(axes=3, depth=8)
    master, slave = pty.openpty()
    tty.setraw(slave)
    stop = threading.Event()

    def serve():
        d = framing.Deframer()
        while not stop.is_set():
            import select
            r, _, _ = select.select([master], [], [], 0.05)
            if not r:
                continue
            for pkt in d.feed(os.read(master, 4096)):
                reply = board.serve(pkt)
                if reply:
                    os.write(master, framing.frame(reply))

    th = threading.Thread(target=serve, daemon=True)
    th.start()
    try:
        t = SerialTransport(SerialUri(os.ttyname(slave), 115200))
        s = Session(t, dead_after_s=2.0)
        ident = read_id(s)
        assert (ident.axes, ident.fifo_depth) == (3, 8)
        s.open()
        s.transact([], [])
        assert board.expect == 1
        assert t.counts.malformed == 0 and t.counts.received >= 3
    finally:
        stop.set()
        th.join()
        os.close(master)
        os.close(slave)
