"""rast8 sectors: worlds of convex sectors joined by portals, for the
portal renderer (R8_VIS_PORTAL).  The `.r8s` extension (docs/scene-format.md):

    world NAME              # a block in a scene file, closed by 'end'
    v X Y Z                 # shared vertices (at most 255, |coord| <= 16383)
    sector NAME             # the faces that follow belong to this sector
    f COLOUR I J K [L]      # a wall, clockwise seen from INSIDE the sector
    p SECTOR I J K [L]      # a portal into SECTOR, clockwise seen from inside
    end
    path X Y Z YAW          # camera waypoints (top level, in order; 16 frames each)
    move N X Y Z            # waypoints of the scene's object N (0: the first
                            # 'object' line), 16 frames each, the last back to
                            # the first: a movable object of the world

Every sector must be convex (all its vertices on or in front of all its
faces) and every portal A->B needs its twin B->A on the same vertices.
The converter emits the world mesh (walls first, then portals), the same
walls as an ordinary mesh (so every other method draws the same scene: the
scene's first object), the sector table, the camera path and the objects'
paths.

    python -m rast8.sectors rooms          # print the built-in rooms world
    python -m rast8.sectors path FILE.r8s  # the camera's sector per frame
"""
from __future__ import annotations

import sys
from dataclasses import dataclass, field

PATH_STEPS = 16     # frames per path segment (scenes/demo.c R8_PATH_STEPS)


class WorldError(Exception):
    def __init__(self, path, line, msg):
        super().__init__(f"{path}:{line}: {msg}")
        self.path, self.line, self.msg = path, line, msg


@dataclass
class Sector:
    name: str
    walls: list = field(default_factory=list)     # [(colour, [i...])]
    portals: list = field(default_factory=list)   # [(target name, [i...], line)]


@dataclass
class World:
    name: str
    verts: list = field(default_factory=list)
    sectors: list = field(default_factory=list)
    path: list = field(default_factory=list)      # [(x, y, z, yaw)]
    moves: dict = field(default_factory=dict)     # {object: [(x, y, z)]}

    def index(self, name):
        for k, s in enumerate(self.sectors):
            if s.name == name:
                return k
        return -1

    def faces(self):
        """Mesh faces: every wall (sector order), then every portal."""
        walls = [(c, idx) for s in self.sectors for c, idx in s.walls]
        portals = [(0, idx) for s in self.sectors for _, idx, _ in s.portals]
        return walls, portals

    def table(self):
        """[(wall0, portal0, nwalls, nportals)], targets (per portal face)."""
        nw = sum(len(s.walls) for s in self.sectors)
        w0, p0, rows, targets = 0, nw, [], []
        for s in self.sectors:
            rows.append((w0, p0, len(s.walls), len(s.portals)))
            w0 += len(s.walls)
            p0 += len(s.portals)
            targets += [self.index(t) for t, _, _ in s.portals]
        return rows, targets


def _ints(toks, path, ln, lo, hi, what):
    out = []
    for t in toks:
        try:
            v = int(t, 0)
        except ValueError:
            raise WorldError(path, ln, f"{what} '{t}' is not an integer") from None
        if not lo <= v <= hi:
            raise WorldError(path, ln, f"{what} {v} out of range {lo}..{hi}")
        out.append(v)
    return out


def _normal(vs, idx):
    a, b, c = (vs[i] for i in idx[:3])
    e1 = [b[j] - a[j] for j in range(3)]
    e2 = [c[j] - a[j] for j in range(3)]
    # the renderer's orientation (scene.c_normals): (v2 - v0) x (v1 - v0)
    return (e2[1] * e1[2] - e2[2] * e1[1], e2[2] * e1[0] - e2[0] * e1[2],
            e2[0] * e1[1] - e2[1] * e1[0])


def _dot(n, a, b):
    return sum(n[j] * (a[j] - b[j]) for j in range(3))


