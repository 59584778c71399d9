/* test_line.c - r8_line drawn band by band equals r8_line drawn whole
 * (the wireframe draws edges in bands), and Wu's anti-aliased line
 * (src/wu.c) against its closed form: random cases near the frame and
 * at the ends of the r8_s16 range, both directions, whole and in bands,
 * IDX8 grey levels and the 1 bpp dither. */
#include <limits.h>
#include "unity.h"
#include "r8raster.h"

#if INT_MAX == 32767
#define N_CASES 12
#else
#define N_CASES 400
#endif

#define W 48
#define H 24

void setUp(void) {}
void tearDown(void) {}

static unsigned long lcg = 7;
static long rnd(long n)
{
    lcg = (lcg * 1103515245UL + 12345UL) & 0x7FFFFFFFUL;
    return (long)((lcg >> 8) % (unsigned long)n);
}

static r8_u8 whole[W * H + 4], part[W * H + 4];

static r8_s16 clamp16(long v)
{
    if (v > 32767L) return 32767;
    if (v < -32768L) return -32768;
    return (r8_s16)v;
}

/* A random line: near the frame, through the frame from far away, or
 * between the corners of the coordinate range. */
static void pick(r8_s16 *p)
{
    static const r8_s16 ext[4] = { -32768, -32767, 32766, 32767 };
    long px = rnd(W), py = rnd(H), ex, ey;
    switch (rnd(4)) {
    case 0:
        p[0] = (r8_s16)(rnd(W * 2) - W / 2); p[1] = (r8_s16)(rnd(H * 2) - H / 2);
        p[2] = (r8_s16)(rnd(W * 2) - W / 2); p[3] = (r8_s16)(rnd(H * 2) - H / 2);
        break;
    case 1:   /* far end anywhere, the other mirrored through the frame */
        ex = rnd(65536L) - 32768L;
        ey = rnd(65536L) - 32768L;
        p[0] = (r8_s16)ex; p[1] = (r8_s16)ey;
        p[2] = clamp16(2 * px - ex); p[3] = clamp16(2 * py - ey);
        break;
    case 2:   /* shallow or steep through the frame, ends at the range */
        if (rnd(2)) {
            p[0] = ext[rnd(2)]; p[2] = ext[2 + rnd(2)];
            p[1] = (r8_s16)(py + rnd(5) - 2); p[3] = (r8_s16)(py + rnd(400) - 200);
        } else {
            p[1] = ext[rnd(2)]; p[3] = ext[2 + rnd(2)];
            p[0] = (r8_s16)(px + rnd(5) - 2); p[2] = (r8_s16)(px + rnd(400) - 200);
        }
        break;
    default:
        p[0] = ext[rnd(4)]; p[1] = ext[rnd(4)];
        p[2] = ext[rnd(4)]; p[3] = ext[rnd(4)];
        if (rnd(2)) { p[2] = (r8_s16)px; p[3] = (r8_s16)py; }
    }
}

/* Reference: the Wu level (0..16) of pixel (x, y) from the closed form. */
static int wu_ref(long x0, long y0, long x1, long y1, long x, long y)
{
    long dx = x1 - x0, dy = y1 - y0, t, ma0, mi0, dm, len, k, off;
    long adx = dx < 0 ? -dx : dx, ady = dy < 0 ? -dy : dy;
    unsigned long p, q, r, w;
    if (ady > adx) {   /* steep: y is the major axis */
        t = x0; x0 = y0; y0 = t; t = x1; x1 = y1; y1 = t; t = x; x = y; y = t;
    }
    if (x1 < x0) {
        t = x0; x0 = x1; x1 = t; t = y0; y0 = y1; y1 = t;
    }
    ma0 = x0; mi0 = y0; len = x1 - x0; dm = y1 - y0;
    k = x - ma0;
    if (k < 0 || k > len)
        return 0;
    off = y - mi0;
    if (len == 0)
        return off == 0 ? 16 : 0;
    if (dm < 0) {
        dm = -dm;
        off = -off;
    }
    p = (unsigned long)k * (unsigned long)dm;
    q = p / (unsigned long)len;
    r = p % (unsigned long)len;
    w = 16UL * r / (unsigned long)len;
    if (off == (long)q)
        return (int)(16UL - w);
    if (off == (long)q + 1)
        return (int)w;
    return 0;
}

