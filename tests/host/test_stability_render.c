/* test_stability_render.c - the whole renderer where visibility methods
 * fail (issue 6; docs/stability.md), on caller-supplied scenes
 * (demo descriptors, as the application builds them): interpenetrating polygons (4x4 block), cyclic
 * overlap and the seed's wall and pillar (painter's), polygons crossing
 * the near plane, vertices at +/-32767 whose edges overflow a 16-bit
 * cross product, objects far beyond the screen.  Every run has guard
 * bytes after the exact work memory (r8_render_ram) and after the band
 * buffer; every case states an error bound against the 16-bit z-buffer
 * or against geometry worked out by hand. */
#include <stdio.h>
#include <string.h>
#include <stdlib.h>
#include "unity.h"
#include "r8render.h"
#include "r8scene.h"
#include "demo.h"
#include "../../src/r8int.h"

#define W 128
#define H 64
#define GUARD 64
#define GB 0x5A

static r8_u8 work[65536 + GUARD];
#define WW 1024   /* the widest frame the renderer takes: 1024-pixel spans */
static r8_u8 bandmem[WW * 8 + W * H + GUARD];
static r8_u8 ref[W * H], img[W * H], tmp[W * H];
static unsigned last_dropped;
static const r8_demo *cur;      /* the scene cfg_for chose */
static r8_demo_run run;

void setUp(void) {}
void tearDown(void) {}

/* Render frame of cfg (IDX8, band rows) into out; checks the guards. */
static void render(const r8_render_cfg *cfg0, r8_u16 frame, r8_u8 *out)
{
    r8_render r;
    r8_render_cfg c = *cfg0, *cfg = &c;
    r8_fb band;
    r8_s16 y;
    unsigned need, bb = r8_fb_bytes(cfg->format, cfg->width, cfg->band), i;
    TEST_ASSERT_EQUAL_INT(0, r8_demo_setup(&run, cur, cfg->width));
    c.scene = &run.scene;
    need = r8_render_ram(cfg);
    TEST_ASSERT_TRUE(need > 0 && need + GUARD <= sizeof work);
    memset(work, GB, sizeof work);
    memset(bandmem, GB, sizeof bandmem);
    TEST_ASSERT_EQUAL_INT(0, r8_render_init(&r, cfg, work, need));
    r8_demo_pose(&run, frame);
    r8_render_frame(&r, &run.cam);
    r8_fb_init(&band, bandmem, cfg->format, cfg->width, cfg->height, 0, cfg->band);
    for (y = 0; y < cfg->height; y = (r8_s16)(y + cfg->band)) {
        r8_s16 rows = cfg->band, yy;
        r8_fb_set_band(&band, y);
        r8_render_band(&r, &band);
        if (y + rows > cfg->height)
            rows = (r8_s16)(cfg->height - y);
        for (yy = 0; yy < rows; yy++)
            memcpy(out + (unsigned)(y + yy) * (unsigned)cfg->width, bandmem + (unsigned)yy * (unsigned)cfg->width,
                   (size_t)cfg->width);
    }
    for (i = need; i < need + GUARD; i++)
        TEST_ASSERT_EQUAL_HEX8(GB, work[i]);
    for (i = bb; i < bb + GUARD; i++)
        TEST_ASSERT_EQUAL_HEX8(GB, bandmem[i]);
    last_dropped = ((const r8_state *)r.state)->dropped;
}

static void cfg_for(r8_render_cfg *c, const r8_demo *sc, r8_u8 method, r8_u8 shading)
{
    r8_render_defaults(c);
    cur = sc;
    c->method = method;
    c->shading = shading;
    c->format = R8_FMT_IDX8;
    c->band = 8;
}

static long ndiff(const r8_u8 *a, const r8_u8 *b)
{
    long d = 0;
    int i;
    for (i = 0; i < W * H; i++)
        d += a[i] != b[i];
    return d;
}

