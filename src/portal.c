/* portal.c - the portal renderer (R8_VIS_PORTAL, r8portal.h).
 *
 * It runs the ordinary renderer's frame machinery on one internal object
 * (the world mesh, identity pose): the same camera transform, the same
 * lazy vertex transform (a vertex is transformed when the first front
 * face that needs it comes), the same near-plane and guard-band clipper,
 * the same scan converter.  What it replaces is the order and the
 * clipping: instead of every face into band buckets, it walks sectors
 * through portals (breadth first from the camera's sector), gives each
 * visit a screen region (one span per row: a portal seen through a
 * region is convex inside a convex region, so one span per row stays
 * exact), and draws each wall's spans cut to its visit's region.  There
 * is no depth memory and no sort: regions of one frame never overlap and
 * faces of one convex sector never overlap on screen.
 *
 * Where this differs from the seed's pseudo-code (docs/visibility.md):
 * the region of a portal is the portal's pixels INSIDE the region it was
 * seen through (the seed passes the portal's own polygon on, and never
 * clips what it draws to it); a sector is entered again through another
 * portal as a separate visit, and the visits are bounded (the seed
 * recurses without limit: no stack to spare on an 8-bit part); the
 * vertices of a sector are transformed once, not per polygon; the camera's
 * sector is found by the renderer (deepest inside), not given. */
#include <stddef.h>
#include <string.h>
#include "r8int.h"
#include "r8portal.h"
#include "portal_int.h"

#ifndef R8_NO_PORTAL

static pstate *pstate_of(const r8_render *r)
{
    r8_u8 *w = r->work;
    w += (PALIGN - ((unsigned)((size_t)(void *)w & (PALIGN - 1)))) & (PALIGN - 1);
    return (pstate *)(void *)w;
}

int r8_portal_init(r8_render *r, const r8_render_cfg *cfg, r8_u8 *work,
                   unsigned work_size)
{
    r8_render_cfg ic, oc;
    pstate *ps;
    r8_u8 *p;
    unsigned need = r8_portal_ram(cfg), n;
    if (!need)
        return -1;
    if (work_size < need)
        return -2;
    r->cfg = *cfg;
    r->work = work;
    r->work_size = work_size;
    ps = pstate_of(r);
    if (!r8_portal_inner(cfg, &ic, &ps->scene, &ps->obj))
        return -1;
    ic.scene = &ps->scene;
    ps->world = cfg->scene->world;
    ps->skip = r8_portal_skip(cfg);
    ps->nmov = 0;
    if (r8_portal_objcfg(cfg, &oc, &ps->oscene))
        ps->nmov = ps->oscene.nobjects;
    p = (r8_u8 *)(void *)ps + R8_PALIGN(sizeof(pstate));
    ps->visit = (pvisit *)(void *)p;
    p += R8_PALIGN(sizeof(pvisit) * R8_PORTAL_VISITS);
    ps->rows = (r8_s16 *)(void *)p;
    ps->rows_cap = (r8_u16)(R8_PORTAL_ROWS * (unsigned)cfg->height);
    p += R8_PALIGN(4u * R8_PORTAL_ROWS * (unsigned)cfg->height);
    ps->draw = (pdraw *)(void *)p;
    ps->maxdraw = R8_PORTAL_DRAWS;
    p += R8_PALIGN(sizeof(pdraw) * R8_PORTAL_DRAWS);
    if (ps->nmov) {
        ps->osec = p;
        ps->oorder = p + ps->nmov;
        p += R8_PALIGN(2u * ps->nmov);
        ps->okey = (r8_s16 *)(void *)p;
        p += R8_PALIGN(2u * r8_portal_okeys(&ps->oscene));
    }
    n = r8_render_ram(&ic);
    if (r8_render_init(&ps->inner, &ic, p, n) != 0)
        return -2;
    p += R8_PALIGN(n);
    if (ps->nmov) {
        oc.scene = &ps->oscene;
        if (r8_render_init(&ps->oinner, &oc, p, (unsigned)(work_size - (unsigned)(p - work))) != 0)
            return -2;
    }
    r->state = ps->inner.state;     /* r8_render_stats_get works as usual */
    ps->nvisit = 0;
    ps->ndraw = 0;
    memset(&ps->stats, 0, sizeof ps->stats);
    ps->stats.sector = 255;
    return 0;
}

