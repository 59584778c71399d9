/* test_raster.c - interpolator, scan conversion fill rule, lines. */
#include <limits.h>
#include "unity.h"
#include "r8raster.h"

/* Fewer random cases on 16-bit-int targets: the simulators run these
 * too, at a few million instructions a second. */
#if INT_MAX == 32767
#define N_TRIALS 4
#define N_LINES 6
#else
#define N_TRIALS 20
#define N_LINES 40
#endif

void setUp(void) {}
void tearDown(void) {}

static r8_u8 cover[64 * 32];   /* coverage counts, 64 x 32 */
static r8_u8 fbmem[1024 + 8];

static void clear_cover(void)
{
    unsigned i;
    for (i = 0; i < sizeof cover; i++)
        cover[i] = 0;
}

/* Scan a polygon and add its spans to the coverage counts. */
static long cover_poly(const r8_svert *v, const r8_u16 *idx, r8_u8 n)
{
    r8_scan s;
    r8_span sp;
    long px = 0;
    r8_s16 x;
    if (!r8_scan_begin(&s, v, idx, n, 0, 0))
        return 0;
    while (r8_scan_next(&s, 32, 1, &sp)) {
        for (x = sp.x0; x < sp.x1; x++) {
            if (x >= 0 && x < 64 && sp.y >= 0 && sp.y < 32) {
                cover[sp.y * 64 + x]++;
                px++;
            }
        }
    }
    return px;
}

static void test_interp_exact_endpoints(void)
{
    static const r8_s16 ends[][2] = {
        {0, 32767}, {32767, 0}, {-16384, 16383}, {100, 101}, {5, 5}, {-7, -12345}
    };
    unsigned e;
    r8_u16 n;
    for (e = 0; e < sizeof ends / sizeof ends[0]; e++) {
        for (n = 1; n <= 10000; n = (r8_u16)(n < 20 ? n + 1 : n * 3 + 1)) {
            r8_interp it;
            r8_u16 k;
            r8_s16 prev;
            r8_interp_reset(&it, ends[e][0], ends[e][1], n);
            TEST_ASSERT_EQUAL_INT(ends[e][0], it.val);
            prev = it.val;
            for (k = 0; k < n; k++) {
                r8_interp_step(&it);
                /* monotone, and never more than one unit off the ideal line */
                if (ends[e][1] >= ends[e][0])
                    TEST_ASSERT_TRUE(it.val >= prev);
                else
                    TEST_ASSERT_TRUE(it.val <= prev);
                prev = it.val;
            }
            TEST_ASSERT_EQUAL_INT(ends[e][1], it.val);
        }
    }
    {   /* exactly 10,000 steps: no drift */
        r8_interp it;
        r8_u16 k;
        r8_interp_reset(&it, 3, 29999, 10000);
        for (k = 0; k < 5000; k++)
            r8_interp_step(&it);
        TEST_ASSERT_EQUAL_INT(3 + 14998, it.val);  /* floor(5000*29996/10000) */
        for (; k < 10000; k++)
            r8_interp_step(&it);
        TEST_ASSERT_EQUAL_INT(29999, it.val);
    }
}

static void test_square_two_triangles_15_10(void)
{
    /* 5x5 pixel square at (2,3), split along its main diagonal. */
    static r8_svert v[4];
    static const r8_u16 t1[3] = {0, 1, 2}, t2[3] = {0, 2, 3};
    r8_s16 i;
    v[0].x = 32; v[0].y = 48;       /* (2,3) */
    v[1].x = 112; v[1].y = 48;      /* (7,3) */
    v[2].x = 112; v[2].y = 128;     /* (7,8) */
    v[3].x = 32; v[3].y = 128;      /* (2,8) */
    clear_cover();
    TEST_ASSERT_EQUAL_INT(15, cover_poly(v, t1, 3));
    TEST_ASSERT_EQUAL_INT(10, cover_poly(v, t2, 3));
    for (i = 0; i < 64 * 32; i++) {
        r8_s16 x = (r8_s16)(i % 64), y = (r8_s16)(i / 64);
        int inside = x >= 2 && x < 7 && y >= 3 && y < 8;
        TEST_ASSERT_EQUAL_INT(inside, cover[i]);
    }
}

static unsigned long lcg = 12345;
static r8_s16 rnd(r8_s16 n)
{
    lcg = (lcg * 1103515245UL + 12345UL) & 0x7FFFFFFFUL;
    return (r8_s16)((lcg >> 12) % (unsigned long)n);
}

