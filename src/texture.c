/* texture.c - texture mapping (R8_SHADE_TEXTURE), the seed's "Texture
 * Mapping Algorithm": u and v are carried by the stepwise interpolator
 * (interp.c) down the edges and across the spans, exactly as Gouraud
 * shade and depth are.  A textured face is scanned over its own corner
 * records (x, y, u, v), so the scan's depth and shade interpolators
 * (scanattr.c) carry u and v, and the ordinary span loop
 * (r8_scan_next) hands each span here with u and v at both ends.
 *
 * Per pixel: the texel at (u, v) (nearest, or bilinear between four for
 * IDX8 textures), times the face's Lambert level, through the 4x4
 * ordered dither on 1 bpp (an index 0..16 on IDX8 output).
 *
 * Perspective correction (cfg.persp = N): u q, v q and q (q = 1/z
 * relative to the face's nearest corner) are affine on the screen; at
 * every N-th pixel of a span (and its last) u and v are worked out at
 * the pixel centre from the three planes (two divisions), and stepped
 * affinely between (the subdivision of Quake and the demo scene).
 *
 * Coordinates are 8.8 texels; the texture repeats (a power of two a
 * side, masked), so no fetch leaves the texture whatever u and v are. */
#include "r8int.h"
#include "r8scan.h"

#if R8_W_TEXTURE

/* Plane of corner values val[k * 4] over the corners' x, y: value << 12
 * at corner 0 and its slopes per subpixel << 12 (k0, k1, k2: the corner
 * triple with the largest area). */
static void plane(r8_tact *t, const r8_s16 *val, r8_u8 k1, r8_u8 k2, r8_s32 cross,
                  r8_s32 *p0, r8_s32 *pa, r8_s32 *pb)
{
    const r8_s16 *c = t->cv;
    r8_s32 x1 = (r8_s32)c[4u * k1] - c[0], y1 = (r8_s32)c[4u * k1 + 1u] - c[1];
    r8_s32 x2 = (r8_s32)c[4u * k2] - c[0], y2 = (r8_s32)c[4u * k2 + 1u] - c[1];
    r8_s32 d1 = (r8_s32)val[4u * k1] - val[0], d2 = (r8_s32)val[4u * k2] - val[0];
    *p0 = (r8_s32)val[0] * 4096L;
    *pa = r8_muldiv(d1, y2 * 4096L, cross) - r8_muldiv(d2, y1 * 4096L, cross);
    *pb = r8_muldiv(d2, x1 * 4096L, cross) - r8_muldiv(d1, x2 * 4096L, cross);
}

