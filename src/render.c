/* render.c - the frame renderer.
 *
 * Per frame (r8_render_frame): transform every vertex once; then every
 * face: cull, trivial reject, clip if it needs it, and put it in a
 * bucket - by the band its first row falls in (cull only, depth
 * methods), or by depth (painter's, far to near: the seed's jeffsort as
 * linked buckets, chained into one draw list).  Every bucket lists its
 * faces in scene order.
 *
 * Per band (r8_render_band): clear the band and its depth memory, then
 * draw its faces: a face is scanned from where it left off (its scan
 * state kept in a small pool between bands) or, without a pooled state,
 * seeked to the band's first row (the same spans: scan.c).  Painter's
 * walks the draw list, skipping faces that start lower down and dropping
 * finished ones.  The other methods merge, in scene order, the faces
 * that go on from the band above with the band's own bucket: a band
 * touches only the faces that cross it, in the order a whole-frame
 * renderer would draw them.
 *
 * Memory is the caller's `work`; it grows with the vertices and faces of
 * the scene (2 bytes per vertex for x and y, 1-2 per face for the list
 * link) and with the scan states kept (cfg.pool), not with the faces on
 * screen. */
#include <stddef.h>
#include <string.h>
#include "r8int.h"
#include "r8ray.h"
#include "r8portal.h"
#include "r8kern.h"
#include "r8zrows.h"

/* Only the fused scan-and-fill (cull, painter's; flat, Lambert) is
 * built when every method and shading that needs depth or shade along
 * the spans is left out. */
#if defined(R8_NO_ZBUF) && defined(R8_NO_BLOCK) && defined(R8_NO_SBUF) && defined(R8_NO_GOURAUD)
#define R8_FAST_ONLY 1
#endif

/* AVR, the fused fill alone into page-1 bands: a face's band goes
 * straight to r8k_scanband (src/r8scan.h; ports/avr/trap.S), and a
 * mesh face starts with its vertex pointers, rows and top vertex found
 * in one pass (face_begin), without r8_scanx_fill and r8_scanx_begin
 * in between (the same rows: scan.c). */
/* The Z80 too with its r8k_scanband (R8_ASM_SCANFILL: ports/z80/
 * scanband_z80.s; the C reference, src/scanband.c, is slower than
 * r8_scanx_fill there). */
#if (defined(__AVR__) || (defined(__SDCC) && defined(R8_ASM_SCANFILL))) && defined(R8_FAST_ONLY) && \
    defined(R8_PAGE1_ONLY) && !R8_W_TEXTURE
#define R8_BANDK 1
#include "r8scan.h"
#endif

#if R8_W_TEXTURE
#define R8_SHADE_MAX R8_SHADE_TEXTURE
#else
#define R8_SHADE_MAX R8_SHADE_GOURAUD
#endif

/* A firmware whose configuration is fixed at compile time (the demo
 * firmware, examples/spin/fw_app.c: R8_CFG_METHOD with R8_CFG_SHADING,
 * _CULL, _FORMAT, _WIDTH, _HEIGHT, _BAND, _CLIP, _POOL): cfg_valid takes
 * that configuration only, and the plan and set-up fold to constants.
 * Without R8_CFG_METHOD (the library) every field is read and checked. */
#ifdef R8_CFG_METHOD
#define CFG_METHOD(c) R8_CFG_METHOD
#define CFG_SHADING(c) R8_CFG_SHADING
#define CFG_CULL(c) R8_CFG_CULL
#define CFG_FORMAT(c) R8_CFG_FORMAT
#define CFG_WIDTH(c) R8_CFG_WIDTH
#define CFG_HEIGHT(c) R8_CFG_HEIGHT
#define CFG_BAND(c) R8_CFG_BAND
#define CFG_CLIP(c) R8_CFG_CLIP
#define CFG_POOL(c) R8_CFG_POOL
#else
#define CFG_METHOD(c) ((c)->method)
#define CFG_SHADING(c) ((c)->shading)
#define CFG_CULL(c) ((c)->cull)
#define CFG_FORMAT(c) ((c)->format)
#define CFG_WIDTH(c) ((c)->width)
#define CFG_HEIGHT(c) ((c)->height)
#define CFG_BAND(c) ((c)->band)
#define CFG_CLIP(c) ((c)->clip)
#define CFG_POOL(c) ((c)->pool)
#endif
/* R8_VSH1: a build whose screen vertices are always 2 r8_s16 (r8int.h:
 * R8_VSH(st) is 1): one branch of the vertex pointer code */
#if !(R8_W_DEPTH || R8_W_GOURAUD || R8_W_TEXTURE)
#define R8_VSH1 1
#endif
/* and, with the normal cull and no clipper, every face draw_face meets
 * is a mesh face whose rows start at the band's first row or below (no
 * Judd test): r8k_scanband alone, without r8_scanx_fill (R8_BANDK_ONLY;
 * r8_scanx_begin stays for the clipped polygons' branch: without it the
 * painter's band loop is 0.5% slower) */
#if defined(R8_BANDK) && defined(R8_CFG_CULL) && defined(R8_NO_CLIP)
#if R8_CFG_CULL == R8_CULL_NORMAL
#define R8_BANDK_ONLY 1
#endif
#endif

void r8_render_defaults(r8_render_cfg *cfg)
{
    cfg->scene = 0;
    cfg->method = R8_VIS_CULL;
    cfg->shading = R8_SHADE_LAMBERT;
    cfg->cull = R8_CULL_NORMAL;
    cfg->format = R8_FMT_PAGE1;
    cfg->width = 128;
    cfg->height = 64;
    cfg->band = 8;
    cfg->clip = 8;
    cfg->pool = R8_POOL_AUTO;
#ifndef R8_NO_WIRE
    cfg->wire = 0;      /* (a build without it ignores the field) */
#endif
#if R8_W_TEXTURE
    cfg->texfilter = R8_TEXF_NEAREST;
    cfg->persp = 0;
#endif
}

static const char *const method_names[] = {
    "cull", "painter", "zbuf8", "zbuf16", "block", "blockmask", "sbuf"
#ifndef R8_NO_BSP
    , "bsp"                        /* (a build without it: no name, no flash) */
#endif
};
#define R8_NAMES ((r8_u8)(sizeof method_names / sizeof method_names[0]))

static int streq(const char *a, const char *b)
{
    while (*a && *a == *b) {
        a++;
        b++;
    }
    return *a == *b;
}

const char *r8_method_name(r8_u8 method)
{
    if (method == R8_VIS_AUTO)
        return "auto";
#ifndef R8_NO_RAY
    if (method == R8_VIS_RAY)
        return "ray";
#endif
#ifndef R8_NO_PORTAL
    if (method == R8_VIS_PORTAL)
        return "portal";
#endif
    return method < R8_NAMES ? method_names[method] : 0;
}

int r8_method_by_name(const char *name)
{
    int i;
    if (streq(name, "auto"))
        return R8_VIS_AUTO;
#ifndef R8_NO_RAY
    if (streq(name, "ray"))
        return R8_VIS_RAY;
#endif
#ifndef R8_NO_PORTAL
    if (streq(name, "portal"))
        return R8_VIS_PORTAL;
#endif
    for (i = 0; i < R8_NAMES; i++)
        if (streq(name, method_names[i]))
            return i;
    return -1;
}

void r8_camera_defaults(r8_camera *c, r8_s16 width)
{
#if defined(__CC65__) || defined(__SDCC)
    /* (cc65 and sdcc: a store through c costs ~15 bytes on the 6502;
     * their null pointer is all bits zero, so clearing the bytes sets
     * position, angles, flags and m as below) */
    r8_u8 *q = (r8_u8 *)c, n;
    for (n = (r8_u8)sizeof *c; n; n--)
        *q++ = 0;
#else
    c->x = c->y = c->z = 0;
    c->yaw = c->pitch = c->roll = 0;
    c->flags = 0;
    c->m = 0;
#endif
    c->focal = width;
    c->znear = 16;
    c->zfar = 4096;
}

/* ---- which methods this build carries ---- */

static int method_built(r8_u8 m)
{
#ifdef R8_PLAN_ONLY
    return m < R8_VIS_COUNT;   /* sizing only: every method is planned */
#endif
    switch (m) {
    case R8_VIS_CULL:
        return 1;
#ifndef R8_NO_PAINTER
    case R8_VIS_PAINTER:
        return 1;
#endif
#ifndef R8_NO_ZBUF
    case R8_VIS_Z8:
    case R8_VIS_Z16:
        return 1;
#endif
#ifndef R8_NO_BLOCK
    case R8_VIS_BLOCK:
    case R8_VIS_BLOCKMASK:
        return 1;
#endif
#ifndef R8_NO_SBUF
    case R8_VIS_SBUF:
        return 1;
#endif
#if !defined(R8_NO_BSP) && !defined(R8_NO_PAINTER)
    case R8_VIS_BSP:
        return 1;
#endif
    default:
        return 0;
    }
}

/* ---- memory plan ---- */

#define ALIGN_TO (sizeof(r8_s32) > sizeof(void *) ? sizeof(r8_s32) : sizeof(void *))

/* R8_FIXED_PLAN: the demo firmware's plan on cc65, sdcc and avr-gcc (cc65
 * and sdcc fold a constant expression but not a value that passes
 * through the plan struct; AVR cube flash -0.6 KB with app.c's
 * APP_FIXED).  With the scene's sizes (R8_CFG_NVERTS, _NFACES, _NOBJ) and
 * the whole configuration fixed, the fused fill alone (cull or painter's,
 * flat or Lambert), no texture and no clipper, every field make_plan
 * computes is a constant: FP_<field> below is make_plan's arithmetic for
 * that case step by step (vsh 1, no run-time normals, no depth memory,
 * no S-buffer), and r8_render_init and r8_render_ram read those instead
 * of calling make_plan (6502 ~1 KB, Z80 ~0.6 KB).  The firmware's arena
 * (FW_RAM) is measured by the sizer (tests/targets/fw_sizes.c), which
 * runs make_plan itself: a constant plan that differed would stop the
 * firmware with APP_E_RAM (identity tests). */
#if defined(R8_CFG_NVERTS) && defined(R8_FAST_ONLY) && !R8_W_TEXTURE && !defined(R8_PLAN_ONLY) && \
    (defined(__CC65__) || defined(__SDCC) || defined(__AVR__))
