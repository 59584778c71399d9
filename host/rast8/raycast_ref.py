"""Floating-point ray caster: the reference the integer one (src/raycast.c)
is measured against, per screen column.

Same world as r8ray.h: cell (i, j) covers x in [i*c, (i+1)*c), z in
[j*c, (j+1)*c), c = 1 << shift; non-zero cells are walls c tall, the eye
at mid-height; the camera at (x, z) looks at yaw (256 steps per turn,
forward (sin, cos), right (cos, -sin)); column col of a width-pixel
screen looks through pixel centre col + 0.5.  A wall seen at
perpendicular depth d is focal * c / d pixels tall.  Rays leaving the
map end on its edge.

    python -m rast8.raycast_ref [--poses N] [--tool build/r8raycols] [--scene tmaze]

runs the C columns (build/r8raycols) over N cameras spread over the maze's
open cells and prints the wall-height error per column: max and mean over
the columns where both casters hit the same cell face, and how many
columns hit a different face (a ray grazing a corner).

Textured walls (--scene tmaze): the float caster also gives the exact hit
place along the face (u, mirrored as r8ray.h says: left to right seen from
outside) and samples the texture at every wall pixel's centre (v from the
row's place in the float wall); that texel, times the C column's own
level, is compared with the level the C renderer drew (IDX8 frames from
r8raycols): wrong pixels per frame (mean, max) and the level error (mean,
max) over the pixels both call the same face's wall."""
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
    return cast_u(cells, w, h, shift, x, z, yaw, focal, width, col)[:5]


def cast_u(cells, w, h, shift, x, z, yaw, focal, width, col):
    """cast() and the hit's place on the face, 0 <= u < 1, left to right
    seen from outside (0.0 off the map)."""
    c = float(1 << shift)
    a = 2 * math.pi * yaw / 256.0
    fx, fz = math.sin(a), math.cos(a)
    rx, rz = math.cos(a), -math.sin(a)
    u = col + 0.5 - width / 2.0
    dx, dz = focal * fx + u * rx, focal * fz + u * rz
    cx, cz = int(math.floor(x / c)), int(math.floor(z / c))
    if x < 0 or z < 0 or cx >= w or cz >= h:
        return 0.0, 0, 0, 0, 0, 0.0
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
    if side == 0:
        f = (z + t * dz) / c
        f -= math.floor(f)
        u = 1.0 - f if sx > 0 else f
    else:
        f = (x + t * dx) / c
        f -= math.floor(f)
        u = f if sz > 0 else 1.0 - f
    return height, cx, cz, side, v, min(max(u, 0.0), 1.0 - 1e-9)


def read_tool(text):
    """r8raycols output -> (grid dict, [(camera tuple, [columns], [rows])]):
    columns (COL, H16, CX, CZ, SIDE, CELL, U); rows the textured frame's
    levels (a list of lists; empty without textures).  The grid's
    "tex": [(w, h, [texels 0..255, row by row])]."""
    lines = text.splitlines()
    _, w, h, shift = lines[0].split()
    w, h, shift = int(w), int(h), int(shift)
    cells = [[int(v) for v in lines[1 + j].split()] for j in range(h)]
    k = 1 + h
    tex = []
    if k < len(lines) and lines[k].startswith("tex "):
        for i in range(int(lines[k].split()[1])):
            tw, th, _ = (int(v) for v in lines[k + 1 + 2 * i].split())
            tex.append((tw, th, [int(v) for v in lines[k + 2 + 2 * i].split()]))
        k += 1 + 2 * len(tex)
    frames, cur = [], None
    for ln in lines[k:]:
        f = ln.split()
        if f[0] == "cam":
            cur = (tuple(int(v) for v in f[1:]), [], [])
            frames.append(cur)
        elif f[0] == "r":
            cur[2].append([int(ch, 17) for ch in f[2]])
        else:
            cur[1].append(tuple(int(v) for v in f))
    return {"cells": cells, "w": w, "h": h, "shift": shift, "tex": tex}, frames


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
    for (x, z, yaw, focal, width), cols, _ in frames:
        for col, h16, cx, cz, side, cell in (c[:6] for c in cols):
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