void r8_tex_face(r8_state *st, r8_tact *t, r8_u16 g, r8_u8 oi, r8_u8 n)
{
    const r8_scene *sc = st->scene;
    const r8_texture *tx;
    const r8_mesh *me;
    const r8_u8 *uv = 0;
    const r8_s16 *cuv = 0;
    r8_s16 dep[R8_SCAN_MAXV];
    r8_u8 j;
    if (oi == 255) {
        cuv = st->cuv + (unsigned)(g - st->nfaces) * R8_CUV_STRIDE;
        me = sc->objects[(r8_u8)cuv[R8_CUV_STRIDE - 1u]].mesh;
    } else {
        me = sc->objects[oi].mesh;
        uv = me->uv + 8u * (unsigned)(g - st->obj[oi].fbase);
    }
    tx = me->tex;
    t->tex = tx;
    for (j = 0; j < n; j++) {
        const r8_s16 *v = t->s.c.vp[j];
        r8_s16 *c = t->cv + 4u * j;
        c[0] = v[0];
        c[1] = v[1];
        c[2] = c[3] = 0;
        dep[j] = v[2];
        t->s.c.vp[j] = c;
        if (tx) {
            if (cuv) {
                c[2] = cuv[2u * j];
                c[3] = cuv[2u * j + 1u];
            } else {
                c[2] = (r8_s16)((r8_u16)R8_RDU8(uv + 2u * j) << (tx->wlog + 1));
                c[3] = (r8_s16)((r8_u16)R8_RDU8(uv + 2u * j + 1u) << (tx->hlog + 1));
            }
        }
    }
    if (st->persp && tx && n >= 3) {
        /* q per corner from its depth (affine in 1/z: transform.c),
         * relative to the nearest corner, Q14; corner u, v become u q,
         * v q for the planes (the corner records themselves keep u, v) */
        r8_s32 w[R8_SCAN_MAXV], wmax = 1, cross = 0, cr;
        r8_s16 val[4 * R8_SCAN_MAXV];
        r8_u8 k, b1 = 1, b2 = 2;
        for (j = 0; j < n; j++) {
            r8_s16 d = dep[j];
            w[j] = (r8_s32)st->wf + r8_muldiv(d, (1L << 20) - (r8_s32)st->wf, 32767L);
            if (w[j] > wmax)
                wmax = w[j];
        }
        for (j = 0; j < n; j++) {
            r8_s32 q = r8_muldiv(w[j], 16384L, wmax);
            r8_s16 *c = t->cv + 4u * j;
            if (q < 1)
                q = 1;
            val[4u * j] = (r8_s16)(r8_asr32(q * c[2], 14));
            val[4u * j + 1u] = (r8_s16)(r8_asr32(q * c[3], 14));
            val[4u * j + 2u] = (r8_s16)q;
        }
        /* the corner triple (0, k, k + 1) with the largest area */
        for (k = 1; k + 1 < n; k++) {
            const r8_s16 *c = t->cv;
            r8_s32 b;
            /* (no (long)a * (long)b of 16-bit values: SDCC 4.2) */
            cr = (r8_s32)c[4u * k] - c[0];
            cr *= (r8_s32)c[4u * k + 5u] - c[1];
            b = (r8_s32)c[4u * k + 4u] - c[0];
            b *= (r8_s32)c[4u * k + 1u] - c[1];
            cr -= b;
            if ((cr < 0 ? -cr : cr) > (cross < 0 ? -cross : cross)) {
                cross = cr;
                b1 = k;
                b2 = (r8_u8)(k + 1);
            }
        }
        t->px = t->cv[0];
        t->py = t->cv[1];
        if (cross == 0) {
            t->pa[0] = t->pa[1] = t->pa[2] = t->pb[0] = t->pb[1] = t->pb[2] = 0;
            t->p0[0] = (r8_s32)t->cv[2] << 12;   /* no area: affine values */
            t->p0[1] = (r8_s32)t->cv[3] << 12;
            t->p0[2] = 16384L << 12;
        } else {
            for (k = 0; k < 3; k++)
                plane(t, val + k, b1, b2, cross, &t->p0[k], &t->pa[k], &t->pb[k]);
        }
    }
    t->s.attrs = R8_ATTR_D | R8_ATTR_S;    /* slots 2, 3: u and v */
    r8_scan_attrs(&t->s);
}

/* The texel at 8.8 coordinates (u, v), 0..255. */
static r8_u8 texel(const r8_texture *tx, const r8_u8 *data, r8_u16 u, r8_u16 v)
{
    r8_u8 wl = tx->wlog;
    r8_u16 tu = (r8_u16)((u >> 8) & ((1u << wl) - 1u));
    r8_u16 tv = (r8_u16)((v >> 8) & ((1u << tx->hlog) - 1u));
    if (tx->format == R8_TEX_IDX8)
        return R8_RDU8(data + (tv << wl) + tu);
    return (r8_u8)(R8_RDU8(data + (tv << (wl - 3)) + (tu >> 3)) & (0x80u >> (tu & 7u)) ? 255 : 0);
}

/* Bilinear (IDX8): the four texels about (u, v) - 1/2 texel, weighted
 * by the fraction (7 bits). */
static r8_u8 texel_bilinear(const r8_texture *tx, const r8_u8 *data, r8_u16 u, r8_u16 v)
{
    r8_u8 wl = tx->wlog;
    r8_u16 wm = (r8_u16)((1u << wl) - 1u), hm = (r8_u16)((1u << tx->hlog) - 1u);
    r8_u16 u0, v0, u1, r0, r1, fu, fv, a, b;
    u = (r8_u16)(u - 128u);
    v = (r8_u16)(v - 128u);
    fu = (r8_u16)((u & 255u) >> 1);
    fv = (r8_u16)((v & 255u) >> 1);
    u0 = (r8_u16)((u >> 8) & wm);
    u1 = (r8_u16)((u0 + 1u) & wm);
    v0 = (r8_u16)((v >> 8) & hm);
    r0 = (r8_u16)(v0 << wl);
    r1 = (r8_u16)(((v0 + 1u) & hm) << wl);
    a = (r8_u16)((R8_RDU8(data + r0 + u0) * (128u - fu) + R8_RDU8(data + r0 + u1) * fu) >> 7);
    b = (r8_u16)((R8_RDU8(data + r1 + u0) * (128u - fu) + R8_RDU8(data + r1 + u1) * fu) >> 7);
    return (r8_u8)((a * (128u - fv) + b * fv) >> 7);
}