#if R8_CFG_CLIP == 0
#define R8_FIXED_PLAN 1
#ifdef __CC65__
#define R8_FP_TABLES 1   /* r8_render_init's stores as tables (below; on
                            sdcc, whose stores through st are short, the
                            tables' loops cost more) */
#endif
#endif
#endif

#ifdef R8_FIXED_PLAN
/* 16-bit pointers: ALIGN_TO is sizeof(r8_s32) */
R8_CASSERT(fixed_plan_align, sizeof(void *) <= sizeof(r8_s32));
#define FP_AL ((unsigned)sizeof(r8_s32))
#define FP_A(n) ((unsigned)(((unsigned)(n) + (FP_AL - 1u)) & ~(FP_AL - 1u)))
#define FP_nverts ((r8_u16)R8_CFG_NVERTS)
#define FP_nfaces ((r8_u16)R8_CFG_NFACES)
#define FP_vsh 1                      /* no depth, Gouraud or texture */
#define FP_fast 1
#define FP_nbands ((r8_u16)((R8_CFG_HEIGHT + R8_CFG_BAND - 1u) / R8_CFG_BAND))
#if R8_W_PAINTER && R8_CFG_METHOD == R8_VIS_PAINTER
#define FP_PAINTER 1
#define FP_nheads R8_JEFF_BUCKETS
#else
#define FP_PAINTER 0
#define FP_nheads FP_nbands
#endif
#define FP_sv_cap FP_nverts           /* (no clipper: + 5 * 0) */
#define FP_NID ((unsigned)R8_CFG_NFACES)
#ifdef R8_NO_POOL
#define FP_NP0 0
#else
#define FP_NP0 R8_CFG_POOL
#endif
#if FP_NP0 > (R8_CFG_NFACES + 1) / 2
#define FP_NP1 ((R8_CFG_NFACES + 1) / 2)
#else
#define FP_NP1 FP_NP0
#endif
#if FP_NP1 > R8_POOL_MAX
#define FP_npool ((r8_u8)R8_POOL_MAX)
#else
#define FP_npool ((r8_u8)FP_NP1)
#endif
#define FP_esize FP_A(sizeof(r8_actx))
#define FP_obj 0u
#define FP_sv FP_A(sizeof(r8_objx) * R8_CFG_NOBJ)
#define FP_vnorm (FP_sv + FP_A(((unsigned)FP_sv_cap << FP_vsh) * 2u))
#define FP_norms FP_vnorm            /* (no run-time normals: 6 * 0) */
#define FP_next FP_norms
#define FP_HEADS0 (FP_next + FP_A(sizeof(r8_fid) * FP_NID))
#if R8_CFG_METHOD != R8_VIS_PAINTER
#define FP_slot (FP_HEADS0 + FP_A(sizeof(r8_fid) * FP_nbands))
#else
#define FP_slot FP_HEADS0
#endif
#if FP_NP1 > 0
#define FP_ftop (FP_slot + FP_A(FP_NID))
#else
#define FP_ftop FP_slot
#endif
#if FP_NP1 > 0 && FP_PAINTER
#define FP_cpoly (FP_ftop + FP_A(FP_NID))
#else
#define FP_cpoly FP_ftop
#endif
#define FP_REGION FP_cpoly           /* (no clipper: the clip polygons 0) */
#if FP_PAINTER                       /* the depth buckets, set-up only */
#define FP_heads FP_REGION
#define FP_clipbuf (FP_REGION + FP_A(sizeof(r8_fid) * FP_nheads))
#define FP_FRAMET FP_A(sizeof(r8_fid) * FP_nheads)
#else
#define FP_heads FP_HEADS0
#define FP_clipbuf FP_REGION
#define FP_FRAMET 0u
#endif
#define FP_tmp FP_REGION
#define FP_pool (FP_REGION + FP_esize)
#define FP_depth (FP_pool + FP_esize * FP_npool)
#define FP_snode FP_depth
#define FP_shead FP_snode
#define FP_BANDT (FP_shead - FP_REGION)
#define FP_total (FP_REGION + (FP_FRAMET > FP_BANDT ? FP_FRAMET : FP_BANDT) + \
                  FP_A(sizeof(r8_state)) + FP_AL)
#define PLV(f) FP_##f
#else
#define PLV(f) (pl.f)
static unsigned align_up(unsigned n)
{
    return (unsigned)((n + (ALIGN_TO - 1)) & ~(unsigned)(ALIGN_TO - 1));
}
#endif

typedef struct plan {
    unsigned obj, sv, ftop, cuv, vnorm, norms, next, slot, cpoly, region, heads, clipbuf,
        pool, tmp, depth, snode, shead, total;
    r8_u16 nverts, nfaces, nbands, nheads, sv_cap;
    unsigned esize;
    r8_u8 vsh, npool, fast;
} plan;

static int cfg_valid(const r8_render_cfg *cfg)
{
    const r8_scene *sc = cfg->scene;
    r8_u32 nf = 0;
    r8_u8 i;
#ifdef R8_CFG_METHOD
    if (cfg->method != R8_CFG_METHOD || cfg->shading != R8_CFG_SHADING ||
        cfg->cull != R8_CFG_CULL || cfg->format != R8_CFG_FORMAT ||
        cfg->width != R8_CFG_WIDTH || cfg->height != R8_CFG_HEIGHT ||
        cfg->band != R8_CFG_BAND || cfg->clip != R8_CFG_CLIP || cfg->pool != R8_CFG_POOL)
        return 0;      /* the one configuration this firmware is built for */
#endif
    if (!sc || sc->nobjects == 0 || !sc->objects || !method_built(CFG_METHOD(cfg)) ||
        CFG_SHADING(cfg) > R8_SHADE_MAX || CFG_CULL(cfg) > R8_CULL_JUDD ||
        CFG_FORMAT(cfg) > R8_FMT_IDX8)
        return 0;
#ifdef R8_NO_GOURAUD
    if (CFG_SHADING(cfg) == R8_SHADE_GOURAUD)
        return 0;
#endif
#ifdef R8_PAGE1_ONLY
    if (CFG_FORMAT(cfg) != R8_FMT_PAGE1)
        return 0;
#endif
#if R8_W_TEXTURE
    if (CFG_SHADING(cfg) == R8_SHADE_TEXTURE) {   /* texture.c */
        if (CFG_METHOD(cfg) > R8_VIS_PAINTER || cfg->texfilter > R8_TEXF_BILINEAR ||
            cfg->persp == 1 || cfg->persp > 64)
            return 0;
        for (i = 0; i < sc->nobjects; i++) {
            const r8_mesh *me = sc->objects[i].mesh;
            if (me && me->tex && (!me->uv || me->tex->wlog < 3 || me->tex->wlog > 6 ||
                                  me->tex->hlog < 3 || me->tex->hlog > 6 ||
                                  me->tex->format > R8_TEX_IDX8 || !me->tex->data))
                return 0;
        }
    }
#endif
    if (CFG_WIDTH(cfg) < 8 || CFG_WIDTH(cfg) > 1024 || CFG_HEIGHT(cfg) < 8 || CFG_HEIGHT(cfg) > 1024)
        return 0;
    if (CFG_BAND(cfg) < 1 || CFG_BAND(cfg) > CFG_HEIGHT(cfg))
        return 0;
    if (CFG_FORMAT(cfg) == R8_FMT_PAGE1 && ((CFG_BAND(cfg) & 7) || (CFG_HEIGHT(cfg) & 7)))
        return 0;
    if ((CFG_METHOD(cfg) == R8_VIS_BLOCK || CFG_METHOD(cfg) == R8_VIS_BLOCKMASK) &&
        ((CFG_BAND(cfg) & 3) || (CFG_HEIGHT(cfg) & 3)))
        return 0;
#ifdef R8_CFG_NVERTS
    /* The demo firmware (its scene's sizes fixed): the same checks in one
     * walk with 16-bit sums.  A sum never passes its constant (each step
     * is refused first), so it cannot wrap to it; the face ids' limit
     * is a constant too. */
    (void)nf;
#if R8_CFG_NFACES + R8_CFG_CLIP >= R8_FID_END
    (void)i;
    return 0;       /* more face ids than r8_fid holds */
#else
    if (sc->nobjects != R8_CFG_NOBJ)
        return 0;      /* the scene this firmware is built for */
    {
        r8_u16 v = 0, f = 0;
        for (i = 0; i < sc->nobjects; i++) {
            const r8_mesh *me = sc->objects[i].mesh;
            if (!me || !me->verts || !me->faces || me->nverts > 255)
                return 0;
#ifdef R8_NO_RT_NORMALS
            if (!me->normals)
                return 0;     /* this build takes meshes with their normals only */
#endif
            if (me->nverts > (r8_u16)R8_CFG_NVERTS - v || me->nfaces > (r8_u16)R8_CFG_NFACES - f)
                return 0;
            v = (r8_u16)(v + me->nverts);
            f = (r8_u16)(f + me->nfaces);
        }
        if (v != (r8_u16)R8_CFG_NVERTS || f != (r8_u16)R8_CFG_NFACES)
            return 0;
    }
    return 1;
#endif
}
#else
#ifdef R8_NO_RT_NORMALS
    for (i = 0; i < sc->nobjects; i++)
        if (sc->objects[i].mesh && !sc->objects[i].mesh->normals)
            return 0;     /* this build takes meshes with their normals only */
#endif
    for (i = 0; i < sc->nobjects; i++) {
        const r8_mesh *me = sc->objects[i].mesh;
        if (!me || !me->verts || !me->faces || me->nverts > 255)
            return 0;
        nf += me->nfaces;
    }
    if (nf + CFG_CLIP(cfg) >= (r8_u32)R8_FID_END)
        return 0;
    return 1;
}
#endif

unsigned r8_vis_depth_bytes(const r8_render_cfg *cfg)
{
    unsigned w = (unsigned)cfg->width, h = (unsigned)cfg->band;
    unsigned blocks = ((w + 3u) >> 2) * ((h + 3u) >> 2);
    switch (cfg->method) {
    case R8_VIS_Z8:
        return w * h;
    case R8_VIS_Z16:
        return 2u * w * h;
    case R8_VIS_BLOCK:
        return 2u * blocks;  /* depth + owner id */
    case R8_VIS_BLOCKMASK:
        return ((blocks + 1u) & ~1u) + 2u * blocks;
    default:
        return 0;
    }
}

