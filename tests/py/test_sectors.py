"""Worlds of sectors and portals (.r8s extension, rast8/sectors.py): the
built-in rooms world, its camera walk, the checks on bad worlds (one line
naming file and line, exit status 1), and the generated C."""
import os
import subprocess
import sys

import pytest

from rast8 import scene, sectors

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
ROOMS = os.path.join(ROOT, "host", "rast8", "scenes", "rooms.r8s")

# two box cells side by side (x 0..100 and 100..200), a portal between
TWO = """scene two
world w
v 0 0 0
v 0 -50 0
v 100 -50 0
v 100 0 0
v 0 0 100
v 0 -50 100
v 100 -50 100
v 100 0 100
v 200 0 0
v 200 -50 0
v 200 -50 100
v 200 0 100
sector a
f 5 0 4 7 3
f 9 1 2 6 5
f 12 0 1 5 4
f 12 3 2 1 0
f 12 4 5 6 7
p b 7 6 2 3
sector b
f 5 3 7 11 8
f 9 2 9 10 6
f 12 11 10 9 8
f 12 8 9 2 3
f 12 6 10 11 7
p a 3 2 6 7
end
path 45 -25 50 64
path 150 -25 50 64
"""


def test_two_cells_parse():
    sc = scene.parse_r8s(TWO, "two.r8s")
    w = sc.world
    assert [s.name for s in w.sectors] == ["a", "b"]
    assert sc.objects[0].mesh == "w" and sc.objects[0].pos == (0, 0, 0)
    walls, portals = w.faces()
    assert len(walls) == 10 and len(portals) == 2
    rows, targets = w.table()
    assert rows == [(0, 10, 5, 1), (5, 11, 5, 1)] and targets == [1, 0]
    # the mesh the other methods draw: walls first, then portals
    assert sc.meshes["w"].faces[:10] == walls
    frames = sectors.frames(w)
    assert len(frames) == 2 * sectors.PATH_STEPS
    assert {sectors.locate(w, f[:3])[0] for f in frames} == {0, 1}


@pytest.mark.parametrize("edit,msg", [
    (("p b 7 6 2 3", "p a 7 6 2 3"), "to itself"),
    (("p a 3 2 6 7", "p c 3 2 6 7"), "unknown sector 'c'"),
    (("p a 3 2 6 7", "f 12 3 2 6 7"), "has no twin"),
    (("f 5 0 4 7 3", "f 5 3 7 4 0"), "not convex"),
    (("v 200 0 100", "v 200 0 140"), "not planar"),
    (("path 150 -25 50 64", "path 150 -100 50 64"), "outside every sector"),
    (("path 150 -25 50 64", "path 100 -25 50 64"), "within 1 unit"),
    (("end\n", ""), "not closed"),
    (("sector b\n", "sector a\n"), "defined twice"),
])
def test_bad_worlds_name_the_line(edit, msg):
    text = TWO.replace(*edit)
    with pytest.raises(scene.SceneError) as e:
        scene.parse_r8s(text, "bad.r8s")
    assert msg in str(e.value) and str(e.value).startswith("bad.r8s:")


def test_rooms_world():
    sc = scene.builtin("rooms")
    w = sc.world
    assert len(w.sectors) == 9
    walls, portals = w.faces()
    assert len(portals) == 2 * 10          # ten doors, a portal each way
    assert len(w.verts) <= 255
    # the walk passes through every sector and back
    seen = [sectors.locate(w, f[:3])[0] for f in sectors.frames(w)]
    assert set(seen) == set(range(9))
    assert len(seen) == 48 * sectors.PATH_STEPS


MOVER = """mesh cube
v -5 -5 -5
v 5 -5 -5
v 5 5 -5
v -5 5 -5
v -5 -5 5
v 5 -5 5
v 5 5 5
v -5 5 5
f 16 0 1 2 3
f 16 5 4 7 6
f 16 1 5 6 2
f 16 4 0 3 7
f 16 4 5 1 0
f 16 3 2 6 7
end
object cube at 40 -10 50
move 0 40 -10 50
move 0 160 -10 50
"""


def test_moving_object_crosses_sectors(tmp_path):
    sc = scene.parse_r8s(TWO + MOVER, "two.r8s")
    w = sc.world
    assert w.moves == {0: [(40, -10, 50), (160, -10, 50)]}
    fr = sectors.move_frames(w.moves[0])
    assert len(fr) == 2 * sectors.PATH_STEPS and fr[1] == (47, -10, 50)
    assert {sectors.locate(w, f)[0] for f in fr} == {0, 1}
    out = tmp_path / "two.c"
    scene.to_c([sc], str(out))
    c = out.read_text()
    assert "static const r8_s16 two_moves[8] R8_FLASH = {\n    1, 2,\n    40, -10, 50,\n    160, -10, 50," in c
    assert "R8_DEMO_WORLDM(&two_world, two_path, 2, two_moves, 1)};" in c