static void test_fan_no_gaps_no_overlaps(void)
{
    /* A convex 9-gon (clockwise on screen; R8_SCAN_MAXV vertices, the
     * most a polygon may have) with a centre vertex, as a fan of 9
     * triangles, at subpixel positions; every pixel of the 9-gon is
     * covered exactly once by the fan. */
    static const r8_s16 ox[9] = {0, 18, 28, 24, 10, -10, -24, -28, -18};
    static const r8_s16 oy[9] = {-15, -11, -3, 8, 14, 14, 8, -3, -11};
    static r8_svert v[10];
    static r8_u16 outer[10], tri[3];
    r8_s16 trial, i;
    for (trial = 0; trial < N_TRIALS; trial++) {
        long fan = 0, whole;
        for (i = 0; i < 9; i++) {
            v[i].x = (r8_s16)((32 + ox[i]) * 16 + rnd(16) - 8);
            v[i].y = (r8_s16)((16 + oy[i]) * 16 + rnd(16) - 8);
            outer[i] = (r8_u16)i;
        }
        v[9].x = (r8_s16)(32 * 16 + rnd(64) - 32);
        v[9].y = (r8_s16)(16 * 16 + rnd(64) - 32);
        outer[9] = 9;
        clear_cover();
        for (i = 0; i < 9; i++) {
            tri[0] = 9;
            tri[1] = (r8_u16)i;
            tri[2] = (r8_u16)((i + 1) % 9);
            fan += cover_poly(v, tri, 3);
        }
        for (i = 0; i < 64 * 32; i++)
            TEST_ASSERT_TRUE(cover[i] <= 1);
        /* the union is exactly the 9-gon; a 10th vertex is refused */
        TEST_ASSERT_EQUAL_INT(0, cover_poly(v, outer, 10) != 0);
        whole = cover_poly(v, outer, 9);
        TEST_ASSERT_EQUAL_INT(fan, whole);
        for (i = 0; i < 64 * 32; i++)
            TEST_ASSERT_TRUE(cover[i] == 0 || cover[i] == 2);
        TEST_ASSERT_TRUE(fan > 800);   /* the 9-gon is about 1300 px */
    }
}

static void test_shared_edges_random_quads(void)
{
    /* A 4x3 grid of jittered points split into triangles both ways:
     * every pixel inside the grid hull is covered once. */
    static r8_svert v[20];
    static r8_u16 tri[3];
    r8_s16 trial, i, j;
    for (trial = 0; trial < N_TRIALS / 2; trial++) {
        clear_cover();
        for (j = 0; j < 4; j++)
            for (i = 0; i < 5; i++) {
                v[j * 5 + i].x = (r8_s16)(i * 14 * 16 + 40 + (i > 0 && i < 4 ? rnd(80) : 0));
                v[j * 5 + i].y = (r8_s16)(j * 9 * 16 + 30 + (j > 0 && j < 3 ? rnd(60) : 0));
            }
        for (j = 0; j < 3; j++)
            for (i = 0; i < 4; i++) {
                r8_u16 a = (r8_u16)(j * 5 + i), b = (r8_u16)(a + 1), c = (r8_u16)(a + 6), d = (r8_u16)(a + 5);
                if ((i + j + trial) & 1) {
                    tri[0] = a; tri[1] = b; tri[2] = c; cover_poly(v, tri, 3);
                    tri[0] = a; tri[1] = c; tri[2] = d; cover_poly(v, tri, 3);
                } else {
                    tri[0] = a; tri[1] = b; tri[2] = d; cover_poly(v, tri, 3);
                    tri[0] = b; tri[1] = c; tri[2] = d; cover_poly(v, tri, 3);
                }
            }
        for (i = 0; i < 64 * 32; i++)
            TEST_ASSERT_TRUE(cover[i] <= 1);
        /* rows strictly inside the grid have no holes between x 3 and 58 */
        for (j = 4; j < 26; j++)
            for (i = 10; i < 53; i++)
                TEST_ASSERT_EQUAL_INT(1, cover[j * 64 + i]);
    }
}

static void test_judd_skips_reversed(void)
{
    static r8_svert v[3];
    static const r8_u16 cw[3] = {0, 1, 2}, ccw[3] = {0, 2, 1};
    r8_scan s;
    r8_span sp;
    v[0].x = 100; v[0].y = 20;
    v[1].x = 400; v[1].y = 200;
    v[2].x = 50; v[2].y = 300;
    TEST_ASSERT_TRUE(r8_scan_begin(&s, v, cw, 3, 0, 0) > 0);
    TEST_ASSERT_EQUAL_INT(1, r8_scan_next(&s, 100, 1, &sp));
    TEST_ASSERT_EQUAL_INT(0, s.c.backface);
    TEST_ASSERT_TRUE(r8_scan_begin(&s, v, ccw, 3, 0, 0) > 0);
    TEST_ASSERT_EQUAL_INT(0, r8_scan_next(&s, 100, 1, &sp));
    TEST_ASSERT_EQUAL_INT(1, s.c.backface);
    /* without the Judd test a reversed polygon simply draws nothing */
    TEST_ASSERT_TRUE(r8_scan_begin(&s, v, ccw, 3, 0, 0) > 0);
    TEST_ASSERT_EQUAL_INT(0, r8_scan_next(&s, 100, 0, &sp));
}