/* u, v at the centre of pixel (x, y) from the planes */
static void persp_at(const r8_tact *t, r8_s16 x, r8_s16 y, r8_s16 *u, r8_s16 *v)
{
    r8_s32 sx = (r8_s32)x * 16 + 8 - t->px, sy = (r8_s32)y * 16 + 8 - t->py, q;
    r8_s32 pu = t->p0[0] + t->pa[0] * sx + t->pb[0] * sy;
    r8_s32 pv = t->p0[1] + t->pa[1] * sx + t->pb[1] * sy;
    q = r8_asr32(t->p0[2] + t->pa[2] * sx + t->pb[2] * sy, 12);
    if (q < 1)
        q = 1;
    /* u = (u q) / q with u q << 12: 14 bits of q, 8 of u's fraction */
    *u = r8_sat16(r8_floordiv(r8_asr32(pu, 12) * 16384L, q));
    *v = r8_sat16(r8_floordiv(r8_asr32(pv, 12) * 16384L, q));
}

static void tex_span(const r8_state *st, const r8_tact *t, r8_fb *fb, const r8_span *sp,
                     r8_u8 level)
{
    const r8_texture *tx = t->tex;
    const r8_u8 *data = tx ? tx->data : 0;
    r8_s16 n = (r8_s16)(sp->x1 - sp->x0), xa = sp->x0, xb, x, seg = 0;
    r8_s16 ub = 0, vb = 0;
    r8_u8 have = 0;     /* ub, vb: the last segment's end, this one's start */
    r8_s16 k0 = 0;
    r8_u8 *row = 0, m = 0, bil, lv = level;
    const r8_u8 *thr = 0;
    r8_interp u, v;
    xb = sp->x1 > fb->width ? fb->width : sp->x1;
    if (xa < 0) {
        k0 = (r8_s16)-xa;
        xa = 0;
    }
    if (xa >= xb)
        return;
    if (fb->format == R8_FMT_PAGE1) {
        r8_s16 by = (r8_s16)(sp->y - fb->y0);
        row = fb->buf + (unsigned)(by >> 3) * (unsigned)fb->width;
        m = R8_FB_BIT(by);
        thr = r8_fb_dither_thresholds(sp->y);
    }
    bil = (r8_u8)(st->texfilter == R8_TEXF_BILINEAR && tx && tx->format == R8_TEX_IDX8);
    if (!st->persp || !tx) {
        r8_interp_init_mul(&u, sp->dl, k0, (r8_s32)sp->dr - sp->dl, (r8_s32)sp->dr - sp->dl, (r8_u16)n);
        r8_interp_init_mul(&v, sp->sl, k0, (r8_s32)sp->sr - sp->sl, (r8_s32)sp->sr - sp->sl, (r8_u16)n);
        seg = 32767;
    }
    for (x = xa; x < xb; x++) {
        if (seg == 0) {
            /* perspective: the next subdivision point (or the span's last
             * pixel), u and v exact there, affine up to it */
            r8_s16 ua = ub, va = vb, stepn = st->persp;
            if (xb - x - 1 < stepn)
                stepn = (r8_s16)(xb - x - 1);
            if (!have)
                persp_at(t, x, sp->y, &ua, &va);
            have = 1;
            if (stepn > 0) {
                persp_at(t, (r8_s16)(x + stepn), sp->y, &ub, &vb);
                r8_interp_reset(&u, ua, ub, (r8_u16)stepn);
                r8_interp_reset(&v, va, vb, (r8_u16)stepn);
            } else {
                ub = ua;
                vb = va;
                r8_interp_reset(&u, ua, ua, 1);
                r8_interp_reset(&v, va, va, 1);
            }
            seg = stepn > 0 ? stepn : 1;
        }
        if (tx) {
            r8_u16 tl = bil ? texel_bilinear(tx, data, (r8_u16)u.val, (r8_u16)v.val)
                            : texel(tx, data, (r8_u16)u.val, (r8_u16)v.val);
            lv = (r8_u8)(((tl + (tl >> 7)) * level + 128u) >> 8);
        }
        if (row) {
            if (lv > R8_RDU8(&thr[x & 3]))
                row[x] |= m;
            else
                row[x] &= (r8_u8)~m;
        } else {
            r8_fb_dot(fb, x, sp->y, lv, 0);
        }
        R8_INTERP_STEP(&u);
        R8_INTERP_STEP(&v);
        seg--;
    }
}

void r8_tex_draw(r8_state *st, r8_tact *t, r8_s16 ylimit, r8_fb *fb)
{
    r8_span sp;
    r8_u8 level = t->level > 16 ? 16 : t->level;
    while (r8_scan_next(&t->s, ylimit, st->judd, &sp))
        tex_span(st, t, fb, &sp, level);
}

#else
typedef int r8_texture_left_out;   /* R8_NO_TEXTURE: an empty file is not C */
#endif
