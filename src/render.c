/* render.c - the frame renderer: per frame, transform every vertex once,
 * cull, clip and set up the visible polygons (and sort them for the
 * painter's); per band, clear the band and its depth memory, then scan
 * every polygon's rows inside the band through the chosen visibility
 * method.  Scan states persist between bands (a pool of R8_SCAN_POOL),
 * so edges are never walked again from the top; a polygon without a
 * pooled state is seeked straight to the band's first row, which gives
 * the same spans.  All memory is the caller's `work`. */
#include <stddef.h>
#include "r8int.h"

void r8_render_defaults(r8_render_cfg *cfg)
{
    cfg->scene = R8_SCENE_CUBE;
    cfg->method = R8_VIS_CULL;
    cfg->shading = R8_SHADE_LAMBERT;
    cfg->cull = R8_CULL_NORMAL;
    cfg->format = R8_FMT_PAGE1;
    cfg->width = 128;
    cfg->height = 64;
    cfg->band = 8;
    cfg->custom = 0;
}

const r8_scene *r8_render_scene(const r8_render_cfg *cfg)
{
    return cfg->custom ? cfg->custom : r8_scene_get(cfg->scene);
}

static const char *const scene_names[R8_SCENE_COUNT] = {
    "cube", "torus", "teapot", "terrain", "wall", "cross", "separate"
};
static const char *const method_names[R8_VIS_COUNT] = {
    "cull", "painter", "zbuf8", "zbuf16", "block", "blockmask", "sbuf"
};

static int streq(const char *a, const char *b)
{
    while (*a && *a == *b) {
        a++;
        b++;
    }
    return *a == *b;
}

const char *r8_scene_name(r8_u8 scene)
{
    return scene < R8_SCENE_COUNT ? scene_names[scene] : 0;
}

const char *r8_method_name(r8_u8 method)
{
    if (method == R8_VIS_AUTO)
        return "auto";
    return method < R8_VIS_COUNT ? method_names[method] : 0;
}

int r8_scene_by_name(const char *name)
{
    int i;
    for (i = 0; i < R8_SCENE_COUNT; i++)
        if (streq(name, scene_names[i]))
            return i;
    return -1;
}

int r8_method_by_name(const char *name)
{
    int i;
    if (streq(name, "auto"))
        return R8_VIS_AUTO;
    for (i = 0; i < R8_VIS_COUNT; i++)
        if (streq(name, method_names[i]))
            return i;
    return -1;
}

/* ---- memory plan ---- */

#define ALIGN_TO (sizeof(r8_s32) > sizeof(void *) ? sizeof(r8_s32) : sizeof(void *))

static unsigned align_up(unsigned n)
{
    return (unsigned)((n + (ALIGN_TO - 1)) & ~(unsigned)(ALIGN_TO - 1));
}

typedef struct plan {
    unsigned clipbuf, obj, sv, out, fnorm, vnorm, poly, idx, order, jeff, pool, depth, snode, shead, total;
    r8_u16 nverts, nfaces, maxidx, nclip;
    r8_u8 npool;
} plan;

static int cfg_valid(const r8_render_cfg *cfg)
{
    const r8_scene *sc = r8_render_scene(cfg);
    if (!sc || sc->nobjects == 0 || cfg->method >= R8_VIS_COUNT ||
        cfg->shading > R8_SHADE_GOURAUD || cfg->cull > R8_CULL_JUDD ||
        cfg->format > R8_FMT_IDX8)
        return 0;
    if (cfg->width < 8 || cfg->width > 1024 || cfg->height < 8 || cfg->height > 1024)
        return 0;
    if (cfg->band < 1 || cfg->band > cfg->height)
        return 0;
    if (cfg->format == R8_FMT_PAGE1 && ((cfg->band & 7) || (cfg->height & 7)))
        return 0;
    if ((cfg->method == R8_VIS_BLOCK || cfg->method == R8_VIS_BLOCKMASK) &&
        ((cfg->band & 3) || (cfg->height & 3)))
        return 0;
    if (cfg->method == R8_VIS_SBUF && cfg->width > 1024)
        return 0;
    return 1;
}

