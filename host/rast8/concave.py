"""Concave and non-planar face splitting for the scene converter (issue 13).

The C renderer draws faces of 3 or 4 vertices that are planar and convex
(its scan converter walks one left and one right edge chain).  A face
that is not - an OBJ n-gon with a notch, or a quad whose corners were
rounded off their plane (the teapot's lid: the lathe's smallest rings
round to integer coordinates) - is split here, once, when the model is
converted, into convex pieces of at most 4 vertices.

The seed's method ("Concave Polygon Splitting Algorithm"): from a convex
vertex, walk the edge list while the piece so far stays convex and its
closing edge crosses no edge of the polygon; output that largest convex
piece, drop its inner vertices and go on with the rest.  As the seed
suggests, the walk is tried from every start vertex and the start that
gives the fewest pieces is kept.  Pieces are also capped at 4 vertices
(the renderer's face size).  `compare()` measures it against ear clipping
(always n - 2 triangles) and the old fan on the seed's own criterion,
the number of pieces.

Non-planar quads: a quad whose corners are off one plane is folded; seen
from some directions its projection is concave (the scan converter then
loses the pixels of the notch) while it still faces the eye.  How wide
that range of directions is grows with the fold: the largest angle
between a corner's normal (the cross product of its two edges) and the
face's normal.  A quad folded by more than FOLD_DEG becomes two
triangles along its shorter diagonal.  Integer rounding folds almost
every curved-surface quad a little (the torus: 3.4 degrees at most, and
then only when seen almost edge-on); the teapot's lid ring (the lathe's
smallest ring rounded to a 1-unit edge) folds its 4 quads by 12.5
degrees: those are split.
"""
from __future__ import annotations

import math

FOLD_DEG = 8.0      # largest corner-normal angle a quad may have (degrees)


def newell(pts):
    """Newell's normal of a 3D polygon (robust for concave polygons)."""
    nx = ny = nz = 0.0
    n = len(pts)
    for i in range(n):
        x0, y0, z0 = pts[i]
        x1, y1, z1 = pts[(i + 1) % n]
        nx += (y0 - y1) * (z0 + z1)
        ny += (z0 - z1) * (x0 + x1)
        nz += (x0 - x1) * (y0 + y1)
    return (nx, ny, nz)


def planarity(pts):
    """Largest distance (model units) of a corner from the mean plane."""
    n = newell(pts)
    ln = math.sqrt(sum(c * c for c in n))
    if ln == 0:
        return 0.0
    n = [c / ln for c in n]
    cx = [sum(p[k] for p in pts) / len(pts) for k in range(3)]
    return max(abs(sum(n[k] * (p[k] - cx[k]) for k in range(3))) for p in pts)


def fold(pts):
    """Largest angle (degrees) between a corner normal and the face's
    Newell normal; corners with a zero-length edge are skipped."""
    n = newell(pts)
    ln = math.sqrt(sum(c * c for c in n))
    if ln == 0:
        return 0.0
    worst = 0.0
    m = len(pts)
    for k in range(m):
        a, b, c = pts[k - 1], pts[k], pts[(k + 1) % m]
        e1 = [b[i] - a[i] for i in range(3)]
        e2 = [c[i] - b[i] for i in range(3)]
        cr = (e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0])
        lc = math.sqrt(sum(x * x for x in cr))
        if lc == 0:
            continue
        d = sum(cr[i] * n[i] for i in range(3)) / (lc * ln)
        worst = max(worst, math.degrees(math.acos(max(-1.0, min(1.0, d)))))
    return worst


def to2d(pts):
    """Project onto the plane of the polygon's Newell normal; the 2D
    polygon keeps the 3D winding as counter-clockwise (positive area)."""
    n = newell(pts)
    ax = max(range(3), key=lambda k: abs(n[k]))
    u, v = [(1, 2), (2, 0), (0, 1)][ax]
    out = [(p[u], p[v]) for p in pts]
    if n[ax] < 0:
        out = [(x, -y) for x, y in out]
    return out


def _cross(o, a, b):
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def area2(p):
    return sum(p[i][0] * p[(i + 1) % len(p)][1] - p[(i + 1) % len(p)][0] * p[i][1] for i in range(len(p)))


def is_convex2(p, eps=1e-9):
    """Counter-clockwise and convex (no reflex corner; collinear allowed)."""
    n = len(p)
    if n < 3 or area2(p) <= eps:
        return False
    return all(_cross(p[i], p[(i + 1) % n], p[(i + 2) % n]) >= -eps for i in range(n))


def _seg_cross(a, b, c, d):
    """Segments ab and cd cross at a point inside both (not at an end)."""
    d1, d2 = _cross(c, d, a), _cross(c, d, b)
    d3, d4 = _cross(a, b, c), _cross(a, b, d)
    return ((d1 > 0 > d2) or (d1 < 0 < d2)) and ((d3 > 0 > d4) or (d3 < 0 < d4))


def _inside_or_on(p, poly):
    """p inside or on the boundary of convex CCW poly."""
    n = len(poly)
    return all(_cross(poly[i], poly[(i + 1) % n], p) >= 0 for i in range(n))


def _piece_ok(piece, rest, pts):
    """Convex piece (list of positions in pts) whose closing edge is a
    diagonal of the remaining polygon `rest`: no other vertex in it, no
    edge crossing it."""
    q = [pts[i] for i in piece]
    if not is_convex2(q):
        return False
    a, b = pts[piece[-1]], pts[piece[0]]
    ps = set(piece)
    for i in rest:
        if i not in ps and pts[i] not in q and _inside_or_on(pts[i], q):
            return False
    m = len(rest)
    for k in range(m):
        c, d = pts[rest[k]], pts[rest[(k + 1) % m]]
        if _seg_cross(a, b, c, d):
            return False
    return True


