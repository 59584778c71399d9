/* vis_zbuf.c - drawing a span with no depth test (cull only, painter's)
 * and through a full z-buffer of 8 or 16 bits per pixel.  Depth is the
 * renderer's 1/z-affine value (larger = nearer), interpolated along the
 * span with the exact stepwise interpolator; a pixel is written when its
 * depth is >= the stored one (so the later of two equal depths wins). */
#include "r8int.h"
#include "r8scan.h"
#include "r8zrows.h"

#if defined(__GNUC__)
#define ZF_NOINLINE __attribute__((noinline))
#else
#define ZF_NOINLINE
#endif

/* Gouraud shade (8.8) to a dither level 0..16, rounded. */
r8_u8 r8_vis_level(r8_s16 s)
{
    r8_s16 l;
    if (s < 0)
        return 0;
    l = (r8_s16)((s + 128) >> 8);
    if (l > 16)
        return 16;
    return (r8_u8)l;
}

/* One row's pixel writer: in SSD1306 page layout the byte and bit are
 * worked out once per span and the dither threshold is a table lookup;
 * other layouts go through r8_fb_dot. */
typedef struct pixw {
    r8_fb *fb;
    r8_u8 *row;          /* page layout: the row's first column byte, else 0 */
    r8_u8 m, nm;
    const r8_u8 *thr;    /* the row's 4 dither thresholds */
    r8_s16 y;
} pixw;

static void pixw_init(pixw *w, r8_fb *fb, r8_s16 y)
{
    w->fb = fb;
    w->y = y;
    w->row = 0;
    if (fb->format == R8_FMT_PAGE1) {
        r8_s16 by = (r8_s16)(y - fb->y0);
        w->row = fb->buf + (unsigned)(by >> 3) * (unsigned)fb->width;
        w->m = R8_FB_BIT(by);
        w->nm = (r8_u8)~w->m;
        w->thr = r8_fb_dither_thresholds(y);
    }
}

static void pixw_put(const pixw *w, r8_s16 x, r8_u8 level)
{
    R8_COUNT_PX_ADD(1);
    if (w->row) {
        if (level > R8_RDU8(&w->thr[x & 3]))
            w->row[x] |= w->m;
        else
            w->row[x] &= w->nm;
    } else {
        r8_fb_dot(w->fb, x, w->y, level, 0);
    }
}

/* Span clipped to the frame: first pixel, end, and the interpolators
 * advanced to the first pixel. */
static int span_setup(const r8_state *st, const r8_fb *fb, const r8_span *sp,
                      r8_s16 *xa, r8_s16 *xb, r8_interp *d, r8_interp *s)
{
    r8_s16 n = (r8_s16)(sp->x1 - sp->x0);
    r8_s16 k0 = 0;
    *xa = sp->x0;
    *xb = sp->x1 > fb->width ? fb->width : sp->x1;
    if (*xa < 0) {
        k0 = (r8_s16)-*xa;
        *xa = 0;
    }
    if (*xa >= *xb)
        return 0;
    if (st->attrs & R8_ATTR_D)
        r8_interp_init_mul(d, sp->dl, k0, (r8_s32)sp->dr - sp->dl, (r8_s32)sp->dr - sp->dl, (r8_u16)n);
    if (st->attrs & R8_ATTR_S)
        r8_interp_init_mul(s, sp->sl, k0, (r8_s32)sp->sr - sp->sl, (r8_s32)sp->sr - sp->sl, (r8_u16)n);
    return 1;
}


/* No depth test, Gouraud shading (cull only and painter's). */
void r8_vis_plain(r8_state *st, r8_fb *fb, r8_u8 level, const r8_span *sp)
{
    r8_s16 xa, xb, x;
    r8_interp d, s;
    pixw w;
    (void)level;   /* flat and Lambert spans go through r8_scanx_fill */
    if (!span_setup(st, fb, sp, &xa, &xb, &d, &s))
        return;
    pixw_init(&w, fb, sp->y);
    for (x = xa; x < xb; x++) {
        pixw_put(&w, x, r8_vis_level(s.val));
        R8_INTERP_STEP(&s);
    }
}

