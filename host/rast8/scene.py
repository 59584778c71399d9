"""rast8 scenes: the compact text scene format (.r8s), an OBJ subset, the
procedural built-in meshes, and the converter to C arrays or a binary blob
for firmware.  Format: docs/scene-format.md.

    python -m rast8.scene c OUTDIR [SCENE.r8s ...]  # one C file per scene (default: built-ins)
    python -m rast8.scene blob SCENE.r8s OUT.bin    # binary blob
    python -m rast8.scene check SCENE.r8s|MODEL.obj # parse and report
"""
from __future__ import annotations

import math
import os
import struct
import sys
from dataclasses import dataclass, field

from .concave import split_mesh
from . import sectors

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE_DIR = os.path.join(HERE, "scenes")
BUILTIN_ORDER = ["cube", "torus", "teapot", "terrain", "wall", "cross", "separate", "crate", "rooms"]


class SceneError(Exception):
    """A bad scene file: the message names the file and line."""

    def __init__(self, path, line, msg):
        super().__init__(f"{path}:{line}: {msg}")
        self.path, self.line, self.msg = path, line, msg


@dataclass
class Mesh:
    name: str
    verts: list = field(default_factory=list)   # [(x, y, z)] ints
    faces: list = field(default_factory=list)   # [(colour, [i, j, k(, l)])]
    convex: bool = False
    bsp: object = None                          # tree bytes (host/rast8/bsp.py) or None
    texture: str = None                         # a Scene.textures name
    uvs: list = field(default_factory=list)     # per face: [(u, v)] per corner, or None

    def radius(self):
        return int(math.ceil(max((math.sqrt(x * x + y * y + z * z) for x, y, z in self.verts), default=0)))


@dataclass
class Obj:
    mesh: str
    pos: tuple = (0, 0, 200)
    rot: tuple = (0, 0, 0)
    spin: tuple = (0, 0, 0)


@dataclass
class Scene:
    name: str
    meshes: dict = field(default_factory=dict)
    objects: list = field(default_factory=list)
    focal: int = 50
    near: int = 16
    light: tuple = (-1.0, -1.0, -1.0)
    ambient: float = 0.2
    bsp: bool = False        # merge rigid groups, split faces for BSP trees
    textures: dict = field(default_factory=dict)   # name -> texture.Texture
    world: object = None    # sectors.World (portal renderer), or None


def _int(tok, path, ln, lo=-32768, hi=32767, what="value"):
    try:
        v = int(tok, 0)
    except ValueError:
        raise SceneError(path, ln, f"{what} '{tok}' is not an integer") from None
    if not lo <= v <= hi:
        raise SceneError(path, ln, f"{what} {v} out of range {lo}..{hi}")
    return v


def _float(tok, path, ln, what="value"):
    try:
        return float(tok)
    except ValueError:
        raise SceneError(path, ln, f"{what} '{tok}' is not a number") from None


def _convex_closed(mesh):
    """Closed (every edge shared by two faces, in opposite directions) and
    every vertex on or behind every face plane."""
    edges = {}
    for _, idx in mesh.faces:
        for a, b in zip(idx, idx[1:] + idx[:1]):
            edges[(a, b)] = edges.get((a, b), 0) + 1
    if any(edges.get((b, a), 0) != 1 for (a, b) in edges):
        return False
    for _, idx in mesh.faces:
        p0, p1, p2 = (mesh.verts[i] for i in idx[:3])
        e1 = [p1[k] - p0[k] for k in range(3)]
        e2 = [p2[k] - p0[k] for k in range(3)]
        n = (e2[1] * e1[2] - e2[2] * e1[1], e2[2] * e1[0] - e2[0] * e1[2], e2[0] * e1[1] - e2[1] * e1[0])
        for v in mesh.verts:
            if sum(n[k] * (v[k] - p0[k]) for k in range(3)) > 0:
                return False
    return True


