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
    run.scene.nobjects = 1;    /* the walls alone (test_portal_obj.c: the objects) */
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
    run.scene.nobjects = 1;
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

/* Band heights change nothing (8, 16, 64 rows; every 16th frame). */
static void test_bands_agree(void)
{
    static r8_u8 full[W * H];
    r8_render_cfg c;
    r8_u16 f;
    for (f = 0; f < NPATH; f = (r8_u16)(f + 16)) {
        cfg_for(&c, R8_VIS_PORTAL, 64);
        TEST_ASSERT_EQUAL_INT(0, render(&c, f, full));
        cfg_for(&c, R8_VIS_PORTAL, 8);
        TEST_ASSERT_EQUAL_INT(0, render(&c, f, img));
        TEST_ASSERT_EQUAL_INT(0, diff(full, img, W * H));
        cfg_for(&c, R8_VIS_PORTAL, 16);
        TEST_ASSERT_EQUAL_INT(0, render(&c, f, img));
        TEST_ASSERT_EQUAL_INT(0, diff(full, img, W * H));
    }
}

/* Only the sectors seen are set up: on the walk the portal renderer
 * tests fewer faces than the world has and visits fewer sectors, and
 * the camera's sector is r8_portal_locate's. */
static void test_only_sectors_seen(void)
{
    r8_render_cfg c;
    r8_u16 f;
    unsigned most = 0, fewest = 255;
    cfg_for(&c, R8_VIS_PORTAL, 8);
    for (f = 0; f < NPATH; f = (r8_u16)(f + 8)) {
        const r8_world *w = run.scene.world;
        TEST_ASSERT_EQUAL_INT(0, render(&c, f, img));
        TEST_ASSERT_EQUAL_INT(r8_portal_locate(w, run.cam.x, run.cam.y, run.cam.z), last.sector);
        TEST_ASSERT_TRUE(last.visits >= 1 && last.visits < w->nsectors);
        TEST_ASSERT_TRUE(last.faces < w->mesh->nfaces);
        TEST_ASSERT_TRUE(last.portals == last.visits - 1u);
        if (last.visits > most) most = last.visits;
        if (last.visits < fewest) fewest = last.visits;
    }
    TEST_ASSERT_TRUE(most >= 3);       /* seen through two doors in a row */
    TEST_ASSERT_EQUAL_INT(1, fewest);  /* facing a wall: its own room only */
}

/* r8_render_ram is what the portal renderer touches: guard bytes past
 * it never change; less memory is refused with -2; a scene without a
 * world, and Gouraud shading, with -1. */
static void test_memory_and_refusals(void)
{
    r8_render_cfg c;
    r8_render r;
    unsigned need, i;
    r8_u16 f;
    cfg_for(&c, R8_VIS_PORTAL, 8);
    need = r8_render_ram(&c);
    TEST_ASSERT_TRUE(need > 0 && need + 64 <= sizeof work);
    for (f = 0; f < NPATH; f = (r8_u16)(f + 32)) {
        memset(work, 0xA5, sizeof work);
        TEST_ASSERT_EQUAL_INT(0, r8_render_init(&r, &c, work, need));
        {
            r8_fb band;
            r8_s16 y;
            r8_demo_pose(&run, f);
            r8_render_frame(&r, &run.cam);
            r8_fb_init(&band, bandbuf, c.format, W, H, 0, c.band);
            for (y = 0; y < H; y = (r8_s16)(y + c.band)) {
                r8_fb_set_band(&band, y);
                r8_render_band(&r, &band);
            }
        }
        for (i = need; i < need + 64; i++)
            TEST_ASSERT_EQUAL_INT(0xA5, work[i]);
    }
    TEST_ASSERT_EQUAL_INT(-2, r8_render_init(&r, &c, work, need - 1));
    c.shading = R8_SHADE_GOURAUD;
    TEST_ASSERT_EQUAL_INT(0, (long)r8_render_ram(&c));
    TEST_ASSERT_EQUAL_INT(-1, r8_render_init(&r, &c, work, sizeof work));
    cfg_for(&c, R8_VIS_PORTAL, 8);
    run.scene.world = 0;
    TEST_ASSERT_EQUAL_INT(0, (long)r8_render_ram(&c));
    TEST_ASSERT_EQUAL_INT(-1, r8_render_init(&r, &c, work, sizeof work));
    TEST_ASSERT_EQUAL_INT(0, strcmp("portal", r8_method_name(R8_VIS_PORTAL)));
    TEST_ASSERT_EQUAL_INT(R8_VIS_PORTAL, r8_method_by_name("portal"));
}

/* The analyser picks the portal renderer for a world, says why, and it
 * needs less memory than the 16-bit z-buffer on the same walls. */
static void test_analyser_picks_portal(void)
{
    r8_render_cfg c, z;
    r8_analysis a;
    cfg_for(&c, R8_VIS_AUTO, 8);
    c.band = 0;
    TEST_ASSERT_EQUAL_INT(0, r8_analyse(&c, &run.cam, 0, 16384u, &a));
    TEST_ASSERT_EQUAL_INT(R8_VIS_PORTAL, a.method);
    TEST_ASSERT_EQUAL_INT(R8_WHY_PORTALS, a.why);
    TEST_ASSERT_EQUAL_INT(1, a.exact);
    cfg_for(&c, R8_VIS_PORTAL, 8);
    cfg_for(&z, R8_VIS_Z16, 8);
    TEST_ASSERT_TRUE(r8_render_ram(&c) < r8_render_ram(&z));
}

int main(int argc, char **argv)
{
    measure = argc > 1 && strcmp(argv[1], "--measure") == 0;
    UNITY_BEGIN();
    RUN_TEST(test_walk_equals_zbuf16);
    RUN_TEST(test_bands_agree);
    RUN_TEST(test_only_sectors_seen);
    RUN_TEST(test_memory_and_refusals);
    RUN_TEST(test_analyser_picks_portal);
    return UNITY_END();
}
