/* wu.c - Wu's anti-aliased line (Xiaolin Wu, 1991), exact integer form:
 * ends ordered along the major axis (so either end gives the same
 * pixels), clipped by arithmetic to the band like r8_line, and walked
 * with two error terms: the minor position q + r/len and the weight
 * w = floor(16 r / len) with its remainder e, so no division per pixel
 * and no rounding that accumulates (r8raster.h gives the definition). */
#include "r8raster.h"
#include "r8fixed.h"

#ifndef R8_NO_WIRE

/* ceil(a * b / c) for a >= 0, b >= 0, c > 0 (a * b < 2^32). */
static r8_s32 ceil_md(r8_s32 a, r8_s32 b, r8_s32 c)
{
    r8_s32 t = r8_muldiv(a, b, c);
    if (t != 2147483647L &&
        (r8_u32)a * (r8_u32)b - (r8_u32)t * (r8_u32)c != 0)
        t++;
    return t;
}

/* Narrow [klo, khi] to the steps whose pair (q, q+1) can touch minor
 * offsets [qa, qb]: q in [qa - 1, qb], q = floor(k dm / len). */
static int k_floor(r8_s32 len, r8_s32 dm, r8_s32 qa, r8_s32 qb,
                   r8_s32 *klo, r8_s32 *khi)
{
    qa--;
    if (qb < 0 || qb < qa)
        return 0;
    if (dm == 0)
        return qa <= 0;
    if (qa > 0) {
        r8_s32 k = ceil_md(qa, len, dm);
        if (k > *klo)
            *klo = k;
    }
    {
        r8_s32 k = ceil_md(qb + 1, len, dm) - 1;
        if (k < *khi)
            *khi = k;
    }
    return *klo <= *khi;
}

static void plot(r8_fb *fb, r8_s16 x, r8_s16 y, r8_u8 lev, r8_u8 base)
{
    if (fb->format == R8_FMT_IDX8) {
        r8_u8 v = (r8_u8)(base + lev);
        if (v > r8_fb_get(fb, x, y))
            r8_fb_pixel(fb, x, y, v);
    } else if (lev > R8_RDU8(&r8_fb_dither_thresholds(y)[x & 3])) {
        r8_fb_pixel(fb, x, y, 1);
    }
}

void r8_wu_line(r8_fb *fb, r8_s16 x0, r8_s16 y0, r8_s16 x1, r8_s16 y1, r8_u8 base)
{
    r8_s32 dx = (r8_s32)x1 - x0, dy = (r8_s32)y1 - y0;
    r8_s32 adx = dx < 0 ? -dx : dx, ady = dy < 0 ? -dy : dy;
    int steep = ady > adx;
    r8_s32 ma0, mi0, len, dm, mlo, mhi, nlo, nhi, klo, khi, q, sm;
    r8_u16 r, e, w, a16, b16, ulen, udm;
    nlo = fb->y0 > 0 ? fb->y0 : 0;
    nhi = (r8_s32)fb->y0 + fb->rows;
    if (nhi > fb->height)
        nhi = fb->height;
    nhi--;
    if (!steep) {
        if (dx < 0) {
            ma0 = x1; mi0 = y1; dm = -dy;
        } else {
            ma0 = x0; mi0 = y0; dm = dy;
        }
        len = adx;
        mlo = 0; mhi = fb->width - 1;
    } else {
        if (dy < 0) {
            ma0 = y1; mi0 = x1; dm = -dx;
        } else {
            ma0 = y0; mi0 = x0; dm = dx;
        }
        len = ady;
        mlo = nlo; mhi = nhi;
        nlo = 0; nhi = fb->width - 1;
    }
    if (nhi < nlo)
        return;
    sm = 1;
    if (dm < 0) {
        sm = -1;
        dm = -dm;
    }
    klo = mlo - ma0;
    khi = mhi - ma0;
    if (klo < 0)
        klo = 0;
    if (khi > len)
        khi = len;
    if (klo > khi)
        return;
    if (len == 0) {
        if (mi0 >= nlo && mi0 <= nhi)
            plot(fb, (r8_s16)(steep ? mi0 : ma0), (r8_s16)(steep ? ma0 : mi0), 16, base);
        return;
    }
    if (sm > 0) {
        if (!k_floor(len, dm, nlo - mi0, nhi - mi0, &klo, &khi))
            return;
    } else {
        if (!k_floor(len, dm, mi0 - nhi, mi0 - nlo, &klo, &khi))
            return;
    }
    ulen = (r8_u16)len;
    udm = (r8_u16)dm;
    {
        r8_u32 p = (r8_u32)klo * (r8_u32)udm, t;
        q = (r8_s32)(p / ulen);
        r = (r8_u16)(p % ulen);
        t = (r8_u32)r << 4;
        w = (r8_u16)(t / ulen);
        e = (r8_u16)(t % ulen);
        t = (r8_u32)udm << 4;
        a16 = (r8_u16)(t / ulen);
        b16 = (r8_u16)(t % ulen);
    }
    {
        /* 16-bit walk: the major coordinate stays in the frame, the minor
         * pair within one pixel of the band */
        r8_s16 ma = (r8_s16)(ma0 + klo), m1 = (r8_s16)(mi0 + sm * q), m2;
        r8_s16 s = (r8_s16)sm, lo = (r8_s16)nlo, hi = (r8_s16)nhi;
        r8_u16 n = (r8_u16)(khi - klo);
        for (;;) {
            m2 = (r8_s16)(m1 + s);
            if (m1 >= lo && m1 <= hi) {
                if (steep)
                    plot(fb, m1, ma, (r8_u8)(16u - w), base);
                else
                    plot(fb, ma, m1, (r8_u8)(16u - w), base);
            }
            if (w && m2 >= lo && m2 <= hi) {
                if (steep)
                    plot(fb, m2, ma, (r8_u8)w, base);
                else
                    plot(fb, ma, m2, (r8_u8)w, base);
            }
            if (!n--)
                break;
            ma++;
            /* r += dm (mod len, carry into the minor); 16 r = w len + e */
            if (e >= ulen - b16) {
                e = (r8_u16)(e - (ulen - b16));
                w++;
            } else {
                e = (r8_u16)(e + b16);
            }
            w = (r8_u16)(w + a16);
            if (r >= ulen - udm) {
                r = (r8_u16)(r - (ulen - udm));
                m1 = m2;
                w = (r8_u16)(w - 16u);
            } else {
                r = (r8_u16)(r + udm);
            }
        }
    }
}

#endif /* R8_NO_WIRE */
