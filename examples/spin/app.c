/* app.c - the demo firmware's main loop (see app.h): render each frame
 * band by band and stream it with the display protocol.  C89, no
 * malloc, no stdio; all memory is the caller's arena.
 *
 * The application itself is a few lines; the rest of this file is the
 * harness every target shares (arena layout, the stream, host hooks):
 *     r8_demo_setup(&run, scene, width);        objects, camera (once)
 *     r8_render_init(&ren, &cfg, work, size);   cfg.scene = &run.scene
 *     per frame n:
 *         r8_demo_pose(&run, n);                the application turns the objects
 *         r8_render_frame(&ren, &run.cam);      the camera stays where it is
 *         for each band: r8_fb_set_band, r8_render_band, r8_tx_band
 * (examples/ssd1306/oled_cube.c is the same with its own mesh and pose
 * and a display instead of the stream; examples/flythrough moves the
 * camera instead.) */
#include "app.h"
#include "plat.h"
#include <stddef.h>
#include <string.h>

static r8_demo_run run;
#ifndef R8_PLAN_ONLY
static r8_tx tx;
static r8_render ren;
static r8_fb band_fb;
#endif

#ifndef R8_PAGE1_ONLY
/* Default IDX8 palette: 17 grey levels for shade indices 0..16. */
static const r8_u8 grey17[17 * 3] = {
    0, 0, 0, 16, 16, 16, 32, 32, 32, 48, 48, 48, 64, 64, 64, 80, 80, 80,
    96, 96, 96, 112, 112, 112, 128, 128, 128, 143, 143, 143, 159, 159, 159,
    175, 175, 175, 191, 191, 191, 207, 207, 207, 223, 223, 223,
    239, 239, 239, 255, 255, 255
};
#endif

void app_defaults(app_cfg *cfg)
{
    cfg->scene = R8_DEMO_CUBE;
    cfg->demo = 0;
    r8_render_defaults(&cfg->render);
    cfg->frames = 64;
    cfg->first_frame = 0;
    cfg->codec = R8_CODEC_RLE;
    cfg->full_period = 32;
    cfg->dirty = 1;
    cfg->palette = 0;
    cfg->npal = 0;
    cfg->on_band = 0;
    cfg->on_frame = 0;
    cfg->ctx = 0;
}

static void tx_cfg_from(const app_cfg *cfg, r8_tx_cfg *t)
{
    t->format = cfg->render.format;
    t->width = cfg->render.width;
    t->height = cfg->render.height;
    t->band = cfg->render.band;
    t->codec = cfg->codec;
    t->full_period = cfg->full_period;
    t->dirty = cfg->dirty;
    t->palette = cfg->palette;
    t->npal = cfg->npal;
#ifndef R8_PAGE1_ONLY
    if (cfg->render.format == R8_FMT_IDX8 && !cfg->palette) {
        t->palette = grey17;
        t->npal = 17;
    }
#endif
}

#ifdef FW_SPIN_SETUP
/* A mesh scene's demo firmware (ports/fw_trim.c: FW_SPIN, the scene's
 * object count fixed, R8_CFG_NOBJ): r8_demo_setup for that case alone,
 * with fw_spin_bad's proof in the same walk (Z80 ~1 KB less than the
 * two).  The camera stays at the origin, not turned (the run is cleared:
 * no grid, no world); each object's |x| + |y| + |z| + radius is at most
 * 2040 (R8_CULL16: |x| + |y| + |z| <= 1000, radius <= 1023), or 0
 * (APP_E_CFG), so the depth range's sums fit 16 bits: the same near and
 * far planes as r8_demo_setup's 32-bit ones.  The focal length: width *
 * focal_num / 64, a multiple of width / 64 when the width is one of 64
 * (cfg_valid refuses any width but R8_CFG_WIDTH; r8_s16 wraps as
 * r8_demo_setup's cast does). */
#ifndef __CC65__      /* (cc65 cannot evaluate it; it packs every struct) */
R8_CASSERT(app_light_after_ambient, offsetof(r8_scene, light) == offsetof(r8_scene, ambient) + 2u &&
           offsetof(r8_demo, light) == offsetof(r8_demo, ambient) + 2u && sizeof(r8_vec3) == 6u);
