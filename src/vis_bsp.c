/* vis_bsp.c - BSP order (R8_VIS_BSP): the seed's BSP tree, walked for an
 * exact back-to-front order with no sort and no depth memory.
 *
 * The scene converter (host/rast8/bsp.py) builds one tree per mesh in
 * model space over its faces, splitting the faces a plane crosses, and
 * stores it in flash (r8_mesh.bsp).  Each node is a face; the eye's side
 * of its plane (the backface test, r8_cull_front, on the face's own
 * normal) says which subtree is nearer.  The order depends only on where
 * the eye is in model space, so the tree holds under any pose.
 *
 * Drawing is painter's: r8_render_ram / r8_render_init hand this method
 * here, and it plans and sets up painter's (one draw list, faces painted
 * over one another) plus the walk's stack; per frame r8_bsp_frame takes
 * the objects far to near (by the far end of their bounding spheres:
 * exact when they are apart in depth, which the analyser checks) and
 * each object's faces in tree order, near to far, each put at the front
 * of the one draw list - which then runs far to near.  Nothing is
 * sorted: the walk is one plane test per face.
 *
 * Memory: painter's, plus 2 bytes per level of the deepest tree and 6
 * (the walk's block, at the start of work memory). */
#include <stddef.h>
#include "r8int.h"

#ifndef R8_NO_BSP

#define BSP_NONE 0xFFFFu

static r8_u16 rd16(const r8_u8 *p)
{
    return (r8_u16)(R8_RDU8(p) | ((r8_u16)R8_RDU8(p + 1) << 8));
}

/* Bytes of the walk's stack: 2 per level of the deepest tree; 0 if a
 * mesh has no tree. */
static unsigned stack_bytes(const r8_scene *sc)
{
    unsigned d = 1;
    r8_u8 i;
    for (i = 0; i < sc->nobjects; i++) {
        const r8_mesh *me = sc->objects[i].mesh;
        r8_u16 k;
        if (!me || !me->bsp)
            return 0;
        k = rd16(me->bsp + 2);
        if (k > d)
            d = k;
    }
    return 2u * d;
}

/* The walk's block at the start of work memory (2-byte aligned): next
 * subtree, entries on the stack, the stack's capacity, then the stack. */
#define BLK_CUR 0
#define BLK_SP 1
#define BLK_CAP 2
#define BLK_HEAD 3

unsigned r8_bsp_ram(const r8_render_cfg *cfg)
{
    r8_render_cfg c;
    unsigned s, n;
    if (!cfg->scene || !cfg->scene->objects || !(s = stack_bytes(cfg->scene)))
        return 0;
    c = *cfg;
    c.method = R8_VIS_PAINTER;
    n = r8_render_ram(&c);
    return n ? n + 2u * BLK_HEAD + s + 1u : 0;     /* + 1: the block's alignment */
}

#ifndef R8_PLAN_ONLY   /* a sizing build plans only */

static r8_u16 *block(const r8_render *r)
{
    r8_u8 *p = r->work;
    if ((size_t)(void *)p & 1u)
        p++;
    return (r8_u16 *)(void *)p;
}

int r8_bsp_init(r8_render *r, const r8_render_cfg *cfg, r8_u8 *work, unsigned work_size)
{
    r8_render_cfg c;
    unsigned need = r8_bsp_ram(cfg), s, head;
    r8_u16 *b;
    int rc;
    if (!need)
        return -1;
    if (work_size < need)
        return -2;
    s = stack_bytes(cfg->scene);
    head = 2u * BLK_HEAD + s + (((size_t)(void *)work & 1u) ? 1u : 0u);
    c = *cfg;
    c.method = R8_VIS_PAINTER;
    rc = r8_render_init(r, &c, work + head, work_size - head);   /* painter's behind it */
    if (rc)
        return rc;
    r->cfg.method = R8_VIS_BSP;
    r->work = work;
    r->work_size = work_size;
    b = block(r);
    b[BLK_CUR] = BSP_NONE;
    b[BLK_SP] = 0;
    b[BLK_CAP] = (r8_u16)(s / 2u);
    return 0;
}

void r8_bsp_begin(r8_render *r, const r8_mesh *me)
{
    r8_u16 *b = block(r);
    b[BLK_CUR] = rd16(me->bsp);
    b[BLK_SP] = 0;
}

/* The next face of object o's mesh, near to far from the eye (an
 * in-order walk with the near subtree first).  The tree is the
 * converter's flash data, trusted like the face list; an index past the
 * faces ends its subtree and the stack never grows past the tree's
 * stated depth (nor the block's capacity), so even a bad tree reads and
 * writes nothing outside. */
r8_u16 r8_bsp_next(r8_render *r, const r8_objx *o, const r8_mesh *me)
{
    const r8_u8 *t = me->bsp;
    r8_u16 *b = block(r), *stk = b + BLK_HEAD;
    r8_u16 n = b[BLK_CUR], sp = b[BLK_SP], cap = rd16(t + 2);
    if (cap > b[BLK_CAP])
        cap = b[BLK_CAP];
    for (;;) {
        if (n >= me->nfaces)
            n = BSP_NONE;
        if (n != BSP_NONE) {
            const r8_u8 *nd = t + 4u + 4u * (unsigned)n;
            const r8_face *fc = &me->faces[n];
            int front = r8_cull_front(o, me->verts + 3u * R8_RDU8(&fc->v[0]), n);
            r8_u16 nearc, farc;
            if (front) {
                nearc = rd16(nd);
                farc = rd16(nd + 2);
            } else {
                nearc = rd16(nd + 2);
                farc = rd16(nd);
            }
            if (nearc == BSP_NONE || sp >= cap) {
                b[BLK_CUR] = farc;
                b[BLK_SP] = sp;
                return n;
            }
            stk[sp++] = (r8_u16)(front ? (n | 0x8000u) : n);
            n = nearc;
        } else {
            r8_u16 e;
            if (!sp) {
                b[BLK_CUR] = BSP_NONE;
                b[BLK_SP] = 0;
                return 0;          /* a malformed tree: never read past it */
            }
            e = stk[--sp];
            n = (r8_u16)(e & 0x7FFFu);
            b[BLK_CUR] = rd16(t + 4u + 4u * (unsigned)n + ((e & 0x8000u) ? 2u : 0u));
            b[BLK_SP] = sp;
            return n;
        }
    }
}

/* Objects near to far by the far end of their bounding spheres, each
 * bucketed in tree order (r8_bucket_object puts every face at the front
 * of the one list: the last object and face bucketed is drawn first). */
void r8_bsp_frame(r8_render *r)
{
    r8_state *st = (r8_state *)r->state;
    const r8_scene *sc = st->scene;
    r8_s32 lastk = 0, bestk = 0;
    r8_u8 n = sc->nobjects, cnt, i, best, last = 255;
    for (cnt = 0; cnt < n; cnt++) {
        best = 255;
        for (i = 0; i < n; i++) {
            r8_s32 k = st->obj[i].t.z + (r8_s32)sc->objects[i].mesh->radius * R8_CSCALE;
            if (last != 255 && (k < lastk || (k == lastk && i <= last)))
                continue;          /* taken already */
            if (best == 255 || k < bestk || (k == bestk && i < best)) {
                best = i;
                bestk = k;
            }
        }
        r8_bucket_object(r, best);
        last = best;
        lastk = bestk;
    }
}

#endif /* R8_PLAN_ONLY */

#else
typedef int r8_vis_bsp_empty;   /* ISO C: no empty translation unit */
#endif
