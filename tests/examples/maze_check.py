#!/usr/bin/env python3
"""maze_check.py [--frames F] [TARGET...] - the maze walk (examples/maze,
the ray caster) against a fixed key script (tests/examples/maze.keys).

Host (build/examples/maze --keys): the stream decodes to F good frames;
every frame was steered by the script line before it (the log's key
column); the camera turned and walked as those keys say (maze.h's
rules), never nearer than MAZE_RADIUS to a wall cell, and the end wall
stopped it; the same run without keys streams other frames; live over a
pty (--pty), INPUT packets written by a reader steer it.
Targets (default avr328 avr1284 6502 z80): the firmware
build/x/T/maze/maze-F.* (examples/maze/fw_maze.c, the script compiled in
and fed through maze_rx after each frame) runs in its simulator and its
stream must equal the host's byte for byte.  A target the program does
not fit is reported as skipped with the reason; the ATmega328P and the
ATmega1284P must run.  The textured maze (maze --textured; firmware
build/x/T/tmaze/tmaze-F.*, -DMAZE_TEXTURED): the same walk (the same
log), other frames, decoding, and every target identical to the host.
Ends with "N passed, N failed".
"""
import argparse
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import walkcheck as W  # noqa: E402  (check, script, stats, host_run, pty, targets)
from walkcheck import KEY, ROOT, check, identity  # noqa: E402

HOST = os.path.join(ROOT, "build", "examples", "maze")
KEYS = os.path.join(ROOT, "tests", "examples", "maze.keys")
EXT = identity.EXT
TURN, STEP, RADIUS = 4, 8, 12    # examples/maze/maze.h
TOOL = os.path.join(ROOT, "build", "r8raycols")


def host_run(frames, keys, log=None, textured=False):
    return W.host_run(HOST, frames, keys, log, ["--textured"] if textured else [])


def grid():
    """The maze's cells (build/r8raycols prints them)."""
    r = subprocess.run([TOOL], input="", stdout=subprocess.PIPE, text=True, check=True)
    lines = r.stdout.splitlines()
    _, w, h, shift = lines[0].split()
    return [[int(v) for v in ln.split()] for ln in lines[1:1 + int(h)]], int(shift)


def steering(rows, masks):
    """The camera between frames as the keys say; returns the problems."""
    cells, shift = grid()
    bad = []

    def clear(x, z):
        for dx in (-RADIUS, RADIUS):
            for dz in (-RADIUS, RADIUS):
                if cells[(z + dz) >> shift][(x + dx) >> shift]:
                    return False
        return True

    for r in rows:
        if not clear(r["x"], r["z"]):
            bad.append("frame %d: the camera (%d, %d) is within %d of a wall" % (r["n"], r["x"], r["z"], RADIUS))
    for prev, cur in zip(rows, rows[1:]):
        k = cur["keys"]
        dyaw = (TURN if k & KEY["RIGHT"] else 0) - (TURN if k & KEY["LEFT"] else 0)
        if (cur["yaw"] - prev["yaw"]) % 256 != dyaw % 256:
            bad.append("frame %d: yaw %d -> %d with keys %04x" % (cur["n"], prev["yaw"], cur["yaw"], k))
        fwd = bool(k & (KEY["UP"] | KEY["A"]))
        back = bool(k & (KEY["DOWN"] | KEY["B"]))
        d = abs(cur["x"] - prev["x"]) + abs(cur["z"] - prev["z"])
        if fwd == back and d:
            bad.append("frame %d: the camera moved with keys %04x" % (cur["n"], k))
        if d > 2 * STEP:
            bad.append("frame %d: a step of %d units" % (cur["n"], d))
        if fwd != back and d == 0:
            # a blocked step: only against a wall (one more step would come within RADIUS)
            a = 2 * math.pi * cur["yaw"] / 256.0
            sgn = 1 if fwd else -1
            nx = prev["x"] + int(round(sgn * STEP * math.sin(a)))
            nz = prev["z"] + int(round(sgn * STEP * math.cos(a)))
            if (nx != prev["x"] and clear(nx, prev["z"])) or (nz != prev["z"] and clear(prev["x"], nz)):
                bad.append("frame %d: keys %04x did not move the camera in the open" % (cur["n"], k))
    return bad


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--frames", type=int, default=24)
    ap.add_argument("targets", nargs="*", default=["avr328", "avr1284", "6502", "z80"])
    a = ap.parse_args()
    os.chdir(ROOT)
    fw = {t: os.path.join("build", "x", t, "maze", "maze-%d.%s" % (a.frames, EXT[t])) for t in a.targets}
    tfw = {t: os.path.join("build", "x", t, "tmaze", "tmaze-%d.%s" % (a.frames, EXT[t])) for t in a.targets}
    if identity.make(["build/emu/avrsim", "build/examples/maze", "build/r8raycols"] + sorted(fw.values()) +
                     sorted(tfw.values())):
        print("maze_check: some builds failed (make output above)")
    # ---- the host build
    ref, rows, masks = W.host_keyed(HOST, "maze", KEYS, a.frames, ["n", "keys", "x", "z", "yaw"])
    if ref is None:
        return W.summary()
    bad = steering(rows, masks)
    check(not bad and len(rows) == a.frames,
          "host: the camera follows the keys over %d frames (turn %d, step %d, %d from walls)%s"
          % (len(rows), TURN, STEP, RADIUS, ": " + "; ".join(bad[:4]) if bad else ""))
    blocked = [r for p, r in zip(rows, rows[1:]) if r["keys"] == 1 and (r["x"], r["z"]) == (p["x"], p["z"])]
    check(len(blocked) >= 2, "host: the end wall stops the walk (%d forward steps blocked)" % len(blocked))
    rc0, still, _ = host_run(a.frames, None)
    check(rc0 == 0 and still != ref and W.stats(still).get("frames") == a.frames,
          "host: without keys the camera stays put and the stream differs (%d vs %d bytes)"
          % (len(still), len(ref)))
    W.pty_check(HOST, "maze", KEY["RIGHT"], "RIGHT")   # turn right
    # ---- the textured maze: the same walk, textured frames
    with tempfile.TemporaryDirectory() as td:
        tlog = os.path.join(td, "log")
        rct, tref, err = host_run(a.frames, KEYS, tlog, textured=True)
        same_walk = os.path.exists(tlog) and [ln.split() for ln in open(tlog)] == \
            [[str(r["n"]), "%04x" % r["keys"], str(r["x"]), str(r["z"]), str(r["yaw"])] for r in rows]
    st = W.stats(tref)
    check(rct == 0 and same_walk and tref != ref and st.get("frames") == a.frames and
          not st.get("bad_packets"), "host: maze --textured: the same walk, other frames "
          "(%d vs %d bytes), %s frames decode %s" % (len(tref), len(ref), st.get("frames"), err))
    # ---- every target against the host
    ran = set()
    jobs = [(t, fw[t], "maze", ref) for t in a.targets] + [(t, tfw[t], "tmaze", tref) for t in a.targets]
    for t, fwp, kind, ref in jobs:
        if W.target_check(t, fwp, "%s %s" % (t, kind), ref, a.frames, "maze_ram()"):
            ran.add((t, kind))
    for t in ("avr328", "avr1284"):
        if t in a.targets:
            for kind in ("maze", "tmaze"):
                check((t, kind) in ran, "mandatory: the %s runs the %s, identical" % (identity.MCU[t], kind))
    return W.summary()


if __name__ == "__main__":
    sys.exit(main())
