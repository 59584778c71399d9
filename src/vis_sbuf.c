/* vis_sbuf.c - the seed's S-buffer ("span buffer"): each row of the band
 * keeps a left-to-right list of non-overlapping spans.  A new span is
 * depth-compared with the spans it overlaps: where it is nearer it cuts
 * them (splitting a span in two when it lands in the middle), where it is
 * farther it is clipped away; where the two depths cross inside the
 * overlap the crossing pixel is found by one division.  Nothing reaches
 * the framebuffer until the band is finished, then every pixel is written
 * once: no overdraw and no per-pixel depth memory.
 * Depth along a span is linear in x (8 fraction bits), from the span's
 * end values; ties go to the newer span, as in the z-buffer.
 * If the node pool runs out, the rest of the span is dropped and counted
 * in st->dropped (a visible error, never a write outside the pool). */
#include "r8int.h"

#define SB_END 0xFFFFu

static r8_s32 depth_at(const r8_snode *n, r8_s16 x)
{
    return n->d + n->dd * (x - n->x0);
}

/* Move a node's left end to x, keeping its depth and shade lines. */
static void cut_left(r8_snode *n, r8_s16 x)
{
    n->d += n->dd * (x - n->x0);
    n->s = (r8_s16)(n->s + r8_mul16(n->ds, (r8_s16)(x - n->x0)));
    n->x0 = x;
}

static r8_u16 new_node(r8_state *st)
{
    if (st->sused >= st->nsnode)
        return SB_END;
    return st->sused++;
}

/* Put a copy of span t, restricted to [u, v), after node `prev` (or at
 * the row head).  Returns the new node or SB_END. */
static r8_u16 put_piece(r8_state *st, r8_u16 *head, r8_u16 prev, const r8_snode *t,
                       r8_s16 u, r8_s16 v)
{
    r8_u16 k = new_node(st);
    r8_snode *n;
    if (k == SB_END) {
        st->dropped++;
        return SB_END;
    }
    n = &st->snode[k];
    *n = *t;
    cut_left(n, u);
    n->x1 = v;
    if (prev == SB_END) {
        n->next = *head;
        *head = k;
    } else {
        n->next = st->snode[prev].next;
        st->snode[prev].next = k;
    }
    return k;
}

void r8_vis_sbuf_insert(r8_state *st, r8_fb *fb, r8_u8 level, const r8_span *sp)
{
    r8_snode t;
    r8_u16 *head = &st->shead[sp->y - fb->y0];
    r8_u16 prev = SB_END, cur = *head;
    r8_s16 n = (r8_s16)(sp->x1 - sp->x0);
    r8_s16 c, b;
    /* the new span as a node (not yet in the list) */
    t.x0 = sp->x0;
    t.x1 = sp->x1;
    t.d = r8_mul16(sp->dl, 256);
    t.dd = r8_floordiv(((r8_s32)sp->dr - sp->dl) * 256, n);
    t.s = sp->sl;
    t.ds = (r8_s16)r8_divround((r8_s32)sp->sr - sp->sl, n);
    t.shade = level;
    t.next = SB_END;
    c = sp->x0 < 0 ? 0 : sp->x0;
    b = sp->x1 > fb->width ? fb->width : sp->x1;
    while (c < b) {
        r8_snode *e;
        r8_s16 lo, hi, xc;
        r8_s32 fl, fh;
        if (cur == SB_END || st->snode[cur].x0 >= b) {
            put_piece(st, head, prev, &t, c, b);  /* free to the end */
            return;
        }
        e = &st->snode[cur];
        if (e->x1 <= c) {
            prev = cur;
            cur = e->next;
            continue;
        }
        if (e->x0 > c) {                  /* free gap before e */
            r8_u16 k = put_piece(st, head, prev, &t, c, e->x0);
            if (k == SB_END)
                return;
            prev = k;
            c = e->x0;
            continue;
        }
        /* overlap [lo, hi) with e; find where t is nearer (f >= 0) */
        lo = c;
        hi = e->x1 < b ? e->x1 : b;
        fl = depth_at(&t, lo) - depth_at(e, lo);
        fh = depth_at(&t, (r8_s16)(hi - 1)) - depth_at(e, (r8_s16)(hi - 1));
        if ((fl >= 0) == (fh >= 0)) {
            xc = hi;                      /* one winner for the whole overlap */
        } else {
            r8_s32 slope = t.dd - e->dd;  /* f(x) = fl + slope * (x - lo) */
            if (fl < 0)                   /* rising: first x with f >= 0 */
                xc = (r8_s16)(lo + (-fl + slope - 1) / slope);
            else                          /* falling: first x with f < 0 */
                xc = (r8_s16)(lo + fl / -slope + 1);
            if (xc <= lo)
                xc = (r8_s16)(lo + 1);
            if (xc > hi)
                xc = hi;
        }
        if (fl < 0) {
            /* e keeps [lo, xc); t may take [xc, hi) */
            c = xc;
            if (xc == hi) {
                prev = cur;
                cur = e->next;
            }
            continue;
        }
        /* t takes [lo, xc) from e */
        if (lo == e->x0 && xc == e->x1) {           /* replace e entirely */
            r8_u16 nx = e->next;
            *e = t;
            cut_left(e, lo);
            e->x1 = xc;
            e->next = nx;
            prev = cur;
            cur = nx;
        } else if (lo == e->x0) {                   /* t before the rest of e */
            r8_u16 k = put_piece(st, head, prev, &t, lo, xc);
            if (k == SB_END)
                return;
            cut_left(&st->snode[cur], xc);
            prev = k;
        } else {                                    /* e keeps [e.x0, lo) */
            r8_s16 eend = e->x1;
            r8_u16 k, r;
            e->x1 = lo;
            k = put_piece(st, head, cur, &t, lo, xc);
            if (k == SB_END) {
                st->snode[cur].x1 = eend;
                return;
            }
            if (xc < eend) {                        /* and the right part of e */
                r8_snode right;
                right = st->snode[cur];   /* assignment: cc65/sdcc reject struct initialisers */
                right.x1 = eend;
                r = put_piece(st, head, k, &right, xc, eend);
                if (r == SB_END) {
                    st->snode[k].x1 = eend;         /* keep the row covered */
                    return;
                }
                prev = k;
                cur = r;
            } else {
                prev = k;
                cur = st->snode[k].next;
            }
        }
        c = xc;
    }
}


void r8_vis_sbuf_flush(r8_state *st, r8_fb *fb)
{
    r8_s16 r;
    for (r = 0; r < fb->rows; r++) {
        r8_u16 k = st->shead[r];
        r8_s16 y = (r8_s16)(fb->y0 + r);
        while (k != SB_END) {
            const r8_snode *n = &st->snode[k];
            if (st->attrs & R8_ATTR_S) {
                r8_s16 x;
                r8_s32 s = n->s;
                for (x = n->x0; x < n->x1; x++) {
                    r8_fb_dot(fb, x, y, r8_vis_level((r8_s16)s), 0);
                    s += n->ds;
                }
            } else {
                r8_fb_span_dither(fb, y, n->x0, n->x1, n->shade, 0);
            }
            k = n->next;
        }
        st->shead[r] = SB_END;
    }
    st->sused = 0;
}
