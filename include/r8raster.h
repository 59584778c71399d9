/* r8raster.h - the stepwise interpolator, Bresenham lines and scan
 * conversion of convex polygons.
 *
 * Fill convention: a pixel (c, r) is inside when its centre
 * (16c + 8, 16r + 8) in 12.4 subpixels lies in the polygon, with left
 * and top edges inclusive, right and bottom edges exclusive (top-left
 * rule).  Polygons sharing an edge therefore leave no gap and draw no
 * pixel twice.  Front faces wind clockwise on screen (y down).
 */
#ifndef R8RASTER_H
#define R8RASTER_H

#include "r8types.h"
#include "r8fb.h"
#include "r8fixed.h"

/* Stepwise linear interpolator, exact form: value(k) =
 * base + floor((num0 + k * step) / den), stepped with an integer error
 * term, so no rounding accumulates and the last step lands exactly on
 * the end value.  Carries any attribute: x along an edge, depth, shade,
 * texture u/v.  den is 1..32767. */
typedef struct r8_interp {
    r8_s16 val;   /* current value (floor) */
    r8_s16 q;     /* whole part of the step */
    r8_u16 err;   /* 0 <= err < den: fraction numerator */
    r8_u16 r;     /* 0 <= r < den: fraction of the step */
    r8_u16 den;
} r8_interp;

/* a to b in n steps (n >= 1): after n r8_interp_step calls val == b.
 * Needs |b - a| <= 32767. */
void r8_interp_reset(r8_interp *it, r8_s16 a, r8_s16 b, r8_u16 n);
/* General form (see above); |num0| and |step| may exceed 16 bits. */
void r8_interp_init(r8_interp *it, r8_s16 base, r8_s32 num0, r8_s32 step,
                    r8_u16 den);
/* Same with num0 = a * b formed without overflow for any a, b whose
 * quotient fits 16 bits. */
void r8_interp_init_mul(r8_interp *it, r8_s16 base, r8_s32 a, r8_s32 b,
                        r8_s32 step, r8_u16 den);
/* r8_interp_init_mul(it, base, s0, dv, dv * R8_SUBPX, n) without a
 * division (an edge's attribute at its first row), for
 * 0 <= s0 < R8_SUBPX, n = 1..256, |dv| < 65536 / R8_SUBPX. */
void r8_interp_init_sub(r8_interp *it, r8_s16 base, r8_u16 s0, r8_s16 dv, r8_u16 n);
#define R8_INTERP_STEP(it) do { (it)->val = (r8_s16)((it)->val + (it)->q); \
    (it)->err = (r8_u16)((it)->err + (it)->r); \
    if ((it)->err >= (it)->den) { (it)->err = (r8_u16)((it)->err - (it)->den); (it)->val++; } } while (0)
void r8_interp_step(r8_interp *it);

/* Bresenham line, endpoints inclusive, all octants, clipped to the
 * framebuffer band; the same pixels whichever end it starts from.
 * Any r8_s16 coordinates (pixels). */
void r8_line(r8_fb *fb, r8_s16 x0, r8_s16 y0, r8_s16 x1, r8_s16 y1, r8_u8 c);

/* Wu's anti-aliased line (src/wu.c), endpoints inclusive, any r8_s16
 * pixel coordinates, clipped exactly to the band like r8_line, the same
 * pixels whichever end it starts from (ends ordered along the major
 * axis).  At major step k the exact minor position is q + r/len
 * (q = floor(k*dminor/len), r its remainder): pixel q gets level
 * 16 - w and pixel q + 1 level w, w = floor(16 r / len) (0..15), the
 * sum always 16; an exact integer walk, no rounding accumulates.
 * IDX8: index base + level, written only where it is brighter than the
 * byte already there (lines crossing keep the brighter); 1 bpp: the
 * level through the 4x4 ordered dither, lit pixels set, none cleared.
 * Level 0 pixels are not touched. */
void r8_wu_line(r8_fb *fb, r8_s16 x0, r8_s16 y0, r8_s16 x1, r8_s16 y1, r8_u8 base);

/* Bresenham's midpoint circle (src/circle.c) about pixel (cx, cy),
 * radius r >= 0 (r < 0 draws nothing, r == 0 the centre pixel),
 * clipped to the frame and band.  Pixel (cx+a, cy+b), lo = min(|a|,|b|),
 * hi = max(|a|,|b|), is on the outline iff
 *     lo^2 + hi^2 - hi  <  r^2  <=  lo^2 + hi^2 + hi
 * (what the integer midpoint walk, d = 1 - r, plots in its 8 octants),
 * and in the filled disc iff lo^2 + hi^2 - hi < r^2: the outline and
 * everything inside it.  r up to 32767; the centre anywhere. */