/* 4x4 blocks of ref holding more than one value (an edge or a crossing) */
static int mixed_block(const r8_u8 *f, int x, int y)
{
    int bx = x & ~3, by = y & ~3, i, j;
    for (j = 0; j < 4; j++)
        for (i = 0; i < 4; i++)
            if (f[(by + j) * W + bx + i] != f[by * W + bx])
                return 1;
    return 0;
}

/* ---- scenes ---- */

static const r8_s16 xa_v[] = {-60, -40, 170, 60, -40, 230, 60, 40, 230, -60, 40, 170};
static const r8_s16 xb_v[] = {-60, -40, 230, 60, -40, 170, 60, 40, 170, -60, 40, 230};
static const r8_face quad_f8[] = {{4, 8, {0, 1, 2, 3}}};
static const r8_face quad_f16[] = {{4, 16, {0, 1, 2, 3}}};
static const r8_face quad_f12[] = {{4, 12, {0, 1, 2, 3}}};
static const r8_mesh xa = {xa_v, quad_f8, 0, 4, 1, 0, 250};
static const r8_mesh xb = {xb_v, quad_f16, 0, 4, 1, 0, 250};
static const r8_demo_obj x_objs[] = {
    {&xa, 0, 0, 0, 0, 0, 0, 0, 0, 1},
    {&xb, 0, 0, 0, 0, 0, 0, 0, 0, 1}
};
static const r8_demo x_scene = {"x", x_objs, 2, 50, 16, 4096, {-9459, -9459, -9459} R8_DEMO_WORLD(0, 0, 0)};

/* Interpenetrating quads (an X seen from above, 60 units deep): every
 * method against the 16-bit z-buffer.  Bounds: the 4x4-block methods go
 * wrong only inside or next to blocks that the 16-bit image shows as
 * mixed (an edge or the crossing runs through them) or where 8-bit depth
 * cannot tell the quads apart (the 8-bit z-buffer is wrong there too):
 * a block's depth is one sample, taken where each polygon enters it.
 * Counts measured over the frames (docs/stability.md). */
static r8_u8 z8img[W * H];

static int block_has_diff(const r8_u8 *a, const r8_u8 *b, int x, int y)
{
    int bx = x & ~3, by = y & ~3, i, j;
    for (j = 0; j < 4; j++)
        for (i = 0; i < 4; i++)
            if (a[(by + j) * W + bx + i] != b[(by + j) * W + bx + i])
                return 1;
    return 0;
}

static void test_interpenetrating(void)
{
    static const r8_u8 methods[] = {R8_VIS_Z8, R8_VIS_BLOCK, R8_VIS_BLOCKMASK, R8_VIS_SBUF, R8_VIS_PAINTER};
    long worst[5] = {0, 0, 0, 0, 0};
    r8_u16 fr;
    unsigned m;
    for (fr = 0; fr < 64; fr = (r8_u16)(fr + 7)) {
        r8_render_cfg c;
        cfg_for(&c, &x_scene, R8_VIS_Z16, R8_SHADE_FLAT);
        render(&c, fr, ref);
        TEST_ASSERT_EQUAL_INT(0, last_dropped);
        cfg_for(&c, &x_scene, R8_VIS_Z8, R8_SHADE_FLAT);
        render(&c, fr, z8img);
        for (m = 0; m < sizeof methods; m++) {
            long d = 0;
            int x, y, unexplained = 0;
            cfg_for(&c, &x_scene, methods[m], R8_SHADE_FLAT);
            render(&c, fr, img);
            for (y = 0; y < H; y++)
                for (x = 0; x < W; x++)
                    if (img[y * W + x] != ref[y * W + x]) {
                        d++;
                        int bx, by, ok = 0;
                        for (by = y - 4; by <= y + 4; by += 4)
                            for (bx = x - 4; bx <= x + 4; bx += 4)
                                if (bx >= 0 && by >= 0 && bx < W && by < H &&
                                    (mixed_block(ref, bx, by) || block_has_diff(z8img, ref, bx, by)))
                                    ok = 1;
                        unexplained += !ok;
                    }
            if (methods[m] == R8_VIS_BLOCK || methods[m] == R8_VIS_BLOCKMASK)
                TEST_ASSERT_EQUAL_INT(0, unexplained);
            if (d > worst[m])
                worst[m] = d;
        }
    }
    TEST_ASSERT_LESS_OR_EQUAL(300, worst[0]);    /* zbuf8 */
    TEST_ASSERT_LESS_OR_EQUAL(600, worst[1]);    /* block */
    TEST_ASSERT_LESS_OR_EQUAL(300, worst[2]);    /* blockmask */
    TEST_ASSERT_LESS_OR_EQUAL(40, worst[3]);     /* sbuf: ties at the crossing (measured 34) */
    TEST_ASSERT_TRUE(worst[4] > 200);            /* painter's: one quad wholly over the other */
    printf("interpenetrating worst: zbuf8 %ld block %ld blockmask %ld sbuf %ld painter %ld\n",
           worst[0], worst[1], worst[2], worst[3], worst[4]);
}

