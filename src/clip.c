/* clip.c - Sutherland-Hodgman clipping in camera space, for faces that
 * cross the near plane or leave the guard band (|sx - cx| or |sy - cy|
 * over cam.guard pixels).  Each plane is one pass over the polygon's
 * edges: inside points are kept, an edge that crosses the plane adds its
 * intersection.  Clipping to the screen itself is left to the scan
 * converter and the span fill (cheaper per span than per polygon here);
 * the guard band only keeps projected coordinates inside 12.4.  Kept
 * original vertices reuse their screen vertex; only intersections are
 * projected and appended to the vertex array. */
#include "r8int.h"

#define NO_SRC 0xFFFFu


static r8_s32 plane_dist(const r8_proj *cam, r8_s32 zn, r8_u8 plane, const r8_clipv *v)
{
    r8_s32 gz = v->z * cam->guard;
    switch (plane) {
    case 0:
        return v->z - zn;
    case 1:
        return gz + v->x * cam->focal;
    case 2:
        return gz - v->x * cam->focal;
    case 3:
        return gz + v->y * cam->focal;
    default:
        return gz - v->y * cam->focal;
    }
}

/* One Sutherland-Hodgman pass; returns the output vertex count. */
static r8_u8 clip_pass(const r8_proj *cam, r8_s32 zn, r8_u8 plane, const r8_clipv *in,
                       r8_u8 n, r8_clipv *out)
{
    r8_u8 i, m = 0;
    for (i = 0; i < n; i++) {
        const r8_clipv *a = &in[i], *b = &in[i + 1 == n ? 0 : i + 1];
        r8_s32 da = plane_dist(cam, zn, plane, a), db = plane_dist(cam, zn, plane, b);
        if (da >= 0)
            out[m++] = *a;
        if ((da >= 0) != (db >= 0)) {
            /* intersection a + (b - a) * da / (da - db) */
            r8_s32 den = da - db;
            r8_clipv *c = &out[m++];
            c->x = a->x + r8_muldiv(b->x - a->x, da, den);
            c->y = a->y + r8_muldiv(b->y - a->y, da, den);
            c->z = a->z + r8_muldiv(b->z - a->z, da, den);
            c->s = (r8_s16)(a->s + r8_muldiv((r8_s32)b->s - a->s, da, den));
#if R8_W_TEXTURE
            c->u = (r8_s16)(a->u + r8_muldiv((r8_s32)b->u - a->u, da, den));
            c->v = (r8_s16)(a->v + r8_muldiv((r8_s32)b->v - a->v, da, den));
#endif
            c->src = NO_SRC;
            if (c->z < zn)
                c->z = zn;
        }
    }
    return m;
}

static r8_s32 absmax(r8_s32 m, r8_s32 v)
{
    if (v < 0)
        v = -v;
    return v > m ? v : m;
}

