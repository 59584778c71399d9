/* r8int.h - private structures shared by the renderer's source files.
 * Everything lives in the caller's work memory (r8_render_init). */
#ifndef R8INT_H
#define R8INT_H

#include "r8render.h"
#include "r8scene.h"
#include "r8raster.h"
#include "r8fixed.h"

#define R8_CLIP_VERTS 48    /* at most this many vertices made by clipping per frame */
#define R8_MAX_CLIP_POLY (R8_MAX_FACE_VERTS + 5)
#define R8_SCAN_POOL 24     /* persistent scan states (more: seeked per band) */
#define R8_JEFF_BUCKETS 64  /* painter's depth buckets */
#define R8_NO_SLOT 0xFF

/* outcodes */
#define R8_OUT_LEFT 1
#define R8_OUT_RIGHT 2
#define R8_OUT_TOP 4
#define R8_OUT_BOTTOM 8
#define R8_OUT_NEAR 16
#define R8_OUT_GUARD 32

typedef struct r8_objx {
    r8_mat3 m;          /* this frame's rotation */
    r8_vec3 light;      /* light direction in model space, Q1.14 */
    r8_vec3l eye;       /* camera position in model space */
    r8_u16 vbase;       /* first screen vertex of this object */
    r8_u16 fbase;       /* first face normal of this object */
} r8_objx;

typedef struct r8_poly {
    r8_u16 idx;         /* first index in the index pool */
    r8_u8 n;            /* vertex count */
    r8_u8 shade;        /* flat/Lambert level 0..16 */
    r8_u8 key;          /* painter's depth bucket: 0 = far */
    r8_u8 slot;         /* persistent scan state, or R8_NO_SLOT */
    r8_s16 ytop, ybot;  /* rows [ytop, ybot) */
} r8_poly;

/* S-buffer span node */
typedef struct r8_snode {
    r8_s16 x0, x1;      /* pixels [x0, x1) */
    r8_s32 d;           /* depth at x0, 16.16 */
    r8_s32 dd;          /* depth step per pixel, 16.16 */
    r8_s16 s, ds;       /* Gouraud shade at x0 (8.8) and step (8.8 per px, rounded) */
    r8_u8 shade;        /* flat level */
    r8_u16 next;        /* next node in the row, 0xFFFF = end */
} r8_snode;

typedef struct r8_state {
    const r8_scene *scene;
    r8_camera cam;
    r8_s32 dc1, dc2;    /* depth = dc1 / z - dc2 */
    r8_u16 nverts, nfaces, maxidx, nclip;
    r8_u8 attrs;        /* R8_ATTR_* the method and shading need */
    r8_u8 need_depth;   /* vertex depth needed (all but cull only) */
    void *clipbuf;      /* r8_clip_bytes(): the clipper's two polygons */
    r8_objx *obj;
    r8_svert *sv;       /* nverts + nclip */
    r8_u8 *out;         /* nverts outcodes */
    r8_vec3 *fnorm;     /* nfaces model-space unit normals */
    r8_vec3 *vnorm;     /* nverts vertex normals (Gouraud only) */
    r8_poly *poly;      /* nfaces */
    r8_u16 *idx;        /* maxidx */
    r8_u16 *order;      /* nfaces: drawing order */
    r8_u16 *jeff;       /* R8_JEFF_BUCKETS counts (painter) */
    r8_scan *pool;      /* R8_SCAN_POOL (or fewer) */
    r8_u8 npool;
    r8_u8 *depth;       /* the method's depth memory for one band */
    unsigned depth_bytes;
    r8_snode *snode;    /* S-buffer nodes */
    r8_u16 *shead;      /* S-buffer row heads, band rows */
    r8_u16 nsnode, sused;
    r8_u16 npoly, nsv, nidx;
    /* counters for the last frame (stability reports) */
    r8_u16 dropped;     /* faces dropped: clip or span pool exhausted */
} r8_state;

/* transform.c */
void r8_tf_objects(r8_state *st, r8_u16 frame);
void r8_tf_vertices(r8_state *st);
r8_s16 r8_tf_depth(const r8_state *st, r8_s32 z);
r8_s16 r8_tf_shade(const r8_state *st, const r8_vec3 *n, const r8_vec3 *light, r8_u8 colour);
/* cull.c */
void r8_cull_normals(r8_state *st);
int r8_cull_front(const r8_state *st, const r8_objx *o, const r8_mesh *me, r8_u16 f);
/* clip.c */
unsigned r8_clip_bytes(void);
int r8_clip_face(r8_state *st, const r8_objx *o, const r8_object *ob,
                 const r8_face *fc, r8_poly *p);
/* vis_painter.c */
void r8_jeffsort(r8_state *st);
/* vis_zbuf.c, vis_sbuf.c: draw one span of polygon p */
r8_u8 r8_vis_level(r8_s16 s);
void r8_vis_plain(r8_state *st, r8_fb *fb, const r8_poly *p, const r8_span *sp);
void r8_vis_zbuf(r8_state *st, r8_fb *fb, const r8_poly *p, const r8_span *sp, int bits16);
void r8_vis_block(r8_state *st, r8_fb *fb, const r8_poly *p, const r8_span *sp, int mask);
void r8_vis_sbuf_insert(r8_state *st, r8_fb *fb, const r8_poly *p, const r8_span *sp);
void r8_vis_sbuf_flush(r8_state *st, r8_fb *fb);
unsigned r8_vis_depth_bytes(const r8_render_cfg *cfg);
r8_u16 r8_vis_sbuf_nodes(const r8_render_cfg *cfg);

#endif
