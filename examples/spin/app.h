/* app.h - the demo firmware's main loop, the same on the host emulator
 * and on every target (AVR, 6502, Z80).
 *
 * C89, no malloc, no stdio: output goes through plat.h (plat_write,
 * plat_mark).  The caller owns all memory: one arena of app_ram(cfg)
 * bytes holds the renderer's work memory, one band buffer and the
 * encoder scratch (app_layout says where each part starts).
 *
 * A target's main:
 *     static r8_u8 mem[APP_RAM];        size it from app_ram() on the host
 *     int main(void) {
 *         app_cfg cfg;
 *         plat_init();
 *         app_defaults(&cfg);             then change what you need
 *         plat_exit(app_run(&cfg, mem, sizeof mem));
 *     }
 * and its UART receive path (ISR or poll) calls app_rx(c) for every
 * byte the display sends (a REQUEST packet asks for a full frame).
 *
 * Markers: PLAT_MARK_START once after setup, PLAT_MARK_FRAME_BEGIN
 * before the frame's poses and r8_render_frame, PLAT_MARK_FRAME_END
 * after the frame's last band is sent, PLAT_MARK_DONE before app_run
 * returns.
 */
#ifndef APP_H
#define APP_H

#include "r8types.h"
#include "r8fb.h"
#include "r8render.h"
#include "r8codec.h"
#include "r8wire.h"
#include "demo.h"

typedef struct app_cfg {
    r8_u8 scene;            /* R8_DEMO_*: the built-in scene to spin */
    const r8_demo *demo;    /* or this one (0: the built-in `scene`) */
    r8_render_cfg render;   /* method, shading, format, size, band (the app
                               sets render.scene to its demo's scene) */
    r8_u16 frames;          /* frames to send; 0 = forever */
    r8_u16 first_frame;     /* number of the first frame */
    r8_u8 codec;            /* R8_CODEC_RLE (default), _LZ77, _RAW */
    r8_u16 full_period;     /* full frame every N frames (default 32) */
    r8_u8 dirty;            /* 1 (default): only changed bands between */
    const r8_u8 *palette;   /* IDX8 palette (RGB triples) or 0 = default */
    r8_u8 npal;
    /* Host-only hooks (leave 0 on targets): called with every rendered
     * band, and after every frame (return non-zero to stop). */
    void (*on_band)(void *ctx, const r8_fb *band);
    int (*on_frame)(void *ctx, r8_u16 frame);
    void *ctx;
} app_cfg;

/* app_run results */
#define APP_OK 0
#define APP_E_CFG 1     /* invalid configuration */
#define APP_E_RAM 2     /* arena smaller than app_ram(cfg) */

/* Defaults: the cube, r8_render_defaults (PAGE1 128x64, band 8), 64
 * frames, RLE, full frame every 32, dirty bands on. */
void app_defaults(app_cfg *cfg);

/* The demo cfg spins, set up at frame 0: objects, scene, camera (0 if
 * cfg->scene is unknown or not linked in this build). */
r8_demo_run *app_demo(const app_cfg *cfg);

/* Arena layout: offsets and sizes of the three parts. */
typedef struct app_layout {
    unsigned work, work_size;       /* renderer work memory */
    unsigned band, band_size;       /* one band buffer */
    unsigned scratch, scratch_size; /* encoder scratch */
    unsigned total;                 /* = app_ram(cfg) */
} app_layout;

/* 0 and *lay filled, or -1 for an invalid cfg. */
int app_plan(const app_cfg *cfg, app_layout *lay);
/* Total RAM in bytes the cfg needs (render work + band + encoder
 * scratch); 0 for an invalid cfg. */
unsigned app_ram(const app_cfg *cfg);

/* Render and stream cfg->frames frames.  APP_OK or APP_E_*. */
int app_run(const app_cfg *cfg, r8_u8 *mem, unsigned mem_size);
/* app_run's set-up alone (renderer, band, encoder in mem): APP_OK or an
 * APP_E_* code.  A function of its own so its stack frame is gone while
 * frames are drawn. */
int app_start(const app_cfg *cfg, r8_u8 *mem, unsigned mem_size);

/* One byte received from the display (safe to call from the UART ISR
 * while app_run runs: it only sets a flag for the next frame). */
void app_rx(r8_u8 c);
/* Every byte the port has received (plat_getc) to app_rx: app_run calls
 * it before each frame, so a polled UART needs no ISR. */
void app_poll(void);
/* The key state from the display's last INPUT packet (R8_KEY_* bits,
 * 1 = pressed; 0 before any). */
r8_u16 app_keys(void);
/* Send a full frame next. */
void app_request_full(void);
/* Bytes written so far by the current/last app_run. */
r8_u32 app_bytes_out(void);

#endif