void r8_vis_zbuf(r8_state *st, r8_fb *fb, r8_u8 level, const r8_span *sp, int bits16)
{
    r8_s16 xa, xb, x;
    r8_interp d, s;
    pixw w;
    unsigned row;
    int gouraud = (st->attrs & R8_ATTR_S) != 0;
    if (!span_setup(st, fb, sp, &xa, &xb, &d, &s))
        return;
    pixw_init(&w, fb, sp->y);
    row = (unsigned)(sp->y - fb->y0) * (unsigned)fb->width;
    if (bits16) {             /* the columns written (st->zx, r8int.h) */
        if ((r8_u8)xa < st->zx[0])
            st->zx[0] = (r8_u8)xa;
        if ((r8_u8)xb > st->zx[1])
            st->zx[1] = (r8_u8)xb;
    }
    if (bits16 && w.row && !gouraud) {
        /* the common case, written out: 16-bit depth, one level, pages */
        r8_u16 *z = (r8_u16 *)(void *)st->depth + row;
        r8_u8 *b = w.row, m = w.m, nm = w.nm, lv = level;
        r8_u8 t[4];
        t[0] = R8_RDU8(&w.thr[0]);
        t[1] = R8_RDU8(&w.thr[1]);
        t[2] = R8_RDU8(&w.thr[2]);
        t[3] = R8_RDU8(&w.thr[3]);
        for (x = xa; x < xb; x++) {
            if ((r8_u16)d.val >= z[x]) {
                z[x] = (r8_u16)d.val;
                if (lv > t[x & 3])
                    b[x] |= m;
                else
                    b[x] &= nm;
            }
            R8_INTERP_STEP(&d);
        }
    } else if (bits16) {
        r8_u16 *z = (r8_u16 *)(void *)st->depth + row;
        for (x = xa; x < xb; x++) {
            if ((r8_u16)d.val >= z[x]) {
                z[x] = (r8_u16)d.val;
                pixw_put(&w, x, gouraud ? r8_vis_level(s.val) : level);
            }
            R8_INTERP_STEP(&d);
            if (gouraud)
                R8_INTERP_STEP(&s);
        }
    } else {
        r8_u8 *z = st->depth + row;
        for (x = xa; x < xb; x++) {
            r8_u8 d8 = (r8_u8)(d.val >> 7);
            if (d8 >= z[x]) {
                z[x] = d8;
                pixw_put(&w, x, gouraud ? r8_vis_level(s.val) : level);
            }
            R8_INTERP_STEP(&d);
            if (gouraud)
                R8_INTERP_STEP(&s);
        }
    }
}

/* floor(65536 / n), n = 2..256 ([1] unused: n = 1 is the quotient
 * itself): the per-span division of r8_zfill as a product, and the
 * attribute set-ups' of src/zrows.c and ports/avr/zfill.S
 * (src/r8int.h). */
const r8_u16 r8_rcp256[257] R8_FLASH = {
    0u, 65535u, 32768u, 21845u, 16384u, 13107u, 10922u, 9362u, 8192u, 7281u,
    6553u, 5957u, 5461u, 5041u, 4681u, 4369u, 4096u, 3855u, 3640u, 3449u,
    3276u, 3120u, 2978u, 2849u, 2730u, 2621u, 2520u, 2427u, 2340u, 2259u,
    2184u, 2114u, 2048u, 1985u, 1927u, 1872u, 1820u, 1771u, 1724u, 1680u,
    1638u, 1598u, 1560u, 1524u, 1489u, 1456u, 1424u, 1394u, 1365u, 1337u,
    1310u, 1285u, 1260u, 1236u, 1213u, 1191u, 1170u, 1149u, 1129u, 1110u,
    1092u, 1074u, 1057u, 1040u, 1024u, 1008u, 992u, 978u, 963u, 949u,
    936u, 923u, 910u, 897u, 885u, 873u, 862u, 851u, 840u, 829u,
    819u, 809u, 799u, 789u, 780u, 771u, 762u, 753u, 744u, 736u,
    728u, 720u, 712u, 704u, 697u, 689u, 682u, 675u, 668u, 661u,
    655u, 648u, 642u, 636u, 630u, 624u, 618u, 612u, 606u, 601u,
    595u, 590u, 585u, 579u, 574u, 569u, 564u, 560u, 555u, 550u,
    546u, 541u, 537u, 532u, 528u, 524u, 520u, 516u, 512u, 508u,
    504u, 500u, 496u, 492u, 489u, 485u, 481u, 478u, 474u, 471u,
    468u, 464u, 461u, 458u, 455u, 451u, 448u, 445u, 442u, 439u,
    436u, 434u, 431u, 428u, 425u, 422u, 420u, 417u, 414u, 412u,
    409u, 407u, 404u, 402u, 399u, 397u, 394u, 392u, 390u, 387u,
    385u, 383u, 381u, 378u, 376u, 374u, 372u, 370u, 368u, 366u,
    364u, 362u, 360u, 358u, 356u, 354u, 352u, 350u, 348u, 346u,
    344u, 343u, 341u, 339u, 337u, 336u, 334u, 332u, 330u, 329u,
    327u, 326u, 324u, 322u, 321u, 319u, 318u, 316u, 315u, 313u,
    312u, 310u, 309u, 307u, 306u, 304u, 303u, 302u, 300u, 299u,
    297u, 296u, 295u, 293u, 292u, 291u, 289u, 288u, 287u, 286u,
    284u, 283u, 282u, 281u, 280u, 278u, 277u, 276u, 275u, 274u,
    273u, 271u, 270u, 269u, 268u, 267u, 266u, 265u, 264u, 263u,
    262u, 261u, 260u, 259u, 258u, 257u, 256u
};

