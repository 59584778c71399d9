/* test_stability.c - the scan converter, interpolator and line drawer at
 * the places where they could fail (issue 6; docs/stability.md): long thin
 * slivers, zero-area, collinear and duplicate-vertex polygons, vertices
 * at +/-32767 subpixels and far beyond the screen, 10,000-step
 * interpolation.  Every buffer has guard bytes on both sides; every case
 * states its error bound against an exact integer rasterisation (64-bit
 * edge functions, pixel centres, top-left rule: the same rule as
 * host/rast8/reference.py). */
#include <stdio.h>
#include <string.h>
#include <stdlib.h>
#include "unity.h"
#include "r8raster.h"
#include "r8fb.h"
#include "r8fixed.h"

#define W 128
#define H 64
#define GUARD 64
#define GB 0xA5

static r8_u8 mem[GUARD + W * H + GUARD];
static r8_u8 *const pix = mem + GUARD;
static r8_u8 exact[W * H];

void setUp(void) {}
void tearDown(void) {}

static void guard_set(void)
{
    memset(mem, GB, sizeof mem);
    memset(pix, 0, W * H);
}

static void guard_check(void)
{
    int i;
    for (i = 0; i < GUARD; i++) {
        TEST_ASSERT_EQUAL_HEX8(GB, mem[i]);
        TEST_ASSERT_EQUAL_HEX8(GB, mem[GUARD + W * H + i]);
    }
}

static unsigned lcg_state = 12345u;
static long rnd(long lo, long hi)
{
    lcg_state = lcg_state * 1103515245u + 12345u;
    return lo + (long)((lcg_state >> 8) % (unsigned long)(hi - lo + 1));
}

/* Exact fill of a clockwise convex polygon (12.4 vertices) into exact[];
 * returns its pixel count.  near_edge[] flags the pixels whose centre
 * lies within `tol` subpixels (horizontally, along the row) of an edge. */
static r8_u8 near_edge[W * H];
static long exact_fill(const r8_svert *v, int n, double tol)
{
    long cnt = 0, area2 = 0;
    int i, r, c;
    memset(exact, 0, sizeof exact);
    memset(near_edge, 0, sizeof near_edge);
    for (i = 0; i < n; i++) {
        const r8_svert *a = &v[i], *b = &v[(i + 1) % n];
        area2 += (long)a->x * b->y - (long)b->x * a->y;
    }
    for (r = 0; r < H; r++)
        for (c = 0; c < W; c++) {
            long long px = 16 * c + 8, py = 16 * r + 8;
            int in = area2 > 0;
            for (i = 0; i < n; i++) {
                const r8_svert *a = &v[i], *b = &v[(i + 1) % n];
                long long dx = (long long)b->x - a->x, dy = (long long)b->y - a->y;
                long long e;
                double len;
                if (dx == 0 && dy == 0)
                    continue;
                e = dx * (py - a->y) - dy * (px - a->x);
                len = (double)dy * dy;   /* horizontal distance to the edge */
                if ((double)e * (double)e <= tol * tol * len)
                    near_edge[r * W + c] = 1;
                if (!(e > 0 || (e == 0 && (dy < 0 || (dy == 0 && dx > 0)))))
                    in = 0;
            }
            exact[r * W + c] = (r8_u8)in;
            cnt += in;
        }
    return cnt;
}

/* r8_fill_poly into pix (IDX8, colour 1) with guards; returns mismatches
 * against exact[] outside the near_edge pixels, and counts in *all. */
static long fill_and_compare(const r8_svert *v, int n, long *all, long *written)
{
    r8_fb fb;
    r8_u16 idx[16];
    long bad = 0, any = 0;
    int i;
    for (i = 0; i < n; i++)
        idx[i] = (r8_u16)i;
    guard_set();
    TEST_ASSERT_EQUAL_INT(0, r8_fb_init(&fb, pix, R8_FMT_IDX8, W, H, 0, H));
    *written = r8_fill_poly(&fb, v, idx, (r8_u8)n, 1);
    guard_check();
    for (i = 0; i < W * H; i++) {
        TEST_ASSERT_TRUE(pix[i] <= 1);
        if (pix[i] != exact[i]) {
            any++;
            if (!near_edge[i])
                bad++;
        }
    }
    *all = any;
    return bad;
}

