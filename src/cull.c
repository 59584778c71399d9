/* cull.c - face normals, backface culling before projection (the seed's
 * first method: the sign of the face normal against the view vector) and
 * the per-face shade.  The second cull, Judd's, lives in the scan
 * converter (scan.c).  Normals come with the mesh (flash, from the scene
 * converter) or are computed once at init from the model's edges:
 * n = (v2 - v0) x (v1 - v0), which points outwards for faces listed
 * clockwise as seen from outside (screen y down), scaled to unit length. */
#include "r8int.h"
#include "r8kern.h"

void r8_pose_identity(r8_pose *p)
{
    p->x = p->y = p->z = 0;
    p->ax = p->ay = p->az = 0;
    p->flags = 0;
    p->colour = 16;
    p->m = 0;
}

static void normal_of(const r8_objx *o, r8_u16 f, r8_vec3 *n)
{
    const r8_s16 *p = o->normals + 3u * f;
#ifndef R8_NO_RT_NORMALS    /* (without: the mesh's, R8_FLASH data) */
    if (!o->nflash) {
        n->x = p[0];
        n->y = p[1];
        n->z = p[2];
        return;
    }
#endif
    n->x = R8_RDS16(p);
    n->y = R8_RDS16(p + 1);
    n->z = R8_RDS16(p + 2);
}

/* Front iff n . (eye - v0) > 0 in model space (eye in 1/16 units), v0
 * the face's first vertex (flash).  In 16 bits when the eye is within
 * 1024 units and v0 within 1023 units of the model origin; else eye - v0
 * is scaled down by a power of two so the dot product fits 32 bits. */
int r8_cull_front(const r8_objx *o, const r8_s16 *v0, r8_u16 f)
{
    r8_s16 x = R8_RDS16(v0), y = R8_RDS16(v0 + 1), z = R8_RDS16(v0 + 2);
    r8_s32 dx, dy, dz;
    r8_vec3 n;
    normal_of(o, f, &n);
    if (o->eye16 && (r8_u16)(x + 1023) <= 2046u && (r8_u16)(y + 1023) <= 2046u &&
        (r8_u16)(z + 1023) <= 2046u)
        return R8_MUL16(n.x, (r8_s16)o->eye.x - (r8_s16)(x * R8_CSCALE)) +
               R8_MUL16(n.y, (r8_s16)o->eye.y - (r8_s16)(y * R8_CSCALE)) +
               R8_MUL16(n.z, (r8_s16)o->eye.z - (r8_s16)(z * R8_CSCALE)) > 0;
    dx = o->eye.x - (r8_s32)x * R8_CSCALE;
    dy = o->eye.y - (r8_s32)y * R8_CSCALE;
    dz = o->eye.z - (r8_s32)z * R8_CSCALE;
    while ((r8_u32)(dx + 32767) > 65534UL || (r8_u32)(dy + 32767) > 65534UL ||
           (r8_u32)(dz + 32767) > 65534UL) {
        dx = R8_ASR32C(dx, 1);
        dy = R8_ASR32C(dy, 1);
        dz = R8_ASR32C(dz, 1);
    }
    return R8_MUL16(n.x, dx) + R8_MUL16(n.y, dy) + R8_MUL16(n.z, dz) > 0;
}

/* Dither level 0..16 of face f of object ob: its colour (or the pose's),
 * lit by the light for Lambert. */
r8_u8 r8_face_level(const r8_state *st, const r8_objx *o, const r8_object *ob, r8_u16 f)
{
    r8_u8 colour = R8_RDU8(&ob->mesh->faces[f].colour);
    if (ob->pose.flags & R8_POSE_COLOUR)
        colour = ob->pose.colour;
    if (st->shading != R8_SHADE_LAMBERT && !R8_TEXTURED(st->shading))
        return colour;
#if defined(__SDCC) || !defined(R8_NO_RT_NORMALS)
#ifndef __SDCC                         /* (R8_SDCC_FACE_KERN in r8kern.h) */
    if (!o->nflash)
#endif
    {
        r8_vec3 n;
        normal_of(o, f, &n);
        return (r8_u8)((r8_tf_shade(st, &n, &o->light, colour) + 128) >> 8);
    }
#endif
#ifndef __SDCC
    {                                  /* flash normals: one kernel (r8kern.h) */
        r8_s16 amb = st->scene->ambient;
        if (amb < 0)
            amb = 0;
        if (amb > R8_ONE14)
            amb = R8_ONE14;
        return r8k_level(o->normals + 3u * f, &o->light, amb, colour);
    }
#endif
}
