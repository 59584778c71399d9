/* fb.c - framebuffer bands: clear, pixel, span fill, dithered spans.
 * Layouts are described in r8fb.h. */
#include <string.h>
#include "r8fb.h"
#include "r8flash.h"

unsigned r8_fb_bytes(r8_u8 format, r8_s16 width, r8_s16 rows)
{
    if (width <= 0 || rows <= 0)
        return 0;
    switch (format) {
    case R8_FMT_PAGE1:
        return R8_FB_PAGE1_BYTES(width, rows);
    case R8_FMT_ROW1:
        return R8_FB_ROW1_BYTES(width, rows);
    case R8_FMT_IDX8:
        return R8_FB_IDX8_BYTES(width, rows);
    default:
        return 0;
    }
}

int r8_fb_init(r8_fb *fb, r8_u8 *buf, r8_u8 format, r8_s16 width,
               r8_s16 height, r8_s16 y0, r8_s16 rows)
{
    if (format > R8_FMT_IDX8 || width <= 0 || height <= 0 || rows <= 0 ||
        y0 < 0 || rows > height)
        return -1;
    if (format == R8_FMT_PAGE1 && ((rows & 7) || (y0 & 7)))
        return -1;
    fb->buf = buf;
    fb->format = format;
    fb->width = width;
    fb->height = height;
    fb->rows = rows;
    fb->y0 = y0;
    return 0;
}

void r8_fb_set_band(r8_fb *fb, r8_s16 y0)
{
    fb->y0 = y0;
}

/* Rows of the band that lie inside the frame. */
static r8_s16 band_rows(const r8_fb *fb)
{
    r8_s16 n = fb->rows;
    if (fb->y0 + n > fb->height)
        n = (r8_s16)(fb->height - fb->y0);
    return n < 0 ? 0 : n;
}

void r8_fb_clear(r8_fb *fb, r8_u8 c)
{
    r8_u8 v = c;
    if (fb->format != R8_FMT_IDX8)
        v = (r8_u8)(c ? 0xFF : 0x00);
    memset(fb->buf, v, r8_fb_bytes(fb->format, fb->width, fb->rows));
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
        m = (r8_u8)(1u << (y & 7));
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

/* Ordered 4x4 dither thresholds: level s lights pixel (x,y) iff
 * s > bayer[y&3][x&3].  Level 0 is black, 16 is white. */
static const r8_u8 bayer4[16] R8_FLASH = {
    0, 8, 2, 10,
    12, 4, 14, 6,
    3, 11, 1, 9,
    15, 7, 13, 5
};

/* The row's 4 thresholds (flash: read with R8_RDU8). */
const r8_u8 *r8_fb_dither_thresholds(r8_s16 y)
{
    return bayer4 + ((y & 3) << 2);
}

/* dither_rows[4 s + (y & 3)]: the pattern of level s on row y */
static const r8_u8 dither_rows[17 * 4] R8_FLASH = {
    0x00, 0x00, 0x00, 0x00,
    0x88, 0x00, 0x00, 0x00,
    0x88, 0x00, 0x22, 0x00,
    0xAA, 0x00, 0x22, 0x00,
    0xAA, 0x00, 0xAA, 0x00,
    0xAA, 0x44, 0xAA, 0x00,
    0xAA, 0x44, 0xAA, 0x11,
    0xAA, 0x55, 0xAA, 0x11,
    0xAA, 0x55, 0xAA, 0x55,
    0xEE, 0x55, 0xAA, 0x55,
    0xEE, 0x55, 0xBB, 0x55,
    0xFF, 0x55, 0xBB, 0x55,
    0xFF, 0x55, 0xFF, 0x55,
    0xFF, 0xDD, 0xFF, 0x55,
    0xFF, 0xDD, 0xFF, 0x77,
    0xFF, 0xFF, 0xFF, 0x77,
    0xFF, 0xFF, 0xFF, 0xFF
};

r8_u8 r8_fb_dither_row(r8_u8 s, r8_s16 y)
{
    if (s > 16)
        s = 16;
    return R8_RDU8(&dither_rows[((unsigned)s << 2) | (unsigned)(y & 3)]);
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

void r8_fb_page_run(r8_u8 *p, unsigned n, r8_u8 m, r8_u8 pat, r8_u8 ph)
{
    r8_u8 nm = (r8_u8)~m;
    r8_u8 *e = p + n;
    if (pat == 0xFF) {
        while (p < e)
            *p++ |= m;
    } else if (pat == 0) {
        while (p < e)
            *p++ &= nm;
    } else {
        /* dither patterns repeat every 4 pixels: one ready-made bit per
         * phase, four columns per step */
        r8_u8 l0 = (r8_u8)(pat & 0x08 ? m : 0), l1 = (r8_u8)(pat & 0x04 ? m : 0);
        r8_u8 l2 = (r8_u8)(pat & 0x02 ? m : 0), l3 = (r8_u8)(pat & 0x01 ? m : 0);
        ph &= 3;
        while (ph && p < e) {
            r8_u8 v = l3;   /* an if chain: cc65 2.19 miscompiles the nested ?: here */
            if (ph == 1)
                v = l1;
            else if (ph == 2)
                v = l2;
            *p = (r8_u8)((*p & nm) | v);
            p++;
            ph = (r8_u8)((ph + 1) & 3);
        }
        while (e - p >= 4) {
            p[0] = (r8_u8)((p[0] & nm) | l0);
            p[1] = (r8_u8)((p[1] & nm) | l1);
            p[2] = (r8_u8)((p[2] & nm) | l2);
            p[3] = (r8_u8)((p[3] & nm) | l3);
            p += 4;
        }
        if (p < e) *p = (r8_u8)((*p & nm) | l0), p++;
        if (p < e) *p = (r8_u8)((*p & nm) | l1), p++;
        if (p < e) *p = (r8_u8)((*p & nm) | l2);
    }
}

/* Page layout: one byte per pixel column, bit (row & 7). */
static void page1_pattern(r8_fb *fb, r8_s16 y, r8_s16 x0, r8_s16 x1, r8_u8 pat)
{
    r8_fb_page_run(fb->buf + (unsigned)(y >> 3) * (unsigned)fb->width + (unsigned)x0,
                   (unsigned)(x1 - x0), (r8_u8)(1u << (y & 7)), pat, (r8_u8)(x0 & 3));
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

void r8_fb_span_dither(r8_fb *fb, r8_s16 y, r8_s16 x0, r8_s16 x1,
                       r8_u8 s, r8_u8 base)
{
    r8_u8 pat;
    if (!clip_span(fb, y, &x0, &x1))
        return;
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
        r8_fb_pixel(fb, x, y, (r8_u8)(s > R8_RDU8(&bayer4[((y & 3) << 2) | (x & 3)])));
}