def parse_r8s(text, path="<scene>"):
    """Parse the text scene format; raises SceneError naming file and line."""
    sc = None
    mesh = None
    try:   # a world block and camera path (rast8/sectors.py)
        text, world = sectors.extract(text, path)
    except sectors.WorldError as e:
        raise SceneError(e.path, e.line, e.msg) from None
    for ln, raw in enumerate(text.splitlines(), 1):
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        t = line.split()
        kw = t[0]
        if kw == "scene":
            if len(t) != 2:
                raise SceneError(path, ln, "usage: scene NAME")
            sc = Scene(t[1])
            continue
        if sc is None:
            raise SceneError(path, ln, f"'{kw}' before 'scene NAME'")
        if mesh is not None and kw not in ("v", "f", "end"):
            raise SceneError(path, ln, f"'{kw}' inside mesh '{mesh.name}' (missing 'end'?)")
        if kw == "bsp":
            if len(t) != 1:
                raise SceneError(path, ln, "usage: bsp")
            sc.bsp = True
        elif kw == "camera":
            kv = dict(zip(t[1::2], t[2::2]))
            if len(t) % 2 == 0 or set(kv) - {"focal", "near"}:
                raise SceneError(path, ln, "usage: camera focal N near N")
            sc.focal = _int(kv.get("focal", "50"), path, ln, 1, 2047, "focal")
            sc.near = _int(kv.get("near", "16"), path, ln, 1, 32767, "near")
        elif kw == "light":
            if len(t) not in (4, 6) or (len(t) == 6 and t[4] != "ambient"):
                raise SceneError(path, ln, "usage: light X Y Z [ambient A]")
            sc.light = tuple(_float(x, path, ln, "light") for x in t[1:4])
            if not any(sc.light):
                raise SceneError(path, ln, "light direction is zero")
            if len(t) == 6:
                sc.ambient = _float(t[5], path, ln, "ambient")
                if not 0 <= sc.ambient <= 1:
                    raise SceneError(path, ln, "ambient must be 0..1")
        elif kw == "texture":
            _texture_line(sc, t, path, ln)
        elif kw == "mesh":
            if len(t) not in (2, 4) or (len(t) == 4 and t[2] != "texture"):
                raise SceneError(path, ln, "usage: mesh NAME [texture TEX]")
            if t[1] in sc.meshes:
                raise SceneError(path, ln, f"mesh '{t[1]}' defined twice")
            mesh = Mesh(t[1])
            if len(t) == 4:
                if t[3] not in sc.textures:
                    raise SceneError(path, ln, f"unknown texture '{t[3]}'")
                mesh.texture = t[3]
        elif kw == "v":
            if mesh is None:
                raise SceneError(path, ln, "'v' outside a mesh")
            if len(t) != 4:
                raise SceneError(path, ln, "usage: v X Y Z")
            mesh.verts.append(tuple(_int(x, path, ln, what="coordinate") for x in t[1:]))
            if len(mesh.verts) > 255:
                raise SceneError(path, ln, "a mesh has at most 255 vertices")
        elif kw == "f":
            if mesh is None:
                raise SceneError(path, ln, "'f' outside a mesh")
            uv = None
            if "uv" in t:
                k = t.index("uv")
                t, uvt = t[:k], t[k + 1:]
                if len(uvt) != 2 * (len(t) - 2):
                    raise SceneError(path, ln, "uv needs U V for every corner")
                uv = [(_float(a, path, ln, "u"), _float(b, path, ln, "v")) for a, b in zip(uvt[::2], uvt[1::2])]
                if any(not 0 <= c < 2 for p in uv for c in p):
                    raise SceneError(path, ln, "texture coordinates must lie in 0..2 (1 = one texture)")
            if len(t) not in (5, 6):
                raise SceneError(path, ln, "usage: f COLOUR I J K [L] [uv U V ...]")
            colour = _int(t[1], path, ln, 0, 16, "colour")
            idx = [_int(x, path, ln, 0, len(mesh.verts) - 1, "vertex index") for x in t[2:]]
            if len(set(idx)) != len(idx):
                raise SceneError(path, ln, "face repeats a vertex")
            mesh.faces.append((colour, idx))
            mesh.uvs.append(uv)
        elif kw == "end":
            if mesh is None:
                raise SceneError(path, ln, "'end' without 'mesh'")
            if not mesh.faces:
                raise SceneError(path, ln, f"mesh '{mesh.name}' has no faces")
            mesh.convex = _convex_closed(mesh)
            sc.meshes[mesh.name] = mesh
            mesh = None
        elif kw == "object":
            # object MESH at X Y Z [rot A B C] [spin A B C]
            if len(t) < 5 or t[2] != "at":
                raise SceneError(path, ln, "usage: object MESH at X Y Z [rot A B C] [spin A B C]")
            if t[1] not in sc.meshes:
                raise SceneError(path, ln, f"unknown mesh '{t[1]}'")
            pos = tuple(_int(x, path, ln, what="position") for x in t[3:6])
            rot, spin = (0, 0, 0), (0, 0, 0)
            rest = t[6:]
            while rest:
                if rest[0] not in ("rot", "spin") or len(rest) < 4:
                    raise SceneError(path, ln, f"expected 'rot A B C' or 'spin A B C', got '{' '.join(rest)}'")
                vals = tuple(_int(x, path, ln, -128 if rest[0] == "spin" else 0,
                                  127 if rest[0] == "spin" else 255, rest[0]) for x in rest[1:4])
                if rest[0] == "rot":
                    rot = vals
                else:
                    spin = vals
                rest = rest[4:]
            sc.objects.append(Obj(t[1], pos, rot, spin))
        else:
            raise SceneError(path, ln, f"unknown keyword '{kw}'")
    if mesh is not None:
        raise SceneError(path, len(text.splitlines()), f"mesh '{mesh.name}' not closed with 'end'")
    if sc is None:
        raise SceneError(path, 1, "no 'scene NAME' line")
    if world is not None:
        if world.name in sc.meshes:
            raise SceneError(path, 1, f"world '{world.name}' has the name of a mesh")
        sc.world = world
        sc.meshes[world.name] = sectors.to_mesh(world)
        sc.objects.insert(0, Obj(world.name, (0, 0, 0)))   # its walls, for the other methods
        for n in world.moves:
            if n + 1 >= len(sc.objects):
                raise SceneError(path, 1, f"'move {n}': the scene has {len(sc.objects) - 1} objects")
    if not sc.objects:
        raise SceneError(path, len(text.splitlines()), "scene has no objects")
    if len(sc.objects) > 255:
        raise SceneError(path, len(text.splitlines()), "at most 255 objects")
    return sc


