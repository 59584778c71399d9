#!/usr/bin/env python3
"""fly_check.py [--frames F] [TARGET...] - the flythrough example against
a fixed key script (tests/examples/fly.keys).

Host (build/examples/flythrough --keys): the stream decodes to F good
frames; every frame was steered by the script line before it (the log's
key column); the camera moved as those keys say (turns, tilts and moves,
from fly.h's rules); the clipper had work and dropped nothing; the same
run without keys streams other frames; live over a pty (--pty), INPUT
packets written by a reader steer it.
Targets (default avr328 avr1284 6502 z80): the firmware
build/x/T/fly/fly-F.* (examples/flythrough/fw_fly.c, the script compiled
in and fed through fly_rx after each frame) runs in its simulator and
its stream must equal the host's byte for byte.  A target the program
does not fit is reported as skipped with the reason; the ATmega1284P
must run, and also with the keys over its UART (FLY_UART: the AVR
port's plat_getc, fed by emu/avrsim -i).  Ends with "N passed, N failed".
"""
import argparse
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import walkcheck as W  # noqa: E402  (check, script, stats, host_run, pty, targets)
from walkcheck import KEY, ROOT, check, identity  # noqa: E402

HOST = os.path.join(ROOT, "build", "examples", "flythrough")
KEYS = os.path.join(ROOT, "tests", "examples", "fly.keys")
EXT = identity.EXT
TURN, TILT, PITCH_MIN, PITCH_MAX = 4, 2, -48, 16    # examples/flythrough/fly.c, fly.h


def host_run(frames, keys, log=None):
    return W.host_run(HOST, frames, keys, log)


def steering(rows, masks):
    """The camera between frames as the keys say; returns the problems."""
    bad = []
    for prev, cur in zip(rows, rows[1:]):
        k = cur["keys"]
        dyaw = (TURN if k & KEY["RIGHT"] else 0) - (TURN if k & KEY["LEFT"] else 0)
        if (cur["yaw"] - prev["yaw"]) % 256 != dyaw % 256:
            bad.append("frame %d: yaw %d -> %d with keys %04x" % (cur["n"], prev["yaw"], cur["yaw"], k))
        p = prev["pitch"] + (TILT if k & KEY["UP"] else 0) - (TILT if k & KEY["DOWN"] else 0)
        p = max(PITCH_MIN, min(PITCH_MAX, p))
        if cur["pitch"] != p:
            bad.append("frame %d: pitch %d -> %d with keys %04x" % (cur["n"], prev["pitch"], cur["pitch"], k))
        moves = bool((k & KEY["A"]) != 0) != bool((k & KEY["B"]) != 0) or k & (KEY["X"] | KEY["Y"])
        moved = (cur["x"], cur["y"], cur["z"]) != (prev["x"], prev["y"], prev["z"])
        if moved and not moves:
            bad.append("frame %d: the camera moved with keys %04x" % (cur["n"], k))
        if k & KEY["A"] and not k & KEY["B"] and not moved:
            bad.append("frame %d: A (forward) did not move the camera" % cur["n"])
    return bad


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--frames", type=int, default=24)
    ap.add_argument("targets", nargs="*", default=["avr328", "avr1284", "6502", "z80"])
    a = ap.parse_args()
    os.chdir(ROOT)
    fw = {t: os.path.join("build", "x", t, "fly", "fly-%d.%s" % (a.frames, EXT[t])) for t in a.targets}
    extra = ["build/x/avr1284/fly/fly-uart-%d.elf" % a.frames] if "avr1284" in a.targets else []
    if identity.make(["build/emu/avrsim", "build/examples/flythrough"] + sorted(fw.values()) + extra):
        print("fly_check: some builds failed (make output above)")
    # ---- the host build
    ref, rows, masks = W.host_keyed(HOST, "flythrough", KEYS, a.frames, ["n", "keys", "x", "y", "z", "yaw", "pitch", "faces", "clipped", "dropped"])
    if ref is None:
        return W.summary()
    bad = steering(rows, masks)
    check(not bad and len(rows) == a.frames,
          "host: the camera follows the keys over %d frames (turn %d, tilt %d, moves)%s"
          % (len(rows), TURN, TILT, ": " + "; ".join(bad[:4]) if bad else ""))
    clipped = sum(r["clipped"] for r in rows)
    dropped = sum(r["dropped"] for r in rows)
    check(clipped > 0 and dropped == 0,
          "host: the dive sends faces through the clipper: %d clipped, %d dropped (budget 8 a frame)"
          % (clipped, dropped))
    rc0, still, _ = host_run(a.frames, None)
    check(rc0 == 0 and still != ref and W.stats(still).get("frames") == a.frames,
          "host: without keys the camera stays put and the stream differs (%d vs %d bytes)"
          % (len(still), len(ref)))
    W.pty_check(HOST, "flythrough", KEY["A"] | KEY["RIGHT"], "A+RIGHT")   # fly forward, turn right
    # ---- every target against the host
    ran = set()
    for t in a.targets:
        if W.target_check(t, fw[t], "%s flythrough" % t, ref, a.frames, "fly_ram()"):
            ran.add(t)
    if "avr1284" in a.targets:
        check("avr1284" in ran, "mandatory: the ATmega1284P runs the flythrough")
        # the same keys over the AVR port's UART receiver (plat_getc), fed
        # by the simulator as a display would send them
        uart = os.path.join(ROOT, "build", "x", "avr1284", "fly", "fly-uart-%d.elf" % a.frames)
        pk = os.path.join(ROOT, "build", "x", "fly", "fly_keys.bin")
        if check(os.path.exists(uart) and os.path.exists(pk) and not identity.is_skip(uart),
                 "avr1284 flythrough, keys over the UART: built"):
            with tempfile.TemporaryDirectory() as td:
                out = os.path.join(td, "o.bin")
                r = subprocess.run([os.path.join(ROOT, "build", "emu", "avrsim"), "-q", "-i", pk,
                                    "-o", out, "atmega1284p", uart], stderr=subprocess.PIPE, timeout=600)
                data = open(out, "rb").read() if os.path.exists(out) else b""
            check(r.returncode == 0 and data == ref,
                  "avr1284 flythrough, keys over the UART (avrsim -i %s, %d bytes): %d bytes %s the host's"
                  % (os.path.relpath(pk, ROOT), os.path.getsize(pk), len(data),
                     "identical to" if data == ref else "DIFFER from"))
    return W.summary()


if __name__ == "__main__":
    sys.exit(main())
