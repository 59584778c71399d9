/* scanband.c - the C89 references of r8k_scanfill and r8k_scanband
 * (r8scan.h): the trapezoid loop of a page-1 band, what scan.c's
 * r8_scanx_fill calls on AVR.  A port that links its own (assembly)
 * versions defines R8_ASM_SCANFILL, and these are left out (AVR:
 * ports/avr/trap.S, which reads the struct offsets asserted here).
 * Other targets keep the loop in scan.c and never link this file; the
 * Z80's firmware calls its kernel (ports/z80/scanband_z80.s) from
 * render.c's draw_face as the AVR's does (R8_BANDK). */
#include <stddef.h>
#include "r8scan.h"
#include "r8flash.h"
#if defined(R8_ASM_SCANFILL) && defined(__SDCC)
/* the Z80's kernel (ports/z80/scanband_z80.s): the C89 reference stays,
 * under other names, for tests/c/test_scanband.c (a firmware drops it) */
#define r8k_scanfill r8k_scanfill_c
#define r8k_scanband r8k_scanband_c
#define R8_SCANBAND_REF 1
void r8k_scanfill_c(r8_scanx *s, r8_trapfill *t, r8_s16 lim);
void r8k_scanband_c(r8_scanx *s, const r8_fb *fb, r8_s16 lim, r8_u8 level);
#endif
#if !defined(R8_ASM_SCANFILL) || defined(R8_SCANBAND_REF)
/* scan.c's trapezoid loop (r8_scanx_fill, the edges decided): from row
 * s->y to lim, restart an edge that ended, fill the rows to the first
 * end of either edge (or lim) with r8k_trap, and on; s->y = lim. */
void r8k_scanfill(r8_scanx *s, r8_trapfill *t, r8_s16 lim)
{
    r8_edge *l = &s->l, *r = &s->r;
    r8_s16 y = s->y;
    while (y < lim) {
        r8_s16 stop = lim;
        if (y >= l->yend)
            r8k_estart(s, l, y, l->vi);
        if (y >= r->yend)
            r8k_estart(s, r, y, r->vi);
        if (l->yend < stop)
            stop = l->yend;
        if (r->yend < stop)
            stop = r->yend;
        r8k_trap(t, &l->x, &r->x, (r8_u16)(stop - y));
        y = stop;
    }
    s->y = y;
}

/* r8_scanx_fill's page-1 set-up (s->y in [fb->y0, lim)): the band's
 * page, bit and dither rows for row s->y, then r8k_scanfill. */
void r8k_scanband(r8_scanx *s, const r8_fb *fb, r8_s16 lim, r8_u8 level)
{
    r8_trapfill t;
    r8_s16 by = (r8_s16)(s->y - fb->y0);
    const r8_u8 *dp;
    t.page = fb->buf + (unsigned)(by >> 3) * (unsigned)fb->width;
    t.m = R8_FB_BIT(by);
    t.k = (r8_u8)(s->y & 3);         /* pat[k] is the pattern of rows k mod 4 */
    t.w = fb->width;
    if (level > 16)
        level = 16;
    dp = r8_fb_dither_tab + ((unsigned)level << 2);
    t.pat[0] = R8_RDU8(dp);
    t.pat[1] = R8_RDU8(dp + 1);
    t.pat[2] = R8_RDU8(dp + 2);
    t.pat[3] = R8_RDU8(dp + 3);
    r8k_scanfill(s, &t, lim);
}
#endif
#ifdef R8_ASM_SCANFILL
/* AVR: ports/avr/trap.S reads these offsets (the Z80's
 * ports/z80/scanband_z80.s too) */
R8_CASSERT(scanband_fb_width_at_2, offsetof(r8_fb, width) == 2);
R8_CASSERT(scanband_fb_y0_at_6, offsetof(r8_fb, y0) == 6);
R8_CASSERT(scanband_t_w_at_8, offsetof(r8_trapfill, w) == 8);
R8_CASSERT(scanfill_y_at_21, offsetof(r8_scanx, y) == 21);
R8_CASSERT(scanfill_l_at_25, offsetof(r8_scanx, l) == 25);
R8_CASSERT(scanfill_r_at_38, offsetof(r8_scanx, r) == 38);
R8_CASSERT(scanfill_yend_at_10, offsetof(r8_edge, yend) == 10);
R8_CASSERT(scanfill_vi_at_12, offsetof(r8_edge, vi) == 12);
#endif