static void draw_banded(r8_u8 *mem, r8_u8 fmt, int band, int wu, const r8_s16 *p, r8_u8 c)
{
    r8_fb fb;
    int y0;
    unsigned bb = r8_fb_bytes(fmt, W, (r8_s16)band);
    for (y0 = 0; y0 < H; y0 += band) {
        r8_fb_init(&fb, mem + (unsigned)(y0 / band) * bb, fmt, W, H, (r8_s16)y0, (r8_s16)band);
        if (wu)
            r8_wu_line(&fb, p[0], p[1], p[2], p[3], c);
        else
            r8_line(&fb, p[0], p[1], p[2], p[3], c);
    }
}

static void clear(r8_u8 *m)
{
    unsigned i;
    for (i = 0; i < W * H + 4; i++)
        m[i] = 0;
}

static void test_line_bands_equal_whole(void)
{
    int i, hits = 0;
    r8_s16 p[4];
    r8_fb fb;
    unsigned k;
    for (i = 0; i < N_CASES; i++) {
        int band = rnd(2) ? 8 : 16;   /* page layout: multiples of 8 */
        pick(p);
        clear(whole);
        clear(part);
        r8_fb_init(&fb, whole, R8_FMT_PAGE1, W, H, 0, H);
        r8_line(&fb, p[0], p[1], p[2], p[3], 1);
        draw_banded(part, R8_FMT_PAGE1, band, 0, p, 1);
        /* bands of 8 rows are consecutive page rows: the same bytes */
        TEST_ASSERT_EQUAL_MEMORY(whole, part, W * H / 8 + 4);
        for (k = 0; k < W * H / 8; k++)
            hits += whole[k] != 0;
    }
    TEST_ASSERT_TRUE(hits > 0);
}

/* The three layouts light the same pixels (each has its own walk). */
static void test_line_formats_agree(void)
{
    static r8_u8 row[W * H / 8 + 4];
    int i, hits = 0;
    r8_s16 p[4], x, y;
    r8_fb a, b, c;
    for (i = 0; i < N_CASES; i++) {
        unsigned k;
        pick(p);
        clear(whole);
        clear(part);
        for (k = 0; k < sizeof row; k++)
            row[k] = 0;
        r8_fb_init(&a, whole, R8_FMT_PAGE1, W, H, 0, H);
        r8_fb_init(&b, part, R8_FMT_IDX8, W, H, 0, H);
        r8_fb_init(&c, row, R8_FMT_ROW1, W, H, 0, H);
        r8_line(&a, p[0], p[1], p[2], p[3], 1);
        r8_line(&b, p[0], p[1], p[2], p[3], 9);
        r8_line(&c, p[0], p[1], p[2], p[3], 1);
        for (y = 0; y < H; y++)
            for (x = 0; x < W; x++) {
                int on = r8_fb_get(&a, x, y);
                TEST_ASSERT_EQUAL_INT(on ? 9 : 0, r8_fb_get(&b, x, y));
                TEST_ASSERT_EQUAL_INT(on, r8_fb_get(&c, x, y));
                hits += on;
            }
        TEST_ASSERT_EQUAL_INT(0, part[W * H] | part[W * H + 1] | row[W * H / 8]);
        /* colour 0 clears exactly those pixels again */
        r8_line(&a, p[2], p[3], p[0], p[1], 0);
        for (k = 0; k < W * H / 8; k++)
            TEST_ASSERT_EQUAL_INT(0, whole[k]);
    }
    TEST_ASSERT_TRUE(hits > 0);
}

static void check_wu(const r8_s16 *p, r8_u8 base)
{
    r8_fb fb;
    r8_s16 x, y, q[4];
    int band = (int)rnd(H) + 1;
    clear(whole);
    clear(part);
    r8_fb_init(&fb, whole, R8_FMT_IDX8, W, H, 0, H);
    r8_wu_line(&fb, p[0], p[1], p[2], p[3], base);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            int l = wu_ref(p[0], p[1], p[2], p[3], x, y);
            TEST_ASSERT_EQUAL_INT(l ? base + l : 0, whole[y * W + x]);
        }
    /* the other way round, in bands of any height: the same bytes */
    q[0] = p[2]; q[1] = p[3]; q[2] = p[0]; q[3] = p[1];
    {
        int y0;
        for (y0 = 0; y0 < H; y0 += band) {
            r8_fb_init(&fb, part + (unsigned)y0 * W, R8_FMT_IDX8, W, H, (r8_s16)y0, (r8_s16)band);
            r8_wu_line(&fb, q[0], q[1], q[2], q[3], base);
        }
    }
    TEST_ASSERT_EQUAL_MEMORY(whole, part, W * H + 4);
}

