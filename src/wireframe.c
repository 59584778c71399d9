/* wireframe.c - the wireframe mode (cfg.wire): every face the renderer
 * keeps is drawn as its outline, Bresenham edges (r8_line) between its
 * screen vertices rounded down to pixels, hidden lines removed by
 *   - the cull (R8_VIS_CULL, and the depth methods, which fall back to
 *     it): only front faces' edges, exact for one convex mesh;
 *   - painter's (R8_VIS_PAINTER): far to near, each face first filled
 *     with level 0 (black), then its edges: nearer faces cover the
 *     edges behind them (exact where painter's is: convex objects apart
 *     in depth).
 * Band by band: r8_line clips exactly, so an edge drawn in pieces gives
 * the pixels it gives whole, and a face's fill is its scan seeked to the
 * band (no scan state kept).  Edges shared by two front faces are drawn
 * twice, with the same pixels (r8_line orders its ends). */
#include "r8int.h"

#ifndef R8_NO_WIRE

/* floor(v / 16): a pixel of a 12.4 coordinate (any r8_s16: the sum
 * wraps in 16 bits) */
#define PIX(v) R8_FLOOR16(v)

/* Screen winding (Judd's cull leaves back faces in the buckets): 1 for
 * a front face (clockwise on screen, y down: positive area). */
static int front(const r8_s16 *const *vp, r8_u8 n)
{
    r8_s32 d[2 * R8_SCAN_MAXV], m = 0, a = 0;
    r8_u8 i, j;
    for (i = 0; i < n; i++) {
        d[2 * i] = (r8_s32)vp[i][0] - vp[0][0];
        d[2 * i + 1] = (r8_s32)vp[i][1] - vp[0][1];
        for (j = 0; j < 2; j++) {
            r8_s32 v = d[2 * i + j] < 0 ? -d[2 * i + j] : d[2 * i + j];
            if (v > m)
                m = v;
        }
    }
    while (m > 8191) {     /* 9 cross terms of 2^27 fit r8_s32 */
        for (i = 0; i < 2 * n; i++)
            d[i] = r8_asr32(d[i], 1);
        m >>= 1;
    }
    for (i = 1; i + 1 < n; i++)
        a += d[2 * i] * d[2 * i + 3] - d[2 * i + 2] * d[2 * i + 1];
    return a > 0;
}

/* Face g's rows in [y0, y1) of fb: filled black first with `fill`. */
static void wire_face(r8_state *st, r8_fid g, r8_fb *fb, r8_s16 y0, r8_s16 y1,
                      int fill, r8_u8 colour)
{
    r8_acthead *e = (r8_acthead *)(void *)st->tmp;
    const r8_s16 **vp = e->c.vp;
    r8_s16 ylo, yhi, ra, rb, ys0 = (r8_s16)(y0 * 16), ys1 = (r8_s16)(y1 * 16);
    r8_u8 n, j;
    n = r8_face_vp(st, g, vp);
    ylo = yhi = vp[0][1];
    for (j = 1; j < n; j++) {
        if (vp[j][1] < ylo)
            ylo = vp[j][1];
        if (vp[j][1] > yhi)
            yhi = vp[j][1];
    }
    /* rows PIX(ylo) .. PIX(yhi) miss [y0, y1): 16 y0 fits (height <= 1024) */
    if (yhi < ys0 || ylo >= ys1)
        return;
    if (st->judd && !front(vp, n))
        return;
    if (fill && r8_scanx_begin(&e->c, n, y0))
        r8_scanx_fill(&e->c, y1, 0, fb, 0);
    for (j = 0; j < n; j++) {
        const r8_s16 *a = vp[j], *b = vp[j + 1 < n ? j + 1 : 0];
        ra = a[1];
        rb = b[1];
        if ((ra < ys0 && rb < ys0) || (ra >= ys1 && rb >= ys1))
            continue;      /* not in this band */
        r8_line(fb, PIX(a[0]), PIX(ra), PIX(b[0]), PIX(rb), colour);
    }
}

void r8_wire_band(r8_render *r, r8_fb *fb)
{
    r8_state *st = (r8_state *)r->state;
    r8_s16 y0 = fb->y0, y1 = (r8_s16)(fb->y0 + fb->rows);
    r8_u8 colour = (r8_u8)(fb->format == R8_FMT_IDX8 ? 16 : 1);
    r8_fid g;
    if (y1 > fb->height)
        y1 = fb->height;
    r8_fb_clear(fb, 0);
#if R8_W_PAINTER
    if (st->method == R8_VIS_PAINTER) {
        for (g = (r8_fid)st->first; g != (r8_fid)R8_FID_END; g = st->next[g])
            wire_face(st, g, fb, y0, y1, 1, colour);
        return;
    }
#endif
    {
        /* a face is in the bucket of its first pixel-centre row; its
         * edges reach at most one row above that: buckets 0 .. b + 1 */
        r8_u16 b, last = (r8_u16)((r8_u16)y0 / (r8_u16)r->cfg.band + 1u);
        if (last >= st->nbands)
            last = (r8_u16)(st->nbands - 1u);
        for (b = 0; b <= last; b++)
            for (g = st->heads[b]; g != (r8_fid)R8_FID_END; g = st->next[g])
                wire_face(st, g, fb, y0, y1, 0, colour);
    }
}

#endif /* R8_NO_WIRE */
