/* clip.c - Sutherland-Hodgman clipping in camera space, for faces that
 * cross the near plane or leave the guard band (|sx - cx| or |sy - cy|
 * over cam.guard pixels).  Each plane is one pass over the polygon's
 * edges: inside points are kept, an edge that crosses the plane adds its
 * intersection.  Clipping to the screen itself is left to the scan
 * converter and the span fill (cheaper per span than per polygon here);
 * the guard band only keeps projected coordinates inside 12.4. */
#include "r8int.h"

typedef struct clipv {
    r8_s32 x, y, z;
    r8_s16 s;
} clipv;

static r8_s32 plane_dist(const r8_camera *cam, r8_u8 plane, const clipv *v)
{
    r8_s32 gz = v->z * cam->guard;
    switch (plane) {
    case 0:
        return v->z - cam->znear;
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
static r8_u8 clip_pass(const r8_camera *cam, r8_u8 plane, const clipv *in,
                       r8_u8 n, clipv *out)
{
    r8_u8 i, m = 0;
    for (i = 0; i < n; i++) {
        const clipv *a = &in[i], *b = &in[i + 1 == n ? 0 : i + 1];
        r8_s32 da = plane_dist(cam, plane, a), db = plane_dist(cam, plane, b);
        if (da >= 0)
            out[m++] = *a;
        if ((da >= 0) != (db >= 0)) {
            /* intersection a + (b - a) * da / (da - db) */
            r8_s32 den = da - db;
            clipv *c = &out[m++];
            c->x = a->x + r8_muldiv(b->x - a->x, da, den);
            c->y = a->y + r8_muldiv(b->y - a->y, da, den);
            c->z = a->z + r8_muldiv(b->z - a->z, da, den);
            c->s = (r8_s16)(a->s + r8_muldiv((r8_s32)b->s - a->s, da, den));
            if (c->z < cam->znear)
                c->z = cam->znear;
        }
    }
    return m;
}

unsigned r8_clip_bytes(void)
{
    return 2u * R8_MAX_CLIP_POLY * (unsigned)sizeof(clipv);
}

int r8_clip_face(r8_state *st, const r8_objx *o, const r8_object *ob,
                 const r8_face *fc, r8_poly *p)
{
    clipv *a = (clipv *)st->clipbuf, *b = a + R8_MAX_CLIP_POLY;  /* work memory, not stack */
    clipv *in = a, *out = b, *t;
    r8_u8 n = fc->n, i, plane;
    const r8_mesh *me = ob->mesh;
    for (i = 0; i < n; i++) {
        const r8_s16 *mv = me->verts + fc->v[i] * 3;
        r8_vec3 v;
        r8_vec3l c;
        v.x = mv[0];
        v.y = mv[1];
        v.z = mv[2];
        r8_mat_apply(&o->m, &v, &c);
        a[i].x = c.x + ob->x;
        a[i].y = c.y + ob->y;
        a[i].z = c.z + ob->z;
        a[i].s = st->sv[o->vbase + fc->v[i]].s;
    }
    for (plane = 0; plane < 5 && n >= 3; plane++) {
        n = clip_pass(&st->cam, plane, in, n, out);
        t = in;
        in = out;
        out = t;
    }
    if (n < 3)
        return 0;
    if (st->nsv + n > st->nverts + st->nclip || st->nidx + n > st->maxidx) {
        st->dropped++;
        return 0;
    }
    p->idx = st->nidx;
    p->n = n;
    for (i = 0; i < n; i++) {
        r8_svert *s = &st->sv[st->nsv];
        r8_vec3l c;
        c.x = in[i].x;
        c.y = in[i].y;
        c.z = in[i].z;
        r8_project(&st->cam, &c, &s->x, &s->y);
        s->d = r8_tf_depth(st, c.z);
        s->s = in[i].s;
        st->idx[st->nidx++] = st->nsv++;
    }
    return 1;
}