unsigned r8_vis_depth_bytes(const r8_render_cfg *cfg)
{
    unsigned w = (unsigned)cfg->width, h = (unsigned)cfg->band;
    unsigned blocks = ((w + 3u) >> 2) * ((h + 3u) >> 2);
    switch (cfg->method) {
    case R8_VIS_Z8:
        return w * h;
    case R8_VIS_Z16:
        return 2u * w * h;
    case R8_VIS_BLOCK:
        return 2u * blocks;  /* depth + owner id */
    case R8_VIS_BLOCKMASK:
        return ((blocks + 1u) & ~1u) + 2u * blocks;
    default:
        return 0;
    }
}

r8_u16 r8_vis_sbuf_nodes(const r8_render_cfg *cfg)
{
    /* per row: one span per face that can cross it plus a split, at most
     * 32; indices are 16-bit */
    const r8_scene *sc = r8_render_scene(cfg);
    unsigned per = 2, n;
    r8_u8 i;
    if (cfg->method != R8_VIS_SBUF || !sc)
        return 0;
    for (i = 0; i < sc->nobjects && per < 32u; i++)
        per += sc->objects[i].mesh->nfaces;
    if (per > 32u)
        per = 32u;
    n = (unsigned)cfg->band * per;
    return (r8_u16)(n > 0xFFF0u ? 0xFFF0u : n);
}

static void make_plan(const r8_render_cfg *cfg, plan *pl)
{
    const r8_scene *sc = r8_render_scene(cfg);
    r8_u8 i;
    unsigned nv = 0, nf = 0, ni = 0, o = 0;
    for (i = 0; i < sc->nobjects; i++) {
        const r8_mesh *me = sc->objects[i].mesh;
        r8_u16 f;
        nv += me->nverts;
        nf += me->nfaces;
        for (f = 0; f < me->nfaces; f++)
            ni += me->faces[f].n;
    }
    pl->nverts = (r8_u16)nv;
    pl->nfaces = (r8_u16)nf;
    /* clipping adds at most 5 vertices per face; the pool is sized for a
     * few faces at a time, and a face that finds it full is dropped and
     * counted (st->dropped) */
    pl->nclip = (r8_u16)(3u * nf + 6u < R8_CLIP_VERTS ? 3u * nf + 6u : R8_CLIP_VERTS);
    pl->maxidx = (r8_u16)(ni + pl->nclip);
    /* a closed mesh shows at most about half its faces at once; polygons
     * beyond the pool are seeked to each band's first row instead */
    pl->npool = (r8_u8)((nf + 1u) / 2u < R8_SCAN_POOL ? (nf + 1u) / 2u : R8_SCAN_POOL);
    pl->obj = o; o += align_up(sizeof(r8_objx) * sc->nobjects);
    pl->sv = o; o += align_up(sizeof(r8_svert) * (nv + pl->nclip));
    pl->out = o; o += align_up(nv);
    pl->fnorm = o; o += align_up(sizeof(r8_vec3) * nf);
    pl->vnorm = o;
    if (cfg->shading == R8_SHADE_GOURAUD)
        o += align_up(sizeof(r8_vec3) * nv);
    pl->poly = o; o += align_up(sizeof(r8_poly) * nf);
    pl->idx = o; o += align_up(2u * pl->maxidx);
    pl->order = o; o += align_up(2u * nf);
    /* One shared region for memory that is never live at the same time:
     * the clipper's polygons (while faces are set up), the painter's
     * bucket counts (while sorting), and the band-time memory: scan
     * states, depth memory, S-buffer. */
    pl->clipbuf = o;
    pl->jeff = o;
    pl->pool = o; o += align_up(sizeof(r8_scan) * pl->npool);
    pl->depth = o; o += align_up(r8_vis_depth_bytes(cfg));
    pl->snode = o; o += align_up(sizeof(r8_snode) * r8_vis_sbuf_nodes(cfg));
    pl->shead = o;
    if (cfg->method == R8_VIS_SBUF)
        o += align_up(2u * (unsigned)cfg->band);
    if (o < pl->clipbuf + align_up(r8_clip_bytes()))
        o = pl->clipbuf + align_up(r8_clip_bytes());
    if (cfg->method == R8_VIS_PAINTER && o < pl->jeff + align_up(2u * R8_JEFF_BUCKETS))
        o = pl->jeff + align_up(2u * R8_JEFF_BUCKETS);
    pl->total = o + align_up(sizeof(r8_state)) + ALIGN_TO; /* + alignment slack */
}

