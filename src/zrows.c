/* zrows.c - r8k_zrows (src/r8zrows.h) and r8_interp_init_sub
 * (r8raster.h), the C89 references of the AVR kernels in
 * ports/avr/zfill.S (chosen by R8_ASM_ZFILL).  r8k_zrows and
 * r8_attr_first are compiled where R8_ZROWS (src/r8zrows.h) uses them,
 * or with R8_ZROWS_REF (the AVR kernel test). */
#include <stddef.h>
#include "r8zrows.h"
#include "r8int.h"
#include "r8scan.h"

#if !defined(R8_ASM_ZFILL) && (R8_ZROWS || defined(R8_ZROWS_REF))
r8_u8 r8_zcols[2];    /* (r8zrows.h; the AVR kernel's in zfill.S) */

int r8k_zrows(r8_zrows *t)
{
    r8_interp *lx = t->lx, *rx = t->rx, *ld = t->ld, *rd = t->rd;
    r8_s16 y = t->y;
    for (; y < t->lim; y++) {
        r8_s16 xl, xr;
        if (y >= *t->lyend || y >= *t->ryend) {
            if (!r8_scan_row_attrs(t->s, y, 0)) {
                t->y = y;
                return 0;
            }
        }
        xl = lx->val;
        xr = rx->val;
        if (xl < xr) {
            r8_u16 n = (r8_u16)(xr - xl);
            if (xl < 0 || n > 255u) {
                t->y = y;
                return 2;                /* r8_zfill's */
            }
            if (xl < (r8_s16)t->w) {
                /* the depth step: floor((rd - ld) / n) by the
                 * reciprocal, one correction */
                r8_s16 diff = (r8_s16)(rd->val - ld->val), dv = ld->val, dq;
                r8_u16 un = diff < 0 ? (r8_u16)~diff : (r8_u16)diff, q, rr;
                r8_u32 p = un;
                r8_u8 de = 0, dr, k, pat = R8_RDU8(&t->pat[t->k]), m = t->m, nm = (r8_u8)~m;
                r8_u16 *z = t->z + xl;
                r8_u8 *bp = t->page + xl;
                p *= R8_RDU16(&r8_rcp256[n]);
                q = (r8_u16)(p >> 16);
                rr = (r8_u16)(un - q * n);
                if (rr >= n) {
                    rr = (r8_u16)(rr - n);
                    q++;
                }
                if (diff < 0) {
                    dq = (r8_s16)~q;
                    dr = (r8_u8)(n - 1u - rr);
                } else {
                    dq = (r8_s16)q;
                    dr = (r8_u8)rr;
                }
                for (k = (r8_u8)(xl & 7); k; k--)      /* pat rotated left */
                    pat = (r8_u8)((pat << 1) | (pat >> 7));
                xr = xr > (r8_s16)t->w ? (r8_s16)t->w : xr;
                if ((r8_u8)xl < r8_zcols[0])             /* the columns drawn */
                    r8_zcols[0] = (r8_u8)xl;
                if ((r8_u8)xr > r8_zcols[1])
                    r8_zcols[1] = (r8_u8)xr;
                k = (r8_u8)(xr - xl);
                do {
                    if ((r8_u16)dv >= *z) {
                        *z = (r8_u16)dv;
                        if (pat & 0x80)
                            *bp |= m;
                        else
                            *bp &= nm;
                    }
                    z++;
                    bp++;
                    pat = (r8_u8)((pat << 1) | (pat >> 7));
                    dv = (r8_s16)(dv + dq);
                    if ((r8_u16)de + dr >= n) {
                        de = (r8_u8)(de + dr - n);
                        dv++;
                    } else {
                        de = (r8_u8)(de + dr);
                    }
                } while (--k);
            }
        }
        R8_INTERP_STEP(lx);
        R8_INTERP_STEP(rx);
        R8_INTERP_STEP(ld);
        R8_INTERP_STEP(rd);
        t->z += t->w;
        t->m = (r8_u8)(t->m << 1);
        if (!t->m) {
            t->m = 1;
            t->page += t->w;
        }
        t->k = (r8_u8)((t->k + 1) & 3);
    }
    t->y = y;
    return 1;
}
#endif