def check(w, path="<world>", line=0):
    """Convex sectors, planar faces, paired portals, sizes."""
    if not w.sectors:
        raise WorldError(path, line, f"world '{w.name}' has no sectors")
    if len(w.sectors) > 254:
        raise WorldError(path, line, "at most 254 sectors")
    pairs = {}
    for k, s in enumerate(w.sectors):
        if len(s.walls) > 255 or len(s.portals) > 255:
            raise WorldError(path, line, f"sector '{s.name}': at most 255 walls and 255 portals")
        faces = [idx for _, idx in s.walls] + [idx for _, idx, _ in s.portals]
        if not faces:
            raise WorldError(path, line, f"sector '{s.name}' has no faces")
        used = sorted({i for idx in faces for i in idx})
        for idx in faces:
            n = _normal(w.verts, idx)
            if n == (0, 0, 0):
                raise WorldError(path, line, f"sector '{s.name}': degenerate face {idx}")
            for i in idx[3:]:
                if _dot(n, w.verts[i], w.verts[idx[0]]) != 0:
                    raise WorldError(path, line, f"sector '{s.name}': face {idx} is not planar")
            for i in used:
                if _dot(n, w.verts[i], w.verts[idx[0]]) < 0:
                    raise WorldError(path, line, f"sector '{s.name}' is not convex (or face {idx} "
                                     "faces outwards): vertex " + str(i) + " lies behind it")
        for t, idx, ln in s.portals:
            j = w.index(t)
            if j < 0:
                raise WorldError(path, ln, f"portal to unknown sector '{t}'")
            if j == k:
                raise WorldError(path, ln, f"portal from sector '{t}' to itself")
            pairs[(k, j, frozenset(idx))] = ln
    for (k, j, vs), ln in pairs.items():
        if (j, k, vs) not in pairs:
            raise WorldError(path, ln, f"portal {w.sectors[k].name} -> {w.sectors[j].name} "
                             "has no twin on the same vertices")
    walls, portals = w.faces()
    if not walls:
        raise WorldError(path, line, "world has no walls")
    if len(walls) + len(portals) > 4000:
        raise WorldError(path, line, "at most 4000 faces")


def parse_block(lines, path):
    """lines: [(line number, tokens)] from 'world NAME' to 'end'."""
    ln0, t0 = lines[0]
    if len(t0) != 2:
        raise WorldError(path, ln0, "usage: world NAME")
    w = World(t0[1])
    cur = None
    for ln, t in lines[1:]:
        kw = t[0]
        if kw == "v":
            if len(t) != 4:
                raise WorldError(path, ln, "usage: v X Y Z")
            w.verts.append(tuple(_ints(t[1:], path, ln, -16383, 16383, "coordinate")))
            if len(w.verts) > 255:
                raise WorldError(path, ln, "a world has at most 255 vertices")
        elif kw == "sector":
            if len(t) != 2:
                raise WorldError(path, ln, "usage: sector NAME")
            if w.index(t[1]) >= 0:
                raise WorldError(path, ln, f"sector '{t[1]}' defined twice")
            cur = Sector(t[1])
            w.sectors.append(cur)
        elif kw in ("f", "p"):
            if cur is None:
                raise WorldError(path, ln, f"'{kw}' before 'sector NAME'")
            if len(t) not in (5, 6):
                raise WorldError(path, ln, f"usage: {kw} {'COLOUR' if kw == 'f' else 'SECTOR'} I J K [L]")
            idx = _ints(t[2:], path, ln, 0, max(0, len(w.verts) - 1), "vertex index")
            if not w.verts:
                raise WorldError(path, ln, "face before any 'v'")
            if len(set(idx)) != len(idx):
                raise WorldError(path, ln, "face repeats a vertex")
            if kw == "f":
                cur.walls.append((_ints(t[1:2], path, ln, 0, 16, "colour")[0], idx))
            else:
                cur.portals.append((t[1], idx, ln))
        else:
            raise WorldError(path, ln, f"unknown keyword '{kw}' in world '{w.name}'")
    return w


