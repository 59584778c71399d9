/* test_ray_render.c - the ray caster through the ordinary entry points
 * (r8_render_ram/init/frame/band with R8_VIS_RAY): the same bytes as
 * r8_ray_* called directly; the names; the analyser's choice for a grid
 * scene (R8_WHY_GRID); the maze demo set up as a grid scene. */
#include <string.h>
#include "unity.h"
#include "r8ray.h"
#include "r8render.h"
#include "demo.h"

static r8_u8 w1[4096], w2[4096], f1[1024], f2[1024];
static r8_demo_run run;

void setUp(void) {}
void tearDown(void) {}

static void test_names(void)
{
    TEST_ASSERT_TRUE(r8_method_name(R8_VIS_RAY) != 0);
    TEST_ASSERT_EQUAL_INT(0, strcmp("ray", r8_method_name(R8_VIS_RAY)));
    TEST_ASSERT_EQUAL_INT(R8_VIS_RAY, r8_method_by_name("ray"));
    TEST_ASSERT_TRUE(R8_VIS_RAY >= R8_VIS_COUNT);
    TEST_ASSERT_EQUAL_INT(R8_DEMO_MAZE, r8_demo_by_name("maze"));
    TEST_ASSERT_TRUE(r8_demo_get(R8_DEMO_COUNT) == 0);
    TEST_ASSERT_TRUE(r8_demo_name(R8_DEMO_COUNT) == 0);
}

static void test_maze_demo_is_a_grid_scene(void)
{
    TEST_ASSERT_EQUAL_INT(0, r8_demo_setup(&run, r8_demo_get(R8_DEMO_MAZE), 128));
    TEST_ASSERT_TRUE(run.scene.grid != 0);
    TEST_ASSERT_EQUAL_INT(0, run.scene.nobjects);
    TEST_ASSERT_EQUAL_INT(96, run.cam.x);      /* the middle of cell (1, 1) */
    TEST_ASSERT_EQUAL_INT(96, run.cam.z);
    r8_demo_pose(&run, 5);
    TEST_ASSERT_EQUAL_INT(10, run.cam.yaw);    /* the spin turns the camera */
    /* the mesh scenes have no grid */
    TEST_ASSERT_EQUAL_INT(0, r8_demo_setup(&run, r8_demo_get(R8_DEMO_CUBE), 128));
    TEST_ASSERT_TRUE(run.scene.grid == 0);
}

static void test_entry_points_equal_the_ray_caster(void)
{
    r8_render_cfg c;
    r8_render a, b;
    r8_render_stats st;
    r8_fb fa, fb;
    r8_s16 y;
    r8_u8 k;
    TEST_ASSERT_EQUAL_INT(0, r8_demo_setup(&run, r8_demo_get(R8_DEMO_MAZE), 128));
    r8_render_defaults(&c);
    c.scene = &run.scene;
    c.method = R8_VIS_RAY;
    TEST_ASSERT_EQUAL_UINT(r8_ray_ram(&c), r8_render_ram(&c));
    TEST_ASSERT_EQUAL_INT(-2, r8_render_init(&a, &c, w1, r8_render_ram(&c) - 1u));
    TEST_ASSERT_EQUAL_INT(0, r8_render_init(&a, &c, w1, sizeof w1));
    TEST_ASSERT_EQUAL_INT(0, r8_ray_init(&b, &c, w2, sizeof w2));
    r8_fb_init(&fa, f1, R8_FMT_PAGE1, 128, 64, 0, 8);
    r8_fb_init(&fb, f2, R8_FMT_PAGE1, 128, 64, 0, 8);
    for (k = 0; k < 12; k++) {
        r8_demo_pose(&run, (r8_u16)(k * 11));
        r8_render_frame(&a, &run.cam);
        r8_ray_frame(&b, &run.cam);
        for (y = 0; y < 64; y = (r8_s16)(y + 8)) {
            memset(f1, 0x5A, sizeof f1);
            r8_fb_set_band(&fa, y);
            r8_fb_set_band(&fb, y);
            r8_render_band(&a, &fa);
            r8_ray_band(&b, &fb);
            TEST_ASSERT_EQUAL_INT(0, memcmp(f1, f2, 128));
        }
        r8_render_stats_get(&a, &st);
        TEST_ASSERT_EQUAL_INT(0, st.faces);
    }
    /* a mesh method on the grid scene (no objects): refused */
    c.method = R8_VIS_CULL;
    TEST_ASSERT_EQUAL_UINT(0, r8_render_ram(&c));
    TEST_ASSERT_EQUAL_INT(-1, r8_render_init(&a, &c, w1, sizeof w1));
}

static void test_analyser_picks_the_ray_caster(void)
{
    r8_render_cfg c;
    r8_analysis an;
    unsigned work;
    TEST_ASSERT_EQUAL_INT(0, r8_demo_setup(&run, r8_demo_get(R8_DEMO_MAZE), 128));
    r8_render_defaults(&c);
    c.scene = &run.scene;
    c.method = R8_VIS_AUTO;
    c.band = 0;
    TEST_ASSERT_EQUAL_INT(0, r8_analyse(&c, &run.cam, 0, 4096, &an));
    TEST_ASSERT_EQUAL_INT(R8_VIS_RAY, an.method);
    TEST_ASSERT_EQUAL_INT(R8_WHY_GRID, an.why);
    TEST_ASSERT_EQUAL_INT(64, an.band);        /* the whole frame fits 4 KB */
    TEST_ASSERT_EQUAL_INT(1, an.exact);
    TEST_ASSERT_EQUAL_UINT(r8_render_ram(&c) + 1024u, an.ram);
    /* a small budget: the largest band that fits */
    c.method = R8_VIS_RAY;
    c.band = 8;
    work = r8_ray_ram(&c);                     /* the same for every band */
    TEST_ASSERT_TRUE(work > 0);
    c.method = R8_VIS_AUTO;
    c.band = 0;
    TEST_ASSERT_EQUAL_INT(0, r8_analyse(&c, &run.cam, 0, work + 300u, &an));
    TEST_ASSERT_EQUAL_INT(16, an.band);
    /* nothing fits; a mesh method asked for on a grid: -1 */
    c.method = R8_VIS_AUTO;
    c.band = 0;
    TEST_ASSERT_EQUAL_INT(-1, r8_analyse(&c, &run.cam, 0, 100, &an));
    c.method = R8_VIS_Z16;
    TEST_ASSERT_EQUAL_INT(-1, r8_analyse(&c, &run.cam, 0, 4096, &an));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_names);
    RUN_TEST(test_maze_demo_is_a_grid_scene);
    RUN_TEST(test_entry_points_equal_the_ray_caster);
    RUN_TEST(test_analyser_picks_the_ray_caster);
    return UNITY_END();
}
