/* scan.c - scan conversion of convex polygons, as the seed describes it:
 * find the top vertex, walk the left chain (backwards through the
 * vertex list) and the right chain (forwards) down the screen, resetting
 * an edge's interpolators when it reaches its lower vertex.  Edges are
 * stepped with the exact interpolator from subpixel vertices and sampled
 * at pixel centres with the top-left rule (r8raster.h).
 *
 * Judd's backface test: on a clockwise (front) polygon the left chain is
 * never right of the right chain; on a back face it is on every row where
 * they differ, so the first row where the two edges' subpixel positions
 * differ decides, before any pixel is drawn. */
#include "r8raster.h"
#include "r8fixed.h"

r8_s16 r8_row_of(r8_s16 y)
{
    r8_s32 v = (r8_s32)y + 7;
    return (r8_s16)(v >= 0 ? v >> 4 : -((-v + 15) >> 4));
}

static r8_u8 wrap(const r8_scan *s, r8_u8 i, int dir)
{
    if (dir > 0)
        return (r8_u8)(i + 1 == s->n ? 0 : i + 1);
    return (r8_u8)(i == 0 ? s->n - 1 : i - 1);
}

/* Set up edge e on the chain going in direction dir from polygon
 * position `from`, for row y: skips edges that end at or above row y. */
static void edge_start(r8_scan *s, r8_edge *e, r8_u8 from, int dir, r8_s16 y)
{
    const r8_svert *a, *b;
    r8_u8 to = wrap(s, from, dir);
    r8_u8 guard = s->n;
    r8_s32 s0, dy, dx;
    r8_u8 sh = 0;
    while (r8_row_of(s->v[s->idx[to]].y) <= y && guard--) {
        from = to;
        to = wrap(s, from, dir);
    }
    a = &s->v[s->idx[from]];
    b = &s->v[s->idx[to]];
    e->vi = to;
    e->yend = r8_row_of(b->y);
    dy = (r8_s32)b->y - a->y;
    if (dy <= 0)
        dy = 1;  /* only for non-convex input; keeps the arithmetic sane */
    s0 = r8_mul16(y, R8_SUBPX) + 8 - a->y;  /* subpixels from a to row y */
    if (dy > 32767) {
        /* Edges over 2047 pixels tall (only reachable by direct callers;
         * the renderer's guard band keeps edges under 1800): measure in
         * half-subpixels: rows stay exact to a subpixel, x can be off by
         * up to 3 subpixels (measured, tests/host/test_stability.c). */
        dy = (dy + 1) >> 1;
        s0 >>= 1;
        sh = 1;
    }
    dx = (r8_s32)b->x - a->x;
    r8_interp_init_mul(&e->x, a->x, s0, dx, dx * (R8_SUBPX >> sh), (r8_u16)dy);
    if (s->attrs & R8_ATTR_D) {
        dx = (r8_s32)b->d - a->d;
        r8_interp_init_mul(&e->d, a->d, s0, dx, dx * (R8_SUBPX >> sh), (r8_u16)dy);
    }
    if (s->attrs & R8_ATTR_S) {
        dx = (r8_s32)b->s - a->s;
        r8_interp_init_mul(&e->s, a->s, s0, dx, dx * (R8_SUBPX >> sh), (r8_u16)dy);
    }
}

r8_s16 r8_scan_begin(r8_scan *s, const r8_svert *v, const r8_u16 *idx,
                     r8_u8 n, r8_u8 attrs, r8_s16 ystart)
{
    r8_u8 i, top = 0;
    r8_s16 ymin, ymax, y;
    s->v = v;
    s->idx = idx;
    s->n = n;
    s->attrs = attrs;
    s->backface = 0;
    s->front = 0;
    s->y = s->ybot = 0;
    if (n < 3)
        return 0;
    ymin = ymax = v[idx[0]].y;
    for (i = 1; i < n; i++) {
        r8_s16 vy = v[idx[i]].y;
        if (vy < ymin) {
            ymin = vy;
            top = i;
        }
        if (vy > ymax)
            ymax = vy;
    }
    s->ybot = r8_row_of(ymax);
    y = r8_row_of(ymin);
    if (y < ystart)
        y = ystart;
    s->y = y;
    if (y >= s->ybot)
        return 0;
    edge_start(s, &s->l, top, -1, y);
    edge_start(s, &s->r, top, 1, y);
    return (r8_s16)(s->ybot - y);
}

