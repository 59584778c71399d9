"""The floating-point reference renderer (rast8.reference) and the metrics
built on it (issue 6): hand-computed cases, exact agreement with the C
scan converter on integer-vertex (12.4 grid) polygons, and bounded
agreement with whole C frames."""
import math
import os
import random
import subprocess

import numpy as np
import pytest

from rast8 import reference as R
from rast8 import metrics as M
from rast8 import scene as S

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
FILL = os.path.join(ROOT, "build", "r8fill")
PROBE = os.path.join(ROOT, "build", "r8probe")


def _need(path):
    if not os.path.exists(path):
        subprocess.run(["make", "-C", ROOT, "-s", os.path.relpath(path, ROOT)], check=True)
    return path


# ---- hand-computed -------------------------------------------------------

def test_square_top_left_rule():
    # square [1, 3) x [1, 3) in pixels: centres 1.5 and 2.5 in each axis
    m = R.fill_mask([1, 3, 3, 1], [1, 1, 3, 3], 5, 5)
    assert m.sum() == 4 and m[1:3, 1:3].all()
    # edges exactly through pixel centres: left/top inclusive, right/bottom exclusive
    m = R.fill_mask([0.5, 2.5, 2.5, 0.5], [0.5, 0.5, 2.5, 2.5], 4, 4)
    assert sorted(map(tuple, np.argwhere(m))) == [(0, 0), (0, 1), (1, 0), (1, 1)]


def test_counter_clockwise_draws_nothing():
    assert R.fill_mask([1, 1, 3, 3], [1, 3, 3, 1], 5, 5).sum() == 0


def test_shared_edge_no_gap_no_overlap():
    w, h = 16, 16
    a = R.fill_mask([0.5, 12.3, 3.7], [0.5, 2.1, 14.9], w, h)
    b = R.fill_mask([12.3, 15.2, 3.7], [2.1, 13.0, 14.9], w, h)
    whole = R.fill_mask([0.5, 12.3, 15.2, 3.7], [0.5, 2.1, 13.0, 14.9], w, h)
    assert not (a & b).any()
    assert ((a | b) == whole).all()


def test_triangle_pixel_count():
    # right triangle legs 8 px from (0,0): centres (c+.5, r+.5) with
    # c + r + 1 < 8 strictly inside, plus those on the hypotenuse (a right
    # edge here: excluded): 7+6+...+1 = 28
    m = R.fill_mask([0, 8, 0], [0, 0, 8], 10, 10)
    assert m.sum() == 28


def test_projection_and_focal():
    sc = S.builtin("cube")
    assert R.focal_px(sc, 128) == (128 * 50) >> 6 == 100
    xs, ys = R.project(sc, np.array([[20.0, -10.0, 200.0]]), 128, 64)
    assert xs[0] == pytest.approx(64 + 100 * 20 / 200)
    assert ys[0] == pytest.approx(32 - 100 * 10 / 200)


def test_rotation_convention():
    # Rz first: a quarter turn about z maps x to y (y down: clockwise on screen)
    m = R.rot_matrix(0, 0, 64)
    assert np.allclose(m @ [1, 0, 0], [0, 1, 0])
    m = R.rot_matrix(64, 64, 0)   # Rx(90) Ry(90): x -> Ry -> -z -> Rx -> y
    assert np.allclose(m @ [1, 0, 0], [0, 1, 0])
    sc = S.builtin("cube")
    ob = sc.objects[0]
    assert R.angles(ob, 300) == tuple((a + s * (300 & 0xFF)) % 256 for a, s in zip(ob.rot, ob.spin))


def _one_face_scene(verts, colour=10, light=(0, 0, -1), ambient=0.25):
    sc = S.Scene("t", focal=64, near=16, light=light, ambient=ambient)
    m = S.Mesh("q", verts=verts, faces=[(colour, list(range(len(verts))))])
    sc.meshes["q"] = m
    sc.objects.append(S.Obj("q", (0, 0, 0)))
    return sc


def test_flat_quad_facing_camera():
    # quad at z = 100, x/y in [-50, 50): f = 64 px at width 64, so it
    # spans 64 +/- 32 ... exactly the whole 64x64 screen: every pixel
    sq = [(-50, -50, 100), (50, -50, 100), (50, 50, 100), (-50, 50, 100)]
    sc = _one_face_scene(sq)
    fr = R.render(sc, 0, 64, 64, "flat")
    assert (fr.level == 10).all() and (fr.fid == 0).all()
    assert np.allclose(fr.z, 100)
    # Lambert: normal (v2-v0)x(v1-v0) points to -z (towards the camera),
    # light (0,0,-1): full light, level = round(10 * 1) = 10; light from
    # the side: ambient only, round(10 * .25) = round(2.5) = 3 (half up)
    assert (R.render(sc, 0, 64, 64, "lambert").level == 10).all()
    sc2 = _one_face_scene(sq, light=(1, 0, 0))
    assert (R.render(sc2, 0, 64, 64, "lambert").level == 3).all()
    # the same quad listed anticlockwise is a back face: nothing drawn
    sc3 = _one_face_scene(sq[::-1])
    assert (R.render(sc3, 0, 64, 64, "flat").fid == -1).all()


