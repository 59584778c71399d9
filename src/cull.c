/* cull.c - backface culling before projection, from the face normal
 * (the seed's first method).  The second method, Judd's, lives in the
 * scan converter (scan.c).  Normals are computed once at init from the
 * model's edges: n = (v2 - v0) x (v1 - v0), which points outwards for
 * faces listed clockwise as seen from outside (screen y down), scaled to
 * unit length. */
#include "r8int.h"

void r8_cull_normals(r8_state *st)
{
    const r8_scene *sc = st->scene;
    r8_u8 i;
    for (i = 0; i < sc->nobjects; i++) {
        const r8_mesh *me = sc->objects[i].mesh;
        const r8_objx *o = &st->obj[i];
        r8_u16 f;
        for (f = 0; f < me->nfaces; f++) {
            const r8_face *fc = &me->faces[f];
            const r8_s16 *a = me->verts + fc->v[0] * 3;
            const r8_s16 *b = me->verts + fc->v[1] * 3;
            const r8_s16 *c = me->verts + fc->v[2] * 3;
            r8_vec3 e1, e2;
            r8_vec3l n;
            r8_s32 d[6];
            r8_u8 j, big = 1;
            /* edges of coordinates up to +/-32767 need 17 bits: halve both
             * until every component fits 16 (same scale: same direction) */
            for (j = 0; j < 3; j++) {
                d[j] = (r8_s32)b[j] - a[j];
                d[3 + j] = (r8_s32)c[j] - a[j];
            }
            while (big) {
                big = 0;
                for (j = 0; j < 6; j++)
                    if (d[j] > 32767 || d[j] < -32767)
                        big = 1;
                if (big)
                    for (j = 0; j < 6; j++)
                        d[j] = r8_asr32(d[j], 1);
            }
            e1.x = (r8_s16)d[0]; e1.y = (r8_s16)d[1]; e1.z = (r8_s16)d[2];
            e2.x = (r8_s16)d[3]; e2.y = (r8_s16)d[4]; e2.z = (r8_s16)d[5];
            r8_cross3(&e2, &e1, &n);  /* outward: faces are clockwise from outside */
            r8_normalize(&n, &st->fnorm[o->fbase + f]);
        }
        if (st->vnorm) {
            /* vertex normals: sum of the unit normals of the faces around */
            r8_u16 k;
            for (k = 0; k < me->nverts; k++) {
                r8_vec3l sum;
                sum.x = sum.y = sum.z = 0;
                for (f = 0; f < me->nfaces; f++) {
                    const r8_face *fc = &me->faces[f];
                    r8_u8 j;
                    for (j = 0; j < fc->n; j++)
                        if (fc->v[j] == k) {
                            sum.x += st->fnorm[o->fbase + f].x;
                            sum.y += st->fnorm[o->fbase + f].y;
                            sum.z += st->fnorm[o->fbase + f].z;
                        }
                }
                r8_normalize(&sum, &st->vnorm[o->vbase + k]);
            }
        }
    }
}

/* Front iff n . (eye - v0) > 0 in model space.  eye - v0 is scaled down
 * by a power of two to 15 bits so the dot product fits 32 bits. */
int r8_cull_front(const r8_state *st, const r8_objx *o, const r8_mesh *me, r8_u16 f)
{
    const r8_face *fc = &me->faces[f];
    const r8_s16 *a = me->verts + fc->v[0] * 3;
    const r8_vec3 *n = &st->fnorm[o->fbase + f];
    r8_s32 dx = o->eye.x - a[0], dy = o->eye.y - a[1], dz = o->eye.z - a[2];
    r8_vec3 d;
    while (dx > 32767 || dx < -32767 || dy > 32767 || dy < -32767 ||
           dz > 32767 || dz < -32767) {
        dx = r8_asr32(dx, 1);
        dy = r8_asr32(dy, 1);
        dz = r8_asr32(dz, 1);
    }
    d.x = (r8_s16)dx;
    d.y = (r8_s16)dy;
    d.z = (r8_s16)dz;
    return r8_dot3(n, &d) > 0;
}
