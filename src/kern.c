/* kern.c - the C89 references of the kernels in r8kern.h.  A port that
 * links its own (assembly) version defines R8_ASM_<NAME>, and this one
 * is left out. */
#include "r8kern.h"
#include "r8fb.h"
#include "r8flash.h"
#include <string.h>

#ifndef R8_ASM_FILL
void r8k_fill(r8_u8 *p, r8_u8 v, unsigned n)
{
    memset(p, v, n);
}
#endif

#ifndef R8_ASM_XFORM
void r8k_xform(const r8_mat3 *m, const r8_vec3l *t, const r8_s16 *v, r8_vec3l *out)
{
    r8_s16 x = R8_RDS16(v), y = R8_RDS16(v + 1), z = R8_RDS16(v + 2);
    const r8_s16 *a = m->m;
    out->x = R8_ASR32C(R8_MUL16(a[0], x) + R8_MUL16(a[1], y) + R8_MUL16(a[2], z) + 512, 10) + t->x;
    out->y = R8_ASR32C(R8_MUL16(a[3], x) + R8_MUL16(a[4], y) + R8_MUL16(a[5], z) + 512, 10) + t->y;
    out->z = R8_ASR32C(R8_MUL16(a[6], x) + R8_MUL16(a[7], y) + R8_MUL16(a[8], z) + 512, 10) + t->z;
}
#endif

#ifndef R8_ASM_PROJECT
int r8k_project(const r8_proj *p, const r8_vec3l *c, r8_s16 *out, r8_u16 *m, r8_s8 *e)
{
    *m = r8_recip(c->z, e);
    return r8_project_recip(p, c, *m, *e, &out[0], &out[1]);
}
#endif

#ifndef R8_ASM_EDGE
/* n / d and n % d for d > 0, by shift and subtract from the quotient's
 * top bit: a few steps for the small quotients of edge slopes (a library
 * 16-bit division always takes 16). */
static r8_u16 udivmod(r8_u16 n, r8_u16 d, r8_u16 *rem)
{
    r8_u16 q = 0, bit = 1;
    if (n < d) {
        *rem = n;
        return 0;
    }
    while (d <= (n >> 1)) {
        d <<= 1;
        bit <<= 1;
    }
    for (;;) {
        if (n >= d) {
            n = (r8_u16)(n - d);
            q |= bit;
        }
        if (bit == 1)
            break;
        d >>= 1;
        bit >>= 1;
    }
    *rem = n;
    return q;
}

r8_s16 r8k_edge(r8_interp *it, const r8_s16 *a, const r8_s16 *b)
{
    r8_s16 ax = a[0], ay = a[1], bx = b[0];
    r8_u16 dy = (r8_u16)((r8_u16)b[1] - (r8_u16)ay), udx, rd, u, d16;
    r8_s16 y0, q, p, dx;
    r8_u8 s0, pl, neg;
    if (dy >= 1424u || ax < -16384 || ax > 16383 || bx < -16384 || bx > 16383)
        return R8_EDGE_WIDE;
    y0 = R8_ROW_OF(ay);
    s0 = (r8_u8)((r8_u16)((r8_u16)y0 * 16u + 8u - (r8_u16)ay));   /* 0..15 */
    dx = (r8_s16)(bx - ax);
    neg = (r8_u8)(dx < 0);
    udx = neg ? (r8_u16)(-(dx + 1)) : (r8_u16)dx;     /* -dx - 1 >= 0 */
    q = (r8_s16)udivmod(udx, dy, &rd);
    if (neg) {
        q = (r8_s16)(-q - 1);                          /* floor */
        rd = (r8_u16)(dy - 1u - rd);
    }
    if (q >= 2048 || q <= -2048)
        return R8_EDGE_WIDE;
    it->q = q;
    it->r = rd;
    it->den = dy;
    /* ax - 8 = 16 axh + axl, P = axl + s0 q = 16 Ph + Pl: the first column
     * is axh + Ph + ceil((dy Pl + s0 rd) / (16 dy)) */
    p = (r8_s16)(((r8_u16)(ax - 8) & 15u) + (r8_s16)s0 * q);
    pl = (r8_u8)((r8_u16)p & 15u);
    it->val = (r8_s16)(R8_FLOOR16(ax - 8) + R8_FLOOR16(p));
    d16 = R8_SHL4U(dy);
    u = (r8_u16)(dy * pl + (r8_u16)s0 * rd + d16 - 1u);     /* < 46 dy < 2^16 */
    while (u >= d16) {
        u = (r8_u16)(u - d16);
        it->val++;
    }
    it->err = R8_SHR4U(u);
    return y0;
}
#endif

