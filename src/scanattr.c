/* scanattr.c - scan conversion with depth and shade along the edges
 * (the depth methods and Gouraud: spans carry their end values), and
 * r8_fill_poly, the public one-call polygon fill.  The edges themselves
 * are scan.c's. */
#include "r8raster.h"
#include "r8fixed.h"
#include "r8scan.h"
#include "r8zrows.h"

/* previous position on the polygon going the other way */
static r8_u8 back(const r8_scanx *s, r8_u8 i, int dir)
{
    if (dir < 0)
        return (r8_u8)(i + 1 == s->n ? 0 : i + 1);
    return (r8_u8)(i == 0 ? s->n - 1 : i - 1);
}

/* Attribute interpolator for the edge of e (its upper vertex is the one
 * before e->vi in direction dir), at row y.  At an edge's first row
 * (where R8_ZROWS, src/r8zrows.h): r8_attr_first, without a division. */
static void attr_start(const r8_scan *s, const r8_edge *e, int dir, r8_s16 y,
                       r8_interp *d, r8_interp *sh)
{
    const r8_scanx *c = &s->c;
    r8_u8 to = e->vi, from = back(c, to, dir);
    const r8_s16 *a = c->vp[from];
    const r8_s16 *b = c->vp[to];
#if R8_ZROWS
    if ((!(s->attrs & R8_ATTR_D) || r8_attr_first(d, a, b, y, 2)) &&
        (!(s->attrs & R8_ATTR_S) || r8_attr_first(sh, a, b, y, 3)))
        return;
#endif
    {
        r8_s32 s0 = r8_mul16(y, R8_SUBPX) + 8 - a[1], dy = (r8_s32)b[1] - a[1], dv;
        r8_u8 sh1 = 0;
        if (dy <= 0)
            dy = 1;
        if (dy > 32767) {
            dy = (dy + 1) >> 1;
            s0 >>= 1;
            sh1 = 1;
        }
        if (s->attrs & R8_ATTR_D) {
            dv = (r8_s32)b[2] - a[2];
            r8_interp_init_mul(d, a[2], s0, dv, dv * (R8_SUBPX >> sh1), (r8_u16)dy);
        }
        if (s->attrs & R8_ATTR_S) {
            dv = (r8_s32)b[3] - a[3];
            r8_interp_init_mul(sh, a[3], s0, dv, dv * (R8_SUBPX >> sh1), (r8_u16)dy);
        }
    }
}

#if R8_ZROWS || defined(R8_ZROWS_REF)
/* (src/r8zrows.h) */
void r8_scan_attr_edge(r8_scan *s, int right, r8_s16 y)
{
    if (right)
        attr_start(s, &s->c.r, 1, y, &s->rd, &s->rs);
    else
        attr_start(s, &s->c.l, -1, y, &s->ld, &s->ls);
}
#endif

/* attr_start with its depth-only path written in the caller (where
 * R8_ZROWS: a call and its register saves fewer per edge) */
#if R8_ZROWS
#define ATTR_START(s, e, dir, y, d, sh) do { \
    if ((s)->attrs != R8_ATTR_D || \
        !r8_attr_first(d, (s)->c.vp[back(&(s)->c, (e)->vi, dir)], (s)->c.vp[(e)->vi], y, 2)) \
        attr_start(s, e, dir, y, d, sh); } while (0)
#else
#define ATTR_START(s, e, dir, y, d, sh) attr_start(s, e, dir, y, d, sh)
#endif

#if !R8_ZROWS
/* (where R8_ZROWS: src/zrows.c's, AVR ports/avr/zfill.S) */
void r8_scan_attrs(r8_scan *s)
{
    if (s->attrs) {
        ATTR_START(s, &s->c.l, -1, s->c.y, &s->ld, &s->ls);
        ATTR_START(s, &s->c.r, 1, s->c.y, &s->rd, &s->rs);
    }
}
#endif

r8_s16 r8_scan_begin(r8_scan *s, const r8_svert *v, const r8_u16 *idx,
                     r8_u8 n, r8_u8 attrs, r8_s16 ystart)
{
    r8_s16 rows;
    r8_u8 i;
    for (i = 0; i < n && i < R8_SCAN_MAXV; i++)
        s->c.vp[i] = &v[idx[i]].x;
    rows = r8_scanx_begin(&s->c, n, ystart);
    s->attrs = attrs;
    if (rows)
        r8_scan_attrs(s);
    return rows;
}

static void attr_step(const r8_scan *s, r8_interp *d, r8_interp *sh)
{
    if (s->attrs & R8_ATTR_D)
        R8_INTERP_STEP(d);
    if (s->attrs & R8_ATTR_S)
        R8_INTERP_STEP(sh);
}

int r8_scan_row_attrs(r8_scan *s, r8_s16 y, int judd)
{
    r8_edge *l = &s->c.l, *r = &s->c.r;
    r8_u8 lv = l->vi, rv = r->vi;
    if (!r8_scan_row(&s->c, y, judd))
        return 0;
    if (s->attrs) {
        if (l->vi != lv)
            ATTR_START(s, l, -1, y, &s->ld, &s->ls);
        if (r->vi != rv)
            ATTR_START(s, r, 1, y, &s->rd, &s->rs);
    }
    return 1;
}

int r8_scan_next(r8_scan *s, r8_s16 ylimit, int judd, r8_span *out)
{
    r8_scanx *c = &s->c;
    r8_edge *l = &c->l, *r = &c->r;
    r8_s16 lim = c->ybot < ylimit ? c->ybot : ylimit;
    while (c->y < lim) {
        r8_s16 y = c->y, xl, xr;
        if (!r8_scan_row_attrs(s, y, judd))
            return 0;
        xl = l->x.val;
        xr = r->x.val;
        R8_INTERP_STEP(&l->x);
        R8_INTERP_STEP(&r->x);
        c->y = (r8_s16)(y + 1);
        if (xl < xr) {
            out->y = y;
            out->x0 = xl;
            out->x1 = xr;
            if (s->attrs) {
                out->dl = s->ld.val;
                out->dr = s->rd.val;
                out->sl = s->ls.val;
                out->sr = s->rs.val;
                attr_step(s, &s->ld, &s->ls);
                attr_step(s, &s->rd, &s->rs);
            }
            return 1;
        }
        if (s->attrs) {
            attr_step(s, &s->ld, &s->ls);
            attr_step(s, &s->rd, &s->rs);
        }
    }
    return 0;
}

r8_s32 r8_fill_poly(r8_fb *fb, const r8_svert *v, const r8_u16 *idx,
                    r8_u8 n, r8_u8 c)
{
    r8_scan sc;
    r8_span sp;
    r8_s32 count = 0;
    r8_s16 bottom = (r8_s16)(fb->y0 + fb->rows);
    if (!r8_scan_begin(&sc, v, idx, n, 0, fb->y0 > 0 ? fb->y0 : 0))
        return 0;
    while (r8_scan_next(&sc, bottom, 0, &sp)) {
        r8_s16 a = sp.x0 < 0 ? 0 : sp.x0, b = sp.x1 > fb->width ? fb->width : sp.x1;
        r8_fb_span(fb, sp.y, sp.x0, sp.x1, c);
        if (a < b)
            count += b - a;
    }
    return count;
}
