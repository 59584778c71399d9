/* line.c - Bresenham's line (the seed's integer stepwise interpolation),
 * endpoints inclusive, in all octants, clipped exactly: the visible part
 * is found by arithmetic (no stepping through off-screen pixels), and the
 * pixels are those of the unclipped line.  Endpoints are put in a fixed
 * order (increasing along the major axis) so both directions give the
 * same pixels.  Minor coordinate at step k: floor(k*dminor/dmajor + 1/2). */
#include "r8raster.h"
#include "r8fixed.h"

/* ceil(a * b / c) for a >= 0, b >= 0, c > 0. */
static r8_s32 ceil_muldiv(r8_s32 a, r8_s32 b, r8_s32 c)
{
    r8_s32 t = r8_muldiv(a, b, c);
    if ((r8_u32)a * (r8_u32)b - (r8_u32)t * (r8_u32)c != 0)
        t++;
    return t;
}

/* Steps k in [0, len] of the line whose minor offset q(k) lies in
 * [qlo, qhi]; returns 0 if none.  q(k) = floor((2k*dm + len) / (2len)). */
static int k_range(r8_s32 len, r8_s32 dm, r8_s32 qlo, r8_s32 qhi,
                   r8_s32 *klo, r8_s32 *khi)
{
    if (qhi < qlo || qhi < 0)
        return 0;
    if (dm == 0) {
        if (qlo > 0)
            return 0;
        return 1; /* q stays 0: leave the range as it is */
    }
    if (qlo > 0) {
        /* q >= qlo  <=>  k >= (2qlo - 1) * len / (2dm) */
        r8_s32 k = ceil_muldiv(2 * qlo - 1, len, 2 * dm);
        if (k > *klo)
            *klo = k;
    }
    {
        /* q <= qhi  <=>  k < (2qhi + 1) * len / (2dm) */
        r8_s32 k = ceil_muldiv(2 * qhi + 1, len, 2 * dm) - 1;
        if (k < *khi)
            *khi = k;
    }
    return *klo <= *khi;
}

void r8_line(r8_fb *fb, r8_s16 x0, r8_s16 y0, r8_s16 x1, r8_s16 y1, r8_u8 c)
{
    r8_s32 dx = (r8_s32)x1 - x0, dy = (r8_s32)y1 - y0;
    r8_s32 adx = dx < 0 ? -dx : dx, ady = dy < 0 ? -dy : dy;
    int steep = ady > adx;
    r8_s32 ma0, mi0, len, dm, sm;     /* major start, minor start, ... */
    r8_s32 mlo, mhi, nlo, nhi;        /* visible major / minor ranges */
    r8_s32 klo, khi, k, q, err;
    r8_u32 a, t;
    nlo = fb->y0 > 0 ? fb->y0 : 0;
    nhi = (r8_s32)fb->y0 + fb->rows;
    if (nhi > fb->height)
        nhi = fb->height;
    nhi--;
    if (!steep) {
        if (dx < 0) { /* go left to right */
            ma0 = x1; mi0 = y1; dm = -dy;
        } else {
            ma0 = x0; mi0 = y0; dm = dy;
        }
        len = adx;
        mlo = 0; mhi = fb->width - 1;
    } else {
        if (dy < 0) { /* go top to bottom */
            ma0 = y1; mi0 = x1; dm = -dx;
        } else {
            ma0 = y0; mi0 = x0; dm = dx;
        }
        len = ady;
        mlo = nlo; mhi = nhi;
        nlo = 0; nhi = fb->width - 1;
    }
    sm = dm < 0 ? -1 : 1;
    if (dm < 0)
        dm = -dm;
    /* major-axis clip */
    klo = mlo - ma0;
    khi = mhi - ma0;
    if (klo < 0)
        klo = 0;
    if (khi > len)
        khi = len;
    if (klo > khi)
        return;
    /* minor-axis clip: minor = mi0 + sm * q */
    if (sm > 0) {
        if (!k_range(len, dm, nlo - mi0, nhi - mi0, &klo, &khi))
            return;
    } else {
        if (!k_range(len, dm, mi0 - nhi, mi0 - nlo, &klo, &khi))
            return;
    }
    if (len == 0) {
        r8_fb_pixel(fb, (r8_s16)(steep ? mi0 : ma0), (r8_s16)(steep ? ma0 : mi0), c);
        return;
    }
    /* q and err at k = klo: (2 k dm + len) / (2 len), without overflow */
    a = (r8_u32)klo * (r8_u32)dm;
    t = 2u * (a % (r8_u32)len) + (r8_u32)len;
    q = (r8_s32)(a / (r8_u32)len + t / (2u * (r8_u32)len));
    err = (r8_s32)(t % (2u * (r8_u32)len));
    for (k = klo; k <= khi; k++) {
        r8_s32 ma = ma0 + k, mi = mi0 + sm * q;
        if (steep)
            r8_fb_pixel(fb, (r8_s16)mi, (r8_s16)ma, c);
        else
            r8_fb_pixel(fb, (r8_s16)ma, (r8_s16)mi, c);
        err += 2 * dm;
        if (err >= 2 * len) {
            err -= 2 * len;
            q++;
        }
    }
}
