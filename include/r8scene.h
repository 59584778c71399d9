/* r8scene.h - the scene model: meshes with shared vertices (indexed
 * faces), per-face colour, and objects placing a mesh with a transform.
 *
 * Camera: at the origin looking down +z, x right, y down (camera space =
 * world space).  Front faces list their vertices clockwise as seen from
 * outside (on screen, y down).  A face has 3 or 4 vertices and must be
 * planar and convex.
 */
#ifndef R8SCENE_H
#define R8SCENE_H

#include "r8types.h"
#include "r8fixed.h"

#define R8_MAX_FACE_VERTS 4

typedef struct r8_face {
    r8_u8 n;                      /* 3 or 4 */
    r8_u8 colour;                 /* brightness level 0..16 */
    r8_u8 v[R8_MAX_FACE_VERTS];   /* vertex indices */
} r8_face;

typedef struct r8_mesh {
    const r8_s16 *verts;   /* x, y, z per vertex, model units */
    const r8_face *faces;
    r8_u16 nverts;         /* at most 255 (face indices are bytes) */
    r8_u16 nfaces;
    r8_u8 convex;          /* closed and convex: backface cull is exact */
    r8_s16 radius;         /* bounding sphere about the model origin */
} r8_mesh;

typedef struct r8_object {
    const r8_mesh *mesh;
    r8_s16 x, y, z;            /* position in camera space */
    r8_u8 ax, ay, az;          /* angles at frame 0 (256 per turn) */
    r8_s8 sx, sy, sz;          /* angle step per frame */
} r8_object;

typedef struct r8_scene {
    const char *name;
    const r8_object *objects;
    r8_u8 nobjects;
    r8_s16 focal_num;          /* focal length = width * focal_num / 64 px */
    r8_s16 znear;              /* near plane */
    r8_s16 ambient;            /* Q1.14 ambient light for Lambert/Gouraud */
    r8_vec3 light;             /* unit vector towards the light, Q1.14 */
} r8_scene;

/* The built-in scenes (R8_SCENE_* in r8render.h); 0 if out of range. */
const r8_scene *r8_scene_get(r8_u8 id);

#endif
