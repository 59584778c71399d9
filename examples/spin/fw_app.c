/* fw_app.c - the demo firmware's main on every target: app.c's loop
 * over a static arena sized for this scene and method on this target.
 *   FW_SCENE, FW_METHOD  R8_DEMO_*, R8_VIS_*               (default 0, 0)
 *   FW_FRAMES            frames to stream                   (default 4)
 *   FW_RAM               app_ram(cfg) measured on the target by
 *                        fw_sizes.c (mk/targets.mk passes it in)
 *   FW_POOL              scan-state pool (default R8_POOL_AUTO; the 2 KB
 *                        ATmega328P builds use 0: least RAM)
 *   FW_SHADING           R8_SHADE_* (default Lambert, texture for the
 *                        crate; make bench measures every shading)
 *   FW_WIRE              1: wireframe (cfg.render.wire; default 0)
 *   FW_SPIN              a fixed camera, no 32-bit projection
 *                        (fw_trim.c; checked here)
 * FW_HOST builds the host reference instead: scene, method and frames
 * from argv, the arena carved to exactly app_ram(cfg) bytes, plat from
 * emu/fw_plat_host.c (stdout). */
#include "plat.h"
#include "app.h"

#ifndef FW_SCENE
#define FW_SCENE 0
#endif
#ifndef FW_METHOD
#define FW_METHOD 0
#endif
#ifndef FW_FRAMES
#define FW_FRAMES 4
#endif
#ifndef FW_SHADING
#if FW_SCENE == 7 || FW_SCENE == 10
#define FW_SHADING R8_SHADE_TEXTURE   /* the crate and tmaze are textured */
#else
#define FW_SHADING R8_SHADE_LAMBERT
#endif
#endif

/* A world of sectors (the rooms) needs the clipper: the floor and
 * ceiling round the camera cross the near plane. */
#if defined(FW_HOST) || !(defined(FW_RENDER) && defined(R8_NO_PORTAL))
static void world_clip(app_cfg *c)
{
#ifndef R8_NO_PORTAL
    const r8_demo *d = r8_demo_get(c->scene);
    if (d && R8_RDPTR(&d->world))
        c->render.clip = R8_PORTAL_CLIP;
#else
    (void)c;
#endif
}
#endif

#ifdef FW_HOST
#include <stdlib.h>
static r8_u8 mem[1L << 20];
static app_cfg cfg;

int main(int argc, char **argv)
{
    unsigned need;
    plat_init();
    app_defaults(&cfg);
    cfg.render.clip = 0;   /* as the target builds: no clipper (fw_trim.c) */
    cfg.scene = (r8_u8)(argc > 1 ? atoi(argv[1]) : FW_SCENE);
    cfg.render.method = (r8_u8)(argc > 2 ? atoi(argv[2]) : FW_METHOD);
    cfg.frames = (r8_u16)(argc > 3 ? atoi(argv[3]) : FW_FRAMES);
    cfg.render.shading = (r8_u8)(argc > 4 ? atoi(argv[4]) : FW_SHADING);
    cfg.render.wire = (r8_u8)(argc > 5 ? atoi(argv[5]) : 0);
    world_clip(&cfg);
    need = app_ram(&cfg);
    if (need == 0 || need > sizeof mem)
        plat_exit(APP_E_CFG);
    plat_exit(app_run(&cfg, mem, need));
    return 0;
}
#else
/* The renderer built into this firmware (fw_trim.c, FW_RENDER) for this
 * configuration only (src/render.c: R8_CFG_METHOD): r8_render_defaults'
 * size, band and cull, PAGE1, no clipper (a mesh scene: a world's
 * firmware keeps its clipper and the general plan). */
#if defined(FW_RENDER) && defined(R8_NO_PORTAL)
/* (cc65 warns "Unreachable code" at the folded checks, a warning with no
 * name to switch off: ports/6502/cc65c.sh lets that one pass in this
 * unit and fails on any other; sdcc's warning about them is off) */
#ifdef __SDCC
#pragma disable_warning 126
#endif
#if FW_METHOD == R8_VIS_BSP
#define R8_CFG_METHOD R8_VIS_PAINTER   /* (vis_bsp.c plans and sets up its
                                          painter's renderer) */
