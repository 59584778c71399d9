/* r8probe.c - the accuracy and cost probe (issue 6): renders a built-in
 * scene or a scene blob (host/rast8/scene.py to_blob) loaded at run time
 * (scenes/blob.c), and writes what the reference comparison
 * needs.  Host tool only (C99).
 *
 *   r8probe [--scene S | --blob FILE] [--method M] [--shading flat|lambert|gouraud|texture]
 *           [--persp N] [--texfilter nearest|bilinear]
 *           [--cull normal|judd] [--format page1|row1|idx8] [--width W]
 *           [--height H] [--band B] [--frame N] [--count K]
 *           [--raw FILE]      frames, raw framebuffer bytes, appended
 *           [--faceid FILE]   per frame, u16 LE per pixel: 0 = background,
 *                             else 1 + global face index (objects in order)
 *           [--verts FILE]    per frame and vertex: "frame obj k sx sy z near"
 *                             (C projection, 12.4; near = 1 behind znear)
 *           [--stats]         print "dropped=N npoly=N" for the last frame
 *           [--normals]       print r8_mesh_normals of every object's mesh,
 *                             "obj face nx ny nz", computed in C at run time
 * Face ids come from rendering flat IDX8 with each face's colour set to
 * its id (two passes when there are more than 254 faces); the visibility
 * method, cull and band are the ones given, so ids show which surface the
 * method put on each pixel. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "r8render.h"
#include "r8scene.h"
#include "r8fixed.h"
#include "../../src/r8int.h"

#include "demo.h"
#include "blob.h"

#define MAXF 16384

static unsigned char work[1 << 21];
static unsigned char frame_buf[1024 * 1024];
static unsigned char band_buf[1024 * 1024];
static unsigned short ids[1024 * 1024];

static r8_face fid[MAXF];
static r8_mesh idmeshes[R8_DEMO_MAXOBJ];
static r8_demo_obj idobjects[R8_DEMO_MAXOBJ];
static r8_demo id_demo;
static r8_demo_run run;

static int pick(const char *v, const char *const *names, int n)
{
    int i;
    for (i = 0; i < n; i++)
        if (!strcmp(v, names[i]))
            return i;
    fprintf(stderr, "r8probe: unknown value '%s'\n", v);
    exit(2);
}

/* id_demo: a copy of d whose objects each get their own mesh copy with
 * face colours = chunk `pass` of the global face index (+1). */
static void make_id_demo(const r8_demo *d, int pass)
{
    int i, nf = 0;
    id_demo = *d;
    for (i = 0; i < d->nobjects; i++) {
        const r8_mesh *m = d->objects[i].mesh;
        int k;
        idobjects[i] = d->objects[i];
        idmeshes[i] = *m;
        idmeshes[i].faces = fid + nf;
        for (k = 0; k < m->nfaces; k++) {
            int g = nf + k;
            fid[g] = m->faces[k];
            fid[g].colour = (r8_u8)(pass == 0 ? g % 255 + 1 : g / 255 + 1);
        }
        idobjects[i].mesh = &idmeshes[i];
        nf += m->nfaces;
    }
    id_demo.objects = idobjects;
}

static int total_faces(const r8_demo *d)
{
    int i, n = 0;
    for (i = 0; i < d->nobjects; i++)
        n += d->objects[i].mesh->nfaces;
    return n;
}

/* Render frame f of cfg into frame_buf (full frame in cfg->format). */
static void render(const r8_render_cfg *cfg, r8_render *r, int f)
{
    r8_fb band, full;
    r8_s16 y;
    r8_fb_init(&full, frame_buf, cfg->format, cfg->width, cfg->height, 0, cfg->height);
    r8_demo_pose(&run, (r8_u16)f);
    r8_render_frame(r, &run.cam);
    r8_fb_init(&band, band_buf, cfg->format, cfg->width, cfg->height, 0, cfg->band);
    for (y = 0; y < cfg->height; y = (r8_s16)(y + cfg->band)) {
        r8_s16 yy, x;
        r8_fb_set_band(&band, y);
        r8_render_band(r, &band);
        for (yy = y; yy < y + cfg->band && yy < cfg->height; yy++)
            for (x = 0; x < cfg->width; x++)
                r8_fb_pixel(&full, x, yy, r8_fb_get(&band, x, yy));
    }
}

