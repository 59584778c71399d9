/* r8probe.c - the accuracy and cost probe (issue 6): renders a built-in
 * scene or a scene blob (host/rast8/scene.py to_blob) loaded at run time
 * through r8_render_cfg.custom, and writes what the reference comparison
 * needs.  Host tool only (C99).
 *
 *   r8probe [--scene S | --blob FILE] [--method M] [--shading flat|lambert|gouraud]
 *           [--cull normal|judd] [--format page1|row1|idx8] [--width W]
 *           [--height H] [--band B] [--frame N] [--count K]
 *           [--raw FILE]      frames, raw framebuffer bytes, appended
 *           [--faceid FILE]   per frame, u16 LE per pixel: 0 = background,
 *                             else 1 + global face index (objects in order)
 *           [--verts FILE]    per frame and vertex: "frame obj k sx sy z near"
 *                             (C projection, 12.4; near = 1 behind znear)
 *           [--stats]         print "dropped=N npoly=N" for the last frame
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

#define MAXM 255
#define MAXV 65536
#define MAXF 16384

static unsigned char work[1 << 21];
static unsigned char frame_buf[1024 * 1024];
static unsigned char band_buf[1024 * 1024];
static unsigned short ids[1024 * 1024];

static r8_s16 vpool[MAXV * 3];
static r8_face fpool[MAXF], fid[MAXF];
static r8_mesh meshes[MAXM], idmeshes[MAXM];
static r8_object objects[MAXM], idobjects[MAXM];
static r8_scene blob_scene, id_scene;

static int pick(const char *v, const char *const *names, int n)
{
    int i;
    for (i = 0; i < n; i++)
        if (!strcmp(v, names[i]))
            return i;
    fprintf(stderr, "r8probe: unknown value '%s'\n", v);
    exit(2);
}

static const unsigned char *bp, *bend;
static void need(size_t n)
{
    if ((size_t)(bend - bp) < n) {
        fprintf(stderr, "r8probe: blob truncated\n");
        exit(2);
    }
}
static int u8(void) { need(1); return *bp++; }
static int s8(void) { int v = u8(); return v > 127 ? v - 256 : v; }
static int u16(void) { int a = u8(); return a | (u8() << 8); }
static int s16(void) { int v = u16(); return v > 32767 ? v - 65536 : v; }

static void load_blob(const char *path)
{
    static unsigned char data[1 << 20];
    FILE *f = fopen(path, "rb");
    size_t n;
    int nm, no, i, nv = 0, nf = 0;
    if (!f) { perror(path); exit(2); }
    n = fread(data, 1, sizeof data, f);
    fclose(f);
    bp = data;
    bend = data + n;
    need(4);
    if (memcmp(bp, "R8SC", 4)) { fprintf(stderr, "r8probe: not a scene blob\n"); exit(2); }
    bp += 4;
    if (u8() != 1) { fprintf(stderr, "r8probe: blob version\n"); exit(2); }
    nm = u8();
    no = u8();
    u8();
    blob_scene.name = "blob";
    blob_scene.focal_num = (r8_s16)s16();
    blob_scene.znear = (r8_s16)s16();
    blob_scene.ambient = (r8_s16)s16();
    blob_scene.light.x = (r8_s16)s16();
    blob_scene.light.y = (r8_s16)s16();
    blob_scene.light.z = (r8_s16)s16();
    for (i = 0; i < nm; i++) {
        r8_mesh *m = &meshes[i];
        int k, mv = u8(), mf = u16();
        m->convex = (r8_u8)u8();
        m->radius = (r8_s16)s16();
        if (nv + mv > MAXV || nf + mf > MAXF) { fprintf(stderr, "r8probe: blob too big\n"); exit(2); }
        m->verts = vpool + nv * 3;
        m->faces = fpool + nf;
        m->nverts = (r8_u16)mv;
        m->nfaces = (r8_u16)mf;
        for (k = 0; k < mv * 3; k++)
            vpool[nv * 3 + k] = (r8_s16)s16();
        for (k = 0; k < mf; k++) {
            r8_face *fc = &fpool[nf + k];
            int j;
            fc->n = (r8_u8)u8();
            fc->colour = (r8_u8)u8();
            for (j = 0; j < 4; j++)
                fc->v[j] = (r8_u8)u8();
        }
        nv += mv;
        nf += mf;
    }
    for (i = 0; i < no; i++) {
        r8_object *o = &objects[i];
        int mi = u8();
        if (mi >= nm) { fprintf(stderr, "r8probe: bad mesh index\n"); exit(2); }
        o->mesh = &meshes[mi];
        o->x = (r8_s16)s16();
        o->y = (r8_s16)s16();
        o->z = (r8_s16)s16();
        o->ax = (r8_u8)u8();
        o->ay = (r8_u8)u8();
        o->az = (r8_u8)u8();
        o->sx = (r8_s8)s8();
        o->sy = (r8_s8)s8();
        o->sz = (r8_s8)s8();
    }
    blob_scene.objects = objects;
    blob_scene.nobjects = (r8_u8)no;
}

/* id_scene: a copy of sc whose objects each get their own mesh copy with
 * face colours = chunk `pass` of the global face index (+1). */
