/* r8raycols.c - the ray caster's columns (r8_ray_cast) for the float
 * reference (host/rast8/raycast_ref.py): the grid (and its textures),
 * then, for every camera line "X Z YAW FOCAL WIDTH" read from stdin, one
 * line per column: "COL H16 CX CZ SIDE CELL U".  A grid with textures
 * (the tmaze) also gets the frame the renderer draws textured
 * (R8_SHADE_TEXTURE, IDX8: levels 0..16, 64 rows): "r Y" and one
 * character per pixel, 0-9 a-g.
 *
 *     r8raycols [--scene NAME] < cameras.txt
 */
#include <stdio.h>
#include <string.h>
#include "demo.h"
#include "r8ray.h"

#define ROWS 64
#define MAXW 256

static r8_u8 work[16384], pix[MAXW * ROWS];

static int frame(r8_scene *sc, const r8_camera *cam, r8_s16 width)
{
    r8_render_cfg cfg;
    r8_render r;
    r8_fb fb;
    int x, y;
    r8_render_defaults(&cfg);
    cfg.scene = sc;
    cfg.method = R8_VIS_RAY;
    cfg.shading = R8_SHADE_TEXTURE;
    cfg.format = R8_FMT_IDX8;
    cfg.width = width;
    cfg.height = ROWS;
    cfg.band = ROWS;
    if (width > MAXW || r8_render_init(&r, &cfg, work, sizeof work) ||
        r8_fb_init(&fb, pix, R8_FMT_IDX8, width, ROWS, 0, ROWS))
        return -1;
    r8_render_frame(&r, cam);
    r8_render_band(&r, &fb);
    for (y = 0; y < ROWS; y++) {
        printf("r %d ", y);
        for (x = 0; x < width; x++)
            putchar("0123456789abcdefg"[r8_fb_get(&fb, (r8_s16)x, (r8_s16)y) & 31]);
        putchar('\n');
    }
    return 0;
}

int main(int argc, char **argv)
{
    const char *name = "maze";
    r8_demo_run run;
    const r8_grid *g;
    long x, z, yaw, focal, width;
    int i, j, id;
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--scene") && i + 1 < argc) {
            name = argv[++i];
        } else if (!strcmp(argv[i], "-h") || !strcmp(argv[i], "--help")) {
            printf("usage: r8raycols [--scene NAME] < cameras\n"
                   "  stdin: lines 'X Z YAW FOCAL WIDTH'; stdout: the grid ('grid W H SHIFT'\n"
                   "  and H rows of cells; 'tex N', then per texture 'W H FORMAT' and its\n"
                   "  texels 0..255), then per camera 'cam ...' and one line\n"
                   "  'COL H16 CX CZ SIDE CELL U' per column (r8_ray_cast); with textures\n"
                   "  also the textured frame, 64 lines 'r Y LEVELS' (0-9a-g)\n");
            return 0;
        } else {
            fprintf(stderr, "r8raycols: unknown argument '%s' (see --help)\n", argv[i]);
            return 2;
        }
    }
    id = r8_demo_by_name(name);
    if (id < 0 || r8_demo_setup(&run, r8_demo_get((r8_u8)id), 128) || !run.scene.grid) {
        fprintf(stderr, "r8raycols: '%s' is not a grid scene\n", name);
        return 2;
    }
    g = run.scene.grid;
    printf("grid %d %d %d\n", g->w, g->h, g->shift);
    for (j = 0; j < g->h; j++) {
        for (i = 0; i < g->w; i++)
            printf("%s%d", i ? " " : "", g->cells[j * g->w + i]);
        printf("\n");
    }
    if (g->tex) {
        printf("tex %d\n", g->ntex);
        for (i = 0; i < g->ntex; i++) {
            const r8_texture *t = &g->tex[i];
            int tw = 1 << t->wlog, th = 1 << t->hlog, k;
            printf("%d %d %d\n", tw, th, t->format);
            for (k = 0; k < tw * th; k++) {
                int v;
                if (t->format == R8_TEX_IDX8)
                    v = t->data[k];
                else
                    v = (t->data[k >> 3] & (0x80 >> (k & 7))) ? 255 : 0;
                printf("%s%d", k ? " " : "", v);
            }
            printf("\n");
        }
    }
    while (scanf("%ld %ld %ld %ld %ld", &x, &z, &yaw, &focal, &width) == 5) {
        r8_camera cam;
        r8_ray_hit hit;
        r8_camera_defaults(&cam, (r8_s16)width);
        cam.x = (r8_s16)x;
        cam.z = (r8_s16)z;
        cam.yaw = (r8_u8)yaw;
        cam.focal = (r8_s16)focal;
        printf("cam %ld %ld %ld %ld %ld\n", x, z, yaw, focal, width);
        for (i = 0; i < width; i++) {
            if (r8_ray_cast(g, &cam, (r8_s16)width, (r8_s16)i, &hit)) {
                fprintf(stderr, "r8raycols: bad camera '%ld %ld %ld %ld %ld'\n", x, z, yaw, focal, width);
                return 2;
            }
            printf("%d %u %d %d %d %d %d\n", i, hit.h16, hit.cx, hit.cz, hit.side, hit.cell, hit.u);
        }
        if (g->tex && frame(&run.scene, &cam, (r8_s16)width)) {
            fprintf(stderr, "r8raycols: cannot draw a %ld-pixel frame\n", width);
            return 2;
        }
    }
    return 0;
}
