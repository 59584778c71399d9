"""Codecs: the shared vectors in Python, the generated C header is up to
date, and C (build/rast8-codec) and Python agree byte for byte on random
data and on malformed input."""
import os
import random
import subprocess

import pytest

from rast8 import codec
from rast8.vectors import load, c_header
from conftest import VECTORS

VECS = load(os.path.join(VECTORS, "codec.txt"))
ERR = {3: "MALFORMED", 4: "TRUNC", 5: "SPACE"}


def test_vectors_h_is_generated_from_codec_txt():
    with open(os.path.join(VECTORS, "vectors.h")) as f:
        assert f.read() == c_header(VECS), "run: python -m rast8.vectors tests/vectors/codec.txt tests/vectors/vectors.h"


@pytest.mark.parametrize("v", VECS, ids=lambda v: "%s-%s" % (v["kind"], v["name"]))
def test_vector_python(v):
    k, i, o = v["kind"], v["input"], v["output"]
    if k == "rle":
        assert codec.rle_encode(i) == o
        assert codec.rle_decode(o) == i
    elif k == "lz77":
        assert codec.lz77_encode(i) == o
        assert codec.lz77_decode(o) == i
    elif k == "lz77_dec":
        assert codec.lz77_decode(i) == o
    elif k == "cobs":
        assert codec.cobs_encode(i) == o
        assert codec.cobs_decode(o) == i
    elif k == "crc":
        assert codec.crc16(i).to_bytes(2, "big") == o
    elif k == "stream":
        from rast8.protocol import Encoder, StreamDecoder
        enc = Encoder(0, 16, 8, 8, codec.RLE, full_period=32, dirty=True)
        assert enc.sync() + enc.frame(0, i) + enc.frame(1, i) == o
        assert [f.pixels for f in StreamDecoder().feed(o)] == [i, i]
    elif k == "dec":
        from rast8.protocol import StreamDecoder
        e = v["expect"]
        dec = StreamDecoder(e["fb"])
        got = dec.feed(i)
        dec.finish()
        assert [f.number for f in got] == e["frames"]
        assert {c: dec.counters()[c if c != "bad" else "bad_packets"]
                for c in ("bad", "dropped", "incomplete", "skipped", "ignored")} == \
            {c: e[c] for c in ("bad", "dropped", "incomplete", "skipped", "ignored")}
        # byte at a time gives the same
        one = StreamDecoder(e["fb"])
        assert [f.number for b in i for f in one.feed(bytes([b]))] == e["frames"]
        one.finish()
        assert one.counters() == dec.counters()
    elif k == "dev":
        from rast8.protocol import parse_to_device
        got = parse_to_device(i)
        e = v["expect"]
        inputs = [x for t, x in got if t == "input"]
        assert sum(t == "request" for t, _ in got) == e["requests"]
        assert len(inputs) == e["inputs"]
        assert (inputs[-1] if inputs else 0) == e["keys"]
    else:
        fn = {"rle_bad": codec.rle_decode, "lz77_bad": codec.lz77_decode,
              "cobs_bad": lambda d, limit=None: codec.cobs_decode(d)}[k]
        with pytest.raises(codec.CodecError):
            fn(i, limit=v["limit"])


def test_seed_rle_example_is_inconsistent():
    """The seed shows nine 03s but codes them as 08 03."""
    seed_input = bytes([0x01] + [0x03] * 9 + [0x08, 0x07, 0x06, 0x05])
    seed_output = bytes.fromhex("810108038408070605")
    assert codec.rle_decode(seed_output) != seed_input
    assert codec.rle_decode(seed_output).count(3) == 8
    assert codec.rle_encode(seed_input) == bytes.fromhex("810109038408070605")


def test_crc_check_value():
    assert codec.crc16(b"123456789") == 0x29B1


def _c(tool, *args, data=b""):
    r = subprocess.run([tool] + list(args), input=data, capture_output=True)
    return r.returncode, r.stdout


def _samples(seed, count):
    rnd = random.Random(seed)
    out = [b"", b"\x00", bytes(300), bytes(range(256)) * 2]
    for _ in range(count):
        n = rnd.choice([1, 2, 3, 5, 17, 127, 128, 129, 254, 255, 256, 700, 1024, 3000])
        mode = rnd.random()
        if mode < 0.3:
            d = bytes(rnd.getrandbits(8) for _ in range(n))
        elif mode < 0.6:       # runs
            d = bytearray()
            while len(d) < n:
                d += bytes([rnd.choice([0, 0xFF, rnd.getrandbits(8)])]) * rnd.randint(1, 300)
            d = bytes(d[:n])
        else:                  # framebuffer-like: sparse, repeated patterns
            pat = bytes(rnd.choice([0, 0, 0x55, 0xAA, 0x11, 0x88]) for _ in range(rnd.randint(1, 16)))
            d = bytes((pat * (n // len(pat) + 1))[:n])
            d = bytes(b if rnd.random() > 0.05 else rnd.getrandbits(8) for b in d)
        out.append(d)
    return out


@pytest.mark.parametrize("name", ["rle", "lz77", "cobs"])
def test_c_and_python_agree_on_random_data(codec_tool, name):
    enc = {"rle": codec.rle_encode, "lz77": codec.lz77_encode, "cobs": codec.cobs_encode}[name]
    dec = {"rle": codec.rle_decode, "lz77": codec.lz77_decode, "cobs": codec.cobs_decode}[name]
    for d in _samples({"rle": 1, "lz77": 2, "cobs": 3}[name], 40):
        rc, c_enc = _c(codec_tool, name, "encode", data=d)
        assert rc == 0
        p_enc = enc(d)
        assert c_enc == p_enc, (name, len(d))
        rc, c_dec = _c(codec_tool, name, "decode", data=c_enc)
        assert rc == 0 and c_dec == d == dec(p_enc)


def test_c_and_python_crc_agree(codec_tool):
    for d in _samples(5, 10):
        rc, out = _c(codec_tool, "crc", data=d)
        assert int(out, 16) == codec.crc16(d)


@pytest.mark.parametrize("name", ["rle", "lz77"])
def test_c_and_python_agree_on_garbage(codec_tool, name):
    """Malformed input: both reject it the same way, never past the limit."""
    dec = {"rle": codec.rle_decode, "lz77": codec.lz77_decode}[name]
    rnd = random.Random(11)
    for _ in range(60):
        d = bytes(rnd.getrandbits(8) for _ in range(rnd.randint(1, 40)))
        limit = rnd.choice([0, 10, 100, 5000])
        rc, out = _c(codec_tool, name, "decode", str(limit), data=d)
        try:
            py = dec(d, limit=limit)
            assert rc == 0 and out == py
        except codec.CodecError:
            assert rc in ERR, rc
            assert out == b""
