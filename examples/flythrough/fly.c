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

/* the scene and the renderer's configuration (walk_loop.c: the rest) */
static int scene_config(r8_render_cfg *rc)
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
    return terrain.mesh != 0;
}

#define WALK_FN(x) fly_##x
#define WALK_UC(x) FLY_##x
#include "walk_loop.c"   /* the arena, the frame loop, rx (examples/common) */

void fly_stats(r8_render_stats *s)
{
    r8_render_stats_get(&ren, s);
}