/* d from base over n pixels by diff, with no rounding offset: the same
 * q, r, den as r8_interp_init(d, base, 0, diff, n) for |diff| < 32768,
 * the quotient from the reciprocal (one correction) for n <= 256. */
static void span_step(r8_interp *d, r8_s16 base, r8_s16 diff, r8_u16 n)
{
    r8_u16 un, q, rr;
    r8_u32 p;
    r8_u8 neg = (r8_u8)(diff < 0);
    if (n > 256u) {
        r8_interp_init(d, base, 0, diff, n);
        return;
    }
    un = neg ? (r8_u16)(-(diff + 1)) : (r8_u16)diff;    /* -diff - 1 >= 0 */
    if (n == 1u) {
        q = un;
        rr = 0;
    } else {
        p = un;
        p *= R8_RDU16(&r8_rcp256[n]);
        q = (r8_u16)(p >> 16);                           /* q or q - 1 */
        rr = (r8_u16)(un - q * n);
        if (rr >= n) {
            rr = (r8_u16)(rr - n);
            q++;
        }
    }
    if (neg) {
        d->q = (r8_s16)(-(r8_s16)q - 1);                 /* floor */
        d->r = (r8_u16)(n - 1u - rr);
    } else {
        d->q = (r8_s16)q;
        d->r = rr;
    }
    d->val = base;
    d->err = 0;
    d->den = n;
}

/* r8_zfill's rows in C: all of them where R8_ZROWS is 0, else the rows
 * r8k_zrows leaves (kept out of line: the kernel's path then saves few
 * registers) */
