/* test_scanx.c - r8_scanx_fill where a port links its own
 * (R8_ASM_SCANX: ports/6502/scanx_6502.s) against the C89 reference
 * r8_scanx_fill_c of src/scan.c, elsewhere the C against itself; on
 * every target the fill of whole bands against the same polygon filled
 * one row per call (the model: the scan resumes exactly).  Random convex
 * polygons (3 and 4 vertices, either winding, partly off the frame),
 * bands of 8 and 16 rows, row limits inside bands, Judd's test on and
 * off, every level; band bytes around the fill compared too. */
#include <stddef.h>
#include <string.h>
#include "unity.h"
#include "r8kern.h"
#include "r8raster.h"
#include "r8fb.h"

#ifdef R8_ASM_SCANX
void r8_scanx_fill_c(r8_scanx *s, r8_s16 ylimit, int judd, r8_fb *fb, r8_u8 level);
#else
#define r8_scanx_fill_c r8_scanx_fill
#endif

void setUp(void) {}
void tearDown(void) {}

static r8_u32 seed = 99;
static r8_u16 rnd16(void)
{
    seed = seed * 1103515245ul + 12345ul;
    return (r8_u16)((seed >> 8) & 0xFFFFu);
}
static r8_s16 rndr(r8_s16 lo, r8_s16 hi) /* lo .. hi */
{
    return (r8_s16)(lo + (r8_s16)(rnd16() % (r8_u16)(hi - lo + 1)));
}

/* 16 directions, 64 * (cos, sin) */
static const r8_s16 dirs[16][2] = {
    { 64, 0 }, { 59, 24 }, { 45, 45 }, { 24, 59 }, { 0, 64 }, { -24, 59 },
    { -45, 45 }, { -59, 24 }, { -64, 0 }, { -59, -24 }, { -45, -45 },
    { -24, -59 }, { 0, -64 }, { 24, -59 }, { 45, -45 }, { 59, -24 }
};

#define W 96
#define H 48
#define GUARD 8
static r8_u8 buf_a[W * 2 + 2 * GUARD], buf_b[W * 2 + 2 * GUARD], buf_c[W * 2 + 2 * GUARD];
static r8_s16 pts[4][2];

static void polygon(r8_scanx *s, r8_u8 *n)
{
    r8_s16 cx = rndr(-10 * 16, (W + 10) * 16), cy = rndr(-8 * 16, (H + 8) * 16);
    r8_s16 rx = rndr(16, 40 * 16) / 64, ry = rndr(16, 30 * 16) / 64;
    unsigned k, a = rnd16() % 16u, step;
    *n = (r8_u8)(3u + rnd16() % 2u);
    for (k = 0; k < *n; k++) {
        step = 1u + rnd16() % (*n == 3u ? 5u : 3u);
        a = (a + step) % 16u;
        pts[k][0] = (r8_s16)(cx + rx * dirs[a][0]);
        pts[k][1] = (r8_s16)(cy + ry * dirs[a][1]);
    }
    if (rnd16() & 1u) { /* the other winding */
        r8_s16 t0 = pts[0][0], t1 = pts[0][1];
        pts[0][0] = pts[2][0];
        pts[0][1] = pts[2][1];
        pts[2][0] = t0;
        pts[2][1] = t1;
    }
    for (k = 0; k < *n; k++)
        s->vp[k] = pts[k];
}