#if !defined(R8_ASM_ZFILL) && (R8_ZROWS || defined(R8_ZROWS_REF))
int r8k_zband(r8_act *a, const r8_fb *fb, r8_u16 *depth, r8_s16 ylimit)
{
    r8_scan *s = &a->s;
    r8_scanx *c = &s->c;
    r8_zrows t;
    r8_u16 w = (r8_u16)fb->width, by = (r8_u16)(c->y - fb->y0);
    r8_u8 lv = a->level > 16 ? 16 : a->level;
    int rc;
    t.lim = c->ybot < ylimit ? c->ybot : ylimit;
    if (t.lim > fb->y0 + fb->rows)
        t.lim = (r8_s16)(fb->y0 + fb->rows);
    t.lx = &c->l.x;
    t.rx = &c->r.x;
    t.ld = &s->ld;
    t.rd = &s->rd;
    t.w = w;
    t.pat = &r8_fb_dither_tab[(unsigned)lv << 2];
    t.s = s;
    t.lyend = &c->l.yend;
    t.ryend = &c->r.yend;
    t.y = c->y;
    t.z = depth + by * w;
    t.page = fb->buf + (by >> 3) * w;
    t.m = R8_FB_BIT(by);
    t.k = (r8_u8)(c->y & 3);
    rc = r8k_zrows(&t);
    if (rc)
        c->y = t.y;
    return rc;
}
#endif

#ifdef R8_ASM_ZFILL
/* ports/avr/zfill.S reads these offsets (also scankern.c's) */
R8_CASSERT(zrows_vp_at_0, offsetof(r8_scanx, vp) == 0);
R8_CASSERT(zrows_c_at_0, offsetof(r8_scan, c) == 0);
R8_CASSERT(zrows_attrs_at_51, offsetof(r8_scan, attrs) == 51);
R8_CASSERT(zrows_n_at_18, offsetof(r8_scanx, n) == 18);
R8_CASSERT(zrows_yend_at_10, offsetof(r8_edge, yend) == 10);
R8_CASSERT(zrows_vi_at_12, offsetof(r8_edge, vi) == 12);
R8_CASSERT(zrows_t_y_at_24, offsetof(r8_zrows, y) == 24);
R8_CASSERT(zrows_t_end_at_28, offsetof(r8_zrows, end) == 28);
R8_CASSERT(zrows_t_fast_at_30, offsetof(r8_zrows, fast) == 30);
R8_CASSERT(zrows_l_x_at_25, offsetof(r8_scanx, l) + offsetof(r8_edge, x) == 25);
R8_CASSERT(zrows_r_x_at_38, offsetof(r8_scanx, r) + offsetof(r8_edge, x) == 38);
R8_CASSERT(zrows_ld_at_52, offsetof(r8_scan, ld) == 52);
R8_CASSERT(zrows_rd_at_72, offsetof(r8_scan, rd) == 72);
R8_CASSERT(sattrs_l_vi_at_37, offsetof(r8_scanx, l) + offsetof(r8_edge, vi) == 37);
R8_CASSERT(sattrs_r_vi_at_50, offsetof(r8_scanx, r) + offsetof(r8_edge, vi) == 50);
R8_CASSERT(zband_s_at_2, offsetof(r8_act, s) == 2);
R8_CASSERT(zband_level_at_0, offsetof(r8_act, level) == 0);
R8_CASSERT(zband_y_at_21, offsetof(r8_scanx, y) == 21);
R8_CASSERT(zband_ybot_at_23, offsetof(r8_scanx, ybot) == 23);
R8_CASSERT(zband_lyend_at_35, offsetof(r8_scanx, l) + offsetof(r8_edge, yend) == 35);
R8_CASSERT(zband_ryend_at_48, offsetof(r8_scanx, r) + offsetof(r8_edge, yend) == 48);
R8_CASSERT(zband_fb_buf_at_0, offsetof(r8_fb, buf) == 0);
R8_CASSERT(zband_fb_width_at_2, offsetof(r8_fb, width) == 2);
R8_CASSERT(zband_fb_y0_at_6, offsetof(r8_fb, y0) == 6);
R8_CASSERT(zband_fb_rows_at_8, offsetof(r8_fb, rows) == 8);
#endif