def _texture_line(sc, t, path, ln):
    """texture NAME FILE.png [1bpp|idx8]  or  texture NAME crate"""
    from . import texture
    if len(t) not in (3, 4):
        raise SceneError(path, ln, "usage: texture NAME FILE.png [1bpp|idx8] (or: texture NAME crate)")
    if t[1] in sc.textures:
        raise SceneError(path, ln, f"texture '{t[1]}' defined twice")
    if t[2] == "crate" and len(t) == 3:
        tex = texture.crate()
        tex.name = t[1]
    else:
        f = t[2] if os.path.isabs(t[2]) else os.path.join(os.path.dirname(os.path.abspath(path)), t[2])
        try:
            tex = texture.load_png(f, t[3] if len(t) == 4 else "idx8", t[1])
        except texture.TextureError as e:
            raise SceneError(path, ln, str(e)) from None
    sc.textures[t[1]] = tex


def load_r8s(path):
    with open(path, encoding="utf-8") as f:
        return parse_r8s(f.read(), path)


def parse_obj(text, path="<obj>", scale=None, colour=16):
    """OBJ subset: 'v x y z' and 'f a b c [d]' (a/b/c forms allowed, only
    the vertex index is used; negative indices count from the end).
    Faces that are not planar and convex with at most 4 vertices are split
    into convex pieces (host/rast8/concave.py).  OBJ is counter-clockwise from
    outside with y up; rast8 is clockwise with y down, so y is negated
    (which also flips the winding).  Coordinates are scaled to fit
    +/-`scale` (default: the largest extent becomes 100)."""
    verts, faces, vts, uvs = [], [], [], []
    for ln, raw in enumerate(text.splitlines(), 1):
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        t = line.split()
        if t[0] == "v":
            if len(t) < 4:
                raise SceneError(path, ln, "usage: v X Y Z")
            verts.append(tuple(_float(x, path, ln, "coordinate") for x in t[1:4]))
        elif t[0] == "f":
            if len(t) < 4:
                raise SceneError(path, ln, "a face needs 3 or more vertices")
            idx, tix = [], []
            for tok in t[1:]:
                parts = tok.split("/")
                try:
                    i = int(parts[0])
                    ti = int(parts[1]) if len(parts) > 1 and parts[1] else None
                except ValueError:
                    raise SceneError(path, ln, f"bad vertex reference '{tok}'") from None
                i = i - 1 if i > 0 else len(verts) + i
                if not 0 <= i < len(verts):
                    raise SceneError(path, ln, f"vertex {tok} not defined yet")
                idx.append(i)
                if ti is not None:
                    ti = ti - 1 if ti > 0 else len(vts) + ti
                    if not 0 <= ti < len(vts):
                        raise SceneError(path, ln, f"texture coordinate {tok} not defined yet")
                tix.append(ti)
            if len(set(idx)) != len(idx):
                raise SceneError(path, ln, "face repeats a vertex")
            faces.append((colour, idx))
            uvs.append([vts[j] for j in tix] if None not in tix else None)
        elif t[0] == "vt":
            if len(t) < 3:
                raise SceneError(path, ln, "usage: vt U V")
            u, v = (_float(x, path, ln, "texture coordinate") for x in t[1:3])
            vts.append((u % 2.0, (1.0 - v) % 2.0))     # OBJ v runs up, rast8's down
        elif t[0] in ("vn", "o", "g", "s", "usemtl", "mtllib", "l"):
            continue
        else:
            raise SceneError(path, ln, f"unsupported OBJ statement '{t[0]}'")
    if not verts or not faces:
        raise SceneError(path, 1, "no vertices or faces")
    if len(verts) > 255:
        raise SceneError(path, 1, f"{len(verts)} vertices: a mesh has at most 255")
    ext = max(abs(c) for v in verts for c in v) or 1.0
    k = (scale or 100) / ext
    m = Mesh(os.path.splitext(os.path.basename(path))[0] or "obj")
    m.verts = [(round(x * k), round(-y * k), round(z * k)) for x, y, z in verts]
    m.faces = faces
    m.uvs = uvs if any(uvs) else []
    split_mesh(m)
    m.convex = _convex_closed(m)
    return m