static void init(r8_render *r, const r8_render_cfg *cfg)
{
    if (!r8_render_ram(cfg) || r8_render_init(r, cfg, work, sizeof work)) {
        fprintf(stderr, "r8probe: invalid configuration (or work memory too small: %u)\n",
                r8_render_ram(cfg));
        exit(2);
    }
}

/* The renderer's own projection of every vertex (the demo camera sits
 * at the origin with no rotation: camera space = world space). */
static void write_verts(FILE *out, const r8_render_cfg *cfg, const r8_demo *d, int f)
{
    r8_proj cam;
    int i;
    r8_proj_init(&cam, cfg->width, cfg->height, run.cam.focal, (r8_s32)d->znear * R8_CSCALE);
    r8_demo_pose(&run, (r8_u16)f);
    for (i = 0; i < d->nobjects; i++) {
        const r8_object *ob = &run.obj[i];
        r8_mat3 m;
        r8_u16 k;
        r8_mat_rotate(&m, ob->pose.ax, ob->pose.ay, ob->pose.az);
        for (k = 0; k < ob->mesh->nverts; k++) {
            r8_vec3 v;
            r8_vec3l c;
            r8_s16 sx = 0, sy = 0;
            int near;
            v.x = ob->mesh->verts[k * 3];
            v.y = ob->mesh->verts[k * 3 + 1];
            v.z = ob->mesh->verts[k * 3 + 2];
            r8_mat_apply16(&m, &v, &c);
            c.x += (r8_s32)ob->pose.x * R8_CSCALE;
            c.y += (r8_s32)ob->pose.y * R8_CSCALE;
            c.z += (r8_s32)ob->pose.z * R8_CSCALE;
            near = c.z < cam.znear;
            if (!near && r8_project(&cam, &c, &sx, &sy))
                near = 1;   /* outside the guard band: clipped, not projected */
            fprintf(out, "%d %d %u %d %d %ld %d\n", f, i, (unsigned)k, sx, sy,
                    (long)(c.z >> R8_CFRAC), near);
        }
    }
}

