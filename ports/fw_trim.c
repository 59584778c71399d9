/* fw_trim.c - link-time trimming for the target firmware (included by
 * examples/spin/fw_app.c and tests/targets/fw_sizes.c): library entry points this firmware can never reach are
 * defined here as stubs, so the linker does not pull their modules from
 * the archive.  The 6502 and Z80 images are otherwise over 64 KB.
 *   FW_TRIM_LZ77  the firmware streams with RLE (app_defaults), so the
 *                 LZ77 codec (src/lz77.c) is never called: stubs return
 *                 R8_E_ARG ("codec not built in").
 *   FW_RENDER     src/render.c itself, built with this firmware's
 *                 R8_NO_* switches (docs/benchmarks.md: the flash each
 *                 part costs); on AVR and the 6502 src/wire.c too, its codecs chosen
 *                 at compile time (R8_NO_LZ77).
 *   FW_SPIN       a mesh scene's firmware (R8_NO_PORTAL: objects that
 *                 only turn in place, no walks, no moving objects, and a
 *                 camera that stays put): src/proj.c built in with
 *                 R8_PROJ16 (no 32-bit projection fallback) and
 *                 transform.c with R8_CAM_FIXED (no camera rotation).
 *                 fw_spin_bad() proves both before the first frame
 *                 (fw_app.c: APP_E_CFG if not; with the scene's object
 *                 count fixed, FW_SPIN_SETUP, examples/spin/app.c's
 *                 app_demo as it sets the run up): the camera is not turned,
 *                 and every camera-space x, y lies within 16 (|d| +
 *                 radius) + 4 of the origin, d = object - camera.
 *                 On AVR, the 6502 and the Z80 (with cull_z80.s, R8_ASM_CULL) also
 *                 R8_CULL16: render.c's back-face test is
 *                 r8k_cull alone (16 bits, flash normals), without the
 *                 32-bit r8_cull_front (564 B); fw_spin_bad proves the
 *                 eye within |d| <= 1000 units of each object and its
 *                 radius <= 1023 (r8k_cull's ranges).
 * The identity tests prove the stream unchanged against the host build,
 * which links the whole library. */
#ifdef FW_TRIM_LZ77
#include "r8codec.h"
int r8_lz77_encode(const r8_u8 *src, unsigned n, r8_u8 *dst, unsigned cap,
                   unsigned *out_len)
{
    (void)src; (void)n; (void)dst; (void)cap;
    *out_len = 0;
    return R8_E_ARG;
}
int r8_lz77_decode(const r8_u8 *src, unsigned n, r8_u8 *dst, unsigned cap,
                   unsigned *out_len)
{
    (void)src; (void)n; (void)dst; (void)cap;
    *out_len = 0;
    return R8_E_ARG;
}
#endif
#ifdef FW_SPIN
#ifndef R8_NO_PORTAL
#error "FW_SPIN: for mesh scenes only (a walk or moving objects break its proof)"
#endif
#define R8_PROJ16
#define R8_CAM_FIXED
#if (defined(__AVR__) || defined(__CC65__) || (defined(__SDCC) && defined(R8_ASM_CULL))) && \
    defined(R8_NO_RT_NORMALS)
#define R8_CULL16     /* the back-face test in 16 bits alone (r8k_cull:
                       * flash normals): no r8_cull_front (6502: 795 B) */
#endif
/* 6502 and Z80 (R8_ASM_PROJECT): ports/6502/proj_6502.s and
 * ports/z80/project_z80.s hand r8_project_recip a point only when its
 * shift sh <= 0, its guard band is 1024 px or more, or x or y is
 * outside +-32767 (the Z80 firmware unit learns of its kernel from
 * mk/targets.mk's FWK_z80).  Here r8_proj_init sets the guard
 * (900 px) and fw_spin_bad proves x and y within 16 (|d| + radius) + 4
 * <= 32644: only sh <= 0 is left, where the C version projects the axis
 * alone (to cx, cy) and refuses any other point.  So that is all the
 * r8_project_recip below does; proj.c's, under another name, is
 * linked only if something else calls it (r8_project). */
#if (defined(__CC65__) || defined(__SDCC)) && defined(R8_ASM_PROJECT)
#define FW_PROJ_AXIS 1
#include "r8fixed.h"
#define r8_project_recip fw_project_recip_full
int r8_project_recip(const r8_proj *p, const r8_vec3l *v, r8_u16 m, r8_s8 e,
                     r8_s16 *sx, r8_s16 *sy);
#endif
#include "proj.c"
#ifdef FW_PROJ_AXIS
#undef r8_project_recip
int r8_project_recip(const r8_proj *p, const r8_vec3l *v, r8_u16 m, r8_s8 e,
                     r8_s16 *sx, r8_s16 *sy)
{
    (void)m; (void)e;
    if (v->x || v->y)
        return 1;
    *sx = p->cx;
    *sy = p->cy;
    return 0;
}
#endif
/* 1 unless the demo scene's camera is not turned and no vertex can
 * reach a camera-space x or y beyond 16 bits: per object |dx| + |dy| +
 * |dz| + radius (world units) against 2040 (16 x 2040 + rounding <
 * 32767).  (r8_demo_pose turns only the objects: these stay.)
 * FW_SPIN_SETUP: the demo firmware of a mesh scene (its object count
 * fixed, fw_app.c R8_CFG_NOBJ) proves the same in app.c's app_demo,
 * which sets the camera up at the origin itself: no fw_spin_bad. */
