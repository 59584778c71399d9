"""Floating-point reference renderer (numpy): the ground truth the fixed-
point renderer is measured against (docs/accuracy.md).

Same conventions as the C renderer, computed in float64 with no
shortcuts:
- camera at the origin looking down +z, x right, y down; object angles
  a = (a0 + spin * (frame & 0xFF)) mod 256 per axis, 256 steps per turn;
  m = Rx(ax) Ry(ay) Rz(az); camera point = m v + position;
- focal f = (width * focal_num) >> 6 pixels; screen x = width/2 + f x/z,
  y = height/2 + f y/z;
- outward normal n = (v2 - v0) x (v1 - v0); front iff n . (eye - v0) > 0
  (back faces are never drawn: the C renderer culls them with either cull);
- near plane z = scene.near: Sutherland-Hodgman in camera space;
- fill: pixel (c, r) is inside iff its centre (c + .5, r + .5) is, left
  and top edges inclusive (top-left rule); only clockwise (front-facing)
  polygons are drawn, as the C scan converter does;
- depth: exact per pixel, the ray through the pixel centre meets the
  face's plane (nearest wins);
- shading: flat = face colour; Lambert = round(colour (amb + (1 - amb)
  max(0, n.L))); Gouraud: vertex intensity 16 (amb + (1 - amb) max(0,
  n_v.L)), n_v the normalised sum of the unit normals of the faces at the
  vertex, interpolated linearly along edges (in camera space where the
  near plane cuts an edge) and then in screen space along the row at the
  pixel centre; level = round(I).  round() is half up, as the C code.
- texture (docs/pipeline.md "Texture mapping"): the ray through the
  pixel centre meets the face at a camera point; its texture coordinates
  are the affine map of the face's corner (u, v) in camera space (exact
  perspective), sampled nearest (the texel containing (u, v)) or
  bilinear (between the four texel centres about it), wrapping; level =
  round(texel / 255 * round(Lambert level)).  Untextured faces draw their
  Lambert level.
- 1 bpp: ordered 4x4 dither, lit iff level > BAYER[y & 3][x & 3].
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

BAYER = np.array([[0, 8, 2, 10], [12, 4, 14, 6], [3, 11, 1, 9], [15, 7, 13, 5]])
FORMATS = ("page1", "row1", "idx8")


def rot_matrix(ax, ay, az):
    """m = Rx(ax) Ry(ay) Rz(az), angles in 256ths of a turn."""
    def cs(a):
        t = 2 * math.pi * a / 256.0
        return math.cos(t), math.sin(t)
    c, s = cs(ax)
    rx = np.array([[1, 0, 0], [0, c, -s], [0, s, c]])
    c, s = cs(ay)
    ry = np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])
    c, s = cs(az)
    rz = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])
    return rx @ ry @ rz


def angles(obj, frame):
    f = frame & 0xFF
    return tuple((a + s * f) % 256 for a, s in zip(obj.rot, obj.spin))


def focal_px(sc, width):
    return (width * sc.focal) >> 6


def round_half_up(x):
    return np.floor(np.asarray(x, dtype=float) + 0.5)


def face_normal(p):
    """Outward normal (v2 - v0) x (v1 - v0) of a face's first three points."""
    return np.cross(p[2] - p[0], p[1] - p[0])


def unit(v):
    n = np.linalg.norm(v)
    return v / n if n > 0 else v * 0.0


# ---- polygon fill --------------------------------------------------------

def signed_area2(xs, ys):
    """Twice the signed area; > 0 for clockwise on screen (y down)."""
    xs = np.asarray(xs, float)
    ys = np.asarray(ys, float)
    return float(np.sum(xs * np.roll(ys, -1) - np.roll(xs, -1) * ys))


def inside(xs, ys, px, py):
    """Boolean array: points (px, py) inside the convex polygon (xs, ys),
    clockwise on screen, with the top-left rule.  All coordinates in
    pixels; exact for coordinates on the 1/16 grid (float64 products)."""
    px = np.asarray(px, float)
    py = np.asarray(py, float)
    m = np.ones(np.broadcast(px, py).shape, bool)
    n = len(xs)
    for i in range(n):
        ax, ay = xs[i], ys[i]
        bx, by = xs[(i + 1) % n], ys[(i + 1) % n]
        dx, dy = bx - ax, by - ay
        if dx == 0 and dy == 0:
            continue                            # repeated vertex: no edge
        e = dx * (py - ay) - dy * (px - ax)
        tl = dy < 0 or (dy == 0 and dx > 0)     # left or top edge
        m &= (e > 0) | ((e == 0) if tl else False)
    return m


