"""Hypothesis properties of the Python codecs (issue 6), beyond the round
trips in test_props.py: byte-for-byte agreement with the C codecs
(build/rast8-codec) on generated and on mutated input, truncation and
corruption behaviour, CRC algebra, chunking independence of the stream
decoder, and the reference renderer's frame byte layouts."""
import os
import subprocess

import numpy as np
from hypothesis import given, settings, strategies as st, HealthCheck

from rast8 import codec as C
from rast8 import reference as R
from rast8.protocol import Encoder, StreamDecoder

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
CODEC = os.path.join(ROOT, "build", "rast8-codec")

runs = st.lists(st.tuples(st.integers(0, 255), st.integers(1, 300)), max_size=12).map(
    lambda rs: b"".join(bytes([b]) * n for b, n in rs))
repeats = st.tuples(st.binary(min_size=1, max_size=40), st.integers(1, 40), st.binary(max_size=30)).map(
    lambda t: t[0] * t[1] + t[2])
data = st.binary(max_size=500) | runs | repeats


def _c(args, inp):
    if not os.path.exists(CODEC):
        subprocess.run(["make", "-C", ROOT, "-s", "build/rast8-codec"], check=True)
    r = subprocess.run([CODEC] + args, input=inp, capture_output=True)
    return r.returncode, r.stdout


def _py_decode(fn, d, limit):
    try:
        return 0, fn(d, limit)
    except C.CodecError:
        return 1, None


@given(data)
@settings(max_examples=40, deadline=None)
def test_encoders_match_c(d):
    for name, enc in (("rle", C.rle_encode), ("lz77", C.lz77_encode), ("cobs", C.cobs_encode),
                      ("huff", C.huff_encode), ("lzw", C.lzw_encode)):
        rc, out = _c([name, "encode"], d)
        assert rc == 0 and out == enc(d), name


@given(data, st.integers(0, 400), st.data())
@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
def test_decoders_match_c_on_mutated_input(d, limit, draw):
    # a valid encoding with a few bytes changed, cut or extended: both
    # decoders accept it with the same output or both refuse it
    for name, enc, dec in (("rle", C.rle_encode, C.rle_decode), ("lz77", C.lz77_encode, C.lz77_decode),
                           ("huff", C.huff_encode, C.huff_decode), ("lzw", C.lzw_encode, C.lzw_decode)):
        e = bytearray(enc(d))
        for _ in range(draw.draw(st.integers(0, 3))):
            if e:
                e[draw.draw(st.integers(0, len(e) - 1))] = draw.draw(st.integers(0, 255))
        e = bytes(e[:draw.draw(st.integers(0, len(e)))]) if draw.draw(st.booleans()) else bytes(e)
        prc, pout = _py_decode(dec, e, limit)
        crc, cout = _c([name, "decode", str(limit)], e)
        assert (prc == 0) == (crc == 0), (name, e)
        if prc == 0:
            assert pout == cout and len(pout) <= limit


@given(data, st.data())
@settings(max_examples=100, deadline=None)
def test_truncated_encoding_gives_prefix_or_error(d, draw):
    for enc, dec in ((C.rle_encode, C.rle_decode), (C.lz77_encode, C.lz77_decode),
                     (C.huff_encode, C.huff_decode), (C.lzw_encode, C.lzw_decode)):
        e = enc(d)
        cut = draw.draw(st.integers(0, len(e)))
        try:
            out = dec(e[:cut])
        except C.CodecError:
            continue
        assert d.startswith(out)


@given(st.binary(max_size=300), st.binary(max_size=300))
@settings(max_examples=100, deadline=None)
def test_crc_incremental_and_single_bit_errors(a, b):
    assert C.crc16(a + b) == C.crc16(b, C.crc16(a))
    whole = a + b
    if whole:
        for bit in (0, 7, 8 * len(whole) - 1):
            m = bytearray(whole)
            m[bit // 8] ^= 1 << (bit % 8)
            assert C.crc16(bytes(m)) != C.crc16(whole)


@given(st.binary(max_size=600))
@settings(max_examples=150, deadline=None)
def test_cobs_decode_arbitrary(d):
    # any input without a zero either decodes to something that encodes
    # back to a canonical form, or is refused; it never raises otherwise
    d = d.replace(b"\0", b"\1")
    try:
        out = C.cobs_decode(d)
    except C.CodecError:
        return
    assert C.cobs_decode(C.cobs_encode(out)) == out


@given(st.lists(st.binary(min_size=32, max_size=32), min_size=1, max_size=4),
       st.lists(st.integers(1, 50), min_size=1, max_size=20))
@settings(max_examples=60, deadline=None)
def test_stream_decoder_chunking_independent(frames, cuts):
    enc = Encoder(0, 16, 16, 8, C.LZ77, full_period=3)
    stream = bytearray(enc.sync())
    for i, px in enumerate(frames):
        stream += enc.frame(i, px)
    whole = [(f.number, f.pixels) for f in StreamDecoder().feed(bytes(stream))]
    dec, got, p, k = StreamDecoder(), [], 0, 0
    while p < len(stream):
        n = cuts[k % len(cuts)]
        got += [(f.number, f.pixels) for f in dec.feed(bytes(stream[p:p + n]))]
        p += n
        k += 1
    assert got == whole == [(i, px) for i, px in enumerate(frames)]


@given(st.integers(1, 40), st.integers(1, 24), st.data())
@settings(max_examples=100, deadline=None)
def test_reference_frame_layouts_round_trip(w, h, draw):
    lev = np.array(draw.draw(st.lists(st.integers(0, 16), min_size=w * h, max_size=w * h))).reshape(h, w)
    fr = R.Frame(w, h, lev, np.where(lev > 0, 0, -1), np.full((h, w), np.inf))
    for fmt in R.FORMATS:
        b = fr.to_bytes(fmt)
        assert len(b) == R.frame_bytes(fmt, w, h)
        assert (R.unpack(b, fmt, w, h) == fr.pixels(fmt)).all()
