#!/usr/bin/env python3
"""z80link.py OUT.ihx OBJ... [LIB...] - links a rast8 Z80 program with sdcc
for the flat 64 KB map of ports/z80/plat_z80.c: code from 0x0200, statics
right after the code, stack down from 0xFFFF.

sdcc puts _DATA at a fixed --data-loc, so this links once to learn where
the code ends, then again with --data-loc there.  An area _R8TAB (the
tables of ports/z80/wire_z80.s that must sit on a 256-byte boundary) is
placed at 0x0200 and the code after it.  It fails with
"does not fit: ..." when the code reaches the statics' space or when less
than 1 KB is left for the stack.  Prints "code=N data=N free=N".
"""
import re
import subprocess
import sys

STACK_MIN = 1024


def link(out, objs, data_loc, code_loc=0x200):
    # -b for _R8TAB only when there is one (sdld fails on an undefined area)
    tab = ["-Wl-b_R8TAB=0x0200"] if code_loc != 0x200 else []
    r = subprocess.run(["sdcc", "-mz80", "--code-loc", "0x%04x" % code_loc, "--data-loc", "0x%04x" % data_loc]
                       + tab + ["-o", out] + objs, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    sys.stdout.write(r.stdout.decode("latin-1"))
    if r.returncode:
        sys.exit(r.returncode)
    s, l = {}, {}
    for line in open(out[:-4] + ".map", errors="replace"):
        m = re.match(r"\s+([0-9A-Fa-f]{8})\s+([sl])__(\w+)\s*$", line)
        if m:
            (s if m.group(2) == "s" else l)[m.group(3)] = int(m.group(1), 16)
    code = ("HOME", "CODE", "INITIALIZER", "GSINIT", "GSFINAL")
    data = ("DATA", "INITIALIZED", "BSEG", "BSS", "HEAP")
    code_end = max(s.get(a, 0) + l.get(a, 0) for a in code)
    data_end = max(s.get(a, 0) + l.get(a, 0) for a in data)
    return code_end, data_end, l.get("R8TAB", 0)


def main():
    out, objs = sys.argv[1], sys.argv[2:]
    code_end, _, tab = link(out, objs, 0x8000)
    code_loc = 0x200
    if tab:  # the aligned tables first, the code after them
        code_loc = (0x200 + tab + 0xFF) & ~0xFF
        code_end, _, _ = link(out, objs, 0x8000, code_loc)
    if code_end >= 0x10000 - STACK_MIN:
        print("does not fit: code ends at 0x%X" % code_end)
        sys.exit(3)
    code_end2, data_end, _ = link(out, objs, code_end, code_loc)
    if code_end2 != code_end:
        print("z80link: code moved between links (0x%X -> 0x%X)" % (code_end, code_end2))
        sys.exit(1)
    free = 0x10000 - data_end
    print("code=%d data=%d free=%d" % (code_end - 0x200, data_end - code_end, free))
    if free < STACK_MIN:
        print("does not fit: statics end at 0x%X, %d bytes left for the stack (< %d)"
              % (data_end, free, STACK_MIN))
        sys.exit(3)


if __name__ == "__main__":
    main()
