/* test_scanband.c - r8k_scanband (src/r8scan.h), a face's page-1 band
 * once Judd's test has decided: where a port links its own (the Z80's
 * ports/z80/scanband_z80.s, -DR8_ASM_SCANFILL) against the C89
 * reference r8k_scanband_c of src/scanband.c; on every target against
 * r8_scanx_fill with no Judd test (scan.c's loop: the model).  Random
 * polygons (3 and 4 vertices, either winding, partly off the frame, some
 * 4 times larger) scanned band by band from r8_scanx_begin, bands of 8
 * and 16 rows, limits inside bands, widths 1..96, every level; the
 * band's bytes (guard bytes around them too) and all of s compared after
 * every call. */
#include <string.h>
#include "unity.h"
#include "r8kern.h"
#include "r8raster.h"
#include "r8fb.h"

/* (src/r8scan.h) */
void r8k_scanband(r8_scanx *s, const r8_fb *fb, r8_s16 lim, r8_u8 level);

#if defined(R8_ASM_SCANFILL) && defined(__SDCC)
#define SB_REF 1
void r8k_scanband_c(r8_scanx *s, const r8_fb *fb, r8_s16 lim, r8_u8 level);
#endif

void setUp(void) {}
void tearDown(void) {}

static r8_u32 seed = 4242;
static r8_u16 rnd16(void)
{
    seed = seed * 1103515245ul + 12345ul;
    return (r8_u16)((seed >> 8) & 0xFFFFu);
}
static r8_s16 rndr(r8_s16 lo, r8_s16 hi) /* lo .. hi */
{
    return (r8_s16)(lo + (r8_s16)(rnd16() % (r8_u16)(hi - lo + 1)));
}

/* 16 directions, 64 (cos, sin) */
static const r8_s16 dirs[16][2] = {
    { 64, 0 }, { 59, 24 }, { 45, 45 }, { 24, 59 }, { 0, 64 }, { -24, 59 },
    { -45, 45 }, { -59, 24 }, { -64, 0 }, { -59, -24 }, { -45, -45 },
    { -24, -59 }, { 0, -64 }, { 24, -59 }, { 45, -45 }, { 59, -24 }
};

#define W 96
#define H 48
#define GUARD 8
#define BYTES (W * 2 + 2 * GUARD)
static r8_u8 buf_a[BYTES], buf_b[BYTES];
static r8_s16 pts[4][2];
static r8_scanx sa, sb;
#ifdef SB_REF
static r8_u8 buf_c[BYTES];
static r8_scanx sc;
#endif

static r8_u8 polygon(r8_scanx *s)
{
    r8_s16 cx = rndr(-10 * 16, (W + 10) * 16), cy = rndr(-8 * 16, (H + 8) * 16);
    r8_s16 rx = (r8_s16)(rndr(16, 40 * 16) / 64), ry = (r8_s16)(rndr(16, 30 * 16) / 64);
    unsigned k, a = rnd16() % 16u, step;
    r8_u8 n = (r8_u8)(3u + rnd16() % 2u);
    if (rnd16() % 8u == 0) {
        rx = (r8_s16)(rx * 4);
        ry = (r8_s16)(ry * 4);
    }
    for (k = 0; k < n; k++) {
        step = 1u + rnd16() % (n == 3u ? 5u : 3u);
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
    for (k = 0; k < n; k++)
        s->vp[k] = pts[k];
    return n;
}

static void test_scanband(void)
{
    unsigned i, k, calls = 0;
    unsigned long rows = 0;
    for (i = 0; i < 600; i++) {
        r8_fb fa, fb;
#ifdef SB_REF
        r8_fb fc;
#endif
        r8_u8 n, level = (r8_u8)(rnd16() % 20u);
        r8_s16 rows_band = (r8_s16)((rnd16() & 1u) ? 16 : 8), w = rndr(1, W), y, y0, lim;
        /* whole structs are compared below: vp[n..] and padding too */
        memset(&sa, 0, sizeof sa);
        memset(&sb, 0, sizeof sb);
        n = polygon(&sa);
        for (k = 0; k < n; k++)
            sb.vp[k] = sa.vp[k];
        y0 = rndr(-4, H);
        if (!r8_scanx_begin(&sa, n, y0))
            continue;
        r8_scanx_begin(&sb, n, y0);
        TEST_ASSERT_EQUAL_INT(0, r8_fb_init(&fa, buf_a + GUARD, R8_FMT_PAGE1, w, H, 0, rows_band));
        TEST_ASSERT_EQUAL_INT(0, r8_fb_init(&fb, buf_b + GUARD, R8_FMT_PAGE1, w, H, 0, rows_band));
#ifdef SB_REF
        sc = sb;
        TEST_ASSERT_EQUAL_INT(0, r8_fb_init(&fc, buf_c + GUARD, R8_FMT_PAGE1, w, H, 0, rows_band));
#endif
        for (y = 0; y < H; y = (r8_s16)(y + rows_band)) {
            r8_fb_set_band(&fa, y);
            r8_fb_set_band(&fb, y);
            lim = (r8_s16)(y + rows_band);
            if (!(rnd16() & 3u))
                lim = (r8_s16)(y + rndr(0, rows_band));
            if (lim > sa.ybot)
                lim = sa.ybot;
            /* the kernel's domain: s->y in [fb->y0, lim) */
            if (sa.y < y || sa.y >= lim)
                continue;
            for (k = 0; k < BYTES; k++)
                buf_a[k] = buf_b[k] = (r8_u8)(rnd16() & 0xFFu);
            r8k_scanband(&sa, &fa, lim, level);
            r8_scanx_fill(&sb, lim, 0, &fb, level);
            TEST_ASSERT_EQUAL_MEMORY(buf_b, buf_a, BYTES);
            TEST_ASSERT_EQUAL_MEMORY(&sb, &sa, sizeof sa);
            TEST_ASSERT_EQUAL_INT(lim, sa.y);
#ifdef SB_REF
            /* the port's kernel against its C89 reference, from the
             * same bytes */
            r8_fb_set_band(&fc, y);
            for (k = 0; k < BYTES; k++)
                buf_c[k] = (r8_u8)(rnd16() & 0xFFu);
            memcpy(buf_a, buf_c, BYTES);
            memcpy(&sa, &sc, sizeof sa);
            r8k_scanband_c(&sc, &fc, lim, level);
            r8k_scanband(&sa, &fa, lim, level);
            TEST_ASSERT_EQUAL_MEMORY(buf_c, buf_a, BYTES);
            TEST_ASSERT_EQUAL_MEMORY(&sc, &sa, sizeof sa);
#endif
            calls++;
            rows += (unsigned long)(lim - y);
        }
    }
    /* enough bands, with rows in them */
    TEST_ASSERT_TRUE(calls > 300u);
    TEST_ASSERT_TRUE(rows > 3ul * calls);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_scanband);
    return UNITY_END();
}
