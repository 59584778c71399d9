/* test_wireframe.c - the wireframe mode (cfg.wire, src/wireframe.c) on
 * the built-in scenes: band by band equals the whole frame (every band
 * height, IDX8 and the page layout); the edges follow the filled
 * render's outline (every silhouette pixel has an edge pixel within 2,
 * every edge pixel an object pixel within 2); painter's hides lines the
 * cull alone leaves (its pixels are a subset of the cull's, fewer where
 * objects overlap); the frame is not the filled one. */
#include <string.h>
#include "unity.h"
#include "r8render.h"
#include "demo.h"

#define W 128
#define H 64
#define NFRAMES 6
static const r8_u16 frames[NFRAMES] = {0, 7, 19, 31, 44, 58};

static r8_u8 work[65536 + 64];
static r8_u8 ref[W * H], img[W * H], fill[W * H], bandbuf[W * H];
static r8_demo_run run;

void setUp(void) {}
void tearDown(void) {}

static void cfg_for(r8_render_cfg *c, r8_u8 scene, r8_u8 method, r8_u8 fmt, r8_s16 band)
{
    r8_render_defaults(c);
    TEST_ASSERT_EQUAL_INT(0, r8_demo_setup(&run, r8_demo_get(scene), W));
    c->scene = &run.scene;
    c->method = method;
    c->format = fmt;
    c->band = band;
    c->width = W;
    c->height = H;
    c->wire = 1;
}

/* One frame of cfg into out, band by band. */
static void render(const r8_render_cfg *cfg, r8_u16 frame, r8_u8 *out)
{
    r8_render r;
    r8_fb fb;
    r8_s16 y;
    unsigned row_bytes = r8_fb_bytes(cfg->format, cfg->width, 8) / 8u;
    TEST_ASSERT_EQUAL_INT(0, r8_render_init(&r, cfg, work, sizeof work));
    r8_demo_pose(&run, frame);
    r8_render_frame(&r, &run.cam);
    r8_fb_init(&fb, bandbuf, cfg->format, cfg->width, cfg->height, 0, cfg->band);
    for (y = 0; y < cfg->height; y = (r8_s16)(y + cfg->band)) {
        r8_s16 rows = cfg->band;
        r8_fb_set_band(&fb, y);
        memset(bandbuf, 0xA5, sizeof bandbuf);    /* the band clears itself */
        r8_render_band(&r, &fb);
        if (y + rows > cfg->height)
            rows = (r8_s16)(cfg->height - y);
        memcpy(out + (unsigned)y * row_bytes, bandbuf, (size_t)row_bytes * (unsigned)rows);
    }
}

static void test_bands_equal_whole(void)
{
    static const r8_u8 scenes[] = { R8_DEMO_CUBE, R8_DEMO_TORUS, R8_DEMO_SEPARATE, R8_DEMO_CROSS };
    static const r8_u8 methods[] = { R8_VIS_CULL, R8_VIS_PAINTER, R8_VIS_Z16 };
    static const r8_s16 bands[] = { 1, 3, 5, 8, 13, 16, 32 };
    unsigned s, m, b, f;
    r8_render_cfg c;
    for (s = 0; s < sizeof scenes; s++)
        for (m = 0; m < sizeof methods; m++)
            for (f = 0; f < NFRAMES; f += 2) {
                long lit = 0;
                unsigned i;
                cfg_for(&c, scenes[s], methods[m], R8_FMT_IDX8, H);
                render(&c, frames[f], ref);
                for (i = 0; i < W * H; i++)
                    lit += ref[i] != 0;
                TEST_ASSERT_TRUE(lit > 0);
                for (b = 0; b < sizeof bands / sizeof bands[0]; b++) {
                    cfg_for(&c, scenes[s], methods[m], R8_FMT_IDX8, bands[b]);
                    render(&c, frames[f], img);
                    TEST_ASSERT_EQUAL_MEMORY(ref, img, W * H);
                }
                /* the page layout: the same pixels, bands of 8 and whole */
                cfg_for(&c, scenes[s], methods[m], R8_FMT_PAGE1, H);
                render(&c, frames[f], ref);
                cfg_for(&c, scenes[s], methods[m], R8_FMT_PAGE1, 8);
                render(&c, frames[f], img);
                TEST_ASSERT_EQUAL_MEMORY(ref, img, W * H / 8);
            }
}