def fill_mask(xs, ys, width, height):
    """Pixels of a clockwise convex polygon (pixel coordinates): the
    reference's r8_fill_poly.  Counter-clockwise polygons draw nothing."""
    out = np.zeros((height, width), bool)
    if len(xs) < 3 or signed_area2(xs, ys) <= 0:
        return out
    c0 = max(0, int(math.floor(min(xs) - 0.5)))
    c1 = min(width, int(math.ceil(max(xs) + 0.5)) + 1)
    r0 = max(0, int(math.floor(min(ys) - 0.5)))
    r1 = min(height, int(math.ceil(max(ys) + 0.5)) + 1)
    if c0 >= c1 or r0 >= r1:
        return out
    py, px = np.mgrid[r0:r1, c0:c1]
    out[r0:r1, c0:c1] = inside(xs, ys, px + 0.5, py + 0.5)
    return out


def clip_near(points, attrs, near):
    """Sutherland-Hodgman against z >= near; attrs interpolate linearly
    along each cut edge.  Returns (points, attrs)."""
    out_p, out_a = [], []
    n = len(points)
    for i in range(n):
        a, b = points[i], points[(i + 1) % n]
        sa, sb = attrs[i], attrs[(i + 1) % n]
        da, db = a[2] - near, b[2] - near
        if da >= 0:
            out_p.append(a)
            out_a.append(sa)
        if (da >= 0) != (db >= 0):
            t = da / (da - db)
            out_p.append(a + (b - a) * t)
            out_a.append(sa + (sb - sa) * t)
    return out_p, out_a


# ---- frames --------------------------------------------------------------

@dataclass
class Poly:
    """One face after transform and near clipping (front or back)."""
    gid: int
    xs: np.ndarray        # screen x (pixels)
    ys: np.ndarray
    inten: np.ndarray     # Gouraud intensity per vertex (0..16)
    n: np.ndarray         # camera-space plane normal
    p0: np.ndarray        # a camera-space point on the plane
    front: bool
    level: float          # flat/Lambert level (unrounded)
    pts: np.ndarray = None    # camera-space corners (after the near clip)
    uv: np.ndarray = None     # texture coordinates per corner (textures)
    tex: object = None        # texture.Texture of the mesh


@dataclass
class Frame:
    width: int
    height: int
    level: np.ndarray     # int 0..16 per pixel (0 = background)
    fid: np.ndarray       # global face index per pixel, -1 = background
    z: np.ndarray         # camera-space depth per pixel, inf = background
    polys: dict = field(default_factory=dict)   # gid -> Poly (all faces in front of near)
    verts: list = field(default_factory=list)   # per object: (N, 3) camera points
    f: int = 0

    def pixels(self, fmt):
        """Unpacked pixel values in a frame format: levels for idx8, 0/1 bits
        (the 4x4 dither) for page1/row1."""
        if fmt == "idx8":
            return self.level.copy()
        yy, xx = np.mgrid[0:self.height, 0:self.width]
        return (self.level > BAYER[yy & 3, xx & 3]).astype(np.uint8)

    def to_bytes(self, fmt):
        return pack(self.pixels(fmt), fmt)

    def depth_at(self, gid, px, py):
        """Camera z where the ray through (px, py) meets face gid's plane."""
        p = self.polys[gid]
        cx, cy = self.width / 2.0, self.height / 2.0
        dx = (np.asarray(px, float) - cx) / self.f
        dy = (np.asarray(py, float) - cy) / self.f
        den = p.n[0] * dx + p.n[1] * dy + p.n[2]
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(den != 0, np.dot(p.n, p.p0) / den, np.inf)

    def covers(self, gid, px, py):
        """Does face gid (front or back) cover pixel centres (px, py)?"""
        p = self.polys.get(gid)
        if p is None:
            return np.zeros(np.broadcast(np.asarray(px), np.asarray(py)).shape, bool)
        xs, ys = p.xs, p.ys
        if signed_area2(xs, ys) < 0:
            xs, ys = xs[::-1], ys[::-1]
        return inside(xs, ys, px, py)


def object_verts(sc, obj, frame):
    m = rot_matrix(*angles(obj, frame))
    v = np.array(sc.meshes[obj.mesh].verts, float)
    return m, v @ m.T + np.array(obj.pos, float)


