"""Floating-point ray caster: the reference the integer one (src/raycast.c)
is measured against, per screen column.

Same world as r8ray.h: cell (i, j) covers x in [i*c, (i+1)*c), z in
[j*c, (j+1)*c), c = 1 << shift; non-zero cells are walls c tall, the eye
at mid-height; the camera at (x, z) looks at yaw (256 steps per turn,
forward (sin, cos), right (cos, -sin)); column col of a width-pixel
screen looks through pixel centre col + 0.5.  A wall seen at
perpendicular depth d is focal * c / d pixels tall.  Rays leaving the
map end on its edge.

    python -m rast8.raycast_ref [--poses N] [--tool build/r8raycols]

runs the C columns (build/r8raycols) over N cameras spread over the maze's
open cells and prints the wall-height error per column: max and mean over
the columns where both casters hit the same cell face, and how many
columns hit a different face (a ray grazing a corner)."""
import argparse
import json
import math
import os
import random
import subprocess
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def cast(cells, w, h, shift, x, z, yaw, focal, width, col):
    """One column: (height in pixels, cx, cz, side, cell); height 0 and
    cell 0 when the camera is off the map."""
    c = float(1 << shift)
    a = 2 * math.pi * yaw / 256.0
    fx, fz = math.sin(a), math.cos(a)
    rx, rz = math.cos(a), -math.sin(a)
    u = col + 0.5 - width / 2.0
    dx, dz = focal * fx + u * rx, focal * fz + u * rz
    cx, cz = int(math.floor(x / c)), int(math.floor(z / c))
    if x < 0 or z < 0 or cx >= w or cz >= h:
        return 0.0, 0, 0, 0, 0
    sx = 1 if dx > 0 else -1
    sz = 1 if dz > 0 else -1
    # ray parameter t at the next boundaries, and per cell
    if dx != 0:
        nx = (cx + 1) * c if sx > 0 else cx * c
        tx, ix = (nx - x) / dx, c / abs(dx)
    else:
        tx, ix = math.inf, math.inf
    if dz != 0:
        nz = (cz + 1) * c if sz > 0 else cz * c
        tz, iz = (nz - z) / dz, c / abs(dz)
    else:
        tz, iz = math.inf, math.inf
    while True:
        if tx < tz:
            t, side = tx, 0
            tx += ix
            cx += sx
            if not 0 <= cx < w:
                v = 16
                break
        else:
            t, side = tz, 1
            tz += iz
            cz += sz
            if not 0 <= cz < h:
                v = 16
                break
        v = cells[cz][cx]
        if v:
            break
    depth = t * (dx * fx + dz * fz)
    height = math.inf if depth <= 0 else focal * c / depth
    return height, cx, cz, side, v


def read_tool(text):
    """r8raycols output -> (grid dict, [(camera tuple, [columns])])."""
    lines = text.splitlines()
    _, w, h, shift = lines[0].split()
    w, h, shift = int(w), int(h), int(shift)
    cells = [[int(v) for v in lines[1 + j].split()] for j in range(h)]
    frames, cur = [], None
    for ln in lines[1 + h:]:
        f = ln.split()
        if f[0] == "cam":
            cur = (tuple(int(v) for v in f[1:]), [])
            frames.append(cur)
        else:
            cur[1].append(tuple(int(v) for v in f))
    return {"cells": cells, "w": w, "h": h, "shift": shift}, frames


def poses(grid, n, seed=14, width=128):
    """n cameras over the open cells (a margin from the walls, as a walk
    keeps), random yaw; focal lengths from 45 to 90 degrees across."""
    rnd = random.Random(seed)
    c = 1 << grid["shift"]
    free = [(i, j) for j in range(grid["h"]) for i in range(grid["w"]) if not grid["cells"][j][i]]
    out = []
    for _ in range(n):
        i, j = rnd.choice(free)
        out.append((i * c + rnd.randint(4, c - 4), j * c + rnd.randint(4, c - 4),
                    rnd.randrange(256), rnd.choice([64, 100, 128, 154]), width))
    return out


def compare(grid, frames):
    """Per-column wall-height error (pixels) of the C columns against
    the float caster: a dict of figures."""
    errs, rel, differ, total = [], [], 0, 0
    for (x, z, yaw, focal, width), cols in frames:
        for col, h16, cx, cz, side, cell in cols:
            ref = cast(grid["cells"], grid["w"], grid["h"], grid["shift"], x, z, yaw, focal,
                       width, col)
            total += 1
            if (cx, cz, side) != ref[1:4]:
                differ += 1
                continue
            hc = h16 / 16.0
            if h16 == 0xFFFF and ref[0] >= hc:
                continue
            errs.append(abs(hc - ref[0]))
            rel.append(abs(hc - ref[0]) / ref[0] if ref[0] else 0.0)
    return {
        "columns": total,
        "other_face": differ,
        "max_px": max(errs) if errs else 0.0,
        "mean_px": sum(errs) / len(errs) if errs else 0.0,
        "max_rel": max(rel) if rel else 0.0,
    }


def run(tool, n, width=128):
    """Run build/r8raycols over n poses; returns compare()'s figures."""
    head = subprocess.run([tool], input="", stdout=subprocess.PIPE, text=True, check=True)
    grid, _ = read_tool(head.stdout)
    cams = poses(grid, n, width=width)
    text = "".join("%d %d %d %d %d\n" % p for p in cams)
    r = subprocess.run([tool], input=text, stdout=subprocess.PIPE, text=True, check=True)
    grid, frames = read_tool(r.stdout)
    return compare(grid, frames)


def main(argv=None):
    ap = argparse.ArgumentParser(description="wall-height error of the integer ray caster "
                                 "against a float one, per column (the maze)")
    ap.add_argument("--poses", type=int, default=200, help="cameras (default 200)")
    ap.add_argument("--tool", default=os.path.join(ROOT, "build", "r8raycols"),
                    help="the C columns (default build/r8raycols: make build/r8raycols)")
    ap.add_argument("--json", action="store_true", help="one JSON object")
    a = ap.parse_args(argv)
    if a.poses < 1:
        print("raycast_ref: --poses must be >= 1", file=sys.stderr)
        return 2
    if not os.path.exists(a.tool):
        print("raycast_ref: %s missing (make build/r8raycols)" % a.tool, file=sys.stderr)
        return 2
    res = run(a.tool, a.poses)
    if a.json:
        print(json.dumps(res))
    else:
        print("%d columns: wall height error max %.3f px (%.2f%%), mean %.4f px; "
              "%d columns hit another face" % (res["columns"], res["max_px"], 100 * res["max_rel"],
                                                res["mean_px"], res["other_face"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