static int near(const r8_u8 *im, int x, int y, int d)
{
    int i, j;
    for (j = y - d; j <= y + d; j++)
        for (i = x - d; i <= x + d; i++)
            if (i >= 0 && i < W && j >= 0 && j < H && im[j * W + i])
                return 1;
    return 0;
}

static void test_edges_follow_outline(void)
{
    static const r8_u8 scenes[] = { R8_DEMO_CUBE, R8_DEMO_TORUS };
    unsigned s, f;
    r8_render_cfg c;
    for (s = 0; s < sizeof scenes; s++)
        for (f = 0; f < NFRAMES; f++) {
            int x, y;
            long sil = 0, same = 0;
            cfg_for(&c, scenes[s], R8_VIS_CULL, R8_FMT_IDX8, 8);
            render(&c, frames[f], img);
            c.wire = 0;
            c.shading = R8_SHADE_FLAT;
            render(&c, frames[f], fill);
            for (y = 0; y < H; y++)
                for (x = 0; x < W; x++) {
                    int p = y * W + x;
                    if (img[p]) {
                        TEST_ASSERT_EQUAL_INT(16, img[p]);
                        TEST_ASSERT_TRUE(near(fill, x, y, 2));
                    }
                    if (fill[p] && ((x > 0 && !fill[p - 1]) || (x < W - 1 && !fill[p + 1]) ||
                                    (y > 0 && !fill[p - W]) || (y < H - 1 && !fill[p + W]))) {
                        TEST_ASSERT_TRUE(near(img, x, y, 2));
                        sil++;
                    }
                    same += (img[p] != 0) == (fill[p] != 0);
                }
            TEST_ASSERT_TRUE(sil > 10);
            TEST_ASSERT_TRUE(same < W * H);      /* not the filled frame */
        }
}

static void test_painter_hides_more(void)
{
    static const r8_u8 scenes[] = { R8_DEMO_SEPARATE, R8_DEMO_TORUS, R8_DEMO_CUBE };
    unsigned s, f, i;
    r8_render_cfg c;
    long fewer = 0;
    for (s = 0; s < sizeof scenes; s++)
        for (f = 0; f < NFRAMES; f++) {
            long a = 0, b = 0;
            cfg_for(&c, scenes[s], R8_VIS_CULL, R8_FMT_IDX8, 8);
            render(&c, frames[f], ref);
            cfg_for(&c, scenes[s], R8_VIS_PAINTER, R8_FMT_IDX8, 8);
            render(&c, frames[f], img);
            for (i = 0; i < W * H; i++) {
                if (img[i])
                    TEST_ASSERT_TRUE(ref[i] != 0);   /* a subset */
                a += ref[i] != 0;
                b += img[i] != 0;
            }
            TEST_ASSERT_TRUE(b > 0);
            if (scenes[s] == R8_DEMO_CUBE)
                TEST_ASSERT_TRUE(a - b < a / 10);    /* convex: little to hide */
            fewer += b < a;
        }
    TEST_ASSERT_TRUE(fewer >= NFRAMES);   /* the torus and the objects hide lines */
}

/* Judd's cull (by screen winding) keeps the same faces' edges. */
static void test_judd_like_normal(void)
{
    r8_render_cfg c;
    unsigned f, i;
    for (f = 0; f < NFRAMES; f++) {
        long d = 0, n = 0;
        cfg_for(&c, R8_DEMO_CUBE, R8_VIS_CULL, R8_FMT_IDX8, 8);
        render(&c, frames[f], ref);
        c.cull = R8_CULL_JUDD;
        render(&c, frames[f], img);
        for (i = 0; i < W * H; i++) {
            d += (ref[i] != 0) != (img[i] != 0);
            n += ref[i] != 0;
        }
        TEST_ASSERT_TRUE(n > 0);
        TEST_ASSERT_EQUAL_INT(0, d);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_bands_equal_whole);
    RUN_TEST(test_edges_follow_outline);
    RUN_TEST(test_painter_hides_more);
    RUN_TEST(test_judd_like_normal);
    return UNITY_END();
}
