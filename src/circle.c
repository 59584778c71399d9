/* circle.c - Bresenham's midpoint circle (the integer form: d = 1 - r),
 * outline and filled, clipped to the frame and band.  One octant is
 * walked (x from 0 while x <= y) and mirrored eight ways; the filled
 * disc is the outline's spans, one per row reached.  The pixels are
 * defined in r8raster.h; tests/c/test_circle.c checks them against that
 * closed form. */
#include "r8raster.h"

#ifndef R8_NO_WIRE

/* band rows [*ylo, *yhi] of fb; 0 if it holds none */
static int band_rows(const r8_fb *fb, r8_s32 *ylo, r8_s32 *yhi)
{
    *ylo = fb->y0 > 0 ? fb->y0 : 0;
    *yhi = (r8_s32)fb->y0 + fb->rows;
    if (*yhi > fb->height)
        *yhi = fb->height;
    (*yhi)--;
    return *ylo <= *yhi;
}

static void dot(r8_fb *fb, r8_s32 x, r8_s32 y, r8_u8 c, r8_s32 ylo, r8_s32 yhi)
{
    if (x >= 0 && x < fb->width && y >= ylo && y <= yhi)
        r8_fb_pixel(fb, (r8_s16)x, (r8_s16)y, c);
}

/* pixels [x0, x1] of row y */
static void span(r8_fb *fb, r8_s32 y, r8_s32 x0, r8_s32 x1, r8_u8 c, r8_s32 ylo, r8_s32 yhi)
{
    if (y < ylo || y > yhi)
        return;
    if (x0 < 0)
        x0 = 0;
    if (x1 >= fb->width)
        x1 = fb->width - 1;
    if (x0 <= x1)
        r8_fb_span(fb, (r8_s16)y, (r8_s16)x0, (r8_s16)(x1 + 1), c);
}

/* The same walk in 16 bits (|cx| + r, |cy| + r <= 32766, r <= 8191:
 * every coordinate and d fit r8_s16); r8_fb_pixel and r8_fb_span clip. */
static void circle16(r8_fb *fb, r8_s16 cx, r8_s16 cy, r8_s16 r, r8_u8 c, int fill)
{
    r8_s16 x = 0, y = r, d = (r8_s16)(1 - r);
    while (x <= y) {
        int ydown = d >= 0;
        if (fill) {
            r8_fb_span(fb, (r8_s16)(cy + x), (r8_s16)(cx - y), (r8_s16)(cx + y + 1), c);
            if (x)
                r8_fb_span(fb, (r8_s16)(cy - x), (r8_s16)(cx - y), (r8_s16)(cx + y + 1), c);
            if (ydown) {
                r8_fb_span(fb, (r8_s16)(cy + y), (r8_s16)(cx - x), (r8_s16)(cx + x + 1), c);
                r8_fb_span(fb, (r8_s16)(cy - y), (r8_s16)(cx - x), (r8_s16)(cx + x + 1), c);
            }
        } else {
            r8_fb_pixel(fb, (r8_s16)(cx + x), (r8_s16)(cy + y), c);
            r8_fb_pixel(fb, (r8_s16)(cx - x), (r8_s16)(cy + y), c);
            r8_fb_pixel(fb, (r8_s16)(cx + x), (r8_s16)(cy - y), c);
            r8_fb_pixel(fb, (r8_s16)(cx - x), (r8_s16)(cy - y), c);
            r8_fb_pixel(fb, (r8_s16)(cx + y), (r8_s16)(cy + x), c);
            r8_fb_pixel(fb, (r8_s16)(cx - y), (r8_s16)(cy + x), c);
            r8_fb_pixel(fb, (r8_s16)(cx + y), (r8_s16)(cy - x), c);
            r8_fb_pixel(fb, (r8_s16)(cx - y), (r8_s16)(cy - x), c);
        }
        if (ydown) {
            d = (r8_s16)(d + 2 * (x - y) + 5);
            y--;
        } else {
            d = (r8_s16)(d + 2 * x + 3);
        }
        x++;
    }
}

/* fill: 0 outline, 1 disc */
static void circle(r8_fb *fb, r8_s16 cx0, r8_s16 cy0, r8_s16 r, r8_u8 c, int fill)
{
    r8_s32 cx = cx0, cy = cy0, x = 0, y = r, d = 1 - (r8_s32)r, ylo, yhi;
    if (r < 0 || !band_rows(fb, &ylo, &yhi))
        return;
    /* nothing of it in the band or frame */
    if (cy + r < ylo || cy - r > yhi || cx + r < 0 || cx - r >= fb->width)
        return;
    if (r == 0) {
        dot(fb, cx, cy, c, ylo, yhi);
        return;
    }
    if (r <= 8191 && cx >= -32766 + r && cx <= 32766 - r && cy >= -32766 + r && cy <= 32766 - r) {
        circle16(fb, cx0, cy0, r, c, fill);
        return;
    }
    while (x <= y) {
        int ydown = d >= 0;    /* the next column steps y down */
        if (fill) {
            span(fb, cy + x, cx - y, cx + y, c, ylo, yhi);
            if (x)
                span(fb, cy - x, cx - y, cx + y, c, ylo, yhi);
            if (ydown) {    /* row y's widest span (a last column with
                               x == y is row x's span above) */
                span(fb, cy + y, cx - x, cx + x, c, ylo, yhi);
                span(fb, cy - y, cx - x, cx + x, c, ylo, yhi);
            }
        } else {
            dot(fb, cx + x, cy + y, c, ylo, yhi);
            dot(fb, cx - x, cy + y, c, ylo, yhi);
            dot(fb, cx + x, cy - y, c, ylo, yhi);
            dot(fb, cx - x, cy - y, c, ylo, yhi);
            dot(fb, cx + y, cy + x, c, ylo, yhi);
            dot(fb, cx - y, cy + x, c, ylo, yhi);
            dot(fb, cx + y, cy - x, c, ylo, yhi);
            dot(fb, cx - y, cy - x, c, ylo, yhi);
        }
        if (ydown) {
            d += 2 * (x - y) + 5;
            y--;
        } else {
            d += 2 * x + 3;
        }
        x++;
    }
}

void r8_circle(r8_fb *fb, r8_s16 cx, r8_s16 cy, r8_s16 r, r8_u8 c)
{
    circle(fb, cx, cy, r, c, 0);
}

void r8_circle_fill(r8_fb *fb, r8_s16 cx, r8_s16 cy, r8_s16 r, r8_u8 c)
{
    circle(fb, cx, cy, r, c, 1);
}

#endif /* R8_NO_WIRE */