def extract(text, path="<scene>"):
    """Take the world block and path lines out of a scene's text (they
    become blank lines, so line numbers stay).  Returns (text, world or
    None); raises WorldError."""
    out, block, world, path_pts, move_pts = [], None, None, [], []
    for ln, raw in enumerate(text.splitlines(), 1):
        t = raw.split("#", 1)[0].split()
        if block is not None:
            out.append("")
            if t and t[0] == "end":
                if world is not None:
                    raise WorldError(path, ln, "a scene has at most one world")
                world = parse_block(block, path)
                check(world, path, block[0][0])
                block = None
            elif t:
                block.append((ln, t))
            continue
        if t and t[0] == "world":
            block = [(ln, t)]
            out.append("")
        elif t and t[0] == "path":
            if len(t) != 5:
                raise WorldError(path, ln, "usage: path X Y Z YAW")
            path_pts.append((tuple(_ints(t[1:4], path, ln, -16383, 16383, "coordinate")) +
                             tuple(_ints(t[4:], path, ln, 0, 255, "yaw")), ln))
            out.append("")
        elif t and t[0] == "move":
            if len(t) != 5:
                raise WorldError(path, ln, "usage: move N X Y Z")
            n = _ints(t[1:2], path, ln, 0, 254, "object")[0]
            move_pts.append((n, tuple(_ints(t[2:5], path, ln, -16383, 16383, "coordinate")), ln))
            out.append("")
        else:
            out.append(raw)
    if block is not None:
        raise WorldError(path, block[0][0], "world not closed with 'end'")
    if path_pts and world is None:
        raise WorldError(path, path_pts[0][1], "'path' without a world")
    if move_pts and world is None:
        raise WorldError(path, move_pts[0][2], "'move' without a world")
    if world is not None:
        world.path = [p for p, _ in path_pts]
        if len(world.path) > 255:
            raise WorldError(path, path_pts[255][1], "at most 255 path points")
        for k, f in enumerate(frames(world)):
            s, d = locate(world, f[:3])
            if d < 0:
                raise WorldError(path, path_pts[0][1], f"camera path frame {k} at {f[:3]} is outside every sector")
            if d < 1 << 14:
                raise WorldError(path, path_pts[0][1], f"camera path frame {k} at {f[:3]} is within 1 unit "
                                 f"of a face of sector '{world.sectors[s].name}'")
        for n, p, ln in move_pts:
            world.moves.setdefault(n, []).append(p)
            if len(world.moves[n]) > 255:
                raise WorldError(path, ln, "at most 255 points per object path")
        for n, pts in world.moves.items():
            for k, f in enumerate(move_frames(pts)):
                if locate(world, f)[1] < 0:
                    ln = [m[2] for m in move_pts if m[0] == n][0]
                    raise WorldError(path, ln, f"object {n}'s path frame {k} at {f} is outside every sector")
    return "\n".join(out), world


def move_frames(pts):
    """An object's position (x, y, z) in every frame of its path's loop,
    as scenes/demo.c moves it (as the camera: PATH_STEPS frames a point)."""
    out, n = [], len(pts)
    for k in range(n):
        a, b = pts[k], pts[(k + 1) % n]
        for t in range(PATH_STEPS if n > 1 else 1):
            out.append(tuple(a[j] + (((b[j] - a[j]) * t) >> 4) for j in range(3)))
    return out


def frames(w):
    """Camera (x, y, z, yaw) of every frame of the path, as scenes/demo.c
    moves it: PATH_STEPS frames from each point to the next, the last back
    to the first."""
    out, n = [], len(w.path)
    for k in range(n if n > 1 else 0):
        a, b = w.path[k], w.path[(k + 1) % n]
        dy = ((b[3] - a[3] + 128) & 255) - 128
        for t in range(PATH_STEPS):
            out.append(tuple(a[j] + (((b[j] - a[j]) * t) >> 4) for j in range(3)) +
                       ((a[3] + ((dy * t) >> 4)) & 255,))
    return out


def _unit(n):
    """The renderer's Q1.14 unit normal (scene._normalize)."""
    from .scene import _normalize
    return _normalize(n)


def locate(w, p):
    """(sector, depth) as r8_portal_locate: the sector p lies deepest in;
    depth = smallest Q1.14 distance to its face planes."""
    best, bs = None, 0
    for k, s in enumerate(w.sectors):
        worst = None
        for idx in [idx for _, idx in s.walls] + [idx for _, idx, _ in s.portals]:
            n = _unit(_normal(w.verts, idx))
            d = _dot(n, p, w.verts[idx[0]])
            worst = d if worst is None or d < worst else worst
        if best is None or worst > best:
            best, bs = worst, k
    return bs, best


def to_mesh(w):
    """The world as a scene.Mesh: walls, then portals."""
    from .scene import Mesh
    walls, portals = w.faces()
    return Mesh(w.name, list(w.verts), walls + portals, False)