# ---- procedural built-ins -------------------------------------------------

def _grid_faces(rows, cols, idx, colour, wrap_cols=True, wrap_rows=False):
    faces = []
    for r in range(rows - (0 if wrap_rows else 1)):
        for c in range(cols - (0 if wrap_cols else 1)):
            a, b = idx(r, c), idx(r, (c + 1) % cols)
            d, e = idx((r + 1) % rows, c), idx((r + 1) % rows, (c + 1) % cols)
            faces.append((colour(r, c), [a, b, e, d]))
    return faces


def torus(R=40, r=16, seg=20, sides=10):
    m = Mesh("torus")
    for i in range(seg):
        a = 2 * math.pi * i / seg
        for j in range(sides):
            b = 2 * math.pi * j / sides
            rr = R + r * math.cos(b)
            m.verts.append((round(rr * math.cos(a)), round(r * math.sin(b)), round(rr * math.sin(a))))
    m.faces = _grid_faces(seg, sides, lambda i, j: i * sides + j, lambda i, j: 16, wrap_rows=True)
    _orient_outward(m, centre_fn=lambda p: (R * p[0] / max(1e-9, math.hypot(p[0], p[2])), 0,
                                            R * p[2] / max(1e-9, math.hypot(p[0], p[2]))))
    return m


def _face_normal(m, idx):
    p0, p1, p2 = (m.verts[i] for i in idx[:3])
    e1 = [p1[k] - p0[k] for k in range(3)]
    e2 = [p2[k] - p0[k] for k in range(3)]
    return (e2[1] * e1[2] - e2[2] * e1[1], e2[2] * e1[0] - e2[0] * e1[2], e2[0] * e1[1] - e2[1] * e1[0])


def _orient_outward(m, centre_fn=lambda p: (0, 0, 0)):
    """Reverse faces whose rast8 outward normal points towards centre_fn."""
    out = []
    for colour, idx in m.faces:
        c = [sum(m.verts[i][k] for i in idx) / len(idx) for k in range(3)]
        ctr = centre_fn(c)
        n = _face_normal(m, idx)
        if sum(n[k] * (c[k] - ctr[k]) for k in range(3)) < 0:
            idx = list(reversed(idx))
        out.append((colour, idx))
    m.faces = out


def _lathe(m, profile, seg, colour, cap_top=True, cap_bottom=True):
    base = len(m.verts)
    for (rad, y) in profile:
        for i in range(seg):
            a = 2 * math.pi * i / seg
            m.verts.append((round(rad * math.cos(a)), round(y), round(rad * math.sin(a))))
    faces = []
    for p in range(len(profile) - 1):
        for i in range(seg):
            a = base + p * seg + i
            b = base + p * seg + (i + 1) % seg
            faces.append((colour, [a, b, b + seg, a + seg]))
    if cap_top:
        top = len(m.verts)
        m.verts.append((0, round(profile[0][1]), 0))
        for i in range(seg):
            faces.append((colour, [top, base + (i + 1) % seg, base + i]))
    if cap_bottom:
        bot = len(m.verts)
        m.verts.append((0, round(profile[-1][1]), 0))
        last = base + (len(profile) - 1) * seg
        for i in range(seg):
            faces.append((colour, [bot, last + i, last + (i + 1) % seg]))
    return faces


def _tube(m, path, radius, sides, colour):
    """A tube along a polyline path (list of 3D points), open ends."""
    base = len(m.verts)
    for k, p in enumerate(path):
        q = path[min(k + 1, len(path) - 1)]
        o = path[max(k - 1, 0)]
        t = [q[i] - o[i] for i in range(3)]
        tl = math.sqrt(sum(x * x for x in t)) or 1
        t = [x / tl for x in t]
        up = (0, 0, 1) if abs(t[2]) < 0.9 else (1, 0, 0)
        u = [t[1] * up[2] - t[2] * up[1], t[2] * up[0] - t[0] * up[2], t[0] * up[1] - t[1] * up[0]]
        ul = math.sqrt(sum(x * x for x in u))
        u = [x / ul for x in u]
        w = [t[1] * u[2] - t[2] * u[1], t[2] * u[0] - t[0] * u[2], t[0] * u[1] - t[1] * u[0]]
        for s in range(sides):
            a = 2 * math.pi * s / sides
            m.verts.append(tuple(round(p[i] + radius * (math.cos(a) * u[i] + math.sin(a) * w[i])) for i in range(3)))
    faces = []
    for k in range(len(path) - 1):
        for s in range(sides):
            a = base + k * sides + s
            b = base + k * sides + (s + 1) % sides
            faces.append((colour, [a, b, b + sides, a + sides]))
    return faces, base


