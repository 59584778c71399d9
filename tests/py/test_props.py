"""Property tests (hypothesis): codecs and COBS round-trip any input,
decoders reject or bound anything, the stream decoder never reports a
frame it was not sent."""
from hypothesis import given, settings, strategies as st

from rast8 import codec as C
from rast8.protocol import Encoder, StreamDecoder

data = st.binary(max_size=600) | st.lists(
    st.tuples(st.integers(0, 255), st.integers(1, 200)), max_size=20).map(
    lambda runs: b"".join(bytes([b]) * n for b, n in runs))


@given(data)
@settings(max_examples=150, deadline=None)
def test_rle_round_trip(d):
    e = C.rle_encode(d)
    assert C.rle_decode(e) == d
    assert len(e) <= C.rle_bound(len(d))


@given(data)
@settings(max_examples=60, deadline=None)
def test_lz77_round_trip(d):
    e = C.lz77_encode(d)
    assert C.lz77_decode(e) == d
    assert len(e) <= C.lz77_bound(len(d))


@given(data)
@settings(max_examples=150, deadline=None)
def test_cobs_round_trip(d):
    e = C.cobs_encode(d)
    assert 0 not in e and C.cobs_decode(e) == d
    assert len(e) <= len(d) + len(d) // 254 + 1


@given(st.binary(max_size=200), st.integers(0, 300))
@settings(max_examples=200, deadline=None)
def test_decoders_bounded(d, limit):
    for fn in (C.rle_decode, C.lz77_decode):
        try:
            assert len(fn(d, limit)) <= limit
        except C.CodecError:
            pass


@given(st.lists(st.binary(min_size=32, max_size=32), min_size=1, max_size=5),
       st.binary(max_size=64), st.integers(0, 10 ** 6))
@settings(max_examples=80, deadline=None)
def test_stream_never_yields_unsent_frames(frames, junk, pos):
    enc = Encoder(0, 16, 16, 8, C.RLE, full_period=2)
    stream = bytearray(enc.sync())
    for i, px in enumerate(frames):
        stream += enc.frame(i, px)
    p = pos % (len(stream) + 1)
    stream[p:p] = junk
    got = StreamDecoder().feed(bytes(stream))
    for f in got:
        assert f.pixels == frames[f.number]