r8_u16 r8_vis_sbuf_nodes(const r8_render_cfg *cfg)
{
    /* per row: one span per face that can cross it plus a split, at most
     * 32; indices are 16-bit */
    const r8_scene *sc = cfg->scene;
    unsigned per = 2, n;
    r8_u8 i;
    if (cfg->method != R8_VIS_SBUF || !sc)
        return 0;
    for (i = 0; i < sc->nobjects && per < 32u; i++)
        per += sc->objects[i].mesh->nfaces;
    if (per > 32u)
        per = 32u;
    n = (unsigned)cfg->band * per;
    return (r8_u16)(n > 0xFFF0u ? 0xFFF0u : n);
}

#ifndef R8_NO_RT_NORMALS
/* Is mesh i's normal table shared with an earlier object's? */
static int mesh_seen(const r8_scene *sc, r8_u8 i)
{
    r8_u8 j;
    for (j = 0; j < i; j++)
        if (sc->objects[j].mesh == sc->objects[i].mesh)
            return 1;
    return 0;
}
#endif

#ifndef R8_FIXED_PLAN
static void make_plan(const r8_render_cfg *cfg, plan *pl)
{
    const r8_scene *sc = cfg->scene;
    r8_u8 i;
    unsigned nv = 0, nf = 0, o = 0, nn = 0, nid, frame_t, band_t;
#ifdef R8_CFG_NVERTS
#ifndef R8_NO_RT_NORMALS
#error "R8_CFG_NVERTS: with R8_NO_RT_NORMALS only (no normals to plan)"
#endif
    nv = R8_CFG_NVERTS;        /* (cfg_valid: the scene's) */
    nf = R8_CFG_NFACES;
    i = R8_CFG_NOBJ;
    (void)sc;
#else
    for (i = 0; i < sc->nobjects; i++) {
        const r8_mesh *me = sc->objects[i].mesh;
        nv += me->nverts;
        nf += me->nfaces;
#ifndef R8_NO_RT_NORMALS       /* (else every mesh has its normals: cfg_valid) */
        if (!me->normals && !mesh_seen(sc, i))
            nn += me->nfaces;
#endif
    }
#endif
    pl->nverts = (r8_u16)nv;
    pl->nfaces = (r8_u16)nf;
    pl->vsh = (r8_u8)(R8_DEPTH(CFG_METHOD(cfg)) || R8_GOURAUD(CFG_SHADING(cfg)) ||
                      R8_TEXTURED(CFG_SHADING(cfg)) ? 2 : 1);
    pl->fast = (r8_u8)(pl->vsh == 1);
    pl->nbands = (r8_u16)(((unsigned)CFG_HEIGHT(cfg) + (unsigned)CFG_BAND(cfg) - 1u) / (unsigned)CFG_BAND(cfg));
    pl->nheads = R8_PAINTER(CFG_METHOD(cfg)) ? R8_JEFF_BUCKETS : pl->nbands;
    /* a clipped polygon adds at most 5 intersections */
    pl->sv_cap = (r8_u16)(nv + 5u * CFG_CLIP(cfg));
    nid = nf + CFG_CLIP(cfg);
#ifdef R8_NO_POOL
    pl->npool = 0;                  /* cfg->pool is taken as 0 */
#else
    pl->npool = CFG_POOL(cfg);
#endif
    if (pl->npool > (nf + 1u) / 2u)
        pl->npool = (r8_u8)((nf + 1u) / 2u);
    if (pl->npool > R8_POOL_MAX)
        pl->npool = R8_POOL_MAX;
    pl->esize = align_up(pl->fast ? sizeof(r8_actx) : sizeof(r8_act));
#if R8_W_TEXTURE
    if (R8_TEXTURED(CFG_SHADING(cfg)))
        pl->esize = align_up(sizeof(r8_tact));
#endif
    pl->obj = o; o += align_up(sizeof(r8_objx) * i);   /* (i: the objects) */
    pl->sv = o; o += align_up(((unsigned)pl->sv_cap << pl->vsh) * 2u);
    pl->vnorm = o;
#if R8_W_GOURAUD
    if (CFG_SHADING(cfg) == R8_SHADE_GOURAUD)
        o += align_up(6u * nv);
#endif
    pl->norms = o; o += align_up(6u * nn);
    pl->next = o; o += align_up(sizeof(r8_fid) * nid);
    pl->heads = o;                  /* band buckets live through the frame */
    if (CFG_METHOD(cfg) != R8_VIS_PAINTER)
        o += align_up(sizeof(r8_fid) * pl->nbands);
    pl->slot = o;
    if (pl->npool)
        o += align_up(nid);
    pl->ftop = o;         /* painter's with a pool: each face's first band */
    if (pl->npool && R8_PAINTER(CFG_METHOD(cfg)))
        o += align_up(nid);
    pl->cpoly = o; o += align_up(sizeof(r8_cpoly) * CFG_CLIP(cfg));
#if R8_W_TEXTURE
    pl->cuv = o;
    if (R8_TEXTURED(CFG_SHADING(cfg)))
        o += align_up(2u * R8_CUV_STRIDE * CFG_CLIP(cfg));
#endif
    /* One region for memory that is never live at the same time: the
     * sort buckets and the clipper's polygons (while the frame is set
     * up), then the scan states, depth memory and S-buffer (while bands
     * are drawn). */
    pl->region = o;
    pl->clipbuf = o;
    frame_t = 0;
#ifndef R8_NO_CLIP
    if (CFG_CLIP(cfg))
        frame_t = align_up(R8_CLIP_BYTES);
#endif
#if R8_W_PAINTER
    if (CFG_METHOD(cfg) == R8_VIS_PAINTER) {
        /* depth buckets: only while the frame is set up */
        pl->heads = o;
        pl->clipbuf = o + align_up(sizeof(r8_fid) * pl->nheads);
        frame_t += align_up(sizeof(r8_fid) * pl->nheads);
    }
#endif
    pl->tmp = o;
    pl->pool = o + pl->esize;
    pl->depth = pl->pool + pl->esize * pl->npool;
    pl->snode = pl->depth;
#if R8_W_DEPTH
    if (CFG_METHOD(cfg) >= R8_VIS_Z8)
        pl->snode += align_up(r8_vis_depth_bytes(cfg));
#endif
    pl->shead = pl->snode;
#if R8_W_SBUF
    if (CFG_METHOD(cfg) == R8_VIS_SBUF)
        pl->shead += align_up(sizeof(r8_snode) * r8_vis_sbuf_nodes(cfg));
#endif
    band_t = pl->shead - o;
#if R8_W_SBUF
    if (CFG_METHOD(cfg) == R8_VIS_SBUF)
        band_t += align_up(2u * (unsigned)CFG_BAND(cfg));
#endif
    o += frame_t > band_t ? frame_t : band_t;
    pl->total = o + align_up(sizeof(r8_state)) + ALIGN_TO; /* + alignment slack */
}
#endif

unsigned r8_render_ram(const r8_render_cfg *cfg)
{
#ifndef R8_FIXED_PLAN
    plan pl;
#endif
#ifndef R8_NO_BSP
    if (cfg->method == R8_VIS_BSP)
        return r8_bsp_ram(cfg);
#endif
#ifndef R8_NO_RAY
    if (cfg->method == R8_VIS_RAY) return r8_ray_ram(cfg);
#endif
#ifndef R8_NO_PORTAL
    if (cfg->method == R8_VIS_PORTAL) return r8_portal_ram(cfg);
#endif
    if (!cfg_valid(cfg))
        return 0;
#ifdef R8_FIXED_PLAN
    return FP_total;
#else
    make_plan(cfg, &pl);
    return pl.total;
#endif
}

#ifndef R8_PLAN_ONLY   /* a sizing build (R8_PLAN_ONLY) stops here */

r8_s16 r8_camera_fov(r8_s16 width, r8_u8 fov)
{
    /* (width / 2) / tan(fov / 2) */
    r8_u8 h = (r8_u8)(fov >> 1);
    r8_s16 s = r8_sin(h), c = r8_cos(h);
    r8_s32 f;
    if (s < 1)
        s = 1;
    f = r8_divround(r8_mul16(width, c) / 2, s);
    if (f < 1)
        f = 1;
    if (f > 2047)
        f = 2047;
    return (r8_s16)f;
}

#ifndef R8_NO_GOURAUD
/* Gouraud vertex normals: the normalised sum of the unit normals of the
 * faces around each vertex. */
static void vertex_normals(r8_state *st, const r8_mesh *me, const r8_objx *o)
{
    r8_u16 k, f;
    for (k = 0; k < me->nverts; k++) {
        r8_vec3l sum;
        r8_vec3 n;
        r8_s16 *out = st->vnorm + 3u * (o->vbase + k);
        sum.x = sum.y = sum.z = 0;
        for (f = 0; f < me->nfaces; f++) {
            const r8_face *fc = &me->faces[f];
            r8_u8 j, nv = R8_RDU8(&fc->n);
            for (j = 0; j < nv; j++)
                if (R8_RDU8(&fc->v[j]) == k) {
                    const r8_s16 *p = o->normals + 3u * f;
                    if (o->nflash) {
                        sum.x += R8_RDS16(p);
                        sum.y += R8_RDS16(p + 1);
                        sum.z += R8_RDS16(p + 2);
                    } else {
                        sum.x += p[0];
                        sum.y += p[1];
                        sum.z += p[2];
                    }
                }
        }
        r8_normalize(&sum, &n);
        out[0] = n.x;
        out[1] = n.y;
        out[2] = n.z;
    }
}

#endif

#ifdef R8_FIXED_PLAN
/* The fixed plan's r8_state as tables (R8_FP_TABLES: cc65 spends 10-20 bytes
 * on each store through st; here 2 or 4): its non-zero bytes (offset,
 * value; words as two) and its arena pointers (offset, FP_* from base).
 * Every other field is 0, as the general path in r8_render_init sets
 * it (nclip, npoly, dropped, nclipped, pool_used, zx[0], attrs before
 * the methods' bits) or r8_render_frame does before reading it. */
#define FPO(f) ((r8_u16)offsetof(r8_state, f))
#define FPWO(o, v) (r8_u8)(o), (r8_u8)((r8_u16)(v) & 255u), \
                   (r8_u8)((o) + 1u), (r8_u8)((r8_u16)(v) >> 8)
