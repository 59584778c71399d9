/* r8zrows.h - the 16-bit z-buffer's row kernel (r8_zfill's rows on
 * which neither edge moves on to its next vertex), shared by
 * src/vis_zbuf.c, its C89 reference src/zrows.c and the AVR assembly
 * ports/avr/zfill.S (R8_ASM_ZFILL). */
#ifndef R8ZROWS_H
#define R8ZROWS_H

#include "r8raster.h"

/* The kernel's state.  Layout fixed (zfill.S's offsets): pointers and
 * u16 are 2 bytes on the AVR, no padding. */
typedef struct r8_zrows {
    r8_interp *lx, *rx;   /* 0, 2: the edges' columns */
    r8_interp *ld, *rd;   /* 4, 6: the edges' depths */
    r8_u16 *z;            /* 8: the depth row of the current row */
    r8_u8 *page;          /* 10: its page row (SSD1306 layout) */
    r8_u16 w;             /* 12: columns (<= 32767) */
    r8_u8 m;              /* 14: the row's bit in the page */
    r8_u8 k;              /* 15: the row's dither phase, y & 3 */
    r8_u8 pat[4];         /* 16: the level's dither pattern of rows k = 0..3 */
} r8_zrows;

/* Up to `rows` rows from the current one: on each, the span
 * [lx->val, rx->val) clipped to [0, w), depth from ld->val at column
 * lx->val to rd->val at rx->val (r8_zfill's exact stepwise interpolator,
 * steps from the reciprocal table), is drawn where its depth is >= the
 * stored one (the depth stored, the page bit set where pat[k] has bit
 * 7 - (x & 7), else cleared); then the four interpolators step, z and
 * page, m, k move to the next row.  Returns the rows not done: it stops
 * before a row whose span (lx->val < rx->val) starts left of column 0
 * or is 256 columns or more (r8_zfill draws that row). */
r8_u16 r8k_zrows(r8_zrows *t, r8_u16 rows);

#endif
