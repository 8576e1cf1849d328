"""The guarded session with a board (docs/link.md, docs/host.md).

Every packet that writes is one Etherbone record from the guard's window:
SEQ = n, then the stream: chunks of a header {count[31:24], word
address[23:0]} and count data words (consecutive word addresses). Its reads
start with the guard's EXPECT, then what the caller asks. The base return
address carries the tag (n, attempt). One packet is in flight: the host
waits for its reply; on a timeout it sends the same packet again (same SEQ,
the next attempt's tag). The guard runs the writes of SEQ n only if it
expects n, so the first copy that arrives runs and every later copy is
refused (its reads still run): the reply that comes back, whichever copy
it answers, says EXPECT = n + 1. A reply with another tag (a late answer to
an earlier attempt, to an earlier packet, or to another session) is
dropped. After `dead_after_s` without the reply the link is declared dead
(LinkDead, naming the URI and the time waited).

Plain reads (no SEQ, no writes) go the same way, with their own tags: `info`
and the session's opening read of EXPECT use them.

Tag (the base return address): bits 31:28 a random session number, bit 27
1 for a guarded packet, bits 26:8 n (guarded) or the plain read's count,
modulo 2^19, bits 7:0 the attempt, modulo 256.
"""
from __future__ import annotations

import random
import time
from dataclasses import dataclass
from typing import List, Sequence, Tuple

from . import etherbone as eb
from .gen.regs import link as guard
from .transport import Transport, TransportError

SEQ_ADDR = guard.SEQ.addr           # write SEQ, read EXPECT
STREAM_WORDS = guard.STREAM.entries  # 255 words after SEQ in one record at most
# One record: SEQ, the stream words and at most MAX_PACKET_READS reads (EXPECT
# among them), within the words a board takes in a record.
MAX_PACKET_READS = 32
MAX_STREAM = min(eb.MAX_RECORD_WORDS - 1 - MAX_PACKET_READS, STREAM_WORDS)
MAX_CHUNK = 255                      # count is 8 bits
WORD_ADDR_LIMIT = 1 << 24            # chunk targets: word addresses below 2^24 (64 MiB)

# Defaults, for a board on a LAN or a UART (docs/host.md: scale them for a
# slow simulated board with --timeout-ms / --retry-ms).
RETRY_S = 0.05      # an attempt's wait for its reply, besides the wire time
DEAD_AFTER_S = 2.0  # no reply for this long: the link is dead


class LinkError(RuntimeError):
    """The link or the board does not behave (exit 1)."""


class LinkDead(LinkError):
    def __init__(self, uri, waited_s: float, attempts: int, what: str):
        self.uri, self.waited_s, self.attempts = uri, waited_s, attempts
        super().__init__(f"{uri}: no reply for {waited_s:.2f} s ({attempts} attempts of {what}): "
                         "the link is dead")


class OutOfStep(LinkError):
    pass


@dataclass
class LinkCounts:
    packets: int = 0          # guarded packets taken
    plain_reads: int = 0      # plain read packets answered
    sends: int = 0            # packets sent, attempts included
    retransmits: int = 0      # attempts after the first
    stale_replies: int = 0    # replies with another tag (dropped)
    malformed: int = 0        # replies that are not Etherbone replies of the length asked
    stream_words: int = 0     # stream words taken (headers included)


def chunk(word_addr_or_byte: int, words: Sequence[int]) -> List[int]:
    """One stream chunk: header {count, word address} then the words, from a
    byte address."""
    if word_addr_or_byte & 3:
        raise ValueError(f"0x{word_addr_or_byte:x} is not word aligned")
    wa = word_addr_or_byte >> 2
    if not 0 < len(words) <= MAX_CHUNK:
        raise ValueError(f"a chunk holds 1..{MAX_CHUNK} words, not {len(words)}")
    if wa >= WORD_ADDR_LIMIT:
        raise ValueError(f"0x{word_addr_or_byte:x} is beyond the stream's 64 MiB reach")
    return [(len(words) << 24) | wa] + [w & 0xFFFFFFFF for w in words]


def chunks_of(writes: Sequence[Tuple[int, int]]) -> List[int]:
    """Writes (byte address, value) in order as stream words: consecutive
    addresses in one chunk."""
    out: List[int] = []
    run_addr, run = None, []
    for addr, value in writes:
        if run and addr == run_addr + 4 * len(run) and len(run) < MAX_CHUNK:
            run.append(value)
            continue
        if run:
            out += chunk(run_addr, run)
        run_addr, run = addr, [value]
    if run:
        out += chunk(run_addr, run)
    return out


def stream_cost(writes: Sequence[Tuple[int, int]]) -> int:
    return len(chunks_of(writes))