int main(int argc, char **argv)
{
    static const char *const shadings[] = {"flat", "lambert", "gouraud", "texture"};
    static const char *const filters[] = {"nearest", "bilinear"};
    static const char *const culls[] = {"normal", "judd"};
    static const char *const formats[] = {"page1", "row1", "idx8"};
    r8_render_cfg cfg;
    r8_render r;
    const char *raw = 0, *faceid = 0, *verts = 0, *blob = 0;
    int frame = 0, count = 1, i, f, stats = 0, normals = 0;
    unsigned bytes;
    const r8_demo *sc = r8_demo_get(R8_DEMO_CUBE);
    char err[160];
    r8_render_defaults(&cfg);
    for (i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : "";
        if (!strcmp(a, "--stats")) { stats = 1; continue; }
        if (!strcmp(a, "--normals")) { normals = 1; continue; }
        i++;
        if (!strcmp(a, "--scene")) {
            if (r8_demo_by_name(v) < 0) { fprintf(stderr, "r8probe: unknown scene %s\n", v); return 2; }
            sc = r8_demo_get((r8_u8)r8_demo_by_name(v));
        } else if (!strcmp(a, "--blob")) blob = v;
        else if (!strcmp(a, "--method")) {
            if (r8_method_by_name(v) < 0 || r8_method_by_name(v) == R8_VIS_AUTO) {
                fprintf(stderr, "r8probe: unknown method %s\n", v);
                return 2;
            }
            cfg.method = (r8_u8)r8_method_by_name(v);
        } else if (!strcmp(a, "--shading")) cfg.shading = (r8_u8)pick(v, shadings, 4);
        else if (!strcmp(a, "--texfilter")) cfg.texfilter = (r8_u8)pick(v, filters, 2);
        else if (!strcmp(a, "--persp")) cfg.persp = (r8_u8)atoi(v);
        else if (!strcmp(a, "--cull")) cfg.cull = (r8_u8)pick(v, culls, 2);
        else if (!strcmp(a, "--format")) cfg.format = (r8_u8)pick(v, formats, 3);
        else if (!strcmp(a, "--width")) cfg.width = (r8_s16)atoi(v);
        else if (!strcmp(a, "--height")) cfg.height = (r8_s16)atoi(v);
        else if (!strcmp(a, "--band")) cfg.band = (r8_s16)atoi(v);
        else if (!strcmp(a, "--frame")) frame = atoi(v);
        else if (!strcmp(a, "--count")) count = atoi(v);
        else if (!strcmp(a, "--raw")) raw = v;
        else if (!strcmp(a, "--faceid")) faceid = v;
        else if (!strcmp(a, "--verts")) verts = v;
        else { fprintf(stderr, "r8probe: unknown option %s\n", a); return 2; }
    }
    if (blob && r8_blob_load(blob, &sc, err, sizeof err)) {
        fprintf(stderr, "r8probe: %s\n", err);
        return 2;
    }
    if (normals) {
        static r8_s16 nbuf[3 * MAXF];
        for (i = 0; i < sc->nobjects; i++) {
            const r8_mesh *m = sc->objects[i].mesh;
            int k;
            r8_mesh_normals(m, nbuf);
            for (k = 0; k < m->nfaces; k++)
                printf("%d %d %d %d %d\n", i, k, nbuf[3 * k], nbuf[3 * k + 1], nbuf[3 * k + 2]);
        }
        return 0;
    }
    r8_demo_setup(&run, sc, cfg.width);
    cfg.scene = &run.scene;
    init(&r, &cfg);
    bytes = r8_fb_bytes(cfg.format, cfg.width, cfg.height);
    if (raw) {
        FILE *out = fopen(raw, "wb");
        if (!out) { perror(raw); return 1; }
        for (f = frame; f < frame + count; f++) {
            render(&cfg, &r, f);
            fwrite(frame_buf, 1, bytes, out);
        }
        fclose(out);
    } else if (!faceid && !verts) {
        for (f = frame; f < frame + count; f++)   /* cost runs: render only */
            render(&cfg, &r, f);
    }
    if (stats) {
        const r8_state *st = (const r8_state *)r.state;
        printf("dropped=%u npoly=%u\n", (unsigned)st->dropped, (unsigned)st->npoly);
    }
    if (faceid) {
        r8_render_cfg c = cfg;
        int passes = total_faces(sc) > 254 ? 2 : 1, p;
        unsigned npx = (unsigned)cfg.width * (unsigned)cfg.height, k;
        FILE *out = fopen(faceid, "wb");
        if (!out) { perror(faceid); return 1; }
        c.shading = R8_SHADE_FLAT;
        c.format = R8_FMT_IDX8;
        for (f = frame; f < frame + count; f++) {
            memset(ids, 0, npx * sizeof ids[0]);
            for (p = 0; p < passes; p++) {
                make_id_demo(sc, p);
                r8_demo_setup(&run, &id_demo, cfg.width);
                c.scene = &run.scene;
                init(&r, &c);
                render(&c, &r, f);
                for (k = 0; k < npx; k++)
                    if (frame_buf[k])
                        ids[k] = (unsigned short)(p == 0 ? frame_buf[k] : ids[k] + 255 * (frame_buf[k] - 1));
            }
            /* pass 0 gives g % 255 + 1, pass 1 adds 255 * (g / 255): id = g + 1 */
            for (k = 0; k < npx; k++) {
                unsigned char b[2];
                b[0] = (unsigned char)(ids[k] & 0xFF);
                b[1] = (unsigned char)(ids[k] >> 8);
                fwrite(b, 1, 2, out);
            }
        }
        fclose(out);
    }
    if (verts) {
        FILE *out = fopen(verts, "w");
        if (!out) { perror(verts); return 1; }
        for (f = frame; f < frame + count; f++)
            write_verts(out, &cfg, sc, f);
        fclose(out);
    }
    return 0;
}