static void test_wu_idx8_exact(void)
{
    int i;
    r8_s16 p[4];
    for (i = 0; i < N_CASES; i++) {
        pick(p);
        check_wu(p, (r8_u8)(rnd(2) ? 0 : 100));
    }
    p[0] = 3; p[1] = 3; p[2] = 3; p[3] = 3;        /* one pixel */
    check_wu(p, 0);
    p[0] = 0; p[1] = 0; p[2] = 47; p[3] = 23;      /* corner to corner */
    check_wu(p, 0);
    p[0] = -32768; p[1] = -32768; p[2] = 32767; p[3] = 32767;
    check_wu(p, 0);
    p[0] = -32768; p[1] = 5; p[2] = 32767; p[3] = 6;
    check_wu(p, 0);
    p[0] = 20; p[1] = -32768; p[2] = 21; p[3] = 32767;
    check_wu(p, 0);
}

/* Crossing lines keep the brighter level; the ends get full weight. */
static void test_wu_max_blend_and_ends(void)
{
    r8_fb fb;
    r8_s16 x, y;
    clear(whole);
    r8_fb_init(&fb, whole, R8_FMT_IDX8, W, H, 0, H);
    r8_wu_line(&fb, 0, 0, 47, 17, 0);
    r8_wu_line(&fb, 0, 20, 40, 1, 0);
    TEST_ASSERT_EQUAL_INT(16, whole[0]);
    TEST_ASSERT_EQUAL_INT(16, whole[17 * W + 47]);
    TEST_ASSERT_EQUAL_INT(16, whole[1 * W + 40]);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            int a = wu_ref(0, 0, 47, 17, x, y), b = wu_ref(0, 20, 40, 1, x, y);
            TEST_ASSERT_EQUAL_INT(a > b ? a : b, whole[y * W + x]);
        }
    /* the two pixels of every column add up to 16 */
    for (x = 0; x < W; x++) {
        int s = 0;
        for (y = 0; y < H; y++)
            s += wu_ref(0, 0, 47, 17, x, y);
        TEST_ASSERT_EQUAL_INT(16, s);
    }
}

/* 1 bpp: the level through the ordered dither, lit pixels only. */
static void test_wu_dither_1bpp(void)
{
    int i, lit = 0;
    r8_s16 p[4], x, y;
    r8_fb fb;
    for (i = 0; i < N_CASES / 2 + 2; i++) {
        r8_u8 fmt = (r8_u8)(rnd(2) ? R8_FMT_ROW1 : R8_FMT_PAGE1);
        pick(p);
        if (i == 0) { p[0] = 0; p[1] = 2; p[2] = 47; p[3] = 13; }
        clear(whole);
        clear(part);
        r8_fb_init(&fb, whole, fmt, W, H, 0, H);
        r8_wu_line(&fb, p[0], p[1], p[2], p[3], 0);
        for (y = 0; y < H; y++)
            for (x = 0; x < W; x++) {
                int l = wu_ref(p[0], p[1], p[2], p[3], x, y);
                int on = l > R8_RDU8(&r8_fb_dither_thresholds(y)[x & 3]);
                TEST_ASSERT_EQUAL_INT(on, r8_fb_get(&fb, x, y));
                lit += on;
            }
        draw_banded(part, fmt, 8, 1, p, 0);
        TEST_ASSERT_EQUAL_MEMORY(whole, part, W * H / 8 + 4);
    }
    TEST_ASSERT_TRUE(lit > 0);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_line_bands_equal_whole);
    RUN_TEST(test_line_formats_agree);
    RUN_TEST(test_wu_idx8_exact);
    RUN_TEST(test_wu_max_blend_and_ends);
    RUN_TEST(test_wu_dither_1bpp);
    return UNITY_END();
}