r8_u8 r8_portal_locate(const r8_world *w, r8_s16 x, r8_s16 y, r8_s16 z)
{
    const r8_mesh *me = w->mesh;
    r8_s32 best = 0;
    r8_u8 s, bs = 0;
    for (s = 0; s < w->nsectors; s++) {
        const r8_sector *sec = &w->sectors[s];
        r8_u16 f0[2], k;
        r8_u8 nf[2], part;
        r8_s32 worst = 0x7FFFFFFFL;
        f0[0] = R8_RDU16(&sec->wall0);
        f0[1] = R8_RDU16(&sec->portal0);
        nf[0] = R8_RDU8(&sec->nwalls);
        nf[1] = R8_RDU8(&sec->nportals);
        for (part = 0; part < 2; part++)
            for (k = f0[part]; k < (r8_u16)(f0[part] + nf[part]); k++) {
                const r8_s16 *v = me->verts + 3u * R8_RDU8(&me->faces[k].v[0]);
                const r8_s16 *n = me->normals + 3u * k;
                r8_s32 d = r8_mul16(R8_RDS16(n), (r8_s16)(x - R8_RDS16(v)));
                d += r8_mul16(R8_RDS16(n + 1), (r8_s16)(y - R8_RDS16(v + 1)));
                d += r8_mul16(R8_RDS16(n + 2), (r8_s16)(z - R8_RDS16(v + 2)));
                if (d < worst) {
                    worst = d;
                    if (s && worst <= best) {
                        part = 2;       /* cannot win: the next sector */
                        break;
                    }
                }
            }
        if (s == 0 || worst > best) {
            best = worst;
            bs = s;
        }
    }
    return bs;
}

/* Rows [*top, *bot) of polygon vp[0..n) inside the frame; 0 if none. */
static int poly_rows(const r8_state *st, const r8_s16 *const *vp, r8_u8 n,
                     r8_s16 *top, r8_s16 *bot)
{
    r8_s16 ymin = vp[0][1], ymax = ymin;
    r8_u8 i;
    for (i = 1; i < n; i++) {
        if (vp[i][1] < ymin) ymin = vp[i][1];
        if (vp[i][1] > ymax) ymax = vp[i][1];
    }
    *top = R8_FLOOR16(ymin + 7);
    *bot = R8_FLOOR16(ymax + 7);
    if (*top < 0)
        *top = 0;
    if (*bot > st->height)
        *bot = st->height;
    return *top < *bot;
}

/* Face id g of renderer state st (the world's, or the objects'):
 * its vertex pointers into vp; returns the vertex count. */
static r8_u8 set_vp(const r8_state *st, r8_u16 g, const r8_s16 **vp)
{
    const r8_scene *sc = st->scene;
    const r8_mesh *me;
    const r8_s16 *base;
    r8_u8 n, j, i = 0, vsh = R8_VSH(st);
    if (g >= st->nfaces) {
        const r8_cpoly *cp = &st->cpoly[g - st->nfaces];
        for (j = 0; j < cp->n; j++)
            vp[j] = st->sv + ((unsigned)cp->idx[j] << vsh);
        return cp->n;
    }
    while (i + 1 < sc->nobjects && g >= st->obj[i + 1].fbase)
        i++;
    me = sc->objects[i].mesh;
    g = (r8_u16)(g - st->obj[i].fbase);
    base = st->sv + ((unsigned)st->obj[i].vbase << vsh);
    n = R8_RDU8(&me->faces[g].n);
    for (j = 0; j < n; j++)
        vp[j] = base + ((unsigned)R8_RDU8(&me->faces[g].v[j]) << vsh);
    return n;
}

/* A new visit of sector `sec`: the region of polygon vp[0..n) inside
 * the region of visit `from` (from == 255: the whole screen).  0 if it
 * is empty or does not fit. */
