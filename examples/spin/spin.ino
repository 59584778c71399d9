/* spin - the rast8 demo on an Arduino: a rotating cube, rendered band
 * by band on the board and streamed over Serial in the rast8 display
 * protocol (docs/protocol.md), 128x64 pixels.  Watch it on the PC with
 *     rast8 view /dev/ttyACM0 --baud 115200
 *
 * The loop is app.c, the same code rast8-emu and every simulator
 * firmware run; this sketch is only its platform layer (plat.h) on
 * Serial.  scene.c (written by `make arduino`) is the demo scene list
 * with the cube's meshes alone (in flash).
 */
#include <r8render.h>
extern "C" {
#include "app.h"
#include "plat.h"
}

#ifndef SPIN_BAUD
#define SPIN_BAUD 115200
#endif
#ifndef SPIN_FRAMES
#define SPIN_FRAMES 0   /* frames to stream; 0 = forever */
#endif
#define SPIN_WIDTH 128
#ifndef SPIN_RAM
/* app_ram() of this configuration on AVR (larger on 32-bit boards:
 * raise it there, app_run returns APP_E_RAM when it is too small). */
#define SPIN_RAM 774
#endif

static r8_u8 arena[SPIN_RAM];
static app_cfg cfg;

/* Bytes from the viewer (a REQUEST asks for a full frame). */
static void poll_rx(void)
{
    while (Serial.available() > 0)
        app_rx((r8_u8)Serial.read());
}

void plat_init(void) { Serial.begin(SPIN_BAUD); }
void plat_putc(r8_u8 c) { poll_rx(); Serial.write(c); }
void plat_write(const r8_u8 *p, unsigned n) { poll_rx(); Serial.write(p, n); }
int plat_getc(void) { return Serial.available() > 0 ? Serial.read() : -1; }
void plat_mark(r8_u8 id) { (void)id; }
void plat_exit(int code) { (void)code; }

void setup()
{
    plat_init();
    app_defaults(&cfg);
    cfg.frames = SPIN_FRAMES;
    cfg.render.width = SPIN_WIDTH;
    cfg.render.clip = 0;    /* the camera never comes near the cube */
    app_run(&cfg, arena, sizeof arena);   /* returns APP_E_RAM if too small */
}

void loop()
{
}
