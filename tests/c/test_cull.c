/* test_cull.c - the seed's two backface culls agree on every
 * non-degenerate polygon: (1) before projection, the sign of the face
 * normal (cross product of two edges) against the view vector; (2) Judd's,
 * during scan conversion, the left edge passing the right edge. */
#include "unity.h"
#include "r8fixed.h"
#include "r8raster.h"

void setUp(void) {}
void tearDown(void) {}

static unsigned long lcg = 99;
static r8_s16 rnd(r8_s16 lo, r8_s16 hi)
{
    lcg = (lcg * 1103515245UL + 12345UL) & 0x7FFFFFFFUL;
    return (r8_s16)(lo + (r8_s16)((lcg >> 8) % (unsigned long)(hi - lo + 1)));
}

/* Normal cull: outward normal n = (v2-v0) x (v1-v0) of a polygon listed
 * clockwise from outside; front iff n . (eye - v0) > 0, eye at 0. */
static int normal_front(const r8_vec3 *v)
{
    r8_vec3 e1, e2, d;
    r8_vec3l n;
    r8_s32 dot;
    e1.x = (r8_s16)(v[1].x - v[0].x); e1.y = (r8_s16)(v[1].y - v[0].y); e1.z = (r8_s16)(v[1].z - v[0].z);
    e2.x = (r8_s16)(v[2].x - v[0].x); e2.y = (r8_s16)(v[2].y - v[0].y); e2.z = (r8_s16)(v[2].z - v[0].z);
    r8_cross3(&e2, &e1, &n);
    /* n fits 17 bits here; scale to 16 for the dot product */
    d.x = (r8_s16)r8_asr32(n.x, 2); d.y = (r8_s16)r8_asr32(n.y, 2); d.z = (r8_s16)r8_asr32(n.z, 2);
    e1.x = (r8_s16)-v[0].x; e1.y = (r8_s16)-v[0].y; e1.z = (r8_s16)-v[0].z;
    dot = r8_dot3(&d, &e1);
    return dot > 0;
}

/* Twice the signed screen area in subpixels^2 (positive = clockwise). */
static r8_s32 area2(const r8_svert *s)
{
    return r8_mul16((r8_s16)(s[1].x - s[0].x), (r8_s16)(s[2].y - s[0].y)) -
           r8_mul16((r8_s16)(s[2].x - s[0].x), (r8_s16)(s[1].y - s[0].y));
}

/* Pixels the scan converter draws for triangle sv, with or without
 * Judd's test; *back is set when the test found a back face. */
static long drawn(const r8_svert *sv, int judd, int *back)
{
    static const r8_u16 idx[3] = {0, 1, 2};
    r8_scan s;
    r8_span sp;
    long n = 0;
    *back = 0;
    if (r8_scan_begin(&s, sv, idx, 3, 0, -32767)) {
        while (r8_scan_next(&s, 32767, judd, &sp))
            n += sp.x1 - sp.x0;
        *back = s.c.backface;
    }
    return n;
}

/* Judd's cull agrees with the normal cull: a back face (by its normal)
 * draws nothing with the test on, a front face exactly the pixels it
 * draws with the test off; the test decides (flags) most back faces. */
static void test_culls_agree_on_random_triangles(void)
{
    static r8_svert sv[3];
    r8_proj cam;
    r8_vec3l c;   /* structs at function scope: SDCC 4.2 overlays a block-scope struct on cam */
    r8_vec3 v[3];
    int n, checked = 0, fronts = 0, flagged = 0;
    r8_proj_init(&cam, 128, 64, 100, 16L << R8_CFRAC);
    for (n = 0; n < 600; n++) {
        r8_u8 k;
        int nf, back, back0;
        long pj, p0;
        for (k = 0; k < 3; k++) {
            v[k].x = rnd(-90, 90);
            v[k].y = rnd(-50, 50);
            v[k].z = rnd(120, 300);
            c.x = (r8_s32)v[k].x * R8_CSCALE;
            c.y = (r8_s32)v[k].y * R8_CSCALE;
            c.z = (r8_s32)v[k].z * R8_CSCALE;
            r8_project(&cam, &c, &sv[k].x, &sv[k].y);
        }
        /* non-degenerate: at least 4 pixels of screen area */
        if (area2(sv) < 2L * 4 * 256 && area2(sv) > -2L * 4 * 256)
            continue;
        nf = normal_front(v);
        pj = drawn(sv, 1, &back);
        p0 = drawn(sv, 0, &back0);
        if (nf) {
            TEST_ASSERT_EQUAL_INT(0, back);
            TEST_ASSERT_EQUAL_INT32(p0, pj);
        } else {
            TEST_ASSERT_EQUAL_INT32(0, pj);
            flagged += back;
        }
        checked++;
        fronts += nf;
    }
    TEST_ASSERT_GREATER_THAN(300, checked);      /* the sample is real */
    TEST_ASSERT_GREATER_THAN(100, fronts);
    TEST_ASSERT_GREATER_THAN(100, checked - fronts);
    TEST_ASSERT_GREATER_THAN((checked - fronts) * 9 / 10, flagged);
}

static void test_judd_quad_both_windings(void)
{
    static r8_svert sv[4];
    static const r8_u16 cw[4] = {0, 1, 2, 3}, ccw[4] = {3, 2, 1, 0};
    r8_scan s;
    r8_span sp;
    int rows = 0;
    sv[0].x = 160; sv[0].y = 100;
    sv[1].x = 900; sv[1].y = 140;
    sv[2].x = 850; sv[2].y = 700;
    sv[3].x = 120; sv[3].y = 650;
    r8_scan_begin(&s, sv, cw, 4, 0, 0);
    while (r8_scan_next(&s, 100, 1, &sp))
        rows++;
    TEST_ASSERT_EQUAL_INT(0, s.c.backface);
    TEST_ASSERT_GREATER_THAN(30, rows);
    r8_scan_begin(&s, sv, ccw, 4, 0, 0);
    TEST_ASSERT_EQUAL_INT(0, r8_scan_next(&s, 100, 1, &sp));
    TEST_ASSERT_EQUAL_INT(1, s.c.backface);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_culls_agree_on_random_triangles);
    RUN_TEST(test_judd_quad_both_windings);
    return UNITY_END();
}