def c_world(w, sid, mid):
    """C for the world, after its mesh `mid` (walls + portals) is written:
    the walls-only mesh (returned as the id objects use), the sector table,
    the portal targets, the r8_world and the path."""
    walls, portals = w.faces()
    rows, targets = w.table()
    m = to_mesh(w)
    out = [f"static const r8_mesh {mid}_walls = {{{mid}_v, {mid}_f, {mid}_n, {len(w.verts)}, "
           f"{len(walls)}, 0, {m.radius()}, 0 R8_MESH_TEX(0, 0)}};",
           f"static const r8_sector {sid}_sectors[{len(rows)}] R8_FLASH = {{"]
    out += [f"    {{{a}, {b}, {c}, {d}}}," for a, b, c, d in rows]
    out.append("};")
    out.append(f"static const r8_u8 {sid}_target[{max(1, len(targets))}] R8_FLASH = {{")
    for k in range(0, len(targets), 16):
        out.append("    " + ", ".join(str(t) for t in targets[k:k + 16]) + ",")
    if not targets:
        out.append("    255")
    out.append("};")
    out.append(f"static const r8_world {sid}_world = {{&{mid}, {sid}_sectors, {sid}_target, "
               f"{len(walls)}, {len(rows)}}};")
    out.append(f"static const r8_s16 {sid}_path[{max(1, 4 * len(w.path))}] R8_FLASH = {{")
    for p in w.path:
        out.append(f"    {p[0]}, {p[1]}, {p[2]}, {p[3]},")
    if not w.path:
        out.append("    0")
    out.append("};")
    if w.moves:
        # per moving object: its index in the demo's objects (the walls are
        # object 0), its point count, then x, y, z per point
        tab = []
        for n in sorted(w.moves):
            tab.append(f"    {n + 1}, {len(w.moves[n])},")
            tab += [f"    {x}, {y}, {z}," for x, y, z in w.moves[n]]
        size = sum(2 + 3 * len(p) for p in w.moves.values())
        out.append(f"static const r8_s16 {sid}_moves[{size}] R8_FLASH = {{")
        out += tab
        out.append("};")
    return out, f"{mid}_walls"


# ---- the built-in indoor world ---------------------------------------------

def _movables():
    """The rooms' movable objects (.r8s lines): a box that goes to and
    fro through the door between the first two rooms, a spinning gem in
    the middle room, and a smaller box through the door from r01 to r02.
    All float 4 units above the floor (no depth ties with it)."""
    from .scene import box, Mesh, _orient_outward
    out = []
    b = box("box", 10, 10, 10, 16)
    g = Mesh("gem")
    g.verts = [(0, -14, 0), (14, 0, 0), (0, 0, 14), (-14, 0, 0), (0, 0, -14), (0, 14, 0)]
    g.faces = [(14, [0, a, c]) for a, c in ((1, 2), (2, 3), (3, 4), (4, 1))] + \
              [(12, [5, a, c]) for a, c in ((1, 2), (2, 3), (3, 4), (4, 1))]
    _orient_outward(g)
    for m in (b, g):
        out.append(f"mesh {m.name}")
        out += [f"v {x} {y} {z}" for x, y, z in m.verts]
        out += [f"f {c} " + " ".join(map(str, idx)) for c, idx in m.faces]
        out.append("end")
    y = FLOOR - 14
    out.append(f"object box at 48 {y} -30 spin 0 2 0")
    out.append(f"object gem at 224 10 380 spin 0 3 0")
    out.append(f"object box at -28 {y} 360")
    out.append(f"move 0 48 {y} -30")
    out.append(f"move 0 208 {y} -30")
    out += [f"move 2 -28 {y} {z}" for z in (360, 440, 540, 440)]
    return out


COLS = [256, 192, 320]      # room widths (x), west to east
ROWS = [256, 320, 192]      # room depths (z), south to north
DOOR = 96                   # door width (full height)
FLOOR, CEIL = 48, -80       # y is down: the eye (y = 0) is 48 above the floor
SNAKE = [(0, 0), (1, 0), (2, 0), (2, 1), (1, 1), (0, 1), (0, 2), (1, 2), (2, 2)]
EXTRA = [((0, 0), (0, 1)), ((1, 1), (1, 2))]    # two more doors: loops


