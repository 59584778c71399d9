/* normals.c - outward unit face normals of a mesh, as the scene
 * converter computes them (host/rast8/scene.py c_normals): for meshes
 * built at run time.  n = (v2 - v0) x (v1 - v0), which points outwards
 * for faces listed clockwise as seen from outside (screen y down). */
#include "r8scene.h"
#include "r8flash.h"

void r8_mesh_normals(const r8_mesh *me, r8_s16 *out)
{
    r8_u16 f;
    for (f = 0; f < me->nfaces; f++) {
        const r8_face *fc = &me->faces[f];
        const r8_s16 *a = me->verts + R8_RDU8(&fc->v[0]) * 3;
        const r8_s16 *b = me->verts + R8_RDU8(&fc->v[1]) * 3;
        const r8_s16 *c = me->verts + R8_RDU8(&fc->v[2]) * 3;
        r8_vec3 e1, e2, nn;
        r8_vec3l n;
        r8_s32 d[6];
        r8_u8 j, big = 1;
        /* edges of coordinates up to +/-32767 need 17 bits: halve both
         * until every component fits 16 (same scale: same direction) */
        for (j = 0; j < 3; j++) {
            d[j] = (r8_s32)R8_RDS16(&b[j]) - R8_RDS16(&a[j]);
            d[3 + j] = (r8_s32)R8_RDS16(&c[j]) - R8_RDS16(&a[j]);
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
        r8_normalize(&n, &nn);
        out[3u * f] = nn.x;
        out[3u * f + 1] = nn.y;
        out[3u * f + 2] = nn.z;
    }
}
