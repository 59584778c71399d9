/* r8render.h - the frame renderer: scene -> transform -> cull and clip
 * -> scan convert -> visibility -> framebuffer band.
 *
 * A minimal program (docs/api.md walks through it):
 *   r8_render_cfg cfg;  r8_render_defaults(&cfg);  cfg.scene = &scene;
 *   need = r8_render_ram(&cfg);           work memory in bytes
 *   r8_render_init(&r, &cfg, work, sizeof work);
 *   per frame:  set the camera and the objects' poses, then
 *               r8_render_frame(&r, &cam);                transform once
 *               for each band: r8_fb_set_band(&fb, y0); r8_render_band(&r, &fb);
 * All memory is the caller's: `work` holds the frame's vertices, face
 * lists, scan states and depth memory; the band buffer is the caller's
 * r8_fb.  The renderer computes nothing from time: poses and camera are
 * the application's.
 *
 * Leaving parts out: a firmware that does not use a visibility method,
 * Gouraud shading, the clipper or run-time normals can leave them out at
 * compile time (r8config.h lists the switches); r8_render_init then
 * rejects a configuration that needs them.
 */
#ifndef R8RENDER_H
#define R8RENDER_H

#include "r8types.h"
#include "r8config.h"
#include "r8fb.h"
#include "r8scene.h"

/* Visibility methods (see docs/visibility.md). */
#define R8_VIS_CULL 0      /* backface cull only: exact for one convex mesh */
#define R8_VIS_PAINTER 1   /* painter's, faces jeffsorted by depth */
#define R8_VIS_Z8 2        /* full z-buffer, 8-bit depth */
#define R8_VIS_Z16 3       /* full z-buffer, 16-bit depth */
#define R8_VIS_BLOCK 4     /* seed's 4x4-block z-buffer, one compare per block */
#define R8_VIS_BLOCKMASK 5 /* 4x4-block z with a coverage mask per block */
#define R8_VIS_SBUF 6      /* S-buffer: depth-clipped spans per scanline */
#define R8_VIS_BSP 7       /* BSP tree order (the meshes' trees), painter's fill */
#define R8_VIS_COUNT 8
#define R8_VIS_RAY 17      /* world renderer: ray caster over the scene's
                              grid map (r8ray.h); not in R8_VIS_COUNT */
#define R8_VIS_AUTO 255    /* let the analyser choose */
#define R8_VIS_PORTAL 16   /* a world of sectors and portals (r8portal.h):
                              a world renderer, outside R8_VIS_COUNT */

/* Shading. */
#define R8_SHADE_FLAT 0    /* the face's own colour */
#define R8_SHADE_LAMBERT 1 /* light . face normal, per face */
#define R8_SHADE_GOURAUD 2 /* light . vertex normal, interpolated */
#define R8_SHADE_TEXTURE 3 /* the mesh's texture times the Lambert level
                              (cull and painter's only; not with
                              R8_NO_TEXTURE) */

/* r8_render_cfg.texfilter */
#define R8_TEXF_NEAREST 0  /* nearest texel */
#define R8_TEXF_BILINEAR 1 /* bilinear between 4 texels (IDX8 textures;
                              1-bpp ones stay nearest) */

/* Backface cull. */
#define R8_CULL_NORMAL 0   /* before projection, from the face normal */
#define R8_CULL_JUDD 1     /* during scan conversion, by screen winding */

/* The application's camera, set before every r8_render_frame.  It sits
 * at (x, y, z) and looks down its own +z axis, x right, y down.  Its
 * rotation camera -> world is Ry(yaw) Rx(pitch) Rz(roll) (256 steps per
 * turn: yaw turns right, pitch tilts up), or, with R8_CAM_MATRIX, *m is
 * the world -> camera rotation the caller fills (Q1.14). */
#define R8_CAM_MATRIX 1
typedef struct r8_camera {
    r8_s16 x, y, z;          /* position, world units */
    r8_u8 yaw, pitch, roll;
    r8_u8 flags;             /* R8_CAM_* */
    const r8_mat3 *m;        /* world -> camera with R8_CAM_MATRIX (caller's) */
    r8_s16 focal;            /* focal length in pixels, 1..2047 */
    r8_s16 znear;            /* near clip plane and near end of the depth
                                range, world units, >= 1 */
    r8_s16 zfar;             /* far end of the depth range (depth methods,
                                painter's keys); farther points clamp */
} r8_camera;

/* At the origin, no rotation, focal length = width pixels (53 degrees
 * across), znear 16, zfar 4096. */
void r8_camera_defaults(r8_camera *c, r8_s16 width);
/* Focal length in pixels for a horizontal field of view `fov` (256 steps
 * per turn, 1..127) on a screen `width` pixels wide. */
r8_s16 r8_camera_fov(r8_s16 width, r8_u8 fov);

