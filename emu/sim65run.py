#!/usr/bin/env python3
"""sim65run.py - runs a rast8 6502 program (cc65 sim6502) in sim65.

    sim65run.py [-o OUT] [-m INFO] [-x CYCLES] [-t SEC] FILE.prg

Program stdout (write(1, ...)) is the UART stream: bytes go to OUT
(default stdout), binary-safe, with sim65 -c's "N cycles" line split off.
INFO (default stderr) gets
    END state=done|limit|timeout code=N cycles=C
    RAM stack_peak=N c=N hw=N        (plat_sim65.c's stderr report)
sim65 2.19 has no readable cycle counter, so per-frame cycles come from
differential runs (bench/bench.py).  Exit status: the program's exit
code, 124 on the cycle limit or timeout.
"""
import argparse
import re
import subprocess
import sys


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("-o", "--out")
    ap.add_argument("-m", "--marks")
    ap.add_argument("-x", "--limit", type=int, default=20000000000)
    ap.add_argument("-t", "--timeout", type=float, default=120.0)
    ap.add_argument("prg")
    a = ap.parse_args()
    state = "done"
    try:
        r = subprocess.run(["sim65", "-c", "-x", str(a.limit), a.prg],
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                           timeout=a.timeout)
        out, err, rc = r.stdout, r.stderr.decode("latin-1"), r.returncode
    except subprocess.TimeoutExpired as e:
        out, err, rc = e.stdout or b"", (e.stderr or b"").decode("latin-1"), 124
        state = "timeout"
    cycles = None
    m = re.search(rb"(\d+) cycles\n$", out)
    if m:
        cycles = int(m.group(1))
        out = out[:m.start()]
    if a.out:
        with open(a.out, "wb") as f:
            f.write(out)
    else:
        sys.stdout.buffer.write(out)
        sys.stdout.flush()
    if state == "done" and "maximum number of cycles" in err.lower():
        state = "limit"
        rc = 124
    info = open(a.marks, "w") if a.marks else sys.stderr
    for line in err.splitlines():
        if not line.startswith("STACK"):
            info.write(line + "\n")
    info.write("END state=%s code=%d cycles=%s\n" % (state, rc, cycles))
    m = re.search(r"STACK c=(\d+) hw=(\d+)", err)
    if m:
        c, hw = int(m.group(1)), int(m.group(2))
        info.write("RAM stack_peak=%d c=%d hw=%d\n" % (c + hw, c, hw))
    info.flush()
    sys.exit(rc)


if __name__ == "__main__":
    main()