static void test_scan_resumes_by_band(void)
{
    /* Scanning in bands of 3 rows gives the same spans as in one go. */
    static r8_svert v[4];
    static const r8_u16 q[4] = {0, 1, 2, 3};
    static r8_span a[40];
    r8_scan s;
    r8_span sp;
    int n = 0, m = 0;
    r8_s16 lim;
    v[0].x = 200; v[0].y = 7;
    v[1].x = 600; v[1].y = 100;
    v[2].x = 300; v[2].y = 470;
    v[3].x = 20; v[3].y = 250;
    r8_scan_begin(&s, v, q, 4, R8_ATTR_D, 0);
    while (r8_scan_next(&s, 100, 0, &sp) && n < 40)
        a[n++] = sp;
    r8_scan_begin(&s, v, q, 4, R8_ATTR_D, 0);
    for (lim = 3; lim < 40; lim = (r8_s16)(lim + 3))
        while (r8_scan_next(&s, lim, 0, &sp)) {
            TEST_ASSERT_TRUE(m < n);
            TEST_ASSERT_EQUAL_INT(a[m].y, sp.y);
            TEST_ASSERT_EQUAL_INT(a[m].x0, sp.x0);
            TEST_ASSERT_EQUAL_INT(a[m].x1, sp.x1);
            m++;
        }
    TEST_ASSERT_EQUAL_INT(n, m);
    TEST_ASSERT_TRUE(n > 20);
}

static void test_scan_far_coordinates(void)
{
    /* A triangle with vertices at the 12.4 extremes covers the whole
     * 64x32 area without overflow. */
    static r8_svert v[3];
    static const r8_u16 t[3] = {0, 1, 2};
    r8_s16 i;
    v[0].x = -32767; v[0].y = -32767;
    v[1].x = 32767; v[1].y = -32767;
    v[2].x = 0; v[2].y = 32767;
    clear_cover();
    TEST_ASSERT_EQUAL_INT(64L * 32, cover_poly(v, t, 3));
    for (i = 0; i < 64 * 32; i++)
        TEST_ASSERT_EQUAL_INT(1, cover[i]);
}

/* floor((2*k*a + b) / (2*b)) without overflowing 32 bits */
static long round_ratio(unsigned long k, unsigned long a, unsigned long b)
{
    unsigned long p = k * a;
    return (long)(p / b + ((p % b) * 2 + b) / (2 * b));
}

/* Reference: pixel (x, y) is on the line iff the formula puts it there. */
static int on_line(long x0, long y0, long x1, long y1, long x, long y)
{
    long dx = x1 - x0, dy = y1 - y0, adx = dx < 0 ? -dx : dx, ady = dy < 0 ? -dy : dy;
    long k, q;
    if (adx >= ady) {
        if (dx < 0) { long t = x0; x0 = x1; x1 = t; t = y0; y0 = y1; y1 = t; dy = -dy; }
        if (x < x0 || x > x1) return 0;
        k = x - x0;
        q = adx ? round_ratio((unsigned long)k, (unsigned long)ady, (unsigned long)adx) : 0;
        return y == y0 + (dy < 0 ? -q : q);
    }
    if (dy < 0) { long t = x0; x0 = x1; x1 = t; t = y0; y0 = y1; y1 = t; dx = -dx; }
    if (y < y0 || y > y1) return 0;
    k = y - y0;
    q = round_ratio((unsigned long)k, (unsigned long)adx, (unsigned long)ady);
    return x == x0 + (dx < 0 ? -q : q);
}

static void check_line(r8_s16 x0, r8_s16 y0, r8_s16 x1, r8_s16 y1)
{
    static r8_u8 other[1024];
    r8_fb fb;
    r8_s16 x, y;
    unsigned i;
    r8_fb_init(&fb, fbmem + 4, R8_FMT_PAGE1, 128, 64, 0, 64);
    r8_fb_clear(&fb, 0);
    r8_line(&fb, x1, y1, x0, y0, 1);
    for (i = 0; i < 1024; i++)
        other[i] = fbmem[4 + i];
    r8_fb_clear(&fb, 0);
    r8_line(&fb, x0, y0, x1, y1, 1);
    TEST_ASSERT_EQUAL_MEMORY(other, fbmem + 4, 1024);
    for (y = 0; y < 64; y++)
        for (x = 0; x < 128; x++)
            TEST_ASSERT_EQUAL_INT(on_line(x0, y0, x1, y1, x, y), r8_fb_get(&fb, x, y));
}

