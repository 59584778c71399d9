/* r8scan.h - what scan.c shares with scanattr.c. */
#ifndef R8SCAN_H
#define R8SCAN_H

#include "r8raster.h"
#include "r8kern.h"
#include "r8fb.h"

/* Start row y of a scan: move either edge on to its next vertex where it
 * ended, then Judd's test.  0: a back face (the scan is over). */
int r8_scan_row(r8_scanx *s, r8_s16 y, int judd);
/* The same for a scan with attributes: an edge that moves on to its next
 * vertex gets its depth and shade interpolators set up again. */
int r8_scan_row_attrs(r8_scan *s, r8_s16 y, int judd);

/* The rare ends of an edge's set-up (scan.c): an empty edge, one
 * r8k_edge does not take, one starting above row y. */
void r8_edge_rare(r8_edge *e, const r8_s16 *a, const r8_s16 *b, r8_s16 y);

/* scan.c's edge set-up (C reference: scankern.c; R8_ASM_ESTART: the
 * port's, AVR ports/avr/edge.S): edge e
 * (&s->l: the left chain, backwards; &s->r: the right one, forwards) set
 * up from polygon position `from` for row y, with y < s->ybot. */
void r8k_estart(r8_scanx *s, r8_edge *e, r8_s16 y, r8_u8 from);

/* r8_scanx_fill's trapezoids once Judd's test has decided (C reference:
 * scanband.c; R8_ASM_SCANFILL: the port's, AVR ports/avr/trap.S): rows
 * s->y to lim (s->y < lim) of the band under t, edges restarted as they
 * end; s->y = lim. */
void r8k_scanfill(r8_scanx *s, r8_trapfill *t, r8_s16 lim);

/* r8_scanx_fill on a page-1 band, s->y in [fb->y0, lim), Judd's test
 * decided: t for row s->y (page, bit, phase, the level's dither rows),
 * then r8k_scanfill (C reference: scanband.c; R8_ASM_SCANFILL: AVR
 * ports/avr/trap.S, t static). */
void r8k_scanband(r8_scanx *s, const r8_fb *fb, r8_s16 lim, r8_u8 level);

#endif