def test_exact_depth_on_slanted_plane():
    # plane z = 100 + x (x in camera units): at a pixel centre (px, py) the
    # ray (t (px - cx)/f, ., t) meets it at z = 100 / (1 - (px - cx)/f)
    q = [(-30, -30, 70), (30, -30, 130), (30, 30, 130), (-30, 30, 70)]
    sc = _one_face_scene(q)
    fr = R.render(sc, 0, 64, 64, "flat")
    rr, cc = np.nonzero(fr.fid == 0)
    k = (cc + 0.5 - 32) / 64.0
    assert len(rr) > 500
    assert np.allclose(fr.z[rr, cc], 100 / (1 - k))


def test_near_clip():
    # a floor quad from z = 4 to z = 200 crossing near = 16: clipped at 16
    q = [(-40, 20, 4), (-40, 20, 200), (40, 20, 200), (40, 20, 4)]
    sc = _one_face_scene(q)
    fr = R.render(sc, 0, 64, 64, "flat")
    p = fr.polys[0]
    assert p.front
    xs, ys = R.project(sc, np.array([[40, 20, 16.0]]), 64, 64)
    assert max(p.ys) == pytest.approx(ys[0])
    assert (fr.z[fr.fid == 0] >= 16 - 1e-9).all()


def test_gouraud_interpolation_linear():
    # one triangle, intensities 0, 8, 16 at its screen vertices: linear in
    # screen space inside it
    xs, ys, it = np.array([2.0, 30.0, 2.0]), np.array([2.0, 2.0, 30.0]), np.array([0.0, 8.0, 16.0])
    px, py = np.array([10.5, 5.5]), np.array([6.5, 20.5])
    got = R.gouraud_at(xs, ys, it, px, py)
    want = (px - 2) / 28 * 8 + (py - 2) / 28 * 16
    assert np.allclose(got, want)


def test_dither_and_pack_layouts():
    lev = np.zeros((8, 8), int)
    lev[0, 0] = 1        # 1 > bayer[0][0] = 0: lit
    lev[0, 1] = 8        # 8 > 8 false: dark
    lev[3, 2] = 14       # bayer[3][2] = 13: lit
    fr = R.Frame(8, 8, lev, np.where(lev > 0, 0, -1), np.full((8, 8), np.inf))
    bits = fr.pixels("page1")
    assert bits[0, 0] == 1 and bits[0, 1] == 0 and bits[3, 2] == 1 and bits.sum() == 2
    pg = fr.to_bytes("page1")       # byte (row/8)*w + x, bit row%8
    assert pg[0] == 0x01 and pg[2] == 0x08
    rw = fr.to_bytes("row1")        # byte row*1 + x/8, bit 7 - x%8
    assert rw[0] == 0x80 and rw[3] == 0x20
    for fmt in R.FORMATS:
        assert (R.unpack(fr.to_bytes(fmt), fmt, 8, 8) == fr.pixels(fmt)).all()


# ---- agreement with the C scan converter --------------------------------

def _c_fill(polys, w, h):
    _need(FILL)
    lines = [f"{w} {h} {len(p)} " + " ".join(f"{x} {y}" for x, y in p) for p in polys]
    out = subprocess.run([FILL], input="\n".join(lines).encode(), capture_output=True, check=True).stdout
    n = w * h
    return [np.frombuffer(out[i * n:(i + 1) * n], np.uint8).reshape(h, w).astype(bool)
            for i in range(len(polys))]


