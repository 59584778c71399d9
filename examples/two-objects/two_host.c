/* two_host.c - the two-objects example on the host (build/examples/two-objects):
 * asks the analyser which visibility method the scene needs for a camera
 * bound, says why, and renders frames with it.  See --help. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "two.h"

static const char *prog = "two-objects";

static void usage(FILE *f)
{
    fprintf(f,
"usage: %s [options]\n"
"Two separate convex objects turning in place; the analyser picks the\n"
"visibility method for where the camera may go, and says why.\n"
"  --bound fixed        the camera stays at --camera (default)\n"
"  --bound box X0,Y0,Z0,X1,Y1,Z1   it moves inside this box (its rotation fixed)\n"
"  --bound any          it may go and turn anywhere\n"
"  --camera X,Y,Z       where it is (default 0,0,0; looking down +z)\n"
"  --turn YAW,PITCH     its rotation, 256 steps a turn (default 0,0)\n"
"  --method M           render with M instead of the analyser's choice\n"
"                       (cull painter zbuf8 zbuf16 block blockmask sbuf)\n"
"  --ram BYTES          RAM budget for the renderer and its band (default 16384)\n"
"  --frames N           frames to render (default 8)\n"
"  --raw FILE           the frames, 1024 bytes each (128x64 SSD1306 pages)\n"
"  --pgm FILE           the first frame as a picture\n"
"Prints the choice and the numbers behind it.  Exit 0, 2 on a bad option,\n"
"3 if nothing fits the budget.\n", prog);
}

static int triple(const char *s, long *v, int n)
{
    int i;
    char *end;
    for (i = 0; i < n; i++) {
        v[i] = strtol(s, &end, 10);
        if (end == s || v[i] < -30000 || v[i] > 30000 || (i < n - 1 ? *end != ',' : *end != 0))
            return -1;
        s = end + 1;
    }
    return 0;
}

static void bad(const char *what, const char *v)
{
    fprintf(stderr, "%s: bad %s '%s' (see --help)\n", prog, what, v ? v : "");
    exit(2);
}

int main(int argc, char **argv)
{
    static r8_u8 work[1 << 16], band_buf[TWO_W * TWO_H / 8], frame[TWO_W * TWO_H / 8];
    r8_render_cfg cfg;
    r8_render ren;
    r8_analysis an;
    r8_bound bound;
    r8_fb band;
    long ram = 16384, frames = 8, v[6];
    int i, method = -1, k;
    const char *raw = 0, *pgm = 0, *bname = "fixed";
    FILE *rf = 0;
    two_init();
    bound.kind = R8_BOUND_FIXED;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i], *val = i + 1 < argc ? argv[i + 1] : 0;
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            usage(stdout);
            return 0;
        } else if (!strcmp(a, "--bound") && val) {
            bname = val;
            i++;
            if (!strcmp(val, "fixed")) {
                bound.kind = R8_BOUND_FIXED;
            } else if (!strcmp(val, "any")) {
                bound.kind = R8_BOUND_ANY;
            } else if (!strcmp(val, "box") && i + 1 < argc && !triple(argv[i + 1], v, 6)) {
                bname = argv[++i];
                bound.kind = R8_BOUND_BOX;
                for (k = 0; k < 3; k++) {
                    bound.lo[k] = (r8_s16)(v[k] < v[k + 3] ? v[k] : v[k + 3]);
                    bound.hi[k] = (r8_s16)(v[k] < v[k + 3] ? v[k + 3] : v[k]);
                }
            } else {
                bad("--bound", i + 1 < argc ? argv[i + 1] : val);
            }
        } else if (!strcmp(a, "--camera") && val) {
            if (triple(val, v, 3))
                bad("--camera", val);
            two_cam.x = (r8_s16)v[0];
            two_cam.y = (r8_s16)v[1];
            two_cam.z = (r8_s16)v[2];
            i++;
        } else if (!strcmp(a, "--turn") && val) {
            if (triple(val, v, 2) || v[0] < 0 || v[0] > 255 || v[1] < -128 || v[1] > 127)
                bad("--turn", val);
            two_cam.yaw = (r8_u8)v[0];
            two_cam.pitch = (r8_u8)v[1];
            i++;
        } else if (!strcmp(a, "--method") && val) {
            if ((method = r8_method_by_name(val)) < 0)
                bad("--method", val);
            i++;
        } else if ((!strcmp(a, "--ram") || !strcmp(a, "--frames")) && val) {
            char *end;
            long n = strtol(val, &end, 0);
            if (*end || end == val || n < 1 || n > 65535)
                bad(a, val);
            if (a[2] == 'r')
                ram = n;
            else
                frames = n;
            i++;
        } else if (!strcmp(a, "--raw") && val) {
            raw = argv[++i];
        } else if (!strcmp(a, "--pgm") && val) {
            pgm = argv[++i];
        } else {
            bad("option", a);
        }
    }
    r8_render_defaults(&cfg);
    cfg.scene = &two_scene;
    cfg.method = R8_VIS_AUTO;
    cfg.band = 0;                         /* the analyser picks it */
    if (two_analyse(&cfg, &bound, (unsigned)ram, &an)) {
        fprintf(stderr, "%s: nothing fits %ld bytes\n", prog, ram);
        return 3;
    }
    printf("analyser: camera at %d,%d,%d turned %u,%d, bound %s: method %s (%s)\n", two_cam.x,
           two_cam.y, two_cam.z, (unsigned)two_cam.yaw, (int)(r8_s8)two_cam.pitch, bname, r8_method_name(an.method), two_why(an.why));
    printf("analyser: depth range %ld..%ld (one painter's bucket: %ld units), gap between "
           "the objects %ld units; band %d rows, %u bytes\n", (long)an.znear, (long)an.zfar,
           (long)((an.zfar - an.znear + 63) / 64 + 1), (long)two_gap(), an.band, an.ram);
    if (method >= 0) {
        cfg.method = (r8_u8)method;
        printf("rendering with %s (--method)\n", r8_method_name(cfg.method));
    }
    if (!r8_render_ram(&cfg) || r8_render_ram(&cfg) > sizeof work ||
        r8_render_init(&ren, &cfg, work, r8_render_ram(&cfg)) ||
        r8_fb_init(&band, band_buf, cfg.format, TWO_W, TWO_H, 0, cfg.band)) {
        fprintf(stderr, "%s: the library refuses %s with band %d\n", prog,
                r8_method_name(cfg.method), cfg.band);
        return 3;
    }
    if (raw && !(rf = fopen(raw, "wb"))) {
        perror(raw);
        return 1;
    }
    for (i = 0; i < frames; i++) {
        r8_s16 y;
        two_pose((r8_u16)i);
        r8_render_frame(&ren, &two_cam);
        for (y = 0; y < TWO_H; y = (r8_s16)(y + cfg.band)) {
            r8_fb_set_band(&band, y);
            r8_render_band(&ren, &band);
            memcpy(frame + (unsigned)y / 8u * TWO_W, band_buf,
                   r8_fb_bytes(cfg.format, TWO_W, band.rows));
        }
        if (rf && fwrite(frame, 1, sizeof frame, rf) != sizeof frame) {
            perror(raw);
            return 1;
        }
        if (pgm && i == 0) {
            FILE *f = fopen(pgm, "wb");
            int x, yy;
            if (!f) {
                perror(pgm);
                return 1;
            }
            fprintf(f, "P5\n%d %d\n255\n", TWO_W, TWO_H);
            for (yy = 0; yy < TWO_H; yy++)
                for (x = 0; x < TWO_W; x++)
                    fputc((frame[yy / 8 * TWO_W + x] >> (yy & 7)) & 1 ? 255 : 0, f);
            fclose(f);
        }
    }
    if (rf)
        fclose(rf);
    return 0;
}
