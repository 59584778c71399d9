/* r8zrows.h - the 16-bit z-buffer's row kernel (r8_zfill's rows on
 * which neither edge moves on to its next vertex), shared by
 * src/vis_zbuf.c, its C89 reference src/zrows.c and the AVR assembly
 * ports/avr/zfill.S (R8_ASM_ZFILL). */
#ifndef R8ZROWS_H
#define R8ZROWS_H

#include "r8raster.h"

/* r8_zfill's rows and the edges' first-row attribute set-up go through
 * r8k_zrows and r8_attr_first with the AVR kernels (R8_ASM_ZFILL) and
 * on the host (the C references, which the frames there then check);
 * the 6502 and the Z80 (and the AVR without the kernels) keep the
 * general C, smaller. */
#if defined(R8_ASM_ZFILL) || !(defined(__AVR__) || defined(__CC65__) || defined(__SDCC))
#define R8_ZROWS 1
#else
#define R8_ZROWS 0
#endif

/* The kernel's state.  Layout fixed (zfill.S's offsets): pointers and
 * u16 are 2 bytes on the AVR, no padding. */
typedef struct r8_zrows {
    r8_interp *lx, *rx;   /* 0, 2: the edges' columns */
    r8_interp *ld, *rd;   /* 4, 6: the edges' depths (the four point into */
                          /* t->s: &s->c.l.x, &s->c.r.x, &s->ld, &s->rd; */
                          /* the AVR kernel finds all from lx) */
    r8_u16 *z;            /* 8: the depth row of row y */
    r8_u8 *page;          /* 10: its page row (SSD1306 layout) */
    r8_u16 w;             /* 12: columns (<= 32767) */
    r8_u8 m;              /* 14: row y's bit in the page */
    r8_u8 k;              /* 15: row y's dither phase, y & 3 (the AVR */
                          /* kernel takes it from y, writes it at the end) */
    const r8_u8 *pat;     /* 16: the level's dither patterns (flash: */
                          /* &r8_fb_dither_tab[4 level]), row k's pat[k] */
    r8_scan *s;           /* 18: the polygon (lx .. rd point into it) */
    const r8_s16 *lyend;  /* 20: &s->c.l.yend */
    const r8_s16 *ryend;  /* 22: &s->c.r.yend */
    r8_s16 y;             /* 24: the current row */
    r8_s16 lim;           /* 26: the first row not done (<= s->c.ybot) */
    r8_s16 end;           /* 28: (the kernel's) */
    r8_u8 fast;           /* 30: (the kernel's) */
} r8_zrows;

/* The columns [r8_zcols[0], r8_zcols[1]) hold every span r8k_zrows has
 * drawn since its caller last set them (bytes: exact for w <= 255; the
 * caller then clears only those columns of the depth rows, vis_zbuf.c's
 * r8_zclear).  One for all renderers: r8_zclear takes it into the
 * state's st->zx after each band's clear and before the next. */
extern r8_u8 r8_zcols[2];

/* r8_zfill's rows from y up to lim (judd's test decided or off): on
 * each, when y reaches an edge's yend, r8_scan_row_attrs(s, y, 0) moves
 * the edges on (the interpolators in s re-read after); then the span
 * [lx->val, rx->val) clipped to [0, w), depth from ld->val at column
 * lx->val to rd->val at rx->val (r8_zfill's exact stepwise
 * interpolator, steps from the reciprocal table), is drawn where its
 * depth is >= the stored one (the depth stored, the page bit set where
 * pat[k] (flash) has bit 7 - (x & 7), else cleared); then the four
 * interpolators step, z and page, m, k move to the next row and y++.
 * Returns 1 when y reached lim; 2 when it stopped before drawing row y
 * (its edges moved on), whose span (lx->val < rx->val) starts left of
 * column 0 or is 256 columns or more: the caller draws that row; 0
 * when r8_scan_row_attrs said the polygon is over.  y is left in t->y.
 * Each span drawn (xa = lx->val to xb = min(rx->val, w)) widens
 * r8_zcols to hold it: [0] = min([0], xa), [1] = max([1], xb), both as
 * bytes. */
int r8k_zrows(r8_zrows *t);

/* r8_zfill's common case in one call: face a's rows from a->s.c.y (at
 * or below fb->y0) up to lim = min(c.ybot, ylimit, fb->y0 + fb->rows)
 * through r8k_zrows, its r8_zrows built from a, fb and depth (the band's
 * 16-bit depth rows, fb->width a row; the page rows fb->buf; the level's
 * dither patterns, min(a->level, 16)).  Returns r8k_zrows's value; on 1
 * and 2 a->s.c.y is its y (2: that row is the caller's, then a call
 * again from the next, as r8_zfill does). */
struct r8_act;
int r8k_zband(struct r8_act *a, const r8_fb *fb, r8_u16 *depth, r8_s16 ylimit);

/* The attribute interpolators of the left (right = 0) or right edge
 * set up again for row y, as r8_scan_row_attrs does when the edge has
 * moved on (scanattr.c; the AVR kernel's general case). */
void r8_scan_attr_edge(r8_scan *s, int right, r8_s16 y);

/* The attribute k (2: depth, 3: shade) of the edge from vertex a down
 * to vertex b (x, y in 12.4, then the attributes) at row y, when that
 * is the edge's first row and the edge at most 256 subpixels tall:
 * r8_interp_init_sub(it, a[k], s0, b[k] - a[k], n), s0 = y * 16 + 8 -
 * a[1], n = b[1] - a[1] (<= 0: 1); returns 1.  0 (it untouched) when
 * not (y outside 0..2047, s0 outside 0..15, n > 256, or |b[k] - a[k]| >=
 * 4096): the caller's general set-up then. */
int r8_attr_first(r8_interp *it, const r8_s16 *a, const r8_s16 *b, r8_s16 y, r8_u8 k);

#endif
