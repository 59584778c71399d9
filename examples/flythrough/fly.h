/* fly.h - flythrough: a camera over the seed's fractal terrain, steered
 * by the display's keys (INPUT packets, docs/protocol.md 2.1), streamed
 * band by band in the display protocol.  The same C89 on the host and
 * on every target; output through plat.h, memory all the caller's.
 *
 * The application owns the camera and moves it from the key mask it
 * received before the frame (fly_steer); the renderer sees only the
 * camera and the terrain's pose:
 *     LEFT / RIGHT   turn (yaw)          UP / DOWN   tilt (pitch)
 *     A / B          fly forward / back along the view direction
 *     X / Y          climb / sink
 * The camera stays inside FLY_BOX (world units) above the terrain.
 *
 * A target's main:
 *     static r8_u8 mem[FLY_RAM];          at least fly_ram() bytes
 *     cfg.frames = N;  cfg.on_frame = 0;  (or a hook that feeds fly_rx)
 *     plat_init();  plat_exit(fly_run(&cfg, mem, sizeof mem));
 * and its UART receive path calls fly_rx(c) for every byte the display
 * sends.  Markers as in examples/spin/app.h (PLAT_MARK_*).
 */
#ifndef FLY_H
#define FLY_H

#include "r8render.h"
#include "r8wire.h"

/* The configuration every build streams (the identity tests compare
 * them): 128x64 SSD1306 pages in bands of 8 rows, Lambert shading, RLE,
 * a full frame every 32, dirty bands.  The clipper is needed: the
 * camera flies into the terrain's bounding box, so faces cross the near
 * plane and the guard band. */
#ifndef FLY_METHOD
#define FLY_METHOD R8_VIS_PAINTER   /* see fly.c: why painter's */
#endif
#define FLY_CLIP 8                  /* clipped polygons per frame (2 at most seen) */
#define FLY_WIDTH 128
#define FLY_HEIGHT 64
#define FLY_BAND 8

/* Where the camera may go (world units; y down, so up is negative y):
 * the terrain spans -77..77 in x and z, heights -30..18. */
#define FLY_XZ_MAX 140
#define FLY_Y_TOP (-110)
#define FLY_Y_LOW (-34)             /* 4 units above the highest peak */

/* The application's state: camera position in 1/16 world units, its
 * heading and tilt (256 steps per turn). */
typedef struct fly_state {
    r8_s32 x, y, z;
    r8_u8 yaw;
    r8_s8 pitch;                    /* FLY_PITCH_MIN..FLY_PITCH_MAX */
} fly_state;
#define FLY_PITCH_MIN (-48)         /* 67.5 degrees down */
#define FLY_PITCH_MAX 16

/* The start: south of the terrain, 56 units up, looking north and down. */
void fly_start(fly_state *s);
/* One frame of steering from key mask `keys` (R8_KEY_* bits). */
void fly_steer(fly_state *s, r8_u16 keys);
/* The camera of state s (position, angles, focal length, depth range). */
void fly_camera(const fly_state *s, r8_camera *cam);

typedef struct fly_cfg {
    r8_u16 frames;                  /* frames to send; 0 = forever */
    /* after every frame (return non-zero to stop): the place to feed
     * received bytes to fly_rx when there is no receive interrupt */
    int (*on_frame)(void *ctx, r8_u16 frame);
    void *ctx;
} fly_cfg;

#define FLY_OK 0
#define FLY_E_CFG 1                 /* the library refuses the configuration */
#define FLY_E_RAM 2                 /* arena smaller than fly_ram() */

/* Arena bytes fly_run needs: render work + one band + encoder scratch
 * (0 if the library refuses the configuration, e.g. a build without
 * FLY_METHOD or the clipper). */
unsigned fly_ram(void);
/* Steer, render and stream cfg->frames frames.  FLY_OK or FLY_E_*. */
int fly_run(const fly_cfg *cfg, r8_u8 *mem, unsigned mem_size);
/* One byte from the display (REQUEST, INPUT): safe from a UART ISR. */
void fly_rx(r8_u8 c);
/* The key mask the next frame steers by; the camera state; the
 * renderer's counters of the last frame. */
r8_u16 fly_keys(void);
const fly_state *fly_where(void);
void fly_stats(r8_render_stats *s);

#endif
