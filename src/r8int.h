/* r8int.h - private structures shared by the renderer's source files.
 * Everything lives in the caller's work memory (r8_render_init). */
#ifndef R8INT_H
#define R8INT_H

#include "r8render.h"
#include "r8scene.h"
#include "r8raster.h"
#include "r8fixed.h"
#include "r8flash.h"

#define R8_MAX_CLIP_POLY (R8_MAX_FACE_VERTS + 5)  /* 5 planes add <= 5 */
#define R8_POOL_MAX 24      /* persistent scan states at most */
#define R8_JEFF_BUCKETS 64  /* painter's depth buckets */
#define R8_NO_SLOT 0xFF

/* A face id: mesh faces of all objects first (object i's face f is
 * fbase_i + f), then the clipper's polygons.  The link type is 16 bits;
 * -DR8_SMALL_SCENE makes it 8 bits (at most 254 faces and clipped
 * polygons per scene: the 2 KB parts). */
#ifdef R8_SMALL_SCENE
typedef r8_u8 r8_fid;
#define R8_FID_END 0xFFu
#else
typedef r8_u16 r8_fid;
#define R8_FID_END 0xFFFFu
#endif

/* A method or shading left out (r8config.h) is refused by cfg_valid, so
 * these tests fold to 0 and the code behind them drops out: R8_DEPTH, a
 * method with depth memory and vertex depth (z-buffers, blocks,
 * S-buffer).  R8_W_* (0 or 1) guard statements with #if (cc65 calls an
 * if (0) unreachable code).  A sizing build (R8_PLAN_ONLY) plans every
 * method. */
#if defined(R8_NO_PAINTER) && !defined(R8_PLAN_ONLY)
#define R8_PAINTER(m) 0
#define R8_W_PAINTER 0
#else
#define R8_PAINTER(m) ((m) == R8_VIS_PAINTER)
#define R8_W_PAINTER 1
#endif
#if defined(R8_NO_SBUF) && !defined(R8_PLAN_ONLY)
#define R8_SBUF(m) 0
#define R8_W_SBUF 0
#else
#define R8_SBUF(m) ((m) == R8_VIS_SBUF)
#define R8_W_SBUF 1
#endif
#if defined(R8_NO_ZBUF) && defined(R8_NO_BLOCK) && defined(R8_NO_SBUF) && !defined(R8_PLAN_ONLY)
#define R8_DEPTH(m) 0
#define R8_W_DEPTH 0
#else
#define R8_DEPTH(m) ((m) >= R8_VIS_Z8)
#define R8_W_DEPTH 1
#endif
#if defined(R8_NO_GOURAUD) && !defined(R8_PLAN_ONLY)
#define R8_GOURAUD(s) 0
#define R8_W_GOURAUD 0
#else
#define R8_GOURAUD(s) ((s) == R8_SHADE_GOURAUD)
#define R8_W_GOURAUD 1
#endif
/* (texture mapping changes r8_mesh: left out, also from a sizing build) */
#if defined(R8_NO_TEXTURE)
#define R8_TEXTURED(s) 0
#define R8_W_TEXTURE 0
#else
#define R8_TEXTURED(s) ((s) == R8_SHADE_TEXTURE)
#define R8_W_TEXTURE 1
#endif
/* st->vsh: 2 r8_s16 per screen vertex, or 4 with depth or shade */
#if R8_W_DEPTH || R8_W_GOURAUD || R8_W_TEXTURE
#define R8_VSH(st) ((st)->vsh)
#else
#define R8_VSH(st) 1
#endif

/* Screen vertex array: 2 r8_s16 (x, y in 12.4) per vertex, or 4 (x, y,
 * depth, shade) for the depth methods and Gouraud.  x == R8_VX_CLIP
 * marks a vertex behind the near plane or outside the guard band: its
 * faces go through the clipper. */
