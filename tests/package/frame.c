/* frame.c - a user program built against an installed rast8 with
 * nothing but `pkg-config --cflags --libs rast8` (tests/package/check.py):
 * renders frame N of the cube (cull, 128x64 SSD1306 pages, one
 * 64-row band) and writes the 1024 framebuffer bytes to stdout.
 *   frame [N]      exit 0, or 1 with a message on stderr */
#include <stdio.h>
#include <stdlib.h>
#include "r8render.h"

static r8_u8 work[4096];
static r8_u8 buf[R8_FB_PAGE1_BYTES(128, 64)];

int main(int argc, char **argv)
{
    r8_render_cfg cfg;
    r8_render r;
    r8_fb fb;
    unsigned need;
    r8_render_defaults(&cfg);
    cfg.band = 64;
    need = r8_render_ram(&cfg);
    if (need == 0 || need > sizeof work) {
        fprintf(stderr, "frame: work memory %u > %u\n", need, (unsigned)sizeof work);
        return 1;
    }
    if (r8_render_init(&r, &cfg, work, need) != 0
        || r8_fb_init(&fb, buf, cfg.format, cfg.width, cfg.height, 0, cfg.band) != 0) {
        fprintf(stderr, "frame: init failed\n");
        return 1;
    }
    r8_render_frame(&r, (r8_u16)(argc > 1 ? atoi(argv[1]) : 0));
    r8_render_band(&r, &fb);
    if (fwrite(buf, 1, sizeof buf, stdout) != sizeof buf)
        return 1;
    return 0;
}
