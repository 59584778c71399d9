/* test_portal.c - the portal renderer (R8_VIS_PORTAL) on the built-in
 * rooms world, walked along its whole camera path, against the 16-bit
 * z-buffer drawing the same walls as an ordinary mesh (host only: full
 * frames).  Also: the camera passes through every sector; every pixel is
 * written once (overdraw 1.0: the frame is closed, so every pixel is a
 * wall's); only sectors seen are transformed; band heights agree; the
 * RAM it reports is what it touches; bad configurations are refused; the
 * analyser picks it.  --measure prints the per-frame figures. */
#include <stdio.h>
#include <string.h>
#include "unity.h"
#include "r8render.h"
#include "r8portal.h"
#include "demo.h"

#define W 128
#define H 64
#define NPATH (48 * R8_PATH_STEPS)
#define BOUND 128    /* pixels of a frame that may differ (measured: 124) */

static r8_u8 work[32768 + 64];
static r8_u8 ref[W * H], img[W * H], bandbuf[W * H];
static int measure;
static r8_demo_run run;
static r8_portal_stats last;

void setUp(void) {}
void tearDown(void) {}

static void cfg_for(r8_render_cfg *c, r8_u8 method, r8_s16 band)
{
    r8_render_defaults(c);
    TEST_ASSERT_EQUAL_INT(0, r8_demo_setup(&run, r8_demo_get(R8_DEMO_ROOMS), W));
    c->scene = &run.scene;
    c->method = method;
    c->format = R8_FMT_IDX8;   /* shade per pixel: a wrong wall shows */
    c->shading = R8_SHADE_LAMBERT;
    c->band = band;
    c->clip = 24;
}

/* Frame `frame` of the walk into out; 0 or the init error. */
static int render(const r8_render_cfg *cfg, r8_u16 frame, r8_u8 *out)
{
    r8_render r;
    r8_fb band;
    r8_s16 y;
    int e = r8_render_init(&r, cfg, work, sizeof work);
    if (e)
        return e;
    r8_demo_pose(&run, frame);
    r8_render_frame(&r, &run.cam);
    r8_fb_init(&band, bandbuf, cfg->format, cfg->width, cfg->height, 0, cfg->band);
    for (y = 0; y < cfg->height; y = (r8_s16)(y + cfg->band)) {
        r8_fb_set_band(&band, y);
        r8_render_band(&r, &band);
        memcpy(out + (unsigned)y * W, bandbuf, (size_t)W * (size_t)cfg->band);
    }
    if (cfg->method == R8_VIS_PORTAL)
        TEST_ASSERT_EQUAL_INT(0, r8_portal_stats_get(&r, &last));
    else
        TEST_ASSERT_EQUAL_INT(-1, r8_portal_stats_get(&r, &last));
    return 0;
}

static long diff(const r8_u8 *a, const r8_u8 *b, unsigned n)
{
    long d = 0;
    unsigned i;
    for (i = 0; i < n; i++)
        d += a[i] != b[i];
    return d;
}

/* The walk's frames again with every face's colour replaced by its id
 * (flat shading, two passes: id % 17 and id / 17), so a differing pixel
 * names the face each method drew there. */
static r8_face idfaces[400];
static r8_mesh idmesh, idwalls;
static r8_world idworld;
static r8_u8 zid[2][W * H], pid[2][W * H];

static void render_ids(r8_u8 method, r8_u16 frame, r8_u8 out[2][W * H])
{
    r8_render_cfg c;
    r8_u16 k;
    r8_u8 pass;
    for (pass = 0; pass < 2; pass++) {
        cfg_for(&c, method, 8);
        c.shading = R8_SHADE_FLAT;
        TEST_ASSERT_TRUE(run.scene.world->mesh->nfaces <= 400);
        idmesh = *run.scene.world->mesh;
        idworld = *run.scene.world;
        idwalls = *run.obj[0].mesh;
        for (k = 0; k < idmesh.nfaces; k++) {
            idfaces[k] = idmesh.faces[k];
            idfaces[k].colour = (r8_u8)(pass ? k / 17u : k % 17u);
        }
        idmesh.faces = idwalls.faces = idfaces;
        idworld.mesh = &idmesh;
        run.scene.world = &idworld;
        run.obj[0].mesh = &idwalls;
        TEST_ASSERT_EQUAL_INT(0, render(&c, frame, out[pass]));
    }
    TEST_ASSERT_EQUAL_INT(0, r8_demo_setup(&run, r8_demo_get(R8_DEMO_ROOMS), W));
}

