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

void r8_fb_clear(r8_fb *fb, r8_u8 c)
{
    r8_u8 v = c;
    if (fb->format != R8_FMT_IDX8)
        v = (r8_u8)(c ? 0xFF : 0x00);
    if (fb->format == R8_FMT_PAGE1 && fb->width > 0 && fb->rows > 0) /* (no call) */
        memset(fb->buf, v, R8_FB_PAGE1_BYTES(fb->width, fb->rows));
    else
        memset(fb->buf, v, r8_fb_bytes(fb->format, fb->width, fb->rows));
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

const r8_u8 r8_fb_bit[8] R8_FLASH = { 1, 2, 4, 8, 16, 32, 64, 128 };

/* r8_fb_dither_tab[4 s + (y & 3)]: the pattern of level s on row y */
const r8_u8 r8_fb_dither_tab[17 * 4] R8_FLASH = {
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
    return R8_FB_DITHER(s, y);
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

