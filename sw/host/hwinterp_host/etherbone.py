"""Etherbone, the subset LiteEth serves (docs/link.md): big-endian 32-bit
words; a packet is an 8-byte header and one record (LiteEth serves one
record a packet) of up to 255 writes to consecutive byte addresses from a
base and up to 255 reads of a list of byte addresses, the base return
address carried back in the reply. The reply to a packet with reads is one
record whose writes are the words read, written "to" the base return
address: the host's tag.

    data = encode(Record(write_base=a, writes=[...], ret_base=tag, reads=[...]))
    reply = decode_reply(data)        # Reply(tag, words)

Header: magic 0x4E6F; version 1 in bits 7:4 of byte 2 and the flags pf
(probe, bit 0), pr (probe reply, bit 1), nr (no reads, bit 2); byte 3 0x44
(32-bit addresses and ports); bytes 4-7 0. Record: flags (byte 0), byte
enable (0x0F), wcount, rcount; then, if wcount > 0, the base write address
and the words; then, if rcount > 0, the base return address and the read
addresses.
"""
from __future__ import annotations

import struct
from dataclasses import dataclass, field
from typing import List, Sequence

MAGIC = 0x4E6F
VERSION = 1
SIZES = 0x44            # address size 4 (bits 7:4), port size 4 (bits 3:0)
FLAG_PF, FLAG_PR, FLAG_NR = 0x01, 0x02, 0x04
MAX_WRITES = 255
MAX_READS = 255
# A record's words (writes and reads, without its two base addresses) that
# every board takes: LiteEth's record buffer (buffer_depth 255) holds 256
# words with the bases (a longer record spoils it: measured on the simulated
# Colorlight, 251 writes and 3 reads pass, 252 and 3 do not), and the UART
# bridge's 1024-byte frame buffer holds the 8-byte header, the record header,
# the two bases, the words and the CRC: 248 words (rtl/link/uart_etherbone.sv).
MAX_RECORD_WORDS = 248
HEADER_BYTES = 8
RECORD_HEADER_BYTES = 4
BYTE_ENABLE = 0x0F


class EtherboneError(ValueError):
    """A packet that is not one this subset can carry or read."""


@dataclass
class Record:
    write_base: int = 0
    writes: Sequence[int] = ()
    ret_base: int = 0      # the base return address: the host's tag
    reads: Sequence[int] = ()
    byte_enable: int = BYTE_ENABLE
    flags: int = 0         # the record's flags byte (LiteEth ignores it)


@dataclass
class Packet:
    flags: int = 0         # the header's pf/pr/nr bits
    record: Record | None = None


@dataclass
class Reply:
    tag: int
    words: List[int] = field(default_factory=list)


def _u32(v: int, what: str) -> int:
    if not 0 <= v <= 0xFFFFFFFF:
        raise EtherboneError(f"{what} 0x{v:x} is not a 32-bit word" if v >= 0 else f"{what} {v} < 0")
    return v


def _header(flags: int) -> bytes:
    return struct.pack(">HBBI", MAGIC, (VERSION << 4) | (flags & 0x0F), SIZES, 0)


def encode(rec: Record, flags: int = 0) -> bytes:
    """One packet of one record (header flags as given: LiteX's own client
    and LiteEth's replies leave nr clear)."""
    nw, nr = len(rec.writes), len(rec.reads)
    if nw > MAX_WRITES:
        raise EtherboneError(f"{nw} writes: a record holds at most {MAX_WRITES}")
    if nr > MAX_READS:
        raise EtherboneError(f"{nr} reads: a record holds at most {MAX_READS}")

    out = bytearray(_header(flags))
    out += struct.pack(">BBBB", rec.flags & 0xFF, rec.byte_enable & 0xFF, nw, nr)
    if nw:
        out += struct.pack(">I", _u32(rec.write_base, "base write address"))
        out += b"".join(struct.pack(">I", _u32(v, "write data")) for v in rec.writes)
    if nr:
        out += struct.pack(">I", _u32(rec.ret_base, "base return address"))
        out += b"".join(struct.pack(">I", _u32(a, "read address")) for a in rec.reads)
    return bytes(out)


def encode_probe() -> bytes:
    """A probe: the header alone with pf set; the board answers pr."""
    return _header(FLAG_PF)


def decode(data: bytes) -> Packet:
    """A packet of this subset: its header flags and its record (None for a
    header-only probe). EtherboneError naming what is wrong."""
    if len(data) < HEADER_BYTES:
        raise EtherboneError(f"{len(data)} bytes: shorter than the {HEADER_BYTES}-byte header")
    magic, vf, sizes, _ = struct.unpack_from(">HBBI", data, 0)
    if magic != MAGIC:
        raise EtherboneError(f"magic 0x{magic:04x}, not 0x{MAGIC:04x}")
    if vf >> 4 != VERSION:
        raise EtherboneError(f"version {vf >> 4}, not {VERSION}")
    if sizes != SIZES:
        raise EtherboneError(f"address/port sizes 0x{sizes:02x}, not 0x{SIZES:02x}")
    pkt = Packet(flags=vf & 0x0F)
    rest = data[HEADER_BYTES:]
    if not rest:
        return pkt
    if len(rest) < RECORD_HEADER_BYTES:
        raise EtherboneError(f"{len(rest)} bytes after the header: a record header is 4")
    rflags, be, nw, nr = struct.unpack_from(">BBBB", rest, 0)
    need = RECORD_HEADER_BYTES + (4 + 4 * nw if nw else 0) + (4 + 4 * nr if nr else 0)
    if len(rest) != need:
        raise EtherboneError(f"a record of {nw} writes and {nr} reads is {need} bytes, not {len(rest)}")
    off = RECORD_HEADER_BYTES
    rec = Record(flags=rflags, byte_enable=be)
    if nw:
        rec.write_base = struct.unpack_from(">I", rest, off)[0]
        rec.writes = list(struct.unpack_from(f">{nw}I", rest, off + 4))
        off += 4 + 4 * nw
    if nr:
        rec.ret_base = struct.unpack_from(">I", rest, off)[0]
        rec.reads = list(struct.unpack_from(f">{nr}I", rest, off + 4))
    pkt.record = rec
    return pkt


def decode_reply(data: bytes) -> Reply:
    """A reply: one record of writes only (the words read, to the base return
    address asked). EtherboneError when it is anything else."""
    pkt = decode(data)
    rec = pkt.record
    if pkt.flags & (FLAG_PF | FLAG_PR) or rec is None:
        raise EtherboneError("a probe, not a reply to reads")
    if rec.reads:
        raise EtherboneError(f"a reply has no reads; this one has {len(rec.reads)}")
    return Reply(tag=rec.write_base, words=list(rec.writes))


def encode_reply(tag: int, words: Sequence[int]) -> bytes:
    """The reply a board gives (for fixtures and tests)."""
    return encode(Record(write_base=tag, writes=words))


def is_probe_reply(data: bytes) -> bool:
    try:
        return bool(decode(data).flags & FLAG_PR)
    except EtherboneError:
        return False