#ifndef R8_ASM_TRAP
void r8k_trap(r8_trapfill *t, r8_interp *l, r8_interp *r, r8_u16 rows)
{
    r8_u8 *page = t->page, m = t->m, k = t->k;
    r8_s16 w = t->w;
    /* the edges in locals (registers on 8-bit CPUs) for the loop */
    r8_s16 lv = l->val, lq = l->q, rv = r->val, rq = r->q;
    r8_u16 le = l->err, lr = l->r, ld = l->den, re = r->err, rr = r->r, rd = r->den;
    while (rows--) {
        r8_s16 xl = lv, xr = rv;
        if (xl < 0)
            xl = 0;
        if (xr > w)
            xr = w;
        if (xl < xr)
            r8_fb_page_run(page + xl, (unsigned)(xr - xl), m, t->pat[k], (r8_u8)(xl & 3));
        lv = (r8_s16)(lv + lq);
        le = (r8_u16)(le + lr);
        if (le >= ld) {
            le = (r8_u16)(le - ld);
            lv++;
        }
        rv = (r8_s16)(rv + rq);
        re = (r8_u16)(re + rr);
        if (re >= rd) {
            re = (r8_u16)(re - rd);
            rv++;
        }
        k = (r8_u8)((k + 1) & 3);
        m = (r8_u8)(m << 1);
        if (!m) {
            m = 1;
            page += w;
        }
    }
    l->val = lv;
    l->err = le;
    r->val = rv;
    r->err = re;
    t->page = page;
    t->m = m;
    t->k = k;
}
#endif

#ifndef R8_ASM_CULL
int r8k_cull(const r8_s16 *n, const r8_s16 *v, const r8_vec3l *eye)
{
    r8_s16 x = R8_RDS16(v), y = R8_RDS16(v + 1), z = R8_RDS16(v + 2);
    if ((r8_u16)(x + 1023) > 2046u || (r8_u16)(y + 1023) > 2046u || (r8_u16)(z + 1023) > 2046u)
        return -1;
    return R8_MUL16(R8_RDS16(n), (r8_s16)eye->x - (r8_s16)(x * R8_CSCALE)) +
           R8_MUL16(R8_RDS16(n + 1), (r8_s16)eye->y - (r8_s16)(y * R8_CSCALE)) +
           R8_MUL16(R8_RDS16(n + 2), (r8_s16)eye->z - (r8_s16)(z * R8_CSCALE)) > 0;
}
#endif