/* Cyclic overlap: three planks along the sides of a triangle, each near
 * at its start and far at its end, so plank i+1 covers plank i at every
 * corner: no drawing order is right.  Painter's must be wrong somewhere,
 * and only where two planks overlap; the z-buffers get every pixel. */
static const r8_s16 p0_v[] = {-6, -76, 170, 63, 43, 230, 49, 51, 230, -19, -68, 170};
static const r8_s16 p1_v[] = {68, 33, 170, -68, 33, 230, -68, 17, 230, 68, 17, 170};
static const r8_s16 p2_v[] = {-63, 43, 170, 6, -76, 230, 19, -68, 230, -49, 51, 170};
static const r8_mesh p0 = {p0_v, quad_f8, 0, 4, 1, 0, 250};
static const r8_mesh p1 = {p1_v, quad_f12, 0, 4, 1, 0, 250};
static const r8_mesh p2 = {p2_v, quad_f16, 0, 4, 1, 0, 250};
static const r8_demo_obj cyc_objs[] = {
    {&p0, 0, 0, 0, 0, 0, 0, 0, 0, 2},
    {&p1, 0, 0, 0, 0, 0, 0, 0, 0, 2},
    {&p2, 0, 0, 0, 0, 0, 0, 0, 0, 2}
};
static const r8_demo cyc_scene = {"cyclic", cyc_objs, 3, 50, 16, 4096, {-9459, -9459, -9459} R8_DEMO_WORLD(0, 0, 0)};

/* Pixels covered by at least two of sc's objects (each rendered alone). */
static void overlap_map(const r8_demo *sc, r8_u16 fr, r8_u8 *cnt)
{
    static r8_demo_obj one[1];
    static r8_demo alone;
    r8_u8 i;
    int k;
    memset(cnt, 0, W * H);
    for (i = 0; i < sc->nobjects; i++) {
        r8_render_cfg c;
        alone = *sc;
        one[0] = sc->objects[i];
        alone.objects = one;
        alone.nobjects = 1;
        cfg_for(&c, &alone, R8_VIS_Z16, R8_SHADE_FLAT);
        render(&c, fr, tmp);
        for (k = 0; k < W * H; k++)
            cnt[k] = (r8_u8)(cnt[k] + (tmp[k] != 0));
    }
}

static void check_painter_fails_only_in_overlaps(const r8_demo *sc, long *worst, long *total)
{
    static r8_u8 cnt[W * H];
    r8_u16 fr;
    *worst = *total = 0;
    for (fr = 0; fr < 128; fr = (r8_u16)(fr + 9)) {
        r8_render_cfg c;
        long d = 0, area = 0;
        int k;
        cfg_for(&c, sc, R8_VIS_Z16, R8_SHADE_FLAT);
        render(&c, fr, ref);
        cfg_for(&c, sc, R8_VIS_PAINTER, R8_SHADE_FLAT);
        render(&c, fr, img);
        overlap_map(sc, fr, cnt);
        for (k = 0; k < W * H; k++) {
            area += cnt[k] >= 2;
            if (img[k] != ref[k]) {
                d++;
                TEST_ASSERT_TRUE(cnt[k] >= 2);   /* wrong only where faces overlap */
            }
        }
        TEST_ASSERT_LESS_OR_EQUAL(area, d);
        if (d > *worst)
            *worst = d;
        *total += d;
        /* S-buffer and 16-bit z agree up to span rounding at the crossings */
        cfg_for(&c, sc, R8_VIS_SBUF, R8_SHADE_FLAT);
        render(&c, fr, img);
        TEST_ASSERT_LESS_OR_EQUAL(24, ndiff(img, ref));
    }
}