static void test_scanx(void)
{
    unsigned i, k, rows_band, fills = 0;
    for (i = 0; i < 500; i++) {
        r8_scanx sa, sb, sc;
        r8_fb fa, fb, fc;
        r8_u8 n, level = (r8_u8)(rnd16() % 20u);
        int judd = (int)(rnd16() & 1u);
        r8_s16 y0, y, lim;
        rows_band = (rnd16() & 1u) ? 16u : 8u;
        /* whole structs are compared below: vp[n..] and padding too */
        memset(&sa, 0, sizeof sa);
        memset(&sb, 0, sizeof sb);
        memset(&sc, 0, sizeof sc);
        polygon(&sa, &n);
        for (k = 0; k < n; k++)
            sb.vp[k] = sc.vp[k] = sa.vp[k];
        y0 = rndr(-4, H);
        if (!r8_scanx_begin(&sa, n, y0))
            continue;
        r8_scanx_begin(&sb, n, y0);
        r8_scanx_begin(&sc, n, y0);
        TEST_ASSERT_EQUAL_INT(0, r8_fb_init(&fa, buf_a + GUARD, R8_FMT_PAGE1, W, H, 0, (r8_s16)rows_band));
        TEST_ASSERT_EQUAL_INT(0, r8_fb_init(&fb, buf_b + GUARD, R8_FMT_PAGE1, W, H, 0, (r8_s16)rows_band));
        TEST_ASSERT_EQUAL_INT(0, r8_fb_init(&fc, buf_c + GUARD, R8_FMT_PAGE1, W, H, 0, (r8_s16)rows_band));
        /* bands from the one above the polygon's first row (the C
         * version's rows above the band) to the bottom */
        for (y = (r8_s16)((y0 < 0 ? 0 : y0) / (r8_s16)rows_band * (r8_s16)rows_band - (r8_s16)rows_band);
             y < H; y = (r8_s16)(y + (r8_s16)rows_band)) {
            if (y < 0)
                continue;
            r8_fb_set_band(&fa, y);
            r8_fb_set_band(&fb, y);
            r8_fb_set_band(&fc, y);
            for (k = 0; k < sizeof buf_a; k++)
                buf_a[k] = buf_b[k] = buf_c[k] = (r8_u8)(rnd16() & 0xFFu);
            lim = (r8_s16)(y + (r8_s16)rows_band);
            if (!(rnd16() & 3u))
                lim = (r8_s16)(y + rndr(0, (r8_s16)rows_band));
            if (!(rnd16() & 7u))
                lim = 30000;
            r8_scanx_fill(&sa, lim, judd, &fa, level);
            r8_scanx_fill_c(&sb, lim, judd, &fb, level);
            TEST_ASSERT_EQUAL_MEMORY(buf_b, buf_a, sizeof buf_a);
            TEST_ASSERT_EQUAL_MEMORY(&sb, &sa, sizeof sa);
            /* the model: one row a call, to the same limit */
            while (sc.y < lim && sc.y < sc.ybot && sc.y < y + (r8_s16)rows_band && !sc.backface) {
                r8_s16 y1 = sc.y;
                r8_scanx_fill(&sc, (r8_s16)(sc.y + 1), judd, &fc, level);
                if (sc.y == y1)
                    break; /* a back face (Judd): the scan is over */
            }
            TEST_ASSERT_EQUAL_MEMORY(buf_a, buf_c, sizeof buf_a);
            fills++;
        }
    }
    TEST_ASSERT_GREATER_THAN(300, fills);
}

#ifdef R8_ASM_SCANX
extern const r8_u8 r8_scanx_offs[];
/* the kernel's offsets are the compiler's */
static void test_offsets(void)
{
    static const r8_u8 want[] = {
        offsetof(r8_scanx, front), offsetof(r8_scanx, y), offsetof(r8_scanx, ybot),
        offsetof(r8_scanx, l), offsetof(r8_scanx, r), offsetof(r8_edge, yend),
        offsetof(r8_fb, buf), offsetof(r8_fb, width), offsetof(r8_fb, y0),
        offsetof(r8_fb, rows), offsetof(r8_fb, format),
        offsetof(r8_trapfill, page), offsetof(r8_trapfill, m), offsetof(r8_trapfill, k),
        offsetof(r8_trapfill, pat), offsetof(r8_trapfill, w)
    };
    TEST_ASSERT_EQUAL_MEMORY(want, r8_scanx_offs, sizeof want);
}
#endif

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_scanx);
#ifdef R8_ASM_SCANX
    RUN_TEST(test_offsets);
#endif
    return UNITY_END();
}
