/* r8fb.h - framebuffers and framebuffer bands.
 *
 * A band is rows y0 .. y0+rows-1 of a width x height frame; the whole
 * frame is the band with y0 = 0, rows = height.  The caller owns buf and
 * sizes it with R8_FB_*_BYTES(width, rows) or r8_fb_bytes().
 *
 * Formats (the wire protocol uses the same numbers and byte layouts):
 *   R8_FMT_PAGE1  1 bpp, SSD1306 page layout: byte (row/8)*width + x,
 *                 bit (row % 8), bit 0 = top row of the page.  rows of a
 *                 band must be a multiple of 8 (y0 too).
 *   R8_FMT_ROW1   1 bpp row-major: byte row*((width+7)/8) + x/8,
 *                 bit 7 - (x % 8) (MSB = leftmost pixel, as PBM).
 *   R8_FMT_IDX8   8 bpp indexed: byte row*width + x is a palette index.
 * A set bit is a lit pixel.
 */
#ifndef R8FB_H
#define R8FB_H

#include "r8types.h"
#include "r8flash.h"

#define R8_FMT_PAGE1 0
#define R8_FMT_ROW1 1
#define R8_FMT_IDX8 2

#define R8_FB_PAGE1_BYTES(w, rows) ((unsigned)(w) * (((unsigned)(rows) + 7u) >> 3))
#define R8_FB_ROW1_BYTES(w, rows) ((((unsigned)(w) + 7u) >> 3) * (unsigned)(rows))
#define R8_FB_IDX8_BYTES(w, rows) ((unsigned)(w) * (unsigned)(rows))

typedef struct r8_fb {
    r8_u8 *buf;
    r8_s16 width;  /* whole frame width in pixels */
    r8_s16 height; /* whole frame height in pixels */
    r8_s16 y0;     /* first frame row held in buf */
    r8_s16 rows;   /* rows held in buf */
    r8_u8 format;  /* R8_FMT_* */
} r8_fb;

/* Bytes needed for `rows` rows of a `width`-wide frame in `format`;
 * 0 for an unknown format. */
unsigned r8_fb_bytes(r8_u8 format, r8_s16 width, r8_s16 rows);

/* Set up fb over buf; returns 0, or -1 for a bad format/size/alignment. */
int r8_fb_init(r8_fb *fb, r8_u8 *buf, r8_u8 format, r8_s16 width,
               r8_s16 height, r8_s16 y0, r8_s16 rows);

/* Move the band to start at frame row y0 (rows unchanged, clipped at the
 * bottom of the frame).  Does not clear. */
void r8_fb_set_band(r8_fb *fb, r8_s16 y0);

/* Fill the band with colour c (0/1 for 1 bpp, an index for 8 bpp). */
void r8_fb_clear(r8_fb *fb, r8_u8 c);

/* Pixel at frame coordinates; writes outside the band or frame are
 * ignored, reads outside return 0. */
void r8_fb_pixel(r8_fb *fb, r8_s16 x, r8_s16 y, r8_u8 c);
r8_u8 r8_fb_get(const r8_fb *fb, r8_s16 x, r8_s16 y);

/* Horizontal span [x0, x1) on frame row y in colour c, clipped to the
 * frame and band; whole bytes are written where the layout allows. */
void r8_fb_span(r8_fb *fb, r8_s16 y, r8_s16 x0, r8_s16 x1, r8_u8 c);

/* Span of shade level s (0 = black .. 16 = white) through the ordered
 * 4x4 dither (1 bpp); for 8 bpp it writes index `base + s`. */
void r8_fb_span_dither(r8_fb *fb, r8_s16 y, r8_s16 x0, r8_s16 x1,
                       r8_u8 s, r8_u8 base);

/* The 4x4 ordered-dither pattern of level s on frame row y: a byte,
 * MSB = pixel x % 8 == 0, period 4. */
r8_u8 r8_fb_dither_row(r8_u8 s, r8_s16 y);
/* The same in line for s <= 16 (the table is R8_FLASH data). */
extern const r8_u8 r8_fb_dither_tab[17 * 4];
#define R8_FB_DITHER(s, y) R8_RDU8(&r8_fb_dither_tab[((unsigned)(s) << 2) | ((unsigned)(y) & 3u)])
/* The 4 dither thresholds of frame row y: level s lights pixel x iff
 * s > t[x & 3].  The table is R8_FLASH data: read it with R8_RDU8. */
const r8_u8 *r8_fb_dither_thresholds(r8_s16 y);

/* Page-layout run: n column bytes from p, bit mask m, 4-periodic
 * pattern pat starting at phase ph (x & 3): the inner loop of page fills. */
void r8_fb_page_run(r8_u8 *p, unsigned n, r8_u8 m, r8_u8 pat, r8_u8 ph);

/* The page-layout bit of row r (0..7): 1 << r, from a table in flash
 * (cc65 2.19 -O miscompiles (r8_u8)(1u << (n & 7)) stored to a struct
 * member; a lookup is also faster than a variable shift on 8-bit CPUs). */
extern const r8_u8 r8_fb_bit[8];
#define R8_FB_BIT(r) R8_RDU8(&r8_fb_bit[(r) & 7])

/* One pixel of shade level s through the same dither (8 bpp: base + s). */
void r8_fb_dot(r8_fb *fb, r8_s16 x, r8_s16 y, r8_u8 s, r8_u8 base);

/* Bench instrumentation (host builds with -DR8_COUNT_PX only, bench/
 * portal_bench.c): pixels written into bands by the span and pixel
 * writers, for the overdraw figures. */
#ifdef R8_COUNT_PX
extern r8_u32 r8_px_written;
#define R8_COUNT_PX_ADD(n) (r8_px_written += (r8_u32)(n))
#else
#define R8_COUNT_PX_ADD(n) ((void)0)
#endif

#endif
