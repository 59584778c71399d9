/* fly_host.c - the flythrough on the host (build/examples/flythrough):
 * fly.c's loop in the keyed walks' host program (examples/common/
 * walk_host.c: the UART is a file, stdout or a pty; with --pty, `rast8
 * view` on the printed device is the display and the gamepad).  See
 * --help. */
#include <stdio.h>

#include "fly.h"
#include "walk_host.h"

static unsigned long dropped;

static int run(r8_u16 frames, int (*on_frame)(void *, r8_u16), void *ctx, r8_u8 *mem, unsigned n)
{
    fly_cfg cfg;
    cfg.frames = frames;
    cfg.on_frame = on_frame;
    cfg.ctx = ctx;
    return fly_run(&cfg, mem, n);
}

static void frame(FILE *log, r8_u16 no)
{
    r8_render_stats s;
    fly_stats(&s);
    dropped += s.dropped;
    if (log) {
        const fly_state *w = fly_where();
        r8_camera c;
        fly_camera(w, &c);
        fprintf(log, "%u %04x %d %d %d %u %d %u %u %u\n", (unsigned)no, (unsigned)fly_keys(), c.x, c.y, c.z,
                (unsigned)c.yaw, (int)w->pitch, (unsigned)s.faces, (unsigned)s.clipped,
                (unsigned)s.dropped);
    }
}

static void summary(FILE *f)
{
    fprintf(f, ", %lu polygons dropped\n", dropped);
}

static const walk_app fly = {
    "flythrough",
    "A camera over the fractal terrain, steered by the display's keys, streamed\n"
    "in the rast8 display protocol (docs/protocol.md).  Keys: LEFT/RIGHT turn,\n"
    "UP/DOWN tilt, A/B fly forward/back, X/Y climb/sink.\n",
    "  --log FILE        per frame: 'frame keys x y z yaw pitch faces clipped dropped'\n"
    "                    (keys the frame was steered by, camera in world units)\n",
    "",
    fly_ram, run, fly_rx, frame, 0, summary
};

int main(int argc, char **argv)
{
    return walk_main(argc, argv, &fly);
}
