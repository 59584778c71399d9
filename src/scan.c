/* scan.c - scan conversion of convex polygons, as the seed describes it:
 * find the top vertex, walk the left chain (backwards through the vertex
 * list) and the right chain (forwards) down the screen, restarting an
 * edge when it reaches its lower vertex.  Pixels are sampled at their
 * centres with the top-left rule (r8raster.h).
 *
 * An edge is stepped directly in pixel columns: the column of the first
 * pixel centre at or right of the edge on row y is
 *     col(y) = ceil((ax - 8 + (16 y + 8 - ay) dx / dy) / 16)
 * (12.4 subpixels, a = upper vertex, dx, dy = b - a), a linear function
 * of y with the rational slope dx / dy.  So an exact DDA steps it: whole
 * columns q = floor(dx / dy) per row plus a fraction r / dy carried in an
 * error term.  Set-up costs one 16-bit division and a few short
 * products; a row costs two adds and a compare per edge, with no
 * rounding and no drift.  (The error term also has a constant part below
 * 1/16 of a step, which never changes and is left out.)
 *
 * Judd's backface test: on a clockwise (front) polygon the left chain is
 * never right of the right chain; on a back face it is on every row where
 * they differ.  The first row whose two columns differ decides, before
 * any pixel is drawn: a back face draws nothing, a front face draws
 * exactly the pixels it draws without the test. */
#include "r8raster.h"
#include "r8fixed.h"
#include "r8flash.h"
#include "r8kern.h"
#include "r8scan.h"

R8_CASSERT(svert_is_4_s16, sizeof(r8_svert) == 4 * sizeof(r8_s16));

r8_s16 r8_row_of(r8_s16 y)
{
    r8_s32 v = (r8_s32)y + 7;
    return (r8_s16)(v >= 0 ? v >> 4 : -((-v + 15) >> 4));
}

#define ROW_OF(y) R8_ROW_OF(y)

#define VX(s, i) ((s)->vp[i][0])
#define VY(s, i) ((s)->vp[i][1])


/* Column DDA of the edge (ax, ay) -> (bx, by), by > ay, on its first row
 * y0 = row_of(ay), in 32 bits: the edges r8k_edge (r8kern.h, the 16-bit
 * set-up) leaves.  Returns y0.  For edges over 2047 pixels tall (only
 * direct callers reach them: the renderer's guard band keeps edges under
 * 1800) coordinates are halved: a column can then be off by one where
 * the edge passes within 1/8 pixel of a centre (tests/host/test_stability.c).
 * R8_SCAN_GUARDED (ports/fw_trim.c: scan.c built into a firmware for its
 * renderer alone): every vertex lies inside the guard band (|x - cx|,
 * |y - cy| <= 900 px, proj.c), so |dx| and dy stay under 1800 px and
 * neither the halved units nor the 32-bit division is built. */
static r8_s16 edge_dda_wide(r8_interp *it, r8_s16 ax, r8_s16 ay, r8_s16 bx, r8_s16 by)
{
    r8_s32 dx = (r8_s32)bx - ax, dy = (r8_s32)by - ay, p;
    r8_s16 y0 = r8_row_of(ay);
    r8_s32 s0 = r8_mul16(y0, R8_SUBPX) + 8 - ay;     /* 0 <= s0 < 16 */
    r8_s32 axm = (r8_s32)ax - 8;
    r8_u32 u, d16, udx;
    r8_u16 den, qd, rd;
    r8_u8 pl;
#ifndef R8_SCAN_GUARDED
    if (dy > 32767) {
        dx = r8_asr32(dx, 1);
        dy = (dy + 1) >> 1;
        axm = r8_asr32(axm, 1);
        s0 >>= 1;
        /* halved units: col = ceil((axm + s0 dx / dy) / 8) */
        p = axm * dy + s0 * dx;      /* |p| < 2^31: coordinates are 16-bit */
        it->den = (r8_u16)dy;
        it->q = (r8_s16)r8_floordiv(dx, dy);
        it->r = (r8_u16)(dx - (r8_s32)it->q * dy);
        d16 = (r8_u32)dy * 8u;
        it->val = (r8_s16)r8_floordiv(p + (r8_s32)d16 - 1, (r8_s32)d16);
        it->err = (r8_u16)(((r8_u32)(p + (r8_s32)d16 - 1 - (r8_s32)it->val * (r8_s32)d16)) >> 3);
        return y0;
    }
#endif
    den = (r8_u16)dy;
    /* dx = qd dy + rd, 0 <= rd < dy (floor division) */
    if (dx >= 0) {
        udx = (r8_u32)dx;
#ifdef R8_SCAN_GUARDED
        qd = (r8_u16)((r8_u16)udx / den);
        rd = (r8_u16)((r8_u16)udx % den);
#else
        if (udx < 0x10000UL) {
            qd = (r8_u16)((r8_u16)udx / den);
            rd = (r8_u16)((r8_u16)udx % den);
        } else {
            qd = (r8_u16)(udx / den);
            rd = (r8_u16)(udx % den);
        }
#endif
        it->q = (r8_s16)qd;
    } else {
        udx = (r8_u32)(-(dx + 1));               /* -dx - 1 >= 0 */
#ifdef R8_SCAN_GUARDED
        qd = (r8_u16)((r8_u16)udx / den);
        rd = (r8_u16)((r8_u16)udx % den);
#else
        if (udx < 0x10000UL) {
            qd = (r8_u16)((r8_u16)udx / den);
            rd = (r8_u16)((r8_u16)udx % den);
        } else {
            qd = (r8_u16)(udx / den);
            rd = (r8_u16)(udx % den);
        }
#endif
        it->q = (r8_s16)(-(r8_s16)qd - 1);
        rd = (r8_u16)(den - 1u - rd);
    }
    it->r = rd;
    it->den = den;
    /* N + D - 1 = 16 dy (axh + Ph) + U with ax - 8 = 16 axh + axl,
     * P = axl + s0 q = 16 Ph + Pl, U = dy Pl + s0 rd + 16 dy - 1 */
    p = (r8_s32)((r8_u32)axm & 15u) + s0 * (r8_s32)it->q;
    pl = (r8_u8)((r8_u32)p & 15u);
    it->val = (r8_s16)(r8_asr32(axm, 4) + r8_asr32(p, 4));
    d16 = (r8_u32)den << 4;
    u = (r8_u32)den * pl + (r8_u32)s0 * rd + d16 - 1u;   /* < 46 dy */
    while (u >= d16) {
        u -= d16;
        it->val++;
    }
    it->err = (r8_u16)(u >> 4);
    return y0;
}