def seed_split(pts, maxv=4, start=0):
    """The seed's greedy split of the simple CCW 2D polygon pts (indices
    into pts), starting the walk at position `start`.  Returns a list of
    index lists, or None if it gets stuck (not a simple polygon)."""
    rest = list(range(len(pts)))
    rest = rest[start:] + rest[:start]
    pieces = []
    guard = 0
    while len(rest) > maxv or not is_convex2([pts[i] for i in rest]):
        guard += 1
        if guard > 4 * len(pts):
            return None
        m = len(rest)
        best = None
        for s in range(m):             # first convex start vertex from here
            piece = [rest[s], rest[(s + 1) % m], rest[(s + 2) % m]]
            if not _piece_ok(piece, rest, pts):
                continue
            k = 3
            while k < min(maxv, m - 1):
                cand = piece + [rest[(s + k) % m]]
                if not _piece_ok(cand, rest, pts):
                    break
                piece = cand
                k += 1
            best = (s, piece)
            break
        if best is None:
            return None
        s, piece = best
        pieces.append(piece)
        inner = set(piece[1:-1])
        rest = [i for i in rest if i not in inner]
        if len(rest) < 3:
            return pieces
    pieces.append(rest)
    return pieces


def ear_clip(pts):
    """Ear clipping: n - 2 triangles of the simple CCW polygon pts."""
    rest = list(range(len(pts)))
    tris = []
    while len(rest) > 3:
        m = len(rest)
        for k in range(m):
            a, b, c = rest[k - 1], rest[k], rest[(k + 1) % m]
            if _cross(pts[a], pts[b], pts[c]) <= 0:
                continue
            tri = [pts[a], pts[b], pts[c]]
            if any(_inside_or_on(pts[i], tri) and pts[i] not in tri for i in rest if i not in (a, b, c)):
                continue
            tris.append([a, b, c])
            rest.pop(k)
            break
        else:
            return None
    tris.append(rest)
    return tris


def fan(n):
    """The converter's old split: a fan from vertex 0."""
    return [[0, k, k + 1] for k in range(1, n - 1)]


def split_polygon(pts2, maxv=4):
    """Fewest pieces from the seed's method tried at every start; ear
    clipping if the seed's walk fails on every start (it cannot on a
    simple polygon, but a self-touching one is taken apart anyway)."""
    n = len(pts2)
    if n <= maxv and is_convex2(pts2):
        return [list(range(n))]
    best = None
    for s in range(n):
        p = seed_split(pts2, maxv, s)
        if p is not None and (best is None or len(p) < len(best)):
            best = p
    return best if best is not None else ear_clip(pts2)


def split_face(verts, idx, maxv=4, tol=FOLD_DEG):
    """Split face idx (vertex indices into verts, rast8 winding) into
    planar convex pieces of at most maxv vertices, same winding.  Returns
    a list of index lists (the face itself when it is fine)."""
    pts = [verts[i] for i in idx]
    n = len(idx)
    if n == 3:
        return [list(idx)]
    p2 = to2d(pts)
    if area2(p2) < 0:            # cannot happen (to2d orients), kept safe
        p2 = [(x, -y) for x, y in p2]
    flat = fold(pts) <= tol
    if n <= maxv and flat and is_convex2(p2):
        return [list(idx)]
    if n == 4:
        # two triangles: through the reflex corner if there is one, else
        # along the shorter diagonal
        refl = [k for k in range(4) if _cross(p2[k - 1], p2[k], p2[(k + 1) % 4]) < 0]
        if refl:
            k = refl[0]
        else:
            d0 = sum((pts[0][j] - pts[2][j]) ** 2 for j in range(3))
            d1 = sum((pts[1][j] - pts[3][j]) ** 2 for j in range(3))
            k = 0 if d0 <= d1 else 1
        a, b, c, d = (idx[(k + j) % 4] for j in range(4))
        return [[a, b, c], [a, c, d]]
    pieces = split_polygon(p2, maxv)
    out = []
    for pc in pieces:
        sub = [idx[i] for i in pc]
        if len(sub) == 4 and fold([verts[i] for i in sub]) > tol:
            out.extend(split_face(verts, sub, maxv, tol))
        else:
            out.append(sub)
    return out


def compare(pts2, maxv=4):
    """Pieces each method gives for one CCW 2D polygon: the seed's
    criterion (fewer is better)."""
    seed0 = seed_split(pts2, maxv, 0)
    return {
        "fan": len(pts2) - 2,
        "ear": len(ear_clip(pts2) or []),
        "seed_first_start": len(seed0) if seed0 else None,
        "seed_best_start": len(split_polygon(pts2, maxv)),
    }


def split_mesh(mesh, tol=FOLD_DEG):
    """Split every face of mesh (scene.Mesh) that is not planar and
    convex; returns the number of faces added."""
    uvs = getattr(mesh, "uvs", None) or []
    out, out_uv = [], []
    for k, (colour, idx) in enumerate(mesh.faces):
        uv = uvs[k] if k < len(uvs) else None
        corner = dict(zip(idx, uv)) if uv else None    # pieces keep the corners' u, v
        for pc in split_face(mesh.verts, idx, 4, tol):
            out.append((colour, pc))
            out_uv.append([corner[i] for i in pc] if corner else None)
    added = len(out) - len(mesh.faces)
    mesh.faces = out
    if uvs:
        mesh.uvs = out_uv
    return added