static void test_cyclic_overlap_painter(void)
{
    long worst, total;
    check_painter_fails_only_in_overlaps(&cyc_scene, &worst, &total);
    TEST_ASSERT_TRUE(worst > 0);      /* a cycle: some frame must be wrong */
    printf("cyclic overlap: painter's worst %ld px, total %ld px\n", worst, total);
}

static void test_wall_and_pillar_painter(void)
{
    long worst, total;
    check_painter_fails_only_in_overlaps(r8_demo_get(R8_DEMO_WALL), &worst, &total);
    TEST_ASSERT_TRUE(worst > 0);      /* the seed's failure shows */
    printf("wall and pillar: painter's worst %ld px, total %ld px\n", worst, total);
}

/* A cube crossing the near plane: clipped, never dropped; one convex
 * mesh, so backface culling alone equals the 16-bit z-buffer exactly, and
 * so do the other exact methods (Lambert).  With Gouraud the S-buffer's
 * 8.8 per-pixel shade step may round differently: at most 1 level off. */
static r8_demo_obj near_objs[1];
static r8_demo near_scene;

static void test_near_plane_crossing(void)
{
    static const r8_u8 exact_methods[] = {R8_VIS_CULL, R8_VIS_PAINTER, R8_VIS_Z8, R8_VIS_SBUF, R8_VIS_BLOCKMASK};
    static const r8_s16 zs[] = {30, 50, 70};
    r8_u16 fr;
    unsigned m, zi;
    long drawn = 0;
    near_scene = *r8_demo_get(R8_DEMO_CUBE);
    near_objs[0] = near_scene.objects[0];
    near_scene.objects = near_objs;
    for (zi = 0; zi < sizeof zs / sizeof zs[0]; zi++) {
        near_objs[0].z = zs[zi];
        near_objs[0].x = (r8_s16)(zi * 20);
        for (fr = 0; fr < 64; fr = (r8_u16)(fr + 5)) {
            r8_render_cfg c;
            int k;
            cfg_for(&c, &near_scene, R8_VIS_Z16, R8_SHADE_GOURAUD);
            render(&c, fr, ref);
            cfg_for(&c, &near_scene, R8_VIS_SBUF, R8_SHADE_GOURAUD);
            render(&c, fr, img);
            for (k = 0; k < W * H; k++)
                TEST_ASSERT_TRUE(img[k] + 1 >= ref[k] && img[k] <= ref[k] + 1 && (img[k] == 0) == (ref[k] == 0));
            cfg_for(&c, &near_scene, R8_VIS_Z16, R8_SHADE_LAMBERT);
            render(&c, fr, ref);
            TEST_ASSERT_EQUAL_INT(0, last_dropped);
            for (k = 0; k < W * H; k++)
                drawn += ref[k] != 0;
            for (m = 0; m < sizeof exact_methods; m++) {
                cfg_for(&c, &near_scene, exact_methods[m], R8_SHADE_LAMBERT);
                render(&c, fr, img);
                TEST_ASSERT_EQUAL_INT(0, last_dropped);
                if (getenv("R8_DEBUG") && ndiff(img, ref))
                    printf("near z %d frame %u method %u diff %ld\n", zs[zi], fr, exact_methods[m], ndiff(img, ref));
                TEST_ASSERT_EQUAL_INT(0, ndiff(img, ref));
            }
        }
    }
    TEST_ASSERT_TRUE(drawn > 0);
}

