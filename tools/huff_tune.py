#!/usr/bin/env python3
"""huff_tune.py - tune the static canonical Huffman table (docs/protocol.md
section 3.4) on typical band data and write src/huff_tab.h and
host/rast8/hufftab.py.

    python3 tools/huff_tune.py --emu build/rast8-emu [--frames 32] [--check]

The sample: every built-in scene rendered by rast8-emu (--dump) at the
default 128x64, in PAGE1 (weight 4: the default format) and in ROW1 and
IDX8 (weight 1 each).  Every byte value gets a count of at least 1, so
every byte has a code; code lengths are limited to HUFF_MAXLEN bits
(package-merge).  --check: regenerate in memory and fail if the files
differ (the table is only rewritten on purpose).
"""
import argparse
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "host"))
from rast8.protocol import read_dump  # noqa: E402

SCENES = ["cube", "torus", "teapot", "terrain", "wall", "cross", "separate"]
FORMATS = [("page1", 4), ("row1", 1), ("idx8", 1)]
MAXLEN = 12


def sample(emu, frames):
    counts = [0] * 256
    with tempfile.TemporaryDirectory() as td:
        for scene in SCENES:
            for fmt, weight in FORMATS:
                dump = os.path.join(td, "d.r8fb")
                subprocess.run([emu, "-q", "--scene", scene, "--format", fmt, "--frames",
                                str(frames), "--out", os.devnull, "--dump", dump], check=True)
                for f in read_dump(dump):
                    for b in f.pixels:
                        counts[b] += weight
    return counts


def package_merge(counts, maxlen):
    """Optimal code lengths (at most maxlen bits) for counts (all > 0)."""
    items = sorted((c, (s,)) for s, c in enumerate(counts))
    cur = list(items)
    for _ in range(maxlen - 1):
        pk = [(cur[i][0] + cur[i + 1][0], cur[i][1] + cur[i + 1][1])
              for i in range(0, len(cur) - 1, 2)]
        cur = sorted(items + pk, key=lambda t: t[0])
    lens = [0] * len(counts)
    for _, syms in cur[:2 * len(counts) - 2]:
        for s in syms:
            lens[s] += 1
    return lens


def canonical(lens):
    """Canonical codes: by length, then by byte value (docs/protocol.md 3.4)."""
    order = sorted(range(256), key=lambda s: (lens[s], s))
    cnt = [0] * (MAXLEN + 1)
    for l in lens:
        cnt[l] += 1
    codes = [0] * 256
    code = prev = 0
    for s in order:
        code <<= lens[s] - prev
        prev = lens[s]
        codes[s] = code
        code += 1
    return codes, order, cnt


def render(lens, counts):
    total = sum(counts)
    bits = sum(c * l for c, l in zip(counts, lens))
    head = ("/* huff_tab.h - the static canonical Huffman code of docs/protocol.md\n"
            " * section 3.4: code length of each byte value, 1..%d bits.  Written by\n"
            " * tools/huff_tune.py (sample: the built-in scenes, PAGE1 x4, ROW1, IDX8;\n"
            " * %.3f bits per byte on it).  Do not edit: regenerate. */\n" % (MAXLEN, bits / total))
    codes, order, cnt = canonical(lens)
    def table(name, ctype, vals, fmt):
        rows = ["    " + ", ".join(fmt % v for v in vals[i:i + 16]) for i in range(0, len(vals), 16)]
        return "static const %s %s[%d] R8_FLASH = {\n%s\n};\n" % (ctype, name, len(vals), ",\n".join(rows))
    c = (head + "#define HUFF_MAXLEN %d\n" % MAXLEN
         + "/* bits of each byte value's code */\n" + table("huff_len", "r8_u8", lens, "%d")
         + "/* each byte value's code (its low huff_len bits) */\n" + table("huff_code", "r8_u16", codes, "0x%03X")
         + "/* the byte values in code order (by length, then value) */\n" + table("huff_sym", "r8_u8", order, "0x%02X")
         + "/* codes of each length 0..HUFF_MAXLEN */\n" + table("huff_cnt", "r8_u16", cnt, "%d"))
    py = ('"""The static canonical Huffman code lengths (docs/protocol.md section 3.4),\n'
          'written by tools/huff_tune.py with src/huff_tab.h: do not edit."""\n'
          "HUFF_LEN = (\n" + "".join("    %s,\n" % ", ".join("%d" % l for l in lens[i:i + 16])
                                     for i in range(0, 256, 16)) + ")\n")
    return c, py


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--emu", default="build/rast8-emu")
    ap.add_argument("--frames", type=int, default=32)
    ap.add_argument("--check", action="store_true")
    a = ap.parse_args()
    if not os.access(a.emu, os.X_OK):
        print("huff_tune: %s is not an executable (make build/rast8-emu)" % a.emu, file=sys.stderr)
        return 2
    counts = [c + 1 for c in sample(a.emu, a.frames)]
    lens = package_merge(counts, MAXLEN)
    assert sum(2 ** -l for l in lens) == 1.0 and max(lens) <= MAXLEN
    c, py = render(lens, counts)
    paths = [(os.path.join(HERE, "..", "src", "huff_tab.h"), c),
             (os.path.join(HERE, "..", "host", "rast8", "hufftab.py"), py)]
    if a.check:
        bad = [p for p, t in paths if not os.path.exists(p) or open(p).read() != t]
        for p in bad:
            print("huff_tune: %s is not what the sample gives" % p, file=sys.stderr)
        return 1 if bad else 0
    for p, t in paths:
        with open(p, "w") as f:
            f.write(t)
    print("huff_tune: %d bytes sampled, lengths %d..%d, %.3f bits/byte" % (
        sum(counts), min(lens), max(lens), sum(c * l for c, l in zip(counts, lens)) / sum(counts)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
