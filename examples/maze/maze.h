/* maze.h - walk the maze: a first-person camera in the maze demo's grid
 * (scenes/maze.c) drawn by the ray caster (r8ray.h, R8_VIS_RAY), steered
 * by the display's keys (INPUT packets, docs/protocol.md 2.1), streamed
 * band by band in the display protocol.  The same C89 on the host and on
 * every target; output through plat.h, memory all the caller's.
 *
 * The application owns the camera and moves it from the key mask it
 * received before the frame (maze_steer):
 *     LEFT / RIGHT   turn (yaw)
 *     UP or A        walk forward     DOWN or B   walk back
 * The walker is a circle of MAZE_RADIUS units: a step into a wall is
 * taken along the other axis only (it slides along walls), so the
 * camera never enters a wall cell.
 *
 * A target's main, as examples/flythrough (fly.h):
 *     static r8_u8 mem[MAZE_RAM];         at least maze_ram() bytes
 *     plat_init();  plat_exit(maze_run(&cfg, mem, sizeof mem));
 * and its UART receive path calls maze_rx(c) for every byte from the
 * display. */
#ifndef MAZE_H
#define MAZE_H

#include "r8render.h"
#include "r8wire.h"

/* 128x64 SSD1306 pages in bands of 8 rows, distance shading, RLE, a full
 * frame every 32, dirty bands. */
#define MAZE_WIDTH 128
#define MAZE_HEIGHT 64
#define MAZE_BAND 8
#define MAZE_STEP 8          /* a step: 8 world units (a cell is 64) */
#define MAZE_TURN 4          /* a turn: 4/256 of a circle */
#define MAZE_RADIUS 12       /* the walker's distance from walls */

typedef struct maze_state {
    r8_s16 x, z;             /* world units */
    r8_u8 yaw;
} maze_state;

/* The start: the grid's start cell, its middle, its yaw. */
void maze_start(maze_state *s);
/* One frame of steering from key mask `keys` (R8_KEY_* bits). */
void maze_steer(maze_state *s, r8_u16 keys);
/* The camera of state s (focal length = width: 53 degrees across). */
void maze_camera(const maze_state *s, r8_camera *cam);

typedef struct maze_cfg {
    r8_u16 frames;           /* frames to send; 0 = forever */
    int (*on_frame)(void *ctx, r8_u16 frame);   /* after each frame; non-zero: stop */
    void *ctx;
} maze_cfg;

#define MAZE_OK 0
#define MAZE_E_CFG 1         /* the library refuses the configuration */
#define MAZE_E_RAM 2         /* arena smaller than maze_ram() */

/* The host build: walk the textured maze (scenes/maze.c, "tmaze", drawn
 * with R8_SHADE_TEXTURE) instead, or back; call before maze_ram() and
 * maze_run().  A firmware links one grid, chosen when it is built
 * (-DMAZE_TEXTURED: the textured one), and has no maze_textured. */
void maze_textured(int on);

unsigned maze_ram(void);
int maze_run(const maze_cfg *cfg, r8_u8 *mem, unsigned mem_size);
void maze_rx(r8_u8 c);
r8_u16 maze_keys(void);
const maze_state *maze_where(void);

#endif