def project(sc, cam, width, height):
    """Screen coordinates (pixels) of camera-space points (N, 3)."""
    f = focal_px(sc, width)
    cam = np.asarray(cam, float)
    return width / 2.0 + f * cam[:, 0] / cam[:, 2], height / 2.0 + f * cam[:, 1] / cam[:, 2]


def render(sc, frame, width=128, height=64, shading="lambert", texfilter="nearest"):
    """Render frame `frame` of scene sc (host/rast8/scene.py Scene);
    shading flat, lambert, gouraud or texture (texfilter nearest or
    bilinear)."""
    f = focal_px(sc, width)
    cx, cy = width / 2.0, height / 2.0
    light = unit(np.array(sc.light, float))
    amb = float(sc.ambient)
    level = np.zeros((height, width), float)
    fid = np.full((height, width), -1, int)
    zb = np.full((height, width), np.inf)
    out = Frame(width, height, level, fid, zb, f=f)
    out.texfilter = texfilter
    gid = 0
    for obj in sc.objects:
        mesh = sc.meshes[obj.mesh]
        m, cam = object_verts(sc, obj, frame)
        out.verts.append(cam)
        mv = np.array(mesh.verts, float)
        fn = [unit(face_normal(mv[idx])) for _, idx in mesh.faces]
        vn = np.zeros((len(mesh.verts), 3))
        for (_, idx), n in zip(mesh.faces, fn):
            for i in idx:
                vn[i] += n
        vint = np.array([16.0 * (amb + (1 - amb) * max(0.0, float(np.dot(m @ unit(n), light))))
                         for n in vn])
        for k, ((colour, idx), n_model) in enumerate(zip(mesh.faces, fn)):
            g = gid
            gid += 1
            p = cam[idx]
            n = face_normal(p)
            front = float(np.dot(n, -p[0])) > 0
            if shading == "flat":
                lev = float(colour)
            else:
                lev = colour * (amb + (1 - amb) * max(0.0, float(np.dot(m @ n_model, light))))
            tex = sc.textures.get(mesh.texture) if shading == "texture" and mesh.texture else None
            if tex is not None:
                uvs = mesh.uvs[k] if k < len(mesh.uvs) and mesh.uvs[k] else [(0.0, 0.0)] * len(idx)
                ats = [np.array([vint[i], uvs[j][0], uvs[j][1]]) for j, i in enumerate(idx)]
            else:
                ats = list(vint[idx])
            pts, ats = clip_near(list(p), ats, sc.near)
            if len(pts) < 3:
                continue
            pts = np.array(pts)
            xs, ys = project(sc, pts, width, height)
            if tex is not None:
                ats = np.array(ats)
                poly = Poly(g, xs, ys, ats[:, 0], n, p[0], front, lev, pts, ats[:, 1:], tex)
            else:
                poly = Poly(g, xs, ys, np.array(ats), n, p[0], front, lev)
            out.polys[g] = poly
            if not front:
                continue
            _draw(out, poly, shading, cx, cy, f)
    out.level = np.clip(round_half_up(level), 0, 16).astype(int)
    out.level[fid < 0] = 0
    return out


def _draw(out, poly, shading, cx, cy, f):
    mask = fill_mask(poly.xs, poly.ys, out.width, out.height)
    if not mask.any():
        return
    rr, cc = np.nonzero(mask)
    px, py = cc + 0.5, rr + 0.5
    dx, dy = (px - cx) / f, (py - cy) / f
    den = poly.n[0] * dx + poly.n[1] * dy + poly.n[2]
    z = np.dot(poly.n, poly.p0) / den
    near = z < out.z[rr, cc]
    rr, cc, z = rr[near], cc[near], z[near]
    out.z[rr, cc] = z
    out.fid[rr, cc] = poly.gid
    if shading == "gouraud":
        out.level[rr, cc] = gouraud_at(poly.xs, poly.ys, poly.inten, cc + 0.5, rr + 0.5)
    elif shading == "texture" and poly.tex is not None:
        pts = np.stack([dx[near] * z, dy[near] * z, z], axis=1)
        u, v = uv_at(poly, pts)
        t = sample(poly.tex, u, v, out.texfilter)
        out.level[rr, cc] = round_half_up(t / 255.0 * float(round_half_up(poly.level)))
    elif shading == "texture":
        out.level[rr, cc] = round_half_up(poly.level)
    else:
        out.level[rr, cc] = poly.level


