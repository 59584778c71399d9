"""Fault injection on real emulator streams: bit flips, dropped,
duplicated and inserted bytes, truncation at every position, garbage.
Asserts that no corrupt frame is ever accepted (every good frame equals
the emulator's own framebuffer) and that the decoder resynchronises
within one packet (every undamaged packet after a fault is accepted)."""
import random

import pytest

from rast8.protocol import StreamDecoder, PKT_FRAME_START
from rast8 import codec as C


def packet_map(stream):
    """For each byte: index of its packet (packet k ends at the k-th 0x00
    after the leading sync; bytes before the sync are packet 0).  Also
    each packet's frame number and type."""
    owner = []
    k = 0
    info = [None]
    start = 0
    for i, b in enumerate(stream):
        owner.append(k)
        if b == 0:
            if k > 0:
                body = C.cobs_decode(stream[start:i])[:-2]
                info.append((body[0], int.from_bytes(body[1:3] if body[0] != PKT_FRAME_START
                                                     else body[2:4], "big")))
            start = i + 1
            k += 1
    return owner, info


def check(stream, frames, bad, damaged_packets):
    """Decode `bad`; assert no wrong frame and that exactly the undamaged
    packets were accepted."""
    dec = StreamDecoder()
    got = dec.feed(bad)
    ref = {f.number: f.pixels for f in frames}
    wrong = [f.number for f in got if ref.get(f.number) != f.pixels]
    assert wrong == [], "corrupt frames accepted: %s" % wrong
    owner, info = packet_map(stream)
    total = len(info) - 1
    lost = {p for p in damaged_packets if 1 <= p <= total}
    assert dec.packets == total - len(lost), (dec.packets, total, sorted(lost))
    return dec, got, info, lost


@pytest.fixture(scope="module")
def small(tmp_path_factory):
    from conftest import run_emu
    return run_emu(tmp_path_factory.mktemp("small"), "--frames", "5", "--width", "40",
                   "--height", "16", "--no-dirty")


def _affected(stream, owner, i, kind):
    k = owner[i]
    if kind == "drop" and i == 0:
        return {1}                     # no sync: packet 1 looks like a late join
    if stream[i] == 0 and kind in ("flip", "drop"):
        return {k, k + 1}              # the delimiter merged two packets
    if kind == "dup" and stream[i] == 0:
        return set()                   # an extra delimiter is harmless
    if kind == "insert" and i > 0 and stream[i - 1] == 0 and stream[i] == 0:
        return {k}
    return {k}


@pytest.mark.parametrize("kind", ["flip", "drop", "dup", "insert"])
def test_every_single_fault_full_frames(small, kind):
    stream, frames = small
    owner, info = packet_map(stream)
    n_frames = len(frames)
    for i in range(len(stream)):
        s = bytearray(stream)
        if kind == "flip":
            s[i] ^= 1 << (i % 8)
        elif kind == "drop":
            del s[i]
        elif kind == "dup":
            s.insert(i, s[i])
        else:
            s.insert(i, 0x55)
        aff = _affected(stream, owner, i, kind)
        dec, got, info, lost = check(stream, frames, bytes(s), aff)
        lost_frames = {info[p][1] for p in lost}
        assert len(got) == n_frames - len(lost_frames), (i, kind)
        if lost:
            # (a damaged leading sync makes packet 1 a late join: dropped silently)
            assert dec.bad_packets >= 1 or max(lost) == len(info) - 1 or i == 0


def test_truncation_at_every_position(emu_stream):
    """A prefix of the stream gives exactly the frames whose FRAME_END
    delimiter it holds, never a wrong one."""
    stream, frames = emu_stream("--frames", "8", "--full-period", "4")
    owner, info = packet_map(stream)
    ends = [i for i, b in enumerate(stream) if b == 0 and owner[i] > 0
            and info[owner[i]][0] == 3]
    dec = StreamDecoder()
    got = []
    for i, b in enumerate(stream):
        got += dec.feed(bytes([b]))
        expect = sum(1 for e in ends if e <= i)
        assert len(got) == expect
    assert [f.pixels for f in got] == [f.pixels for f in frames]


@pytest.mark.parametrize("seed", range(4))
def test_random_faults_dirty_bands(emu_stream, seed):
    """Several faults of every kind in a dirty-band stream: nothing wrong
    is accepted, undamaged packets are accepted, and every frame after
    the next full frame past the damage decodes."""
    stream, frames = emu_stream("--frames", "24", "--full-period", "6", name="d%d" % seed)
    full_of = {f.number: f.full for f in StreamDecoder().feed(stream)}
    owner, info = packet_map(stream)
    rnd = random.Random(seed)
    for _ in range(60):
        s = bytearray(stream)
        nfaults = rnd.randint(1, 3)
        positions = sorted(rnd.sample(range(1, len(stream)), nfaults), reverse=True)
        damaged = set()
        for i in positions:        # right to left keeps earlier indices valid
            kind = rnd.choice(["flip", "drop", "dup", "insert"])
            if kind == "flip":
                s[i] ^= 1 << rnd.randrange(8)
            elif kind == "drop":
                del s[i]
            elif kind == "dup":
                s.insert(i, s[i])
            else:
                s.insert(i, rnd.randrange(1, 256))
            damaged |= _affected(stream, owner, i, kind)
        dec, got, _, lost = check(stream, frames, bytes(s), damaged)
        good = {f.number for f in got}
        last_bad_frame = max(info[p][1] for p in lost) if lost else -1
        resync = [f.number for f in frames if f.number > last_bad_frame and full_of[f.number]]
        if resync:
            must = [f.number for f in frames if f.number >= resync[0]]
            assert set(must) <= good, (sorted(set(must) - good))


def test_pure_garbage_then_stream(emu_stream):
    stream, frames = emu_stream("--frames", "6")
    rnd = random.Random(9)
    dec = StreamDecoder()
    junk = bytes(rnd.getrandbits(8) for _ in range(20000))
    assert dec.feed(junk) == []
    assert dec.bad_packets > 0 and dec.frames == 0
    got = dec.feed(b"\x00" + stream)
    assert [f.pixels for f in got] == [f.pixels for f in frames]


def test_garbage_without_delimiters_cannot_overflow():
    dec = StreamDecoder(max_frame_bytes=1024)
    assert dec.feed(b"\x00" + bytes([0x41]) * 100000) == []
    assert len(dec._pkt) <= dec.pkt_size
    dec.feed(b"\x00")
    assert dec.bad_packets == 1


def test_lost_start_counts_incomplete_and_lost_frame_counts_dropped(emu_stream):
    stream, frames = emu_stream("--frames", "6", "--no-dirty")
    owner, info = packet_map(stream)
    # remove all of frame 2's packets: dropped; remove frame 4's start: incomplete
    keep = bytearray()
    for i, b in enumerate(stream):
        p = owner[i]
        if p and info[p][1] == 2:
            continue
        if p and info[p] == (PKT_FRAME_START, 4):
            continue
        keep.append(b)
    dec = StreamDecoder()
    got = dec.feed(bytes(keep))
    assert [f.number for f in got] == [0, 1, 3, 5]
    assert dec.dropped == 1 and dec.incomplete == 1 and dec.bad_packets == 0