static void sv(r8_svert *v, long x, long y)
{
    v->x = (r8_s16)x;
    v->y = (r8_s16)y;
    v->d = 0;
    v->s = 0;
}

/* Long thin slivers: 1 to 2 subpixels wide, 200 to 4000 pixels long, at
 * every angle, through the screen.  Bound: exact (0 pixels differ). */
static void test_slivers_exact(void)
{
    int k;
    long total = 0;
    for (k = 0; k < 400; k++) {
        r8_svert v[3];
        long all, wr, cx = rnd(0, W * 16), cy = rnd(0, H * 16);
        long len = rnd(200, 1000) * 16;   /* half length, subpixels: edges under 2048 px tall */
        long ex = k % 2 ? rnd(-len, len) : len, ey = k % 2 ? len : rnd(-len, len);
        long w = rnd(1, 2);
        if (cx + ex > 32767 || cx - ex < -32767 || cy + ey > 32767 || cy - ey < -32767)
            continue;
        sv(&v[0], cx - ex, cy - ey);
        sv(&v[1], cx + ex, cy + ey);
        sv(&v[2], cx + ex + w, cy + ey + w);
        if ((long)(v[1].x - v[0].x) * (v[2].y - v[0].y) - (long)(v[1].y - v[0].y) * (v[2].x - v[0].x) < 0) {
            r8_svert t = v[1];
            v[1] = v[2];
            v[2] = t;
        }
        total += exact_fill(v, 3, 0.0);
        if (getenv("R8_DEBUG") && fill_and_compare(v, 3, &all, &wr))
            printf("%d %d %d %d %d %d\n", v[0].x, v[0].y, v[1].x, v[1].y, v[2].x, v[2].y);
        TEST_ASSERT_EQUAL_INT(0, fill_and_compare(v, 3, &all, &wr));
        TEST_ASSERT_EQUAL_INT(0, all);
    }
    TEST_ASSERT_TRUE(total > 0);   /* some slivers do hit pixel centres */
}

/* Zero-area (all vertices collinear or equal): nothing drawn, nothing
 * written anywhere.  Duplicate vertices: the same pixels as without. */
static void test_degenerate_polygons(void)
{
    int k;
    for (k = 0; k < 300; k++) {
        r8_svert v[6];
        long all, wr;
        long x0 = rnd(-3000, 3000), y0 = rnd(-3000, 3000), dx = rnd(-400, 400), dy = rnd(-400, 400);
        int i;
        for (i = 0; i < 4; i++) {         /* collinear, possibly repeated */
            long m = rnd(0, 3);
            sv(&v[i], x0 + dx * m, y0 + dy * m);
        }
        exact_fill(v, 4, 0.0);
        if (getenv("R8_DEBUG") && fill_and_compare(v, 4, &all, &wr))
            printf("%d %d %d %d %d %d %d %d\n", v[0].x, v[0].y, v[1].x, v[1].y, v[2].x, v[2].y, v[3].x, v[3].y);
        TEST_ASSERT_EQUAL_INT(0, fill_and_compare(v, 4, &all, &wr));
        TEST_ASSERT_EQUAL_INT(0, wr);
        TEST_ASSERT_EQUAL_INT(0, all);
        /* a triangle with each vertex repeated: same as the triangle */
        sv(&v[0], rnd(-500, 2500), rnd(-500, 1500));
        sv(&v[2], rnd(-500, 2500), rnd(-500, 1500));
        sv(&v[4], rnd(-500, 2500), rnd(-500, 1500));
        if ((long)(v[2].x - v[0].x) * (v[4].y - v[0].y) - (long)(v[2].y - v[0].y) * (v[4].x - v[0].x) < 0) {
            r8_svert t = v[2];
            v[2] = v[4];
            v[4] = t;
        }
        v[1] = v[0];
        v[3] = v[2];
        v[5] = v[4];
        exact_fill(v, 6, 0.0);
        TEST_ASSERT_EQUAL_INT(0, fill_and_compare(v, 6, &all, &wr));
        TEST_ASSERT_EQUAL_INT(0, all);
    }
}