/* A floor plane with vertices at +/-32767 (edges 65534 units long: the
 * 16-bit cross product of its edges overflows), 40 units below the eye
 * and reaching behind the camera: near-clipped and guard-clipped.  By
 * hand: the horizon is at y = 32 + 100 * 40 / z px, under 0.13 px below
 * the centre for z <= 32767, so rows 32..63 are covered and rows 0..31
 * empty, for every method and every rotation about the vertical axis. */
static const r8_s16 floor_v[] = {-32767, 0, -32767, 32767, 0, -32767, 32767, 0, 32767, -32767, 0, 32767};
static const r8_face floor_f[] = {{4, 16, {3, 2, 1, 0}}};   /* clockwise seen from above */
static const r8_mesh floor_m = {floor_v, floor_f, 0, 4, 1, 0, 32767};
static r8_demo_obj floor_objs[1] = {{&floor_m, 0, 40, 0, 0, 0, 0, 0, 3, 0}};
static const r8_demo floor_scene = {"floor", floor_objs, 1, 50, 16, 4096, {-9459, -9459, -9459} R8_DEMO_WORLD(0, 0, 0)};

/* The 16-bit overflow case proper: a floor 65534 units wide but only
 * 1980 deep, from z = 20 to z = 2000: its edge vectors are (65534, 0, 0)
 * and (65534, 0, -1980); truncated to 16 bits the first becomes (-2, 0, 0)
 * and the normal's y flips sign, so a 16-bit normal culls the face.  By
 * hand: its far edge projects to y = 32 + 100 * 40 / 2000 = 34 px, its
 * near edge below the screen: rows 34..63 covered, 0..33 empty. */
static const r8_s16 strip_v[] = {-32767, 0, 2000, 32767, 0, 2000, 32767, 0, 20, -32767, 0, 20};
static const r8_face strip_f[] = {{4, 16, {0, 1, 2, 3}}};
static const r8_mesh strip_m = {strip_v, strip_f, 0, 4, 1, 0, 32767};
static const r8_demo_obj strip_objs[1] = {{&strip_m, 0, 40, 0, 0, 0, 0, 0, 0, 0}};
static const r8_demo strip_scene = {"strip", strip_objs, 1, 50, 16, 4096, {-9459, -9459, -9459} R8_DEMO_WORLD(0, 0, 0)};

static void test_cross_product_overflow(void)
{
    r8_u8 m, cull;
    for (cull = 0; cull < 2; cull++)
        for (m = 0; m < R8_VIS_COUNT; m++) {
            r8_render_cfg c;
            int x, y;
            long wrong = 0;
            cfg_for(&c, &strip_scene, m, R8_SHADE_LAMBERT);
            c.cull = cull;
            render(&c, 0, img);
            TEST_ASSERT_EQUAL_INT(0, last_dropped);
            for (y = 0; y < H; y++)
                for (x = 0; x < W; x++)
                    wrong += (img[y * W + x] != 0) != (y >= 34);
            if (wrong && getenv("R8_DEBUG"))
                printf("strip cull %u method %u wrong %ld\n", cull, m, wrong);
            TEST_ASSERT_EQUAL_INT(0, wrong);
        }
}

static void test_huge_floor(void)
{
    r8_u16 fr;
    r8_u8 m;
    for (fr = 0; fr < 86; fr = (r8_u16)(fr + 5))
        for (m = 0; m < R8_VIS_COUNT; m++) {
            r8_render_cfg c;
            int x, y;
            long wrong = 0;
            cfg_for(&c, &floor_scene, m, R8_SHADE_FLAT);
            render(&c, fr, img);
            TEST_ASSERT_EQUAL_INT(0, last_dropped);
            for (y = 0; y < H; y++)
                for (x = 0; x < W; x++)
                    wrong += (img[y * W + x] != 0) != (y >= 32);
            if (wrong && getenv("R8_DEBUG"))
                printf("floor frame %u method %u wrong %ld lit %ld\n", fr, m, wrong, W * H - ndiff(img, tmp));
            TEST_ASSERT_EQUAL_INT(0, wrong);
        }
}

/* Objects far beyond the screen (x = +/-30000 at z = 200, behind the
 * camera, 30000 deep): nothing drawn, nothing written outside, no drop. */
