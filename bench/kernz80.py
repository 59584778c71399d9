#!/usr/bin/env python3
"""kernz80.py - what each Z80 assembly kernel buys: the cube / cull
firmware (build/x/z80/fw/fw-0-0-4.ihx: 128x64 PAGE1, bands of 8,
Lambert, 4 frames) rebuilt with Z80_ASM set to each variant, T-states per
frame (emu/z80sim, Zilog timing: the mean of frames 1-3; frame 0 is
listed too) and image size (code + tables, .ihx.size flash).

    python3 bench/kernz80.py [--json FILE] [VARIANT...]

A VARIANT is a Z80_ASM value ("mul16 mullong wire trap", "0", ...); the
default list is the build, each kernel left out in turn, and none.
Rebuilds build/x/z80 for every variant (a minute or two each) and once
more with the defaults at the end.  Prints a markdown table; every
variant's stream must equal the host's (build/emu/fw-host 0 0 4), else it
says so and exits 1.  Not part of `make test`: it measures.
"""
import argparse
import json
import os
import re
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
FW = "build/x/z80/fw/fw-0-0-4.ihx"
SIM = "build/emu/z80sim"
ALL = "mul16 mullong mulint wire trap fill xform project edge txband scanx tframe scanband band"   # Z80_KALL in mk/targets.mk
# the build, each kernel left out in turn, and none
DEFAULT = [ALL] + [" ".join(k for k in ALL.split() if k != x) for x in ALL.split()] + ["0"]


def build_and_measure(asm):
    env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MFLAGS", "MAKELEVEL")}
    cmd = ["flock", os.path.join(ROOT, "build", "x", ".lock"), "make", "-s", "-j2",
           FW, SIM, "build/emu/fw-host", "Z80_ASM=" + asm]
    try:
        os.unlink(os.path.join(ROOT, FW))
    except OSError:
        pass
    r = subprocess.run(cmd, cwd=ROOT, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    if r.returncode:
        return {"error": r.stdout.decode("latin-1")[-400:]}
    p = os.path.join(ROOT, FW)
    if open(p, "rb").read(5) == b"SKIP:":
        return {"error": open(p).read().strip()}
    s = subprocess.run([os.path.join(ROOT, SIM), "-q", "-o", "/dev/stdout", "-m", "/dev/stderr", p],
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=900)
    frames = [int(x) for x in re.findall(rb"FRAME \d+ cycles=(\d+)", s.stderr)]
    host = subprocess.run([os.path.join(ROOT, "build", "emu", "fw-host"), "0", "0", "4"],
                          stdout=subprocess.PIPE).stdout
    size = dict(kv.split("=") for kv in open(p + ".size").read().split())
    if len(frames) < 4:
        return {"error": "z80sim: %d frames" % len(frames)}
    return {"t_per_frame": sum(frames[1:]) // (len(frames) - 1), "frames": frames,
            "flash_bytes": int(size["flash"]), "ram_static_bytes": int(size["ram_static"]),
            "identical": s.stdout == host}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--json")
    ap.add_argument("variants", nargs="*", help="Z80_ASM values (default: %s)" % "; ".join(DEFAULT))
    a = ap.parse_args()
    res = []
    try:
        for v in a.variants or DEFAULT:
            sys.stderr.write("kernz80: Z80_ASM=%s\n" % v)
            r = build_and_measure(v)
            r["variant"] = v
            res.append(r)
    finally:
        sys.stderr.write("kernz80: rebuilding the default (Z80_ASM=1)\n")
        build_and_measure("1")   # leave the default build behind
    base = res[0].get("t_per_frame")
    print("| Z80 cube / cull, Z80_ASM= | T/frame (frames 1-3) | vs first | frame 0 | flash | RAM static | same |")
    print("|---|---:|---:|---:|---:|---:|---|")
    for r in res:
        if "error" in r:
            print("| %s | - | - | - | - | - | %s |" % (r["variant"], r["error"].strip().splitlines()[-1][:80]))
            continue
        d = r["t_per_frame"] - base if base else 0
        print("| %s | {:,} | {:+,} | {:,} | {:,} | {:,} | %s |".format(
            r["t_per_frame"], d, r["frames"][0], r["flash_bytes"], r["ram_static_bytes"]) %
              (r["variant"], "yes" if r["identical"] else "**NO**"))
    if a.json:
        with open(a.json, "w") as f:
            json.dump(res, f, indent=1)
    return 0 if all(r.get("identical") for r in res if "error" not in r) else 1


if __name__ == "__main__":
    sys.exit(main())