def uv_at(poly, pts):
    """Texture coordinates at camera points on the face: the affine map
    of its corners' (u, v) (least squares over the corners)."""
    c = poly.pts
    o = c[0]
    e = c[1:] - o
    a = np.linalg.lstsq(e, poly.uv[1:] - poly.uv[0], rcond=None)[0]
    d = pts - o
    uv = poly.uv[0] + d @ a
    return uv[:, 0], uv[:, 1]


def sample(tex, u, v, texfilter="nearest"):
    """Texel grey 0..255 at texture coordinates (1.0 = one repeat)."""
    s = tex.side
    grey = np.frombuffer(bytes(tex.grey), np.uint8).reshape(s, s).astype(float)
    if tex.fmt == 0:
        grey = np.where(grey >= 128, 255.0, 0.0)
    x, y = np.asarray(u) * s, np.asarray(v) * s
    if texfilter != "bilinear" or tex.fmt == 0:
        return grey[np.floor(y).astype(int) % s, np.floor(x).astype(int) % s]
    x, y = x - 0.5, y - 0.5
    x0, y0 = np.floor(x).astype(int), np.floor(y).astype(int)
    fx, fy = x - x0, y - y0
    g = lambda yy, xx: grey[yy % s, xx % s]  # noqa: E731
    a = g(y0, x0) * (1 - fx) + g(y0, x0 + 1) * fx
    b = g(y0 + 1, x0) * (1 - fx) + g(y0 + 1, x0 + 1) * fx
    return a * (1 - fy) + b * fy


def gouraud_at(xs, ys, inten, px, py):
    """Screen-space scanline interpolation of per-vertex intensities at
    points (px, py) inside the convex polygon: along the edges to the
    row's centre line, then along the row."""
    px = np.asarray(px, float)
    py = np.asarray(py, float)
    res = np.zeros(px.shape)
    n = len(xs)
    for y in np.unique(py):
        hits = []
        for i in range(n):
            ax, ay, ai = xs[i], ys[i], inten[i]
            bx, by, bi = xs[(i + 1) % n], ys[(i + 1) % n], inten[(i + 1) % n]
            if ay == by:
                continue
            t = (y - ay) / (by - ay)
            if 0 <= t <= 1:
                hits.append((ax + (bx - ax) * t, ai + (bi - ai) * t))
        sel = py == y
        if not hits:
            continue
        xl, il = min(hits)
        xr, ir = max(hits)
        if xr > xl:
            res[sel] = il + (ir - il) * (px[sel] - xl) / (xr - xl)
        else:
            res[sel] = il
    return res


# ---- frame bytes ----------------------------------------------------------

def pack(pix, fmt):
    """Pixels (H, W) -> frame bytes in a rast8 format (include/r8fb.h)."""
    pix = np.asarray(pix)
    h, w = pix.shape
    if fmt == "idx8":
        return pix.astype(np.uint8).tobytes()
    bits = (pix != 0).astype(np.uint8)
    if fmt == "row1":
        return np.packbits(bits, axis=1, bitorder="big").tobytes()
    if fmt == "page1":
        pages = (h + 7) // 8
        b = np.zeros((pages * 8, w), np.uint8)
        b[:h] = bits
        b = b.reshape(pages, 8, w)
        return (b * (1 << np.arange(8))[None, :, None]).sum(axis=1).astype(np.uint8).tobytes()
    raise ValueError(fmt)


def unpack(data, fmt, width, height):
    """Frame bytes -> pixels (H, W): levels for idx8, 0/1 for 1 bpp."""
    a = np.frombuffer(bytes(data), np.uint8)
    if fmt == "idx8":
        return a[:width * height].reshape(height, width).astype(int)
    if fmt == "row1":
        rb = (width + 7) // 8
        bits = np.unpackbits(a[:rb * height].reshape(height, rb), axis=1, bitorder="big")
        return bits[:, :width].astype(int)
    if fmt == "page1":
        pages = (height + 7) // 8
        b = a[:pages * width].reshape(pages, width)
        bits = (b[:, None, :] >> np.arange(8)[None, :, None]) & 1
        return bits.reshape(pages * 8, width)[:height].astype(int)
    raise ValueError(fmt)


def frame_bytes(fmt, width, height):
    if fmt == "idx8":
        return width * height
    if fmt == "row1":
        return (width + 7) // 8 * height
    return width * ((height + 7) // 8)
