#!/usr/bin/env python3
"""codec_bench.py - the band codecs' cost on each CPU (issue 13): encode and
decode cycles per byte of RLE, LZ77, Huffman, LZW and the per-band
choice ("best"), and the payload bytes each gives, for one rendered
frame (the cube, PAGE1 128x64, 8 bands of 128 bytes: bench/fw_codecs.c)
on the ATmega1284P (emu/avrsim, exact), the 6502 (emu/prof65, sim65's
cycle counts) and the Z80 (ucsim via emu/sz80run.py, T-states).

    python3 bench/codec_bench.py [--json FILE]      (make bench-codecs)

Checks that every CPU's payloads equal the Python codecs' (CRC-16 of
the codec ids and payloads) and decode back, and that the frame sent
through src/wire.c with the per-band choice ("stream (best)": packets,
COBS, delimiters; its payload column is the stream's bytes) is the
Python encoder's stream byte for byte (CRC-16 and length); exits 1 if
not.  Also part
of `make bench` (bench/bench.py).  "Wins" compares what the choice
costs with what it saves: the extra encode cycles over RLE per payload
byte saved, against the cycles one byte takes on the wire at 115200
baud 8N1 (AVR 16 MHz, 6502 0.985 MHz, Z80 3.5 MHz); the choice pays only
on a link slower than the break-even baud rate.
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
sys.path.insert(0, os.path.join(ROOT, "host"))
from rast8 import codec as C  # noqa: E402
from rast8.protocol import Encoder  # noqa: E402

PIECES = ["rle", "lz77", "huff", "lzw", "best"]
TARGETS = [("avr1284", "build/x/avr1284/codecs.elf", 16000000),
           ("6502", "build/x/6502/codecs.prg", 985248),
           ("z80", "build/x/z80/codecs.ihx", 3500000)]
FRAME = os.path.join(ROOT, "tests", "golden", "cube_f16_page1.raw")


def expected():
    """(payload bytes, CRC) per piece from the Python codecs."""
    d = open(FRAME, "rb").read()
    res = {}
    for name in PIECES:
        crc, tot = 0xFFFF, 0
        for k in range(8):
            b = d[k * 128:(k + 1) * 128]
            if name == "best":
                c, e = C.best_encode(b)
            else:
                c, e = C.CODEC_NAMES[name], C.encode(C.CODEC_NAMES[name], b)
                if len(e) > 127:
                    c, e = C.RAW, b
            crc = C.crc16(bytes([c]) + e, crc)
            tot += len(e)
        res[name] = (tot, crc)
    s = Encoder(0, 128, 64, 8, C.BEST, full_period=0).frame(0, d)
    res["stream"] = (len(s), C.crc16(s))
    return res


def run_target(t, path):
    with tempfile.TemporaryDirectory() as td:
        out, info = os.path.join(td, "o.txt"), os.path.join(td, "i.txt")
        if t == "avr1284":
            cmd = [os.path.join(ROOT, "build", "emu", "avrsim"), "-m", info, "-o", out,
                   "atmega1284p", path]
        elif t == "6502":
            cmd = [os.path.join(ROOT, "build", "emu", "prof65"), "-m", info, "-o", out, path]
        else:
            cmd = [sys.executable, os.path.join(ROOT, "emu", "sz80run.py"), "-m", info, "-o", out, path]
        subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=600)
        text = open(info).read() if os.path.exists(info) else ""
        lines = open(out).read().splitlines() if os.path.exists(out) else []
    delta = {int(m.group(1)): int(m.group(2))
             for m in re.finditer(r"MARK (\d+) \S+ delta=(\d+)", text)}
    return delta, lines


def measure():
    exp = expected()
    rows, bad = [], []
    for t, path, hz in TARGETS:
        p = os.path.join(ROOT, path)
        if not os.path.exists(p) or open(p, "rb").read(5) == b"SKIP:":
            bad.append("%s: %s not built" % (t, path))
            continue
        delta, lines = run_target(t, p)
        for j, name in enumerate(PIECES):
            f = dict(kv.split("=") for kv in lines[j].split()[1:]) if j < len(lines) else {}
            got = (int(f.get("out", -1)), int(f.get("crc", -1)))
            if not f or lines[j].split()[0] != name or got != exp[name] or f.get("bad") != "0":
                bad.append("%s %s: %s, the Python codecs give out=%d crc=%d" % (
                    t, name, lines[j] if j < len(lines) else "no line", exp[name][0], exp[name][1]))
            enc, dec = delta.get(11 + 4 * j), delta.get(13 + 4 * j)
            rows.append({"target": t, "codec": name, "clock_hz": hz, "raw_bytes": 1024,
                         "payload_bytes": exp[name][0],
                         "encode_cycles": enc, "decode_cycles": dec,
                         "encode_cycles_per_byte": round(enc / 1024.0, 1) if enc else None,
                         "decode_cycles_per_byte": round(dec / 1024.0, 1) if dec else None})
        # the whole frame through src/wire.c with the choice: the stream
        # must be the Python encoder's, byte for byte (CRC and length)
        f = dict(kv.split("=") for kv in lines[5].split()[1:]) if len(lines) > 5 else {}
        got = (int(f.get("out", -1)), int(f.get("crc", -1)))
        if got != exp["stream"]:
            bad.append("%s: wire stream out=%d crc=%d, the Python encoder's out=%d crc=%d" % (
                (t,) + got + exp["stream"]))
        else:
            rows.append({"target": t, "codec": "stream (best)", "clock_hz": hz, "raw_bytes": 1024,
                         "payload_bytes": got[0], "same_as_python": True,
                         "encode_cycles": delta.get(41), "decode_cycles": None,
                         "encode_cycles_per_byte": round(delta[41] / 1024.0, 1) if delta.get(41) else None,
                         "decode_cycles_per_byte": None})
    # the choice's price: extra encode cycles over RLE per byte it saves
    for r in rows:
        if r["codec"] not in PIECES:
            continue
        rle = [x for x in rows if x["target"] == r["target"] and x["codec"] == "rle"][0]
        saved = rle["payload_bytes"] - r["payload_bytes"]
        wire = r["clock_hz"] * 10.0 / 115200
        if r["codec"] != "rle" and saved > 0 and r["encode_cycles"] and rle["encode_cycles"]:
            per = (r["encode_cycles"] - rle["encode_cycles"]) / float(saved)
            r["cycles_per_byte_saved"] = round(per)
            r["wire_cycles_per_byte_115200"] = round(wire)
            r["wins_at_115200"] = per < wire
            r["break_even_baud"] = int(r["clock_hz"] * 10.0 / per) if per > 0 else None
    return rows, bad


def table(rows):
    L = ["| CPU | codec | payload B (of 1024) | encode cycles/B | decode cycles/B | "
         "extra cycles per byte saved vs RLE | wire cycles/B at 115200 | pays below |",
         "|---|---|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        L.append("| %s | %s | %d | %s | %s | %s | %s | %s |" % (
            r["target"], r["codec"], r["payload_bytes"], r["encode_cycles_per_byte"],
            r["decode_cycles_per_byte"] or "-", r.get("cycles_per_byte_saved", "-"),
            r.get("wire_cycles_per_byte_115200", "-"),
            ("%d baud" % r["break_even_baud"]) if r.get("break_even_baud") else "-"))
    return L


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--json", default=os.path.join(ROOT, "build", "bench", "codecs.json"))
    ap.add_argument("--no-build", action="store_true", help="do not run make first")
    ap.add_argument("--test", action="store_true",
                    help="only the checks, one per CPU, ending with 'N passed, N failed'")
    a = ap.parse_args()
    if not a.no_build:
        # serialised with the other target builds (tests/targets/unit.sh)
        os.makedirs(os.path.join(ROOT, "build", "x"), exist_ok=True)
        env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL")}
        r = subprocess.run(["flock", os.path.join(ROOT, "build", "x", ".lock"), "make", "-s", "-j2",
                            "-C", ROOT, "build/emu/avrsim", "build/emu/prof65"]
                           + [t[1] for t in TARGETS], env=env)
        if r.returncode:
            print("codecs: the benchmark programs did not build", file=sys.stderr)
            return 1
    rows, bad = measure()
    if a.test:
        for b in bad:
            print("FAIL %s" % b)
        nbad = len({b.split()[0].rstrip(":") for b in bad})
        print("codecs: payloads and the wire stream with the per-band choice equal the Python "
              "codecs' on %s" % ", ".join(t[0] for t in TARGETS))
        print("%d passed, %d failed" % (len(TARGETS) - nbad, nbad))
        return 1 if bad else 0
    os.makedirs(os.path.dirname(a.json), exist_ok=True)
    with open(a.json, "w") as f:
        json.dump(rows, f, indent=1)
    print("\n".join(table(rows)))
    for b in bad:
        print("codecs: FAIL %s" % b, file=sys.stderr)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
