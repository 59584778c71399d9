#!/usr/bin/env python3
"""prof65_check.py - emu/prof65 (the 6502 profiler's simulator) against
sim65 on the same programs: the same cycle total, exit code and stream,
byte for byte; its FRAME cycles add up between the markers; a profile
and a coverage file come out with the time inside the frames.

    prof65_check.py [PROGRAM.prg ...]

Default programs: the cube firmware fw-0-0-2 and two unit tests.
Prints one line per check and "N passed, N failed".
"""
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
XB = os.path.join(ROOT, "build", "x", "6502")
PROF = os.path.join(ROOT, "build", "emu", "prof65")
DEFAULT = [os.path.join(XB, "fw", "fw-0-0-2.prg"),
           os.path.join(XB, "tests", "test_wirek.prg"),
           os.path.join(XB, "tests", "test_fixed.prg")]


def main():
    progs = sys.argv[1:] or DEFAULT
    env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL")}
    r = subprocess.run(["flock", os.path.join(ROOT, "build", "x", ".lock"), "make", "-s",
                        "--no-print-directory", "build/emu/prof65"] +
                       [os.path.relpath(p, ROOT) for p in progs],
                       cwd=ROOT, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    if r.returncode:
        print(r.stdout.decode("latin-1"))
    ok = bad = 0

    def check(cond, what):
        nonlocal ok, bad
        print(("ok   " if cond else "FAIL ") + what)
        if cond:
            ok += 1
        else:
            bad += 1

    with tempfile.TemporaryDirectory() as td:
        for p in progs:
            name = os.path.basename(p)
            if not os.path.exists(p) or open(p, "rb").read(5) == b"SKIP:":
                check(False, "%s: not built" % name)
                continue
            s = subprocess.run(["sim65", "-c", p], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, timeout=600)
            m = re.search(rb"(\d+) cycles\n$", s.stdout)
            s_cyc = int(m.group(1)) if m else None
            s_out = s.stdout[:m.start()] if m else s.stdout
            out, marks = os.path.join(td, "o.bin"), os.path.join(td, "m.txt")
            prof, cov = os.path.join(td, "p.txt"), os.path.join(td, "c.txt")
            q = subprocess.run([PROF, "-o", out, "-m", marks, "-P", prof, "-C", cov, p],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=600)
            info = open(marks).read()
            m = re.search(r"END state=(\w+) code=(-?\d+) cycles=(\d+)", info)
            check(m is not None and m.group(1) == "done", "%s: prof65 runs to the end" % name)
            if not m:
                continue
            check(int(m.group(3)) == s_cyc,
                  "%s: cycles prof65 %s = sim65 %s" % (name, m.group(3), s_cyc))
            check(q.returncode == s.returncode,
                  "%s: exit code prof65 %d = sim65 %d" % (name, q.returncode, s.returncode))
            check(open(out, "rb").read() == s_out,
                  "%s: stream identical (%d bytes)" % (name, len(s_out)))
            frames = [int(x) for x in re.findall(r"FRAME \d+ cycles=(\d+)", info)]
            marks2 = [(int(i), int(c)) for i, c in re.findall(r"MARK (\d+) cycle=(\d+)", info)]
            if frames:
                pairs = [c3 - c2 for (i2, c2), (i3, c3) in zip(marks2, marks2[1:]) if i2 == 2 and i3 == 3]
                check(pairs == frames, "%s: %d FRAME lines = marker 2..3 spans" % (name, len(frames)))
                head = open(prof).readline()
                t = re.search(r"total (\d+)", head)
                check(t is not None and int(t.group(1)) == sum(frames),
                      "%s: profile total %s = the frames' cycles %d" % (name, t and t.group(1), sum(frames)))
                rows = [l.split() for l in open(prof) if not l.startswith("#")]
                self_sum = sum(int(r[0]) for r in rows)
                check(self_sum == sum(frames), "%s: self cycles add up (%d)" % (name, self_sum))
            tot = open(cov).read().splitlines()[-1].split()
            check(len(tot) > 2 and int(tot[1]) > 0 and int(tot[1]) <= int(tot[0]),
                  "%s: coverage %s of %s code bytes executed" % (name, tot[1], tot[0]))
    print("%d passed, %d failed" % (ok, bad))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
