"""Fault-injection soak of the Python decoder (rast8.protocol.StreamDecoder)
on a real emulator stream: the twin of tests/soak/soak.c (same fault
kinds, same checks, same summary line).  `make soak` runs both.

    python tests/soak/soak.py STREAM DUMP [--faults N] [--seed S] [--jobs J]

Each pass copies the stream with faults in it (at most one per frame,
fault frames at least 3 apart, a fault every 3..64 frames), decodes it
and checks: every good frame equals the reference frame of that number;
a cluster of k faults whose recovery windows overlap loses at most
k * (P + 1) frames (P = the stream's full-frame period); a duplicated
packet loses none; every frame outside a fault window decodes.
Exit 1 if a check failed.
"""
import argparse
import os
import random
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "host"))

from rast8.protocol import StreamDecoder, read_dump, PKT_FRAME_START, FLAG_FULL  # noqa: E402
from rast8 import codec as C  # noqa: E402

KINDS = ["flip", "drop", "insert", "burst", "cut", "dup", "swap", "frame"]


def index_stream(stream):
    """Packets as (start, end = index of its 0x00, frame index); the first
    packet of each frame; the full-frame period P."""
    pkts, first, fi, last_full, period = [], [], -1, -1, 1
    version = 0
    start = None
    for i, b in enumerate(stream):
        if b:
            continue
        if start is not None and i > start:
            # the kind is the first body byte (never 0: the first code > 1)
            if stream[start + 1] == PKT_FRAME_START and stream[start] > 1:
                body = C.cobs_decode(stream[start:i])
                fi += 1
                first.append(len(pkts))
                version = body[1]
                if body[12] & FLAG_FULL:
                    if last_full >= 0:
                        period = max(period, fi - last_full)
                    last_full = fi
            pkts.append((start, i, fi))
        start = i + 1
    period = max(period, fi - last_full)
    first.append(len(pkts))
    return pkts, first, fi + 1, period, version


class Stats:
    def __init__(self):
        self.faults = 0
        self.kinds = dict.fromkeys(KINDS, 0)
        self.truncs = 0
        self.checked = self.wrong = self.over = self.dup_lost = self.unexplained = 0
        self.worst = 0
        self.worst_kind = dict.fromkeys(KINDS, 0)

    def add(self, o):
        for k in ("faults", "truncs", "checked", "wrong", "over", "dup_lost", "unexplained"):
            setattr(self, k, getattr(self, k) + getattr(o, k))
        for k in KINDS:
            self.kinds[k] += o.kinds[k]
            self.worst_kind[k] = max(self.worst_kind[k], o.worst_kind[k])
        self.worst = max(self.worst, o.worst)