#define R8_VX_CLIP (-32767 - 1)
/* x == R8_VX_TODO: not transformed yet this frame (normal cull: only the
 * vertices of front faces are, as the faces come). */
#define R8_VX_TODO (-32767)

typedef struct r8_objx {
    r8_mat3 m;          /* model -> camera rotation this frame */
    r8_vec3l t;         /* model origin in camera space (<< R8_CFRAC) */
    r8_vec3l eye;       /* camera in model space (<< R8_CFRAC) */
    r8_u8 eye16;        /* |eye| components <= 16383: 16-bit cull */
    r8_vec3 light;      /* light direction in model space, Q1.14 */
    const r8_s16 *normals;  /* face normals: the mesh's (flash) or work memory */
    r8_u8 nflash;       /* normals are R8_FLASH data */
    r8_u8 hidden;
    r8_u16 vbase;       /* first screen vertex of this object */
    r8_u16 fbase;       /* first face id of this object */
} r8_objx;

/* A vertex in the clipper (clip.c): camera space, << R8_CFRAC >> the
 * polygon's shift; Gouraud shade; the screen vertex it came from or
 * 0xFFFF.  The clipper works on two polygons of these. */
typedef struct r8_clipv {
    r8_s32 x, y, z;
    r8_s16 s;
    r8_u16 src;
    r8_s16 u, v;        /* texture coordinates (8.8 texels); kept in builds
                           without textures too, so clip.c and render.c
                           agree on R8_CLIP_BYTES whatever the flags */
} r8_clipv;
#define R8_CLIP_BYTES (2u * R8_MAX_CLIP_POLY * (unsigned)sizeof(r8_clipv))

/* A polygon made by the clipper: its vertices (some appended to the
 * vertex array) and its shade level. */
typedef struct r8_cpoly {
    r8_u16 idx[R8_MAX_CLIP_POLY];
    r8_u8 n;
    r8_u8 level;
} r8_cpoly;

/* A face being scanned: its level, then the scan state (edges only on
 * the fast path, edges and attributes otherwise; the scan state starts
 * with the polygon's vertex pointers). */
typedef struct r8_actx {
    r8_u8 level;
    r8_u8 used;         /* a pool entry in use */
    r8_scanx c;
} r8_actx;
typedef struct r8_act {
    r8_u8 level;
    r8_u8 used;
    r8_scan s;
} r8_act;
/* the fields both entry kinds share, at the same place (r8_scan starts
 * with its r8_scanx) */
typedef struct r8_acthead {
    r8_u8 level;
    r8_u8 used;
    r8_scanx c;
} r8_acthead;

/* A textured face being scanned (texture.c): the scan with attributes
 * over the face's own corner records x, y (12.4), u, v (8.8 texels), so
 * the depth and shade interpolators carry u and v; the texture, and for
 * perspective correction the planes of u q, v q and q (q = 1/z scaled
 * to the face's nearest corner, Q14) over the screen, 12 fraction bits
 * per subpixel. */