static void test_lines_all_octants_both_ways(void)
{
    int i;
    for (i = 0; i < N_LINES; i++)
        check_line((r8_s16)(rnd(200) - 36), (r8_s16)(rnd(120) - 28),
                   (r8_s16)(rnd(200) - 36), (r8_s16)(rnd(120) - 28));
    check_line(5, 5, 5, 5);
    check_line(0, 0, 127, 63);
    check_line(127, 0, 0, 63);
    check_line(-10, 30, 200, 30);
    check_line(40, -10, 40, 100);
}

static void test_lines_at_extremes(void)
{
    r8_fb fb;
    r8_s16 i;
    unsigned n = 0;
    fbmem[0] = fbmem[1] = fbmem[1028] = fbmem[1029] = 0x5A;
    r8_fb_init(&fb, fbmem + 4, R8_FMT_PAGE1, 128, 64, 0, 64);
    r8_fb_clear(&fb, 0);
    r8_line(&fb, -32767, -32767, 32767, 32767, 1);
    for (i = 0; i < 64; i++)
        TEST_ASSERT_EQUAL_INT(1, r8_fb_get(&fb, i, i));
    for (i = 0; i < 1024; i++)
        n += fbmem[4 + i] != 0;
    TEST_ASSERT_EQUAL_UINT(64, n);
    r8_line(&fb, -32768, 32767, 32767, -32768, 1);
    r8_line(&fb, 32767, 32767, 32767, -32768, 1);  /* entirely off screen */
    r8_line(&fb, -32768, 10, 32767, 10, 1);
    for (i = 0; i < 128; i++)
        TEST_ASSERT_EQUAL_INT(1, r8_fb_get(&fb, i, 10));
    TEST_ASSERT_EQUAL_HEX8(0x5A, fbmem[0]);
    TEST_ASSERT_EQUAL_HEX8(0x5A, fbmem[1]);
    TEST_ASSERT_EQUAL_HEX8(0x5A, fbmem[1028]);
    TEST_ASSERT_EQUAL_HEX8(0x5A, fbmem[1029]);
    check_line(-30000, -15000, 30000, 15000);
    check_line(-32767, 32767, 32767, -32767);
}

/* r8_interp_init_sub (reciprocal products) against r8_interp_init_mul
 * (divisions): every field equal, at the ends of each range and on
 * random inputs. */
static void check_sub(r8_s16 base, r8_u16 s0, r8_s16 dv, r8_u16 n)
{
    r8_interp a, b;
    r8_interp_init_sub(&b, base, s0, dv, n);
    r8_interp_init_mul(&a, base, (r8_s32)s0, dv, (r8_s32)dv * R8_SUBPX, n);
    TEST_ASSERT_EQUAL_INT(a.val, b.val);
    TEST_ASSERT_EQUAL_INT(a.q, b.q);
    TEST_ASSERT_EQUAL_UINT(a.err, b.err);
    TEST_ASSERT_EQUAL_UINT(a.r, b.r);
    TEST_ASSERT_EQUAL_UINT(a.den, b.den);
}

static void test_interp_init_sub_matches_mul(void)
{
    static const r8_u16 ns[] = { 1, 2, 3, 7, 15, 16, 17, 100, 163, 255, 256 };
    static const r8_s16 dvs[] = { 0, 1, -1, 2, -2, 17, -17, 4094, -4094, 4095, -4095 };
    static const r8_s16 bases[] = { 0, 32767, -32768, 1000 };
    r8_u16 s0, i, j, k;
    for (s0 = 0; s0 < R8_SUBPX; s0++)
        for (i = 0; i < sizeof ns / sizeof ns[0]; i++)
            for (j = 0; j < sizeof dvs / sizeof dvs[0]; j++)
                for (k = 0; k < sizeof bases / sizeof bases[0]; k++)
                    check_sub(bases[k], s0, dvs[j], ns[i]);
    for (i = 0; i < 200 * N_TRIALS; i++) {
        r8_s16 dv = (r8_s16)(rnd(8191) - 4095);
        check_sub((r8_s16)(rnd(32767) - rnd(32767)), (r8_u16)rnd(R8_SUBPX), dv,
                  (r8_u16)(rnd(256) + 1));
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_interp_exact_endpoints);
    RUN_TEST(test_square_two_triangles_15_10);
    RUN_TEST(test_fan_no_gaps_no_overlaps);
    RUN_TEST(test_shared_edges_random_quads);
    RUN_TEST(test_judd_skips_reversed);
    RUN_TEST(test_scan_resumes_by_band);
    RUN_TEST(test_scan_far_coordinates);
    RUN_TEST(test_lines_all_octants_both_ways);
    RUN_TEST(test_lines_at_extremes);
    RUN_TEST(test_interp_init_sub_matches_mul);
    return UNITY_END();
}
