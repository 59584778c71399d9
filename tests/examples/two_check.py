#!/usr/bin/env python3
"""two_check.py - the two-objects example: the analyser's choice for two
separate convex objects, and what it rests on.

  * camera fixed: the analyser picks painter's and says why (convex
    objects apart in depth); its frames equal the 16-bit z-buffer's byte
    for byte, while drawing without a sort (cull only) does not: the
    objects overlap on screen, so the order matters;
  * R8_BOUND_BOX where the camera moves 40 units every way: still
    painter's, and at the box's 8 corners and centre (depth range from
    the analysis) painter's frames equal the z-buffer's;
  * a box 3000 units deep along the view axis: not painter's (the depth
    range is so deep that one of painter's 64 buckets is wider than the
    gap between the objects: their keys could tie or cross); the same
    for R8_BOUND_ANY (the camera may turn: the order can flip).
Ends with "N passed, N failed".
"""
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
PROG = os.path.join(ROOT, "build", "examples", "two-objects")
FRAMES = 16
NEAR = "-40,-30,-40,40,30,40"
DEEP = "-40,-30,-3000,40,30,0"

passed = failed = 0


def check(ok, msg):
    global passed, failed
    print("%s %s" % ("PASS" if ok else "FAIL", msg))
    if ok:
        passed += 1
    else:
        failed += 1
    return ok


def run(args, tmp):
    raw = os.path.join(tmp, "f.raw")
    if os.path.exists(raw):
        os.unlink(raw)
    r = subprocess.run([PROG, "--frames", str(FRAMES), "--raw", raw] + args,
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=60)
    out = r.stdout.decode()
    m = re.search(r"method (\w+) \((.*)\)", out)
    n = re.search(r"bucket: (\d+) units\), gap between the objects (-?\d+)", out)
    return {"rc": r.returncode, "out": out.strip(), "err": r.stderr.decode().strip(),
            "method": m.group(1) if m else None, "why": m.group(2) if m else "",
            "bucket": int(n.group(1)) if n else None, "gap": int(n.group(2)) if n else None,
            "frames": open(raw, "rb").read() if os.path.exists(raw) else b""}


def lit(data):
    return sum(bin(b).count("1") for b in data)


def main():
    if not os.access(PROG, os.X_OK):
        print("two_check: %s missing (make %s)" % (PROG, os.path.relpath(PROG, ROOT)))
        print("0 passed, 1 failed")
        return 1
    with tempfile.TemporaryDirectory() as tmp:
        a = run([], tmp)
        print("  " + a["out"].replace("\n", "\n  "))
        check(a["rc"] == 0 and a["method"] == "painter" and "painter's is exact" in a["why"],
              "fixed camera: the analyser picks painter's and says why: %s (%s)"
              % (a["method"], a["why"]))
        z = run(["--method", "zbuf16"], tmp)
        c = run(["--method", "cull"], tmp)
        frames_ok = len(a["frames"]) == FRAMES * 1024 and lit(a["frames"]) > FRAMES * 300
        check(frames_ok and a["frames"] == z["frames"],
              "fixed camera: painter's %d frames equal the 16-bit z-buffer's byte for byte"
              % FRAMES)
        check(c["frames"] != z["frames"] and len(c["frames"]) == len(z["frames"]),
              "fixed camera: without a sort (cull only) the frames differ: the objects overlap "
              "on screen, their order matters")
        b = run(["--bound", "box", NEAR], tmp)
        check(b["method"] == "painter" and b["bucket"] is not None and b["bucket"] < b["gap"],
              "R8_BOUND_BOX %s (the camera moves 40 units every way): %s, a bucket %s units "
              "< the gap %s units" % (NEAR, b["method"], b["bucket"], b["gap"]))
        lo, hi = [int(v) for v in NEAR.split(",")[:3]], [int(v) for v in NEAR.split(",")[3:]]
        spots = [(x, y, zz) for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for zz in (lo[2], hi[2])]
        spots.append(((lo[0] + hi[0]) // 2, (lo[1] + hi[1]) // 2, (lo[2] + hi[2]) // 2))
        same = 0
        for s in spots:
            cam = "%d,%d,%d" % s
            p = run(["--bound", "box", NEAR, "--camera", cam, "--method", "painter"], tmp)
            q = run(["--bound", "box", NEAR, "--camera", cam, "--method", "zbuf16"], tmp)
            ok = p["frames"] == q["frames"] and len(p["frames"]) == FRAMES * 1024
            same += ok
            if not ok:
                print("  camera %s: painter's differs from the z-buffer" % cam)
        check(same == len(spots), "R8_BOUND_BOX %s: at the 8 corners and the centre painter's "
              "frames equal the z-buffer's (%d of %d positions, %d frames each)"
              % (NEAR, same, len(spots), FRAMES))
        d = run(["--bound", "box", DEEP], tmp)
        check(d["method"] not in (None, "painter") and "z-buffer" in d["why"]
              and d["bucket"] is not None and d["bucket"] > d["gap"],
              "R8_BOUND_BOX %s (the camera may back off 3000 units): %s (%s): one bucket %s "
              "units > the gap %s units" % (DEEP, d["method"], d["why"], d["bucket"], d["gap"]))
        n = run(["--bound", "any"], tmp)
        check(n["method"] not in (None, "painter") and "z-buffer" in n["why"],
              "R8_BOUND_ANY (the camera may turn, the order can flip): %s" % n["method"])
    print("%d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