unsigned r8_render_ram(const r8_render_cfg *cfg)
{
    plan pl;
    if (!cfg_valid(cfg))
        return 0;
    make_plan(cfg, &pl);
    return pl.total;
}

int r8_render_init(r8_render *r, const r8_render_cfg *cfg, r8_u8 *work,
                   unsigned work_size)
{
    plan pl;
    r8_state *st;
    r8_u8 *base;
    const r8_scene *sc;
    r8_s32 zn, zf;
    r8_u8 i;
    r8_u16 vb = 0, fb = 0, k;
    if (!cfg_valid(cfg))
        return -1;
    make_plan(cfg, &pl);
    if (work_size < pl.total)
        return -2;
    /* state first, aligned; the rest follows */
    base = work + ((ALIGN_TO - ((unsigned)((size_t)(void *)work & (ALIGN_TO - 1)))) & (ALIGN_TO - 1));
    st = (r8_state *)(void *)base;
    base += align_up(sizeof(r8_state));
    r->cfg = *cfg;
    r->work = work;
    r->work_size = work_size;
    r->frame = 0;
    r->state = st;
    sc = r8_render_scene(cfg);
    st->scene = sc;
    st->nverts = pl.nverts;
    st->nfaces = pl.nfaces;
    st->maxidx = pl.maxidx;
    st->nclip = pl.nclip;
    st->npool = pl.npool;
    st->clipbuf = base + pl.clipbuf;
    st->obj = (r8_objx *)(void *)(base + pl.obj);
    st->sv = (r8_svert *)(void *)(base + pl.sv);
    st->out = base + pl.out;
    st->fnorm = (r8_vec3 *)(void *)(base + pl.fnorm);
    st->vnorm = cfg->shading == R8_SHADE_GOURAUD ? (r8_vec3 *)(void *)(base + pl.vnorm) : 0;
    st->poly = (r8_poly *)(void *)(base + pl.poly);
    st->idx = (r8_u16 *)(void *)(base + pl.idx);
    st->order = (r8_u16 *)(void *)(base + pl.order);
    st->jeff = (r8_u16 *)(void *)(base + pl.jeff);
    st->pool = (r8_scan *)(void *)(base + pl.pool);
    st->depth = base + pl.depth;
    st->depth_bytes = r8_vis_depth_bytes(cfg);
    st->snode = (r8_snode *)(void *)(base + pl.snode);
    st->nsnode = r8_vis_sbuf_nodes(cfg);
    st->shead = (r8_u16 *)(void *)(base + pl.shead);
    st->sused = 0;
    for (k = 0; k < (r8_u16)cfg->band && cfg->method == R8_VIS_SBUF; k++)
        st->shead[k] = 0xFFFF;
    st->attrs = 0;
    st->need_depth = cfg->method != R8_VIS_CULL;   /* painter's keys use it too */
    if (cfg->method >= R8_VIS_Z8)
        st->attrs |= R8_ATTR_D;
    if (cfg->shading == R8_SHADE_GOURAUD)
        st->attrs |= R8_ATTR_S;
    st->npoly = 0;
    st->dropped = 0;
    /* camera and depth range from the scene's extents */
    r8_camera_init(&st->cam, cfg->width, cfg->height,
                   (r8_s16)(r8_mul16(cfg->width, sc->focal_num) >> 6), sc->znear);
    zn = 0x7FFFFFFFL;
    zf = 1;
    for (i = 0; i < sc->nobjects; i++) {
        const r8_object *ob = &sc->objects[i];
        r8_s32 a = (r8_s32)ob->z - ob->mesh->radius, b = (r8_s32)ob->z + ob->mesh->radius;
        if (a < zn) zn = a;
        if (b > zf) zf = b;
        st->obj[i].vbase = vb;
        st->obj[i].fbase = fb;
        vb = (r8_u16)(vb + ob->mesh->nverts);
        fb = (r8_u16)(fb + ob->mesh->nfaces);
    }
    if (zn < sc->znear)
        zn = sc->znear;
    if (zf <= zn)
        zf = zn + 1;
    /* depth = 32767 * (1/z - 1/zf) / (1/zn - 1/zf) = dc1 / z - dc2 */
    st->dc1 = r8_muldiv(r8_muldiv(32767L, zn, zf - zn), zf, 1);
    st->dc2 = r8_muldiv(32767L, zn, zf - zn);
    r8_cull_normals(st);
    return 0;
}

