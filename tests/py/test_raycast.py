"""The ray caster (issue 14): the float reference (rast8.raycast_ref) on
hand-computed cases, the integer columns (build/r8raycols) against it per
column, the textured maze's pixels against its texels, and the mazes
through rast8-emu and the decoder."""
import json
import math
import os
import subprocess
import sys

import pytest

from rast8 import raycast_ref as RR

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
TOOL = os.path.join(ROOT, "build", "r8raycols")
EMU = os.path.join(ROOT, "build", "rast8-emu")


def _need(path):
    if not os.path.exists(path):
        subprocess.run(["make", "-C", ROOT, "-s", os.path.relpath(path, ROOT)], check=True)
    return path


ROOM = [[1, 1, 1, 1], [1, 0, 0, 1], [1, 0, 0, 1], [1, 1, 1, 1]]


def test_reference_straight_wall_has_no_fisheye():
    # camera at (64, 40) in a 4x4 room of 32-unit cells looking +z: the far
    # wall at z = 96 for every column that sees it: depth 56
    for col in range(0, 64, 7):
        h, cx, cz, side, v = RR.cast(ROOM, 4, 4, 5, 64, 40, 0, 64, 64, col)
        if cz == 3 and side == 1:
            assert h == pytest.approx(64 * 32 / 56.0)
    h, cx, cz, side, v = RR.cast(ROOM, 4, 4, 5, 64, 40, 0, 64, 64, 32)
    assert (cz, side, v) == (3, 1, 1)


def test_reference_side_and_off_map():
    # looking -x (yaw 192) from x = 50: the wall face at x = 32, depth 18
    h, cx, cz, side, v = RR.cast(ROOM, 4, 4, 5, 50, 48, 192, 64, 64, 32)
    assert (cx, side) == (0, 0)
    assert h == pytest.approx(64 * 32 / 18.0, rel=1e-3)
    assert RR.cast(ROOM, 4, 4, 5, -1, 48, 0, 64, 64, 3)[0] == 0.0
    assert RR.cast(ROOM, 4, 4, 5, 200, 48, 0, 64, 64, 3)[4] == 0


def test_reference_u_reads_left_to_right_from_outside():
    # the far wall (z = 96) seen from inside the room looking +z: u grows
    # with the column and is the hit x's place in its 32-unit cell
    last = -1.0
    for col in range(20, 44):
        h, cx, cz, side, v, u = RR.cast_u(ROOM, 4, 4, 5, 64, 40, 0, 64, 64, col)
        assert (cz, side) == (3, 1)
        xh = 64 + (col + 0.5 - 32) * 56 / 64.0
        assert u == pytest.approx(xh / 32 - math.floor(xh / 32))
        if cx == 2:
            assert u > last
            last = u
    # looking -z at the near wall (z = 32): screen right is -x, u = 1 - f
    h, cx, cz, side, v, u = RR.cast_u(ROOM, 4, 4, 5, 40, 48, 128, 64, 64, 40)
    xh = 40 - (40 + 0.5 - 32) * 16 / 64.0
    assert (cz, side) == (0, 1) and u == pytest.approx(1 - (xh / 32 - math.floor(xh / 32)))
    # an x face (looking +x at x = 96): screen right is -z
    h, cx, cz, side, v, u = RR.cast_u(ROOM, 4, 4, 5, 50, 48, 64, 64, 64, 40)
    zh = 48 - (40 + 0.5 - 32) * 46 / 64.0
    assert (cx, side) == (3, 0) and u == pytest.approx(1 - (zh / 32 - math.floor(zh / 32)))


def test_textured_frames_match_the_float_texels():
    """The textured maze over 200 cameras: the C frame's wall pixels
    against the float caster's texel at each pixel centre (times the
    column's level).  Texel boundaries may fall on the other side of a
    pixel centre (u to 1/256 of a face, v's step from an 8-bit
    reciprocal), so a few pixels per frame differ; a mirrored u (the
    control) is wrong on about a quarter of them."""
    res = RR.run(_need(TOOL), 200, scene="tmaze")
    t = res["tex"]
    assert t["frames"] == 200 and t["wall_pixels"] > 200 * 4000, t
    assert t["wrong_rate"] <= 0.01, t
    assert t["wrong_mean"] <= 60 and t["wrong_max"] <= 300, t
    assert t["level_mean"] <= 0.1, t
    head = subprocess.run([TOOL, "--scene", "tmaze"], input="".join(
        "%d %d %d %d %d\n" % p for p in RR.poses(RR.read_tool(subprocess.run(
            [TOOL, "--scene", "tmaze"], input="", stdout=subprocess.PIPE, text=True,
            check=True).stdout)[0], 30)), stdout=subprocess.PIPE, text=True, check=True)
    grid, frames = RR.read_tool(head.stdout)
    bad = RR.compare_tex(grid, frames, flip=True)
    assert bad["wrong_rate"] > 0.1, bad
    # the untextured maze has no texture figures
    assert "tex" not in RR.run(TOOL, 3)