static void make_id_scene(const r8_scene *sc, int pass)
{
    int i, nf = 0;
    id_scene = *sc;
    for (i = 0; i < sc->nobjects; i++) {
        const r8_mesh *m = sc->objects[i].mesh;
        int k;
        idobjects[i] = sc->objects[i];
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
    id_scene.objects = idobjects;
}

static int total_faces(const r8_scene *sc)
{
    int i, n = 0;
    for (i = 0; i < sc->nobjects; i++)
        n += sc->objects[i].mesh->nfaces;
    return n;
}

/* Render frame f of cfg into frame_buf (full frame in cfg->format). */
static void render(const r8_render_cfg *cfg, r8_render *r, int f)
{
    r8_fb band, full;
    r8_s16 y;
    r8_fb_init(&full, frame_buf, cfg->format, cfg->width, cfg->height, 0, cfg->height);
    r8_render_frame(r, (r8_u16)f);
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

static void write_verts(FILE *out, const r8_render_cfg *cfg, const r8_scene *sc, int f)
{
    r8_camera cam;
    int i;
    r8_camera_init(&cam, cfg->width, cfg->height,
                   (r8_s16)(((r8_s32)cfg->width * sc->focal_num) >> 6), sc->znear);
    for (i = 0; i < sc->nobjects; i++) {
        const r8_object *ob = &sc->objects[i];
        r8_mat3 m;
        r8_u16 k;
        r8_u8 ax = (r8_u8)(ob->ax + (r8_u8)(ob->sx * (f & 0xFF)));
        r8_u8 ay = (r8_u8)(ob->ay + (r8_u8)(ob->sy * (f & 0xFF)));
        r8_u8 az = (r8_u8)(ob->az + (r8_u8)(ob->sz * (f & 0xFF)));
        r8_mat_rotate(&m, ax, ay, az);
        for (k = 0; k < ob->mesh->nverts; k++) {
            r8_vec3 v;
            r8_vec3l c;
            r8_s16 sx = 0, sy = 0;
            v.x = ob->mesh->verts[k * 3];
            v.y = ob->mesh->verts[k * 3 + 1];
            v.z = ob->mesh->verts[k * 3 + 2];
            r8_mat_apply(&m, &v, &c);
            c.x += ob->x;
            c.y += ob->y;
            c.z += ob->z;
            if (c.z >= cam.znear)
                r8_project(&cam, &c, &sx, &sy);
            fprintf(out, "%d %d %u %d %d %ld %d\n", f, i, (unsigned)k, sx, sy, (long)c.z,
                    c.z < cam.znear);
        }
    }
}

int main(int argc, char **argv)
{
    static const char *const shadings[] = {"flat", "lambert", "gouraud"};
    static const char *const culls[] = {"normal", "judd"};
    static const char *const formats[] = {"page1", "row1", "idx8"};
    r8_render_cfg cfg;
    r8_render r;
    const char *raw = 0, *faceid = 0, *verts = 0, *blob = 0;
    int frame = 0, count = 1, i, f, stats = 0;
    unsigned bytes;
    const r8_scene *sc;
    r8_render_defaults(&cfg);
    for (i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : "";
        if (!strcmp(a, "--stats")) { stats = 1; continue; }
        i++;
        if (!strcmp(a, "--scene")) {
            if (r8_scene_by_name(v) < 0) { fprintf(stderr, "r8probe: unknown scene %s\n", v); return 2; }
            cfg.scene = (r8_u8)r8_scene_by_name(v);
        } else if (!strcmp(a, "--blob")) blob = v;
        else if (!strcmp(a, "--method")) {
            if (r8_method_by_name(v) < 0 || r8_method_by_name(v) == R8_VIS_AUTO) {
                fprintf(stderr, "r8probe: unknown method %s\n", v);
                return 2;
            }
            cfg.method = (r8_u8)r8_method_by_name(v);
        } else if (!strcmp(a, "--shading")) cfg.shading = (r8_u8)pick(v, shadings, 3);
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
    if (blob) {
        load_blob(blob);
        cfg.custom = &blob_scene;
    }
    sc = r8_render_scene(&cfg);
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
        c.custom = &id_scene;
        for (f = frame; f < frame + count; f++) {
            memset(ids, 0, npx * sizeof ids[0]);
            for (p = 0; p < passes; p++) {
                make_id_scene(sc, p);
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