#endif
/* n bytes of R8_FLASH data from s to q */
static void app_rd(void *q, const void *s, r8_u8 n)
{
    r8_u8 *d = (r8_u8 *)q;
    const r8_u8 *f = (const r8_u8 *)s;
    for (; n; n--)
        *d++ = R8_RDU8(f++);
}
r8_demo_run *app_demo(const app_cfg *cfg)
{
    const r8_demo *d = cfg->demo ? cfg->demo : r8_demo_get(cfg->scene);
    const r8_demo_obj *o;
    r8_object *ob = run.obj;
    r8_s16 zn = 0x7FFF, zf = 1, z, r, *p;
    r8_u16 b;
    r8_u8 i, k;
    if (!d || R8_RDU8(&d->nobjects) != R8_CFG_NOBJ)
        return 0;
    memset(&run, 0, sizeof run);
    run.demo = d;
    o = (const r8_demo_obj *)R8_RDPTR(&d->objects);
    for (i = 0; i < R8_CFG_NOBJ; i++, o++, ob++) {
        p = &ob->pose.x;
        app_rd(&ob->mesh, &o->mesh, (r8_u8)sizeof ob->mesh);
        app_rd(p, &o->x, 6);                 /* x, y, z */
        ob->pose.colour = 16;                /* (r8_pose_identity's) */
        r = ob->mesh->radius;
        b = 0;
        for (k = 0; k < 3; k++) {
            z = p[k];
            if (z < -2040 || z > 2040)
                return 0;
            b = (r8_u16)(b + (r8_u16)(z < 0 ? -z : z));
        }
#ifdef R8_CULL16
        if (b > 1000u || r < 0 || r > 1023)
#else
        if (r < 0 || r > 2040 || b + (r8_u16)r > 2040u)
#endif
            return 0;
        if (z - r < zn)                      /* (z: the object's z) */
            zn = (r8_s16)(z - r);
        if (z + r > zf)
            zf = (r8_s16)(z + r);
    }
    run.scene.objects = run.obj;
    run.scene.nobjects = R8_CFG_NOBJ;
    app_rd(&run.scene.ambient, &d->ambient, 8);   /* ambient, light */
#if R8_CFG_WIDTH % 64 == 0
    run.cam.focal = (r8_s16)((r8_u16)R8_RDS16(&d->focal_num) * (R8_CFG_WIDTH / 64u));
#else
    run.cam.focal = (r8_s16)(r8_mul16(R8_CFG_WIDTH, R8_RDS16(&d->focal_num)) >> 6);
#endif
    z = R8_RDS16(&d->znear);
    if (zn < z)
        zn = z;
    if (zf <= zn)
        zf = (r8_s16)((r8_u16)zn + 1u);
    run.cam.znear = zn;
    run.cam.zfar = zf;
    r8_demo_pose(&run, 0);
    return &run;
}
#else
r8_demo_run *app_demo(const app_cfg *cfg)
{
    if (r8_demo_setup(&run, cfg->demo ? cfg->demo : r8_demo_get(cfg->scene),
                      cfg->render.width))
        return 0;
#if defined(FW_WALLS_ALONE) && !defined(R8_NO_PORTAL)
    if (run.scene.world)
        run.scene.nobjects = 1;   /* make bench-portal: the world's walls alone */
#endif
    return &run;
}
#endif

int app_plan(const app_cfg *cfg, app_layout *lay)
{
    r8_tx_cfg t;
    r8_render_cfg rc;
    unsigned max = 0u - 1u;
    if (!app_demo(cfg))
        return -1;
    rc = cfg->render;
    rc.scene = &run.scene;
    tx_cfg_from(cfg, &t);
    lay->work = 0;
    lay->work_size = r8_render_ram(&rc); /* 0: cfg rejected */
    lay->band_size = r8_tx_band_bytes(&t);
    lay->scratch_size = r8_tx_scratch(&t);
    if (!lay->work_size || !lay->band_size || !lay->scratch_size ||
        r8_fb_bytes(t.format, t.width, t.band) != lay->band_size)
        return -1;
    /* the sum must fit an unsigned (16 bits on the targets) */
    if (lay->work_size > max - lay->band_size ||
        lay->work_size + lay->band_size > max - lay->scratch_size)
        return -1;
    lay->band = lay->work_size;
    lay->scratch = lay->band + lay->band_size;
    lay->total = lay->scratch + lay->scratch_size;
    return 0;
}

unsigned app_ram(const app_cfg *cfg)
{
    app_layout lay;
    return app_plan(cfg, &lay) ? 0u : lay.total;
}