def rooms():
    """A 3 x 3 grid of box rooms, doors between them (a snake through all
    nine and two loops), as .r8s text.  Each room is split on the door
    lines (3 x 3 floor and ceiling quads, 3 quads per side) so faces meet
    at shared vertices only (no T-junctions: no pixel cracks)."""
    xs = [-COLS[0] // 2]
    for wd in COLS:
        xs.append(xs[-1] + wd)
    zs = [-ROWS[0] // 2]
    for dp in ROWS:
        zs.append(zs[-1] + dp)
    doors = {tuple(sorted(p)) for p in zip(SNAKE, SNAKE[1:])} | {tuple(sorted(p)) for p in EXTRA}
    verts, vid = [], {}

    def v(x, y, z):
        if (x, y, z) not in vid:
            vid[(x, y, z)] = len(verts)
            verts.append((x, y, z))
        return vid[(x, y, z)]

    lines = ["world rooms"]
    body = []
    for r in range(3):
        for c in range(3):
            x0, x1, z0, z1 = xs[c], xs[c + 1], zs[r], zs[r + 1]
            gx = [x0, (x0 + x1) // 2 - DOOR // 2, (x0 + x1) // 2 + DOOR // 2, x1]
            gz = [z0, (z0 + z1) // 2 - DOOR // 2, (z0 + z1) // 2 + DOOR // 2, z1]
            body.append(f"sector r{c}{r}")
            wc = 10 + (3 * c + r) % 6          # wall colour per room
            # floor (seen from above: y down, so clockwise on screen looking down)
            for i in range(3):
                for k in range(3):
                    a, b = gx[i], gx[i + 1]
                    p, q = gz[k], gz[k + 1]
                    body.append(f"f 5 {v(a, FLOOR, p)} {v(a, FLOOR, q)} {v(b, FLOOR, q)} {v(b, FLOOR, p)}")
                    body.append(f"f 9 {v(a, CEIL, p)} {v(b, CEIL, p)} {v(b, CEIL, q)} {v(a, CEIL, q)}")
            # sides: (fixed coordinate, along, neighbour, orientation)
            for side in range(4):
                for i in range(3):
                    if side == 0:      # south wall z = z0, seen looking -z
                        a, b = (gx[i], z0), (gx[i + 1], z0)
                        nb = (c, r - 1)
                    elif side == 1:    # north wall z = z1
                        a, b = (gx[i + 1], z1), (gx[i], z1)
                        nb = (c, r + 1)
                    elif side == 2:    # west wall x = x0
                        a, b = (x0, gz[i + 1]), (x0, gz[i])
                        nb = (c - 1, r)
                    else:              # east wall x = x1
                        a, b = (x1, gz[i]), (x1, gz[i + 1])
                        nb = (c + 1, r)
                    quad = [v(b[0], FLOOR, b[1]), v(b[0], CEIL, b[1]), v(a[0], CEIL, a[1]), v(a[0], FLOOR, a[1])]
                    if i == 1 and tuple(sorted([(c, r), nb])) in doors:
                        body.append(f"p r{nb[0]}{nb[1]} " + " ".join(map(str, quad)))
                    else:
                        body.append(f"f {wc if side < 2 else wc - 3} " + " ".join(map(str, quad)))
    lines += [f"v {x} {y} {z}" for x, y, z in verts] + body + ["end"]
    # the walk: through every room along the snake and back, straight
    # through each door; points 37 before and 43 after a door so no frame
    # stands in a door's plane
    pts = []

    def centre(c, r):
        return ((xs[c] + xs[c + 1]) // 2 + 3, 0, (zs[r] + zs[r + 1]) // 2 + 5)

    def yaw_of(dx, dz):
        return {(1, 0): 64, (-1, 0): 192, (0, 1): 0, (0, -1): 128}[(dx, dz)]

    route = SNAKE + SNAKE[-2::-1]
    for k, (c, r) in enumerate(route[:-1]):
        nc, nr = route[k + 1]
        dx, dz = nc - c, nr - r
        yaw = yaw_of(dx, dz)
        cx, _, cz = centre(c, r)
        pts.append((cx, 0, cz, yaw))
        if dx:
            xd = xs[max(c, nc)]
            zd = (zs[r] + zs[r + 1]) // 2 + 5
            pts.append((xd - 37 * dx, 0, zd, yaw))
            pts.append((xd + 43 * dx, 0, zd, yaw))
        else:
            zd = zs[max(r, nr)]
            xd = (xs[c] + xs[c + 1]) // 2 + 3
            pts.append((xd, 0, zd - 37 * dz, yaw))
            pts.append((xd, 0, zd + 43 * dz, yaw))
    text = "\n".join(lines) + "\n" + "\n".join(_movables())
    head = ("# rooms: nine box rooms in a 3 x 3 grid joined by doors (generated by\n"
            "# `python -m rast8.sectors rooms`): the portal renderer's scene\n"
            "scene rooms\ncamera focal 40 near 8\nlight -0.3 -1.0 -0.5 ambient 0.35\n")
    return head + text + "\n" + "\n".join(f"path {x} {y} {z} {yw}" for x, y, z, yw in pts) + "\n"


def main(argv=None):
    argv = list(sys.argv[1:] if argv is None else argv)
    if not argv or argv[0] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if argv else 2
    if argv[0] == "rooms" and len(argv) == 1:
        sys.stdout.write(rooms())
        return 0
    if argv[0] == "path" and len(argv) == 2:
        from .scene import load_r8s, SceneError
        try:
            sc = load_r8s(argv[1])
        except (SceneError, OSError) as e:
            print(f"rast8 sectors: {e}", file=sys.stderr)
            return 1
        if sc.world is None:
            print(f"rast8 sectors: {argv[1]}: no world", file=sys.stderr)
            return 1
        for k, f in enumerate(frames(sc.world)):
            s, d = locate(sc.world, f[:3])
            print(k, *f, sc.world.sectors[s].name)
        return 0
    print(__doc__.strip(), file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main())