/* Vertices anywhere in r8_s16 (+/-2047 pixels): edges over 2047 pixels
 * tall take the scan converter's half-subpixel path (row position within
 * one subpixel, so x within |dx/dy| <= 2 subpixels plus rounding): a
 * pixel may differ from the exact fill only when its centre lies within
 * 3 subpixels (along the row) of an edge.  Shorter edges stay exact. */
static void test_huge_coordinates(void)
{
    int k;
    long near_total = 0, tall = 0;
    static const long ext[4][2] = {{-32767, -32767}, {32767, -32767}, {32767, 32767}, {-32767, 32767}};
    for (k = 0; k < 400; k++) {
        r8_svert v[4];
        long all, wr, bad;
        int i, n = 3;
        for (i = 0; i < 3; i++) {
            if (rnd(0, 3) == 0)
                sv(&v[i], ext[rnd(0, 3)][0], ext[rnd(0, 3)][1]);
            else
                sv(&v[i], rnd(-32767, 32767), rnd(-32767, 32767));
        }
        if ((long)(v[1].x - v[0].x) * (v[2].y - v[0].y) - (long)(v[1].y - v[0].y) * (v[2].x - v[0].x) < 0) {
            r8_svert t = v[1];
            v[1] = v[2];
            v[2] = t;
        }
        for (i = 0; i < 3; i++) {
            long dy = (long)v[(i + 1) % 3].y - v[i].y;
            if (dy > 32767 || dy < -32767)
                tall++;
        }
        exact_fill(v, n, 3.0);
        bad = fill_and_compare(v, n, &all, &wr);
        TEST_ASSERT_EQUAL_INT(0, bad);
        near_total += all;
    }
    /* the whole screen, from vertices at the corners of the 12.4 range */
    {
        r8_svert v[4];
        long all, wr;
        sv(&v[0], -32767, -32767);
        sv(&v[1], 32767, -32767);
        sv(&v[2], 32767, 32767);
        sv(&v[3], -32767, 32767);
        exact_fill(v, 4, 0.0);
        if (getenv("R8_DEBUG") && fill_and_compare(v, 4, &all, &wr))
            printf("%d %d %d %d %d %d %d %d\n", v[0].x, v[0].y, v[1].x, v[1].y, v[2].x, v[2].y, v[3].x, v[3].y);
        TEST_ASSERT_EQUAL_INT(0, fill_and_compare(v, 4, &all, &wr));
        TEST_ASSERT_EQUAL_INT(W * H, wr);
    }
    TEST_ASSERT_TRUE(tall > 50);            /* the half-subpixel path was taken */
    TEST_ASSERT_LESS_OR_EQUAL(150, near_total);  /* measured 74 in 400 triangles: docs/stability.md */
}

/* The scan converter walked band by band (ystart, ylimit) over a huge
 * polygon gives the same spans as in one go; spans never exceed the
 * polygon's exact extent. */
static void test_bands_on_huge_polygon(void)
{
    r8_svert v[4];
    r8_u16 idx[4] = {0, 1, 2, 3};
    r8_scan a, b;
    r8_span sa, sb;
    r8_s16 y;
    sv(&v[0], -30000, -31000);
    sv(&v[1], 29000, -20000);
    sv(&v[2], 31000, 32000);
    sv(&v[3], -32000, 25000);
    TEST_ASSERT_TRUE(r8_scan_begin(&a, v, idx, 4, 0, 0) > 0);
    for (y = 0; y < H; y += 8) {
        TEST_ASSERT_TRUE(r8_scan_begin(&b, v, idx, 4, 0, y) > 0);
        while (r8_scan_next(&a, (r8_s16)(y + 8), 0, &sa)) {
            TEST_ASSERT_TRUE(r8_scan_next(&b, (r8_s16)(y + 8), 0, &sb));
            TEST_ASSERT_EQUAL_INT(sa.y, sb.y);
            TEST_ASSERT_EQUAL_INT(sa.x0, sb.x0);
            TEST_ASSERT_EQUAL_INT(sa.x1, sb.x1);
            TEST_ASSERT_TRUE(sa.x0 >= -2048 && sa.x1 <= 2048);
        }
    }
}

