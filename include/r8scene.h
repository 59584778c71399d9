/* r8scene.h - what the renderer draws: meshes (flash data), objects that
 * place a mesh with a pose, and the scene the application owns.
 *
 * World and camera space: x right, y down, z forward (a camera with no
 * rotation looks down +z).  Front faces list their vertices clockwise as
 * seen from outside (on screen, y down).  A face has 3 or 4 vertices and
 * must be planar and convex (the scene converter splits other faces).
 *
 * Memory: a mesh's arrays are constant data declared R8_FLASH (r8flash.h)
 * and read through R8_RD*, so on AVR they cost flash, not SRAM.  The
 * r8_mesh, r8_object and r8_scene structs themselves are small and live
 * in RAM; the application changes poses between frames.
 */
#ifndef R8SCENE_H
#define R8SCENE_H

#include "r8types.h"
#include "r8fixed.h"
#include "r8flash.h"

#define R8_MAX_FACE_VERTS 4

typedef struct r8_face {
    r8_u8 n;                      /* 3 or 4 */
    r8_u8 colour;                 /* brightness level 0..16 */
    r8_u8 v[R8_MAX_FACE_VERTS];   /* vertex indices */
} r8_face;

typedef struct r8_mesh {
    const r8_s16 *verts;    /* R8_FLASH: x, y, z per vertex, model units */
    const r8_face *faces;   /* R8_FLASH */
    const r8_s16 *normals;  /* R8_FLASH: outward unit face normals, Q1.14,
                               x, y, z per face; 0: r8_render_init computes
                               them into work memory (r8_render_ram counts
                               it) */
    r8_u16 nverts;          /* at most 255 (face indices are bytes) */
    r8_u16 nfaces;
    r8_u8 convex;           /* closed and convex: backface cull is exact */
    r8_s16 radius;          /* bounding sphere about the model origin */
    const r8_u8 *bsp;       /* R8_FLASH: BSP tree over the faces (the scene
                               converter's host/rast8/bsp.py: u16 root, u16
                               depth, then per face u16 front and back
                               child, 0xFFFF none, little-endian); 0: none
                               (R8_VIS_BSP refuses the mesh) */
#ifndef R8_NO_TEXTURE
    const struct r8_texture *tex; /* 0: untextured (R8_SHADE_TEXTURE
                               then draws the face's Lambert level) */
    const r8_u8 *uv;        /* R8_FLASH: u, v per face corner, 8 bytes a
                               face (4 corners); 128 = the texture's width
                               (height), so 0..255 spans two repeats */
#endif
} r8_mesh;
/* The converter writes R8_MESH_BSP(tree) so a build without BSP
 * (R8_NO_BSP) links no tree. */
#ifdef R8_NO_BSP
#define R8_MESH_BSP(t) 0
#else
#define R8_MESH_BSP(t) t
#endif
/* The texture members in a positional r8_mesh initialiser, after radius:
 * {verts, faces, normals, nverts, nfaces, convex, radius, R8_MESH_BSP(tree)
 *  R8_MESH_TEX(t, uv)}
 * (nothing in a build without texture mapping, so its meshes stay as
 * small as before). */
#ifdef R8_NO_TEXTURE
#define R8_MESH_TEX(t, uv)
#else
#define R8_MESH_TEX(t, uv) , t, uv
#endif

/* A texture (docs/pipeline.md "Texture mapping"): 2^wlog x 2^hlog texels
 * (8..64 a side), rows top to bottom in R8_FLASH data.  R8_TEX_1BPP: a
 * row is 2^wlog / 8 bytes, MSB = leftmost texel, a set bit is lit
 * (level 16).  R8_TEX_IDX8: a byte per texel, an index into a grey ramp
 * 0 (black) .. 255 (white).  Coordinates wrap (the texture repeats). */
#define R8_TEX_1BPP 0
#define R8_TEX_IDX8 1
typedef struct r8_texture {
    const r8_u8 *data;      /* R8_FLASH */
    r8_u8 wlog, hlog;       /* log2 width, height: 3..6 */
    r8_u8 format;           /* R8_TEX_* */
} r8_texture;

/* r8_pose.flags */
#define R8_POSE_HIDDEN 1    /* not drawn this frame */
#define R8_POSE_MATRIX 2    /* m is the rotation (else ax, ay, az) */
#define R8_POSE_COLOUR 4    /* colour replaces every face's own */

/* Where an object is: model space -> world space is rotation, then
 * translation by (x, y, z).  The rotation is Rx(ax) Ry(ay) Rz(az)
 * (angles in 256 steps per turn: spun about its own z, then y, then x),
 * or, when flags has R8_POSE_MATRIX, the caller's Q1.14 matrix *m. */
typedef struct r8_pose {
    r8_s16 x, y, z;         /* position, world units */
    r8_u8 ax, ay, az;       /* rotation angles */
    r8_u8 flags;            /* R8_POSE_* */
    r8_u8 colour;           /* level 0..16 with R8_POSE_COLOUR */
    const r8_mat3 *m;       /* rotation with R8_POSE_MATRIX (caller's) */
} r8_pose;

typedef struct r8_object {
    const r8_mesh *mesh;
    r8_pose pose;
} r8_object;

/* The scene: the application's objects and the light.  Poses are read
 * at every r8_render_frame; the object list itself (count, meshes) is
 * fixed after r8_render_init. */
struct r8_world;             /* r8portal.h */

typedef struct r8_scene {
    r8_object *objects;
    r8_u8 nobjects;
    r8_s16 ambient;         /* Q1.14 ambient light for Lambert/Gouraud */
    r8_vec3 light;          /* unit vector towards the light, world space, Q1.14 */
    const struct r8_grid *grid; /* a grid map for the ray caster (r8ray.h,
                               R8_VIS_RAY); 0 = none */
    const struct r8_world *world;  /* sectors and portals (r8portal.h), 0 = none */
} r8_scene;

/* A pose at the origin with no rotation, visible, own colours. */
void r8_pose_identity(r8_pose *p);

/* Outward unit face normals (Q1.14) of mesh m into out[3 * m->nfaces]:
 * what the scene converter stores in r8_mesh.normals, for meshes built
 * at run time. */
void r8_mesh_normals(const r8_mesh *m, r8_s16 *out);

#endif
