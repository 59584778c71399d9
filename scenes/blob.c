/* blob.c - the scene blob loader (see blob.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "blob.h"

#define MAXM 32
#define MAXV 16384
#define MAXF 16384

static r8_s16 vpool[MAXV * 3];
static r8_face fpool[MAXF];
static r8_mesh meshes[MAXM];
static r8_demo_obj objects[R8_DEMO_MAXOBJ];
static r8_demo scene;

static const unsigned char *bp, *bend;
static int ok;

static int u8(void)
{
    if (bp >= bend) {
        ok = 0;
        return 0;
    }
    return *bp++;
}
static int s8(void) { int v = u8(); return v > 127 ? v - 256 : v; }
static int u16(void) { int a = u8(); return a | (u8() << 8); }
static int s16(void) { int v = u16(); return v > 32767 ? v - 65536 : v; }

static int fail(char *err, unsigned n, const char *path, const char *why)
{
    if (n)
        sprintf(err, "%.*s: %.60s", (int)(n > 80 ? n - 70 : 8), path, why);
    return -1;
}

int r8_blob_load(const char *path, const r8_demo **out, char *err, unsigned errlen)
{
    static unsigned char data[1 << 20];
    FILE *f = fopen(path, "rb");
    size_t n;
    int nm, no, i, nv = 0, nf = 0;
    if (!f)
        return fail(err, errlen, path, "cannot open");
    n = fread(data, 1, sizeof data, f);
    fclose(f);
    bp = data;
    bend = data + n;
    ok = 1;
    if (n < 4 || memcmp(bp, "R8SC", 4))
        return fail(err, errlen, path, "not a scene blob (no R8SC header)");
    bp += 4;
    if (u8() != 1)
        return fail(err, errlen, path, "unknown blob version");
    nm = u8();
    no = u8();
    u8();
    if (nm > MAXM || no > R8_DEMO_MAXOBJ || no == 0)
        return fail(err, errlen, path, "too many meshes or objects (or none)");
    scene.name = "blob";
    scene.focal_num = (r8_s16)s16();
    scene.znear = (r8_s16)s16();
    scene.ambient = (r8_s16)s16();
    scene.light.x = (r8_s16)s16();
    scene.light.y = (r8_s16)s16();
    scene.light.z = (r8_s16)s16();
    for (i = 0; i < nm && ok; i++) {
        r8_mesh *m = &meshes[i];
        int k, mv = u8(), mf = u16();
        m->convex = (r8_u8)u8();
        m->radius = (r8_s16)s16();
        if (nv + mv > MAXV || nf + mf > MAXF)
            return fail(err, errlen, path, "scene too big");
        m->verts = vpool + nv * 3;
        m->faces = fpool + nf;
        m->normals = 0;
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
            if (ok && (fc->n < 3 || fc->n > 4 || fc->v[0] >= mv || fc->v[1] >= mv ||
                       fc->v[2] >= mv || (fc->n == 4 && fc->v[3] >= mv)))
                return fail(err, errlen, path, "bad face");
        }
        nv += mv;
        nf += mf;
    }
    for (i = 0; i < no && ok; i++) {
        r8_demo_obj *o = &objects[i];
        int mi = u8();
        if (mi >= nm)
            return fail(err, errlen, path, "bad mesh index");
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
    if (!ok)
        return fail(err, errlen, path, "blob truncated");
    scene.objects = objects;
    scene.nobjects = (r8_u8)no;
    *out = &scene;
    return 0;
}

static int ends_with(const char *s, const char *tail)
{
    size_t a = strlen(s), b = strlen(tail);
    return a >= b && !strcmp(s + a - b, tail);
}

#ifndef R8_HOST_DIR
#define R8_HOST_DIR "host"
#endif

int r8_scene_open(const char *name, const r8_demo **out, char *err, unsigned errlen)
{
    static char cmd[1200], tmp[64];
    static unsigned serial;
    FILE *f;
    int id = r8_demo_by_name(name), rc;
    if (id >= 0) {
        *out = r8_demo_get((r8_u8)id);
        return *out ? 0 : fail(err, errlen, name, "scene not linked");
    }
    f = fopen(name, "rb");
    if (!f)
        return fail(err, errlen, name, "unknown scene and no such file");
    fclose(f);
    if (!ends_with(name, ".r8s") && !ends_with(name, ".obj") &&
        !ends_with(name, ".R8S") && !ends_with(name, ".OBJ"))
        return r8_blob_load(name, out, err, errlen);
    if (strlen(name) > 900 || strchr(name, '\'') || strchr(name, '"'))
        return fail(err, errlen, name, "path too long or with quotes");
    sprintf(tmp, "/tmp/r8scene-%lu-%u.blob", (unsigned long)clock(), serial++);
    sprintf(cmd, "PYTHONPATH='%s' python3 -m rast8.scene blob '%s' '%s' >/dev/null",
            R8_HOST_DIR, name, tmp);
    rc = system(cmd);
    if (rc != 0) {
        remove(tmp);
        /* the converter printed its one line (file:line: what) on stderr */
        return fail(err, errlen, name, "the scene converter rejected it (see above)");
    }
    rc = r8_blob_load(tmp, out, err, errlen);
    remove(tmp);
    return rc;
}