def test_integer_vertex_triangles_match_c_exactly():
    rng = random.Random(6)
    w, h = 24, 20
    polys = []
    for k in range(1500):
        p = [(rng.randint(-40, w * 16 + 40), rng.randint(-40, h * 16 + 40)) for _ in range(3)]
        if k % 3 == 0:      # snap to pixel centres and corners: every tie case
            p = [(x // 16 * 16 + rng.choice((0, 8)), y // 16 * 16 + rng.choice((0, 8))) for x, y in p]
        polys.append(p)
    for p, c in zip(polys, _c_fill(polys, w, h)):
        r = R.fill_mask([x / 16 for x, _ in p], [y / 16 for _, y in p], w, h)
        assert (c == r).all(), p


def _convex(p):
    q = [a for i, a in enumerate(p) if a != p[i - 1]]
    n = len(q)
    for i in range(n):
        (ax, ay), (bx, by), (cx, cy) = q[i], q[(i + 1) % n], q[(i + 2) % n]
        if (bx - ax) * (cy - by) - (by - ay) * (cx - bx) < 0:
            return False
    return True


def test_integer_vertex_quads_match_c_exactly():
    rng = random.Random(7)
    w, h = 20, 20
    polys = []
    for _ in range(500):
        cx, cy, r = rng.randint(40, 280), rng.randint(40, 280), rng.randint(8, 200)
        a0 = rng.random() * 2 * math.pi
        ang = sorted(a0 + rng.random() * 2 * math.pi for _ in range(4))
        # clockwise on screen (y down) = increasing angle
        polys.append([(round(cx + r * math.cos(a)), round(cy + r * math.sin(a))) for a in ang])
    checked = 0
    for p, c in zip(polys, _c_fill(polys, w, h)):
        xs, ys = [x / 16 for x, _ in p], [y / 16 for _, y in p]
        if R.signed_area2(xs, ys) <= 0 or not _convex(p):
            continue    # rounding made it non-convex: outside the spec
        r = R.fill_mask(xs, ys, w, h)
        assert (c == r).all(), p
        checked += 1
    assert checked >= 400


# ---- agreement with whole C frames (bounded) ----------------------------

@pytest.fixture(scope="module")
def probe_tool():
    return _need(PROBE)


def test_cube_frames_close_to_c(probe_tool):
    # The cube is convex: every method that is exact for it shows the same
    # surfaces as the reference.  Differences come from the Q1.14 rotation,
    # integer camera coordinates and 12.4 vertices (edge pixels) only.
    for method in ("cull", "zbuf16", "sbuf"):
        m = M.measure("cube", method, "flat", "idx8", frames=(0, 19, 43))
        assert m["depth_order_errors"] == 0
        assert m["coverage_diff_pct"] < 0.5
        assert m["shade_diff_pct"] == 0
        assert m["vertex_error_subpx_max"] <= 6   # 0.5 unit at z~184, f=100: 4.3
    lam = M.measure("cube", "cull", "lambert", "idx8", frames=(0, 19, 43))
    assert lam["shade_diff_pct"] < 0.5            # Q1.14 light, rounding ties
    gou = M.measure("cube", "cull", "gouraud", "idx8", frames=(0, 19, 43))
    assert gou["shade_diff_pct"] < 5              # span shade sampled at the edges, not centres
    pg = M.measure("cube", "cull", "lambert", "page1", frames=(0, 19, 43))
    assert pg["pixels_wrong"] <= pg["pixels_total"] * 0.005


def test_depth_order_errors_seen(probe_tool):
    # the seed's wall-and-pillar case: painter's shows the wall over the
    # pillar; the z-buffer does not
    paint = M.measure("wall", "painter", "flat", "idx8", frames=(0, 31))
    zbuf = M.measure("wall", "zbuf16", "flat", "idx8", frames=(0, 31))
    assert paint["depth_order_errors"] > 50
    assert zbuf["depth_order_errors"] == 0


def test_blob_scene_renders_like_builtin(probe_tool, tmp_path):
    # the probe's run-time scene blob gives the built-in scene's frames
    blob = tmp_path / "torus.bin"
    blob.write_bytes(S.to_blob(S.builtin("torus")))
    a, ia, _ = M.probe("torus", "zbuf16", frames=(5,))
    b, ib, _ = M.probe("torus", "zbuf16", frames=(5,), blob=str(blob))
    assert (a[0] == b[0]).all() and (ia[0] == ib[0]).all()


def test_bench_accuracy_annotates_records(probe_tool, tmp_path):
    # bench/accuracy.py adds the accuracy fields to every benchmark record
    import json
    import sys
    sys.path.insert(0, os.path.join(ROOT, "bench"))
    import accuracy
    res = tmp_path / "results.json"
    recs = [{"target": "avr1284", "scene": "wall", "method": "painter", "width": 128, "height": 64,
             "format": "page1", "cycles_per_frame": 1},
            {"target": "z80", "scene": "wall", "method": "painter", "width": 128, "height": 64,
             "format": "page1", "cycles_per_frame": 2},
            {"target": "host", "scene": "cube", "method": "cull", "format": "idx8"}]
    res.write_text(json.dumps(recs))
    accuracy.annotate(str(res))
    out = json.loads(res.read_text())
    for r in out:
        for k in ("pixel_diff_pct", "depth_order_errors", "vertex_error_subpx_max", "psnr_db"):
            assert k in r
    assert out[0]["depth_order_errors"] == out[1]["depth_order_errors"] > 0   # the seed's painter failure
    assert out[0]["pixels_total"] == 128 * 64 * len(M.FRAMES)                  # 1 bpp: raw counts
    assert out[2]["depth_order_errors"] == 0 and "pixels_total" not in out[2]
