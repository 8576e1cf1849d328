"""The two links to a board, named by a URI:

    udp:HOST[:PORT]      Etherbone over UDP (LiteEth), PORT 1234 by default
    serial:DEV[@BAUD]    Etherbone over a UART in SLIP + CRC-32 frames
                         (framing.py), 8N1, BAUD 1000000 by default (the rate of
                         the project's UART boards, cmake/cores.cmake); DEV a
                         serial device or a pty (raw: no echo, no flow control)

A transport sends one packet and receives whole packets; it knows nothing
of tags or retries (link.py does). parse_uri raises UriError naming the URI
and what is wrong with it.
"""
from __future__ import annotations

import os
import select
import socket
import time
from dataclasses import dataclass
from typing import Optional, Union

from .framing import Deframer, frame

DEFAULT_UDP_PORT = 1234
DEFAULT_BAUD = 1_000_000


class UriError(ValueError):
    """A link URI that cannot be used (bad input: exit 2)."""


class TransportError(OSError):
    """The link cannot be opened or used (the device, the socket)."""


@dataclass(frozen=True)
class UdpUri:
    host: str
    port: int = DEFAULT_UDP_PORT

    def __str__(self):
        return f"udp:{self.host}:{self.port}"


@dataclass(frozen=True)
class SerialUri:
    device: str
    baud: int = DEFAULT_BAUD

    def __str__(self):
        return f"serial:{self.device}@{self.baud}"


Uri = Union[UdpUri, SerialUri]


def parse_uri(uri: str) -> Uri:
    """udp:HOST[:PORT] or serial:DEV[@BAUD]; UriError naming it otherwise."""
    def bad(why):
        return UriError(f"link URI '{uri}': {why} (give udp:HOST[:PORT] or serial:DEV[@BAUD])")

    scheme, sep, rest = uri.partition(":")
    if not sep:
        raise bad("no scheme")
    if scheme == "udp":
        host, port = rest, str(DEFAULT_UDP_PORT)
        if rest.startswith("["):              # udp:[v6]:port
            close = rest.find("]")
            if close < 0:
                raise bad("unclosed [")
            host, tail = rest[1:close], rest[close + 1:]
            if tail:
                if not tail.startswith(":"):
                    raise bad(f"'{tail}' after the address")
                port = tail[1:]
        elif rest.count(":") == 1:
            host, port = rest.split(":")
        elif rest.count(":") > 1:
            raise bad("an IPv6 address goes in brackets, udp:[ADDR]:PORT")
        if not host:
            raise bad("no host")
        if not port.isdigit() or not 1 <= int(port) <= 65535:
            raise bad(f"port '{port}' is not 1..65535")
        return UdpUri(host, int(port))
    if scheme == "serial":
        dev, at, baud = rest.rpartition("@")
        if not at:
            dev, baud = rest, str(DEFAULT_BAUD)
        if not dev:
            raise bad("no device")
        if not baud.isdigit() or int(baud) <= 0:
            raise bad(f"baud rate '{baud}' is not a positive integer")
        return SerialUri(dev, int(baud))
    raise bad(f"unknown scheme '{scheme}'")


@dataclass
class TransportCounts:
    sent: int = 0           # packets
    received: int = 0       # packets (UART: good frames)
    bytes_sent: int = 0
    bytes_received: int = 0
    malformed: int = 0      # UART: frames dropped (CRC, escape, length)


class Transport:
    uri: Uri
    counts: TransportCounts

    def send(self, packet: bytes) -> None:
        raise NotImplementedError

    def recv(self, timeout_s: float) -> Optional[bytes]:
        """The next packet within timeout_s, or None."""
        raise NotImplementedError

    def wire_seconds(self, nbytes: int) -> float:
        """The time nbytes take on the wire (0: negligible)."""
        return 0.0

    def close(self) -> None:
        pass


