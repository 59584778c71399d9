/* portal_bench.c - the portal renderer against zbuf16 and painter's on
 * the rooms walk (host, built with -DR8_COUNT_PX: bench/bench.py --portal
 * runs it).  Every frame of the camera path, 128x64, 8 bpp, Lambert,
 * band 8, 24 clipped polygons: pixels written per pixel of the frame
 * (overdraw: every pixel of the closed world shows a wall), polygons set
 * up, vertices transformed, sectors visited and faces tested (portal),
 * pixels differing from zbuf16, and the work memory r8_render_ram gives.
 * Prints one JSON object per method, one per line. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "r8render.h"
#include "r8portal.h"
#include "demo.h"
#include "../src/r8int.h"

#define W 128
#define H 64
#define NFRAMES (48 * R8_PATH_STEPS)

static r8_u8 work[32768 + 64];
static r8_u8 img[W * H], ref[W * H], bandbuf[W * H];
static r8_demo_run run;

static r8_u8 nobj;     /* the scene's objects: all, or 1 (the walls alone) */

static void render(r8_u8 method, r8_u16 frame, r8_u8 *out, r8_render *r)
{
    r8_render_cfg c;
    r8_fb band;
    r8_s16 y;
    r8_render_defaults(&c);
    run.scene.nobjects = nobj;
    c.scene = &run.scene;
    c.method = method;
    c.format = R8_FMT_IDX8;
    c.shading = R8_SHADE_LAMBERT;
    c.band = 8;
    c.clip = 24;
    if (r8_render_init(r, &c, work, sizeof work)) {
        fprintf(stderr, "portal_bench: r8_render_init failed for method %u\n", method);
        exit(1);
    }
    r8_demo_pose(&run, frame);
    r8_render_frame(r, &run.cam);
    r8_fb_init(&band, bandbuf, c.format, W, H, 0, c.band);
    for (y = 0; y < H; y = (r8_s16)(y + c.band)) {
        r8_fb_set_band(&band, y);
        r8_render_band(r, &band);
        memcpy(out + (unsigned)y * W, bandbuf, (size_t)W * (size_t)c.band);
    }
}

static unsigned transformed(const r8_render *r)
{
    const r8_state *st = (const r8_state *)r->state;
    unsigned k, n = 0;
    for (k = 0; k < st->nverts; k++)
        n += st->sv[(unsigned)k << R8_VSH(st)] != R8_VX_TODO;
    return n;
}

int main(int argc, char **argv)
{
    /* the last run: the portal renderer on the walls alone (zbuf16 too) */
    static const r8_u8 methods[4] = {R8_VIS_PORTAL, R8_VIS_Z16, R8_VIS_PAINTER, R8_VIS_PORTAL};
    r8_render r;
    r8_render_cfg c;
    r8_u8 all;
    int k, step = argc > 1 ? atoi(argv[1]) : 1;
    if (step < 1)
        step = 1;
    if (r8_demo_setup(&run, r8_demo_get(R8_DEMO_ROOMS), W)) {
        fprintf(stderr, "portal_bench: no rooms scene in this build\n");
        return 1;
    }
    all = run.scene.nobjects;
    for (k = 0; k < 4; k++) {
        r8_u8 m = methods[k];
        double px = 0, pxmax = 0, polys = 0, verts = 0, diff = 0, visits = 0, tested = 0;
        double oseen = 0, ounseen = 0, opolys = 0;
        unsigned polymax = 0, vmax = 0, diffmax = 0, vismax = 0, testmax = 0, n = 0, f, i;
        r8_portal_stats ps;
        nobj = k == 3 ? 1 : all;
        for (f = 0; f < NFRAMES; f += (unsigned)step) {
            r8_render_stats rs;
            unsigned d = 0, tv;
            double o;
            render(R8_VIS_Z16, (r8_u16)f, ref, &r);
            r8_px_written = 0;
            render(m, (r8_u16)f, img, &r);
            o = (double)r8_px_written / (W * H);
            px += o;
            if (o > pxmax) pxmax = o;
            r8_render_stats_get(&r, &rs);
            polys += rs.faces;
            tv = transformed(&r);
            if (r8_portal_stats_get(&r, &ps) == 0) {
                polys += ps.opolys;     /* the objects' (rs: the walls') */
                tv += ps.overts;
            }
            {
                unsigned np = (unsigned)rs.faces + (m == R8_VIS_PORTAL ? (unsigned)ps.opolys : 0u);
                if (np > polymax)
                    polymax = np;
            }
            verts += tv;
            if (tv > vmax) vmax = tv;
            for (i = 0; i < W * H; i++)
                d += img[i] != ref[i];
            diff += d;
            if (d > diffmax) diffmax = d;
            if (m == R8_VIS_PORTAL) {
                visits += ps.visits;
                tested += ps.faces;
                if (ps.visits > vismax) vismax = ps.visits;
                if (ps.faces > testmax) testmax = ps.faces;
                oseen += ps.objects;
                ounseen += ps.unseen;
                opolys += ps.opolys;
            }
            n++;
        }
        run.scene.nobjects = nobj;
        r8_render_defaults(&c);
        c.scene = &run.scene;
        c.method = m;
        c.band = 8;
        c.clip = 24;
        printf("{\"method\": \"%s%s\", \"objects\": %u, \"frames\": %u, \"overdraw_mean\": %.3f, "
               "\"overdraw_max\": %.3f, \"polygons_mean\": %.1f, \"polygons_max\": %u, "
               "\"vertices_transformed_mean\": %.1f, \"vertices_transformed_max\": %u, "
               "\"vertices\": %u, \"faces\": %u, ",
               r8_method_name(m), k == 3 ? " (walls alone)" : "", nobj - 1u, n, px / n, pxmax,
               polys / n, polymax, verts / n, vmax,
               (unsigned)run.obj[0].mesh->nverts, (unsigned)run.scene.world->mesh->nfaces);
        if (m == R8_VIS_PORTAL)
            printf("\"sectors_visited_mean\": %.2f, \"sectors_visited_max\": %u, "
                   "\"sectors\": %u, \"faces_tested_mean\": %.1f, \"faces_tested_max\": %u, "
                   "\"objects_set_up_mean\": %.2f, \"objects_unseen_mean\": %.2f, "
                   "\"object_polygons_mean\": %.2f, ",
                   visits / n, vismax, (unsigned)run.scene.world->nsectors, tested / n, testmax,
                   oseen / n, ounseen / n, opolys / n);
        printf("\"pixels_differing_from_zbuf16_mean\": %.1f, \"pixels_differing_from_zbuf16_max\": %u, "
               "\"work_bytes_band8\": %u}\n", diff / n, diffmax, r8_render_ram(&c));
    }
    return 0;
}
