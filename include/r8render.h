/* r8render.h - the frame renderer: scene -> transform -> cull and clip
 * -> scan convert -> visibility -> framebuffer band.
 *
 * Usage (the same on the host emulator and on every target):
 *   r8_render_cfg cfg;  r8_render_defaults(&cfg); cfg.scene = ...;
 *   need = r8_render_ram(&cfg);           work memory in bytes
 *   r8_render_init(&r, &cfg, work, sizeof work);
 *   per frame:  r8_render_frame(&r, frame_no);       transform once
 *               for each band: r8_fb_set_band(&fb, y0); r8_render_band(&r, &fb);
 * All memory is the caller's: `work` holds vertices, face lists and
 * depth memory; the band buffer is the caller's r8_fb.
 */
#ifndef R8RENDER_H
#define R8RENDER_H

#include "r8types.h"
#include "r8fb.h"

struct r8_scene;

/* Visibility methods (see docs/visibility.md). */
#define R8_VIS_CULL 0      /* backface cull only: exact for one convex mesh */
#define R8_VIS_PAINTER 1   /* painter's, faces jeffsorted by depth */
#define R8_VIS_Z8 2        /* full z-buffer, 8-bit depth */
#define R8_VIS_Z16 3       /* full z-buffer, 16-bit depth */
#define R8_VIS_BLOCK 4     /* seed's 4x4-block z-buffer, one compare per block */
#define R8_VIS_BLOCKMASK 5 /* 4x4-block z with a coverage mask per block */
#define R8_VIS_SBUF 6      /* S-buffer: depth-clipped spans per scanline */
#define R8_VIS_COUNT 7
#define R8_VIS_AUTO 255    /* let the analyser choose */

/* Shading. */
#define R8_SHADE_FLAT 0    /* the face's own colour */
#define R8_SHADE_LAMBERT 1 /* light . face normal, per face */
#define R8_SHADE_GOURAUD 2 /* light . vertex normal, interpolated */

/* Backface cull. */
#define R8_CULL_NORMAL 0   /* before projection, from the face normal */
#define R8_CULL_JUDD 1     /* during scan conversion, by screen winding */

typedef struct r8_render_cfg {
    r8_u8 scene;       /* R8_SCENE_* (r8scene.h) */
    r8_u8 method;      /* R8_VIS_* */
    r8_u8 shading;     /* R8_SHADE_* */
    r8_u8 cull;        /* R8_CULL_* */
    r8_u8 format;      /* R8_FMT_* */
    r8_s16 width, height;
    r8_s16 band;       /* band height in rows (multiple of 8 for PAGE1) */
    const struct r8_scene *custom; /* 0: built-in `scene`; else render this
                                      caller-owned scene (tools, tests) */
} r8_render_cfg;

/* Built-in scenes. */
#define R8_SCENE_CUBE 0        /* the rotating cube (one convex mesh) */
#define R8_SCENE_TORUS 1       /* ~200-face torus */
#define R8_SCENE_TEAPOT 2      /* ~240-face teapot-class model */
#define R8_SCENE_TERRAIN 3     /* seed's fractal terrain */
#define R8_SCENE_WALL 4        /* seed's wall-and-pillar case */
#define R8_SCENE_CROSS 5       /* two interpenetrating objects */
#define R8_SCENE_SEPARATE 6    /* several separate objects */
#define R8_SCENE_COUNT 7

/* Defaults: cube, cull only, Lambert, normal cull, PAGE1 128x64, band 8,
 * no custom scene. */
void r8_render_defaults(r8_render_cfg *cfg);

/* The scene cfg renders: cfg->custom if set, else built-in cfg->scene. */
const struct r8_scene *r8_render_scene(const r8_render_cfg *cfg);

/* Scene and method names ("cube", "zbuf16", ...); 0 when out of range.
 * r8_*_by_name return -1 for an unknown name. */
const char *r8_scene_name(r8_u8 scene);
const char *r8_method_name(r8_u8 method);
int r8_scene_by_name(const char *name);
int r8_method_by_name(const char *name);

/* Work memory (bytes) r8_render_init needs for cfg: vertices, face lists
 * and depth memory.  The band buffer itself is not included. */
unsigned r8_render_ram(const r8_render_cfg *cfg);

typedef struct r8_render {
    r8_render_cfg cfg;
    r8_u8 *work;
    unsigned work_size;
    r8_u16 frame;
    void *state;       /* points into work */
} r8_render;

/* 0 on success; -1 if cfg is invalid, -2 if work is too small. */
int r8_render_init(r8_render *r, const r8_render_cfg *cfg, r8_u8 *work,
                   unsigned work_size);
/* Set up frame `frame` (animation angle from it): transform once. */
void r8_render_frame(r8_render *r, r8_u16 frame);
/* Clear the band and draw every face's rows inside it. */
void r8_render_band(r8_render *r, r8_fb *band);

/* ---- the analyser: no more than a scene needs ---- */

#define R8_WHY_CONVEX 1      /* one convex mesh: backface cull is exact */
#define R8_WHY_SORTABLE 2    /* convex objects apart in depth: painter's is exact */
#define R8_WHY_OVERLAP 3     /* non-convex or interpenetrating: z-buffer */
#define R8_WHY_USER 4        /* method given by the user */
#define R8_WHY_RAM 5         /* exact method does not fit; best that fits */

typedef struct r8_analysis {
    r8_u8 method;       /* chosen visibility method */
    r8_u8 why;          /* R8_WHY_* */
    r8_s16 band;        /* chosen band height (rows) */
    unsigned ram;       /* r8_render_ram + band buffer at that choice */
    r8_s32 znear, zfar; /* camera-space depth range from the scene's extents */
    r8_u8 coord_bits;   /* bits a camera-space coordinate needs (with sign) */
    r8_u8 exact;        /* 1 if the method is exact for this scene */
} r8_analysis;

/* Choose for cfg's scene: the cheapest exact visibility method (unless
 * cfg->method is a real method: then it is kept), and the largest band
 * height whose renderer work memory plus band buffer fits `budget`
 * bytes (unless cfg->band > 0 is given and fits).  Writes the choice
 * into cfg and a report into a.  Returns 0, or -1 if nothing fits. */
int r8_analyse(r8_render_cfg *cfg, unsigned budget, r8_analysis *a);

#endif
