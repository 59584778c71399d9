"""Concave and non-planar face splitting (issue 13, host/rast8/concave.py):
the pieces are convex, at most 4 corners, same winding, and cover the
face exactly; the seed's method gives fewer pieces than ear clipping or
the old fan; and, through the C renderer (build/r8probe), coverage
against the float reference on concave inputs before and after."""
import math
import os
import random
import subprocess

import numpy as np
import pytest

from rast8 import concave as C
from rast8 import metrics as M
from rast8 import reference as R
from rast8 import scene as S

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
PROBE = os.path.join(ROOT, "build", "r8probe")

STAR = [(0, 0), (3, 1), (6, 0), (5, 3), (6, 6), (3, 5), (0, 6), (1, 3)]
# an OBJ face (both windings) with a notch next to its first corner: the
# old fan from that corner covers the notch
NOTCH_OBJ = ("v 0 -20 0\nv -60 -60 0\nv 60 -60 0\nv 60 60 0\nv -60 60 0\n"
             "v -60 -40 0\nf 2 3 4 5 6 1\nf 2 1 6 5 4 3\n")


def _random_polygon(rng, n):
    """A random star-shaped simple polygon, counter-clockwise."""
    angs = sorted(rng.uniform(0, 2 * math.pi) for _ in range(n))
    rad = [100 * rng.uniform(0.3, 1) for _ in angs]
    return [(round(r * math.cos(a)), round(r * math.sin(a))) for r, a in zip(rad, angs)]


def _simple(p):
    n = len(p)
    return not any(C._seg_cross(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n])
                   for i in range(n) for j in range(i + 2, n) if (j + 1) % n != i)


def test_pieces_convex_and_exact():
    rng = random.Random(13)
    done = 0
    for _ in range(300):
        p = _random_polygon(rng, rng.randint(4, 12))
        if len(set(p)) != len(p) or C.area2(p) <= 0 or not _simple(p):
            continue
        pieces = C.split_polygon(p)
        assert pieces
        assert all(3 <= len(pc) <= 4 for pc in pieces)
        assert all(C.is_convex2([p[i] for i in pc]) for pc in pieces)
        # same winding, and the areas add up to the face's: no overlap, no gap
        assert sum(C.area2([p[i] for i in pc]) for pc in pieces) == pytest.approx(C.area2(p))
        assert len(pieces) <= len(C.ear_clip(p))
        done += 1
    assert done > 200


def test_seed_method_fewer_pieces():
    c = C.compare(STAR)
    assert c == {"fan": 6, "ear": 6, "seed_first_start": 5, "seed_best_start": 4}


def test_face_splitting_rules():
    v = [(0, 0, 0), (10, 0, 0), (10, 10, 0), (0, 10, 0), (3, 3, 0), (10, 10, 6)]
    assert C.split_face(v, [0, 1, 2, 3]) == [[0, 1, 2, 3]]          # planar convex: whole
    pcs = C.split_face(v, [0, 1, 4, 3])                            # concave: cut at the notch
    assert len(pcs) == 2 and all(4 in pc for pc in pcs)
    assert C.fold([v[0], v[1], v[5], v[3]]) > C.FOLD_DEG               # folded quad
    assert len(C.split_face(v, [0, 1, 5, 3])) == 2


def _coverage_error(sc, truth, frames, tmp_path):
    """Pixels where the C renderer's coverage (any face) differs from the
    float reference rendering `truth`, over frames."""
    blob = str(tmp_path / "s.bin")
    with open(blob, "wb") as f:
        f.write(S.to_blob(sc))
    _, ids, _ = M.probe(None, "zbuf16", frames=frames, blob=blob)
    return sum(int(np.sum((ci >= 0) != (R.render(truth, fr).fid >= 0))) for fr, ci in zip(frames, ids))


def _scene_of(mesh, spin=(1, 2, 0)):
    sc = S.Scene(mesh.name)
    sc.meshes[mesh.name] = mesh
    sc.objects.append(S.Obj(mesh.name, (0, 0, 260), (0, 0, 0), spin))
    return sc


@pytest.fixture(scope="module")
def probe():
    if not os.path.exists(PROBE):
        subprocess.run(["make", "-C", ROOT, "-s", "build/r8probe"], check=True)
    return PROBE


def test_concave_obj_coverage_before_after(probe, tmp_path):
    after = S.parse_obj(NOTCH_OBJ, "notch.obj")
    assert all(len(idx) <= 4 for _, idx in after.faces)
    # before: the converter's old fan from corner 0
    before = S.Mesh("notch", list(after.verts), [])
    for colour, idx in [(16, [1, 2, 3, 4, 5, 0]), (16, [1, 0, 5, 4, 3, 2])]:
        before.faces += [(colour, [idx[0], idx[k], idx[k + 1]]) for k in range(1, len(idx) - 1)]
    # the truth: the same face ear-clipped (exact) in the float reference
    truth = S.Mesh("notch", list(after.verts), [])
    for idx in ([0, 1, 2, 3, 4, 5], [0, 5, 4, 3, 2, 1]):
        p2 = C.to2d([after.verts[i] for i in idx])
        truth.faces += [(16, [idx[i] for i in t]) for t in C.ear_clip(p2)]
    frames = tuple(range(0, 128, 8))
    err_before = _coverage_error(_scene_of(before), _scene_of(truth), frames, tmp_path)
    err_after = _coverage_error(_scene_of(after), _scene_of(truth), frames, tmp_path)
    print(f"notch: coverage error before {err_before} px, after {err_after} px")
    assert err_before > 500 and err_before > 20 * err_after   # the fan covers the notch
    assert err_after <= 40            # edge rounding only (1/16-pixel vertices)


def test_teapot_lid_coverage_before_after(probe, tmp_path):
    after = S.builtin("teapot")
    before = S._builtin("teapot")     # without the converter's passes
    assert len(after.meshes["teapot"].faces) == len(before.meshes["teapot"].faces) + 4
    frames = tuple(range(0, 256, 4))
    err_before = _coverage_error(before, after, frames, tmp_path)
    err_after = _coverage_error(after, after, frames, tmp_path)
    print(f"teapot: coverage error before {err_before} px, after {err_after} px")
    assert err_after < err_before
