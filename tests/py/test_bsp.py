"""BSP trees (issue 14, host/rast8/bsp.py and src/vis_bsp.c): the tree
covers every face once and separates its subtrees by each node's plane;
splits keep the surface (areas add up, no T-junction left); rigid groups
are merged; the C walk against the float reference and the 16-bit
z-buffer (build/r8probe)."""
import copy
import os
import random
import subprocess

import pytest

from rast8 import bsp as B
from rast8 import concave as C
from rast8 import metrics as M
from rast8 import scene as S

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
PROBE = os.path.join(ROOT, "build", "r8probe")


def _tree(m):
    b = m.bsp
    rd = lambda k: b[k] | (b[k + 1] << 8)  # noqa: E731
    n = (len(b) - 4) // 4
    return [rd(4 + 4 * f) for f in range(n)], [rd(6 + 4 * f) for f in range(n)], rd(0), rd(2)


def _check_tree(m, tol=0.51):
    fr, bk, root, depth = _tree(m)
    assert len(fr) == len(m.faces)
    seen = []

    def sub(f, d):
        if f == B.NONE:
            return []
        assert d <= depth
        seen.append(f)
        return [f] + sub(fr[f], d + 1) + sub(bk[f], d + 1)

    sub(root, 1)
    assert sorted(seen) == list(range(len(m.faces)))          # every face once
    for f in range(len(m.faces)):
        pl = B._plane(m, f)
        for g in sub(fr[f], 0) if fr[f] != B.NONE else []:
            assert all(B._dist(pl, m.verts[i]) >= -tol for i in m.faces[g][1])
        for g in sub(bk[f], 0) if bk[f] != B.NONE else []:
            assert all(B._dist(pl, m.verts[i]) <= tol for i in m.faces[g][1])


def _area(m, idx):
    return abs(C.area2(C.to2d([m.verts[i] for i in idx]))) / 2


def test_builtin_trees():
    have = {}
    for n in S.BUILTIN_ORDER:
        sc = S.builtin(n)
        for name, m in sc.meshes.items():
            if m.bsp:
                _check_tree(m)
            have[(n, name)] = bool(m.bsp)
    # split-free trees leave the meshes alone; the cross asks for BSP
    assert have[("cube", "cube")] and have[("wall", "wall")] and have[("wall", "pillar")]
    assert have[("cross", "slab_post")]
    assert not have[("torus", "torus")] and not have[("teapot", "teapot")]


def test_cross_merged_and_split():
    raw = S._builtin("cross")
    sc = S.builtin("cross")
    assert len(raw.objects) == 2 and len(sc.objects) == 1       # one rigid body
    m = sc.meshes["slab_post"]
    before = sum(_area(raw.meshes[k], idx) for k in raw.meshes for _, idx in raw.meshes[k].faces)
    after = sum(_area(m, idx) for _, idx in m.faces)
    assert after == pytest.approx(before)                       # same surface, cut
    assert len(m.faces) > 12 and all(len(idx) <= 4 for _, idx in m.faces)
    # no T-junction: no vertex lies inside another face's edge
    for _, idx in m.faces:
        for k in range(len(idx)):
            a, b = m.verts[idx[k]], m.verts[idx[(k + 1) % len(idx)]]
            assert not any(B._on_edge(a, b, v) for v in m.verts)


def test_unsplittable_gets_no_tree():
    sc = S._builtin("torus")
    m = copy.deepcopy(sc.meshes["torus"])
    with pytest.raises(B.SplitNeeded):
        B.build(m, allow_split=False)
    assert m.faces == sc.meshes["torus"].faces