static int add_visit(pstate *ps, r8_state *st, r8_u8 sec, r8_u8 from,
                     const r8_s16 *const *vp, r8_u8 n)
{
    pvisit *v;
    r8_s16 top, bot, y, *out;
    r8_scan s;
    r8_span sp;
    r8_s16 first = 0x7FFF, last = -1;
    if (ps->nvisit >= R8_PORTAL_VISITS) {
        ps->stats.dropped++;
        return 0;
    }
    v = &ps->visit[ps->nvisit];
    if (from == 255) {
        top = 0;
        bot = st->height;
    } else {
        const pvisit *pv = &ps->visit[from];
        if (!poly_rows(st, vp, n, &top, &bot))
            return 0;
        if (top < pv->ytop) top = pv->ytop;
        if (bot > pv->ybot) bot = pv->ybot;
        if (top >= bot)
            return 0;
    }
    if ((r8_u16)(bot - top) > (r8_u16)(ps->rows_cap - ps->rows_used)) {
        ps->stats.dropped++;
        return 0;
    }
    out = ps->rows + 2u * ps->rows_used;
    if (from == 255) {
        for (y = top; y < bot; y++) {
            out[2 * y] = 0;
            out[2 * y + 1] = st->width;
        }
        first = top;
        last = (r8_s16)(bot - 1);
    } else {
        const pvisit *pv = &ps->visit[from];
        const r8_s16 *pr = ps->rows + 2u * pv->row0;
        r8_u8 j;
        for (y = top; y < bot; y++)
            out[2 * (y - top)] = out[2 * (y - top) + 1] = 0;
        for (j = 0; j < n; j++)
            s.c.vp[j] = vp[j];
        if (r8_scanx_begin(&s.c, n, top)) {
            s.attrs = 0;
            r8_scan_attrs(&s);
            while (r8_scan_next(&s, bot, 0, &sp)) {
                r8_s16 a = sp.x0, b = sp.x1, k = (r8_s16)(sp.y - pv->ytop);
                if (a < pr[2 * k]) a = pr[2 * k];
                if (b > pr[2 * k + 1]) b = pr[2 * k + 1];
                if (a < b) {
                    out[2 * (sp.y - top)] = a;
                    out[2 * (sp.y - top) + 1] = b;
                    if (sp.y < first) first = sp.y;
                    last = sp.y;
                }
            }
        }
        if (last < 0)
            return 0;
        /* keep the rows that have pixels */
        if (first > top) {
            for (y = first; y <= last; y++) {
                out[2 * (y - first)] = out[2 * (y - top)];
                out[2 * (y - first) + 1] = out[2 * (y - top) + 1];
            }
        }
    }
    v->ytop = first;
    v->ybot = (r8_s16)(last + 1);
    v->row0 = ps->rows_used;
    v->sector = sec;
    ps->rows_used = (r8_u16)(ps->rows_used + (r8_u16)(last + 1 - first));
    ps->nvisit++;
    return 1;
}

/* Face f of object ob (its transform o in renderer state st): cull,
 * vertex pointers (transforming vertices on first use), clip.  Returns
 * the polygon's id and its vertex count in *n, or R8_FID_END when
 * nothing of it is in front. */
static r8_u16 face_in(pstate *ps, r8_state *st, const r8_objx *o, const r8_object *ob,
                      r8_u16 f, const r8_s16 **vp, r8_u8 *n, int portal)
{
    const r8_mesh *me = ob->mesh;
    const r8_face *fc = &me->faces[f];
    r8_u8 vi[R8_MAX_FACE_VERTS], j, clip = 0, vsh = R8_VSH(st);
    r8_s32 zsum;
    *n = R8_RDU8(&fc->n);
    if (*n < 3 || *n > R8_MAX_FACE_VERTS)
        return (r8_u16)R8_FID_END;
    vi[0] = R8_RDU8(&fc->v[0]);
    if (!r8_cull_front(o, me->verts + 3u * vi[0], f))
        return (r8_u16)R8_FID_END;
    for (j = 0; j < *n; j++) {
        r8_u16 g;
        vi[j] = R8_RDU8(&fc->v[j]);
        g = (r8_u16)(o->vbase + vi[j]);
        vp[j] = st->sv + ((unsigned)g << vsh);
        if (vp[j][0] == R8_VX_TODO) {
            r8_tf_vertex(st, o, me->verts + 3u * vi[j], g);
            if (st != (r8_state *)ps->inner.state)
                ps->stats.overts++;
        }
        if (vp[j][0] == R8_VX_CLIP)
            clip = 1;
    }
    if (!clip)
        return (r8_u16)(o->fbase + f);
#ifdef R8_NO_CLIP
    st->dropped++;
    return (r8_u16)R8_FID_END;
#else
    {
        r8_cpoly *cp;
        if (st->nclipped >= st->nclip) {
            st->dropped++;
            return (r8_u16)R8_FID_END;
        }
        cp = &st->cpoly[st->nclipped];
        if (portal) {
            /* a portal is cut at z = 1 unit, not at the near plane: a
             * ray that crosses it nearer than znear still sees the
             * sector behind (whose walls are cut at znear as usual) */
            r8_s32 zn = st->zn16;
            int ok;
            st->zn16 = (r8_s32)1 << R8_CFRAC;
            ok = r8_clip_face(st, o, ob, f, vi, *n, cp, &zsum);
            st->zn16 = zn;
            if (!ok)
                return (r8_u16)R8_FID_END;
        } else if (!r8_clip_face(st, o, ob, f, vi, *n, cp, &zsum))
            return (r8_u16)R8_FID_END;
        *n = cp->n;
        for (j = 0; j < *n; j++)
            vp[j] = st->sv + ((unsigned)cp->idx[j] << vsh);
        st->nclipped++;
        st->npoly++;
        return (r8_u16)(st->nfaces + st->nclipped - 1u);
    }
#endif
}