def teapot():
    """A teapot-class model: lathed body and lid with knob, a spout and a
    handle as tubes pushed into the body (so it self-intersects, like the
    real one's spout and handle)."""
    m = Mesh("teapot")
    body = [(0.1, -40), (14, -40), (24, -36), (30, -26), (33, -14), (34, -2), (32, 10), (27, 20), (20, 26), (4, 30)]
    prof = [(r, y) for r, y in body]
    faces = _lathe(m, prof, 18, 16, cap_top=False, cap_bottom=True)
    tmp = Mesh("t", m.verts, faces)
    _orient_outward(tmp, lambda p: (0, p[1], 0))
    faces = tmp.faces
    spout_path = [(26, 6, 0), (38, 0, 0), (46, -10, 0), (52, -22, 0), (58, -30, 0)]
    sf, _ = _tube(m, spout_path, 5, 8, 14)
    tmp = Mesh("s", m.verts, sf)
    _orient_outward(tmp, lambda p: _nearest_on_path(p, spout_path))
    faces += tmp.faces
    handle_path = [(-26, -16, 0), (-38, -20, 0), (-46, -10, 0), (-46, 4, 0), (-38, 14, 0), (-27, 12, 0)]
    hf, _ = _tube(m, handle_path, 4, 4, 12)
    tmp = Mesh("h", m.verts, hf)
    _orient_outward(tmp, lambda p: _nearest_on_path(p, handle_path))
    faces += tmp.faces
    m.faces = faces
    # flip y so the pot stands upright on screen (rast8 y is down)
    m.verts = [(x, -y, z) for x, y, z in m.verts]
    m.faces = [(c, list(reversed(i))) for c, i in m.faces]
    return m


def _nearest_on_path(p, path):
    best, bd = path[0], 1e18
    for a, b in zip(path, path[1:]):
        ab = [b[i] - a[i] for i in range(3)]
        t = sum((p[i] - a[i]) * ab[i] for i in range(3)) / (sum(x * x for x in ab) or 1)
        t = max(0.0, min(1.0, t))
        q = [a[i] + t * ab[i] for i in range(3)]
        d = sum((p[i] - q[i]) ** 2 for i in range(3))
        if d < bd:
            best, bd = q, d
    return best


class _Lcg:
    """The terrain's random numbers: a 32-bit LCG, so C and Python agree."""

    def __init__(self, seed):
        self.s = seed & 0xFFFFFFFF

    def next(self):
        self.s = (self.s * 1103515245 + 12345) & 0xFFFFFFFF
        return (self.s >> 16) & 0x7FFF


