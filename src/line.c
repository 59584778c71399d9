/* line.c - Bresenham's line (the seed's integer stepwise interpolation),
 * endpoints inclusive, in all octants, clipped exactly: the visible part
 * is found by arithmetic (no stepping through off-screen pixels), and the
 * pixels are those of the unclipped line.  Endpoints are put in a fixed
 * order (increasing along the major axis) so both directions give the
 * same pixels.  Minor coordinate at step k: floor(k*dminor/dmajor + 1/2). */
#include "r8raster.h"
#include "r8fixed.h"

/* ceil(a * b / c) for a >= 0, b >= 0, c > 0: 16- or 32-bit division
 * when the product fits (lines on and near the screen), else the 64-bit
 * r8_muldiv. */
static r8_s32 ceil_muldiv(r8_s32 a, r8_s32 b, r8_s32 c)
{
    r8_s32 t;
    if (a <= 0xFFFFL && b <= 0xFFFFL) {
        r8_u32 p = (r8_u32)a * (r8_u32)b;
        if (p <= 0xFFFFu && c <= 0xFFFFL) {
            r8_u16 p16 = (r8_u16)p, c16 = (r8_u16)c;
            return (r8_s32)(p16 / c16 + (p16 % c16 != 0));
        }
        return (r8_s32)(p / (r8_u32)c + (p % (r8_u32)c != 0));
    }
    t = r8_muldiv(a, b, c);
    if (t != 2147483647L &&     /* saturated: far past any end anyway */
        (r8_u32)a * (r8_u32)b - (r8_u32)t * (r8_u32)c != 0)
        t++;
    return t;
}

/* The walk in place (PAGE1, IDX8; len < 16384): byte offset and bit mask
 * stepped with the pixel, 16-bit error term, no per-pixel call. */
static void walk(r8_fb *fb, r8_s16 x, r8_s16 y, int steep, r8_s16 sm,
                 r8_u16 n, r8_u16 err, r8_u16 e2dm, r8_u16 e2len, r8_u8 c)
{
    unsigned w = (unsigned)fb->width, off;
    r8_u8 *buf = fb->buf, m = 0;
    int idx8 = fb->format == R8_FMT_IDX8;
    y = (r8_s16)(y - fb->y0);
    if (idx8) {
        off = (unsigned)y * w + (unsigned)x;
    } else {
        off = (unsigned)(y >> 3) * w + (unsigned)x;
        m = R8_FB_BIT(y);
    }
    for (;;) {
        int minor;
        if (idx8)
            buf[off] = c;
        else if (c)
            buf[off] = (r8_u8)(buf[off] | m);
        else
            buf[off] = (r8_u8)(buf[off] & ~m);
        if (!n--)
            break;
        err = (r8_u16)(err + e2dm);
        minor = err >= e2len;
        if (minor)
            err = (r8_u16)(err - e2len);
        /* major step: x + 1, or y + 1 when steep */
        if (!steep || idx8) {
            off += steep ? w : 1u;
        } else {
            m = (r8_u8)(m << 1);
            if (!m) {
                m = 1;
                off += w;
            }
        }
        if (!minor)
            continue;
        /* minor step: y + sm, or x + sm when steep */
        if (steep) {
            off += (unsigned)(r8_s16)sm;    /* wraps back for -1 */
        } else if (idx8) {
            off += sm > 0 ? w : (unsigned)(0u - w);
        } else if (sm > 0) {
            m = (r8_u8)(m << 1);
            if (!m) {
                m = 1;
                off += w;
            }
        } else {
            m = (r8_u8)(m >> 1);
            if (!m) {
                m = 0x80;
                off -= w;
            }
        }
    }
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
    /* minor-axis clip: minor = mi0 + sm * q (none if the line's minor
     * range lies inside: steep edges in a band) */
    if (mi0 >= nlo && mi0 <= nhi && mi0 + sm * dm >= nlo && mi0 + sm * dm <= nhi) {
        /* whole minor range visible */
    } else if (sm > 0) {
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
    if (len < 16384 && fb->format != R8_FMT_ROW1) {
        /* q and err at k = klo, 16 bits: 2 k dm + len < 2^16 * 3/4 */
        r8_u16 e2len = (r8_u16)(2 * len), t16 = 0xFFFFu;
        if (klo < 256 && dm < 256)
            t16 = (r8_u16)((r8_u16)klo * (r8_u16)dm);
        if (t16 <= 0x5FFFu) {
            t16 = (r8_u16)(2u * t16 + (r8_u16)len);
            q = (r8_s32)(t16 / e2len);
            err = (r8_s32)(t16 % e2len);
        } else {
            a = (r8_u32)klo * (r8_u32)dm;      /* 32-bit only when needed */
            t = 2u * (a % (r8_u32)len) + (r8_u32)len;
            q = (r8_s32)(a / (r8_u32)len + t / (2u * (r8_u32)len));
            err = (r8_s32)(t % (2u * (r8_u32)len));
        }
        if (steep)
            walk(fb, (r8_s16)(mi0 + sm * q), (r8_s16)(ma0 + klo), 1, (r8_s16)sm,
                 (r8_u16)(khi - klo), (r8_u16)err, (r8_u16)(2 * dm), e2len, c);
        else
            walk(fb, (r8_s16)(ma0 + klo), (r8_s16)(mi0 + sm * q), 0, (r8_s16)sm,
                 (r8_u16)(khi - klo), (r8_u16)err, (r8_u16)(2 * dm), e2len, c);
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