/* Camera-space depth (units) of face f of object o: the mean z of its
 * corners, for painter's order inside a mesh that is not convex. */
static r8_s16 face_key(const r8_objx *o, const r8_mesh *me, r8_u16 f)
{
    const r8_face *fc = &me->faces[f];
    r8_u8 j, n = R8_RDU8(&fc->n);
    r8_s32 z = 0;
    for (j = 0; j < n; j++) {
        const r8_s16 *v = me->verts + 3u * R8_RDU8(&fc->v[j]);
        z += R8_ASR32C(r8_mul16(o->m.m[6], R8_RDS16(v)) + r8_mul16(o->m.m[7], R8_RDS16(v + 1)) +
                       r8_mul16(o->m.m[8], R8_RDS16(v + 2)), 14);
    }
    z = z / (r8_s32)n + R8_ASR32C(o->t.z, R8_CFRAC);
    if (z > 32767)
        z = 32767;
    if (z < -32767)
        z = -32767;
    return (r8_s16)z;
}

/* Is sector sec visited this frame? */
static int seen(const pstate *ps, r8_u8 sec)
{
    r8_u8 k;
    for (k = 0; k < ps->nvisit; k++)
        if (ps->visit[k].sector == sec)
            return 1;
    return 0;
}

/* The movable objects (after the portal walk): each one's sector from
 * its origin; those in sectors seen are transformed (the ordinary
 * frame set-up on a one-object view of the objects' scene), their
 * vertices marked to transform on first use, and put in oorder, far
 * to near by the depth of their origin.  Returns how many. */
static r8_u8 objects_frame(pstate *ps, const r8_camera *cam)
{
    r8_state *os = (r8_state *)ps->oinner.state;
    r8_object *objs = ps->oscene.objects;
    r8_objx *ox = os->obj;
    r8_u8 i, k, no = 0, vsh = R8_VSH(os);
    os->npoly = 0;
    os->sv_used = os->nverts;
    os->nclipped = 0;
    os->dropped = 0;
    os->pool_used = 0;
    for (i = 0; i < ps->nmov; i++) {
        const r8_pose *pp = &objs[i].pose;
        r8_u8 sec = 255;
        ps->osec[i] = 255;
        if (pp->flags & R8_POSE_HIDDEN)
            continue;
        if (pp->x >= -16383 && pp->x <= 16383 && pp->y >= -16383 && pp->y <= 16383 &&
            pp->z >= -16383 && pp->z <= 16383)
            sec = r8_portal_locate(ps->world, pp->x, pp->y, pp->z);
        if (sec == 255 || !seen(ps, sec)) {
            ps->stats.unseen++;       /* not transformed */
            continue;
        }
        ps->oscene.objects = objs + i;
        ps->oscene.nobjects = 1;
        os->obj = ox + i;
        r8_tf_frame(os, cam);
        os->obj = ox;
        ps->oscene.objects = objs;
        ps->oscene.nobjects = ps->nmov;
        {
            r8_s16 *sv = os->sv + ((unsigned)ox[i].vbase << vsh);
            r8_u16 v, nv = objs[i].mesh->nverts;
            for (v = 0; v < nv; v++, sv += 1u << vsh)
                *sv = R8_VX_TODO;
        }
        ps->osec[i] = sec;
        /* far to near (ties: scene order) */
        for (k = no; k > 0 && ox[ps->oorder[k - 1]].t.z < ox[i].t.z; k--)
            ps->oorder[k] = ps->oorder[k - 1];
        ps->oorder[k] = i;
        no++;
    }
    ps->stats.objects = no;
    return no;
}

/* Visit k's objects: their front faces (clipped to the visit's region
 * when drawn), object after object far to near; painter's order of the
 * faces inside a mesh that is not convex. */
