"""Accuracy metrics: the C renderer (through build/r8probe) against the
floating-point reference (rast8.reference).  docs/accuracy.md defines
every number.

Per frame, both rendered at the same size and format:
- pixel_diff: pixels whose value differs (shade level for idx8, lit bit
  for 1 bpp), split into
  - coverage: one side shows background, the other a face (face ids);
  - shade: both show the same face but a different value;
  - depth order: both show a face, a different one, and the face C shows
    really covers that pixel centre in the reference but lies behind the
    face the reference shows there (a wrong surface, not a shifted edge);
- vertex error: the largest |C 12.4 projection - 16 * float projection|
  over the vertices in front of the near plane, in subpixels;
- error: pixel_diff or depth order (a hidden surface of the same shade
  is still wrong): the charts' error axis;
- PSNR: 10 log10(peak^2 / MSE), peak 16 for levels and 1 for bits; 100 dB
  stands for identical frames;
- 1 bpp: raw counts of wrong, C-lit and reference-lit pixels as well.
"""
from __future__ import annotations

import math
import os
import subprocess
import tempfile

import numpy as np

from . import reference as R
from . import scene as S

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
PROBE = os.path.join(ROOT, "build", "r8probe")
FRAMES = (0, 7, 19, 31, 43, 55, 67, 79)
PSNR_CAP = 100.0


def load_scene(name):
    """A built-in scene name, or a path to a .r8s file."""
    return S.load_any(name) if os.path.exists(name) else S.builtin(name)


def probe(scene, method, shading="lambert", fmt="idx8", width=128, height=64,
          frames=FRAMES, cull="normal", band=8, blob=None, probe_path=PROBE):
    """Run r8probe: returns (pixels[k], ids[k] (-1 background), verts dict
    {(frame, obj, k): (sx, sy, near)})."""
    pix, ids, verts = [], [], {}
    with tempfile.TemporaryDirectory() as td:
        for fr in frames:
            raw, fid, vf = (os.path.join(td, n) for n in ("f.raw", "f.id", "f.txt"))
            cmd = [probe_path, "--method", method, "--shading", shading, "--cull", cull,
                   "--format", fmt, "--width", str(width), "--height", str(height),
                   "--band", str(band), "--frame", str(fr), "--raw", raw, "--faceid", fid,
                   "--verts", vf]
            cmd += ["--blob", blob] if blob else ["--scene", scene]
            subprocess.run(cmd, check=True, capture_output=True)
            with open(raw, "rb") as f:
                pix.append(R.unpack(f.read(), fmt, width, height))
            with open(fid, "rb") as f:
                ids.append(np.frombuffer(f.read(), "<u2").reshape(height, width).astype(int) - 1)
            with open(vf) as f:
                for line in f:
                    a = line.split()
                    verts[(int(a[0]), int(a[1]), int(a[2]))] = (int(a[3]), int(a[4]), int(a[6]))
    return pix, ids, verts


def depth_order_mask(ref, cids):
    """Pixels where C shows face A, the reference shows face B != A, and A
    covers the pixel in the reference but is farther than B there."""
    both = (cids >= 0) & (ref.fid >= 0) & (cids != ref.fid)
    out = np.zeros(cids.shape, bool)
    for a in np.unique(cids[both]):
        sel = both & (cids == a)
        rr, cc = np.nonzero(sel)
        px, py = cc + 0.5, rr + 0.5
        cov = ref.covers(int(a), px, py)
        if not cov.any():
            continue
        za = ref.depth_at(int(a), px, py)
        zb = ref.z[rr, cc]
        bad = cov & (za > zb * (1 + 1e-9) + 1e-9)
        out[rr[bad], cc[bad]] = True
    return out


def depth_order_errors(ref, cids):
    return int(depth_order_mask(ref, cids).sum())


def vertex_error(sc, ref, frame, verts):
    """Largest C-vs-float projection error (subpixels) of frame's vertices."""
    worst = 0.0
    for oi, cam in enumerate(ref.verts):
        xs, ys = R.project(sc, cam, ref.width, ref.height)
        for k in range(len(cam)):
            c = verts.get((frame, oi, k))
            if c is None or c[2] or cam[k, 2] < sc.near:
                continue
            worst = max(worst, abs(c[0] - 16 * xs[k]), abs(c[1] - 16 * ys[k]))
    return worst


def compare_frame(ref, cpix, cids, fmt):
    """Metrics of one frame; ref is a reference.Frame."""
    rpix = ref.pixels(fmt)
    npx = rpix.size
    diff = cpix != rpix
    ccov, rcov = cids >= 0, ref.fid >= 0
    cov = ccov != rcov
    shade = ccov & rcov & (cids == ref.fid) & diff
    dmask = depth_order_mask(ref, cids)
    peak = 16.0 if fmt == "idx8" else 1.0
    se = float(np.sum((cpix.astype(float) - rpix) ** 2))
    return {
        "pixels": npx,
        "pixels_wrong": int(diff.sum()),
        "coverage_wrong": int(cov.sum()),
        "shade_wrong": int(shade.sum()),
        "surface_wrong": int((ccov & rcov & (cids != ref.fid)).sum()),
        "depth_order_errors": int(dmask.sum()),
        "any_wrong": int((diff | dmask).sum()),
        "sq_err": se,
        "peak": peak,
        "pixels_lit_c": int((cpix != 0).sum()),
        "pixels_lit_ref": int((rpix != 0).sum()),
    }


def psnr(sq_err, n, peak):
    if sq_err <= 0:
        return PSNR_CAP
    return min(PSNR_CAP, 10 * math.log10(peak * peak / (sq_err / n)))


def measure(scene, method, shading="lambert", fmt="idx8", width=128, height=64,
            frames=FRAMES, cull="normal", band=8, blob=None, sc=None):
    """Aggregate metrics over `frames` for one configuration (a dict ready
    to merge into a benchmark record)."""
    sc = sc or load_scene(scene)
    if method in ("block", "blockmask") and band % 4:
        band = 8
    pix, ids, verts = probe(scene, method, shading, fmt, width, height, frames, cull, band, blob)
    tot = {}
    vmax = 0.0
    per = []
    for fr, cp, ci in zip(frames, pix, ids):
        ref = R.render(sc, fr, width, height, shading)
        m = compare_frame(ref, cp, ci, fmt)
        per.append(m)
        for k, v in m.items():
            tot[k] = tot.get(k, 0) + v if k != "peak" else v
        vmax = max(vmax, vertex_error(sc, ref, fr, verts))
    n = tot["pixels"]
    out = {
        "pixel_diff_pct": round(100.0 * tot["pixels_wrong"] / n, 4),
        "error_pct": round(100.0 * tot["any_wrong"] / n, 4),
        "coverage_diff_pct": round(100.0 * tot["coverage_wrong"] / n, 4),
        "shade_diff_pct": round(100.0 * tot["shade_wrong"] / n, 4),
        "surface_diff_pct": round(100.0 * tot["surface_wrong"] / n, 4),
        "depth_order_errors": tot["depth_order_errors"],
        "depth_order_errors_max_frame": max(m["depth_order_errors"] for m in per),
        "vertex_error_subpx_max": round(vmax, 3),
        "psnr_db": round(psnr(tot["sq_err"], n, tot["peak"]), 3),
        "accuracy_frames": list(frames),
        "accuracy_format": fmt,
        "accuracy_shading": shading,
    }
    if fmt != "idx8":
        out.update(pixels_wrong=tot["pixels_wrong"], pixels_lit_c=tot["pixels_lit_c"],
                   pixels_lit_ref=tot["pixels_lit_ref"], pixels_total=n)
    return out