def fractal_heights(n=16, seed=1998, rough=12):
    """The seed's midpoint displacement on an n x n array that wraps at
    its edges (indices mod n, as the seed's 1-byte indices wrap at 256),
    so the landscape is continuous across them.  random*size is an
    integer in [-size*rough/16, size*rough/16]."""
    rng = _Lcg(seed)
    a = [[None] * n for _ in range(n)]
    a[0][0] = 0

    def rnd(size):
        span = size * rough // 16
        return rng.next() % (2 * span + 1) - span if span else 0

    def get(x, y):
        return a[y % n][x % n]

    def setv(x, y, v):
        if a[y % n][x % n] is None:
            a[y % n][x % n] = v

    def sample(x1, y1, size):
        half = size // 2
        xh, yh, x2, y2 = x1 + half, y1 + half, x1 + size, y1 + size
        setv(xh, y1, (get(x1, y1) + get(x2, y1)) // 2 + rnd(size))
        setv(xh, y2, (get(x1, y2) + get(x2, y2)) // 2 + rnd(size))
        setv(x1, yh, (get(x1, y1) + get(x1, y2)) // 2 + rnd(size))
        setv(x2, yh, (get(x2, y1) + get(x2, y2)) // 2 + rnd(size))
        setv(xh, yh, (get(xh, y1) + get(xh, y2) + get(x1, yh) + get(x2, yh)) // 4 + rnd(size))
        if half > 1:
            sample(x1, y1, half)
            sample(xh, y1, half)
            sample(x1, yh, half)
            sample(xh, yh, half)

    sample(0, 0, n)
    return a


def terrain(n=16, show=12, cell=14):
    """A show x show patch of the wrapping fractal heightfield, as
    triangles, colour by height."""
    h = fractal_heights(n)
    m = Mesh("terrain")
    off = (show - 1) * cell / 2
    for r in range(show):
        for c in range(show):
            m.verts.append((round(c * cell - off), -h[r % n][c % n] * 3, round(r * cell - off)))
    hs = [v[1] for v in m.verts]
    lo, hi = min(hs), max(hs)
    faces = []
    for r in range(show - 1):
        for c in range(show - 1):
            a, b, d, e = r * show + c, r * show + c + 1, (r + 1) * show + c, (r + 1) * show + c + 1
            for tri in ([a, b, e], [a, e, d]) if (r + c) % 2 else ([a, b, d], [b, e, d]):
                y = sum(m.verts[i][1] for i in tri) / 3
                colour = 6 + round(10 * (hi - y) / ((hi - lo) or 1))
                faces.append((colour, tri))
    tmp = Mesh("t", m.verts, faces)
    _orient_outward(tmp, lambda p: (p[0], p[1] + 1000, p[2]))   # normals up (-y)
    m.faces = tmp.faces
    return m


def box(name, hx, hy, hz, colour=16):
    m = Mesh(name)
    for z in (-hz, hz):
        for (x, y) in ((-hx, -hy), (hx, -hy), (hx, hy), (-hx, hy)):
            m.verts.append((x, y, z))
    for idx in ([0, 1, 2, 3], [5, 4, 7, 6], [1, 5, 6, 2], [4, 0, 3, 7], [4, 5, 1, 0], [3, 2, 6, 7]):
        m.faces.append((colour, idx))
    m.convex = True
    return m


def finish(sc):
    """Converter passes after parsing: concave and non-planar faces split
    (concave.py), then BSP trees (bsp.py).  Returns sc."""
    from . import bsp
    for m in sc.meshes.values():
        if split_mesh(m):
            m.convex = _convex_closed(m)
    bsp.attach(sc)
    return sc


def builtin(name):
    """The built-in scene called name."""
    return finish(_builtin(name))


def _builtin(name):
    path = os.path.join(SCENE_DIR, name + ".r8s")
    if os.path.exists(path):
        return load_r8s(path)
    sc = Scene(name)
    if name == "torus":
        sc.meshes["torus"] = torus()
        sc.objects.append(Obj("torus", (0, 0, 170), (40, 0, 0), (2, 3, 1)))
    elif name == "teapot":
        sc.meshes["teapot"] = teapot()
        sc.objects.append(Obj("teapot", (0, 0, 190), (20, 0, 0), (0, 3, 0)))
    elif name == "terrain":
        sc.meshes["terrain"] = terrain()
        sc.objects.append(Obj("terrain", (0, 10, 210), (28, 0, 0), (0, 2, 0)))
        sc.focal = 44
    elif name == "cross":
        sc.bsp = True        # one rigid body: slab and post merged, one tree
        sc.meshes["slab"] = box("slab", 50, 12, 12, 12)
        sc.meshes["post"] = box("post", 14, 40, 14, 16)
        sc.objects.append(Obj("slab", (0, 0, 200), (0, 0, 0), (1, 3, 0)))
        sc.objects.append(Obj("post", (0, 0, 200), (0, 0, 0), (1, 3, 0)))
    elif name == "crate":
        from . import texture
        sc.textures["crate"] = texture.crate()
        m = box("crate", 40, 40, 40, 16)
        m.texture = "crate"
        m.uvs = [[(0, 0), (1, 0), (1, 1), (0, 1)] for _ in m.faces]
        sc.meshes["crate"] = m
        sc.objects.append(Obj("crate", (0, 0, 200), (0, 0, 0), (1, 2, 0)))
    elif name == "separate":
        sc.meshes["cube"] = box("cube", 16, 16, 16, 16)
        sc.meshes["bar"] = box("bar", 26, 8, 8, 11)
        sc.objects.append(Obj("cube", (-50, -10, 140), (0, 0, 0), (2, 3, 0)))
        sc.objects.append(Obj("bar", (10, 14, 230), (0, 0, 0), (0, 2, 3)))
        sc.objects.append(Obj("cube", (60, -20, 320), (0, 0, 0), (3, 1, 2)))
        sc.objects.append(Obj("bar", (-30, 30, 420), (0, 0, 0), (1, 0, 2)))
    else:
        raise KeyError(name)
    return sc


# ---- output ----------------------------------------------------------------

def _q14(v):
    return max(-32768, min(32767, round(v * 16384)))


def _light_q14(light):
    n = math.sqrt(sum(x * x for x in light))
    return tuple(_q14(x / n) for x in light)


def _divround(n, d):
    """C r8_divround: n / d rounded to nearest, ties away from zero."""
    q, r = divmod(abs(n), abs(d))
    if r >= abs(d) - r:
        q += 1
    return -q if (n < 0) != (d < 0) else q


def _normalize(v):
    """C r8_normalize: scale into 14 bits, then to unit length in Q1.14."""
    m = max(abs(x) for x in v)
    if m == 0:
        return (0, 0, 0)
    sh = 0
    while (m >> sh) >= 0x4000:
        sh += 1
    if sh:
        v = tuple(_divround(x, 1 << sh) for x in v)
    ln = math.isqrt(sum(x * x for x in v)) or 1
    return tuple(_divround(x * 16384, ln) for x in v)


def c_normals(m):
    """Unit face normals exactly as the C r8_mesh_normals computes them:
    (v2 - v0) x (v1 - v0), edges halved until they fit 16 bits."""
    out = []
    for _, idx in m.faces:
        a, b, c = (m.verts[i] for i in idx[:3])
        d = [b[j] - a[j] for j in range(3)] + [c[j] - a[j] for j in range(3)]
        while any(x > 32767 or x < -32767 for x in d):
            d = [x >> 1 for x in d]
        e1, e2 = d[:3], d[3:]
        n = (e2[1] * e1[2] - e2[2] * e1[1], e2[2] * e1[0] - e2[0] * e1[2],
             e2[0] * e1[1] - e2[1] * e1[0])
        out.append(_normalize(n))
    return out


def _cname(name):
    return "".join(ch if ch.isalnum() else "_" for ch in name)


def to_c_scene(sc):
    """C source for one scene (scenes/<name>.c): its meshes as R8_FLASH
    arrays with their face normals, and the demo descriptor r8_demo_<name>
    (objects with start angles and spin, camera focal and near plane)."""
    sid = _cname(sc.name)
    out = [f"/* Generated by host/rast8/scene.py from scene {sc.name!r}: do not edit; "
           "run `make scenes`. */",
           '#include "demo.h"', ""]
    mids, tids = {}, {}
    if sc.textures:
        from . import texture
        for tname, tex in sc.textures.items():
            tids[tname] = f"{sid}_tex_{_cname(tname)}"
            out.extend(texture.to_c(tex, tids[tname]))
    for mname, m in sc.meshes.items():
        cid = f"{sid}_{_cname(mname)}"
        mids[mname] = cid
        out.append(f"static const r8_s16 {cid}_v[{len(m.verts) * 3}] R8_FLASH = {{")
        for k in range(0, len(m.verts), 4):
            out.append("    " + ", ".join(f"{x}, {y}, {z}" for x, y, z in m.verts[k:k + 4]) + ",")
        out.append("};")
        out.append(f"static const r8_face {cid}_f[{len(m.faces)}] R8_FLASH = {{")
        for colour, idx in m.faces:
            vs = idx + [0] * (4 - len(idx))
            out.append(f"    {{{len(idx)}, {colour}, {{{vs[0]}, {vs[1]}, {vs[2]}, {vs[3]}}}}},")
        out.append("};")
        out.append(f"static const r8_s16 {cid}_n[{len(m.faces) * 3}] R8_FLASH = {{")
        ns = c_normals(m)
        for k in range(0, len(ns), 4):
            out.append("    " + ", ".join(f"{x}, {y}, {z}" for x, y, z in ns[k:k + 4]) + ",")
        out.append("};")
        tex = " R8_MESH_TEX(0, 0)"      # r8_mesh.tex, uv: untextured
        if m.texture:
            from . import texture
            out.append(f"static const r8_u8 {cid}_uv[{len(m.faces) * 8}] R8_FLASH = {{")
            for k in range(len(m.faces)):
                uv = (m.uvs[k] if k < len(m.uvs) and m.uvs[k] else [(0, 0)] * len(m.faces[k][1]))
                bs = [texture.uv_byte(c) for p in uv for c in p] + [0] * (8 - 2 * len(uv))
                out.append("    " + ", ".join(str(b) for b in bs) + ",")
            out.append("};")
            tex = f" R8_MESH_TEX(&{tids[m.texture]}, {cid}_uv)"
        tail = ", 0"
        if m.bsp:
            out.append("#ifndef R8_NO_BSP")
            out.append(f"static const r8_u8 {cid}_bsp[{len(m.bsp)}] R8_FLASH = {{")
            for k in range(0, len(m.bsp), 16):
                out.append("    " + ", ".join(str(x) for x in m.bsp[k:k + 16]) + ",")
            out.append("};")
            out.append("#endif")
            tail = f", R8_MESH_BSP({cid}_bsp)"
        mesh = (f"static const r8_mesh {cid} = {{{cid}_v, {cid}_f, {cid}_n, {len(m.verts)}, "
                f"{len(m.faces)}, {1 if m.convex else 0}, {m.radius()}{tail}{tex}}};")
        if sc.world is not None and mname == sc.world.name:
            lines, mids[mname] = sectors.c_world(sc.world, sid, cid)
            out += [lines[0], "#ifndef R8_NO_PORTAL", mesh] + lines[1:] + ["#endif"]
        else:
            out.append(mesh)
    out.append(f"static const r8_demo_obj {sid}_objects[{len(sc.objects)}] R8_FLASH = {{")
    for o in sc.objects:
        out.append(f"    {{&{mids[o.mesh]}, {o.pos[0]}, {o.pos[1]}, {o.pos[2]}, "
                   f"{o.rot[0]}, {o.rot[1]}, {o.rot[2]}, {o.spin[0]}, {o.spin[1]}, {o.spin[2]}}},")
    out.append("};")
    lx, ly, lz = _light_q14(sc.light)
    out.append(f'static const char {sid}_name[] R8_FLASH = "{sc.name}";')
    world = " R8_DEMO_WORLD(0, 0, 0)"
    if sc.world is not None:
        world = f" R8_DEMO_WORLD(&{sid}_world, {sid}_path, {len(sc.world.path)})"
        if sc.world.moves:
            world = (f" R8_DEMO_WORLDM(&{sid}_world, {sid}_path, {len(sc.world.path)}, "
                     f"{sid}_moves, {len(sc.world.moves)})")
    out.append(f"const r8_demo r8_demo_{sid} R8_FLASH = {{{sid}_name, {sid}_objects, {len(sc.objects)}, "
               f"{sc.focal}, {sc.near}, {_q14(sc.ambient)}, {{{lx}, {ly}, {lz}}}{world}}};")
    return "\n".join(out) + "\n"


def to_c(scenes, out):
    """Write the scenes as C: one file per scene (<name>.c) into the
    directory `out`, or all of them into one file when `out` ends in .c.
    Returns the paths written."""
    if out.endswith(".c"):
        with open(out, "w", encoding="utf-8") as f:
            f.write("\n".join(to_c_scene(sc) for sc in scenes))
        return [out]
    names = []
    for sc in scenes:
        path = os.path.join(out, _cname(sc.name) + ".c")
        with open(path, "w", encoding="utf-8") as f:
            f.write(to_c_scene(sc))
        names.append(path)
    return names


def to_blob(sc):
    """Binary blob (little-endian), for firmware that loads scenes:
    'R8SC' u8 version=1 u8 nmeshes u8 nobjects u8 pad
    s16 focal s16 near s16 ambient(Q1.14) s16 light[3](Q1.14)
    per mesh: u8 nverts u16 nfaces u8 convex s16 radius, verts s16[3*n],
              faces {u8 n, u8 colour, u8 v[4]}
    per object: u8 mesh s16 pos[3] u8 rot[3] s8 spin[3]"""
    names = list(sc.meshes)
    b = bytearray(b"R8SC")
    b += struct.pack("<BBBB", 1, len(names), len(sc.objects), 0)
    b += struct.pack("<hhh", sc.focal, sc.near, _q14(sc.ambient))
    b += struct.pack("<hhh", *_light_q14(sc.light))
    for n in names:
        m = sc.meshes[n]
        b += struct.pack("<BHBh", len(m.verts), len(m.faces), 1 if m.convex else 0, m.radius())
        for v in m.verts:
            b += struct.pack("<hhh", *v)
        for colour, idx in m.faces:
            vs = idx + [0] * (4 - len(idx))
            b += struct.pack("<BB4B", len(idx), colour, *vs)
    for o in sc.objects:
        b += struct.pack("<Bhhh3B3b", names.index(o.mesh), *o.pos, *o.rot, *o.spin)
    return bytes(b)


def load_any(path):
    if path.lower().endswith(".obj"):
        with open(path, encoding="utf-8") as f:
            m = parse_obj(f.read(), path)
        sc = Scene(m.name)
        sc.meshes[m.name] = m
        sc.objects.append(Obj(m.name, (0, 0, 260), (0, 0, 0), (1, 2, 0)))
        return finish(sc)
    return finish(load_r8s(path))


def main(argv=None):
    argv = list(sys.argv[1:] if argv is None else argv)
    if not argv or argv[0] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if argv else 2
    cmd, args = argv[0], argv[1:]
    try:
        if cmd == "c" and args:
            scenes = [load_any(p) for p in args[1:]] or [builtin(n) for n in BUILTIN_ORDER]
            paths = to_c(scenes, args[0])
            print(f"wrote {args[0]}: {len(scenes)} scenes in {len(paths)} file(s), "
                  f"{sum(len(m.faces) for s in scenes for m in s.meshes.values())} faces")
        elif cmd == "blob" and len(args) == 2:
            data = to_blob(load_any(args[0]))
            with open(args[1], "wb") as f:
                f.write(data)
            print(f"wrote {args[1]}: {len(data)} bytes")
        elif cmd == "check" and len(args) == 1:
            sc = load_any(args[0])
            for n, m in sc.meshes.items():
                print(f"{n}: {len(m.verts)} vertices, {len(m.faces)} faces, "
                      f"{'convex' if m.convex else 'not convex'}, radius {m.radius()}, "
                      f"{'BSP tree ' + str(len(m.bsp)) + ' bytes' if m.bsp else 'no BSP tree'}")
            print(f"{len(sc.objects)} objects")
        else:
            print(__doc__.strip(), file=sys.stderr)
            return 2
    except SceneError as e:
        print(f"rast8 scene: {e}", file=sys.stderr)
        return 1
    except OSError as e:
        print(f"rast8 scene: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