int r8_clip_face(r8_state *st, const r8_objx *o, const r8_object *ob, r8_u16 f,
                 const r8_u8 *vi, r8_u8 n, r8_cpoly *cp, r8_s32 *zsum)
{
    r8_clipv *a = (r8_clipv *)st->clipbuf, *b = a + R8_MAX_CLIP_POLY;  /* work memory, not stack */
    r8_clipv *in = a, *out = b, *t;
    r8_u8 i, plane, sh = 0;
    r8_s32 big = 0, zn = st->zn16;
    const r8_mesh *me = ob->mesh;
    r8_proj wide;
#if R8_W_TEXTURE
    r8_s16 *tuv = 0;
#endif
    unsigned stride = 2u;   /* 1 << vsh: no run-time shift (cc65 trap, DEVELOPERS.md) */
    if (st->vsh == 2)
        stride = 4u;
    for (i = 0; i < n; i++) {
        r8_u16 g = (r8_u16)(o->vbase + vi[i]);
        const r8_s16 *mv = me->verts + 3u * vi[i];
        const r8_s16 *sv = st->sv + (unsigned)g * stride;
        r8_vec3 v;
        r8_vec3l c;
        v.x = R8_RDS16(mv);
        v.y = R8_RDS16(mv + 1);
        v.z = R8_RDS16(mv + 2);
        r8_mat_apply16(&o->m, &v, &c);
        a[i].x = c.x + o->t.x;
        a[i].y = c.y + o->t.y;
        a[i].z = c.z + o->t.z;
        a[i].s = st->vsh == 2 ? sv[3] : 0;
        a[i].src = sv[0] == R8_VX_CLIP ? NO_SRC : g;
#if R8_W_TEXTURE
        a[i].u = a[i].v = 0;
        if (R8_TEXTURED(st->shading) && me->tex) {
            /* the corner's texture coordinates, 8.8 texels (texture.c) */
            const r8_u8 *uv = me->uv + 8u * f + 2u * i;
            a[i].u = (r8_s16)((r8_u16)R8_RDU8(uv) << (me->tex->wlog + 1));
            a[i].v = (r8_s16)((r8_u16)R8_RDU8(uv + 1) << (me->tex->hlog + 1));
        }
#endif
        big = absmax(absmax(absmax(big, a[i].x), a[i].y), a[i].z);
    }
    /* plane distances are z * guard +- x * focal: keep |coord| < 2^19 */
    while (big >= (1L << 19)) {
        big >>= 1;
        sh++;
    }
    if (sh) {
        for (i = 0; i < n; i++) {
            a[i].x = r8_asr32(a[i].x, sh);
            a[i].y = r8_asr32(a[i].y, sh);
            a[i].z = r8_asr32(a[i].z, sh);
        }
        zn = r8_asr32(zn, sh);
        if (zn < 1)
            zn = 1;
    }
    for (plane = 0; plane < 5 && n >= 3; plane++) {
        n = clip_pass(&st->cam, zn, plane, in, n, out);
        t = in;
        in = out;
        out = t;
    }
    if (n < 3)
        return 0;
    wide = st->cam;
    wide.guard = 1400;   /* intersections lie on the 900 px planes */
#if R8_W_TEXTURE
    if (R8_TEXTURED(st->shading)) {
        /* u, v of the corners beside the polygon (cp is
         * st->cpoly[st->nclipped]), and its object */
        const r8_object *p = st->scene->objects;
        r8_u8 k = 0;
        while (p != ob) {
            p++;
            k++;
        }
        tuv = st->cuv + (unsigned)st->nclipped * R8_CUV_STRIDE;
        tuv[R8_CUV_STRIDE - 1u] = k;
    }
#endif
    *zsum = 0;
    for (i = 0; i < n; i++) {
        r8_vec3l c;
        r8_s16 *s;
#if R8_W_TEXTURE
        if (tuv) {
            tuv[2u * i] = in[i].u;
            tuv[2u * i + 1u] = in[i].v;
        }
#endif
        c.x = in[i].x;
        c.y = in[i].y;
        c.z = (r8_s32)((r8_u32)in[i].z << sh);
        *zsum += c.z;
        if (in[i].src != NO_SRC) {
            cp->idx[i] = in[i].src;
            continue;
        }
        if (st->sv_used >= st->sv_cap) {
            st->dropped++;
            return 0;
        }
        s = st->sv + (unsigned)st->sv_used * stride;
        c.x = (r8_s32)((r8_u32)c.x << sh);
        c.y = (r8_s32)((r8_u32)c.y << sh);
        {
            r8_s8 e;
            r8_u16 m = r8_recip(c.z, &e);
            if (r8_project_recip(&wide, &c, m, e, &s[0], &s[1]))
                return 0;            /* cannot happen for a clipped point */
            if (st->vsh == 2) {
                s[2] = st->attrs & R8_ATTR_D ? r8_tf_depth(st, m, e) : 0;
                s[3] = in[i].s;
            }
        }
        cp->idx[i] = st->sv_used++;
    }
    cp->n = n;
    cp->level = r8_face_level(st, o, ob, f);
    return 1;
}