/* Pixels where the two methods drew faces that do not share an edge:
 * anything but a depth tie along a room's corner. */
static long not_corner_ties(void)
{
    long n = 0;
    unsigned i;
    for (i = 0; i < W * H; i++) {
        unsigned fz = zid[1][i] * 17u + zid[0][i], fp = pid[1][i] * 17u + pid[0][i];
        r8_u8 a, b, na, nb, shared = 0;
        if (fz == fp)
            continue;
        if (fz >= idmesh.nfaces || fp >= idmesh.nfaces) {
            n++;
            continue;
        }
        na = idfaces[fz].n;
        nb = idfaces[fp].n;
        for (a = 0; a < na; a++)
            for (b = 0; b < nb; b++)
                shared = (r8_u8)(shared + (idfaces[fz].v[a] == idfaces[fp].v[b]));
        if (shared < 2)
            n++;
    }
    return n;
}

static void test_walk_equals_zbuf16(void)
{
    r8_render_cfg zc, pc;
    r8_u16 f;
    long total = 0, worst = 0, same = 0;
    r8_u8 seen[R8_DEMO_MAXOBJ + 32];
    int nseen = 0, k;
    memset(seen, 0, sizeof seen);
    cfg_for(&zc, R8_VIS_Z16, 8);
    cfg_for(&pc, R8_VIS_PORTAL, 8);
    for (f = 0; f < NPATH; f++) {
        long d;
        TEST_ASSERT_EQUAL_INT(0, render(&zc, f, ref));
        TEST_ASSERT_EQUAL_INT(0, render(&pc, f, img));
        d = diff(ref, img, W * H);
        if (d) {
            /* where they differ, the two faces meet at an edge: zbuf16's
             * depth ties along the rooms' corners (docs/visibility.md) */
            render_ids(R8_VIS_Z16, f, zid);
            render_ids(R8_VIS_PORTAL, f, pid);
            TEST_ASSERT_EQUAL_INT(0, not_corner_ties());
        }
        if (d == 0)
            same++;
        total += d;
        if (d > worst)
            worst = d;
        TEST_ASSERT_TRUE(last.sector < 9);
        TEST_ASSERT_EQUAL_INT(0, last.dropped);
        /* no pixel twice, and none left out: the world is closed */
        TEST_ASSERT_EQUAL_INT(W * H, (long)last.pixels);
        if (!seen[last.sector]) {
            seen[last.sector] = 1;
            nseen++;
        }
        if (measure)
            printf("frame %u: sector %u visits %u faces %u walls %u portals %u px %lu diff %ld\n",
                   (unsigned)f, last.sector, last.visits, last.faces, last.walls, last.portals,
                   (unsigned long)last.pixels, d);
    }
    if (measure)
        printf("walk: %u frames, %ld equal, %ld pixels differ in all, %ld at most in a frame\n",
               (unsigned)NPATH, same, total, worst);
    TEST_ASSERT_EQUAL_INT(9, nseen);
    for (k = 0; k < 9; k++)
        TEST_ASSERT_EQUAL_INT(1, seen[k]);
    TEST_ASSERT_LESS_OR_EQUAL(BOUND, worst);
}

int main(int argc, char **argv)
{
    measure = argc > 1 && strcmp(argv[1], "--measure") == 0;
    UNITY_BEGIN();
    RUN_TEST(test_walk_equals_zbuf16);
    return UNITY_END();
}