#ifndef R8_PLAN_ONLY   /* a sizing build (tests/targets/fw_sizes.c) stops here */
static void put(void *ctx, const r8_u8 *p, unsigned n)
{
    (void)ctx;
    plat_write(p, n);
}

/* Everything app_run needs before the first frame, in its own stack
 * frame (gone while frames are drawn: the 2 KB parts need the bytes;
 * external, so -Os does not fold it into app_run). */
#if defined(R8_FIXED_PLAN) && defined(R8_TXCFG_FORMAT) && defined(R8_NO_BSP)
/* (not the BSP firmware: its renderer's work is r8_bsp_ram's) */
#if R8_TXCFG_FORMAT == R8_FMT_PAGE1 && R8_TXCFG_FORMAT == R8_CFG_FORMAT && \
    R8_TXCFG_WIDTH == R8_CFG_WIDTH && R8_TXCFG_HEIGHT == R8_CFG_HEIGHT && R8_TXCFG_BAND == R8_CFG_BAND
#define APP_FIXED 1
#endif
#endif
#ifdef APP_FIXED
/* The demo firmware on cc65, sdcc and AVR (src/render.c R8_FIXED_PLAN, the
 * stream fixed by R8_TXCFG_*): app_plan's layout with the renderer's
 * work (FP_total, which r8_render_ram returns for the one configuration
 * it takes) and the band (PAGE1) as constants, so app_plan is not
 * linked and the set-up runs once; the stream as constants (app_tx), so
 * tx_cfg_from is not called.  What the build does not prove is still
 * checked here: cfg's stream fields against app_tx's; r8_render_init
 * refuses any other configuration (-1: APP_E_CFG, before its size: -2,
 * APP_E_RAM); the stream's scratch (r8_tx_scratch, 0 for another
 * stream) against what is left.  The arena is as app_plan lays it out
 * (work, band, scratch), which app_ram measures. */
#define APP_BAND_AT ((unsigned)FP_total)
#define APP_BAND_BYTES ((unsigned)R8_FB_PAGE1_BYTES(R8_TXCFG_WIDTH, R8_TXCFG_BAND))
#define APP_SCRATCH_AT (APP_BAND_AT + APP_BAND_BYTES)
/* what r8_fb_init checks of the band (PAGE1: APP_FIXED's condition) */
#if R8_TXCFG_WIDTH <= 0 || R8_TXCFG_HEIGHT <= 0 || R8_TXCFG_BAND <= 0 || \
    R8_TXCFG_BAND > R8_TXCFG_HEIGHT || (R8_TXCFG_BAND & 7) != 0
#error "APP_FIXED: a band r8_fb_init would refuse"
#endif
/* (app_plan refused a layout past an unsigned; this one is constant:
 * sdcc checks it, cc65 cannot evaluate FP_total in a constant expression) */
#ifndef __CC65__
R8_CASSERT(app_fixed_fits, (unsigned long)FP_total + APP_BAND_BYTES < 0xFFF0ul);
#endif
/* the stream: what tx_cfg_from makes of cfg, whose codec, full period,
 * dirty flag and palette size app_start checks against it (its format
 * and size are the renderer's, which cfg_valid checks against R8_CFG_*,
 * equal to these: APP_FIXED; no palette with PAGE1) */
