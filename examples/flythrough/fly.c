/* fly.c - the flythrough application (see fly.h).
 *
 * Why painter's: the terrain is one concave mesh, so the analyser would
 * ask for a 16-bit z-buffer (exact).  That fits the ATmega1284P but not
 * the 64 KB 6502 and Z80 images next to the clipper, so every build
 * uses painter's (faces sorted by depth, drawn far to near): a
 * heightfield seen from above is what the seed's method was made for.
 * Build with -DFLY_METHOD=R8_VIS_Z16 for the exact picture. */
#include "fly.h"
#include "demo.h"   /* the terrain scene's mesh (scenes/terrain.c) */
#include "plat.h"

static r8_object terrain;
static r8_scene scene;
static r8_camera cam;
static fly_state st;
static r8_render ren;
static r8_fb band;
static r8_tx tx;

#define STEP 80      /* a move: 5 world units (1/16 units) */
#define TURN 4       /* a turn: 4/256 of a circle */
#define TILT 2

void fly_start(fly_state *s)
{
    s->x = 0;
    s->y = -56L * 16;
    s->z = -120L * 16;
    s->yaw = 0;
    s->pitch = -16;
}

static r8_s32 clamp(r8_s32 v, r8_s32 lo, r8_s32 hi)
{
    if (v < lo)
        return lo;
    if (v > hi)
        return hi;
    return v;
}

void fly_steer(fly_state *s, r8_u16 keys)
{
    int p = s->pitch;
    if (keys & R8_KEY_LEFT)
        s->yaw = (r8_u8)(s->yaw - TURN);
    if (keys & R8_KEY_RIGHT)
        s->yaw = (r8_u8)(s->yaw + TURN);
    if (keys & R8_KEY_UP)
        p += TILT;
    if (keys & R8_KEY_DOWN)
        p -= TILT;
    if (p < FLY_PITCH_MIN)
        p = FLY_PITCH_MIN;
    if (p > FLY_PITCH_MAX)
        p = FLY_PITCH_MAX;
    s->pitch = (r8_s8)p;
    if (keys & (R8_KEY_A | R8_KEY_B)) {
        /* the view direction, camera -> world Ry(yaw) Rx(pitch) applied
         * to +z: (sin yaw cos pitch, -sin pitch, cos yaw cos pitch) */
        r8_u8 a = (r8_u8)s->pitch;
        r8_s16 cp = r8_cos(a), step = (keys & R8_KEY_A) ? STEP : -STEP;
        if ((keys & R8_KEY_A) && (keys & R8_KEY_B))
            step = 0;
        s->x += r8_mulq(r8_mulq(r8_sin(s->yaw), cp, R8_Q14), step, R8_Q14);
        s->y -= r8_mulq(r8_sin(a), step, R8_Q14);
        s->z += r8_mulq(r8_mulq(r8_cos(s->yaw), cp, R8_Q14), step, R8_Q14);
    }
    if (keys & R8_KEY_X)
        s->y -= STEP;
    if (keys & R8_KEY_Y)
        s->y += STEP;
    s->x = clamp(s->x, -FLY_XZ_MAX * 16L, FLY_XZ_MAX * 16L);
    s->z = clamp(s->z, -FLY_XZ_MAX * 16L, FLY_XZ_MAX * 16L);
    s->y = clamp(s->y, FLY_Y_TOP * 16L, FLY_Y_LOW * 16L);
}

void fly_camera(const fly_state *s, r8_camera *c)
{
    r8_camera_defaults(c, FLY_WIDTH);
    c->x = (r8_s16)r8_asr32(s->x, 4);
    c->y = (r8_s16)r8_asr32(s->y, 4);
    c->z = (r8_s16)r8_asr32(s->z, 4);
    c->yaw = s->yaw;
    c->pitch = (r8_u8)s->pitch;
    c->focal = 80;          /* 77 degrees across */
    c->znear = 4;           /* the camera stays 12 units above every peak */
    c->zfar = 400;          /* the farthest corner seen from the box */
}