class Session:
    def __init__(self, transport: Transport, retry_s: float = RETRY_S,
                 dead_after_s: float = DEAD_AFTER_S, rng: random.Random | None = None,
                 clock=time.monotonic):
        self.t = transport
        self.retry_s, self.dead_after_s = retry_s, dead_after_s
        self.counts = LinkCounts()
        self.session = (rng or random.SystemRandom()).randrange(16)
        self.seq = None          # the next SEQ: EXPECT as read on open
        self._plain = 0
        self._clock = clock

    @property
    def uri(self):
        return self.t.uri

    # -- tags
    def tag(self, n: int, attempt: int, guarded: bool = True) -> int:
        return (self.session << 28) | (int(guarded) << 27) | ((n & 0x7FFFF) << 8) | (attempt & 0xFF)

    # -- one exchange, retried
    def _exchange(self, make, nreads: int, what: str):
        """Send make(attempt) until its reply comes; the reply's words."""
        start = self._clock()
        attempt = 0
        while True:
            tag, packet = make(attempt)
            # the attempt's wait: the retry time and the packet's and reply's time on the wire
            wait = self.retry_s + self.t.wire_seconds(len(packet) + 16 + 4 * nreads) * 1.5
            try:
                self.t.send(packet)
            except (TransportError, OSError) as e:
                raise LinkError(f"{self.uri}: {e}") from None
            self.counts.sends += 1
            if attempt:
                self.counts.retransmits += 1
            deadline = self._clock() + wait
            while True:
                left = deadline - self._clock()
                if left <= 0:
                    break
                try:
                    data = self.t.recv(left)
                except (TransportError, OSError) as e:
                    raise LinkError(f"{self.uri}: {e}") from None
                if data is None:
                    break
                try:
                    reply = eb.decode_reply(data)
                except eb.EtherboneError:
                    self.counts.malformed += 1
                    continue
                if reply.tag != tag:
                    self.counts.stale_replies += 1
                    continue
                if len(reply.words) != nreads:
                    self.counts.malformed += 1
                    continue
                return reply.words
            attempt += 1
            waited = self._clock() - start
            if waited >= self.dead_after_s:
                raise LinkDead(self.uri, waited, attempt, what)

    # -- plain reads
    def read(self, addrs: Sequence[int]) -> List[int]:
        """Reads with no writes (no SEQ): any number of addresses, in packets
        of at most the words a board takes in a record."""
        out: List[int] = []
        for i in range(0, len(addrs), eb.MAX_RECORD_WORDS):
            part = list(addrs[i:i + eb.MAX_RECORD_WORDS])
            n = self._plain
            self._plain += 1

            def make(attempt, part=part, n=n):
                tag = self.tag(n, attempt, guarded=False)
                return tag, eb.encode(eb.Record(ret_base=tag, reads=part))
            out += self._exchange(make, len(part), "a read")
            self.counts.plain_reads += 1
        return out

    def write_plain(self, base: int, words: Sequence[int], reads: Sequence[int] = ()) -> List[int]:
        """Writes to consecutive addresses from `base` with no SEQ (outside the
        guard's window they pass through it unchanged), then reads. A lost
        reply sends them again, so they may run more than once: only for
        writes that do the same when repeated (status's snapshot)."""
        if not 0 < len(words) or len(words) + len(reads) > eb.MAX_RECORD_WORDS:
            raise ValueError(f"{len(words)} writes, {len(reads)} reads: at least 1 write, and "
                             f"at most {eb.MAX_RECORD_WORDS} words in all")
        n = self._plain
        self._plain += 1
        reads = list(reads)

        def make(attempt):
            tag = self.tag(n, attempt, guarded=False)
            return tag, eb.encode(eb.Record(write_base=base, writes=list(words), ret_base=tag,
                                            reads=reads or [SEQ_ADDR]))
        out = self._exchange(make, len(reads) or 1, "a write")
        self.counts.plain_reads += 1
        return out if reads else []

    def open(self) -> int:
        """Reads the guard's EXPECT: the next packet's SEQ."""
        self.seq = self.read([SEQ_ADDR])[0]
        return self.seq

    # -- guarded packets
    def transact(self, stream: Sequence[int], reads: Sequence[int] = ()) -> List[int]:
        """One guarded packet: SEQ n, the stream words (chunks_of), then the
        reads (EXPECT first, then `reads`). The words read for `reads`.
        OutOfStep when the guard did not take SEQ n."""
        if self.seq is None:
            self.open()
        if len(stream) > MAX_STREAM:
            raise ValueError(f"{len(stream)} stream words: a packet holds at most {MAX_STREAM}")
        if len(reads) + 1 > MAX_PACKET_READS:
            raise ValueError(f"{len(reads)} reads: a packet holds at most {MAX_PACKET_READS - 1}")
        n = self.seq
        writes = [n] + list(stream)
        addrs = [SEQ_ADDR] + list(reads)

        def make(attempt):
            tag = self.tag(n, attempt)
            return tag, eb.encode(eb.Record(write_base=SEQ_ADDR, writes=writes, ret_base=tag,
                                            reads=addrs))
        words = self._exchange(make, len(addrs), f"packet SEQ {n}")
        expect = words[0]
        want = (n + 1) & 0xFFFFFFFF
        if expect != want:
            raise OutOfStep(
                f"{self.uri}: the guard expects SEQ {expect} after packet {n} (not {want}): "
                "the board was reset or another host uses the link")
        self.seq = want
        self.counts.packets += 1
        self.counts.stream_words += len(stream)
        return words[1:]

    def close(self):
        self.t.close()
