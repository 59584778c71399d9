"""BSP trees over a mesh's faces for the scene converter (issue 14).

The seed's "BSP Tree Algorithm" for the wall-and-pillar case: a face's
plane splits space; everything on the far side of it from the eye is
drawn first, then the face, then the near side - an exact back-to-front
order with no sort and no depth memory (src/vis_bsp.c walks it).

The tree lives in MODEL space, one per mesh: the order depends only on
where the eye is in model space, so it holds for the object under any
rotation or translation.  Objects that move together (same position,
start angles and spin: the demo's "cross") are merged into one mesh
first (`merge_rigid`), so their faces share one tree; separate objects
are ordered between themselves by the renderer (far to near by the far
end of their bounding spheres, exact when they are apart in depth).

Every node is one face; coplanar faces go to the node's front side
(they cannot hide one another).  A face the splitter's plane crosses is
cut in two (new vertices rounded to integer model units) when splitting
is allowed; else the mesh gets no tree.

The flash array (r8_mesh.bsp, read with R8_RDU8):
    u16 root, u16 depth (the walk's stack entries), then per face f:
    u16 front child, u16 back child (0xFFFF: none), little-endian.
"""
from __future__ import annotations

from . import concave

NONE = 0xFFFF
EPS = 1e-6


class SplitNeeded(Exception):
    pass


def _plane(mesh, f):
    idx = mesh.faces[f][1]
    pts = [mesh.verts[i] for i in idx]
    n = concave.newell(pts)
    c = [sum(p[k] for p in pts) / len(pts) for k in range(3)]
    ln = sum(x * x for x in n) ** 0.5 or 1.0
    n = [x / ln for x in n]
    # rast8 winding is clockwise from outside with y down: Newell's normal
    # of it points inward; the outward normal is its negation
    n = [-x for x in n]
    return n, c


def _dist(plane, p):
    n, c = plane
    return sum(n[k] * (p[k] - c[k]) for k in range(3))


def _classify(mesh, plane, f, tol):
    d = [_dist(plane, mesh.verts[i]) for i in mesh.faces[f][1]]
    front = any(x > tol for x in d)
    back = any(x < -tol for x in d)
    if front and back:
        return "split", d
    return ("back" if back else "front"), d


def _vertex(mesh, p):
    p = tuple(int(round(x)) for x in p)
    try:
        return mesh.verts.index(p)
    except ValueError:
        mesh.verts.append(p)
        return len(mesh.verts) - 1


def _split(mesh, f, d, tol):
    """Cut face f by the plane whose signed distances of f's corners are
    d: face f becomes its front part (pieces beyond 4 corners split
    again), new faces are appended.  Returns (front ids, back ids)."""
    colour, idx = mesh.faces[f]
    fr, bk = [], []
    n = len(idx)
    for k in range(n):
        i, j = idx[k], idx[(k + 1) % n]
        di, dj = d[k], d[(k + 1) % n]
        if di >= -tol:
            fr.append(i)
        if di <= tol:
            bk.append(i)
        if (di > tol and dj < -tol) or (di < -tol and dj > tol):
            t = di / (di - dj)
            a, b = mesh.verts[i], mesh.verts[j]
            v = _vertex(mesh, [a[q] + t * (b[q] - a[q]) for q in range(3)])
            fr.append(v)
            bk.append(v)
    out = []
    for part in (fr, bk):
        part = [v for k, v in enumerate(part) if v != part[k - 1]]
        ids = []
        if len(set(part)) >= 3:
            for pc in concave.split_face(mesh.verts, part, 4, 1e9):
                if f is not None and not ids and not out:
                    mesh.faces[f] = (colour, pc)
                    ids.append(f)
                else:
                    mesh.faces.append((colour, pc))
                    ids.append(len(mesh.faces) - 1)
        out.append(ids)
    if not out[0]:                    # f's slot must stay a real face
        raise SplitNeeded("degenerate split")
    return out[0], out[1]


