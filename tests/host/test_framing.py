"""The UART framing (sw/host/hwinterp_host/framing.py): CRC-32/IEEE, SLIP
escapes, and the deframer's refusals, against hand-checked bytes."""
import struct

from hwinterp_host import framing as fr

PKT = bytes.fromhex("4e6f104400000000000f0100" "00080000" "00000007")


def test_crc32_check_value():
    assert fr.crc32(b"123456789") == 0xCBF43926      # the standard check value
    assert fr.crc32(b"") == 0


def test_frame_bytes_by_hand():
    # a payload holding END and ESC: each becomes ESC + code; CRC least significant byte first
    pkt = bytes([0x01, fr.END, 0x02, fr.ESC, 0x03])
    crc = fr.crc32(pkt)
    want = (bytes([fr.END, 0x01, fr.ESC, fr.ESC_END, 0x02, fr.ESC, fr.ESC_ESC, 0x03])
            + fr.escape(struct.pack("<I", crc)) + bytes([fr.END]))
    assert fr.frame(pkt) == want
    assert struct.pack("<I", 0xCBF43926) == bytes([0x26, 0x39, 0xF4, 0xCB])


def test_round_trip_in_pieces_and_noise():
    d = fr.Deframer()
    wire = b"\x11\x22" + fr.frame(PKT) + fr.frame(PKT[:-1] + b"\xc0") + fr.frame(PKT)
    got = []
    for i in range(0, len(wire), 3):          # the bytes arrive in small pieces
        got += d.feed(wire[i:i + 3])
    assert got == [PKT, PKT[:-1] + b"\xc0", PKT]
    # the noise before the first END made one frame of 2 bytes: too short
    assert d.counts.frames == 3 and d.counts.too_short == 1


def test_refusals():
    d = fr.Deframer()
    good = fr.frame(PKT)
    bad_crc = bytearray(good)
    bad_crc[5] ^= 0x01
    assert d.feed(bytes(bad_crc)) == [] and d.counts.bad_crc == 1
    assert d.feed(bytes([fr.END, 0x41, fr.ESC, 0x41, fr.END])) == [] and d.counts.bad_escape == 1
    short = bytes(PKT[:7])
    assert d.feed(fr.frame(short)) == [] and d.counts.too_short == 1
    small = fr.Deframer(max_bytes=16)
    assert small.feed(good) == [] and small.counts.too_long == 1
    assert d.feed(good) == [PKT]              # and the next good frame goes through
    assert d.feed(bytes([fr.END, fr.END])) == []   # empty frames are ignored
    assert d.counts.frames == 1
