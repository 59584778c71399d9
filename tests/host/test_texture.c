/* test_texture.c - texture mapping (src/texture.c, docs/pipeline.md
 * "Texture mapping"): u and v stepped exactly along edges and spans,
 * the textured crate drawn with its texture, perspective subdivision
 * closer to the true perspective mapping than affine, and no write
 * outside the band buffer or the work memory with faces off screen,
 * across the band edges and through the near plane. */
#include <stdio.h>
#include <string.h>
#include "unity.h"
#include "r8render.h"
#include "r8raster.h"
#include "demo.h"
#include "../../src/r8int.h"

#define W 128
#define H 64
#define GUARD 64
#define GB 0x5A

static r8_u8 work[32768 + GUARD];
static r8_u8 bandmem[W * H + GUARD];
static r8_u8 img[W * H];
static r8_demo_run run;
static r8_render_stats last;

void setUp(void) {}
void tearDown(void) {}

static unsigned long lcg = 4242;
static long rnd(long lo, long hi)
{
    lcg = (lcg * 1103515245UL + 12345UL) & 0x7FFFFFFFUL;
    return lo + (long)((lcg >> 8) % (unsigned long)(hi - lo + 1));
}

static long floordiv(long long n, long long d)
{
    long long q = n / d;
    if ((n % d != 0) && ((n < 0) != (d < 0)))
        q--;
    return (long)q;
}

/* u and v ride in the scan's depth and shade slots: on every row the
 * edge values are the exact floor of the edge's linear function at the
 * row centre, and stepping a span's u from its left to its right value
 * over its pixels lands exactly on the right value, every pixel being
 * the exact floor in between (no drift), for u, v up to 2 repeats of a
 * 64-texel texture in 8.8 (32640). */
static void test_uv_stepping_exact(void)
{
    int trial;
    long spans = 0;
    for (trial = 0; trial < 3000; trial++) {
        r8_svert v[4];
        r8_u16 idx[4] = {0, 1, 2, 3};
        r8_scan s;
        r8_span sp;
        int k;
        /* a convex clockwise quad: a random box's corners, jittered */
        long x0 = rnd(-400, 1800), y0 = rnd(-400, 900), w = rnd(1, 2000), h = rnd(1, 1200);
        v[0].x = (r8_s16)x0; v[0].y = (r8_s16)y0;
        v[1].x = (r8_s16)(x0 + w); v[1].y = (r8_s16)(y0 + rnd(0, h / 3));
        v[2].x = (r8_s16)(x0 + w - rnd(0, w / 3)); v[2].y = (r8_s16)(y0 + h);
        v[3].x = (r8_s16)(x0 - rnd(0, w / 3)); v[3].y = (r8_s16)(y0 + h - rnd(0, h / 3));
        for (k = 0; k < 4; k++) {
            v[k].d = (r8_s16)rnd(0, 32640);
            v[k].s = (r8_s16)rnd(0, 32640);
        }
        if (!r8_scan_begin(&s, v, idx, 4, R8_ATTR_D | R8_ATTR_S, 0))
            continue;
        while (r8_scan_next(&s, 2048, 0, &sp)) {
            r8_interp u;
            long n = sp.x1 - sp.x0, j;
            r8_interp_init_mul(&u, sp.dl, 0, (r8_s32)sp.dr - sp.dl, (r8_s32)sp.dr - sp.dl, (r8_u16)n);
            for (j = 0; j <= n; j++) {
                long want = sp.dl + floordiv((long long)j * (sp.dr - sp.dl), n);
                if (u.val != want) {
                    char msg[120];
                    sprintf(msg, "trial %d row %d pixel %ld/%ld: u %d, exact %ld", trial, sp.y, j, n, u.val, want);
                    TEST_FAIL_MESSAGE(msg);
                }
                R8_INTERP_STEP(&u);
            }
            spans++;
        }
    }
    TEST_ASSERT_TRUE(spans > 10000);
}