static const r8_tx_cfg app_tx = {
    R8_TXCFG_FORMAT, R8_TXCFG_WIDTH, R8_TXCFG_HEIGHT, R8_TXCFG_BAND, R8_TXCFG_CODEC,
    R8_TXCFG_FULL, R8_TXCFG_DIRTY, 0, R8_TXCFG_NPAL
};
int app_start(const app_cfg *cfg, r8_u8 *mem, unsigned mem_size)
{
    r8_render_cfg rc;
    unsigned sc, ws = 0;
    int e;
    if (!app_demo(cfg) || cfg->codec != R8_TXCFG_CODEC || cfg->full_period != R8_TXCFG_FULL ||
        cfg->dirty != R8_TXCFG_DIRTY || cfg->npal != R8_TXCFG_NPAL)
        return APP_E_CFG;
    if (cfg->on_band || cfg->on_frame)
        return APP_E_CFG;          /* (host hooks: app_run calls none here) */
    rc = cfg->render;
    rc.scene = &run.scene;
    sc = r8_tx_scratch(&app_tx);
    if (mem_size >= APP_SCRATCH_AT && mem_size - APP_SCRATCH_AT >= sc)
        ws = APP_BAND_AT;                /* else r8_render_init: -2 */
    e = r8_render_init(&ren, &rc, mem, ws);
    if (e == -2 && sc)
        return APP_E_RAM;
    if (e || !sc)
        return APP_E_CFG;
    /* the band: r8_fb_init's stores, its checks proven above (#error;
     * r8_fb_bytes gives R8_FB_PAGE1_BYTES for PAGE1 and a width and rows
     * > 0: APP_BAND_BYTES), without the call (Z80 ~0.2 KB) */
    band_fb.buf = mem + APP_BAND_AT;
    band_fb.width = R8_TXCFG_WIDTH;
    band_fb.height = R8_TXCFG_HEIGHT;
    band_fb.y0 = 0;
    band_fb.rows = R8_TXCFG_BAND;
    band_fb.format = R8_TXCFG_FORMAT;
    if (r8_tx_init(&tx, &app_tx, mem + APP_SCRATCH_AT, sc, put, 0))
        return APP_E_CFG;
    return APP_OK;
}
#else
int app_start(const app_cfg *cfg, r8_u8 *mem, unsigned mem_size)
{
    app_layout lay;
    r8_tx_cfg t;
    r8_render_cfg rc;
    if (app_plan(cfg, &lay))
        return APP_E_CFG;
    if (mem_size < lay.total)
        return APP_E_RAM;
    tx_cfg_from(cfg, &t);
    rc = cfg->render;
    rc.scene = &run.scene;
    if (r8_render_init(&ren, &rc, mem + lay.work, lay.work_size) ||
        r8_fb_init(&band_fb, mem + lay.band, t.format, t.width, t.height, 0, t.band) ||
        r8_tx_init(&tx, &t, mem + lay.scratch, lay.scratch_size, put, 0))
        return APP_E_CFG;
    return APP_OK;
}
#endif

int app_run(const app_cfg *cfg, r8_u8 *mem, unsigned mem_size)
{
    r8_u16 i, no;
    r8_s16 y;
    int e = app_start(cfg, mem, mem_size);
    if (e != APP_OK)
        return e;
    plat_mark(PLAT_MARK_START);
    r8_tx_sync(&tx);
    for (i = 0; !cfg->frames || i < cfg->frames; i++) {
        no = (r8_u16)(cfg->first_frame + i);
        app_poll();                   /* the display's bytes since the last frame */
        plat_mark(PLAT_MARK_FRAME_BEGIN);
        r8_demo_pose(&run, no);            /* the spin: angle = start + turn * frame */
        r8_render_frame(&ren, &run.cam);   /* transform, cull, sort: once a frame */
        r8_tx_frame_begin(&tx, no);
#ifdef APP_FIXED
        /* (the band as app_start made it; no hooks) */
        for (y = 0; y < R8_TXCFG_HEIGHT; y = (r8_s16)(y + R8_TXCFG_BAND)) {
            r8_fb_set_band(&band_fb, y);
            r8_render_band(&ren, &band_fb);
            r8_tx_band(&tx, &band_fb);
        }
        r8_tx_frame_end(&tx);
        plat_mark(PLAT_MARK_FRAME_END);
#else
        for (y = 0; y < band_fb.height; y = (r8_s16)(y + band_fb.rows)) {
            r8_fb_set_band(&band_fb, y);
            r8_render_band(&ren, &band_fb);
            if (cfg->on_band)
                cfg->on_band(cfg->ctx, &band_fb);
            r8_tx_band(&tx, &band_fb);
        }
        r8_tx_frame_end(&tx);
        plat_mark(PLAT_MARK_FRAME_END);
        if (cfg->on_frame && cfg->on_frame(cfg->ctx, no))
            break;
#endif
    }
    plat_mark(PLAT_MARK_DONE);
    return APP_OK;
}

void app_rx(r8_u8 c)
{
    r8_tx_rx(&tx, c);
}

void app_poll(void)
{
    int c;
    while ((c = plat_getc()) >= 0)
        app_rx((r8_u8)c);
}

r8_u16 app_keys(void)
{
    return tx.keys;
}

void app_request_full(void)
{
    r8_tx_request_full(&tx);
}

r8_u32 app_bytes_out(void)
{
    return tx.bytes;
}
#endif