static void objects_visit(pstate *ps, r8_u8 k, r8_u8 no)
{
    r8_state *os = (r8_state *)ps->oinner.state;
    const r8_object *objs = ps->oscene.objects;
    pvisit *v = &ps->visit[k];
    const r8_s16 *vp[R8_SCAN_MAXV];
    r8_u8 j, n;
    v->o0 = ps->ndraw;
    for (j = 0; j < no; j++) {
        r8_u8 i = ps->oorder[j];
        const r8_object *ob = &objs[i];
        const r8_mesh *me = ob->mesh;
        const r8_objx *o = &os->obj[i];
        r8_u16 f, d0 = ps->ndraw, a, b;
        if (ps->osec[i] != v->sector)
            continue;
        for (f = 0; f < me->nfaces; f++) {
            r8_u16 g = face_in(ps, os, o, ob, f, vp, &n, 0);
            r8_s16 top, bot;
            pdraw *d;
            if (g == (r8_u16)R8_FID_END || !poly_rows(os, vp, n, &top, &bot) ||
                top >= v->ybot || bot <= v->ytop)
                continue;
            if (ps->ndraw >= ps->maxdraw) {
                ps->stats.dropped++;
                continue;
            }
            d = &ps->draw[ps->ndraw];
            d->g = g;
            d->visit = (r8_u8)(k | PD_OBJ);
            if (g >= os->nfaces)
                d->level = os->cpoly[g - os->nfaces].level;
            else
                d->level = r8_face_level(os, o, ob, f);
            if (!me->convex)
                ps->okey[ps->ndraw - d0] = face_key(o, me, f);
            ps->ndraw++;
            ps->stats.opolys++;
            if (g < os->nfaces)
                os->npoly++;
        }
        if (me->convex)
            continue;
        /* insertion sort of this object's draws, far (large z) first */
        for (a = 1; a < (r8_u16)(ps->ndraw - d0); a++) {
            pdraw t;
            r8_s16 key = ps->okey[a];
            t = ps->draw[d0 + a];
            for (b = a; b > 0 && ps->okey[b - 1] < key; b--) {
                ps->draw[d0 + b] = ps->draw[d0 + b - 1];
                ps->okey[b] = ps->okey[b - 1];
            }
            ps->draw[d0 + b] = t;
            ps->okey[b] = key;
        }
    }
    v->no = (r8_u16)(ps->ndraw - v->o0);
}

void r8_portal_frame(r8_render *r, const r8_camera *cam)
{
    pstate *ps = pstate_of(r);
    r8_state *st = (r8_state *)ps->inner.state;
    const r8_world *w = ps->world;
    const r8_s16 *vp[R8_SCAN_MAXV];
    r8_u8 k, n, no;
    st->npoly = 0;
    st->sv_used = st->nverts;
    st->nclipped = 0;
    st->dropped = 0;
    st->pool_used = 0;
    ps->nvisit = 0;
    ps->rows_used = 0;
    ps->ndraw = 0;
    memset(&ps->stats, 0, sizeof ps->stats);
    ps->stats.sector = 255;
    r8_tf_frame(st, cam);
    r8_tf_vertices(st, 1);
    if (st->obj[0].hidden)
        return;
    ps->stats.sector = r8_portal_locate(w, cam->x, cam->y, cam->z);
    vp[0] = st->sv;     /* (unused: the whole screen) */
    add_visit(ps, st, ps->stats.sector, 255, vp, 0);
    /* breadth first: visit k's portals add visits after it */
    for (k = 0; k < ps->nvisit; k++) {
        const r8_sector *sec = &w->sectors[ps->visit[k].sector];
        r8_u16 f, f0 = R8_RDU16(&sec->wall0), f1 = (r8_u16)(f0 + R8_RDU8(&sec->nwalls));
        ps->visit[k].w0 = ps->ndraw;
        for (f = f0; f < f1; f++) {
            r8_u16 g = face_in(ps, st, &st->obj[0], &ps->obj, f, vp, &n, 0);
            r8_s16 top, bot;
            ps->stats.faces++;
            if (g == (r8_u16)R8_FID_END || !poly_rows(st, vp, n, &top, &bot) ||
                top >= ps->visit[k].ybot || bot <= ps->visit[k].ytop)
                continue;
            if (ps->ndraw >= ps->maxdraw) {
                ps->stats.dropped++;
                continue;
            }
            ps->draw[ps->ndraw].g = g;
            ps->draw[ps->ndraw].visit = k;
            if (g >= st->nfaces)
                ps->draw[ps->ndraw].level = st->cpoly[g - st->nfaces].level;
            else
                ps->draw[ps->ndraw].level = r8_face_level(st, &st->obj[0], &ps->obj, f);
            ps->ndraw++;
            if (g < st->nfaces)
                st->npoly++;
        }
        ps->visit[k].nw = (r8_u16)(ps->ndraw - ps->visit[k].w0);
        ps->visit[k].o0 = ps->ndraw;
        ps->visit[k].no = 0;
        f0 = R8_RDU16(&sec->portal0);
        f1 = (r8_u16)(f0 + R8_RDU8(&sec->nportals));
        for (f = f0; f < f1; f++) {
            r8_u16 sv_used = st->sv_used;
            r8_u16 g = face_in(ps, st, &st->obj[0], &ps->obj, f, vp, &n, 1);
            ps->stats.faces++;
            if (g == (r8_u16)R8_FID_END)
                continue;
            if (add_visit(ps, st, R8_RDU8(&w->target[f - w->nwalls]), k, vp, n))
                ps->stats.portals++;
            if (g >= st->nfaces) {      /* a clipped portal: its polygon is done */
                st->nclipped--;
                st->npoly--;
                st->sv_used = sv_used;
            }
        }
    }
    ps->stats.visits = ps->nvisit;
    ps->stats.walls = ps->ndraw;
    if (!ps->nmov)
        return;
    /* the objects: only those in the sectors seen, each drawn in every
     * visit of its sector, after that visit's walls */
    no = objects_frame(ps, cam);
    for (k = 0; no && k < ps->nvisit; k++)
        objects_visit(ps, k, no);
}