static ZF_NOINLINE void zfill_gen(r8_state *st, r8_act *a, r8_s16 ylimit, r8_fb *fb, int bits16)
{
    r8_scan *s = &a->s;
    r8_scanx *c = &s->c;
    r8_edge *l = &c->l, *r = &c->r;
    r8_s16 lim = c->ybot < ylimit ? c->ybot : ylimit, w = fb->width, y = c->y;
    r8_u8 lv = a->level > 16 ? 16 : a->level, judd = st->judd;
    if (lim > fb->y0 + fb->rows)
        lim = (r8_s16)(fb->y0 + fb->rows);
    for (; y < lim; y++) {
        r8_s16 xl, xr;
        if (y >= l->yend || y >= r->yend || (judd && !c->front))
            if (!r8_scan_row_attrs(s, y, judd))
                return;           /* a back face: over */
        xl = l->x.val;
        xr = r->x.val;
        if (xl < xr && y >= fb->y0) {
            /* r8_vis_zbuf's span [xl, xr) from depth ld to rd */
            r8_s16 xa = xl, xb = xr > w ? w : xr;
            r8_interp d;
            if (xa < 0) {
                xa = 0;
                r8_interp_init_mul(&d, s->ld.val, -xl, (r8_s32)s->rd.val - s->ld.val,
                                   (r8_s32)s->rd.val - s->ld.val, (r8_u16)(xr - xl));
            } else {
                span_step(&d, s->ld.val, (r8_s16)(s->rd.val - s->ld.val), (r8_u16)(xr - xl));
            }
            if (xa < xb) {
                /* the loop on locals: the interpolator, the row's page
                 * byte and bit, the dither pattern and its bit for x */
                r8_u16 by = (r8_u16)(y - fb->y0);
                r8_u8 *bp = fb->buf + (by >> 3) * (unsigned)w + xa;
                r8_u8 m = R8_FB_BIT(by), nm = (r8_u8)~m;
                r8_u8 pat = R8_FB_DITHER(lv, y), mb = R8_FB_BIT(7 - (xa & 7));
                r8_s16 dv = d.val, dq = d.q;
                r8_u16 de = d.err, dr = d.r, dn = d.den, k = (r8_u16)(xb - xa);
                if (bits16) {
                    r8_u16 *z = (r8_u16 *)(void *)st->depth + by * (unsigned)w + xa;
                    if ((r8_u8)xa < st->zx[0])           /* the columns written */
                        st->zx[0] = (r8_u8)xa;
                    if ((r8_u8)xb > st->zx[1])
                        st->zx[1] = (r8_u8)xb;
                    do {
                        if ((r8_u16)dv >= *z) {
                            *z = (r8_u16)dv;
                            if (pat & mb)
                                *bp |= m;
                            else
                                *bp &= nm;
                        }
                        z++;
                        bp++;
                        mb = (r8_u8)(mb >> 1);
                        if (!mb)
                            mb = 0x80;
                        dv = (r8_s16)(dv + dq);
                        de = (r8_u16)(de + dr);
                        if (de >= dn) {
                            de = (r8_u16)(de - dn);
                            dv++;
                        }
                    } while (--k);
                } else {
                    r8_u8 *z = st->depth + by * (unsigned)w + xa;
                    do {
                        r8_u8 d8 = (r8_u8)(dv >> 7);
                        if (d8 >= *z) {
                            *z = d8;
                            if (pat & mb)
                                *bp |= m;
                            else
                                *bp &= nm;
                        }
                        z++;
                        bp++;
                        mb = (r8_u8)(mb >> 1);
                        if (!mb)
                            mb = 0x80;
                        dv = (r8_s16)(dv + dq);
                        de = (r8_u16)(de + dr);
                        if (de >= dn) {
                            de = (r8_u16)(de - dn);
                            dv++;
                        }
                    } while (--k);
                }
            }
        }
        R8_INTERP_STEP(&l->x);
        R8_INTERP_STEP(&r->x);
        R8_INTERP_STEP(&s->ld);
        R8_INTERP_STEP(&s->rd);
    }
    c->y = y;
}

#if R8_ZROWS
/* the rows r8k_zband leaves (its 2): each in C, then on with the
 * kernel from the next (out of line: r8_zfill's own path stays short) */
static ZF_NOINLINE void zfill_stops(r8_state *st, r8_act *a, r8_s16 ylimit, r8_fb *fb)
{
    do
        zfill_gen(st, a, (r8_s16)(a->s.c.y + 1), fb, 1);
    while (r8k_zband(a, fb, (r8_u16 *)(void *)st->depth, ylimit) == 2);
}
#endif

void r8_zfill(r8_state *st, r8_act *a, r8_s16 ylimit, r8_fb *fb, int bits16)
{
#if R8_ZROWS
    r8_scanx *c = &a->s.c;
    if (bits16 && c->y >= fb->y0 && (!st->judd || c->front)) {
        /* the rows from y on: r8k_zband (src/r8zrows.h), up to the band's
         * or the face's end, or a row it leaves to zfill_gen (whose
         * edges it has moved on); 0: a back face, over */
        if (r8k_zband(a, fb, (r8_u16 *)(void *)st->depth, ylimit) == 2)
            zfill_stops(st, a, ylimit, fb);
        return;
    }
#endif
    zfill_gen(st, a, ylimit, fb, bits16);
}

/* (r8int.h) the depth rows' columns st->zx cleared (band rows w
 * apart), then none written: st->zx and the kernel's r8_zcols empty;
 * all of them next when this band's rows lie another width apart */