#ifndef R8_ASM_ZFILL
/* floor(num / n) for n = 1..256, num = un or (neg) -un - 1: the
 * remainder (0..n-1) in *rem, the quotient returned.  The quotient of
 * un / n comes from the reciprocal (r8_rcp256: q or q - 1, one
 * correction), not a division. */
static r8_s32 fdiv_small(r8_u16 un, r8_u8 neg, r8_u16 n, r8_u16 *rem)
{
    r8_u16 q = un, rr = 0;
    if (n > 1u) {
        r8_u32 p = un;
        p *= R8_RDU16(&r8_rcp256[n]);
        q = (r8_u16)(p >> 16);
        rr = (r8_u16)(un - q * n);
        if (rr >= n) {
            rr = (r8_u16)(rr - n);
            q++;
        }
    }
    if (neg) {
        *rem = (r8_u16)(n - 1u - rr);
        return -(r8_s32)q - 1;
    }
    *rem = rr;
    return (r8_s32)q;
}

static r8_s16 sat16(r8_s32 v)
{
    if (v > 32767L)
        return 32767;
    if (v < -32768L)
        return -32767 - 1;
    return (r8_s16)v;
}

/* (r8raster.h) both numerators fit a u16: two reciprocal products */
void r8_interp_init_sub(r8_interp *it, r8_s16 base, r8_u16 s0, r8_s16 dv, r8_u16 n)
{
    r8_u16 m = (r8_u16)(dv < 0 ? -dv : dv), un = (r8_u16)(s0 * m), rem;
    r8_u8 neg = (r8_u8)(dv < 0 && un);
    r8_s32 q = fdiv_small((r8_u16)(un - neg), neg, n, &rem);
    it->val = sat16(q + base);
    it->err = rem;
    un = (r8_u16)(m * R8_SUBPX);
    neg = (r8_u8)(dv < 0);
    q = fdiv_small((r8_u16)(un - neg), neg, n, &rem);
    it->q = sat16(q);
    it->r = rem;
    it->den = n;
}
#endif

#if !defined(R8_ASM_ZFILL) && (R8_ZROWS || defined(R8_ZROWS_REF))
/* r8_scan_attrs (r8raster.h) where R8_ZROWS (else src/scanattr.c's):
 * each edge's attributes at row c.y, depth alone from r8_attr_first
 * (its upper vertex: the left edge's vi + 1, the right's vi - 1, round
 * the polygon), else (shade too, or r8_attr_first's 0) through
 * r8_scan_attr_edge; the AVR kernel in ports/avr/zfill.S */
void r8_scan_attrs(r8_scan *s)
{
    r8_scanx *c = &s->c;
    r8_u8 from;
    if (!s->attrs)
        return;
    from = (r8_u8)(c->l.vi + 1 == c->n ? 0 : c->l.vi + 1);
    if (s->attrs != R8_ATTR_D || !r8_attr_first(&s->ld, c->vp[from], c->vp[c->l.vi], c->y, 2))
        r8_scan_attr_edge(s, 0, c->y);
    from = (r8_u8)(c->r.vi == 0 ? c->n - 1 : c->r.vi - 1);
    if (s->attrs != R8_ATTR_D || !r8_attr_first(&s->rd, c->vp[from], c->vp[c->r.vi], c->y, 2))
        r8_scan_attr_edge(s, 1, c->y);
}

int r8_attr_first(r8_interp *it, const r8_s16 *a, const r8_s16 *b, r8_s16 y, r8_u8 k)
{
    r8_s16 ay = a[1], by = b[1];
    /* 16 bits, exact for 0 <= y < 2048: s0 then lies in (-32760, 65528] */
    r8_u16 s0 = (r8_u16)((r8_u16)y * R8_SUBPX + 8u - (r8_u16)ay);
    r8_u16 n = by > ay ? (r8_u16)(by - ay) : 1u;
    r8_s32 dv = (r8_s32)b[k] - a[k];
    if ((r8_u16)y >= 2048u || s0 >= R8_SUBPX || n > 256u ||
        dv <= -(65536L / R8_SUBPX) || dv >= 65536L / R8_SUBPX)
        return 0;
    r8_interp_init_sub(it, a[k], s0, (r8_s16)dv, n);
    return 1;
}
#endif
