/* test_mul.c - the multiplies: r8_mul16, the signed 16 x 16 -> 32-bit
 * product (with R8_ASM_MUL16 a port's assembly, ports/6502/mul16_6502.s,
 * elsewhere the C of src/fixed.c) against the C89 reference (r8_s32 p =
 * a; p *= b); and the compiler's own int and long `*` (on the 6502
 * ports/6502/rtmul_6502.s replaces cc65's runtime for them) against a
 * model made of 8-bit products.  On every sign, the extremes, each byte
 * at 0x00 / 0x7F / 0x80 / 0xFF, and random operands. */
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

/* the low 32 bits of a * b from byte products (no long multiply) */
static r8_u32 model32(r8_u32 a, r8_u32 b)
{
    unsigned acc[8], i, j;
    r8_u32 r = 0;
    for (i = 0; i < 8; i++)
        acc[i] = 0;
    for (i = 0; i < 4; i++)
        for (j = 0; i + j < 4; j++) {
            unsigned p = (unsigned)((a >> (8 * i)) & 0xFFu) * (unsigned)((b >> (8 * j)) & 0xFFu);
            acc[i + j] += p & 0xFFu;
            acc[i + j + 1] += p >> 8;
        }
    for (i = 0; i < 4; i++) {
        acc[i + 1] += acc[i] >> 8;
        r |= (r8_u32)(acc[i] & 0xFFu) << (8 * i);
    }
    return r;
}

static r8_u32 rnd32(void)
{
    r8_u32 v = rnd16();
    v = (v << 16) | rnd16();
    switch (rnd16() & 7u) {
    case 0:
        return v & 0xFFFFu;                            /* unsigned 16 */
    case 1:
        return (r8_u32)(r8_s32)(r8_s16)(v & 0xFFFFu);  /* signed 16 */
    case 2:
        return (r8_u32)(r8_s32)(r8_s8)(v & 0xFFu);
    case 3:
        return v & 0x00FFFFFFul;
    default:
        return v;
    }
}

/* Whether a * b fits in r8_s32: signed overflow is undefined in C (the
 * host's sanitizer build stops on it), so the signed products are only
 * checked where they fit; the unsigned ones cover the wrap. */
static int fits(r8_s32 a, r8_s32 b)
{
    r8_u32 ua = a < 0 ? (r8_u32)0 - (r8_u32)a : (r8_u32)a;
    r8_u32 ub = b < 0 ? (r8_u32)0 - (r8_u32)b : (r8_u32)b;
    return ua == 0 || ub <= 0x7FFFFFFFul / ua;
}

static void test_long_and_int(void)
{
    static const r8_u32 edge[] = {0, 1, 0xFFFFFFFFul, 0x80000000ul, 0x7FFFFFFFul,
                                  0xFFFFul, 0x10000ul, 0x8000ul, 0xFFFF8000ul, 0xFF00FF00ul};
    unsigned i, j;
    for (i = 0; i < sizeof edge / sizeof edge[0]; i++)
        for (j = 0; j < sizeof edge / sizeof edge[0]; j++) {
            r8_u32 a = edge[i], b = edge[j];
            r8_s32 sa = (r8_s32)a, sb = (r8_s32)b;
            TEST_ASSERT_EQUAL_UINT32(model32(a, b), a * b);
            if (fits(sa, sb))
                TEST_ASSERT_EQUAL_UINT32(model32(a, b), (r8_u32)(sa * sb));
        }
    for (i = 0; i < 3000; i++) {
        r8_u32 a = rnd32(), b = rnd32();
        r8_s32 sa = (r8_s32)a, sb = (r8_s32)b;
        r8_u16 ua = (r8_u16)a, ub = (r8_u16)b;
        r8_s16 ia = (r8_s16)ua, ib = (r8_s16)ub;
        TEST_ASSERT_EQUAL_UINT32(model32(a, b), a * b);
        if (fits(sa, sb))
            TEST_ASSERT_EQUAL_UINT32(model32(a, b), (r8_u32)(sa * sb));
        else if (fits(sa, (r8_s32)ib))        /* a long by a signed 16-bit */
            TEST_ASSERT_EQUAL_UINT32(model32(a, (r8_u32)(r8_s32)ib), (r8_u32)(sa * ib));
        TEST_ASSERT_EQUAL_UINT32(model32(a, ub), a * ub);          /* long * unsigned */
        TEST_ASSERT_EQUAL_HEX16((r8_u16)model32(ua, ub), (r8_u16)((unsigned)ua * ub));
        TEST_ASSERT_EQUAL_HEX16((r8_u16)model32(ua, ub), (r8_u16)(ia * ib));
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_long_and_int);
    RUN_TEST(test_bytes);
    RUN_TEST(test_random);
    return UNITY_END();
}
