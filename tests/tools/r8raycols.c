/* r8raycols.c - the ray caster's columns (r8_ray_cast) for the float
 * reference (host/rast8/raycast_ref.py): the maze's grid, then, for
 * every camera line "X Z YAW FOCAL WIDTH" read from stdin, one line per
 * column: "COL H16 CX CZ SIDE CELL".
 *
 *     r8raycols [--scene NAME] < cameras.txt
 */
#include <stdio.h>
#include <string.h>
#include "demo.h"
#include "r8ray.h"

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
                   "  and H rows of cells), then per camera 'cam ...' and one line\n"
                   "  'COL H16 CX CZ SIDE CELL' per column (r8_ray_cast)\n");
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
            printf("%d %u %d %d %d %d\n", i, hit.h16, hit.cx, hit.cz, hit.side, hit.cell);
        }
    }
    return 0;
}