/* Along one edge, u at row y is u_a + floor((16 y + 8 - y_a) du / dy). */
static void test_edge_values_exact(void)
{
    int trial, rows = 0;
    for (trial = 0; trial < 2000; trial++) {
        r8_svert v[3];
        r8_u16 idx[3] = {0, 1, 2};
        r8_scan s;
        r8_span sp;
        /* a right triangle: vertical left edge from v0 down to v2 */
        long x = rnd(0, 1000), y = rnd(-200, 700), h = rnd(16, 1500);
        v[0].x = (r8_s16)x; v[0].y = (r8_s16)y;
        v[1].x = (r8_s16)(x + rnd(200, 1500)); v[1].y = (r8_s16)(y + h);
        v[2].x = (r8_s16)x; v[2].y = (r8_s16)(y + h);
        v[0].d = (r8_s16)rnd(0, 32640); v[2].d = (r8_s16)rnd(0, 32640); v[1].d = 0;
        v[0].s = v[1].s = v[2].s = 0;
        if (!r8_scan_begin(&s, v, idx, 3, R8_ATTR_D | R8_ATTR_S, 0))
            continue;
        while (r8_scan_next(&s, 2048, 0, &sp)) {
            long want = v[0].d + floordiv((long long)(16L * sp.y + 8 - y) * (v[2].d - v[0].d), h);
            TEST_ASSERT_EQUAL_INT(want, sp.dl);
            rows++;
        }
    }
    TEST_ASSERT_TRUE(rows > 1000);
}

/* Render the crate at frame `frame`, IDX8, band by band, with the guard
 * bytes after the work memory and the band checked. */
static void render(r8_render_cfg *c, r8_u16 frame, r8_s16 dz, r8_s16 dx, r8_u8 *out)
{
    r8_render r;
    r8_fb band;
    r8_s16 y;
    unsigned need, bb, i;
    TEST_ASSERT_EQUAL_INT(0, r8_demo_setup(&run, r8_demo_get(R8_DEMO_CRATE), c->width));
    c->scene = &run.scene;
    need = r8_render_ram(c);
    bb = r8_fb_bytes(c->format, c->width, c->band);
    TEST_ASSERT_TRUE(need > 0 && need + GUARD <= sizeof work);
    memset(work, GB, sizeof work);
    memset(bandmem, GB, sizeof bandmem);
    TEST_ASSERT_EQUAL_INT(0, r8_render_init(&r, c, work, need));
    r8_demo_pose(&run, frame);
    run.obj[0].pose.z = (r8_s16)(run.obj[0].pose.z + dz);
    run.obj[0].pose.x = (r8_s16)(run.obj[0].pose.x + dx);
    r8_render_frame(&r, &run.cam);
    r8_fb_init(&band, bandmem, c->format, c->width, c->height, 0, c->band);
    for (y = 0; y < c->height; y = (r8_s16)(y + c->band)) {
        r8_fb_set_band(&band, y);
        r8_render_band(&r, &band);
        if (out && c->format == R8_FMT_IDX8)
            memcpy(out + (unsigned)y * (unsigned)c->width, bandmem, (size_t)bb);
        for (i = bb; i < bb + GUARD; i++)
            TEST_ASSERT_EQUAL_HEX8(GB, bandmem[i]);
    }
    for (i = need; i < need + GUARD; i++)
        TEST_ASSERT_EQUAL_HEX8(GB, work[i]);
    r8_render_stats_get(&r, &last);
}

static void cfg_tex(r8_render_cfg *c, r8_u8 format, r8_u8 persp, r8_u8 filter)
{
    r8_render_defaults(c);
    c->shading = R8_SHADE_TEXTURE;
    c->format = format;
    c->band = 8;
    c->persp = persp;
    c->texfilter = filter;
    c->clip = 8;
}