static void edge_step(const r8_scan *s, r8_edge *e)
{
    R8_INTERP_STEP(&e->x);
    if (s->attrs & R8_ATTR_D)
        R8_INTERP_STEP(&e->d);
    if (s->attrs & R8_ATTR_S)
        R8_INTERP_STEP(&e->s);
}

/* Column of the first pixel centre at or right of edge x (16-bit: edge x
 * stays inside the guard band). */
#define COL_OF(it, c) do { r8_s16 v_ = (it).val; \
    if (v_ > 32700) c = 2044; else { v_ = (r8_s16)(v_ + 7 + ((it).err != 0)); \
    c = (r8_s16)(v_ >= 0 ? v_ >> 4 : -((-v_ + 15) >> 4)); } } while (0)

/* Start row y: move either edge on to its next vertex where it ended,
 * then Judd's test, decided on the first row where the edges differ by a
 * subpixel, before any pixel of the polygon is drawn.  0: a back face
 * (the scan is over). */
static int row_begin(r8_scan *s, r8_s16 y, int judd)
{
    r8_edge *l = &s->l, *r = &s->r;
    if (y >= l->yend)
        edge_start(s, l, l->vi, -1, y);
    if (y >= r->yend)
        edge_start(s, r, r->vi, 1, y);
    if (judd && !s->front && l->x.val != r->x.val) {
        if (l->x.val > r->x.val) {
            s->backface = 1;
            s->y = s->ybot;
            return 0;
        }
        s->front = 1;
    }
    return 1;
}

int r8_scan_next(r8_scan *s, r8_s16 ylimit, int judd, r8_span *out)
{
    r8_edge *l = &s->l, *r = &s->r;
    r8_s16 lim = s->ybot < ylimit ? s->ybot : ylimit;
    r8_u8 attrs = s->attrs;
    while (s->y < lim) {
        r8_s16 y = s->y, xl, xr;
        if (!row_begin(s, y, judd))
            return 0;
        COL_OF(l->x, xl);
        COL_OF(r->x, xr);
        s->y = (r8_s16)(y + 1);
        if (xl < xr) {
            out->y = y;
            out->x0 = xl;
            out->x1 = xr;
            if (attrs) {
                out->dl = l->d.val;
                out->dr = r->d.val;
                out->sl = l->s.val;
                out->sr = r->s.val;
                edge_step(s, l);
                edge_step(s, r);
            } else {
                R8_INTERP_STEP(&l->x);
                R8_INTERP_STEP(&r->x);
            }
            return 1;
        }
        if (attrs) {
            edge_step(s, l);
            edge_step(s, r);
        } else {
            R8_INTERP_STEP(&l->x);
            R8_INTERP_STEP(&r->x);
        }
    }
    return 0;
}

void r8_scan_fill(r8_scan *s, r8_s16 ylimit, int judd, r8_fb *fb, r8_u8 level)
{
    r8_edge *l = &s->l, *r = &s->r;
    r8_s16 lim = s->ybot < ylimit ? s->ybot : ylimit;
    r8_s16 w = fb->width, y = s->y;
    if (s->attrs || fb->format != R8_FMT_PAGE1) {
        /* general case: one span at a time */
        r8_span sp;
        while (r8_scan_next(s, ylimit, judd, &sp))
            r8_fb_span_dither(fb, sp.y, sp.x0, sp.x1, level, 0);
        return;
    }
    for (; y < lim; y++) {
        r8_s16 xl, xr;
        if (!row_begin(s, y, judd))
            return;
        COL_OF(l->x, xl);
        COL_OF(r->x, xr);
        R8_INTERP_STEP(&l->x);
        R8_INTERP_STEP(&r->x);
        if (xl < 0)
            xl = 0;
        if (xr > w)
            xr = w;
        if (xl < xr && y >= fb->y0) {
            /* SSD1306 page: one byte per column, bit (row & 7) */
            r8_s16 by = (r8_s16)(y - fb->y0);
            r8_u8 pat = 0xFF;     /* if chain, not nested ?: (cc65) */
            if (level == 0)
                pat = 0;
            else if (level < 16)
                pat = r8_fb_dither_row(level, y);
            r8_fb_page_run(fb->buf + (unsigned)(by >> 3) * (unsigned)w + (unsigned)xl,
                           (unsigned)(xr - xl), (r8_u8)(1u << (by & 7)), pat,
                           (r8_u8)(xl & 3));
        }
    }
    s->y = y;
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
