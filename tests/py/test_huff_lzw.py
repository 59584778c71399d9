"""Static Huffman and LZW (docs/protocol.md 3.4, 3.5) and the per-band
choice (3.6): the document's vectors, C and Python byte for byte on band
data and random data, malformed payloads rejected by both, and damaged
payloads with good packet CRCs never giving a wrong frame."""
import json
import random
import subprocess

import pytest

from rast8 import codec as C
from rast8.protocol import StreamDecoder, read_dump, packet
from rast8.hufftab import HUFF_LEN

HUFF_VECTORS = [
    ("00 00 00 00 00 00 00 00", "00"),
    ("00 00 00 FF FF 00 01 03", "19 E6 D1 3F"),
    ("00 00 00 00 00 00 FF FF FF FF 00 00 00 00 00 00", "03 3C F3 CC 0F"),
    ("41", "F6 8F"),
    ("", ""),
]
LZW_VECTORS = [
    ("00 00 00 00 00 00 00 00", "00 40 20 30 00"),
    (b"TOBEORNOTTOBEORTOBEORNOT".hex(), "2A 13 C8 44 52 79 48 9C 4F 2A 40 20 50 48 4C 0E 0B 07"),
    ("61 61 61 61 61 61 61", "30 C0 20 26 10"),
    ("41", "20 80"),
    ("", ""),
]


def _h(s):
    return bytes.fromhex(s)


@pytest.mark.parametrize("raw,enc", HUFF_VECTORS)
def test_huff_vectors(raw, enc):
    assert C.huff_encode(_h(raw)) == _h(enc)
    assert C.huff_decode(_h(enc)) == _h(raw)


@pytest.mark.parametrize("raw,enc", LZW_VECTORS)
def test_lzw_vectors(raw, enc):
    assert C.lzw_encode(_h(raw)) == _h(enc)
    assert C.lzw_decode(_h(enc)) == _h(raw)


def test_huff_code_is_complete_canonical_and_padding_safe():
    assert sum(2.0 ** -l for l in HUFF_LEN) == 1.0
    assert 8 <= max(HUFF_LEN) <= C.HUFF_MAXLEN
    # all-ones strings shorter than 8 bits are never a code (the padding)
    for ln in range(1, 8):
        assert (ln, (1 << ln) - 1) not in C._HUFF_DEC


def _samples(tmp_path, emu_stream):
    _, frames = emu_stream("--frames", "6", "--scene", "teapot")
    _, frames2 = emu_stream("--frames", "3", "--format", "idx8", name="i")
    out = [b"", b"\x00", bytes(300), bytes(range(256)) * 2]
    for f in frames:
        out += [bytes(f.pixels[k:k + 128]) for k in range(0, 1024, 128)]
    out += [bytes(f.pixels[k:k + 1024]) for f in frames2 for k in (0, 3072)]
    rnd = random.Random(13)
    for _ in range(30):
        n = rnd.randrange(0, 900)
        out.append(bytes(rnd.choice((0, 0, 0, 255, 7, rnd.randrange(256))) for _ in range(n)))
    return out


@pytest.mark.parametrize("name", ["huff", "lzw"])
def test_c_and_python_agree(tmp_path, emu_stream, codec_tool, name):
    cid = C.CODEC_NAMES[name]
    for s in _samples(tmp_path, emu_stream):
        e = C.encode(cid, s)
        r = subprocess.run([codec_tool, name, "encode"], input=s, capture_output=True)
        assert r.returncode == 0 and r.stdout == e
        assert len(e) <= (C.huff_bound if name == "huff" else C.lzw_bound)(len(s))
        r = subprocess.run([codec_tool, name, "decode"], input=e, capture_output=True)
        assert r.returncode == 0 and r.stdout == s
        assert C.decode(cid, e, limit=len(s)) == s


@pytest.mark.parametrize("name", ["huff", "lzw"])
def test_malformed_rejected_by_both(codec_tool, name):
    cid = C.CODEC_NAMES[name]
    rnd = random.Random(5)
    bad = 0
    for _ in range(300):
        data = bytes(rnd.randrange(256) for _ in range(rnd.randrange(1, 40)))
        r = subprocess.run([codec_tool, name, "decode", "4096"], input=data, capture_output=True)
        try:
            py = C.decode(cid, data, limit=4096)
        except C.CodecError:
            py = None
        if py is None:
            bad += 1
            assert r.returncode in (3, 4), data.hex()
        else:
            assert r.returncode == 0 and r.stdout == py, data.hex()
    assert bad > 10   # random input is often malformed (a cut code, a bad entry, padding)


def test_best_is_the_smallest_ties_to_the_lower_id(tmp_path, emu_stream):
    for s in _samples(tmp_path, emu_stream)[4:40]:
        cid, e = C.best_encode(s)
        sizes = {c: len(C.encode(c, s)) for c in (C.RLE, C.LZ77, C.HUFF, C.LZW)}
        if cid == C.RAW:
            assert min(sizes.values()) >= len(s)
        else:
            assert len(e) == sizes[cid] == min(sizes.values()) < len(s)
            assert all(c >= cid for c, n in sizes.items() if n == sizes[cid])
        assert C.decode(cid, e) == s


@pytest.mark.parametrize("codec", ["huff", "lzw", "best"])
def test_damaged_payloads_never_give_a_wrong_frame(emu_stream, codec_tool, codec):
    """Payload bytes changed and the packet CRC recomputed (so only the
    codec and the frame check stand between the damage and the display):
    both decoders agree, and every frame they call good is the
    emulator's."""
    stream, frames = emu_stream("--frames", "10", "--full-period", "3", "--codec", codec)
    ref = {f.number: f.pixels for f in frames}
    pkts = stream.split(b"\x00")
    bodies = [C.cobs_decode(p)[:-2] if p else None for p in pkts]
    bands = [i for i, b in enumerate(bodies) if b and b[0] == 2 and len(b) > 7]
    rnd = random.Random(17)
    wrong_len = 0
    for _ in range(60):
        i = rnd.choice(bands)
        b = bytearray(bodies[i])
        for _ in range(rnd.randrange(1, 4)):
            b[rnd.randrange(6, len(b))] ^= 1 << rnd.randrange(8)
        if rnd.random() < 0.3:
            del b[rnd.randrange(6, len(b))]
        new = pkts[:]
        new[i] = packet(bytes(b))[:-1]
        bad = b"\x00".join(new)
        dec = StreamDecoder()
        got = dec.feed(bad)
        dec.finish()
        r = subprocess.run([codec_tool, "dec"], input=bad, capture_output=True)
        cgot = read_dump(r.stdout)
        assert [(f.number, f.pixels) for f in got] == [(f.number, f.pixels) for f in cgot]
        assert json.loads(r.stderr) == dec.counters()
        assert all(ref[f.number] == f.pixels for f in got)
        wrong_len += dec.bad_packets
    assert wrong_len > 0