def build(mesh, allow_split=False, tol=0.01):
    """Build the tree over mesh (scene.Mesh), splitting faces (changing
    mesh.faces/verts) if allow_split.  Returns (front, back, root, depth)
    lists, or raises SplitNeeded."""
    front, back = {}, {}

    def score(cands, faces):
        best = None
        for s in cands:
            pl = _plane(mesh, s)
            nf = nb = ns = 0
            for g in faces:
                if g == s:
                    continue
                k, _ = _classify(mesh, pl, g, tol)
                if k == "split":
                    ns += 1
                elif k == "front":
                    nf += 1
                else:
                    nb += 1
            sc = (ns, abs(nf - nb))
            if best is None or sc < best[0]:
                best = (sc, s)
        return best[1]

    def rec(faces, depth):
        if not faces:
            return NONE, depth
        s = score(faces if len(faces) <= 48 else faces[:: max(1, len(faces) // 48)], faces)
        pl = _plane(mesh, s)
        fs, bs = [], []
        for g in faces:
            if g == s:
                continue
            k, d = _classify(mesh, pl, g, tol)
            if k == "front":
                fs.append(g)
            elif k == "back":
                bs.append(g)
            else:
                if not allow_split:
                    raise SplitNeeded(f"face {g} crosses the plane of face {s}")
                a, b = _split(mesh, g, d, tol)
                fs += a
                bs += b
        fr, d1 = rec(fs, depth + 1)
        bk, d2 = rec(bs, depth + 1)
        front[s], back[s] = fr, bk
        return s, max(d1, d2)

    root, depth = rec(list(range(len(mesh.faces))), 1)
    n = len(mesh.faces)
    if len(mesh.verts) > 255:
        raise SplitNeeded(f"{len(mesh.verts)} vertices after splitting (at most 255)")
    return [front[f] for f in range(n)], [back[f] for f in range(n)], root, depth


def _on_edge(a, b, p):
    """p lies on segment ab strictly between its ends (integer points)."""
    ab = [b[k] - a[k] for k in range(3)]
    ap = [p[k] - a[k] for k in range(3)]
    cr = (ab[1] * ap[2] - ab[2] * ap[1], ab[2] * ap[0] - ab[0] * ap[2], ab[0] * ap[1] - ab[1] * ap[0])
    if any(cr):
        return False
    t = sum(ab[k] * ap[k] for k in range(3))
    return 0 < t < sum(x * x for x in ab)


def fix_tjunctions(mesh, tree):
    """A split puts new vertices on edges of neighbouring faces that were
    not split (T-junctions: after rounding to subpixels the two sides of
    the edge no longer meet, a pixel crack or overlap).  Each such vertex
    is inserted into the neighbour's edge; a face that then has more than
    4 corners is cut into convex pieces, the extra pieces put into the
    tree as coplanar nodes on the face's front side (coplanar faces cannot
    hide one another).  Returns the tree with the new faces."""
    fr, bk, root, depth = tree
    fr, bk = list(fr), list(bk)
    extra = 0
    for f in range(len(mesh.faces)):
        colour, idx = mesh.faces[f]
        poly = []
        n = len(idx)
        for k in range(n):
            a, b = idx[k], idx[(k + 1) % n]
            poly.append(a)
            pa, pb = mesh.verts[a], mesh.verts[b]
            on = [v for v in range(len(mesh.verts)) if v not in idx and _on_edge(pa, pb, mesh.verts[v])]
            on.sort(key=lambda v: sum((mesh.verts[v][q] - pa[q]) ** 2 for q in range(3)))
            poly += on
        if len(poly) == n:
            continue
        pieces = concave.split_face(mesh.verts, poly, 4, 1e9)
        mesh.faces[f] = (colour, pieces[0])
        for pc in pieces[1:]:
            mesh.faces.append((colour, pc))
            g = len(mesh.faces) - 1
            fr.append(fr[f])
            bk.append(NONE)
            fr[f] = g
            extra += 1
    return fr, bk, root, depth + extra


def to_bytes(tree):
    fr, bk, root, depth = tree
    b = bytearray([root & 255, root >> 8, depth & 255, depth >> 8])
    for a, c in zip(fr, bk):
        b += bytes([a & 255, a >> 8, c & 255, c >> 8])
    return bytes(b)


def order(tree, mesh, eye):
    """Back-to-front face order for an eye in model space (the C walk's,
    for tests)."""
    fr, bk, root, _ = tree
    out = []

    def rec(f):
        if f == NONE:
            return
        if _dist(_plane(mesh, f), eye) > 0:
            rec(bk[f]); out.append(f); rec(fr[f])
        else:
            rec(fr[f]); out.append(f); rec(bk[f])
    rec(root)
    return out


def merge_rigid(sc):
    """Merge objects that move together (same mesh-independent pose:
    position, start angles, spin) into one mesh each; returns the number
    of objects merged away.  Only objects whose meshes are used once."""
    from .scene import Mesh, Obj, _convex_closed
    uses = {}
    for o in sc.objects:
        uses[o.mesh] = uses.get(o.mesh, 0) + 1
    groups = {}
    for o in sc.objects:
        groups.setdefault((o.pos, o.rot, o.spin), []).append(o)
    merged = 0
    objs = []
    done = set()
    for o in sc.objects:
        key = (o.pos, o.rot, o.spin)
        g = groups[key]
        if key in done:
            continue
        if len(g) < 2 or any(uses[x.mesh] != 1 for x in g) or \
                sum(len(sc.meshes[x.mesh].verts) for x in g) > 255:
            objs.append(o)
            continue
        done.add(key)
        m = Mesh("_".join(x.mesh for x in g))
        for x in g:
            src = sc.meshes.pop(x.mesh)
            base = len(m.verts)
            m.verts += list(src.verts)
            m.faces += [(c, [i + base for i in idx]) for c, idx in src.faces]
        m.convex = _convex_closed(m)
        sc.meshes[m.name] = m
        objs.append(Obj(m.name, o.pos, o.rot, o.spin))
        merged += len(g) - 1
    sc.objects = objs
    return merged


def attach(sc):
    """Give every mesh of scene sc a tree (mesh.bsp = bytes) where one
    exists: with face splits when the scene asks for BSP (sc.bsp), else
    only if no face needs splitting (then the mesh's faces are
    unchanged).  Returns {mesh name: faces added by splits}."""
    import copy
    added = {}
    if getattr(sc, "bsp", False):
        merge_rigid(sc)
    for name, m in sc.meshes.items():
        trial = copy.deepcopy(m)
        try:
            tree = build(trial, allow_split=getattr(sc, "bsp", False))
            if len(trial.faces) != len(m.faces):
                tree = fix_tjunctions(trial, tree)
        except SplitNeeded:
            m.bsp = None
            continue
        added[name] = len(trial.faces) - len(m.faces)
        m.verts, m.faces = trial.verts, trial.faces
        if added[name]:
            from .scene import _convex_closed
            m.convex = _convex_closed(m)
        m.bsp = to_bytes(tree)
    return added
