/* r8dump.c - render frames of a built-in scene, or of a scene file
 * (.r8s, .obj or a scene blob), on the host and write them as raw
 * framebuffer bytes or as a PGM picture.  A test and tooling helper
 * (golden frames, reference comparisons, stability runs, previews).
 *
 *   r8dump [--scene S|FILE] [--method M] [--shading flat|lambert|gouraud]
 *          [--cull normal|judd] [--format page1|row1|idx8] [--width W]
 *          [--height H] [--band B] [--frame N] [--count K]
 *          [--pgm FILE | --raw FILE]
 * Prints "work=BYTES dropped=N" for the last frame. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "r8render.h"
#include "demo.h"
#include "blob.h"

static unsigned char work[1 << 20];
static unsigned char frame_buf[1024 * 1024];
static unsigned char band_buf[1024 * 1024];

static int pick(const char *v, const char *const *names, int n)
{
    int i;
    for (i = 0; i < n; i++)
        if (!strcmp(v, names[i]))
            return i;
    fprintf(stderr, "r8dump: unknown value '%s'\n", v);
    exit(2);
}

int main(int argc, char **argv)
{
    static const char *const shadings[] = {"flat", "lambert", "gouraud"};
    static const char *const culls[] = {"normal", "judd"};
    static const char *const formats[] = {"page1", "row1", "idx8"};
    r8_render_cfg cfg;
    r8_render r;
    static r8_demo_run run;
    const r8_demo *scene = r8_demo_get(R8_DEMO_CUBE);
    char err[200];
    r8_fb band, full;
    const char *pgm = 0, *raw = 0;
    int frame = 0, count = 1, i, f;
    unsigned need, bytes;
    r8_render_defaults(&cfg);
    for (i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : "";
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            int k;
            printf("usage: r8dump [--scene S|FILE] [--method M] [--shading flat|lambert|gouraud]\n"
                   "  [--cull normal|judd] [--format page1|row1|idx8] [--width W] [--height H]\n"
                   "  [--band B] [--frame N] [--count K] [--pgm FILE | --raw FILE]\n"
                   "Renders frames of a built-in scene, or of a .r8s/.obj/blob scene file,\n"
                   "on the host (PGM picture or raw bytes).\n"
                   "scenes:");
            for (k = 0; k < R8_DEMO_COUNT; k++)
                if (r8_demo_get((r8_u8)k))
                    printf(" %s", r8_demo_name((r8_u8)k));
            printf("\nmethods: auto (the analyser picks)");
            for (k = 0; k < R8_VIS_COUNT; k++)
                printf(" %s", r8_method_name((r8_u8)k));
            printf(" portal");
            printf("\n");
            return 0;
        }
        i++;
        if (!strcmp(a, "--scene")) {
            if (r8_scene_open(v, &scene, err, sizeof err)) { fprintf(stderr, "r8dump: %s\n", err); return 2; }
        } else if (!strcmp(a, "--method")) {
            if (r8_method_by_name(v) < 0) { fprintf(stderr, "r8dump: unknown method %s\n", v); return 2; }
            cfg.method = (r8_u8)r8_method_by_name(v);
        } else if (!strcmp(a, "--shading")) cfg.shading = (r8_u8)pick(v, shadings, 3);
        else if (!strcmp(a, "--cull")) cfg.cull = (r8_u8)pick(v, culls, 2);
        else if (!strcmp(a, "--format")) cfg.format = (r8_u8)pick(v, formats, 3);
        else if (!strcmp(a, "--width")) cfg.width = (r8_s16)atoi(v);
        else if (!strcmp(a, "--height")) cfg.height = (r8_s16)atoi(v);
        else if (!strcmp(a, "--band")) cfg.band = (r8_s16)atoi(v);
        else if (!strcmp(a, "--frame")) frame = atoi(v);
        else if (!strcmp(a, "--count")) count = atoi(v);
        else if (!strcmp(a, "--pgm")) pgm = v;
        else if (!strcmp(a, "--raw")) raw = v;
        else { fprintf(stderr, "r8dump: unknown option %s\n", a); return 2; }
    }
    r8_demo_setup(&run, scene, cfg.width);
    cfg.scene = &run.scene;
    if (cfg.method == R8_VIS_AUTO) {
        r8_analysis an;
        r8_s16 band = cfg.band;
        if (r8_analyse(&cfg, &run.cam, 0, 16384u, &an)) {
            fprintf(stderr, "r8dump: --method auto: nothing fits 16 KB for this scene\n");
            return 2;
        }
        cfg.band = band; /* the picture does not depend on the band */
        fprintf(stderr, "r8dump: analyser: method %s\n", r8_method_name(cfg.method));
    }
    need = r8_render_ram(&cfg);
    if (!need || r8_render_init(&r, &cfg, work, sizeof work)) {
        fprintf(stderr, "r8dump: invalid configuration\n");
        return 2;
    }
    bytes = r8_fb_bytes(cfg.format, cfg.width, cfg.height);
    r8_fb_init(&full, frame_buf, cfg.format, cfg.width, cfg.height, 0, cfg.height);
    for (f = frame; f < frame + count; f++) {
        r8_s16 y;
        FILE *out;
        r8_demo_pose(&run, (r8_u16)f);
        r8_render_frame(&r, &run.cam);
        r8_fb_init(&band, band_buf, cfg.format, cfg.width, cfg.height, 0, cfg.band);
        for (y = 0; y < cfg.height; y = (r8_s16)(y + cfg.band)) {
            r8_s16 yy, x;
            r8_fb_set_band(&band, y);
            r8_render_band(&r, &band);
            if (!raw && !pgm)
                continue;   /* benchmarking: render only */
            for (yy = y; yy < y + cfg.band && yy < cfg.height; yy++)
                for (x = 0; x < cfg.width; x++)
                    r8_fb_pixel(&full, x, yy, r8_fb_get(&band, x, yy));
        }
        if (raw) {
            out = fopen(raw, f == frame ? "wb" : "ab");
            if (!out) { perror(raw); return 1; }
            fwrite(frame_buf, 1, bytes, out);
            fclose(out);
        }
        if (pgm) {
            out = fopen(pgm, "wb");
            if (!out) { perror(pgm); return 1; }
            fprintf(out, "P5\n%d %d\n255\n", cfg.width, cfg.height);
            for (y = 0; y < cfg.height; y++) {
                r8_s16 x;
                for (x = 0; x < cfg.width; x++) {
                    int v = r8_fb_get(&full, x, y);
                    fputc(cfg.format == R8_FMT_IDX8 ? v * 255 / 16 : v * 255, out);
                }
            }
            fclose(out);
        }
    }
    printf("work=%u\n", need);
    return 0;
}