/* ---- per frame ---- */

static r8_u8 row_range(const r8_state *st, const r8_poly *p, r8_s16 *top, r8_s16 *bot)
{
    r8_s16 ymin = 32767, ymax = -32767 - 1;
    r8_u8 i;
    for (i = 0; i < p->n; i++) {
        r8_s16 y = st->sv[st->idx[p->idx + i]].y;
        if (y < ymin) ymin = y;
        if (y > ymax) ymax = y;
    }
    *top = r8_row_of(ymin);
    *bot = r8_row_of(ymax);
    return *top < *bot;
}

void r8_render_frame(r8_render *r, r8_u16 frame)
{
    r8_state *st = (r8_state *)r->state;
    const r8_scene *sc = st->scene;
    r8_u8 i;
    r->frame = frame;
    st->npoly = 0;
    st->nsv = st->nverts;
    st->nidx = 0;
    st->dropped = 0;
    r8_tf_objects(st, frame);
    r8_tf_vertices(st);
    for (i = 0; i < sc->nobjects; i++) {
        const r8_object *ob = &sc->objects[i];
        const r8_mesh *me = ob->mesh;
        const r8_objx *o = &st->obj[i];
        r8_u16 f;
        for (f = 0; f < me->nfaces; f++) {
            const r8_face *fc = &me->faces[f];
            r8_poly *p = &st->poly[st->npoly];
            r8_u8 oand = 0xFF, oor = 0, k;
            r8_s32 dsum = 0;
            for (k = 0; k < fc->n; k++) {
                r8_u8 c = st->out[o->vbase + fc->v[k]];
                oand &= c;
                oor |= c;
            }
            if (oand & (r8_u8)~R8_OUT_GUARD) /* all outside one side (the guard
                                                 flag is any side: clip instead) */
                continue;
            if (r->cfg.cull == R8_CULL_NORMAL && !r8_cull_front(st, o, me, f))
                continue;
            if (oor & (R8_OUT_NEAR | R8_OUT_GUARD)) {
                if (!r8_clip_face(st, o, ob, fc, p))
                    continue;
            } else {
                if (st->nidx + fc->n > st->maxidx) {
                    st->dropped++;
                    continue;
                }
                p->idx = st->nidx;
                p->n = fc->n;
                for (k = 0; k < fc->n; k++)
                    st->idx[st->nidx++] = (r8_u16)(o->vbase + fc->v[k]);
            }
            if (!row_range(st, p, &p->ytop, &p->ybot)) {
                st->nidx = p->idx;   /* no pixel centre inside: drop it */
                continue;
            }
            if (r->cfg.method == R8_VIS_PAINTER) {
                for (k = 0; k < p->n; k++)
                    dsum += st->sv[st->idx[p->idx + k]].d;
                /* mean depth >> 9: 0..63, 0 = far (16-bit division) */
                p->key = (r8_u8)((r8_u16)(dsum >> 4) / p->n >> 5);
            }
            if (r->cfg.shading == R8_SHADE_FLAT)
                p->shade = fc->colour;
            else
                p->shade = (r8_u8)((r8_tf_shade(st, &st->fnorm[o->fbase + f], &o->light,
                                                fc->colour) + 128) >> 8);
            p->slot = R8_NO_SLOT;
            st->npoly++;
        }
    }
    if (r->cfg.method == R8_VIS_PAINTER) {
        r8_jeffsort(st);
    } else {
        r8_u16 k;
        for (k = 0; k < st->npoly; k++)
            st->order[k] = k;
    }
    for (i = 0; i < st->npool; i++)
        st->pool[i].n = 0;              /* n == 0: free slot */
}

