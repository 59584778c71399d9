"""Scene model: the text format and OBJ subset, their errors (file and
line), the generated C for the built-ins, and the binary blob."""
import os
import struct
import subprocess
import sys

import pytest

from rast8 import scene

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

GOOD = """# a tiny scene
scene tiny
camera focal 40 near 8
light 0 -1 -1 ambient 0.5
mesh tri
v 0 -10 0
v 10 10 0
v -10 10 0
f 12 0 1 2
end
object tri at 0 0 100 rot 0 0 0 spin 1 2 3
"""


def test_parse_good_scene():
    sc = scene.parse_r8s(GOOD, "tiny.r8s")
    assert sc.name == "tiny" and sc.focal == 40 and sc.near == 8
    assert sc.meshes["tri"].verts == [(0, -10, 0), (10, 10, 0), (-10, 10, 0)]
    assert sc.meshes["tri"].faces == [(12, [0, 1, 2])]
    assert not sc.meshes["tri"].convex       # open: one triangle
    assert sc.objects[0].pos == (0, 0, 100) and sc.objects[0].spin == (1, 2, 3)


@pytest.mark.parametrize("line,text,msg", [
    (6, "v 0 -10\n", "usage: v X Y Z"),
    (6, "v 0 -10 40000\n", "out of range"),
    (9, "f 12 0 1 7\n", "vertex index 7 out of range"),
    (9, "f 17 0 1 2\n", "colour 17 out of range"),
    (9, "f 12 0 1 1\n", "repeats a vertex"),
    (11, "object nosuch at 0 0 100\n", "unknown mesh 'nosuch'"),
    (11, "object tri at 0 0 x\n", "position 'x' is not an integer"),
    (3, "camera focal 0 near 8\n", "focal 0 out of range"),
    (4, "light 0 0 0\n", "light direction is zero"),
    (3, "bogus 1\n", "unknown keyword 'bogus'"),
])
def test_errors_name_file_and_line(line, text, msg):
    lines = GOOD.splitlines(True)
    lines[line - 1] = text
    with pytest.raises(scene.SceneError) as e:
        scene.parse_r8s("".join(lines), "bad.r8s")
    assert str(e.value).startswith(f"bad.r8s:{line}: ")
    assert msg in str(e.value)


def test_unclosed_mesh_and_missing_scene():
    with pytest.raises(scene.SceneError, match=r"^x.r8s:\d+: mesh 'tri' not closed"):
        scene.parse_r8s(GOOD.replace("end\n", "").replace("object tri at 0 0 100 rot 0 0 0 spin 1 2 3\n", ""), "x.r8s")
    with pytest.raises(scene.SceneError, match=r"^y.r8s:1: 'mesh' before 'scene NAME'"):
        scene.parse_r8s("mesh a\n", "y.r8s")


def test_cli_reports_bad_file(tmp_path):
    bad = tmp_path / "bad.r8s"
    bad.write_text(GOOD.replace("f 12 0 1 2", "f 12 0 1 9"))
    r = subprocess.run([sys.executable, "-m", "rast8.scene", "check", str(bad)],
                       capture_output=True, text=True)
    assert r.returncode == 1
    assert f"{bad}:9: vertex index 9 out of range" in r.stderr


def test_obj_subset(tmp_path):
    obj = ("# cube-ish\nv -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\n"
           "v -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
           "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n")
    m = scene.parse_obj(obj, "c.obj")
    assert len(m.verts) == 8 and len(m.faces) == 6       # planar convex quads kept whole (concave.py)
    assert max(abs(c) for v in m.verts for c in v) == 100
    assert m.convex                                      # OBJ winding converted
    with pytest.raises(scene.SceneError, match=r"^c.obj:2: vertex 2 not defined yet"):
        scene.parse_obj("v 0 0 0\nf 1 2 9\n", "c.obj")
    with pytest.raises(scene.SceneError, match=r"^c.obj:1: unsupported OBJ statement 'curv'"):
        scene.parse_obj("curv 1 2\n", "c.obj")


def test_builtins_have_the_promised_sizes():
    faces = {n: sum(len(m.faces) for m in scene.builtin(n).meshes.values()) for n in scene.BUILTIN_ORDER}
    assert faces["cube"] == 6
    assert 180 <= faces["torus"] <= 220
    assert 220 <= faces["teapot"] <= 260
    assert scene.builtin("cube").meshes["cube"].convex
    assert not scene.builtin("torus").meshes["torus"].convex
    assert len(scene.builtin("separate").objects) >= 3
    for n in scene.BUILTIN_ORDER:
        for m in scene.builtin(n).meshes.values():
            assert len(m.verts) <= 255


def test_terrain_wraps_at_its_edges():
    """The seed's array indices wrap (mod n), so the heightfield tiles: the
    step across the seam is no larger than steps inside the array."""
    n = 16
    h = scene.fractal_heights(n)
    assert all(v is not None for row in h for v in row)
    inner = max(abs(h[r][c + 1] - h[r][c]) for r in range(n) for c in range(n - 1))
    inner = max(inner, max(abs(h[r + 1][c] - h[r][c]) for r in range(n - 1) for c in range(n)))
    seam = max(max(abs(h[r][0] - h[r][n - 1]) for r in range(n)),
               max(abs(h[0][c] - h[n - 1][c]) for c in range(n)))
    assert seam <= inner
    assert max(max(r) for r in h) - min(min(r) for r in h) >= 8   # it is not flat


def test_generated_c_is_up_to_date():
    for n in scene.BUILTIN_ORDER:
        with open(os.path.join(ROOT, "scenes", n + ".c"), encoding="utf-8") as f:
            committed = f.read()
        assert committed == scene.to_c_scene(scene.builtin(n)), \
            f"scenes/{n}.c is stale: run `make scenes`"


def test_normals_match_the_c_library():
    """The converter's face normals are the C r8_mesh_normals ones, bit
    for bit (a mesh built at run time shades like a generated one)."""
    import subprocess
    tool = os.path.join(ROOT, "build", "r8probe")
    for n in ("cube", "torus", "teapot", "terrain", "separate"):
        sc = scene.builtin(n)
        out = subprocess.run([tool, "--scene", n, "--normals"], capture_output=True,
                             text=True, check=True).stdout.split("\n")
        got = [tuple(int(v) for v in line.split()[2:]) for line in out if line]
        want = [nv for o in sc.objects for nv in scene.c_normals(sc.meshes[o.mesh])]
        assert got == want


def test_blob_layout():
    sc = scene.parse_r8s(GOOD, "tiny.r8s")
    b = scene.to_blob(sc)
    assert b[:4] == b"R8SC"
    ver, nmesh, nobj, _ = struct.unpack_from("<BBBB", b, 4)
    assert (ver, nmesh, nobj) == (1, 1, 1)
    focal, near, amb = struct.unpack_from("<hhh", b, 8)
    assert (focal, near, amb) == (40, 8, 8192)
    nv, nf, convex, radius = struct.unpack_from("<BHBh", b, 20)
    assert (nv, nf, convex) == (3, 1, 0) and radius == 15
    assert len(b) == 20 + 6 + 3 * 6 + 1 * 6 + 13