#define R8_CUV_STRIDE (2u * R8_MAX_CLIP_POLY + 1u)
typedef struct r8_tact {
    r8_u8 level;
    r8_u8 used;
    r8_scan s;
    r8_s16 cv[4 * R8_SCAN_MAXV];
    const r8_texture *tex;
    r8_s16 px, py;      /* plane origin (12.4) */
    r8_s32 p0[3], pa[3], pb[3];  /* value << 12 there, d/dx, d/dy */
} r8_tact;

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
    r8_proj cam;
    r8_s16 width, height;
    r8_u16 nverts, nfaces;
    r8_u8 attrs;        /* R8_ATTR_* the method and shading need */
    r8_u8 vsh;          /* log2 of r8_s16 per screen vertex: 1 or 2 */
    r8_u8 fast;         /* cull/painter, flat/Lambert: the fused fill */
    r8_u8 judd;
    r8_u8 method, shading;
    r8_s16 bsh;         /* log2 band height, or -1 (not a power of two) */
    r8_u16 nbands;
    r8_objx *obj;
    r8_s16 *sv;         /* screen vertices (nverts + clip vertices) */
    r8_s16 *vnorm;      /* Gouraud: unit vertex normals, 3 per vertex */
    r8_fid *next;       /* draw-order links, per face id */
    r8_fid *heads;      /* buckets: per band, or painter's depth (frame
                           time only) */
    r8_u16 nheads;
    r8_u16 first;       /* painter's: the draw list; else the faces that
                           go on from the band above (an r8_fid; 16 bits
                           so the layout is the same with R8_SMALL_SCENE) */
    r8_u8 *slot;        /* pool slot per face id (0 when there is no pool) */
    r8_u8 *ftop;        /* painter's with a pool: first band per face id */
    r8_u8 *pool;        /* pool entries (r8_actx or r8_act) */
    r8_u8 *tmp;         /* one entry for faces without a slot */
    unsigned esize;     /* bytes per entry */
    r8_u8 npool;
    r8_u8 pool_used;
    r8_u8 pool_free;    /* first free pool entry (R8_NO_SLOT: none); a free
                           entry's level byte links the next */
    r8_cpoly *cpoly;    /* clipper polygons */
    r8_u8 nclip, nclipped;
    r8_u16 sv_used;     /* vertices in sv, clip vertices included */
    r8_u16 sv_cap;
    void *clipbuf;      /* the clipper's two polygons (frame time only) */
    /* depth mapping: depth = ((W - wf) * gh + 2^15) >> 16 with W = zn/z
     * in Q20 (zn = camera znear, zf = zfar) */
    r8_s16 znm;         /* camera znear (<< R8_CFRAC) normalised ... */
    r8_s8 zne;          /* ... znear = znm * 2^zne */
    r8_u32 wf, gh;
    r8_s32 zn16, zf16;  /* znear, zfar << R8_CFRAC */
    r8_u32 kmul, kmul3; /* painter's keys: (z - zn16) * kmul >> 16 over
                           zn16..zf16 in 64 buckets; kmul3 for z sums of 3 */
    r8_u8 *depth;       /* the method's depth memory for one band */
    unsigned depth_bytes;
    r8_u8 zx[2];        /* 16-bit z-buffer, width <= 255: the columns */
                        /* [zx[0], zx[1]) hold every depth written since */
                        /* the last clear (r8_render_band clears those); */
                        /* 0, 255: unknown, the whole band is cleared */
    r8_snode *snode;    /* S-buffer nodes */
    r8_u16 *shead;      /* S-buffer row heads, band rows */
    r8_u16 nsnode, sused;
    r8_u16 npoly;       /* faces set up this frame */
    r8_u16 dropped;     /* polygons lost: clip budget, S-buffer pool */
#if R8_W_TEXTURE
    /* last, so a build without textures (firmware sources compiled with
     * R8_NO_TEXTURE beside library objects compiled without it) keeps
     * every other member where it was */
    r8_s16 *cuv;        /* textures: per clipper polygon R8_CUV_STRIDE
                           r8_s16: u, v of its corners, its object */
    r8_u8 texfilter, persp;
#endif
} r8_state;