#define FPW(f, v) FPWO(FPO(f), v)
#if R8_CFG_BAND == 1
#define FP_bsh 0
#elif R8_CFG_BAND == 2
#define FP_bsh 1
#elif R8_CFG_BAND == 4
#define FP_bsh 2
#elif R8_CFG_BAND == 8
#define FP_bsh 3
#elif R8_CFG_BAND == 16
#define FP_bsh 4
#elif R8_CFG_BAND == 32
#define FP_bsh 5
#elif R8_CFG_BAND == 64
#define FP_bsh 6
#elif R8_CFG_BAND == 128
#define FP_bsh 7
#elif R8_CFG_BAND == 256
#define FP_bsh 8
#elif R8_CFG_BAND == 512
#define FP_bsh 9
#elif R8_CFG_BAND == 1024
#define FP_bsh 10
#else
#define FP_bsh (-1)
#endif
R8_CASSERT(fixed_plan_state_small, sizeof(r8_state) <= 256);
/* n bytes of v from q (the state's clear, the buckets' R8_FID_END) */
static void fp_fill(r8_u8 *q, r8_u16 n, r8_u8 v)
{
    for (; n; n--)
        *q++ = v;
}
#define FP_HEADS_BYTES ((r8_u16)(FP_nheads * sizeof(r8_fid)))
R8_CASSERT(fixed_plan_fid_end, (r8_fid)R8_FID_END == (r8_fid)~(r8_fid)0);
#ifdef R8_FP_TABLES
static R8_FLASH const r8_u8 fp_b[] = {
    (r8_u8)FPO(vsh), FP_vsh,
    (r8_u8)FPO(fast), FP_fast,
    (r8_u8)FPO(judd), (r8_u8)(R8_CFG_CULL == R8_CULL_JUDD),
    (r8_u8)FPO(method), R8_CFG_METHOD,
    (r8_u8)FPO(shading), R8_CFG_SHADING,
    (r8_u8)FPO(npool), FP_npool,
    (r8_u8)FPO(nclip), R8_CFG_CLIP,
    (r8_u8)(FPO(zx) + 1u), 255,
    (r8_u8)FPO(pool_free), R8_NO_SLOT,
    /* the words, a byte at a time (6502 and Z80: little-endian) */
    FPW(width, R8_CFG_WIDTH),
    FPW(height, R8_CFG_HEIGHT),
    FPW(nverts, FP_nverts),
    FPW(nfaces, FP_nfaces),
    FPW(bsh, FP_bsh),
    FPW(nbands, FP_nbands),
    FPW(nheads, FP_nheads),
    FPW(sv_cap, FP_sv_cap),
    FPW(esize, FP_esize),
    FPW(first, R8_FID_END),
    FPWO(FPO(cam) + offsetof(r8_proj, cx), R8_CFG_WIDTH * 8),
    FPWO(FPO(cam) + offsetof(r8_proj, cy), R8_CFG_HEIGHT * 8)
};
static R8_FLASH const r8_u16 fp_p[] = {
    FPO(obj), FP_obj,
    FPO(sv), FP_sv,
    FPO(vnorm), FP_vnorm,
    FPO(next), FP_next,
#if FP_NP1 > 0
    FPO(slot), FP_slot,               /* (npool: 0 when FP_NP1 is) */
#if FP_PAINTER
    FPO(ftop), FP_ftop,
#endif
#endif
    FPO(cpoly), FP_cpoly,
    FPO(heads), FP_heads,
    FPO(clipbuf), FP_clipbuf,
    FPO(tmp), FP_tmp,
    FPO(pool), FP_pool,
    FPO(depth), FP_depth,
    FPO(snode), FP_snode,
    FPO(shead), FP_shead
};
#endif
#endif

int r8_render_init(r8_render *r, const r8_render_cfg *cfg, r8_u8 *work,
                   unsigned work_size)
{
#ifndef R8_FIXED_PLAN
    plan pl;
#endif
    r8_state *st;
    r8_u8 *base;
    const r8_scene *sc;
#ifndef R8_NO_RT_NORMALS
    r8_s16 *norms;
#endif
    r8_u8 i;
    r8_u16 vb = 0, fb = 0, k;
#if defined(R8_FIXED_PLAN) && !defined(R8_FP_TABLES) && defined(R8_CFG_BAND) && R8_CFG_BAND == 8
    (void)k;           /* (AVR: the fixed plan's stores need no loop) */
#endif
#ifndef R8_NO_BSP
    if (cfg->method == R8_VIS_BSP)
        return r8_bsp_init(r, cfg, work, work_size);
#endif
#ifndef R8_NO_RAY
    if (cfg->method == R8_VIS_RAY) return r8_ray_init(r, cfg, work, work_size);
#endif
#ifndef R8_NO_PORTAL
    if (cfg->method == R8_VIS_PORTAL) return r8_portal_init(r, cfg, work, work_size);
#endif
    if (!cfg_valid(cfg))
        return -1;
#ifndef R8_FIXED_PLAN
    make_plan(cfg, &pl);
#endif
    if (work_size < PLV(total))
        return -2;
    /* state first, aligned; the rest follows */
    base = work + ((ALIGN_TO - ((unsigned)((size_t)(void *)work & (ALIGN_TO - 1)))) & (ALIGN_TO - 1));
    st = (r8_state *)(void *)base;
#ifdef R8_FIXED_PLAN
    base += FP_A(sizeof(r8_state));
#else
    base += align_up(sizeof(r8_state));
#endif
    r->cfg = *cfg;
    r->work = work;
    r->work_size = work_size;
    r->state = st;
    sc = cfg->scene;
#ifdef R8_FP_TABLES
    /* the fields below from fp_b and fp_p (zero first): the same
     * values as the general path after #else, field by field */
    fp_fill((r8_u8 *)st, (r8_u16)sizeof *st, 0);
    st->scene = sc;
    for (k = 0; k < (r8_u16)sizeof fp_b; k = (r8_u16)(k + 2u))
        ((r8_u8 *)st)[R8_RDU8(&fp_b[k])] = R8_RDU8(&fp_b[k + 1u]);
    for (k = 0; k < (r8_u16)(sizeof fp_p / sizeof fp_p[0]); k = (r8_u16)(k + 2u))
        *(r8_u8 **)(void *)((r8_u8 *)st + R8_RDU16(&fp_p[k])) = base + R8_RDU16(&fp_p[k + 1u]);
    /* (R8_FAST_ONLY: cull or painter's, so depth_bytes and nsnode 0;
     * the attributes as below) */
#if R8_W_DEPTH
    if (CFG_METHOD(cfg) >= R8_VIS_Z8)
        st->attrs |= R8_ATTR_D;
#endif
#if R8_W_GOURAUD
    if (CFG_SHADING(cfg) == R8_SHADE_GOURAUD)
        st->attrs |= R8_ATTR_S;
#endif
#else
    st->scene = sc;
    st->width = CFG_WIDTH(cfg);
    st->height = CFG_HEIGHT(cfg);
    st->nverts = PLV(nverts);
    st->nfaces = PLV(nfaces);
    st->vsh = PLV(vsh);
    st->fast = PLV(fast);
    st->judd = (r8_u8)(CFG_CULL(cfg) == R8_CULL_JUDD);
    st->method = CFG_METHOD(cfg);
    st->shading = CFG_SHADING(cfg);
    st->nbands = PLV(nbands);
    st->nheads = PLV(nheads);
    st->bsh = -1;
#if defined(R8_CFG_BAND) && R8_CFG_BAND == 8
    st->bsh = 3;                /* (the demo's band) */
#else
    for (k = 0; k < 11; k++)
        if (CFG_BAND(cfg) == (1 << k))
            st->bsh = (r8_s16)k;
#endif
    st->obj = (r8_objx *)(void *)(base + PLV(obj));
    st->sv = (r8_s16 *)(void *)(base + PLV(sv));
    st->sv_cap = PLV(sv_cap);
    st->vnorm = (r8_s16 *)(void *)(base + PLV(vnorm));
    st->next = (r8_fid *)(void *)(base + PLV(next));
    st->slot = PLV(npool) ? base + PLV(slot) : 0;
    st->ftop = PLV(npool) && R8_PAINTER(CFG_METHOD(cfg)) ? base + PLV(ftop) : 0;
    st->cpoly = (r8_cpoly *)(void *)(base + PLV(cpoly));
    st->nclip = CFG_CLIP(cfg);
    st->heads = (r8_fid *)(void *)(base + PLV(heads));
    st->clipbuf = base + PLV(clipbuf);
    st->tmp = base + PLV(tmp);
    st->pool = base + PLV(pool);
    st->esize = PLV(esize);
    st->npool = PLV(npool);
    st->depth = base + PLV(depth);
    st->depth_bytes = R8_DEPTH(CFG_METHOD(cfg)) ? r8_vis_depth_bytes(cfg) : 0;
    st->snode = (r8_snode *)(void *)(base + PLV(snode));
    st->nsnode = R8_SBUF(CFG_METHOD(cfg)) ? r8_vis_sbuf_nodes(cfg) : 0;
    st->shead = (r8_u16 *)(void *)(base + PLV(shead));
    st->attrs = 0;
#if R8_W_DEPTH
    if (CFG_METHOD(cfg) >= R8_VIS_Z8)
        st->attrs |= R8_ATTR_D;
#endif
#if R8_W_GOURAUD
    if (CFG_SHADING(cfg) == R8_SHADE_GOURAUD)
        st->attrs |= R8_ATTR_S;
#endif
#if R8_W_TEXTURE
    if (R8_TEXTURED(CFG_SHADING(cfg)))
        st->attrs |= R8_ATTR_D;      /* vertex 1/z for perspective */
    st->cuv = (r8_s16 *)(void *)(base + PLV(cuv));
    st->texfilter = cfg->texfilter;
    st->persp = cfg->persp;
#endif
    st->first = (r8_fid)R8_FID_END;
    st->zx[0] = 0;        /* the depth memory: unknown, all cleared first */
    st->zx[1] = 255;
    st->npoly = 0;
    st->dropped = 0;
    st->nclipped = 0;
    st->pool_used = 0;
    st->pool_free = R8_NO_SLOT;
    st->cam.cx = (r8_s16)(CFG_WIDTH(cfg) * 8);
    st->cam.cy = (r8_s16)(CFG_HEIGHT(cfg) * 8);
#endif
#ifndef R8_NO_RT_NORMALS
    norms = (r8_s16 *)(void *)(base + PLV(norms));
#endif
    for (i = 0; i < sc->nobjects; i++) {
        const r8_mesh *me = sc->objects[i].mesh;
        r8_objx *o = &st->obj[i];
        o->vbase = vb;
        o->fbase = fb;
        vb = (r8_u16)(vb + me->nverts);
        fb = (r8_u16)(fb + me->nfaces);
        o->hidden = 1;      /* until the first r8_render_frame */
#ifdef R8_NO_RT_NORMALS
        o->normals = me->normals;   /* every mesh has them (cfg_valid) */
        o->nflash = R8_HAVE_PROGMEM;
#else
        if (me->normals) {
            o->normals = me->normals;
            o->nflash = R8_HAVE_PROGMEM;
        } else {
            r8_u8 j;
            o->nflash = 0;
            o->normals = 0;
            for (j = 0; j < i; j++)
                if (sc->objects[j].mesh == me)
                    o->normals = st->obj[j].normals;
            if (!o->normals) {
                r8_mesh_normals(me, norms);
                o->normals = norms;
                norms += 3u * me->nfaces;
            }
        }
#endif
#ifndef R8_NO_GOURAUD
        if (CFG_SHADING(cfg) == R8_SHADE_GOURAUD)
            vertex_normals(st, me, o);
#endif
    }
#ifdef R8_FIXED_PLAN
    fp_fill((r8_u8 *)st->heads, FP_HEADS_BYTES, 0xFF);   /* R8_FID_END: all ones */
#else
    for (k = 0; k < st->nheads; k++)
        st->heads[k] = (r8_fid)R8_FID_END;
#endif
    return 0;
}