/* The rare ends of edge_start, out of line so that the common path
 * keeps few registers (AVR: a short prologue): an empty edge (b at or
 * above a, only for non-convex input), an edge r8k_edge does not take
 * (R8_EDGE_WIDE), and an edge starting above row y, stepped down to it.
 * (The 16-bit set-up runs again here: these cases are rare.) */
void r8_edge_rare(r8_edge *e, const r8_s16 *a, const r8_s16 *b, r8_s16 y)
{
    r8_s16 y0;
    if (b[1] <= a[1]) {
        /* only for non-convex input: an empty edge at b */
        e->x.val = r8_row_of(b[0]);
        e->x.q = 0;
        e->x.r = e->x.err = 0;
        e->x.den = 1;
        return;
    }
    y0 = r8k_edge(&e->x, a, b);
    if (y0 == R8_EDGE_WIDE)
        y0 = edge_dda_wide(&e->x, a[0], a[1], b[0], b[1]);
    while (y0 < y) {
        R8_INTERP_STEP(&e->x);
        y0++;
    }
}

/* Set up edge e for row y from polygon position `from` (r8scan.h's
 * r8k_estart: its C reference is in scankern.c, AVR's in edge.S). */
#define edge_start(s, e, from, dir, y) r8k_estart(s, e, y, from)

r8_s16 r8_scanx_begin(r8_scanx *s, r8_u8 n, r8_s16 ystart)
{
    r8_u8 i, top = 0;
    r8_s16 ymin, ymax, y;
    s->n = n;
    s->backface = 0;
    s->front = 0;
    s->y = s->ybot = 0;
    if (n < 3 || n > R8_SCAN_MAXV)
        return 0;
    ymin = ymax = VY(s, 0);
    for (i = 1; i < n; i++) {
        r8_s16 vy = VY(s, i);
        if (vy < ymin) {
            ymin = vy;
            top = i;
        }
        if (vy > ymax)
            ymax = vy;
    }
    s->ybot = ROW_OF(ymax);
    y = ROW_OF(ymin);
    if (y < ystart)
        y = ystart;
    s->y = y;
    if (y >= s->ybot)
        return 0;
    edge_start(s, &s->l, top, -1, y);
    edge_start(s, &s->r, top, 1, y);
    return (r8_s16)(s->ybot - y);
}

/* Start row y: move either edge on to its next vertex where it ended,
 * then Judd's test.  0: a back face (the scan is over). */
int r8_scan_row(r8_scanx *s, r8_s16 y, int judd)
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


#if defined(R8_ASM_SCANX) && !defined(r8_scanx_fill)
/* a port's r8_scanx_fill (6502: ports/6502/scanx_6502.s) hands the
 * calls it does not take to this one, the reference, and restarts
 * edges through r8_scanx_edge */
#define r8_scanx_fill r8_scanx_fill_c
void r8_scanx_fill_c(r8_scanx *s, r8_s16 ylimit, int judd, r8_fb *fb, r8_u8 level);
void r8_scanx_edge(r8_scanx *s, r8_edge *e, int dir, r8_s16 y);
void r8_scanx_edge(r8_scanx *s, r8_edge *e, int dir, r8_s16 y)
{
    (void)dir;                     /* (e tells the chain) */
    edge_start(s, e, e->vi, dir, y);
}
#endif
#ifdef __AVR__
/* AVR: a page-1 band with no rows above it and Judd's test decided (the
 * common case) goes to r8k_scanband (r8scan.h; scanband.c's C, or
 * ports/avr/trap.S with R8_ASM_SCANFILL), the rest to this function */
