/* test_fb.c - framebuffer layouts, clipping and span fills. */
#include "unity.h"
#include "r8fb.h"

static r8_u8 mem[4 + 256 + 4];
#define GUARD 0xA5

void setUp(void)
{
    unsigned i;
    for (i = 0; i < sizeof mem; i++)
        mem[i] = GUARD;
}
void tearDown(void) {}

static void check_guards(unsigned used)
{
    unsigned i;
    for (i = 0; i < 4; i++)
        TEST_ASSERT_EQUAL_HEX8(GUARD, mem[i]);
    for (i = 4 + used; i < sizeof mem; i++)
        TEST_ASSERT_EQUAL_HEX8(GUARD, mem[i]);
}

static void test_sizes(void)
{
    TEST_ASSERT_EQUAL_UINT(1024, r8_fb_bytes(R8_FMT_PAGE1, 128, 64));
    TEST_ASSERT_EQUAL_UINT(128, r8_fb_bytes(R8_FMT_PAGE1, 128, 8));
    TEST_ASSERT_EQUAL_UINT(2 * 3, r8_fb_bytes(R8_FMT_ROW1, 9, 3));
    TEST_ASSERT_EQUAL_UINT(27, r8_fb_bytes(R8_FMT_IDX8, 9, 3));
    TEST_ASSERT_EQUAL_UINT(0, r8_fb_bytes(9, 9, 3));
}

static void test_page_layout(void)
{
    r8_fb fb;
    TEST_ASSERT_EQUAL_INT(0, r8_fb_init(&fb, mem + 4, R8_FMT_PAGE1, 16, 16, 8, 8));
    r8_fb_clear(&fb, 0);
    r8_fb_pixel(&fb, 3, 8, 1);   /* first row of the band: bit 0 */
    r8_fb_pixel(&fb, 4, 15, 1);  /* last row: bit 7 */
    r8_fb_pixel(&fb, 5, 7, 1);   /* above the band: ignored */
    r8_fb_pixel(&fb, 16, 9, 1);  /* right of the frame: ignored */
    TEST_ASSERT_EQUAL_HEX8(0x01, mem[4 + 3]);
    TEST_ASSERT_EQUAL_HEX8(0x80, mem[4 + 4]);
    TEST_ASSERT_EQUAL_HEX8(0x00, mem[4 + 5]);
    TEST_ASSERT_EQUAL_INT(1, r8_fb_get(&fb, 4, 15));
    TEST_ASSERT_EQUAL_INT(0, r8_fb_get(&fb, 4, 14));
    check_guards(16);
    /* band rows must be a multiple of 8 in page layout */
    TEST_ASSERT_EQUAL_INT(-1, r8_fb_init(&fb, mem + 4, R8_FMT_PAGE1, 16, 16, 0, 4));
}

static void test_row_span_whole_bytes(void)
{
    r8_fb fb;
    TEST_ASSERT_EQUAL_INT(0, r8_fb_init(&fb, mem + 4, R8_FMT_ROW1, 32, 2, 0, 2));
    r8_fb_clear(&fb, 0);
    r8_fb_span(&fb, 1, 3, 29, 1);
    TEST_ASSERT_EQUAL_HEX8(0x1F, mem[4 + 4]);
    TEST_ASSERT_EQUAL_HEX8(0xFF, mem[4 + 5]);
    TEST_ASSERT_EQUAL_HEX8(0xFF, mem[4 + 6]);
    TEST_ASSERT_EQUAL_HEX8(0xF8, mem[4 + 7]);
    TEST_ASSERT_EQUAL_HEX8(0x00, mem[4 + 3]);
    r8_fb_span(&fb, 0, 5, 6, 1);    /* one pixel inside one byte */
    TEST_ASSERT_EQUAL_HEX8(0x04, mem[4 + 0]);
    r8_fb_span(&fb, 1, 8, 16, 0);   /* clear exactly one byte */
    TEST_ASSERT_EQUAL_HEX8(0x00, mem[4 + 5]);
    TEST_ASSERT_EQUAL_HEX8(0xFF, mem[4 + 6]);
    check_guards(8);
}

static void test_span_clipping_extremes(void)
{
    r8_fb fb;
    r8_s16 x;
    unsigned n = 0;
    TEST_ASSERT_EQUAL_INT(0, r8_fb_init(&fb, mem + 4, R8_FMT_IDX8, 16, 16, 4, 4));
    r8_fb_clear(&fb, 0);
    r8_fb_span(&fb, 5, -32767 - 1, 32767, 7);
    r8_fb_span(&fb, 3, -5, 30, 9);       /* row above the band */
    r8_fb_span(&fb, 8, -5, 30, 9);       /* row below the band */
    r8_fb_span(&fb, 6, 10, 10, 9);       /* empty */
    r8_fb_span(&fb, 6, 12, 3, 9);        /* reversed: empty */
    r8_fb_span(&fb, -32768, 0, 16, 9);
    r8_fb_span(&fb, 32767, 0, 16, 9);
    for (x = 0; x < 16; x++)
        TEST_ASSERT_EQUAL_INT(7, r8_fb_get(&fb, x, 5));
    for (x = 0; x < 64; x++)
        n += mem[4 + x] != 0;
    TEST_ASSERT_EQUAL_UINT(16, n);
    check_guards(64);
}

static void test_dither_levels(void)
{
    r8_fb fb;
    r8_s16 y, x;
    r8_u8 s;
    for (s = 0; s <= 16; s++) {
        unsigned lit = 0;
        TEST_ASSERT_EQUAL_INT(0, r8_fb_init(&fb, mem + 4, R8_FMT_PAGE1, 8, 8, 0, 8));
        r8_fb_clear(&fb, 0);
        for (y = 0; y < 4; y++)
            r8_fb_span_dither(&fb, y, 0, 4, s, 0);
        for (y = 0; y < 4; y++)
            for (x = 0; x < 4; x++)
                lit += r8_fb_get(&fb, x, y);
        TEST_ASSERT_EQUAL_UINT(s, lit);   /* level s lights s of 16 */
    }
}

static void test_dither_same_in_both_layouts(void)
{
    static r8_u8 a[64], b[64];
    r8_fb fa, fbb;
    r8_s16 y, x;
    r8_fb_init(&fa, a, R8_FMT_PAGE1, 24, 16, 0, 16);
    r8_fb_init(&fbb, b, R8_FMT_ROW1, 24, 16, 0, 16);
    r8_fb_clear(&fa, 0);
    r8_fb_clear(&fbb, 0);
    for (y = 0; y < 16; y++) {
        r8_fb_span_dither(&fa, y, (r8_s16)(y % 5), (r8_s16)(21 - y % 3), (r8_u8)y, 0);
        r8_fb_span_dither(&fbb, y, (r8_s16)(y % 5), (r8_s16)(21 - y % 3), (r8_u8)y, 0);
    }
    for (y = 0; y < 16; y++)
        for (x = 0; x < 24; x++)
            TEST_ASSERT_EQUAL_INT(r8_fb_get(&fa, x, y), r8_fb_get(&fbb, x, y));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_sizes);
    RUN_TEST(test_page_layout);
    RUN_TEST(test_row_span_whole_bytes);
    RUN_TEST(test_span_clipping_extremes);
    RUN_TEST(test_dither_levels);
    RUN_TEST(test_dither_same_in_both_layouts);
    return UNITY_END();
}