class UdpTransport(Transport):
    def __init__(self, uri: UdpUri):
        self.uri = uri
        self.counts = TransportCounts()
        try:
            infos = socket.getaddrinfo(uri.host, uri.port, type=socket.SOCK_DGRAM)
        except socket.gaierror as e:
            raise TransportError(f"{uri}: cannot resolve '{uri.host}': {e.strerror}") from None
        family, _, _, _, addr = infos[0]
        self.sock = socket.socket(family, socket.SOCK_DGRAM)
        try:
            self.sock.connect(addr)    # replies from elsewhere are not ours
        except OSError as e:
            self.sock.close()
            raise TransportError(f"{uri}: {e.strerror or e}") from None
        self.sock.setblocking(False)

    def send(self, packet: bytes) -> None:
        try:
            self.sock.send(packet)
        except OSError:
            pass        # e.g. ECONNREFUSED from an earlier datagram: a lost packet
        self.counts.sent += 1
        self.counts.bytes_sent += len(packet)

    def recv(self, timeout_s: float) -> Optional[bytes]:
        end = time.monotonic() + max(0.0, timeout_s)
        while True:
            left = end - time.monotonic()
            r, _, _ = select.select([self.sock], [], [], max(0.0, left))
            if r:
                try:
                    data = self.sock.recv(65536)
                except (BlockingIOError, InterruptedError):
                    continue
                except OSError:      # ICMP port unreachable: nothing listens (yet)
                    if time.monotonic() >= end:
                        return None
                    time.sleep(min(0.005, max(0.0, end - time.monotonic())))
                    continue
                self.counts.received += 1
                self.counts.bytes_received += len(data)
                return data
            if left <= 0:
                return None

    def close(self) -> None:
        self.sock.close()


class SerialTransport(Transport):
    def __init__(self, uri: SerialUri):
        import serial  # pyserial
        self.uri = uri
        self.counts = TransportCounts()
        self.deframer = Deframer()
        self._queue = []
        try:
            self.port = serial.Serial(uri.device, uri.baud, bytesize=8, parity="N", stopbits=1,
                                      timeout=0, xonxoff=False, rtscts=False, dsrdtr=False)
        except (serial.SerialException, OSError, ValueError) as e:
            raise TransportError(f"{uri}: {e}") from None
        self.port.reset_input_buffer()

    def send(self, packet: bytes) -> None:
        data = frame(packet)
        self.port.write(data)
        self.port.flush()
        self.counts.sent += 1
        self.counts.bytes_sent += len(data)

    def recv(self, timeout_s: float) -> Optional[bytes]:
        end = time.monotonic() + max(0.0, timeout_s)
        while not self._queue:
            left = end - time.monotonic()
            if left < 0:
                return None
            fd = self.port.fileno()
            r, _, _ = select.select([fd], [], [], left)
            if not r:
                continue
            try:
                data = os.read(fd, 4096)
            except BlockingIOError:
                continue
            except OSError as e:
                raise TransportError(f"{self.uri}: {e.strerror or e}") from None
            if not data:     # a pty whose other end closed: nothing will come
                time.sleep(min(0.01, max(0.0, left)))
                continue
            self.counts.bytes_received += len(data)
            before = self.deframer.counts
            bad0 = before.bad_crc + before.bad_escape + before.too_short + before.too_long
            self._queue.extend(self.deframer.feed(data))
            c = self.deframer.counts
            self.counts.malformed += c.bad_crc + c.bad_escape + c.too_short + c.too_long - bad0
        self.counts.received += 1
        return self._queue.pop(0)

    def wire_seconds(self, nbytes: int) -> float:
        # 10 bits a byte (8N1), SLIP's escapes and END bytes ignored
        return nbytes * 10.0 / self.uri.baud

    def close(self) -> None:
        self.port.close()


def open_transport(uri: Union[str, Uri]) -> Transport:
    """The transport of a URI (a string is parsed: UriError when bad)."""
    u = parse_uri(uri) if isinstance(uri, str) else uri
    return UdpTransport(u) if isinstance(u, UdpUri) else SerialTransport(u)
