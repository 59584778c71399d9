/* test_circle.c - Bresenham's midpoint circle (src/circle.c), outline
 * and filled, against the closed form in r8raster.h: random centres and
 * radii near the frame and far outside it (up to the ends of the r8_s16
 * range), whole frames and bands. */
#include <limits.h>
#include "unity.h"
#include "r8raster.h"

#if INT_MAX == 32767
#define N_CASES 10
#define BIG_R 3000      /* the walk is O(r): keep the simulators quick */
#else
#define N_CASES 300
#define BIG_R 32767
#endif

#define W 48
#define H 24

void setUp(void) {}
void tearDown(void) {}

static unsigned long lcg = 11;
static long rnd(long n)
{
    lcg = (lcg * 1103515245UL + 12345UL) & 0x7FFFFFFFUL;
    return (long)((lcg >> 8) % (unsigned long)n);
}

static r8_u8 whole[W * H / 8], part[W * H / 8];

/* Reference: 1 if pixel (x, y) is on (fill 0) or in (fill 1) the circle. */
static int ref(long cx, long cy, long r, long x, long y, int fill)
{
    long a = x - cx, b = y - cy, lo, hi;
    unsigned long s, rr;
    if (a < 0) a = -a;
    if (b < 0) b = -b;
    lo = a < b ? a : b;
    hi = a < b ? b : a;
    if (r < 0)
        return 0;
    if (r == 0)
        return hi == 0;
    s = (unsigned long)lo * (unsigned long)lo + (unsigned long)hi * (unsigned long)hi;
    rr = (unsigned long)r * (unsigned long)r;
    if (s - (unsigned long)hi >= rr)
        return 0;
    return fill || s + (unsigned long)hi >= rr;
}

static void check(r8_s16 cx, r8_s16 cy, r8_s16 r, int fill)
{
    r8_fb fb;
    r8_s16 x, y, y0;
    unsigned i;
    for (i = 0; i < sizeof whole; i++)
        whole[i] = part[i] = 0;
    r8_fb_init(&fb, whole, R8_FMT_PAGE1, W, H, 0, H);
    if (fill)
        r8_circle_fill(&fb, cx, cy, r, 1);
    else
        r8_circle(&fb, cx, cy, r, 1);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++)
            TEST_ASSERT_EQUAL_INT(ref(cx, cy, r, x, y, fill), r8_fb_get(&fb, x, y));
    for (y0 = 0; y0 < H; y0 += 8) {
        r8_fb_init(&fb, part + (unsigned)y0 / 8u * W, R8_FMT_PAGE1, W, H, y0, 8);
        if (fill)
            r8_circle_fill(&fb, cx, cy, r, 1);
        else
            r8_circle(&fb, cx, cy, r, 1);
    }
    TEST_ASSERT_EQUAL_MEMORY(whole, part, sizeof whole);
}

static void test_circle_small_exact(void)
{
    r8_s16 r;
    for (r = -1; r <= 30; r++) {
        check(23, 11, r, 0);
        check(23, 11, r, 1);
        check(0, 23, r, 0);
        check(47, 0, r, 1);
    }
}

static void test_circle_random_exact(void)
{
    int i;
    for (i = 0; i < N_CASES; i++) {
        r8_s16 cx = (r8_s16)(rnd(W * 3) - W), cy = (r8_s16)(rnd(H * 3) - H);
        r8_s16 r = (r8_s16)rnd(60);
        check(cx, cy, r, (int)rnd(2));
    }
}

/* Big circles whose arc crosses the frame, centres near the range ends. */
static void test_circle_far_exact(void)
{
    int i;
    for (i = 0; i < N_CASES / 3 + 2; i++) {
        long r = BIG_R - rnd(BIG_R / 8), off = rnd(W);
        int side = (int)rnd(4), fill = (int)rnd(2);
        r8_s16 cx = (r8_s16)off, cy = (r8_s16)off;
        if (side == 0) cx = (r8_s16)(-r + 20 + rnd(8));
        if (side == 1) cx = (r8_s16)(r + 20 - rnd(8));
        if (side == 2) cy = (r8_s16)(-r + 10 + rnd(8));
        if (side == 3) cy = (r8_s16)(r + 10 - rnd(8));
        check(cx, cy, (r8_s16)r, fill);
    }
    check(-32768, -32768, 32767, 0);   /* nothing reaches the frame */
    check(32767, 32767, 32767, 1);
    check(-32767 + 30, 10, 32767, 0);  /* the arc's rightmost column */
    /* both sides of the 16-bit walk's limits (r 8191, |c| + r 32766) */
    check(-8191 + 20, 5, 8191, 0);
    check(-8192 + 20, 5, 8192, 1);
    check(-32766 + 3000 + 30, 12, 3000, 0);
    check(-32767 + 3000 + 30, 12, 3000, 1);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_circle_small_exact);
    RUN_TEST(test_circle_random_exact);
    RUN_TEST(test_circle_far_exact);
    return UNITY_END();
}