void r8_render_stats_get(const r8_render *r, r8_render_stats *s)
{
    const r8_state *st = (const r8_state *)r->state;
#ifndef R8_NO_RAY
    if (r->cfg.method == R8_VIS_RAY) { s->faces = s->clipped = s->dropped = 0; return; }
#endif
    s->faces = st->npoly;
    s->clipped = st->nclipped;
    s->dropped = st->dropped;
}

/* ---- per frame ---- */

#define ENTRY(st, k) ((st)->pool + (unsigned)(k) * (st)->esize)

static r8_u16 band_of(const r8_state *st, r8_s16 y, r8_s16 band)
{
    if (y < 0)
        return 0;
#if defined(R8_CFG_BAND) && R8_CFG_BAND == 8
    (void)st; (void)band;
    return (r8_u16)((r8_u16)y >> 3);   /* (st->bsh: r8_render_init) */
#else
    if (st->bsh >= 0)
        return (r8_u16)((r8_u16)y >> st->bsh);
    return (r8_u16)((r8_u16)y / (r8_u16)band);
#endif
}

/* Rows [*top, *bot) of the box [xmin, xmax] x [ymin, ymax] (12.4); 0 if
 * no pixel centre of the frame can be inside. */
static int box_rows(const r8_state *st, r8_s16 xmin, r8_s16 xmax, r8_s16 ymin, r8_s16 ymax,
                    r8_s16 *top, r8_s16 *bot)
{
    *top = R8_FLOOR16(ymin + 7);
    *bot = R8_FLOOR16(ymax + 7);
    return *top < *bot && *bot > 0 && *top < st->height &&
           R8_FLOOR16(xmax + 7) > 0 && R8_FLOOR16(xmin + 7) < st->width;
}

#if !defined(R8_NO_CLIP) || R8_W_PAINTER
/* Rows [*top, *bot) and columns of the polygon vp[0..n); 0 if no pixel
 * centre of the frame can be inside. */
static int face_rows(const r8_state *st, const r8_s16 *const *vp, r8_u8 n, r8_s16 *top, r8_s16 *bot)
{
    r8_s16 ymin = vp[0][1], ymax = ymin, xmin = vp[0][0], xmax = xmin;
    r8_u8 i;
    for (i = 1; i < n; i++) {
        const r8_s16 *v = vp[i];
        if (v[0] < xmin) xmin = v[0];
        if (v[0] > xmax) xmax = v[0];
        if (v[1] < ymin) ymin = v[1];
        if (v[1] > ymax) ymax = v[1];
    }
    return box_rows(st, xmin, xmax, ymin, ymax, top, bot);
}
#endif

#ifndef R8_NO_CLIP
/* Vertex pointers of the polygon over screen vertex list idx. */
static void face_vp(const r8_state *st, const r8_u16 *idx, r8_u8 n, const r8_s16 **vp)
{
    r8_u8 i;
    for (i = 0; i < n; i++)
        vp[i] = st->sv + ((unsigned)idx[i] << R8_VSH(st));
}
#endif

#if R8_W_PAINTER
/* Painter's key of a polygon whose camera-space z summed over its n
 * vertices is zsum: the centroid's depth in 64 buckets between znear
 * and zfar, 0 = far .. 63 = near (the seed's midpoint sort). */
static r8_u8 depth_key(const r8_state *st, r8_s32 zsum, r8_u8 n)
{
    r8_s32 zn = st->zn16, zr = st->zf16 - st->zn16, z;
    r8_u32 k;
    if (n == 4) {
        zn <<= 2;
        zr <<= 2;
    } else if (n == 3) {
        zn += zn << 1;
        zr += zr << 1;
    } else {
        zn *= n;
        zr *= n;
    }
    z = zsum - zn;                     /* n (centroid z - znear) */
    if (z < 0)
        z = 0;
    if (z >= zr)
        return 0;
    /* z kmul < 2^24 (kmul = 64 2^16 / range): the key is its top bits */
    if (n == 4)
        k = (r8_u16)((r8_u32)z * st->kmul >> 16) >> 2;
    else if (n == 3)
        k = (r8_u16)((r8_u32)z * st->kmul3 >> 16);
    else
        k = ((r8_u32)z / n * st->kmul) >> 16;
    if (k > R8_JEFF_BUCKETS - 1)
        k = R8_JEFF_BUCKETS - 1;
    return (r8_u8)(R8_JEFF_BUCKETS - 1 - k);
}

/* Camera-space z summed over face vi[0..n) of object o: the vertices
 * added in model space (flash), then the one product row. */
static r8_s32 face_zsum(const r8_objx *o, const r8_mesh *me, const r8_u8 *vi, r8_u8 n)
{
    r8_s32 sx, tz;
#ifndef __SDCC                         /* (R8_SDCC_FACE_KERN in r8kern.h) */
    if (!r8k_zsum(me->verts, vi, n, &o->m.m[6], &sx))
#endif
    {
        /* a sum past 16 bits: all halved until they fit, the product
         * shifted back */
        r8_s32 sy = 0, sz = 0;
        r8_u8 k, sh = 0;
        sx = 0;
        for (k = 0; k < n; k++) {
            const r8_s16 *mv = me->verts + 3u * vi[k];
            sx += R8_RDS16(mv);
            sy += R8_RDS16(mv + 1);
            sz += R8_RDS16(mv + 2);
        }
        while ((r8_u32)(sx + 32767) > 65534UL || (r8_u32)(sy + 32767) > 65534UL ||
               (r8_u32)(sz + 32767) > 65534UL) {
            sx = R8_ASR32C(sx, 1);
            sy = R8_ASR32C(sy, 1);
            sz = R8_ASR32C(sz, 1);
            sh++;
        }
        sx = R8_ASR32C(R8_MUL16(o->m.m[6], sx) + R8_MUL16(o->m.m[7], sy) +
                       R8_MUL16(o->m.m[8], sz) + 512, 10);
        if (sh)
            sx = (r8_s32)((r8_u32)sx << sh);
    }
    tz = o->t.z;
    if (n == 4)
        tz <<= 2;
    else if (n == 3)
        tz += tz << 1;
    else
        tz *= n;
    return sx + tz;
}
#endif

/* R8_FWALK_K: r8_bucket_object walks the faces with r8k_fwalk (AVR:
 * ports/avr/fwalk.S; the host: kern.c's reference) and takes the ones
 * it hands back (R8_FW_OTHER) through its own loop; the 6502 and Z80
 * keep the loop alone, and so does a build with R8_NO_FWALK (firmware
 * whose meshes are small: ports/fwdefs.sh). */
#if !defined(R8_NO_FWALK) && (defined(R8_ASM_FWALK) || !(defined(__SDCC) || defined(__CC65__)))
#define R8_FWALK_K 1
/* R8_FWALK_PK: with painter's, r8k_fwalk puts the faces in their depth
 * buckets itself (an r8_fwpk: 29 B more stack, which the 2 KB parts,
 * built with R8_SMALL_SCENE, cannot spare: they keep the C keys) */
#ifndef R8_SMALL_SCENE
#define R8_FWALK_PK 1
#endif
#else
#define R8_FWALK_K 0
#endif

/* Object i's faces into their buckets (r8_render_frame): cull, vertex
 * pointers (transforming vertices on first use), clip, trivial reject.
 * External so -Os keeps its stack frame apart from r8_tf_frame's (the
 * deepest point of a frame: it matters on the 2 KB parts). */