#if !defined(R8_ASM_FWALK) && !defined(__SDCC) && !defined(__CC65__)
/* (not on the 6502 and Z80, which keep render.c's loop; 16-bit wrapping sums, as on the targets: unsigned arithmetic) */
#define R8_FW_FLOOR(v) ((r8_s16)((r8_u16)((r8_u16)(v) + 0x8007u) >> 4) - 2048)
r8_u8 r8k_fwalk(r8_fwalk *w)
{
    while (w->f) {
        r8_u16 f = --w->f;
        const r8_face *fc = &w->faces[f];
        r8_s16 xmin = 32767, xmax = -32767, ymin = 32767, ymax = -32767, top, bot;
        r8_u8 n = R8_RDU8(&fc->n), j;
        if (n < 3 || n > R8_MAX_FACE_VERTS)
            return R8_FW_OTHER;
        if (w->normals) {
            int c = r8k_cull(w->normals + 3u * f, w->verts + 3u * R8_RDU8(&fc->v[0]), w->eye);
            if (c < 0)
                return R8_FW_OTHER;
            if (!c)
                continue;
        }
        for (j = 0; j < n; j++) {
            r8_u8 i = R8_RDU8(&fc->v[j]);
            const r8_s16 *v = w->base + ((unsigned)i << w->vsh);
            r8_s16 x = v[0], y;
            if (x == -32767) {
                r8_tf_vertex((struct r8_state *)w->st, (const struct r8_objx *)w->o, w->verts + 3u * i,
                             (r8_u16)(w->vbase + i));
                x = v[0];
            }
            if (x == -32767 - 1)
                return R8_FW_OTHER;
            y = v[1];
            if (x < xmin) xmin = x;
            if (x > xmax) xmax = x;
            if (y < ymin) ymin = y;
            if (y > ymax) ymax = y;
        }
        top = R8_FW_FLOOR(ymin);
        bot = R8_FW_FLOOR(ymax);
        if (top < bot && bot > 0 && top < w->h && R8_FW_FLOOR(xmax) > 0 && R8_FW_FLOOR(xmin) < w->w) {
            r8_u16 key = 0, id = (r8_u16)(w->fbase + f);
            if (w->bsh < 0) {
                r8_fwpk *p = w->pk;
                const r8_s32 *pk;
                r8_u32 z;
                r8_u8 vi[R8_MAX_FACE_VERTS];
                r8_s32 zs;
                w->top = top;
                w->bot = bot;
                if (!p)
                    return 1;
                for (j = 0; j < n; j++)
                    vi[j] = R8_RDU8(&fc->v[j]);
                if (!r8k_zsum(w->verts, vi, n, p->row, &zs))
                    return 1;
                pk = p->k + (n == 4 ? 3 : 0);
                z = (r8_u32)zs + (r8_u32)pk[0];
                if (z & 0x80000000UL)
                    z = 0;
                if ((r8_s32)z < pk[1]) {
                    key = (r8_u16)((z * (r8_u32)pk[2]) >> 16);
                    if (n == 4)
                        key >>= 2;
                    if (key > 63)
                        key = 63;
                    key = (r8_u16)(63 - key);
                }
                if (p->ftop) {
                    r8_u16 b = 0;
                    if (top > 0)
                        b = (r8_u16)((r8_u16)top >> p->fbsh);
                    p->ftop[w->fid8 ? (r8_u8)id : id] = (r8_u8)(b > 255 ? 255 : b);
                }
            } else if (top > 0)
                key = (r8_u16)((r8_u16)top >> w->bsh);
            if (w->fid8) {
                r8_u8 *h = (r8_u8 *)w->heads, *nx = (r8_u8 *)w->next;
                id = (r8_u8)id;
                nx[id] = h[key];
                h[key] = (r8_u8)id;
            } else {
                r8_u16 *h = (r8_u16 *)w->heads, *nx = (r8_u16 *)w->next;
                nx[id] = h[key];
                h[key] = id;
            }
            if (w->slot)
                w->slot[id] = 0xFF;
            w->npoly++;
        }
    }
    return 0;
}
#undef R8_FW_FLOOR
#ifdef __AVR__
/* (render.c points w->paint here when fwalk.S is not built in; this
 * reference never jumps there) */