/* render.c */
void r8_bucket_object(r8_render *r, r8_u8 i);
#ifndef R8_NO_WIRE
/* face id g's vertex pointers into vp; returns its vertex count */
r8_u8 r8_face_vp(const r8_state *st, r8_fid g, const r8_s16 **vp);
/* wireframe.c: r8_render_band with cfg.wire */
void r8_wire_band(r8_render *r, r8_fb *fb);
#endif
/* transform.c */
void r8_tf_frame(r8_state *st, const r8_camera *cam);
void r8_tf_vertices(r8_state *st, int lazy);
void r8_tf_vertex(r8_state *st, const r8_objx *o, const r8_s16 *mv, r8_u16 g);
r8_s16 r8_tf_depth(const r8_state *st, r8_u16 m, r8_s8 e);
r8_s16 r8_tf_shade(const r8_state *st, const r8_vec3 *n, const r8_vec3 *light, r8_u8 colour);
void r8_tf_camera(const r8_vec3l *c, r8_state *st, r8_u16 g);
/* cull.c */
void r8_cull_normals(const r8_mesh *me, r8_s16 *out);
int r8_cull_front(const r8_objx *o, const r8_s16 *v0, r8_u16 f);
r8_u8 r8_face_level(const r8_state *st, const r8_objx *o, const r8_object *ob, r8_u16 f);
/* clip.c */
int r8_clip_face(r8_state *st, const r8_objx *o, const r8_object *ob, r8_u16 f,
                 const r8_u8 *vi, r8_u8 n, r8_cpoly *cp, r8_s32 *zsum);
/* vis_zbuf.c, vis_sbuf.c: draw one span of a face at `level` */
r8_u8 r8_vis_level(r8_s16 s);
void r8_vis_plain(r8_state *st, r8_fb *fb, r8_u8 level, const r8_span *sp);
void r8_vis_zbuf(r8_state *st, r8_fb *fb, r8_u8 level, const r8_span *sp, int bits16);
/* The z-buffer's fast path (flat and Lambert shading, page layout): the
 * rows < ylimit of a face filled straight from its edges, the same
 * pixels and depths as r8_scan_next + r8_vis_zbuf, without a span
 * record or a division per span. */
void r8_zfill(r8_state *st, r8_act *a, r8_s16 ylimit, r8_fb *fb, int bits16);
/* The 16-bit z-buffer of width w (<= 255, band rows): before a band
 * (of fb) r8_zclear clears the columns st->zx, after it r8_zkeep adds
 * the kernel's (r8zrows.h) to st->zx. */
void r8_zclear(r8_state *st, const r8_fb *fb, r8_u16 w, r8_u16 band);
void r8_zkeep(r8_state *st);
void r8_vis_block(r8_state *st, r8_fb *fb, r8_u8 level, r8_u8 id, const r8_span *sp, int mask);
void r8_vis_sbuf_insert(r8_state *st, r8_fb *fb, r8_u8 level, const r8_span *sp);
void r8_vis_sbuf_flush(r8_state *st, r8_fb *fb);
unsigned r8_vis_depth_bytes(const r8_render_cfg *cfg);
/* vis_bsp.c: BSP order.  r8_render_ram / r8_render_init hand R8_VIS_BSP
 * here; it plans and sets up painter's (whose draw list it fills in tree
 * order) behind the walk's own block at the start of work memory (so
 * r8_state is the same with and without BSP). */
unsigned r8_bsp_ram(const r8_render_cfg *cfg);
int r8_bsp_init(r8_render *r, const r8_render_cfg *cfg, r8_u8 *work, unsigned work_size);
void r8_bsp_begin(r8_render *r, const r8_mesh *me);
r8_u16 r8_bsp_next(r8_render *r, const r8_objx *o, const r8_mesh *me);
void r8_bsp_frame(r8_render *r);
/* texture.c: set up textured face g (object oi, 255: clipper polygon
 * g - nfaces) whose scan t->s.c.vp[0..n) face_setup has set; draw its
 * rows < ylimit */
void r8_tex_face(r8_state *st, r8_tact *t, r8_u16 g, r8_u8 oi, r8_u8 n);
void r8_tex_draw(r8_state *st, r8_tact *t, r8_s16 ylimit, r8_fb *fb);
r8_u16 r8_vis_sbuf_nodes(const r8_render_cfg *cfg);

/* floor(65536 / n) for n = 2..256, in flash (vis_zbuf.c): the quotients
 * of a u16 by n = 1..256 as a product and one correction */
extern const r8_u16 r8_rcp256[257] R8_FLASH;

#endif
