#!/usr/bin/env python3
"""prof65_lines.py - cycles per C source line of a 6502 program, from
emu/prof65's per-instruction histogram (-H) and ld65's debug file
(--dbgfile, written next to every 6502 program by ports/xbuild.sh).

    prof65_lines.py [-n N] [--frames F] HIST PROGRAM.dbg

Each executed instruction is charged to the C line (cc65 -g) whose code
span holds it, or, in hand-written assembly, to its assembly line.
Prints the N (default 40) costliest lines: cycles (divided by F, the
profiled frames, when given), share, executions of their first
instruction, file:line and the source text.
"""
import argparse
import os
import re
import signal
import sys


def parse_dbg(path):
    segs, spans, files, lines = {}, {}, {}, []
    for l in open(path):
        kind, _, rest = l.partition("\t")
        if kind not in ("seg", "span", "file", "line"):
            continue
        f = dict(kv.split("=", 1) for kv in re.findall(r'(\w+=(?:"[^"]*"|[^,]*))', rest.strip()))
        i = int(f["id"])
        if kind == "seg":
            segs[i] = int(f["start"], 16)
        elif kind == "span":
            spans[i] = (int(f["seg"]), int(f["start"]), int(f["size"]))
        elif kind == "file":
            files[i] = f["name"].strip('"')
        elif "span" in f:
            lines.append((int(f["file"]), int(f["line"]), int(f.get("type", "0")),
                          [int(s) for s in f["span"].split("+")]))
    return segs, spans, files, lines


def main():
    signal.signal(signal.SIGPIPE, signal.SIG_DFL)   # | head: no traceback
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("-n", type=int, default=40)
    ap.add_argument("--frames", type=int, default=1)
    ap.add_argument("hist")
    ap.add_argument("dbg")
    a = ap.parse_args()
    try:
        segs, spans, files, lines = parse_dbg(a.dbg)
        hist = [tuple(int(x, 16) if k == 0 else int(x) for k, x in enumerate(l.split()))
                for l in open(a.hist)]
    except (OSError, ValueError, KeyError) as e:
        sys.stderr.write("prof65_lines: %s\n" % e)
        return 2
    # address ranges -> (file, line), C lines (type 1) before assembly lines
    ranges = []
    for fi, ln, ty, sp in lines:
        for s in sp:
            seg, start, size = spans[s]
            lo = segs[seg] + start
            ranges.append((0 if ty == 1 else 1, size, lo, lo + size, fi, ln))
    ranges.sort()
    owner = {}
    for _, _, lo, hi, fi, ln in ranges:
        for x in range(lo, hi):
            owner.setdefault(x, (fi, ln))
    cyc, execs = {}, {}
    total = 0
    for addr, c, n in hist:
        key = owner.get(addr, (-1, addr))
        cyc[key] = cyc.get(key, 0) + c
        execs.setdefault(key, n)
        total += c
    src = {}
    def text(fi, ln):
        if fi < 0:
            return "(no line: $%04X)" % ln
        path = files.get(fi, "?")
        if path not in src:
            try:
                src[path] = open(path, errors="replace").read().splitlines()
            except OSError:
                src[path] = []
        t = src[path][ln - 1].strip() if 0 < ln <= len(src[path]) else ""
        return "%s:%d  %s" % (os.path.relpath(path) if os.path.exists(path) else path, ln, t[:70])
    print("# cycles per source line%s, total %d" %
          (" per frame (%d frames)" % a.frames if a.frames > 1 else "", total // a.frames))
    for key, c in sorted(cyc.items(), key=lambda kv: -kv[1])[:a.n]:
        print("%9d %5.1f%% %7d  %s" % (c // a.frames, 100.0 * c / total if total else 0,
                                       execs[key], text(*key)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