def c_level(h16, cell, side, rows):
    """The C column's wall level (src/raycast.c level_of, distance
    shaded): the cell's, 3/4 across z, times min(h, full) / full."""
    lv = min(cell, 16)
    if side:
        lv -= lv >> 2
    hb, full = 0, 1
    while (rows >> hb) > 1:
        hb += 1
        full *= 2
    half = min((h16 >> 5) + ((h16 >> 4) & 1), rows // 2)
    if half:
        lv = max((lv * min(h16 >> 4, full)) >> hb, 3)
    return lv, half


def compare_tex(grid, frames, flip=False):
    """Texel error of the textured C frames against the float caster
    sampling the texture at each wall pixel's centre (flip: the float u
    mirrored, the check that the measure sees a wrong mapping)."""
    tex = grid["tex"]
    wrong_frames, diffs, maxd, pixels = [], 0, 0, 0
    for (x, z, yaw, focal, width), cols, rows in frames:
        nrows = len(rows)
        cy = nrows // 2
        wrong = 0
        for col, h16, cx, cz, side, cell, _u in cols:
            ref = cast_u(grid["cells"], grid["w"], grid["h"], grid["shift"], x, z, yaw, focal,
                         width, col)
            if (cx, cz, side) != ref[1:4] or not cell:
                continue
            lv, half = c_level(h16, cell, side, nrows)
            hf, u = ref[0], ref[5]
            if flip:
                u = 1.0 - 1e-9 - u
            tw, th, texels = tex[(cell - 1) % len(tex)]
            tu = min(int(u * tw), tw - 1)
            for y in range(cy - half, cy + half):
                v = (y + 0.5 - (cy - hf / 2.0)) / hf
                if not 0.0 <= v <= 1.0:
                    continue          # outside the float wall: the height error
                tv = min(int(v * th), th - 1)
                tl = texels[tv * tw + tu]
                want = ((tl + (tl >> 7)) * lv + 128) >> 8
                d = abs(rows[y][col] - want)
                pixels += 1
                diffs += d
                maxd = max(maxd, d)
                wrong += d != 0
        wrong_frames.append(wrong)
    n = len(wrong_frames) or 1
    return {
        "frames": len(wrong_frames),
        "wall_pixels": pixels,
        "wrong_mean": sum(wrong_frames) / float(n),
        "wrong_max": max(wrong_frames) if wrong_frames else 0,
        "wrong_rate": sum(wrong_frames) / float(pixels or 1),
        "level_mean": diffs / float(pixels or 1),
        "level_max": maxd,
    }


def run(tool, n, width=128, scene="maze"):
    """Run build/r8raycols over n poses; returns compare()'s figures
    (and, for a textured grid, compare_tex()'s as "tex")."""
    head = subprocess.run([tool, "--scene", scene], input="", stdout=subprocess.PIPE, text=True,
                          check=True)
    grid, _ = read_tool(head.stdout)
    cams = poses(grid, n, width=width)
    text = "".join("%d %d %d %d %d\n" % p for p in cams)
    r = subprocess.run([tool, "--scene", scene], input=text, stdout=subprocess.PIPE, text=True,
                       check=True)
    grid, frames = read_tool(r.stdout)
    res = compare(grid, frames)
    if grid["tex"]:
        res["tex"] = compare_tex(grid, frames)
    return res


def main(argv=None):
    ap = argparse.ArgumentParser(description="wall-height error of the integer ray caster "
                                 "against a float one, per column (the maze)")
    ap.add_argument("--poses", type=int, default=200, help="cameras (default 200)")
    ap.add_argument("--tool", default=os.path.join(ROOT, "build", "r8raycols"),
                    help="the C columns (default build/r8raycols: make build/r8raycols)")
    ap.add_argument("--scene", default="maze", help="a grid scene (default maze; tmaze: "
                    "the textured maze, its texel error too)")
    ap.add_argument("--json", action="store_true", help="one JSON object")
    a = ap.parse_args(argv)
    if a.poses < 1:
        print("raycast_ref: --poses must be >= 1", file=sys.stderr)
        return 2
    if not os.path.exists(a.tool):
        print("raycast_ref: %s missing (make build/r8raycols)" % a.tool, file=sys.stderr)
        return 2
    try:
        res = run(a.tool, a.poses, scene=a.scene)
    except subprocess.CalledProcessError:
        print("raycast_ref: %s failed on scene '%s' (not a grid scene?)" % (a.tool, a.scene),
              file=sys.stderr)
        return 2
    if a.json:
        print(json.dumps(res))
    else:
        print("%d columns: wall height error max %.3f px (%.2f%%), mean %.4f px; "
              "%d columns hit another face" % (res["columns"], res["max_px"], 100 * res["max_rel"],
                                                res["mean_px"], res["other_face"]))
        if "tex" in res:
            t = res["tex"]
            print("textured: %d frames, %d wall pixels: wrong pixels per frame mean %.1f, max %d "
                  "(%.2f%%); level error mean %.4f, max %d" % (
                      t["frames"], t["wall_pixels"], t["wrong_mean"], t["wrong_max"],
                      100 * t["wrong_rate"], t["level_mean"], t["level_max"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