void r8_circle(r8_fb *fb, r8_s16 cx, r8_s16 cy, r8_s16 r, r8_u8 c);
void r8_circle_fill(r8_fb *fb, r8_s16 cx, r8_s16 cy, r8_s16 r, r8_u8 c);

/* Screen-space vertex for the scan converter. */
typedef struct r8_svert {
    r8_s16 x, y;  /* 12.4 subpixels */
    r8_s16 d;     /* depth 0..32767, larger = nearer */
    r8_s16 s;     /* shade 8.8, 0..4096 */
} r8_svert;

#define R8_ATTR_D 1
#define R8_ATTR_S 2

/* One edge of a polygon being scanned.  x.val is the column of the
 * first pixel centre at or right of the edge on the current row, stepped
 * exactly from row to row (an exact DDA in pixel columns: no rounding
 * per row, no division per row). */
typedef struct r8_edge {
    r8_interp x;
    r8_s16 yend;  /* first row this edge does not cover */
    r8_u8 vi;     /* polygon position of the edge's lower vertex */
} r8_edge;

/* Vertices of a scanned polygon at most: a face (4) and what clipping
 * to five planes adds. */
#define R8_SCAN_MAXV 9

/* Resumable scan conversion of one convex polygon, top to bottom, edges
 * only (no attributes): a polygon can be scanned band by band without
 * re-walking its edges.  Vertex k of the polygon is vp[k]: x, y in 12.4,
 * then (for r8_scan with attributes) depth and shade: an r8_svert. */
typedef struct r8_scanx {
    const r8_s16 *vp[R8_SCAN_MAXV]; /* clockwise on screen for a front face */
    r8_u8 n;
    r8_u8 backface;     /* set when Judd's test found left right of right */
    r8_u8 front;        /* set when Judd's test found a front face */
    r8_s16 y;           /* next row */
    r8_s16 ybot;        /* first row below the polygon */
    r8_edge l, r;
} r8_scanx;

/* The same with depth and shade interpolated along the edges. */
typedef struct r8_scan {
    r8_scanx c;
    r8_u8 attrs;        /* R8_ATTR_* to interpolate */
    r8_interp ld, ls, rd, rs;
} r8_scan;

/* One span: pixels [x0, x1) of row y, with attributes at the left and
 * right edges (at this row's centre). */
typedef struct r8_span {
    r8_s16 y, x0, x1;
    r8_s16 dl, dr, sl, sr;
} r8_span;

/* Start scanning a polygon of n (3..R8_SCAN_MAXV) vertices v[idx[k]] at
 * row ystart (rows above it are skipped).  Returns the number of rows
 * left to scan (0: nothing to draw, or n out of range). */
r8_s16 r8_scan_begin(r8_scan *s, const r8_svert *v, const r8_u16 *idx,
                     r8_u8 n, r8_u8 attrs, r8_s16 ystart);
/* Next non-empty span on a row < ylimit; returns 0 when none is left
 * before ylimit (the scan can resume later with a larger ylimit).
 * With judd != 0 a row whose left edge lies right of its right edge
 * marks the polygon as a back face (s->c.backface) and ends it: back
 * faces draw nothing, front faces exactly what judd == 0 draws. */
int r8_scan_next(r8_scan *s, r8_s16 ylimit, int judd, r8_span *out);

/* Edges only: the caller has set s->vp[0..n). */
r8_s16 r8_scanx_begin(r8_scanx *s, r8_u8 n, r8_s16 ystart);
/* After r8_scanx_begin(&s->c, ...) returned rows: set up the attributes
 * s->attrs asks for along both edges. */
void r8_scan_attrs(r8_scan *s);
/* Scan rows < ylimit and fill every span with dither level `level` (no
 * depth test): the same pixels as r8_scan_next + r8_fb_span_dither, in
 * one loop (the fast path for cull-only and painter's with flat or
 * Lambert shading).  fb's band must cover the rows scanned. */
void r8_scanx_fill(r8_scanx *s, r8_s16 ylimit, int judd, r8_fb *fb, r8_u8 level);

/* Row of the first pixel centre at or below subpixel y: ceil((y-8)/16). */
r8_s16 r8_row_of(r8_s16 y);
/* The same in line, for |y| < 32760 (2048 beyond: below any frame). */
#define R8_ROW_OF(y) ((y) > 32760 ? 2048 : R8_FLOOR16((y) + 7))

/* Fill a polygon into fb with colour c, flat (convenience for tests and
 * tools).  Returns pixels written inside the band. */
r8_s32 r8_fill_poly(r8_fb *fb, const r8_svert *v, const r8_u16 *idx,
                    r8_u8 n, r8_u8 c);

#endif
