/* transform.c - per frame: object rotations, then every vertex once:
 * rotate and translate into camera space, project to 12.4 screen
 * coordinates, depth (affine in 1/z) and, for Gouraud, the vertex shade.
 * Vertices behind the near plane or outside the guard band are flagged
 * (outcodes) and their faces go through the clipper. */
#include "r8int.h"

void r8_tf_objects(r8_state *st, r8_u16 frame)
{
    const r8_scene *sc = st->scene;
    r8_u8 i;
    for (i = 0; i < sc->nobjects; i++) {
        const r8_object *ob = &sc->objects[i];
        r8_objx *o = &st->obj[i];
        r8_vec3 p;
        r8_u8 ax = (r8_u8)(ob->ax + (r8_u8)(ob->sx * (int)(frame & 0xFF)));
        r8_u8 ay = (r8_u8)(ob->ay + (r8_u8)(ob->sy * (int)(frame & 0xFF)));
        r8_u8 az = (r8_u8)(ob->az + (r8_u8)(ob->sz * (int)(frame & 0xFF)));
        r8_mat_rotate(&o->m, ax, ay, az);
        r8_mat_apply_t14(&o->m, &sc->light, &o->light);
        /* eye in model space: R^T * (0 - position) */
        p.x = (r8_s16)-ob->x;
        p.y = (r8_s16)-ob->y;
        p.z = (r8_s16)-ob->z;
        o->eye.x = r8_asr14(r8_mul16(o->m.m[0], p.x) + r8_mul16(o->m.m[3], p.y) +
                            r8_mul16(o->m.m[6], p.z) + 8192);
        o->eye.y = r8_asr14(r8_mul16(o->m.m[1], p.x) + r8_mul16(o->m.m[4], p.y) +
                            r8_mul16(o->m.m[7], p.z) + 8192);
        o->eye.z = r8_asr14(r8_mul16(o->m.m[2], p.x) + r8_mul16(o->m.m[5], p.y) +
                            r8_mul16(o->m.m[8], p.z) + 8192);
    }
}

r8_s16 r8_tf_depth(const r8_state *st, r8_s32 z)
{
    r8_s32 d;
    if (z < 1)
        z = 1;
    d = st->dc1 / z - st->dc2;
    if (d < 0)
        d = 0;
    if (d > 32767)
        d = 32767;
    return (r8_s16)d;
}

/* Shade in 8.8 (level 0..16 << 8) of a surface with unit normal n under
 * `light`, for brightness `colour`: colour * (ambient + (1-ambient) *
 * max(0, n.l)). */
r8_s16 r8_tf_shade(const r8_state *st, const r8_vec3 *n, const r8_vec3 *light,
                   r8_u8 colour)
{
    r8_s32 i = r8_asr14(r8_dot3(n, light));   /* Q1.14 cosine */
    r8_s32 amb = st->scene->ambient, k;
    if (i < 0)
        i = 0;
    if (i > R8_ONE14)
        i = R8_ONE14;
    k = amb + r8_asr14((R8_ONE14 - amb) * i);  /* Q1.14 intensity */
    return (r8_s16)r8_asr14(k * ((r8_s32)colour << 8) + 8192);
}

void r8_tf_vertices(r8_state *st)
{
    const r8_scene *sc = st->scene;
    const r8_camera *cam = &st->cam;
    r8_s32 wsub = r8_mul16(st->cam.cx, 2), hsub = r8_mul16(st->cam.cy, 2);
    r8_u8 i;
    for (i = 0; i < sc->nobjects; i++) {
        const r8_object *ob = &sc->objects[i];
        const r8_mesh *me = ob->mesh;
        const r8_objx *o = &st->obj[i];
        r8_u16 k;
        for (k = 0; k < me->nverts; k++) {
            r8_u16 g = (r8_u16)(o->vbase + k);
            r8_svert *s = &st->sv[g];
            const r8_s16 *mv = me->verts + k * 3;
            r8_vec3 v;
            r8_vec3l c;
            r8_u8 out = 0;
            v.x = mv[0];
            v.y = mv[1];
            v.z = mv[2];
            r8_mat_apply(&o->m, &v, &c);
            c.x += ob->x;
            c.y += ob->y;
            c.z += ob->z;
            if (c.z < cam->znear) {
                out = R8_OUT_NEAR;
                s->x = s->y = 0;
                s->d = 0;
            } else {
                r8_s32 gz = c.z * cam->guard, ax = c.x < 0 ? -c.x : c.x, ay = c.y < 0 ? -c.y : c.y;
                if (ax * cam->focal > gz || ay * cam->focal > gz)
                    out = R8_OUT_GUARD;
                r8_project(cam, &c, &s->x, &s->y);
                if (s->x < 0) out |= R8_OUT_LEFT;
                if (s->x >= wsub) out |= R8_OUT_RIGHT;
                if (s->y < 0) out |= R8_OUT_TOP;
                if (s->y >= hsub) out |= R8_OUT_BOTTOM;
                s->d = st->need_depth ? r8_tf_depth(st, c.z) : 0;
            }
            s->s = 0;
            if (st->attrs & R8_ATTR_S)
                s->s = r8_tf_shade(st, &st->vnorm[g], &o->light, 16);
            st->out[g] = out;
        }
    }
}
