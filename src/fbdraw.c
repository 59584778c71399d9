/* fbdraw.c - drawing into a band in any layout: pixels and spans, plain
 * and dithered, clipped to the frame and band.  (The renderer's page
 * layout fast path needs only fb.c.) */
#include "r8fb.h"
#include "r8flash.h"

/* Rows of the band that lie inside the frame. */
static r8_s16 band_rows(const r8_fb *fb)
{
    r8_s16 n = fb->rows;
    if (fb->y0 + n > fb->height)
        n = (r8_s16)(fb->height - fb->y0);
    return n < 0 ? 0 : n;
}

void r8_fb_pixel(r8_fb *fb, r8_s16 x, r8_s16 y, r8_u8 c)
{
    r8_u8 *p, m;
    if (x < 0 || x >= fb->width || y < fb->y0 || y >= fb->y0 + band_rows(fb))
        return;
    y = (r8_s16)(y - fb->y0);
    switch (fb->format) {
    case R8_FMT_PAGE1:
        p = fb->buf + (unsigned)(y >> 3) * (unsigned)fb->width + (unsigned)x;
        m = R8_FB_BIT(y);
        break;
    case R8_FMT_ROW1:
        p = fb->buf + (unsigned)y * (((unsigned)fb->width + 7u) >> 3) + ((unsigned)x >> 3);
        m = (r8_u8)(0x80u >> (x & 7));
        break;
    default:
        fb->buf[(unsigned)y * (unsigned)fb->width + (unsigned)x] = c;
        return;
    }
    if (c)
        *p |= m;
    else
        *p = (r8_u8)(*p & ~m);
}

r8_u8 r8_fb_get(const r8_fb *fb, r8_s16 x, r8_s16 y)
{
    if (x < 0 || x >= fb->width || y < fb->y0 || y >= fb->y0 + band_rows(fb))
        return 0;
    y = (r8_s16)(y - fb->y0);
    switch (fb->format) {
    case R8_FMT_PAGE1:
        return (r8_u8)((fb->buf[(unsigned)(y >> 3) * (unsigned)fb->width + (unsigned)x] >> (y & 7)) & 1u);
    case R8_FMT_ROW1:
        return (r8_u8)((fb->buf[(unsigned)y * (((unsigned)fb->width + 7u) >> 3) + ((unsigned)x >> 3)] >> (7 - (x & 7))) & 1u);
    default:
        return fb->buf[(unsigned)y * (unsigned)fb->width + (unsigned)x];
    }
}

/* Clip [x0,x1) on row y to frame and band; returns 0 if nothing left. */
static int clip_span(const r8_fb *fb, r8_s16 y, r8_s16 *x0, r8_s16 *x1)
{
    if (y < fb->y0 || y >= fb->y0 + band_rows(fb))
        return 0;
    if (*x0 < 0)
        *x0 = 0;
    if (*x1 > fb->width)
        *x1 = fb->width;
    return *x0 < *x1;
}

/* Write pattern pat (byte-wide, MSB = leftmost pixel with x%8 == 0)
 * into [x0,x1) of row y (band-relative).  Row-major 1 bpp. */
static void row1_pattern(r8_fb *fb, r8_s16 y, r8_s16 x0, r8_s16 x1, r8_u8 pat)
{
    r8_u8 *p = fb->buf + (unsigned)y * (((unsigned)fb->width + 7u) >> 3) + ((unsigned)x0 >> 3);
    r8_u8 lm = (r8_u8)(0xFFu >> (x0 & 7));           /* bits from x0 on */
    r8_s16 last = (r8_s16)(x1 - 1);
    r8_u8 rm = (r8_u8)(0xFFu << (7 - (last & 7)));   /* bits up to last */
    r8_s16 n = (r8_s16)((last >> 3) - (x0 >> 3));
    if (n == 0) {
        lm &= rm;
        *p = (r8_u8)((*p & ~lm) | (pat & lm));
        return;
    }
    *p = (r8_u8)((*p & ~lm) | (pat & lm));
    p++;
    while (--n > 0)
        *p++ = pat;
    *p = (r8_u8)((*p & ~rm) | (pat & rm));
}

/* Page layout: one byte per pixel column, bit (row & 7). */
static void page1_pattern(r8_fb *fb, r8_s16 y, r8_s16 x0, r8_s16 x1, r8_u8 pat)
{
    r8_fb_page_run(fb->buf + (unsigned)(y >> 3) * (unsigned)fb->width + (unsigned)x0,
                   (unsigned)(x1 - x0), R8_FB_BIT(y), pat, (r8_u8)(x0 & 3));
}

static void idx8_fill(r8_fb *fb, r8_s16 y, r8_s16 x0, r8_s16 x1, r8_u8 c)
{
    r8_u8 *p = fb->buf + (unsigned)y * (unsigned)fb->width + (unsigned)x0;
    r8_s16 x;
    for (x = x0; x < x1; x++)
        *p++ = c;
}

void r8_fb_span(r8_fb *fb, r8_s16 y, r8_s16 x0, r8_s16 x1, r8_u8 c)
{
    if (!clip_span(fb, y, &x0, &x1))
        return;
    y = (r8_s16)(y - fb->y0);
    switch (fb->format) {
    case R8_FMT_PAGE1:
        page1_pattern(fb, y, x0, x1, (r8_u8)(c ? 0xFF : 0));
        break;
    case R8_FMT_ROW1:
        row1_pattern(fb, y, x0, x1, (r8_u8)(c ? 0xFF : 0));
        break;
    default:
        idx8_fill(fb, y, x0, x1, c);
    }
}

#ifdef R8_COUNT_PX
r8_u32 r8_px_written;
#endif

void r8_fb_span_dither(r8_fb *fb, r8_s16 y, r8_s16 x0, r8_s16 x1,
                       r8_u8 s, r8_u8 base)
{
    r8_u8 pat;
    if (!clip_span(fb, y, &x0, &x1))
        return;
    R8_COUNT_PX_ADD(x1 - x0);
    pat = r8_fb_dither_row(s, y);
    y = (r8_s16)(y - fb->y0);
    switch (fb->format) {
    case R8_FMT_PAGE1:
        page1_pattern(fb, y, x0, x1, pat);
        break;
    case R8_FMT_ROW1:
        row1_pattern(fb, y, x0, x1, pat);
        break;
    default:
        idx8_fill(fb, y, x0, x1, (r8_u8)(base + s));
    }
}

void r8_fb_dot(r8_fb *fb, r8_s16 x, r8_s16 y, r8_u8 s, r8_u8 base)
{
    if (fb->format == R8_FMT_IDX8)
        r8_fb_pixel(fb, x, y, (r8_u8)(base + s));
    else
        r8_fb_pixel(fb, x, y, (r8_u8)(s > R8_RDU8(&r8_fb_dither_thresholds(y)[x & 3])));
}
