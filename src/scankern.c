/* scankern.c - the C89 reference of r8k_estart (r8scan.h), scan.c's
 * edge set-up.  A port that links its own (assembly) version defines
 * R8_ASM_ESTART, and this one is left out (AVR: ports/avr/edge.S, which
 * reads the struct offsets asserted here). */
#include <stddef.h>
#include "r8scan.h"
#ifndef R8_ASM_ESTART
static r8_u8 wrap(const r8_scanx *s, r8_u8 i, int dir)
{
    if (dir > 0)
        return (r8_u8)(i + 1 == s->n ? 0 : i + 1);
    return (r8_u8)(i == 0 ? s->n - 1 : i - 1);
}

/* scan.c's edge set-up: edge e (&s->l walks the polygon backwards, &s->r
 * forwards) from position `from` on to the first edge that ends below
 * row y, then its DDA, stepped down to row y. */
void r8k_estart(r8_scanx *s, r8_edge *e, r8_s16 y, r8_u8 from)
{
    int dir = e == &s->l ? -1 : 1;
    r8_u8 to = wrap(s, from, dir);
    r8_u8 guard = s->n;
    const r8_s16 *a, *b;
    r8_s16 yb;
    yb = R8_ROW_OF(s->vp[to][1]);
    while (yb <= y && guard--) {
        from = to;
        to = wrap(s, from, dir);
        yb = R8_ROW_OF(s->vp[to][1]);
    }
    a = s->vp[from];
    b = s->vp[to];
    e->vi = to;
    e->yend = yb;
    if (b[1] > a[1] && r8k_edge(&e->x, a, b) >= y)   /* the common case */
        return;
    r8_edge_rare(e, a, b, y);          /* (R8_EDGE_WIDE < y) */
}
#else
/* AVR: ports/avr/edge.S reads these offsets */
R8_CASSERT(estart_n_at_18, offsetof(r8_scanx, n) == 18);
R8_CASSERT(estart_l_at_25, offsetof(r8_scanx, l) == 25);
R8_CASSERT(estart_r_at_38, offsetof(r8_scanx, r) == 38);
R8_CASSERT(estart_yend_at_10, offsetof(r8_edge, yend) == 10);
R8_CASSERT(estart_vi_at_12, offsetof(r8_edge, vi) == 12);
#endif