/* 10,000-step interpolation: the stepwise interpolator is exact at every
 * step (value k == floor(a + (b - a) k / n)), so nothing drifts however
 * long the span; the same values from r8_interp_init_mul with products
 * past 32 bits.  A naive 8.8 accumulated delta drifts by up to
 * n / 256 (docs/stability.md): 33 over 10,000 steps. */
static void test_interp_no_drift(void)
{
    static const long ends[][2] = {{0, 32767}, {32767, 0}, {-16384, 16383}, {5, 6}, {100, -100}, {0, 0}};
    static const unsigned ns[] = {1, 3, 255, 10000, 32767};
    unsigned e, j;
    for (e = 0; e < sizeof ends / sizeof ends[0]; e++)
        for (j = 0; j < sizeof ns / sizeof ns[0]; j++) {
            r8_interp it;
            long a = ends[e][0], b = ends[e][1], n = (long)ns[j], k, worst = 0;
            long naive = a * 256, dn = ((b - a) * 256) / n;
            r8_interp_reset(&it, (r8_s16)a, (r8_s16)b, (r8_u16)n);
            for (k = 0; k <= n; k++) {
                long long num = (long long)(b - a) * k;
                long want = a + (long)(num >= 0 ? num / n : -((-num + n - 1) / n));
                long dv = (naive >> 8) - want;
                TEST_ASSERT_EQUAL_INT(want, it.val);
                if (dv < 0) dv = -dv;
                if (dv > worst) worst = dv;
                if (k < n) {
                    R8_INTERP_STEP(&it);
                    naive += dn;
                }
            }
            TEST_ASSERT_EQUAL_INT(b, it.val);
            TEST_ASSERT_LESS_OR_EQUAL(n / 256 + 1, worst);  /* the naive form's drift bound */
        }
    /* start part-way along (spans clipped at x = 0): a * b past 2^31 */
    {
        r8_interp it, ref;
        long k, k0 = 9000, n = 10000;
        r8_interp_init_mul(&it, 0, k0, 30000L, 30000L, (r8_u16)n);
        r8_interp_reset(&ref, 0, 30000, (r8_u16)n);
        for (k = 0; k < k0; k++)
            R8_INTERP_STEP(&ref);
        for (k = k0; k <= n; k++) {
            TEST_ASSERT_EQUAL_INT(ref.val, it.val);
            R8_INTERP_STEP(&it);
            R8_INTERP_STEP(&ref);
        }
    }
}

/* Lines from far outside the screen: clipped exactly, never written
 * outside the band (all four formats' writers go through r8_fb_pixel or
 * the byte layouts; guards on IDX8). */
static void test_lines_far_outside(void)
{
    int k;
    r8_fb fb;
    for (k = 0; k < 2000; k++) {
        long x0 = rnd(-32768, 32767), y0 = rnd(-32768, 32767);
        long x1 = rnd(-32768, 32767), y1 = rnd(-32768, 32767);
        guard_set();
        TEST_ASSERT_EQUAL_INT(0, r8_fb_init(&fb, pix, R8_FMT_IDX8, W, H, 0, H));
        r8_line(&fb, (r8_s16)x0, (r8_s16)y0, (r8_s16)x1, (r8_s16)y1, 7);
        guard_check();
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_slivers_exact);
    RUN_TEST(test_degenerate_polygons);
    RUN_TEST(test_huge_coordinates);
    RUN_TEST(test_bands_on_huge_polygon);
    RUN_TEST(test_interp_no_drift);
    RUN_TEST(test_lines_far_outside);
    return UNITY_END();
}
