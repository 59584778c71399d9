#!/usr/bin/env python3
"""sz80run.py - runs a rast8 Z80 firmware (Intel hex from sdcc) in ucsim sz80.

    sz80run.py [-o OUT] [-m MARKS] [-t SEC] [-n RUNS] FILE.ihx

The simif byte at 0x01FF streams the UART: bytes go to OUT (default
stdout), binary-safe.  A write breakpoint on the marker byte 0x01FE stops
the simulator at every plat_mark(); the tick count of each stop gives

    MARK id ticks=T delta=D          (to MARKS, default stderr)
    FRAME n cycles=D                 (for every marker 3 after a marker 2)
    END state=done|timeout|nostop code=N ticks=T
    RAM stack_peak=N                 (plat_z80.c paints and reports it)

ucsim's Z80 timing is approximate ((HL) read-modify-write ops are
under-counted), so the figures are indicative.  sz80 always exits 0; this
wrapper exits with the firmware's plat_exit code, 124 on timeout, 125 if
the program never stopped itself.  Each breakpoint stop costs ~0.15 s of
sz80's console polling; -G runs without them (no per-frame figures).
(sz80 -G itself is not used: it quits as soon as its stdin ends.)
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile
import select
import time


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("-o", "--out")
    ap.add_argument("-m", "--marks")
    ap.add_argument("-t", "--timeout", type=float, default=120.0)
    ap.add_argument("-n", "--runs", type=int, default=80)
    ap.add_argument("-G", "--go", action="store_true",
                    help="no marker breakpoints: one run to the end (exit code and"
                         " stack are still read)")
    ap.add_argument("ihx")
    a = ap.parse_args()
    if not os.path.exists(a.ihx):
        sys.exit("sz80run: no such file: %s" % a.ihx)
    with tempfile.TemporaryDirectory() as td:
        out = a.out or os.path.join(td, "uart.bin")
        if os.path.exists(out):
            os.unlink(out)
        # Interactive: one command at a time, reading its whole answer
        # before the next (piping a script makes sz80 echo the input into
        # the middle of its output lines).
        p = subprocess.Popen(
            ["sz80", "-q", "-b", "-I", "if=rom[0x1ff],out=%s" % out, "-c", "-", a.ihx],
            stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        deadline = time.time() + a.timeout
        lines = []
        buf = [b""]
        fd = p.stdout.fileno()

        def readline():
            while b"\n" not in buf[0]:
                left = deadline - time.time()
                if left <= 0 or not select.select([fd], [], [], left)[0]:
                    return None
                chunk = os.read(fd, 65536)
                if not chunk:
                    return None
                buf[0] += chunk
            line, buf[0] = buf[0].split(b"\n", 1)
            return line

        def ask(cmd, done):
            p.stdin.write((cmd + "\n").encode())
            p.stdin.flush()
            while True:
                line = readline()
                if line is None:
                    return False
                line = line.decode("latin-1")
                lines.append(line)
                if done(line):
                    return True

        state = "done"
        ok = True
        if not a.go:
            ok = ask("break rom w 0x1fe", lambda l: l.startswith("break"))
        for _ in range(1 if a.go else a.runs):
            if not ok:
                break
            ok = ask("run", lambda l: l.startswith("Host usage"))
            ok = ok and ask("dump rom 0x1fc 0x1fe", lambda l: re.match(r"0x0*1fc\s", l) is not None)
            if any("Program stopped itself" in l for l in lines[-12:]):
                break
        if not ok:
            state = "timeout"
        try:
            p.stdin.write(b"quit\n")
            p.stdin.close()
        except OSError:
            pass
        try:
            p.wait(timeout=5)
        except subprocess.TimeoutExpired:
            p.kill()
        text = "\n".join(lines)
        if not a.out:
            if os.path.exists(out):
                with open(out, "rb") as f:
                    sys.stdout.buffer.write(f.read())
            sys.stdout.flush()
        mf = open(a.marks, "w") if a.marks else sys.stderr
        total = 0
        code = None
        stack = None
        in_frame = False
        frame = 0
        pending = None
        stopped = False
        for line in text.splitlines():
            m = re.match(r"Simulated (\d+) ticks", line)
            if m:
                pending = int(m.group(1))
                continue
            m = re.match(r"0x0*1fc\s+([0-9a-f]{2}) ([0-9a-f]{2}) ([0-9a-f]{2})", line)
            if m and pending is not None:
                lo, hi, mk = (int(m.group(i), 16) for i in (1, 2, 3))
                total += pending
                delta, pending = pending, None
                if code is not None:
                    continue
                if mk >= 0xE0 and mk != 0xFF:  # exit marker (plat_exit)
                    code = mk & 0x0F
                    stack = lo | hi << 8
                    continue
                if stopped:
                    continue
                mf.write("MARK %d ticks=%d delta=%d\n" % (mk, total, delta))
                if mk == 2:
                    in_frame = True
                elif mk == 3 and in_frame:
                    mf.write("FRAME %d cycles=%d\n" % (frame, delta))
                    frame += 1
                    in_frame = False
            if "Program stopped itself" in line:
                stopped = True
        if state == "done" and code is None:
            state = "nostop"
        mf.write("END state=%s code=%s ticks=%d\n" % (state, code, total))
        if stack is not None:
            mf.write("RAM stack_peak=%d\n" % stack)
        mf.flush()
    if state == "timeout":
        sys.exit(124)
    if code is None:
        sys.exit(125)
    sys.exit(code)


if __name__ == "__main__":
    main()