static void test_far_beyond_screen(void)
{
    static const r8_s16 pos[][3] = {{30000, 0, 200}, {-30000, -30000, 200}, {0, 0, -300},
                                   {0, 0, 30000}, {0, 30000, 100}};
    static r8_demo_obj objs[1];
    static r8_demo sc;
    unsigned p;
    r8_u8 m;
    sc = *r8_demo_get(R8_DEMO_CUBE);
    objs[0] = sc.objects[0];
    sc.objects = objs;
    for (p = 0; p < sizeof pos / sizeof pos[0]; p++)
        for (m = 0; m < R8_VIS_COUNT; m++) {
            r8_render_cfg c;
            int k;
            long lit = 0;
            objs[0].x = pos[p][0];
            objs[0].y = pos[p][1];
            objs[0].z = pos[p][2];
            cfg_for(&c, &sc, m, R8_SHADE_LAMBERT);
            render(&c, 3, img);
            for (k = 0; k < W * H; k++)
                lit += img[k] != 0;
            if (pos[p][2] == 30000)
                TEST_ASSERT_LESS_OR_EQUAL(1, lit);   /* 72 units at 30000: under a pixel */
            else
                TEST_ASSERT_EQUAL_INT(0, lit);
        }
}

/* 1024-pixel spans (the widest frame): the X scene at 1024x64, where
 * every row is one or two spans up to 1024 px long.  The z-buffers step
 * depth with the exact interpolator (no drift); the S-buffer steps 16.16
 * depth and 8.8 shade per pixel.  Bound: away from the crossing the
 * S-buffer's Gouraud levels stay within 1 of the 16-bit z-buffer's over
 * the whole 1024 px (no drift); pixels off by more (a different surface)
 * only where the quads' depths tie within rounding: at most 12 per row
 * (measured 8 where the crossing runs nearly along a row) and 320 in all
 * (measured 280) over 8 frames.  (Vertex depth comes from a 16-bit
 * reciprocal, within 1 unit of 32767: ties are a little wider than with
 * the 32-bit division it replaced, 113 px then; both methods match the
 * float reference equally on the cross scene, bench/accuracy.py.) */
static r8_u8 wref[WW * H], wimg[WW * H];

static void test_1024_pixel_spans(void)
{
    r8_u16 fr;
    long worst = 0, off1 = 0, total = 0;
    for (fr = 0; fr < 64; fr = (r8_u16)(fr + 9)) {
        r8_render_cfg c;
        int k, y;
        cfg_for(&c, &x_scene, R8_VIS_Z16, R8_SHADE_GOURAUD);
        c.width = WW;
        render(&c, fr, wref);
        cfg_for(&c, &x_scene, R8_VIS_SBUF, R8_SHADE_GOURAUD);
        c.width = WW;
        render(&c, fr, wimg);
        for (y = 0; y < H; y++) {
            long d = 0;
            for (k = y * WW; k < (y + 1) * WW; k++) {
                int a = wimg[k], b = wref[k];
                if ((a == 0) != (b == 0) || a > b + 1 || b > a + 1) {
                    d++;
                    if (getenv("R8_DEBUG"))
                        printf("fr %u y %d x %d sbuf %d z16 %d\n", fr, y, k - y * WW, a, b);
                }
                off1 += a != b;
            }
            if (d > worst)
                worst = d;
            total += d;
        }
    }
    TEST_ASSERT_LESS_OR_EQUAL(12, worst);
    TEST_ASSERT_LESS_OR_EQUAL(320, total);
    printf("1024-px spans: S-buffer off by > 1 level (surface): worst %ld px/row, %ld px; %ld px differ at all\n",
           worst, total, off1);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_interpenetrating);
    RUN_TEST(test_cyclic_overlap_painter);
    RUN_TEST(test_wall_and_pillar_painter);
    RUN_TEST(test_near_plane_crossing);
    RUN_TEST(test_huge_floor);
    RUN_TEST(test_cross_product_overflow);
    RUN_TEST(test_far_beyond_screen);
    RUN_TEST(test_1024_pixel_spans);
    return UNITY_END();
}