/* Draws [d0, d0 + nd) into band fb's rows [y0, y1), each cut to its
 * visit's region. */
static void draw_range(pstate *ps, r8_u16 d0, r8_u16 nd, r8_fb *fb, r8_s16 y0, r8_s16 y1)
{
    r8_scan s;
    r8_span sp;
    r8_u16 i;
    for (i = d0; i < (r8_u16)(d0 + nd); i++) {
        const pdraw *d = &ps->draw[i];
        const pvisit *v = &ps->visit[d->visit & (PD_OBJ - 1)];
        const r8_s16 *rows = ps->rows + 2u * v->row0;
        const r8_state *st = (const r8_state *)((d->visit & PD_OBJ) ? ps->oinner.state
                                                                    : ps->inner.state);
        r8_s16 ya = y0 > v->ytop ? y0 : v->ytop, yb = y1 < v->ybot ? y1 : v->ybot;
        r8_u8 n;
        if (ya >= yb)
            continue;
        n = set_vp(st, d->g, s.c.vp);
        if (!r8_scanx_begin(&s.c, n, ya))
            continue;
        s.attrs = 0;
        r8_scan_attrs(&s);
        while (r8_scan_next(&s, yb, 0, &sp)) {
            const r8_s16 *rw = rows + 2 * (sp.y - v->ytop);
            r8_s16 a = sp.x0, b = sp.x1;
            if (a < rw[0]) a = rw[0];
            if (b > rw[1]) b = rw[1];
            if (a < b) {
                r8_fb_span_dither(fb, sp.y, a, b, d->level, 0);
                ps->stats.pixels += (r8_u16)(b - a);
            }
        }
    }
}

void r8_portal_band(r8_render *r, r8_fb *fb)
{
    pstate *ps = pstate_of(r);
    r8_s16 y0 = fb->y0, y1 = (r8_s16)(fb->y0 + fb->rows);
    r8_u8 k;
    if (y1 > fb->height)
        y1 = fb->height;
    r8_fb_clear(fb, 0);
    /* deepest visits first (breadth first: a visit's region lies inside
     * the one it was seen through), each one's walls, then its objects:
     * what lies in a sector covers what is seen through its portals */
    for (k = ps->nvisit; k-- > 0;) {
        const pvisit *v = &ps->visit[k];
        draw_range(ps, v->w0, v->nw, fb, y0, y1);
        draw_range(ps, v->o0, v->no, fb, y0, y1);
    }
}

int r8_portal_stats_get(const r8_render *r, r8_portal_stats *s)
{
    if (r->cfg.method != R8_VIS_PORTAL)
        return -1;
    *s = pstate_of(r)->stats;
    return 0;
}

#else
typedef int r8_portal_unused;   /* ISO C: no empty translation unit */
#endif