typedef struct r8_render_cfg {
    const r8_scene *scene; /* the application's scene (required) */
    r8_u8 method;      /* R8_VIS_* */
    r8_u8 shading;     /* R8_SHADE_* */
    r8_u8 cull;        /* R8_CULL_* */
    r8_u8 format;      /* R8_FMT_* */
    r8_s16 width, height;
    r8_s16 band;       /* band height in rows (multiple of 8 for PAGE1) */
    r8_u8 clip;        /* polygons the clipper may make per frame (near
                          plane, guard band); more are dropped and counted */
    r8_u8 pool;        /* scan states kept from band to band (faces that
                          cross a band boundary); 0: every band seeks
                          its faces again (least RAM, more cycles) */
    r8_u8 wire;        /* 1: wireframe, the edges of the faces the method
                          keeps (docs/pipeline.md "Lines and circles");
                          ignored by a build with R8_NO_WIRE */
    r8_u8 texfilter;   /* R8_TEXF_* (R8_SHADE_TEXTURE) */
    r8_u8 persp;       /* R8_SHADE_TEXTURE: 0 affine texture mapping, or
                          perspective-correct u, v every `persp` pixels
                          of a span (2..64), affine between */
} r8_render_cfg;

/* Defaults: no scene, cull only, Lambert, normal cull, PAGE1 128x64,
 * band 8, clip 8, pool R8_POOL_AUTO, no wireframe,
 * nearest texel, affine. */
#define R8_POOL_AUTO 255   /* as many scan states as help (up to 24) */
void r8_render_defaults(r8_render_cfg *cfg);

/* Method name ("cull", "zbuf16", ...); 0 when out of range.
 * r8_method_by_name returns -1 for an unknown name. */
const char *r8_method_name(r8_u8 method);
int r8_method_by_name(const char *name);

/* Work memory (bytes) r8_render_init needs for cfg: vertices, face lists
 * and depth memory.  The band buffer itself is not included. */
unsigned r8_render_ram(const r8_render_cfg *cfg);

typedef struct r8_render {
    r8_render_cfg cfg;
    r8_u8 *work;
    unsigned work_size;
    void *state;       /* points into work */
} r8_render;

/* Counters of the last frame (r8_render_stats). */
typedef struct r8_render_stats {
    r8_u16 faces;      /* faces set up (in front, in view) */
    r8_u16 clipped;    /* of which went through the clipper */
    r8_u16 dropped;    /* polygons lost: clip budget or S-buffer pool full */
} r8_render_stats;

/* 0 on success; -1 if cfg is invalid, -2 if work is too small. */
int r8_render_init(r8_render *r, const r8_render_cfg *cfg, r8_u8 *work,
                   unsigned work_size);
/* Set up a frame from the scene's current poses seen by cam: transform
 * every vertex once, cull, clip, sort. */
void r8_render_frame(r8_render *r, const r8_camera *cam);
/* Clear the band and draw every face's rows inside it.  Bands go top
 * to bottom, each once per frame. */
void r8_render_band(r8_render *r, r8_fb *band);
void r8_render_stats_get(const r8_render *r, r8_render_stats *s);

/* ---- the analyser: no more than a scene needs ---- */

#define R8_WHY_CONVEX 1      /* one convex mesh: backface cull is exact */
#define R8_WHY_SORTABLE 2    /* convex objects apart in depth: painter's is exact */
#define R8_WHY_OVERLAP 3     /* non-convex or interpenetrating: z-buffer */
#define R8_WHY_USER 4        /* method given by the user */
#define R8_WHY_RAM 5         /* exact method does not fit; best that fits */
#define R8_WHY_GRID 6        /* a grid map: the ray caster draws it */
#define R8_WHY_PORTALS 7     /* sectors and portals: the portal renderer */
#define R8_WHY_BSP 8         /* non-convex meshes with BSP trees, apart in
                                depth: BSP order is exact, no depth memory */

typedef struct r8_analysis {
    r8_u8 method;       /* chosen visibility method */
    r8_u8 why;          /* R8_WHY_* */
    r8_s16 band;        /* chosen band height (rows) */
    r8_u8 pool;         /* chosen scan-state pool */
    unsigned ram;       /* r8_render_ram + band buffer at that choice */
    r8_s32 znear, zfar; /* depth range the scene can occupy (world units):
                           a tight camera znear/zfar for the depth methods */
    r8_u8 coord_bits;   /* bits a camera-space coordinate needs (with sign) */
    r8_u8 exact;        /* 1 if the method is exact for this scene */
} r8_analysis;

/* What the application promises about its camera, for the analyser. */
#define R8_BOUND_FIXED 0   /* the camera stays as given */
#define R8_BOUND_BOX 1     /* it moves inside the box lo..hi (world units),
                              its rotation stays as given */
#define R8_BOUND_ANY 2     /* anything: only choices exact everywhere */
typedef struct r8_bound {
    r8_u8 kind;
    r8_s16 lo[3], hi[3];
} r8_bound;

/* Choose for cfg's scene, seen from cam moving within bound (0: FIXED):
 * the cheapest exact visibility method (unless cfg->method is a real
 * method: then it is kept), and the largest band height (then pool)
 * whose renderer work memory plus band buffer fits `budget` bytes
 * (unless cfg->band > 0 is given and fits).  Objects are taken at their
 * current positions (they may turn about them).  Writes the choice into
 * cfg and a report into a.  Returns 0, or -1 if nothing fits. */
int r8_analyse(r8_render_cfg *cfg, const r8_camera *cam, const r8_bound *bound,
               unsigned budget, r8_analysis *a);

#endif