/* Face-on at frame 0 the crate's front face shows its texture: the
 * frame's dark outer border, the light boards, the darker planks in
 * between (levels of texel x Lambert, not one flat level). */
static void test_crate_shows_texture(void)
{
    r8_render_cfg c;
    int x, y = H / 2, levels[17] = {0}, distinct = 0, k;
    cfg_tex(&c, R8_FMT_IDX8, 0, R8_TEXF_NEAREST);
    render(&c, 0, 0, 0, img);
    for (x = 0; x < W; x++) {
        TEST_ASSERT_TRUE(img[y * W + x] <= 16);
        levels[img[y * W + x]]++;
    }
    for (k = 1; k <= 16; k++)
        distinct += levels[k] > 0;
    TEST_ASSERT_TRUE(distinct >= 3);
    /* the same face with Lambert alone is one level */
    c.shading = R8_SHADE_LAMBERT;
    render(&c, 0, 0, 0, img);
    for (k = 0; k <= 16; k++)
        levels[k] = 0;
    for (x = 0; x < W; x++)
        levels[img[y * W + x]]++;
    for (k = 1, distinct = 0; k <= 16; k++)
        distinct += levels[k] > 0;
    TEST_ASSERT_EQUAL_INT(1, distinct);
}

/* Every format, filter and mode, poses off screen, half off, across the
 * near plane (the clipper carries u, v) and around the camera: nothing
 * written outside the band or the work memory (the guards). */
static void test_no_write_outside(void)
{
    static const r8_s16 dz[] = {0, -120, -160, -185, -200, -230, 400, 3000};
    static const r8_s16 dx[] = {0, 90, -150, 400, -30};
    static const r8_u8 fmts[] = {R8_FMT_PAGE1, R8_FMT_ROW1, R8_FMT_IDX8};
    r8_render_cfg c;
    unsigned a, b, f, m, clipped = 0;
    for (f = 0; f < 3; f++)
        for (m = 0; m < 4; m++)
            for (a = 0; a < sizeof dz / sizeof dz[0]; a++)
                for (b = 0; b < sizeof dx / sizeof dx[0]; b++) {
                    cfg_tex(&c, fmts[f], (r8_u8)(m & 1 ? 8 : 0), (r8_u8)(m >> 1));
                    c.method = (r8_u8)(a & 1 ? R8_VIS_PAINTER : R8_VIS_CULL);
                    render(&c, (r8_u16)(a * 37 + b * 11), dz[a], dx[b], 0);
                    clipped += last.clipped;
                }
    TEST_ASSERT_TRUE(clipped > 0);     /* the clipper's path was taken */
}

/* Untextured configurations are refused where texturing is not built
 * for them: depth methods, bad persp. */
static void test_cfg(void)
{
    r8_render_cfg c;
    TEST_ASSERT_EQUAL_INT(0, r8_demo_setup(&run, r8_demo_get(R8_DEMO_CRATE), W));
    cfg_tex(&c, R8_FMT_PAGE1, 0, 0);
    c.scene = &run.scene;
    TEST_ASSERT_TRUE(r8_render_ram(&c) > 0);
    c.method = R8_VIS_Z16;
    TEST_ASSERT_EQUAL_INT(0, (int)r8_render_ram(&c));
    c.method = R8_VIS_CULL;
    c.persp = 1;
    TEST_ASSERT_EQUAL_INT(0, (int)r8_render_ram(&c));
    c.persp = 65;
    TEST_ASSERT_EQUAL_INT(0, (int)r8_render_ram(&c));
    c.persp = 16;
    c.texfilter = 2;
    TEST_ASSERT_EQUAL_INT(0, (int)r8_render_ram(&c));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_uv_stepping_exact);
    RUN_TEST(test_edge_values_exact);
    RUN_TEST(test_crate_shows_texture);
    RUN_TEST(test_no_write_outside);
    RUN_TEST(test_cfg);
    return UNITY_END();
}