static void draw_span(r8_state *st, r8_render *r, r8_fb *fb, const r8_poly *p, const r8_span *sp)
{
    switch (r->cfg.method) {
    case R8_VIS_Z8:
        r8_vis_zbuf(st, fb, p, sp, 0);
        break;
    case R8_VIS_Z16:
        r8_vis_zbuf(st, fb, p, sp, 1);
        break;
    case R8_VIS_BLOCK:
        r8_vis_block(st, fb, p, sp, 0);
        break;
    case R8_VIS_BLOCKMASK:
        r8_vis_block(st, fb, p, sp, 1);
        break;
    case R8_VIS_SBUF:
        r8_vis_sbuf_insert(st, fb, p, sp);
        break;
    default:
        r8_vis_plain(st, fb, p, sp);
    }
}

void r8_render_band(r8_render *r, r8_fb *fb)
{
    r8_state *st = (r8_state *)r->state;
    r8_s16 y0 = fb->y0, y1 = (r8_s16)(fb->y0 + fb->rows);
    int judd = r->cfg.cull == R8_CULL_JUDD;
    /* no depth test and one level per face: the fused scan-and-fill loop */
    int fast = (r->cfg.method == R8_VIS_CULL || r->cfg.method == R8_VIS_PAINTER) &&
               !(st->attrs & R8_ATTR_S);
    r8_u16 k;
    if (y1 > fb->height)
        y1 = fb->height;
    r8_fb_clear(fb, 0);
    {
        r8_u8 *z = st->depth, *ze = z + st->depth_bytes;
        while (z < ze)
            *z++ = 0;
        if (r->cfg.method == R8_VIS_BLOCK)   /* owner ids: none */
            for (z = st->depth + st->depth_bytes / 2u; z < ze; z++)
                *z = 0xFF;
    }
    for (k = 0; k < st->npoly; k++) {
        r8_poly *p = &st->poly[st->order[k]];
        r8_scan tmp, *sc;
        r8_span sp;
        if (p->ybot <= y0 || p->ytop >= y1)
            continue;
        if (p->slot != R8_NO_SLOT) {
            sc = &st->pool[p->slot];
        } else {
            r8_u8 j;
            sc = &tmp;
            for (j = 0; j < st->npool; j++)
                if (st->pool[j].n == 0) {
                    sc = &st->pool[j];
                    p->slot = j;
                    break;
                }
            if (!r8_scan_begin(sc, st->sv, st->idx + p->idx, p->n, st->attrs, y0)) {
                sc->n = 0;
                p->ybot = y0;     /* nothing left */
                p->slot = R8_NO_SLOT;
                continue;
            }
        }
        if (fast)
            r8_scan_fill(sc, y1, judd, fb, p->shade);
        else
            while (r8_scan_next(sc, y1, judd, &sp))
                draw_span(st, r, fb, p, &sp);
        if (sc->y >= sc->ybot || sc->backface) {
            p->ybot = y0;         /* finished: never looked at again */
            if (p->slot != R8_NO_SLOT) {
                st->pool[p->slot].n = 0;
                p->slot = R8_NO_SLOT;
            }
        }
    }
    if (r->cfg.method == R8_VIS_SBUF)
        r8_vis_sbuf_flush(st, fb);
}