@pytest.mark.parametrize("edit,msg", [
    (("move 0 160 -10 50", "move 0 260 -10 50"), "outside every sector"),
    (("move 0 160 -10 50", "move 1 160 -10 50"), "'move 1': the scene has 1 objects"),
    (("move 0 160 -10 50", "move 0 160 -10"), "usage: move N X Y Z"),
    (("move 0 160 -10 50", "move -1 160 -10 50"), "out of range"),
])
def test_bad_moves_name_the_line(edit, msg):
    with pytest.raises(scene.SceneError) as e:
        scene.parse_r8s(TWO + MOVER.replace(*edit), "bad.r8s")
    assert msg in str(e.value) and str(e.value).startswith("bad.r8s:")


def test_move_without_world():
    with pytest.raises(scene.SceneError) as e:
        scene.parse_r8s("scene s\n" + MOVER, "bad.r8s")
    assert "'move' without a world" in str(e.value)


def test_rooms_objects_move_between_rooms():
    w = scene.builtin("rooms").world
    assert sorted(w.moves) == [0, 2]
    names = [w.sectors[k].name for k in range(len(w.sectors))]
    for n, rooms in ((0, {"r00", "r10"}), (2, {"r01", "r02"})):
        assert {names[sectors.locate(w, f)[0]] for f in sectors.move_frames(w.moves[n])} == rooms


def test_rooms_file_is_the_generator_output():
    with open(ROOMS, encoding="utf-8") as f:
        assert f.read() == sectors.rooms()


def test_rooms_c_has_the_world_and_the_walls_mesh(tmp_path):
    out = tmp_path / "rooms.c"
    scene.to_c([scene.builtin("rooms")], str(out))
    c = out.read_text()
    walls, portals = scene.builtin("rooms").world.faces()
    assert "static const r8_world rooms_world = {&rooms_rooms, rooms_sectors, rooms_target, %d, 9};" \
        % len(walls) in c
    assert "rooms_rooms_walls = {rooms_rooms_v, rooms_rooms_f, rooms_rooms_n, 200, %d," % len(walls) in c
    assert "R8_DEMO_WORLDM(&rooms_world, rooms_path, 48, rooms_moves, 2)};" in c
    # the moving objects' table: demo object index, point count, points
    assert "static const r8_s16 rooms_moves[22] R8_FLASH = {\n    1, 2,\n    48, 34, -30," in c
    # the generated scenes/rooms.c is up to date
    with open(os.path.join(ROOT, "scenes", "rooms.c"), encoding="utf-8") as f:
        assert f.read() == c


def test_cli_check_and_bad_file(tmp_path):
    rast8 = [sys.executable, "-m", "rast8"]
    r = subprocess.run(rast8 + ["scene", "check", ROOMS], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert "world rooms: 9 sectors" in r.stdout and "(768 frames)" in r.stdout
    bad = tmp_path / "bad.r8s"
    bad.write_text(TWO.replace("p a 3 2 6 7", "f 12 3 2 6 7"))
    r = subprocess.run(rast8 + ["scene", "check", str(bad)], capture_output=True, text=True)
    assert r.returncode == 1
    assert "Traceback" not in r.stderr and len(r.stderr.strip().splitlines()) == 1
    assert "has no twin" in r.stderr


@pytest.mark.skipif(not __import__("shutil").which("xvfb-run"), reason="needs Xvfb")
def test_rooms_walk_live_in_the_viewer(emu, tmp_path):
    """The portal walk-through live: the emulator renders the rooms with
    the portal renderer on a paced pty, rast8 view shows it; its last
    frame on screen is the emulator's."""
    from PIL import Image, ImageChops
    from rast8.protocol import read_dump
    dump = tmp_path / "ref.r8fb"
    p = subprocess.Popen([emu, "--scene", "rooms", "--method", "portal", "--pty", "--frames", "40",
                          "--baud", "1000000", "--dump", str(dump), "--linger", "10"],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    path = p.stdout.readline().strip()
    shot = tmp_path / "live.png"
    r = subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 800x600x24",
                        sys.executable, "-m", "rast8.cli", "view", path, "--frames", "40",
                        "--scale", "2", "--screenshot", str(shot)],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    assert p.wait(timeout=30) == 0
    frames = read_dump(str(dump))
    assert len(frames) == 40
    # the camera moves: the walk's frames differ
    assert frames[0].pixels != frames[-1].pixels
    want = frames[-1].to_image(2).convert("RGB")
    assert ImageChops.difference(Image.open(shot).convert("RGB"), want).getbbox() is None
    assert "errors 0" in r.stdout