def test_integer_columns_match_the_float_caster():
    res = RR.run(_need(TOOL), 150)
    assert res["columns"] == 150 * 128
    # heights within half a pixel and 2 %, and a grazing ray at a corner
    # may see the other face of the same corner: rarely
    assert res["max_px"] <= 0.6, res
    assert res["max_rel"] <= 0.02, res
    assert res["mean_px"] <= 0.1, res
    assert res["other_face"] <= res["columns"] // 500, res


def test_integer_columns_see_the_float_faces_exactly_in_straight_views():
    # axis-aligned views from cell centres: every column hits the face the
    # float caster hits
    _need(TOOL)
    cams = "".join("%d %d %d 128 128\n" % (96 + 64 * i, 96, yaw)
                   for i in (0, 4, 8) for yaw in (0, 64, 128, 192))
    r = subprocess.run([TOOL], input=cams, stdout=subprocess.PIPE, text=True, check=True)
    grid, frames = RR.read_tool(r.stdout)
    res = RR.compare(grid, frames)
    assert res["other_face"] == 0 and res["max_px"] <= 0.6, res


def test_cli_figures_and_bad_input(tmp_path):
    _need(TOOL)
    r = subprocess.run([sys.executable, "-m", "rast8.raycast_ref", "--poses", "5", "--json"],
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=ROOT)
    assert r.returncode == 0, r.stderr
    assert json.loads(r.stdout)["columns"] == 5 * 128
    r = subprocess.run([sys.executable, "-m", "rast8.raycast_ref", "--poses", "0"],
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=ROOT)
    assert r.returncode == 2 and "Traceback" not in r.stderr and r.stderr.count("\n") == 1
    r = subprocess.run([sys.executable, "-m", "rast8.raycast_ref", "--tool", str(tmp_path / "no")],
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=ROOT)
    assert r.returncode == 2 and "Traceback" not in r.stderr
    r = subprocess.run([TOOL, "--scene", "cube"], input="", stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, text=True)
    assert r.returncode == 2 and "not a grid scene" in r.stderr


def test_emu_tmaze_textured_differs_from_lambert(tmp_path):
    _need(EMU)
    outs = {}
    for sh in ("texture", "lambert"):
        out = tmp_path / ("t-%s.r8" % sh)
        r = subprocess.run([EMU, "--scene", "tmaze", "--shading", sh, "--frames", "4", "--out",
                            str(out)], stderr=subprocess.PIPE, text=True)
        assert r.returncode == 0, r.stderr
        outs[sh] = out.read_bytes()
    plain = tmp_path / "m.r8"
    subprocess.run([EMU, "--scene", "maze", "--frames", "4", "--out", str(plain)], check=True,
                   stderr=subprocess.DEVNULL)
    # Lambert ignores the textures: the maze's frames exactly
    assert outs["lambert"] == plain.read_bytes()
    assert outs["texture"] != outs["lambert"]
    rast8 = os.path.join(ROOT, ".venv", "bin", "rast8")
    st = subprocess.run([rast8, "stats", "--json", str(tmp_path / "t-texture.r8")],
                        stdout=subprocess.PIPE, text=True)
    st = json.loads(st.stdout)
    assert st["frames"] == 4 and not st["errors"] and not st["bad_packets"]


def test_emu_maze_streams_and_the_analyser_names_the_grid(tmp_path):
    _need(EMU)
    out = tmp_path / "maze.r8"
    r = subprocess.run([EMU, "--scene", "maze", "--frames", "8", "--out", str(out)],
                       stderr=subprocess.PIPE, text=True)
    assert r.returncode == 0, r.stderr
    rast8 = os.path.join(ROOT, ".venv", "bin", "rast8")
    st = subprocess.run([rast8, "stats", "--json", str(out)], stdout=subprocess.PIPE, text=True)
    st = json.loads(st.stdout)
    assert st["frames"] == 8 and not st["errors"] and not st["bad_packets"]
    r = subprocess.run([EMU, "--scene", "maze", "--method", "auto", "--frames", "1", "--out",
                        str(tmp_path / "a.r8")], stderr=subprocess.PIPE, text=True)
    assert r.returncode == 0 and "method ray (a grid map" in r.stderr, r.stderr
    # a mesh method on the grid scene: one clear line, exit 2
    r = subprocess.run([EMU, "--scene", "maze", "--method", "cull", "--frames", "1", "--out",
                        str(tmp_path / "b.r8")], stderr=subprocess.PIPE, text=True)
    assert r.returncode == 2 and "invalid configuration" in r.stderr
    # the ray caster on a mesh scene: the same
    r = subprocess.run([EMU, "--scene", "cube", "--method", "ray", "--frames", "1", "--out",
                        str(tmp_path / "c.r8")], stderr=subprocess.PIPE, text=True)
    assert r.returncode == 2 and "invalid configuration" in r.stderr
