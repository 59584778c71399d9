"""The wrong frame the soak accepted (issue 12), replayed exactly.

tests/vectors/soak-3548-{clean,damaged}.bin are frames 3544 (full) to
3548 of the soak's emulator stream (64x32 PAGE1, RLE), as the emulator
wrote them and as `r8soak --seed 2` damaged them: a burst of random bytes
in the literal run of frame 3548's second band.  The error pattern is a
multiple of the CRC polynomial 0x11021, so the packet CRC-16 passes; the
bytes land unchanged in the frame, so the frame CRC-16 (same polynomial)
passes too, whatever the rest of the frame.  Version 1 reports a wrong
frame good; version 2 (CRC-32 frame check, docs/protocol.md 4.1) does
not."""
import binascii
import json
import os
import subprocess
import sys

from rast8 import codec as C
from rast8.protocol import StreamDecoder, read_dump

HERE = os.path.dirname(os.path.abspath(__file__))
VEC = os.path.join(HERE, "..", "vectors")
sys.path.insert(0, os.path.join(HERE, "..", "soak"))
from wire2 import to_v2  # noqa: E402

FB = 256


def _read(name):
    with open(os.path.join(VEC, name), "rb") as f:
        return f.read()


def _packets(stream):
    return [C.cobs_decode(r) for r in stream.split(b"\x00") if r]


def _polymod(v, nbits, g=0x11021):
    for i in range(nbits - 1, 15, -1):
        if v >> i & 1:
            v ^= g << (i - 16)
    return v


def _decode_both(stream, codec_tool):
    dec = StreamDecoder(FB)
    got = dec.feed(stream)
    dec.finish()
    r = subprocess.run([codec_tool, "dec", str(FB)], input=stream, capture_output=True)
    cgot = read_dump(r.stdout)
    assert [(f.number, f.pixels) for f in got] == [(f.number, f.pixels) for f in cgot]
    assert json.loads(r.stderr) == dec.counters()
    return {f.number: f.pixels for f in got}, dec.counters()


def test_the_damaged_band_passes_both_crc16_checks():
    clean, bad = _read("soak-3548-clean.bin"), _read("soak-3548-damaged.bin")
    diff = [(a, b) for a, b in zip(_packets(clean), _packets(bad)) if a != b]
    assert len(diff) == 1
    o, d = diff[0]
    assert d[0] == 2 and d[1:5] == o[1:5] and len(d) == len(o)     # BAND 3548, y0 8
    for p in (o, d):                                                 # packet CRC-16 good
        assert C.crc16(p[:-2]) == int.from_bytes(p[-2:], "big")
    e = bytes(a ^ b for a, b in zip(o, d))
    assert sum(1 for b in e if b) == 14
    assert _polymod(int.from_bytes(e, "big"), 8 * len(e)) == 0      # a multiple of 0x11021
    bo, bd = C.decode(o[5], o[6:-2], limit=64), C.decode(d[5], d[6:-2], limit=64)
    assert len(bo) == len(bd) == 64 and bo != bd
    # the same error pattern in the frame: the frame CRC-16 cannot see it,
    # wherever the band sits and whatever the other bytes are; CRC-32 can
    assert bytes(a ^ b for a, b in zip(bo, bd)).strip(b"\0") == e.strip(b"\0")
    for pre, post in ((b"", b""), (b"\x55" * 64, b"\xff" * 128), (bytes(range(192)), b"")):
        assert C.crc16(pre + bo + post) == C.crc16(pre + bd + post)
        assert binascii.crc32(pre + bo + post) != binascii.crc32(pre + bd + post)


def test_version_1_accepts_the_wrong_frame(codec_tool):
    clean, _ = _decode_both(_read("soak-3548-clean.bin"), codec_tool)
    assert sorted(clean) == [3544, 3545, 3546, 3547, 3548]
    bad, cnt = _decode_both(_read("soak-3548-damaged.bin"), codec_tool)
    assert sorted(bad) == sorted(clean) and cnt["bad_packets"] == cnt["incomplete"] == 0
    assert bad[3548] != clean[3548]                    # the hole, exactly as in the soak
    assert all(bad[f] == clean[f] for f in range(3544, 3548))


def test_version_2_rejects_it(codec_tool):
    ref, _ = _decode_both(_read("soak-3548-clean.bin"), codec_tool)
    clean2 = to_v2(_read("soak-3548-clean.bin"), ref)
    bad2 = to_v2(_read("soak-3548-damaged.bin"), ref)
    got, cnt = _decode_both(clean2, codec_tool)
    assert got == ref and cnt["incomplete"] == cnt["bad_packets"] == 0
    got, cnt = _decode_both(bad2, codec_tool)
    assert sorted(got) == [3544, 3545, 3546, 3547] and all(got[f] == ref[f] for f in got)
    assert cnt["incomplete"] == 1 and cnt["bad_packets"] == 0


def _rank(nbytes):
    """Rank of the 48 check bits (packet CRC-16, frame CRC-32) over all
    damage confined to `nbytes` consecutive bytes."""
    z = bytes(nbytes)
    c16, c32 = C.crc16(z), binascii.crc32(z)
    basis = {}
    for bit in range(8 * nbytes):
        m = bytearray(nbytes)
        m[bit // 8] ^= 1 << (bit % 8)
        v = ((C.crc16(bytes(m)) ^ c16) << 32) | (binascii.crc32(bytes(m)) ^ c32)
        while v:
            h = v.bit_length() - 1
            if h not in basis:
                basis[h] = v
                break
            v ^= basis[h]
    return len(basis)


def test_crc16_and_crc32_are_independent_checks():
    # docs/protocol.md 4.1: within 5 bytes no damage passes both (rank =
    # all 40 bits); from 7 bytes on the 48 check bits are independent, so
    # 2^-32 of what the packet CRC misses passes the CRC-32
    assert _rank(5) == 40
    assert _rank(7) == _rank(64) == 48
