"""The protocol on real emulator streams: the Python encoder writes the
emulator's bytes exactly; the Python and C decoders give the emulator's
framebuffers and agree with each other (frames and counters) on clean
and damaged streams."""
import random
import subprocess

import pytest

from rast8.protocol import (StreamDecoder, Encoder, read_dump, request_packet,
                            FORMAT_NAMES, fb_bytes)
from rast8 import codec as C

CONFIGS = [
    ("--codec", "rle"),
    ("--codec", "lz77"),
    ("--codec", "raw"),
    ("--codec", "rle", "--no-dirty"),
    ("--codec", "lz77", "--full-period", "5", "--band", "16"),
    ("--format", "row1", "--band", "5"),
    ("--format", "idx8", "--width", "48", "--height", "30", "--band", "7"),
    ("--width", "64", "--height", "40", "--band", "40"),
    ("--codec", "huff"),
    ("--codec", "lzw"),
    ("--codec", "best"),
    ("--codec", "best", "--format", "idx8", "--width", "48", "--height", "30", "--band", "7"),
]


def _opt(args, name, default):
    return args[args.index(name) + 1] if name in args else default


@pytest.mark.parametrize("args", CONFIGS, ids=lambda a: " ".join(a))
def test_python_encoder_matches_emulator_bytes(emu_stream, args):
    stream, frames = emu_stream("--frames", "12", *args)
    assert len(frames) == 12
    fmt = FORMAT_NAMES[_opt(args, "--format", "page1")]
    w, h = int(_opt(args, "--width", 128)), int(_opt(args, "--height", 64))
    pal = [(v, v, v) for v in (0, 16, 32, 48, 64, 80, 96, 112, 128, 143, 159, 175, 191,
                               207, 223, 239, 255)] if fmt == 2 else []
    enc = Encoder(fmt, w, h, int(_opt(args, "--band", 8)),
                  dict(C.CODEC_NAMES, best=C.BEST)[_opt(args, "--codec", "rle")],
                  int(_opt(args, "--full-period", 32)), "--no-dirty" not in args, pal)
    ours = enc.sync() + b"".join(enc.frame(f.number, f.pixels) for f in frames)
    assert ours == stream


@pytest.mark.parametrize("args", CONFIGS, ids=lambda a: " ".join(a))
def test_decoders_give_the_emulator_framebuffers(emu_stream, codec_tool, args):
    stream, frames = emu_stream("--frames", "12", *args)
    dec = StreamDecoder()
    got = dec.feed(stream)
    assert [f.number for f in got] == [f.number for f in frames]
    assert all(a.pixels == b.pixels for a, b in zip(got, frames))
    assert dec.counters()["bad_packets"] == dec.dropped == dec.incomplete == 0
    r = subprocess.run([codec_tool, "dec"], input=stream, capture_output=True)
    assert [f.pixels for f in read_dump(r.stdout)] == [f.pixels for f in frames]



@pytest.mark.parametrize("args", CONFIGS[:3] + CONFIGS[5:7], ids=lambda a: " ".join(a))
def test_version_2_streams_decode_in_both_decoders(emu_stream, codec_tool, args):
    """The emulator's frames re-encoded as version 2 (CRC-32 frame check,
    docs/protocol.md 4.1): the same frames from both decoders."""
    stream, frames = emu_stream("--frames", "12", *args)
    fmt = FORMAT_NAMES[_opt(args, "--format", "page1")]
    w, h = int(_opt(args, "--width", 128)), int(_opt(args, "--height", 64))
    enc = Encoder(fmt, w, h, int(_opt(args, "--band", 8)),
                  C.CODEC_NAMES[_opt(args, "--codec", "rle")],
                  int(_opt(args, "--full-period", 32)), "--no-dirty" not in args, version=2)
    v2 = enc.sync() + b"".join(enc.frame(f.number, f.pixels) for f in frames)
    assert v2 != stream
    dec = StreamDecoder()
    got = dec.feed(v2)
    dec.finish()
    assert [(f.number, f.pixels) for f in got] == [(f.number, f.pixels) for f in frames]
    assert dec.counters()["bad_packets"] == dec.incomplete == 0
    r = subprocess.run([codec_tool, "dec"], input=v2, capture_output=True)
    assert [f.pixels for f in read_dump(r.stdout)] == [f.pixels for f in frames]

def _damage(stream, rnd):
    s = bytearray(stream)
    for _ in range(rnd.randint(1, 4)):
        kind = rnd.choice(["flip", "drop", "dup", "insert", "zero", "burst"])
        i = rnd.randrange(len(s))
        if kind == "flip":
            s[i] ^= 1 << rnd.randrange(8)
        elif kind == "drop":
            del s[i]
        elif kind == "dup":
            s[i:i] = s[i:i + rnd.randint(1, 30)]
        elif kind == "insert":
            s[i:i] = bytes([rnd.getrandbits(8)])
        elif kind == "zero":
            s[i] = 0
        else:
            s[i:i + 8] = bytes(rnd.getrandbits(8) for _ in range(8))
    return bytes(s)


def test_c_and_python_decoders_agree_on_damaged_streams(emu_stream, codec_tool):
    stream, frames = emu_stream("--frames", "10", "--full-period", "3")
    ref = {f.number: f.pixels for f in frames}
    rnd = random.Random(3)
    import json
    for _ in range(40):
        bad = _damage(stream, rnd)
        dec = StreamDecoder()
        got = dec.feed(bad)
        dec.finish()
        r = subprocess.run([codec_tool, "dec"], input=bad, capture_output=True)
        cgot = read_dump(r.stdout)
        assert [(f.number, f.pixels) for f in got] == [(f.number, f.pixels) for f in cgot]
        assert json.loads(r.stderr) == dec.counters()
        assert all(ref[f.number] == f.pixels for f in got)


def test_request_packet_bytes():
    # 10 + CRC, COBS, delimited: fixed bytes, documented in docs/protocol.md
    p = request_packet()
    assert p[0] == 0 and p[-1] == 0 and 0 not in p[1:-1]
    assert C.cobs_decode(p[1:-1])[0] == 0x10
    assert C.crc16(C.cobs_decode(p[1:-1])[:1]) == int.from_bytes(C.cobs_decode(p[1:-1])[1:], "big")


def test_image_layouts_agree_with_framebuffer_layouts(emu_stream):
    """Each format's image shows the same picture (same lit pixels) for
    the same frame."""
    imgs = {}
    for fmt in ("page1", "row1"):
        _, frames = emu_stream("--frames", "3", "--format", fmt, name=fmt)
        imgs[fmt] = [f.to_image().tobytes() for f in frames]
    assert imgs["page1"] == imgs["row1"]