#if defined(FW_RENDER) && defined(R8_CFG_NOBJ)
#define FW_SPIN_SETUP 1
#else
static int fw_spin_bad(const app_cfg *c)
{
    r8_demo_run *run = app_demo(c);
    r8_u8 i;
    if (!run)
        return 0;                    /* app_run reports the scene */
    if (run->cam.yaw || run->cam.pitch || run->cam.roll || run->cam.flags ||
        run->scene.grid)
        return 1;
    for (i = 0; i < run->scene.nobjects; i++) {
        const r8_object *o = &run->obj[i];
        const r8_s16 *p = &o->pose.x, *q = &run->cam.x;
        r8_s16 r = o->mesh->radius;
        r8_u16 b = 0, d;             /* (16 bits: each term <= 2040) */
        r8_u8 k;
        if (r < 0 || r > 2040)
            return 1;
        for (k = 0; k < 3; k++) {
            /* |p - q| (up to 65535: unsigned, no overflow) */
            if (p[k] >= q[k])
                d = (r8_u16)((r8_u16)p[k] - (r8_u16)q[k]);
            else
                d = (r8_u16)((r8_u16)q[k] - (r8_u16)p[k]);
            if (d > 2040u)
                return 1;
            b = (r8_u16)(b + d);
        }
        if (b + (r8_u16)r > 2040u)
            return 1;
#ifdef R8_CULL16
        /* the eye within 16383/16 units of the model origin (r8_tf_frame's
         * eye16: |R^T d| <= |d|) and every vertex within 1023 units
         * (the radius bounds them): r8k_cull is always in range */
        if (b > 1000u || r > 1023)
            return 1;
#endif
    }
    return 0;
}
#endif
#endif
#ifdef FW_RENDER
/* The renderer compiled into the firmware with its switches (fwdefs.sh:
 * -DR8_NO_PAINTER, -DR8_NO_ZBUF, ... for every method this firmware does
 * not use): the archive's render.o is then not linked, nor are the
 * visibility methods, clipper or run-time normals it would pull in.
 * transform.c and cull.c come along: without depth methods and
 * painter's, the vertex depth and r8_muldiv drop out; without run-time
 * normals, the reads of normals from RAM. */
#include "render.c"
#define R8_SCAN_GUARDED  /* only the renderer scans: inside its guard band */
/* 6502 and Z80 (R8_ASM_SCANX): ports/6502/scanx_6502.s (and
 * ports/z80/scanx_z80.s, the same test) hands r8_scanx_fill_c,
 * scan.c's C version, only a call with a Judd test pending, a band not
 * PAGE1, or a polygon whose next row lies above the band.  This
 * firmware's configuration has none of them: the normal cull (judd 0),
 * PAGE1 bands, and with no clipper and the fused fill alone every face
 * draw_face meets is a mesh face started at the band's first row
 * (r8_scanx_begin) or going on where the band above stopped (as the
 * AVR's R8_BANDK_ONLY).  So the C version is left out (6502 1,328 B, Z80 1,312 B): it is
 * compiled under another name nothing calls, and r8_scanx_fill_c below
 * stops the firmware if it were ever reached. */
#if (defined(__CC65__) || defined(__SDCC)) && defined(R8_ASM_SCANX) && defined(R8_CFG_CULL) && defined(R8_NO_CLIP) && \
    defined(R8_FAST_ONLY)
#if R8_CFG_CULL == R8_CULL_NORMAL && R8_CFG_FORMAT == R8_FMT_PAGE1
#define FW_NO_SCANX_C 1
#endif
#endif
#ifdef FW_NO_SCANX_C
#define r8_scanx_fill_c fw_scanx_fill_unused
#endif
#include "scan.c"
#ifdef FW_NO_SCANX_C
#undef r8_scanx_fill_c
void r8_scanx_fill_c(r8_scanx *s, r8_s16 ylimit, int judd, r8_fb *fb, r8_u8 level);
void r8_scanx_fill_c(r8_scanx *s, r8_s16 ylimit, int judd, r8_fb *fb, r8_u8 level)
{
    (void)s; (void)ylimit; (void)judd; (void)fb; (void)level;
    plat_exit(APP_E_CFG);          /* (never: see above) */
}
#endif
#include "transform.c"
#include "cull.c"
#if !defined(R8_NO_WIRE) && !defined(R8_PLAN_ONLY)
#include "wireframe.c"   /* FW_WIRE firmwares (fwdefs.sh) */
#endif
#ifndef R8_NO_BSP
#include "vis_bsp.c"  /* BSP firmware: its walk with this firmware's switches */
#endif
#include "app.c"     /* its demo run sized for this scene (R8_DEMO_MAXOBJ) */
#if (defined(__AVR__) || defined(__CC65__) || defined(__SDCC)) && !defined(R8_PLAN_ONLY) && defined(R8_NO_RAY)
/* the wire encoder with this firmware's codec switches (fwdefs.sh: it
 * streams RLE; R8_NO_LZ77, R8_NO_HUFF, R8_NO_LZW leave the others out at
 * compile time, and its stream fixed: R8_TXCFG_* in fw_app.c): the
 * archive's wire.o, built with LZ77, is not linked.  On the 6502 and
 * the Z80 too (txband_6502.s / txband_z80.s then hand their other bands
 * to this unit's r8_tx_band_c; Z80 cube image -961 B).  (The maze's
 * firmware keeps the archive's: raycast.c has a cfg_ok of its own.) */
#include "wire.c"
#endif
#ifndef R8_NO_RAY
#include "raycast.c" /* the maze's: its texture code only where textured */
#endif
#endif
