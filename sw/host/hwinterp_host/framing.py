"""The UART link's framing (docs/link.md): SLIP (RFC 1055) frames of an
Etherbone packet followed by its CRC-32 (IEEE 802.3: reflected, initial
0xFFFFFFFF, final XOR 0xFFFFFFFF; the 4 bytes least significant first).
END (0xC0) and ESC (0xDB) inside the frame are sent as ESC 0xDC and ESC
0xDD; END closes the frame. The sender also sends END before a frame to
flush noise; an empty frame is ignored.

    wire = frame(packet)
    dec = Deframer(); packets = dec.feed(received_bytes)

A received frame is kept only if it is whole: no bad escape, at least
MIN_FRAME bytes before the CRC, at most max_bytes, and the CRC right; the
Deframer counts each kind it drops.
"""
from __future__ import annotations

import struct
import zlib
from dataclasses import dataclass
from typing import List

END, ESC, ESC_END, ESC_ESC = 0xC0, 0xDB, 0xDC, 0xDD
MIN_FRAME = 12      # an Etherbone header and a record header
MAX_FRAME = 2048    # a reply of 255 words is 8 + 4 + 4 + 1020 = 1036 bytes


def crc32(data: bytes) -> int:
    """CRC-32/IEEE 802.3 (reflected, init and final XOR 0xFFFFFFFF)."""
    return zlib.crc32(data) & 0xFFFFFFFF


def escape(data: bytes) -> bytes:
    return data.replace(bytes([ESC]), bytes([ESC, ESC_ESC])).replace(bytes([END]), bytes([ESC, ESC_END]))


def frame(packet: bytes) -> bytes:
    """END, the packet and its CRC escaped, END."""
    body = packet + struct.pack("<I", crc32(packet))
    return bytes([END]) + escape(body) + bytes([END])


@dataclass
class FrameCounts:
    frames: int = 0        # good frames delivered
    bad_crc: int = 0
    bad_escape: int = 0
    too_short: int = 0
    too_long: int = 0


class Deframer:
    """Bytes in, good packets (CRC stripped) out."""

    def __init__(self, max_bytes: int = MAX_FRAME):
        self.max_bytes = max_bytes
        self.counts = FrameCounts()
        self._buf = bytearray()
        self._esc = False
        self._bad = False    # a bad escape or an overlong frame: drop at END
        self._long = False

    def feed(self, data: bytes) -> List[bytes]:
        out: List[bytes] = []
        for b in data:
            if b == END:
                pkt = self._close()
                if pkt is not None:
                    out.append(pkt)
                continue
            if self._esc:
                self._esc = False
                if b == ESC_END:
                    b = END
                elif b == ESC_ESC:
                    b = ESC
                else:
                    self._bad = True
                    continue
            elif b == ESC:
                self._esc = True
                continue
            if len(self._buf) >= self.max_bytes:
                self._long = True
                continue
            self._buf.append(b)
        return out

    def _close(self):
        buf, bad, long_, esc = bytes(self._buf), self._bad, self._long, self._esc
        self._buf.clear()
        self._bad = self._long = self._esc = False
        if not buf and not (bad or long_ or esc):
            return None           # an empty frame (the flush END)
        if bad or esc:
            self.counts.bad_escape += 1
            return None
        if long_:
            self.counts.too_long += 1
            return None
        if len(buf) < MIN_FRAME + 4:
            self.counts.too_short += 1
            return None
        pkt, crc = buf[:-4], struct.unpack("<I", buf[-4:])[0]
        if crc32(pkt) != crc:
            self.counts.bad_crc += 1
            return None
        self.counts.frames += 1
        return pkt
