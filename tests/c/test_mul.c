/* test_mul.c - r8_mul16, the signed 16 x 16 -> 32-bit product: with
 * R8_ASM_MUL16 a port's assembly (ports/6502/mul_6502.s), elsewhere the C
 * of src/fixed.c; either against the C89 reference (r8_s32 p = a;
 * p *= b) on every sign, the extremes, each byte at 0x00 / 0x7F / 0x80
 * / 0xFF, and random operands. */
#include "unity.h"
#include "r8fixed.h"

void setUp(void) {}
void tearDown(void) {}

static r8_s32 ref(r8_s16 a, r8_s16 b)
{
    r8_s32 p = a;
    p *= b;
    return p;
}

static r8_u32 seed = 2024;
static r8_u16 rnd16(void)
{
    seed = seed * 1103515245ul + 12345ul;
    return (r8_u16)((seed >> 8) & 0xFFFFu);
}

static void test_bytes(void)
{
    static const r8_u8 edge[] = {0x00, 0x01, 0x7F, 0x80, 0x81, 0xFE, 0xFF};
    unsigned i, j, k, l;
    for (i = 0; i < sizeof edge; i++)
        for (j = 0; j < sizeof edge; j++)
            for (k = 0; k < sizeof edge; k++)
                for (l = 0; l < sizeof edge; l++) {
                    r8_s16 a = (r8_s16)(r8_u16)((edge[i] << 8) | edge[j]);
                    r8_s16 b = (r8_s16)(r8_u16)((edge[k] << 8) | edge[l]);
                    TEST_ASSERT_EQUAL_INT32(ref(a, b), r8_mul16(a, b));
                    TEST_ASSERT_EQUAL_INT32(ref(a, b), R8_MUL16(a, b));
                }
    TEST_ASSERT_EQUAL_INT32(1073741824L, r8_mul16(-32768, -32768));
    TEST_ASSERT_EQUAL_INT32(-1073709056L, r8_mul16(-32768, 32767));
}

static void test_random(void)
{
    unsigned i;
    for (i = 0; i < 3000; i++) {
        r8_s16 a = (r8_s16)rnd16(), b = (r8_s16)rnd16();
        if (i & 1)
            b = (r8_s16)(b >> 7); /* small operands, as the kernels see them */
        TEST_ASSERT_EQUAL_INT32(ref(a, b), r8_mul16(a, b));
        TEST_ASSERT_EQUAL_INT32(ref(b, a), R8_MUL16(b, a));
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_bytes);
    RUN_TEST(test_random);
    return UNITY_END();
}