#else
#define R8_CFG_METHOD FW_METHOD
#endif
#define R8_CFG_SHADING FW_SHADING
#define R8_CFG_CULL R8_CULL_NORMAL
#define R8_CFG_FORMAT R8_FMT_PAGE1
#define R8_CFG_WIDTH 128
#define R8_CFG_HEIGHT 64
#define R8_CFG_BAND 8
#define R8_CFG_CLIP 0
#ifdef FW_POOL
#define R8_CFG_POOL FW_POOL
#else
#define R8_CFG_POOL R8_POOL_AUTO
#endif
#ifdef FW_NVERTS      /* its scene's sizes (ports/scene_strip.py --counts) */
#define R8_CFG_NOBJ FW_NOBJ
#define R8_CFG_NVERTS FW_NVERTS
#define R8_CFG_NFACES FW_NFACES
#endif
/* and its stream (src/wire.c, built into the AVR firmware): app_defaults' */
#define R8_TXCFG_FORMAT R8_FMT_PAGE1
#define R8_TXCFG_WIDTH 128
#define R8_TXCFG_HEIGHT 64
#define R8_TXCFG_BAND 8
#define R8_TXCFG_CODEC R8_CODEC_RLE
#define R8_TXCFG_FULL 32
#define R8_TXCFG_DIRTY 1
#define R8_TXCFG_NPAL 0
#endif
#include "fw_trim.c"
#ifndef FW_RAM
#define FW_RAM 1
#endif
static r8_u8 mem[FW_RAM];

#ifdef R8_CFG_METHOD
/* A mesh scene's firmware (its configuration fixed above): cfg as
 * app_defaults() leaves it with main's changes below, as data, so
 * neither app_defaults nor r8_render_defaults is linked; world_clip
 * is not needed (R8_NO_PORTAL: no world).
 * What the build does not prove stays checked at run time: the
 * renderer's cfg_valid takes R8_CFG_* only and the stream's cfg_ok
 * R8_TXCFG_* only (APP_E_CFG otherwise), so a field set wrong here
 * stops the firmware, never draws wrong. */
#ifdef FW_POOL
#define FW_CFG_POOL FW_POOL
#else
#define FW_CFG_POOL R8_POOL_AUTO
#endif
#ifdef FW_WIRE
#define FW_CFG_WIRE FW_WIRE
#else
#define FW_CFG_WIRE 0
#endif
#ifdef FW_TEXFILTER
#define FW_CFG_TEXF FW_TEXFILTER
#else
#define FW_CFG_TEXF R8_TEXF_NEAREST
#endif
#ifdef FW_PERSP
#define FW_CFG_PERSP FW_PERSP
#else
#define FW_CFG_PERSP 0
#endif
static app_cfg cfg = {
    FW_SCENE, 0,
    /* render: scene (app_run's), method, shading, cull, format, width,
     * height, band, clip (none: fw_trim.c), pool, wire, texfilter,
     * persp */
    { 0, FW_METHOD, FW_SHADING, R8_CULL_NORMAL, R8_FMT_PAGE1, 128, 64, 8, 0,
      FW_CFG_POOL, FW_CFG_WIRE, FW_CFG_TEXF, FW_CFG_PERSP },
    /* frames, first frame, codec, full period, dirty, palette, npal,
     * on_band, on_frame, ctx */
    FW_FRAMES, 0, R8_CODEC_RLE, 32, 1, 0, 0, 0, 0, 0
};
#else
static app_cfg cfg;
#endif

int main(void)
{
    plat_init();
#ifndef R8_CFG_METHOD
    app_defaults(&cfg);
    cfg.render.clip = 0;   /* built without the clipper (fw_trim.c) */
#ifdef FW_POOL
    cfg.render.pool = FW_POOL;
#endif
    cfg.scene = FW_SCENE;
    cfg.render.method = FW_METHOD;
    cfg.render.shading = FW_SHADING;
#ifdef FW_PERSP
    cfg.render.persp = FW_PERSP;            /* texture variants (make bench) */
#endif
#ifdef FW_TEXFILTER
    cfg.render.texfilter = FW_TEXFILTER;
#endif
    cfg.frames = FW_FRAMES;
#ifdef FW_WIRE
    cfg.render.wire = FW_WIRE;
#endif
    world_clip(&cfg);
#endif
#if defined(FW_SPIN) && !defined(FW_SPIN_SETUP)   /* (else app_demo proves it) */
    if (fw_spin_bad(&cfg))
        plat_exit(APP_E_CFG);    /* built for a fixed camera, 16-bit points */
#endif
    plat_exit(app_run(&cfg, mem, sizeof mem));
    return 0;
}
#endif