void r8_zclear(r8_state *st, const r8_fb *fb, r8_u16 w, r8_u16 band)
{
    r8_u16 lo = st->zx[0], hi = st->zx[1];
    if (hi > w)
        hi = w;
    if (lo < hi) {
        r8_u8 *p = st->depth + 2u * lo;
        r8_u16 n = (r8_u16)(2u * (hi - lo)), step = (r8_u16)(2u * w);
        for (; band; band--) {
            r8k_fill(p, 0, n);
            p += step;
        }
    }
    st->zx[0] = 255;
    st->zx[1] = 0;
    if (fb->width != (r8_s16)w) {
        st->zx[0] = 0;
        st->zx[1] = 255;
    }
#if R8_ZROWS
    r8_zcols[0] = 255;
    r8_zcols[1] = 0;
#endif
}

/* (r8int.h) the columns the kernel drew this band, into st->zx */
void r8_zkeep(r8_state *st)
{
#if R8_ZROWS
    if (r8_zcols[0] < st->zx[0])
        st->zx[0] = r8_zcols[0];
    if (r8_zcols[1] > st->zx[1])
        st->zx[1] = r8_zcols[1];
#else
    (void)st;
#endif
}

/* The 4x4-block z-buffer, two designs (docs/visibility.md):
 *  naive (the seed's): one 8-bit depth per 4x4 block, compared once per
 *    block and polygon: the first span row of a polygon entering a block
 *    compares its depth there with the block's; if nearer (or equal) the
 *    polygon owns the block (its id is kept beside the depth) and all
 *    its pixels in the block are drawn, else they are dropped until a
 *    later row passes the test.  A polygon that only partly covers a
 *    block still claims it, so a farther polygon loses the rest of the
 *    block: holes at edges and wrong winners at intersections.
 *  mask: the same depth plus a 16-bit coverage mask per block.  Pixels
 *    not yet covered are always drawn (and marked); covered pixels are
 *    drawn only if nearer than the block depth, which keeps the nearest
 *    depth drawn.  No holes; errors remain where surfaces cross inside a
 *    block. */
void r8_vis_block(r8_state *st, r8_fb *fb, r8_u8 level, r8_u8 id, const r8_span *sp, int mask)
{
    r8_s16 xa, xb, x;
    r8_interp d, s;
    pixw w;
    r8_u16 bw = (r8_u16)((fb->width + 3) >> 2);
    r8_u16 brow = (r8_u16)(((sp->y - fb->y0) >> 2) * bw);
    r8_u16 nblocks = (r8_u16)(bw * (r8_u16)(fb->rows >> 2));
    r8_u8 *bz = st->depth;
    r8_u8 *owner = st->depth + nblocks;   /* naive: polygon id per block */
    r8_u16 *bm = (r8_u16 *)(void *)(st->depth + ((nblocks + 1u) & ~1u));
    r8_u16 rowbits = (r8_u16)((sp->y & 3) << 2);
    int gouraud = (st->attrs & R8_ATTR_S) != 0;
    if (!span_setup(st, fb, sp, &xa, &xb, &d, &s))
        return;
    pixw_init(&w, fb, sp->y);
    x = xa;
    while (x < xb) {
        r8_s16 end = (r8_s16)((x | 3) + 1);
        r8_u16 b = (r8_u16)(brow + (x >> 2));
        r8_u8 d8 = (r8_u8)(d.val >> 7);
        if (end > xb)
            end = xb;
        if (!mask) {
            int draw = owner[b] == id || d8 >= bz[b];
            if (draw && owner[b] != id) {
                bz[b] = d8;
                owner[b] = id;
            }
            for (; x < end; x++) {
                if (draw)
                    pixw_put(&w, x, gouraud ? r8_vis_level(s.val) : level);
                R8_INTERP_STEP(&d);
                if (gouraud)
                    R8_INTERP_STEP(&s);
            }
        } else {
            r8_u16 m = bm[b];
            int drawn = 0;
            for (; x < end; x++) {
                r8_u16 bit = (r8_u16)(1u << (rowbits | (x & 3)));
                if (!(m & bit) || d8 >= bz[b]) {
                    bm[b] = (r8_u16)(bm[b] | bit);
                    pixw_put(&w, x, gouraud ? r8_vis_level(s.val) : level);
                    drawn = 1;
                }
                R8_INTERP_STEP(&d);
                if (gouraud)
                    R8_INTERP_STEP(&s);
            }
            if (drawn && (m == 0 || d8 > bz[b]))
                bz[b] = d8;
        }
    }
}