#define R8_SCANBAND 1
#define R8_SCANX_FILL r8_scanx_fill_gen
void r8_scanx_fill_gen(r8_scanx *s, r8_s16 ylimit, int judd, r8_fb *fb, r8_u8 level);
#else
#define R8_SCANX_FILL r8_scanx_fill
#endif
void R8_SCANX_FILL(r8_scanx *s, r8_s16 ylimit, int judd, r8_fb *fb, r8_u8 level)
{
    r8_edge *l = &s->l, *r = &s->r;
    r8_s16 lim = s->ybot < ylimit ? s->ybot : ylimit;
#ifdef R8_SCANBAND
    r8_s16 y = s->y;
#else
    r8_s16 w = fb->width, y = s->y, by;
    r8_trapfill t;
#endif
#ifndef R8_PAGE1_ONLY
    if (fb->format != R8_FMT_PAGE1) {
        /* other layouts: one span at a time */
        for (; y < lim; y++) {
            r8_s16 xl, xr;
            if (!r8_scan_row(s, y, judd))
                return;
            xl = l->x.val;
            xr = r->x.val;
            R8_INTERP_STEP(&l->x);
            R8_INTERP_STEP(&r->x);
            if (xl < xr)
                r8_fb_span_dither(fb, y, xl, xr, level, 0);
        }
        s->y = y;
        return;
    }
#endif
    if (lim > fb->y0 + fb->rows)
        lim = (r8_s16)(fb->y0 + fb->rows);    /* never below the band */
    for (; y < fb->y0 && y < lim; y++) {      /* never above it either */
        if (!r8_scan_row(s, y, judd))
            return;
        R8_INTERP_STEP(&l->x);
        R8_INTERP_STEP(&r->x);
    }
    if (y >= lim) {
        s->y = y;
        return;
    }
#ifdef R8_SCANBAND
    /* (AVR) Judd's test row by row while undecided (each row then one
     * row of r8k_scanband, its edges already restarted), then the rest
     * of the band in one r8k_scanband */
    while (y < lim && judd && !s->front) {
        if (!r8_scan_row(s, y, judd))
            return;
        s->y = y;
        r8k_scanband(s, fb, (r8_s16)(y + 1), level);
        y++;
    }
    s->y = y;
    if (y < lim)
        r8k_scanband(s, fb, lim, level);
#else
    /* this row's page and bit, and the level's 4 dither rows in the
     * order the rows come; then trapezoids: runs of rows on which
     * neither edge ends, filled by the kernel (r8kern.h) */
    by = (r8_s16)(y - fb->y0);
    t.page = fb->buf + (unsigned)(by >> 3) * (unsigned)w;
    t.m = R8_FB_BIT(by);
    t.k = (r8_u8)(y & 3);            /* pat[k] is the pattern of rows k mod 4 */
    t.w = w;
    if (level > 16)
        level = 16;
    {
        /* R8_FB_DITHER(level, 0..3), the index once */
        const r8_u8 *dp = r8_fb_dither_tab + ((unsigned)level << 2);
        t.pat[0] = R8_RDU8(dp);
        t.pat[1] = R8_RDU8(dp + 1);
        t.pat[2] = R8_RDU8(dp + 2);
        t.pat[3] = R8_RDU8(dp + 3);
    }
    while (y < lim) {
        r8_s16 stop = lim;
        if (judd && !s->front) {
            if (!r8_scan_row(s, y, judd))
                return;
        } else {
            /* r8_scan_row without Judd's test: edges that ended restart */
            if (y >= l->yend)
                edge_start(s, l, l->vi, -1, y);
            if (y >= r->yend)
                edge_start(s, r, r->vi, 1, y);
        }
        if (l->yend < stop)
            stop = l->yend;
        if (r->yend < stop)
            stop = r->yend;
        if (judd && !s->front)
            stop = (r8_s16)(y + 1);       /* undecided: one row at a time */
        r8k_trap(&t, &l->x, &r->x, (r8_u16)(stop - y));
        y = stop;
    }
    s->y = y;
#endif
}

#ifdef R8_SCANBAND
void r8_scanx_fill(r8_scanx *s, r8_s16 ylimit, int judd, r8_fb *fb, r8_u8 level)
{
#ifndef R8_PAGE1_ONLY
    if (fb->format == R8_FMT_PAGE1)
#endif
    {
        r8_s16 lim = s->ybot < ylimit ? s->ybot : ylimit;
        if (lim > fb->y0 + fb->rows)
            lim = (r8_s16)(fb->y0 + fb->rows);
        if (s->y >= fb->y0 && (!judd || s->front)) {
            if (s->y < lim)
                r8k_scanband(s, fb, lim, level);
            return;
        }
    }
    r8_scanx_fill_gen(s, ylimit, judd, fb, level);
}
#endif