void r8k_fwpaint(void)
{
}
#endif
#elif defined(R8_ASM_FWALK)
#include <stddef.h>
/* AVR: ports/avr/fwalk.S reads these offsets */
R8_CASSERT(fwalk_faces_at_2, offsetof(r8_fwalk, faces) == 2);
R8_CASSERT(fwalk_normals_at_4, offsetof(r8_fwalk, normals) == 4);
R8_CASSERT(fwalk_verts_at_6, offsetof(r8_fwalk, verts) == 6);
R8_CASSERT(fwalk_eye_at_8, offsetof(r8_fwalk, eye) == 8);
R8_CASSERT(fwalk_f_at_10, offsetof(r8_fwalk, f) == 10);
R8_CASSERT(fwalk_w_at_12, offsetof(r8_fwalk, w) == 12);
R8_CASSERT(fwalk_h_at_14, offsetof(r8_fwalk, h) == 14);
R8_CASSERT(fwalk_top_at_16, offsetof(r8_fwalk, top) == 16);
R8_CASSERT(fwalk_bot_at_18, offsetof(r8_fwalk, bot) == 18);
R8_CASSERT(fwalk_vsh_at_20, offsetof(r8_fwalk, vsh) == 20);
R8_CASSERT(fwalk_heads_at_25, offsetof(r8_fwalk, heads) == 25);
R8_CASSERT(fwalk_next_at_27, offsetof(r8_fwalk, next) == 27);
R8_CASSERT(fwalk_slot_at_29, offsetof(r8_fwalk, slot) == 29);
R8_CASSERT(fwalk_npoly_at_31, offsetof(r8_fwalk, npoly) == 31);
R8_CASSERT(fwalk_fbase_at_33, offsetof(r8_fwalk, fbase) == 33);
R8_CASSERT(fwalk_bsh_at_35, offsetof(r8_fwalk, bsh) == 35);
R8_CASSERT(fwalk_fid8_at_36, offsetof(r8_fwalk, fid8) == 36);
R8_CASSERT(fwalk_vbase_at_37, offsetof(r8_fwalk, vbase) == 37);
R8_CASSERT(fwalk_pk_at_39, offsetof(r8_fwalk, pk) == 39);
R8_CASSERT(fwalk_paint_at_41, offsetof(r8_fwalk, paint) == 41);
/* ports/avr/fwpaint.S reads these */
R8_CASSERT(fwpk_row_at_24, offsetof(r8_fwpk, row) == 24);
R8_CASSERT(fwpk_ftop_at_26, offsetof(r8_fwpk, ftop) == 26);
R8_CASSERT(fwpk_fbsh_at_28, offsetof(r8_fwpk, fbsh) == 28);
R8_CASSERT(fwalk_face_6, sizeof(r8_face) == 6 && offsetof(r8_face, v) == 2);
#endif

#ifndef R8_ASM_LEVEL
r8_u8 r8k_level(const r8_s16 *n, const r8_vec3 *light, r8_s16 amb, r8_u8 colour)
{
    r8_s32 d = R8_MUL16(R8_RDS16(n), light->x) + R8_MUL16(R8_RDS16(n + 1), light->y) +
               R8_MUL16(R8_RDS16(n + 2), light->z);
    r8_s16 i = 0;                          /* as r8_tf_shade, step by step */
    r8_u32 p;
    if (d > 0) {
        i = (r8_s16)R8_SHR14U(d);
        if (i > R8_ONE14)
            i = R8_ONE14;
    }
    p = (r8_u32)R8_MUL16(R8_ONE14 - amb, i);
    p = (r8_u16)(amb + R8_SHR14U(p));
    /* ((p colour 256 + 8192) >> 14 in 16 bits, + 128) >> 8, in 8 bits */
    return (r8_u8)((p * colour + 8224u) >> 14);
}
#endif

#ifndef R8_ASM_ZSUM
int r8k_zsum(const r8_s16 *verts, const r8_u8 *vi, r8_u8 n, const r8_s16 *row, r8_s32 *out)
{
    r8_s32 sx = 0, sy = 0, sz = 0;      /* (face_zsum's own sums) */
    r8_u8 k;
    for (k = 0; k < n; k++) {
        const r8_s16 *mv = verts + 3u * vi[k];
        sx += R8_RDS16(mv);
        sy += R8_RDS16(mv + 1);
        sz += R8_RDS16(mv + 2);
    }
    if ((r8_u32)(sx + 32767) > 65534UL || (r8_u32)(sy + 32767) > 65534UL ||
        (r8_u32)(sz + 32767) > 65534UL)
        return 0;
    *out = R8_ASR32C(R8_MUL16(row[0], sx) + R8_MUL16(row[1], sy) + R8_MUL16(row[2], sz) + 512, 10);
    return 1;
}
#endif