void r8_bucket_object(r8_render *r, r8_u8 i)
{
    r8_state *st = (r8_state *)r->state;
    const r8_scene *sc = st->scene;
    const r8_object *ob = &sc->objects[i];
    const r8_mesh *me = ob->mesh;
    const r8_objx *o = &st->obj[i];
    const r8_s16 *base = st->sv + ((unsigned)o->vbase << R8_VSH(st));
    /* (painter, normal: constants where the build fixes them, as cc65
     * folds no local variable: the depth keys and cull paths go) */
#if R8_W_PAINTER
    int painter = R8_PAINTER(st->method);
#else
#define painter 0
#endif
#ifdef R8_CFG_CULL
#define normal (R8_CFG_CULL == R8_CULL_NORMAL)
#else
    r8_u8 normal = (r8_u8)(r->cfg.cull == R8_CULL_NORMAL);
#endif
    r8_u8 vsh = R8_VSH(st);
#ifndef __SDCC
    r8_u8 kcull;
#endif
    r8_u16 f;
#ifndef R8_NO_BSP
    r8_u16 nf;
    int bsp = r->cfg.method == R8_VIS_BSP;   /* faces in tree order, near to far */
#endif
#if R8_FWALK_K
    r8_fwalk fw;
    r8_u8 kw = 0;              /* r8k_fwalk's answer: 1 (cull and box
                                  done), R8_FW_OTHER; 0: not used */
#ifdef R8_FWALK_PK
    r8_fwpk pk;                /* painter's: depth_key's constants */
#endif
#endif
    if (o->hidden)
        return;
#ifndef __SDCC
    kcull = o->eye16;             /* r8k_cull reads flash normals */
#ifndef R8_NO_RT_NORMALS
    if (!o->nflash)
        kcull = 0;
#endif
#endif
#if R8_FWALK_K
    fw.f = 0;
    fw.npoly = 0;
    if ((normal ? kcull : 1)
#ifndef R8_NO_BSP
        && !bsp
#endif
       ) {
        fw.base = base;
        fw.faces = me->faces;
        fw.normals = normal ? o->normals : 0;
        fw.verts = me->verts;
        fw.eye = &o->eye;
        fw.f = me->nfaces;
        fw.w = st->width;
        fw.h = st->height;
        fw.vsh = vsh;
        fw.st = st;
        fw.o = o;
        /* the band buckets: r8k_fwalk fills them itself */
        fw.bsh = (r8_s8)(painter || st->bsh < 0 ? -1 : st->bsh);
        fw.heads = st->heads;
        fw.next = st->next;
#ifdef R8_NO_POOL
        fw.slot = 0;
#else
        fw.slot = st->slot;
#endif
        fw.fbase = o->fbase;
        fw.fid8 = (r8_u8)(sizeof(r8_fid) == 1);
        fw.vbase = o->vbase;
        /* painter's: r8k_fwalk puts the faces in their depth buckets
         * (depth_key with n (t.z - znear), n range and kmul taken once) */
        fw.pk = 0;
        fw.paint = 0;
#ifdef R8_FWALK_PK
        if (painter && (!st->ftop || st->bsh >= 0)) {
            r8_u32 zc = (r8_u32)o->t.z - (r8_u32)st->zn16, zr = (r8_u32)(st->zf16 - st->zn16);
            pk.k[0] = (r8_s32)(zc + (zc << 1));
            pk.k[1] = (r8_s32)(zr + (zr << 1));
            pk.k[2] = (r8_s32)st->kmul3;
            pk.k[3] = (r8_s32)(zc << 2);
            pk.k[4] = (r8_s32)(zr << 2);
            pk.k[5] = (r8_s32)st->kmul;
            pk.row = &o->m.m[6];
            pk.ftop = st->ftop;
            pk.fbsh = (r8_s8)st->bsh;
            fw.pk = &pk;
#ifdef __AVR__                 /* (fwpaint.S, or kern.c's stub) */
            fw.paint = r8k_fwpaint;
#endif
        }
#endif
    }
#endif
#ifndef R8_NO_BSP
    if (bsp)
        r8_bsp_begin(r, me);
    for (nf = me->nfaces; nf-- > 0;) {
        const r8_face *fc;
        f = bsp ? r8_bsp_next(r, o, me) : nf;
#if R8_FWALK_K
        if (fw.f) {            /* (a face left: fw.f >= 1) */
            kw = r8k_fwalk(&fw);
            if (!kw)
                break;
            f = fw.f;          /* (as nf or below) */
        } else if (kw) {
            break;             /* the walk is over */
        }
#endif
        fc = &me->faces[f];
        {
#else
    for (f = me->nfaces; f-- > 0;) {
        const r8_face *fc;
#if R8_FWALK_K
        if (fw.f) {
            kw = r8k_fwalk(&fw);
            if (!kw)
                break;
            f = fw.f;          /* (the loop goes on below it) */
        } else if (kw) {
            break;             /* the walk is over */
        }
#endif
        fc = &me->faces[f];
        {
#endif
        r8_u8 vi[R8_MAX_FACE_VERTS], n = R8_RDU8(&fc->n), j, clip = 0;
#ifndef R8_NO_CLIP
        const r8_s16 *vp[R8_SCAN_MAXV];
#endif
        r8_s16 top, bot, xmin = 32767, xmax = -32767, ymin = 32767, ymax = -32767;
#if R8_W_PAINTER || !defined(R8_NO_CLIP)
        r8_s32 zsum = 0;       /* (painter's keys, the clipper's sums) */
#endif
        r8_fid id;
        r8_u16 key;
        if (n < 3 || n > R8_MAX_FACE_VERTS)
            continue;
        vi[0] = R8_RDU8(&fc->v[0]);
#if R8_FWALK_K
        if (kw == 1) {         /* culled and boxed by r8k_fwalk */
            top = fw.top;
            bot = fw.bot;
            id = (r8_fid)(o->fbase + f);
            if (painter)
                for (j = 1; j < n; j++)
                    vi[j] = R8_RDU8(&fc->v[j]);
            goto bucket;
        }
#endif
        if (normal) {          /* 16-bit test (r8k_cull), else 32-bit */
            const r8_s16 *v0 = me->verts + 3u * vi[0];
            int c;
#ifdef R8_CULL16               /* (ports/fw_trim.c: always in 16 bits) */
            c = r8k_cull(o->normals + 3u * f, v0, &o->eye);
#ifndef __SDCC                 /* (sdcc's build has no kcull) */
            (void)kcull;
#endif
#else
#ifndef __SDCC                 /* (R8_SDCC_FACE_KERN in r8kern.h) */
            c = -1;
            if (kcull)
                c = r8k_cull(o->normals + 3u * f, v0, &o->eye);
            if (c < 0)
#endif
                c = r8_cull_front(o, v0, f);
#endif
            if (!c)
                continue;
        }
        /* the vertices' box; a marked vertex sends the face to the
         * clipper */
        for (j = 0; j < n; j++) {
            const r8_s16 *v;
            r8_s16 x;
            if (j)
                vi[j] = R8_RDU8(&fc->v[j]);
#ifdef R8_VSH1
            v = base + 2u * vi[j];
            (void)vsh;
#else
            v = base + (vsh == 1 ? 2u * vi[j] : 4u * vi[j]);   /* no variable shift */
#endif
#ifndef R8_NO_CLIP
            vp[j] = v;
#endif
            x = v[0];
            if (x == R8_VX_TODO) {
                r8_tf_vertex(st, o, me->verts + 3u * vi[j], (r8_u16)(o->vbase + vi[j]));
                x = v[0];
            }
            if (x == R8_VX_CLIP) {
                clip = 1;
            } else {
                r8_s16 y = v[1];
                if (x < xmin) xmin = x;
                if (x > xmax) xmax = x;
                if (y < ymin) ymin = y;
                if (y > ymax) ymax = y;
            }
        }
        if (clip) {
#ifdef R8_NO_CLIP
            st->dropped++;     /* this build has no clipper */
            continue;
#else
            r8_cpoly *cp;
            if (st->nclipped >= st->nclip) {
                st->dropped++;
                continue;
            }
            cp = &st->cpoly[st->nclipped];
            if (!r8_clip_face(st, o, ob, f, vi, n, cp, &zsum))
                continue;
            n = cp->n;
            face_vp(st, cp->idx, n, vp);
            if (!face_rows(st, vp, n, &top, &bot))
                continue;
            id = (r8_fid)(st->nfaces + st->nclipped);
#endif
        } else {
            if (!box_rows(st, xmin, xmax, ymin, ymax, &top, &bot))
                continue;
            id = (r8_fid)(o->fbase + f);
        }
#ifndef R8_NO_CLIP             /* (without: a clipped face went on above) */
        if (clip)
            st->nclipped++;
#endif
#if R8_FWALK_K
    bucket:
#endif
#if R8_W_PAINTER
        if (painter) {
#ifndef R8_NO_BSP
            if (bsp)
                key = 0;           /* one list, in tree order */
            else
#endif
            {
                if (!clip)
                    zsum = face_zsum(o, me, vi, n);
                key = depth_key(st, zsum, n);
            }
            if (st->ftop) {
                r8_u16 b = band_of(st, top, r->cfg.band);
                st->ftop[id] = (r8_u8)(b > 255 ? 255 : b);
            }
        } else
#elif !defined(R8_NO_CLIP)
        (void)zsum;
#endif
        {
            key = band_of(st, top, r->cfg.band);
        }
        st->next[id] = st->heads[key];
        st->heads[key] = id;
#ifndef R8_NO_POOL
        if (st->slot)
            st->slot[id] = R8_NO_SLOT;
#endif
        st->npoly++;
        }
    }
#if R8_FWALK_K
    st->npoly = (r8_u16)(st->npoly + fw.npoly);   /* those r8k_fwalk put */
#endif
}
#undef painter
#undef normal

void r8_render_frame(r8_render *r, const r8_camera *cam)
{
    r8_state *st = (r8_state *)r->state;
    const r8_scene *sc;
#if R8_W_PAINTER
    int painter;
#endif
    r8_u16 k;
    r8_u8 i;
    r8_fid cur;
#ifndef R8_NO_RAY
    if (r->cfg.method == R8_VIS_RAY) { r8_ray_frame(r, cam); return; }
#endif
#ifndef R8_NO_PORTAL
    if (r->cfg.method == R8_VIS_PORTAL) { r8_portal_frame(r, cam); return; }
#endif
    sc = st->scene;
#ifdef R8_FIXED_PLAN
    (void)k;      /* (the fixed plan, no pool and no painter's: no loop on k) */
#endif
#if R8_W_PAINTER
    painter = R8_PAINTER(st->method);
#endif
    st->npoly = 0;
    st->sv_used = st->nverts;
    st->nclipped = 0;
    st->dropped = 0;
    st->pool_used = 0;
    r8_tf_frame(st, cam);
    /* with the normal cull, vertices are transformed as front faces need
     * them (a closed mesh shows about half its faces) */
    r8_tf_vertices(st, CFG_CULL(&r->cfg) == R8_CULL_NORMAL);
#if defined(R8_FIXED_PLAN) && defined(R8_NO_BSP)   /* (BSP: r8_bsp_init's plan) */
    fp_fill((r8_u8 *)st->heads, FP_HEADS_BYTES, 0xFF);   /* R8_FID_END: all ones */
#else
    for (k = 0; k < st->nheads; k++)
        st->heads[k] = (r8_fid)R8_FID_END;
#endif
    /* faces last to first, each put at the front of its bucket: every
     * bucket then lists its faces in scene order */
#ifndef R8_NO_BSP
    if (r->cfg.method == R8_VIS_BSP)
        r8_bsp_frame(r);           /* BSP: tree order instead */
    else
#endif
    for (i = sc->nobjects; i-- > 0;)
        r8_bucket_object(r, i);
    /* painter's: chain the buckets, far to near, into the draw list;
     * band buckets stay apart (r8_render_band merges them) */
    cur = (r8_fid)R8_FID_END;
#if R8_W_PAINTER
    for (k = st->nheads; painter && k-- > 0;) {
        r8_fid h = st->heads[k];
        if (h != (r8_fid)R8_FID_END) {
            r8_fid t = h;
            while (st->next[t] != (r8_fid)R8_FID_END)
                t = st->next[t];
            st->next[t] = cur;
            cur = h;
        }
    }
#endif
    st->first = cur;
#if R8_W_DEPTH
    if (st->nclip) {      /* the clipper's polygons may lie on the depth */
        st->zx[0] = 0;    /* memory: the next band clears all of it */
        st->zx[1] = 255;
    }
#endif
    /* the pool shares memory with the buckets and the clipper: all free,
     * in one list */
#if defined(R8_FIXED_PLAN) && defined(R8_NO_BSP) && !defined(R8_NO_POOL)
    /* (the fixed plan: FP_npool entries of FP_esize bytes) */
#if FP_NP1 > 0
    {
        r8_u8 *q = st->pool;
        st->pool_free = 0;
        for (k = 1; k <= FP_npool; k++, q += FP_esize) {
            r8_acthead *e = (r8_acthead *)(void *)q;
            e->used = 0;
            if (k < FP_npool)
                e->level = (r8_u8)k;
            else
                e->level = R8_NO_SLOT;
        }
    }
#else
    st->pool_free = R8_NO_SLOT;
#endif
#elif !defined(R8_NO_POOL)
    st->pool_free = st->npool ? 0 : R8_NO_SLOT;
    for (k = 0; k < st->npool; k++) {
        r8_acthead *e = (r8_acthead *)(void *)ENTRY(st, k);
        e->used = 0;
        e->level = (r8_u8)(k + 1u < st->npool ? k + 1u : R8_NO_SLOT);
    }
#endif
}

/* ---- per band ---- */

/* The vertex pointers of face id g into vp; returns n (and the object
 * it belongs to in *oi, 255 for a clipped polygon). */
static r8_u8 face_setup(const r8_state *st, r8_fid g, const r8_s16 **vp, r8_u8 *oi)
{
    const r8_scene *sc = st->scene;
    r8_u8 i = 0, n, j;
#ifndef R8_NO_CLIP                      /* (else no clipped polygons) */
    if (g >= st->nfaces) {
        const r8_cpoly *cp = &st->cpoly[g - st->nfaces];
        face_vp(st, cp->idx, cp->n, vp);
        *oi = 255;
        return cp->n;
    }
#endif
    while (i + 1 < sc->nobjects && g >= st->obj[i + 1].fbase)
        i++;
    {
        const r8_objx *o = &st->obj[i];
        const r8_face *fc = &sc->objects[i].mesh->faces[g - o->fbase];
        const r8_s16 *base = st->sv + ((unsigned)o->vbase << R8_VSH(st));
        n = R8_RDU8(&fc->n);
#ifndef R8_VSH1
        if (R8_VSH(st) != 1) {
            for (j = 0; j < n; j++)
                vp[j] = base + 4u * R8_RDU8(&fc->v[j]);
        } else
#endif
        {                               /* no run-time multiply */
            for (j = 0; j < n; j++)
                vp[j] = base + 2u * R8_RDU8(&fc->v[j]);
        }
    }
    *oi = i;
    return n;
}

/* The dither level of face id g of object oi (face_setup). */
static r8_u8 face_level(const r8_state *st, r8_fid g, r8_u8 oi)
{
    const r8_objx *o;
#ifndef R8_NO_CLIP
    if (oi == 255)
        return st->cpoly[g - st->nfaces].level;
#endif
    o = &st->obj[oi];
    return r8_face_level(st, o, &st->scene->objects[oi], (r8_u16)(g - o->fbase));
}

#ifndef R8_NO_WIRE
/* face_setup for wireframe.c */
r8_u8 r8_face_vp(const r8_state *st, r8_fid g, const r8_s16 **vp)
{
    r8_u8 oi;
    return face_setup(st, g, vp, &oi);
}
#endif

#ifndef R8_FAST_ONLY
static void draw_span(r8_state *st, r8_fb *fb, r8_u8 level, r8_fid g, const r8_span *sp)
{
    switch (st->method) {
#ifndef R8_NO_ZBUF
    case R8_VIS_Z8:
        r8_vis_zbuf(st, fb, level, sp, 0);
        break;
    case R8_VIS_Z16:
        r8_vis_zbuf(st, fb, level, sp, 1);
        break;
#endif
#ifndef R8_NO_BLOCK
    case R8_VIS_BLOCK:
        r8_vis_block(st, fb, level, (r8_u8)(g % 255u), sp, 0);
        break;
    case R8_VIS_BLOCKMASK:
        r8_vis_block(st, fb, level, (r8_u8)(g % 255u), sp, 1);
        break;
#endif
#ifndef R8_NO_SBUF
    case R8_VIS_SBUF:
        r8_vis_sbuf_insert(st, fb, level, sp);
        break;
#endif
    default:
        r8_vis_plain(st, fb, level, sp);
    }
    (void)g;
}
#endif

#ifdef R8_BANDK
/* face_setup and r8_scanx_begin for mesh face g (< st->nfaces) in one
 * pass: c's vertex pointers, its rows from max(its top, y0) and both
 * edges; 0 when it has no row from y0 on (c->ybot <= c->y).  With the
 * painter's check (a face starting below y1: 2) as draw_face does it. */
static int face_begin(const r8_state *st, r8_fid g, r8_scanx *c, r8_s16 y0, r8_s16 y1, r8_u8 *oi)
{
    const r8_scene *sc = st->scene;
    const r8_objx *o;
    const r8_face *fc;
    const r8_s16 *base, *p;
    const r8_u8 *fv;
    r8_u8 i = 0, n, j, top = 0;
    r8_s16 ymin, ymax, y;
    while (i + 1 < sc->nobjects && g >= st->obj[i + 1].fbase)
        i++;
    *oi = i;
    o = &st->obj[i];
    fc = &sc->objects[i].mesh->faces[g - o->fbase];
    base = st->sv + 2u * o->vbase;
    n = R8_RDU8(&fc->n);
    if (n < 3)
        return 0;              /* (r8_scanx_begin: no rows) */
    fv = fc->v;
    p = base + 2u * R8_RDU8(fv);
    c->vp[0] = p;
    ymin = ymax = p[1];
    for (j = 1; j < n; j++) {
        r8_s16 vy;
        p = base + 2u * R8_RDU8(fv + j);
        c->vp[j] = p;
        vy = p[1];
        if (vy < ymin) {
            ymin = vy;
            top = j;
        }
        if (vy > ymax)
            ymax = vy;
    }
#if R8_W_PAINTER
    if (st->method == R8_VIS_PAINTER && (!st->ftop || st->ftop[g] == 255)) {
        r8_s16 t, b;
        face_rows(st, c->vp, n, &t, &b);
        if (t >= y1)
            return 2;          /* starts lower down */
    }
#else
    (void)y1;
#endif
    c->n = n;
    c->backface = 0;
    c->front = 0;
    c->ybot = R8_ROW_OF(ymax);
    y = R8_ROW_OF(ymin);
    if (y < y0)
        y = y0;
    c->y = y;
    if (y >= c->ybot)
        return 0;
    r8k_estart(c, &c->l, y, top);
    r8k_estart(c, &c->r, y, top);
    return 1;
}
#endif

/* Draw face g's rows in [y0, y1).  Returns 1 when the face is finished
 * (or a back face), 0 when it goes on below y1, 2 when it starts below. */
static int draw_face(r8_state *st, r8_fid g, r8_s16 y0, r8_s16 y1, r8_fb *fb)
{
    r8_acthead *e;
#ifndef R8_NO_POOL
    r8_u8 k = st->slot ? st->slot[g] : R8_NO_SLOT;
#endif
    r8_scanx *c;
    int done;
#ifndef R8_NO_POOL
    if (k != R8_NO_SLOT) {
        e = (r8_acthead *)(void *)ENTRY(st, k);
    } else
#endif
    {
        r8_u8 n, oi;
        /* a pool entry if one is free (kept if the face goes on below
         * this band), else the one-off entry */
        e = (r8_acthead *)(void *)st->tmp;
#ifndef R8_NO_POOL
        k = st->pool_free;
        if (k != R8_NO_SLOT)
            e = (r8_acthead *)(void *)ENTRY(st, k);
#endif
#ifdef R8_BANDK
        if (g < st->nfaces) {
            int b = face_begin(st, g, &e->c, y0, y1, &oi);
            if (b != 1)
                return b ? 2 : 1;  /* starts lower down; no row from y0 on */
        } else
#endif
        {
            n = face_setup(st, g, e->c.vp, &oi);
#if R8_W_PAINTER
            if (st->method == R8_VIS_PAINTER && (!st->ftop || st->ftop[g] == 255)) {
                /* (with ftop, r8_render_band has already skipped the faces
                 * that start lower down) */
                r8_s16 top, bot;
                face_rows(st, e->c.vp, n, &top, &bot);
                if (top >= y1)
                    return 2;          /* starts lower down */
            }
#endif
            if (!r8_scanx_begin(&e->c, n, y0))
                return 1;              /* nothing from this band on */
        }
#ifndef R8_NO_POOL
        if (k != R8_NO_SLOT) {
            st->pool_free = e->level;       /* off the free list */
            e->used = 1;
            st->slot[g] = k;
            st->pool_used++;
        }
#endif
        e->level = face_level(st, g, oi);
#if R8_W_TEXTURE
        if (R8_TEXTURED(st->shading))
            r8_tex_face(st, (r8_tact *)(void *)e, g, oi, n);
#endif
#ifndef R8_FAST_ONLY
        if (!st->fast && !R8_TEXTURED(st->shading)) {
            r8_act *a = (r8_act *)(void *)e;
            a->s.attrs = st->attrs;
            r8_scan_attrs(&a->s);
        }
#endif
    }
    c = &e->c;
#if R8_W_TEXTURE
    if (R8_TEXTURED(st->shading))
        r8_tex_draw(st, (r8_tact *)(void *)e, y1, fb);
    else
#endif
#ifndef R8_FAST_ONLY
    if (!st->fast) {
        r8_act *a = (r8_act *)(void *)e;
        r8_span sp;
#ifndef R8_NO_ZBUF
        if ((st->method == R8_VIS_Z8 || st->method == R8_VIS_Z16) &&
            !(st->attrs & R8_ATTR_S) && fb->format == R8_FMT_PAGE1) {
#if R8_ZROWS
            /* r8_zfill's common case called here (src/r8zrows.h); its
             * 2 (a row the kernel leaves): r8_zfill on from there */
            if (st->method == R8_VIS_Z16 && e->c.y >= fb->y0 && (!st->judd || e->c.front)) {
                if (r8k_zband((struct r8_act *)a, fb, (r8_u16 *)(void *)st->depth, y1) == 2)
                    r8_zfill(st, a, y1, fb, 1);
            } else
#endif
            r8_zfill(st, a, y1, fb, st->method == R8_VIS_Z16);   /* the common case */
        } else
#endif
        while (r8_scan_next(&a->s, y1, st->judd, &sp))
            draw_span(st, fb, e->level, g, &sp);
    } else
#endif
#ifdef R8_BANDK
    {
        /* r8_scanx_fill's page-1 case (y1 is never below the band) */
        r8_s16 lim = c->ybot < y1 ? c->ybot : y1;
#ifdef R8_BANDK_ONLY
        if (c->y < lim)        /* (c->y >= y0: face_begin, or the band above) */
            r8k_scanband(c, fb, lim, e->level);
#else
        if (c->y >= y0 && (!st->judd || c->front)) {
            if (c->y < lim)
                r8k_scanband(c, fb, lim, e->level);
        } else
            r8_scanx_fill(c, y1, st->judd, fb, e->level);
#endif
    }
#else
        r8_scanx_fill(c, y1, st->judd, fb, e->level);
#endif
    done = c->y >= c->ybot || c->backface;
#ifndef R8_NO_POOL
    if (done && k != R8_NO_SLOT) {
        e->used = 0;
        e->level = st->pool_free;           /* back on the free list */
        st->pool_free = k;
        st->slot[g] = R8_NO_SLOT;
        st->pool_used--;
    }
#endif
    return done;
}

/* Z80, the cull method's firmware (page-1 bands of 8 rows, the fused
 * fill alone, no painter's, depth, S-buffer, wireframe, ray or portal):
 * r8_render_band is r8k_band, ports/z80/band_z80.s (R8_ASM_BAND), which calls
 * draw_face through r8_band_face, except for a face with a pool slot
 * (one going on from the band above): draw_face's path for it (the
 * entry, r8k_scanband, the release) is in the kernel; this C89 version
 * stays, the reference, as r8_render_band_c. */
#if defined(R8_ASM_BAND) && defined(__SDCC) && defined(R8_BANDK_ONLY) && defined(R8_CFG_BAND) && \
    defined(R8_NO_WIRE) && defined(R8_NO_RAY) && defined(R8_NO_PORTAL) && !defined(R8_SMALL_SCENE)
#if R8_CFG_BAND == 8 && !R8_W_PAINTER && !R8_W_DEPTH && !R8_W_SBUF
#define R8_BAND_Z80 1
#endif
#endif
#ifdef R8_BAND_Z80
R8_CASSERT(bandz80_r_state_at_21, offsetof(r8_render, state) == 21);
R8_CASSERT(bandz80_st_nbands_at_33, offsetof(r8_state, nbands) == 33);
R8_CASSERT(bandz80_st_next_at_41, offsetof(r8_state, next) == 41);
R8_CASSERT(bandz80_st_heads_at_43, offsetof(r8_state, heads) == 43);
R8_CASSERT(bandz80_st_first_at_47, offsetof(r8_state, first) == 47);
R8_CASSERT(bandz80_st_slot_at_49, offsetof(r8_state, slot) == 49);
R8_CASSERT(bandz80_st_pool_at_53, offsetof(r8_state, pool) == 53);
R8_CASSERT(bandz80_st_esize_at_57, offsetof(r8_state, esize) == 57);
R8_CASSERT(bandz80_st_pool_used_at_60, offsetof(r8_state, pool_used) == 60);
R8_CASSERT(bandz80_st_pool_free_at_61, offsetof(r8_state, pool_free) == 61);
R8_CASSERT(bandz80_e_c_at_2, offsetof(r8_acthead, c) == 2);
R8_CASSERT(bandz80_c_backface_at_19, offsetof(r8_scanx, backface) == 19);
R8_CASSERT(bandz80_c_y_at_21, offsetof(r8_scanx, y) == 21);
R8_CASSERT(bandz80_c_ybot_at_23, offsetof(r8_scanx, ybot) == 23);
int r8_band_face(r8_state *st, r8_fid g, r8_s16 y0, r8_s16 y1, r8_fb *fb);
int r8_band_face(r8_state *st, r8_fid g, r8_s16 y0, r8_s16 y1, r8_fb *fb)
{
    return draw_face(st, g, y0, y1, fb);
}
void r8k_band(r8_render *r, r8_fb *fb);
void r8_render_band(r8_render *r, r8_fb *fb)
{
    r8k_band(r, fb);
}
#define r8_render_band r8_render_band_c
void r8_render_band_c(r8_render *r, r8_fb *fb);
#endif
void r8_render_band(r8_render *r, r8_fb *fb)
{
    r8_state *st = (r8_state *)r->state;
    r8_s16 y0 = fb->y0, y1 = (r8_s16)(fb->y0 + fb->rows);
    r8_fid head, *link = &head, g;
#ifndef R8_NO_RAY
    if (r->cfg.method == R8_VIS_RAY) { r8_ray_band(r, fb); return; }
#endif
#ifndef R8_NO_PORTAL
    if (r->cfg.method == R8_VIS_PORTAL) { r8_portal_band(r, fb); return; }
#endif
#ifndef R8_NO_WIRE
    if (r->cfg.wire) {
        r8_wire_band(r, fb);    /* wireframe.c */
        return;
    }
#endif
    head = (r8_fid)st->first;
    if (y1 > fb->height)
        y1 = fb->height;
    /* the band and depth clears: r8k_fill (r8kern.h; AVR: fill.S) */
#ifndef R8_PAGE1_ONLY          /* (r8config.h: page-1 bands only) */
    if (fb->format != R8_FMT_PAGE1)
        r8k_fill(fb->buf, 0, r8_fb_bytes(fb->format, fb->width, fb->rows));
    else
#endif
        r8k_fill(fb->buf, 0, R8_FB_PAGE1_BYTES(fb->width, fb->rows));
#if R8_W_DEPTH
    if (st->method >= R8_VIS_Z8 && st->depth_bytes) {
#ifndef R8_NO_ZBUF
        if (st->method == R8_VIS_Z16 && CFG_WIDTH(&r->cfg) <= 255)
            r8_zclear(st, fb, (r8_u16)CFG_WIDTH(&r->cfg), (r8_u16)CFG_BAND(&r->cfg));
        else
#endif
        {
            r8k_fill(st->depth, 0, st->depth_bytes);
            if (st->method == R8_VIS_BLOCK)   /* owner ids: none */
                memset(st->depth + st->depth_bytes / 2u, 0xFF, st->depth_bytes - st->depth_bytes / 2u);
        }
    }
#endif
#if R8_W_SBUF
    if (st->method == R8_VIS_SBUF) {
        /* the row lists share memory with the frame set-up: start empty */
        r8_s16 k;
        for (k = 0; k < fb->rows; k++)
            st->shead[k] = 0xFFFFu;
        st->sused = 0;
    }
#endif
    {
        /* painter's: the draw list, skipping the faces that start lower
         * down, dropping the finished ones.  Else merge the faces going
         * on from above (st->first) with the band's bucket, both in
         * scene order; those that go on form the next band's list.  (One
         * loop, one call of draw_face: inlined.) */
        r8_u16 b = band_of(st, y0, r->cfg.band);
#if R8_W_PAINTER
        r8_u8 paint = st->method == R8_VIS_PAINTER;
        r8_u8 b8 = (r8_u8)(b > 255 ? 255 : b);
        const r8_u8 *ftop = st->ftop;
        r8_fid *nx = st->next;
#endif
        r8_fid a = head, n = (r8_fid)R8_FID_END;
#if R8_W_PAINTER
        if (!paint)
#endif
            if (b < st->nbands)
                n = st->heads[b];
#if R8_W_PAINTER
        for (;;) {
#else
        while (a != (r8_fid)R8_FID_END || n != (r8_fid)R8_FID_END) {
#endif
            int d;
#if R8_W_PAINTER
            if (paint) {
                g = *link;
                if (ftop)                 /* past those starting lower down */
                    while (g != (r8_fid)R8_FID_END && ftop[g] > b8) {
                        link = &nx[g];
                        g = *link;
                    }
                if (g == (r8_fid)R8_FID_END)
                    break;
            } else
#endif
            {
#if R8_W_PAINTER
                if (a == (r8_fid)R8_FID_END && n == (r8_fid)R8_FID_END)
                    break;
#endif
                if (n == (r8_fid)R8_FID_END || (a != (r8_fid)R8_FID_END && a < n)) {
                    g = a;
                    a = st->next[a];
                } else {
                    g = n;
                    n = st->next[n];
                }
            }
            d = draw_face(st, g, y0, y1, fb);
#if R8_W_PAINTER
            if (paint) {
                if (d == 1)
                    *link = st->next[g];  /* finished: leaves the list */
                else
                    link = &st->next[g];
                continue;
            }
#endif
            if (d != 1) {
                *link = g;
                link = &st->next[g];
            }
        }
#if R8_W_PAINTER
        if (!paint)
#endif
            *link = (r8_fid)R8_FID_END;
    }
    st->first = head;
#ifndef R8_NO_ZBUF
    if (st->method == R8_VIS_Z16)
        r8_zkeep(st);      /* the columns r8k_zband drew: cleared next */
#endif
#ifndef R8_NO_SBUF
#if R8_W_SBUF
    if (st->method == R8_VIS_SBUF)
        r8_vis_sbuf_flush(st, fb);
#endif
#endif
}

#ifdef R8_BAND_Z80
#undef r8_render_band   /* (the firmware unit calls it below: app.c) */
#endif

#endif /* R8_PLAN_ONLY */
