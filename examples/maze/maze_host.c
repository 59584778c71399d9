/* maze_host.c - the maze walk on the host (build/examples/maze): maze.c's
 * loop in the keyed walks' host program (examples/common/walk_host.c:
 * the UART is a file, stdout or a pty; with --pty, `rast8 view` on the
 * printed device is the display and the gamepad).  See --help. */
#include <stdio.h>
#include <string.h>

#include "maze.h"
#include "walk_host.h"

static int run(r8_u16 frames, int (*on_frame)(void *, r8_u16), void *ctx, r8_u8 *mem, unsigned n)
{
    maze_cfg cfg;
    cfg.frames = frames;
    cfg.on_frame = on_frame;
    cfg.ctx = ctx;
    return maze_run(&cfg, mem, n);
}

static void frame(FILE *log, r8_u16 no)
{
    if (log) {
        const maze_state *w = maze_where();
        fprintf(log, "%u %04x %d %d %u\n", (unsigned)no, (unsigned)maze_keys(), w->x, w->z,
                (unsigned)w->yaw);
    }
}

static int option(const char *a)
{
    if (strcmp(a, "--textured"))
        return 0;
    maze_textured(1);
    return 1;
}

static void summary(FILE *f)
{
    fprintf(f, "\n");
}

static const walk_app maze = {
    "maze",
    "A first-person walk through the maze demo's grid, drawn by the ray caster,\n"
    "steered by the display's keys, streamed in the rast8 display protocol\n"
    "(docs/protocol.md).  Keys: LEFT/RIGHT turn, UP or A walk forward, DOWN or B back.\n",
    "  --log FILE        per frame: 'frame keys x z yaw' (the keys the\n"
    "                    frame was steered by, the camera in world units)\n",
    "  --textured        the textured maze (brick and panel walls, R8_SHADE_TEXTURE)\n",
    maze_ram, run, maze_rx, frame, option, summary
};

int main(int argc, char **argv)
{
    return walk_main(argc, argv, &maze);
}