def test_order_is_back_to_front():
    """For random eyes, no face drawn earlier lies in front of a later
    one across any node plane (the painter's invariant the tree gives)."""
    sc = S.builtin("cross")
    m = sc.meshes["slab_post"]
    tree = _tree(m)
    rng = random.Random(14)
    for _ in range(50):
        eye = [rng.uniform(-300, 300) for _ in range(3)]
        order = B.order(tree, m, eye)
        assert sorted(order) == list(range(len(m.faces)))
        pos = {f: k for k, f in enumerate(order)}
        for f in range(len(m.faces)):
            side = B._dist(B._plane(m, f), eye) > 0
            near = tree[0][f] if side else tree[1][f]
            stack = [near] if near != B.NONE else []
            while stack:                       # the near subtree comes after f
                g = stack.pop()
                assert pos[g] > pos[f]
                stack += [c for c in (tree[0][g], tree[1][g]) if c != B.NONE]


def test_rast8_scene_check_reports_tree(tmp_path):
    r = subprocess.run([os.path.join(ROOT, ".venv", "bin", "python"), "-m", "rast8.scene", "check",
                        os.path.join(ROOT, "host", "rast8", "scenes", "wall.r8s")],
                       capture_output=True, text=True)
    assert r.returncode == 0 and "BSP tree" in r.stdout


@pytest.fixture(scope="module")
def probe():
    if not os.path.exists(PROBE):
        subprocess.run(["make", "-C", ROOT, "-s", "build/r8probe"], check=True)
    return PROBE


@pytest.mark.parametrize("scene", ["wall", "cross", "separate"])
def test_c_walk_against_reference(probe, scene):
    """The C BSP order against the float reference: never more depth-order
    errors (a hidden surface shown) than the 16-bit z-buffer; on the wall
    and the separate objects none at all, like the z-buffer."""
    frames = tuple(range(0, 64, 3))
    z = M.measure(scene, "zbuf16", frames=frames)
    b = M.measure(scene, "bsp", frames=frames)
    print(scene, "zbuf16", z["depth_order_errors"], z["error_pct"], "bsp", b["depth_order_errors"], b["error_pct"])
    assert b["depth_order_errors"] <= z["depth_order_errors"]
    assert b["coverage_diff_pct"] == z["coverage_diff_pct"]     # same faces, same edges
    if scene != "cross":
        assert b["depth_order_errors"] == 0 and b["error_pct"] == z["error_pct"]


def test_bsp_keyword_merges_and_cuts():
    text = ("scene x\nbsp\n"
            "mesh a\nv -50 -5 -5\nv 50 -5 -5\nv 50 5 -5\nv -50 5 -5\nv -50 -5 5\nv 50 -5 5\nv 50 5 5\nv -50 5 5\n"
            "f 9 0 1 2 3\nf 9 5 4 7 6\nf 9 1 5 6 2\nf 9 4 0 3 7\nf 9 4 5 1 0\nf 9 3 2 6 7\nend\n"
            "mesh b\nv -5 -50 -5\nv 5 -50 -5\nv 5 50 -5\nv -5 50 -5\nv -5 -50 5\nv 5 -50 5\nv 5 50 5\nv -5 50 5\n"
            "f 9 0 1 2 3\nf 9 5 4 7 6\nf 9 1 5 6 2\nf 9 4 0 3 7\nf 9 4 5 1 0\nf 9 3 2 6 7\nend\n"
            "object a at 0 0 200 spin 1 2 0\nobject b at 0 0 200 spin 1 2 0\n")
    sc = S.finish(S.parse_r8s(text, "x.r8s"))
    assert sc.bsp and len(sc.objects) == 1
    (m,) = sc.meshes.values()
    assert m.bsp and len(m.faces) > 12
    _check_tree(m)
    plain = S.finish(S.parse_r8s(text.replace("bsp\n", ""), "x.r8s"))
    assert len(plain.objects) == 2 and all(mm.bsp for mm in plain.meshes.values())   # convex: no cut
    with pytest.raises(S.SceneError, match="usage: bsp"):
        S.parse_r8s(text.replace("bsp\n", "bsp 1\n"), "x.r8s")