static void config(r8_render_cfg *rc, r8_tx_cfg *t)
{
    const r8_demo *d = r8_demo_get(R8_DEMO_TERRAIN);
    /* the demo tables are R8_FLASH data (demo.h): read through R8_RDPTR */
    const r8_demo_obj *o = d ? (const r8_demo_obj *)R8_RDPTR(&d->objects) : 0;
    terrain.mesh = o ? (const r8_mesh *)R8_RDPTR(&o->mesh) : 0;
    r8_pose_identity(&terrain.pose);           /* the terrain at the origin */
    scene.objects = &terrain;
    scene.nobjects = 1;
    scene.ambient = 3277;                      /* 0.2 */
    scene.light.x = scene.light.y = scene.light.z = -9459;  /* from above left */
    r8_render_defaults(rc);
    rc->scene = &scene;
    rc->method = FLY_METHOD;
    rc->width = FLY_WIDTH;
    rc->height = FLY_HEIGHT;
    rc->band = FLY_BAND;
    rc->clip = FLY_CLIP;
    t->format = rc->format;
    t->width = FLY_WIDTH;
    t->height = FLY_HEIGHT;
    t->band = FLY_BAND;
    t->codec = R8_CODEC_RLE;
    t->full_period = 32;
    t->dirty = 1;
    t->palette = 0;
    t->npal = 0;
}

/* The arena: render work, then one band, then the encoder scratch. */
static unsigned plan(r8_render_cfg *rc, r8_tx_cfg *t, unsigned *work, unsigned *fb)
{
    unsigned s;
    config(rc, t);
    if (!terrain.mesh)
        return 0;
    *work = r8_render_ram(rc);
    *fb = r8_fb_bytes(t->format, t->width, t->band);
    s = r8_tx_scratch(t);
    if (!*work || !*fb || !s || *work > 0xFFFFu - *fb - s)
        return 0;
    return *work + *fb + s;
}

unsigned fly_ram(void)
{
    r8_render_cfg rc;
    r8_tx_cfg t;
    unsigned w, b;
    return plan(&rc, &t, &w, &b);
}

static void put(void *ctx, const r8_u8 *p, unsigned n)
{
    (void)ctx;
    plat_write(p, n);
}

int fly_run(const fly_cfg *cfg, r8_u8 *mem, unsigned mem_size)
{
    r8_render_cfg rc;
    r8_tx_cfg t;
    unsigned work, fb, total = plan(&rc, &t, &work, &fb);
    r8_u16 i;
    r8_s16 y;
    if (!total)
        return FLY_E_CFG;
    if (mem_size < total)
        return FLY_E_RAM;
    if (r8_render_init(&ren, &rc, mem, work) ||
        r8_fb_init(&band, mem + work, t.format, t.width, t.height, 0, t.band) ||
        r8_tx_init(&tx, &t, mem + work + fb, total - work - fb, put, 0))
        return FLY_E_CFG;
    fly_start(&st);
    plat_mark(PLAT_MARK_START);
    r8_tx_sync(&tx);
    for (i = 0; !cfg->frames || i < cfg->frames; i++) {
        plat_mark(PLAT_MARK_FRAME_BEGIN);
        fly_steer(&st, tx.keys);        /* the keys received so far */
        fly_camera(&st, &cam);
        r8_render_frame(&ren, &cam);
        r8_tx_frame_begin(&tx, i);
        for (y = 0; y < FLY_HEIGHT; y = (r8_s16)(y + FLY_BAND)) {
            r8_fb_set_band(&band, y);
            r8_render_band(&ren, &band);
            r8_tx_band(&tx, &band);
        }
        r8_tx_frame_end(&tx);
        plat_mark(PLAT_MARK_FRAME_END);
        if (cfg->on_frame && cfg->on_frame(cfg->ctx, i))
            break;
    }
    plat_mark(PLAT_MARK_DONE);
    return FLY_OK;
}

void fly_rx(r8_u8 c)
{
    r8_tx_rx(&tx, c);
}

r8_u16 fly_keys(void)
{
    return tx.keys;
}

const fly_state *fly_where(void)
{
    return &st;
}

void fly_stats(r8_render_stats *s)
{
    r8_render_stats_get(&ren, s);
}