def one_pass(rnd, stream, pkts, first, nframes, period, ref, idx, fbytes, npass, st):
    spacing = 3 + rnd.randrange(62)
    faults = []                                   # [kind, frame, packet, lo, hi]
    f = 1 + rnd.randrange(spacing)
    while f < nframes - 1:
        faults.append([rnd.choice(KINDS), f, first[f] + rnd.randrange(first[f + 1] - first[f]),
                       f, f])
        f += 3 + rnd.randrange(2 * spacing - 3)
    by_frame = {x[1]: x for x in faults}
    out = bytearray(stream[:pkts[0][0]])
    frame_end = [0] * nframes
    k = 0
    rb = lambda n: bytes(rnd.getrandbits(8) for _ in range(n))  # noqa: E731
    while k < len(pkts):
        s, e, fr = pkts[k]
        x = by_frame.get(fr)
        if x and x[0] == "frame":
            pass
        elif x and k == x[2]:
            p = s + rnd.randrange(e + 1 - s)
            kind = x[0]
            if kind == "flip":
                out += stream[s:p] + bytes([stream[p] ^ (1 << rnd.randrange(8))]) + stream[p + 1:e + 1]
            elif kind == "drop":
                n = min(1 + rnd.randrange(4), e + 1 - p)
                out += stream[s:p] + stream[p + n:e + 1]
            elif kind == "insert":
                out += stream[s:p] + rb(1 + rnd.randrange(4)) + stream[p:e + 1]
            elif kind == "burst":
                n = 2 + rnd.randrange(15)
                if p + n > e + 1:
                    p = max(s, e + 1 - n)
                n = min(n, e + 1 - p)
                out += stream[s:p] + rb(n) + stream[p + n:e + 1]
            elif kind == "cut":
                out += stream[s:p] + b"\x00"
            elif kind == "dup":
                out += stream[s:e + 1] * 2
            elif kind == "swap":
                if k + 1 < len(pkts):
                    ns, ne, _ = pkts[k + 1]
                    out += stream[ns:ne + 1] + stream[s:e + 1]
                    k += 1
                else:
                    out += stream[s:e + 1]
            if k + 1 < len(pkts) and pkts[k + 1][2] != fr:
                x[4] = fr + 1
        else:
            out += stream[s:e + 1]
        frame_end[fr] = len(out)
        k += 1
    st.faults += len(faults)
    for x in faults:
        st.kinds[x[0]] += 1
    end_frame = nframes
    if npass % 4 == 3:
        cut = len(out) - 1 - rnd.randrange(len(out) // 10 + 1)
        del out[cut:]
        while end_frame > 0 and frame_end[end_frame - 1] > cut:
            end_frame -= 1
        st.faults += 1
        st.truncs += 1
    dec = StreamDecoder(fbytes)
    good = [False] * nframes
    for fr in dec.feed(out):
        fi = idx.get(fr.number)
        if fi is None or fr.pixels != ref[fi]:
            st.wrong += 1
            continue
        st.checked += 1
        good[fi] = True
    dec.finish()
    # clusters of faults whose windows overlap
    c0 = 0
    for i in range(len(faults) + 1):
        if i < len(faults) and i > c0 and faults[i][3] <= faults[i - 1][4] + period + 1:
            continue
        if i > c0:
            lo, hi = faults[c0][3], min(faults[i - 1][4] + period + 1, end_frame - 1)
            lost = sum(1 for fr in range(lo, hi + 1) if not good[fr])
            kk = i - c0
            if lost > kk * (period + 1):
                st.over += 1
            if all(x[0] == "dup" for x in faults[c0:i]) and lost:
                st.dup_lost += 1
            if kk == 1:
                st.worst = max(st.worst, lost)
                st.worst_kind[faults[c0][0]] = max(st.worst_kind[faults[c0][0]], lost)
        c0 = i
    i = 0
    for fr in range(end_frame):
        while i < len(faults) and faults[i][4] + period + 1 < fr:
            i += 1
        if i < len(faults) and fr >= faults[i][3]:
            continue
        if not good[fr]:
            st.unexplained += 1


def run(stream_path, dump_path, want, seed, job=0, jobs=1, progress=True):
    stream = open(stream_path, "rb").read()
    frames = read_dump(dump_path)
    pkts, first, nframes, period, version = index_stream(stream)
    if len(frames) != nframes:
        raise SystemExit("soak: the dump has %d frames, the stream %d" % (len(frames), nframes))
    ref = [f.pixels for f in frames]
    idx = {f.number: i for i, f in enumerate(frames)}
    if len(idx) != nframes:
        raise SystemExit("soak: frame numbers repeat: use a stream of < 65536 frames")
    rnd = random.Random(seed * 1000 + job)
    st = Stats()
    npass = 0
    while st.faults < want:
        one_pass(rnd, stream, pkts, first, nframes, period, ref, idx, len(ref[0]), npass, st)
        npass += 1
        if progress and npass % 20 == 0:
            print("soak.py: %d faults..." % st.faults, file=sys.stderr, flush=True)
    return st, period, version


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("stream")
    ap.add_argument("dump")
    ap.add_argument("--faults", type=int, default=10 ** 7)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--jobs", type=int, default=1, help="worker processes")
    ap.add_argument("--quiet", action="store_true")
    a = ap.parse_args(argv)
    if a.jobs > 1:
        from concurrent.futures import ProcessPoolExecutor
        per = (a.faults + a.jobs - 1) // a.jobs
        with ProcessPoolExecutor(a.jobs) as ex:
            res = list(ex.map(run, [a.stream] * a.jobs, [a.dump] * a.jobs, [per] * a.jobs,
                              [a.seed] * a.jobs, range(a.jobs), [a.jobs] * a.jobs,
                              [not a.quiet and j == 0 for j in range(a.jobs)]))
        st, period, version = Stats(), res[0][1], res[0][2]
        for r, _, _ in res:
            st.add(r)
    else:
        st, period, version = run(a.stream, a.dump, a.faults, a.seed, progress=not a.quiet)
    kinds = ", ".join("%s %d" % (k, st.kinds[k]) for k in KINDS)
    wk = " ".join("%s %d" % (k, st.worst_kind[k]) for k in KINDS)
    print("soak Python decoder (protocol v%d): %d faults (%s, truncation %d), %d frames checked, %d wrong "
          "frames accepted, worst frames lost per fault %d (bound P+1 = %d; %s), %d over the "
          "bound, %d duplicates that cost a frame, %d frames lost outside a fault window" % (
              version, st.faults, kinds, st.truncs, st.checked, st.wrong, st.worst, period + 1, wk,
              st.over, st.dup_lost, st.unexplained))
    bad = st.wrong or st.over or st.dup_lost or st.unexplained or st.worst > period + 1
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
