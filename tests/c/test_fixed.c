/* test_fixed.c - fixed-point helpers at the extremes, trig, vectors. */
#include "unity.h"
#include "r8fixed.h"

void setUp(void) {}
void tearDown(void) {}

static void test_mul16_extremes(void)
{
    TEST_ASSERT_EQUAL_INT32(1073741824L, r8_mul16(-32768, -32768));
    TEST_ASSERT_EQUAL_INT32(-1073709056L, r8_mul16(-32768, 32767));
    TEST_ASSERT_EQUAL_INT32(1073676289L, r8_mul16(32767, 32767));
    /* low bytes of 0x80 and above: the SDCC widening-multiply bug case */
    TEST_ASSERT_EQUAL_INT32(0x00018789L, r8_mul16(0x183, 0x103));
    TEST_ASSERT_EQUAL_INT32(0x80L * 0xFFL, r8_mul16(0x80, 0xFF));
    TEST_ASSERT_EQUAL_INT32(-0x1FFL * 0x80L, r8_mul16(-0x1FF, 0x80));
    TEST_ASSERT_EQUAL_INT32(0x7F80L * 0x00C0L, r8_mul16(0x7F80, 0x00C0));
    TEST_ASSERT_EQUAL_INT32(-0x7F80L * 0x00C0L, r8_mul16(-0x7F80, 0x00C0));
}

static void test_mulq_rounding_and_saturation(void)
{
    TEST_ASSERT_EQUAL_INT(256, r8_mulq(256, 256, 8));         /* 1.0 * 1.0 Q8.8 */
    TEST_ASSERT_EQUAL_INT(-384, r8_mulq(-256, 384, 8));       /* -1 * 1.5 */
    TEST_ASSERT_EQUAL_INT(1, r8_mulq(0x80, 0x01, 7));         /* 0.5 rounds away */
    TEST_ASSERT_EQUAL_INT(-1, r8_mulq(-0x80, 0x01, 7));
    TEST_ASSERT_EQUAL_INT(32767, r8_mulq(-32768, -32768, 8)); /* saturates */
    TEST_ASSERT_EQUAL_INT(-32768, r8_mulq(32767, -32768, 8));
    TEST_ASSERT_EQUAL_INT(16384, r8_mulq(16384, 16384, 14));  /* Q1.14 1*1 */
    TEST_ASSERT_EQUAL_INT(0x1C0, r8_mulq(0x01C0, 0x0100, 8)); /* low byte 0xC0 */
    TEST_ASSERT_EQUAL_INT(-0x0181, r8_mulq(-0x0181, 0x0100, 8));
}

static void test_shift_and_division(void)
{
    static const long vals[] = {0, 1, -1, 16383, 16384, -16384, -16385, 1073741823L,
                                -1073741824L, 2147483647L, -2147483647L - 1, 123456789L, -98765432L};
    unsigned i;
    for (i = 0; i < sizeof vals / sizeof vals[0]; i++)
        TEST_ASSERT_EQUAL_INT32(r8_asr32(vals[i], 14), r8_asr14(vals[i]));
    TEST_ASSERT_EQUAL_INT32(-1, r8_asr14(-1));
    TEST_ASSERT_EQUAL_INT32(131071L, r8_asr14(2147483647L));
    TEST_ASSERT_EQUAL_INT32(-131072L, r8_asr14(-2147483647L - 1));
    TEST_ASSERT_EQUAL_INT32(-4, r8_asr32(-7, 1));
    TEST_ASSERT_EQUAL_INT32(-1, r8_asr32(-1, 14));
    TEST_ASSERT_EQUAL_INT32(3, r8_asr32(7, 1));
    TEST_ASSERT_EQUAL_INT32(-4, r8_floordiv(-7, 2));
    TEST_ASSERT_EQUAL_INT32(-3, r8_floordiv(-6, 2));
    TEST_ASSERT_EQUAL_INT32(3, r8_floordiv(7, 2));
    TEST_ASSERT_EQUAL_INT32(-4, r8_divround(-7, 2));
    TEST_ASSERT_EQUAL_INT32(4, r8_divround(7, 2));
    TEST_ASSERT_EQUAL_INT32(-2, r8_divround(7, -4));
    TEST_ASSERT_EQUAL_INT32(-2147483647L - 1, r8_divround(-2147483647L - 1, 1));
}

static void test_muldiv_wide(void)
{
    TEST_ASSERT_EQUAL_INT32(65534L, r8_muldiv(2147483647L, 65534L, 2147483647L));
    TEST_ASSERT_EQUAL_INT32(-1073741823L, r8_muldiv(-2147483647L, 1, 2));
    TEST_ASSERT_EQUAL_INT32(1431655764L, r8_muldiv(2147483647L, 2, 3));
    TEST_ASSERT_EQUAL_INT32(2147483647L, r8_muldiv(2147483647L, 2, 1)); /* saturates */
    TEST_ASSERT_EQUAL_INT32(-6000, r8_muldiv(-100000L, 200000L, 3333333L));
}

static void test_isqrt(void)
{
    TEST_ASSERT_EQUAL_UINT(0, r8_isqrt32(0));
    TEST_ASSERT_EQUAL_UINT(46340u, r8_isqrt32(2147483647UL));
    TEST_ASSERT_EQUAL_UINT(65535u, r8_isqrt32(0xFFFFFFFFUL));
    TEST_ASSERT_EQUAL_UINT(3u, r8_isqrt32(15));
    TEST_ASSERT_EQUAL_UINT(4u, r8_isqrt32(16));
}

static void test_sin_cos(void)
{
    unsigned a;
    TEST_ASSERT_EQUAL_INT(0, r8_sin(0));
    TEST_ASSERT_EQUAL_INT(16384, r8_sin(64));
    TEST_ASSERT_EQUAL_INT(0, r8_sin(128));
    TEST_ASSERT_EQUAL_INT(-16384, r8_sin(192));
    TEST_ASSERT_EQUAL_INT(11585, r8_sin(32));  /* sin 45 deg */
    TEST_ASSERT_EQUAL_INT(16384, r8_cos(0));
    for (a = 0; a < 256; a++) {
        /* sin^2 + cos^2 = 1 to within table rounding */
        r8_s32 s = r8_sin((r8_u8)a), c = r8_cos((r8_u8)a);
        TEST_ASSERT_INT_WITHIN(40000L, 268435456L, s * s + c * c);
        TEST_ASSERT_EQUAL_INT(-r8_sin((r8_u8)a), r8_sin((r8_u8)(256 - a)));
    }
}

static void test_cross_dot_extremes(void)
{
    r8_vec3 a, b;
    r8_vec3l c;
    a.x = -32768; a.y = -32768; a.z = 32767;
    b.x = 32767; b.y = -32768; b.z = -32768;
    r8_cross3(&a, &b, &c);
    /* y*z' - z*y' = (-32768)(-32768) - (32767)(-32768) */
    TEST_ASSERT_EQUAL_INT32(2147450880L, c.x);
    a.x = 3; a.y = 0; a.z = 0;
    b.x = 0; b.y = 5; b.z = 0;
    r8_cross3(&a, &b, &c);
    TEST_ASSERT_EQUAL_INT32(0, c.x);
    TEST_ASSERT_EQUAL_INT32(0, c.y);
    TEST_ASSERT_EQUAL_INT32(15, c.z);
    TEST_ASSERT_EQUAL_INT32(0, r8_dot3(&a, &b));
    TEST_ASSERT_EQUAL_INT32(9, r8_dot3(&a, &a));
}

static void test_normalize(void)
{
    r8_vec3l v;
    r8_vec3 n;
    v.x = 2000000000L; v.y = 0; v.z = 0;
    r8_normalize(&v, &n);
    TEST_ASSERT_EQUAL_INT(16384, n.x);
    v.x = 3; v.y = -4; v.z = 0;
    r8_normalize(&v, &n);
    TEST_ASSERT_INT_WITHIN(2, 9830, n.x);
    TEST_ASSERT_INT_WITHIN(2, -13107, n.y);
}

static void test_rotation(void)
{
    r8_mat3 m;
    r8_vec3 v;
    r8_vec3l o;
    r8_mat_rotate(&m, 0, 64, 0);  /* 90 deg about Y: x -> -z */
    v.x = 100; v.y = 7; v.z = 0;
    r8_mat_apply(&m, &v, &o);
    TEST_ASSERT_EQUAL_INT32(0, o.x);
    TEST_ASSERT_EQUAL_INT32(7, o.y);
    TEST_ASSERT_EQUAL_INT32(-100, o.z);
    r8_mat_rotate(&m, 17, 99, 201);
    v.x = 32767; v.y = -32768; v.z = 32767;
    r8_mat_apply(&m, &v, &o);   /* |o| = |v| = 56755 within rounding */
    TEST_ASSERT_INT_WITHIN(60, 56755L, (r8_s32)r8_isqrt32((r8_u32)(o.x * o.x) + (r8_u32)(o.y * o.y) + (r8_u32)(o.z * o.z)));
}

static void test_projection(void)
{
    r8_proj cam;
    r8_vec3l v;
    r8_s16 sx, sy;
    r8_proj_init(&cam, 128, 64, 100, 16L << R8_CFRAC);
    v.x = 50L << R8_CFRAC; v.y = -25L * R8_CSCALE; v.z = 200L << R8_CFRAC;
    TEST_ASSERT_EQUAL_INT(0, r8_project(&cam, &v, &sx, &sy));
    TEST_ASSERT_EQUAL_INT(64 * 16 + 400, sx);   /* 100*50/200 = 25 px */
    TEST_ASSERT_EQUAL_INT(32 * 16 - 200, sy);
    /* large coordinates: 1000000/100000 * 100 = 1000 px is outside the
     * 900 px guard band; 80 px inside */
    v.x = 1000000L; v.y = -1000000L; v.z = 100000L;
    TEST_ASSERT_EQUAL_INT(1, r8_project(&cam, &v, &sx, &sy));
    v.x = 1000000L; v.y = -1000000L; v.z = 1250000L;
    TEST_ASSERT_EQUAL_INT(0, r8_project(&cam, &v, &sx, &sy));
    TEST_ASSERT_EQUAL_INT(64 * 16 + 1280, sx);
    TEST_ASSERT_EQUAL_INT(32 * 16 - 1280, sy);
}

/* The reciprocal projection against the exact quotient, 100 px either
 * side of the centre, z from 1 to 2^17 units: within one subpixel
 * (rounding to nearest is half; the table's error adds less than 1/8 on
 * screen). */
static void test_projection_precision(void)
{
    r8_proj cam;
    r8_vec3l v;
    r8_s16 sx, sy;
    long z, worst = 0;
    int i;
    r8_proj_init(&cam, 128, 64, 100, 16);
    for (z = 16; z < (1L << 21); z = z * 9 / 8 + 1)
        for (i = -4; i <= 4; i++) {
            long x = z / 4 * i, exact2, got2, err;   /* up to 100 px out */
            v.x = x; v.y = -x; v.z = z;
            if (r8_project(&cam, &v, &sx, &sy))
                continue;
            /* 2 * 16 * 100 * x / z, truncated, in half subpixels */
            exact2 = r8_muldiv(3200L, x, z);
            got2 = 2L * (sx - 64 * 16);
            err = got2 - exact2;
            if (err < 0) err = -err;
            if (err > worst) worst = err;
            TEST_ASSERT_INT_WITHIN(1, -(sx - 64 * 16), sy - 32 * 16);  /* ties round up */
        }
    TEST_ASSERT_TRUE(worst <= 2);   /* half subpixels: rounding plus table error */
}

/* r8_recip: m * 2^(e - 31) within 2^-15 of 1/z, for every magnitude. */
static void test_recip(void)
{
    r8_s32 z;
    r8_s8 e;
    for (z = 1; z < 0x50000000L; z = z + z / 3 + 1) {
        r8_u16 m = r8_recip(z, &e);
        /* z * m * 2^(e-31) ~= 1: scale z into 16 bits with the same e */
        r8_u32 zn = e >= 0 ? (r8_u32)z << e : (r8_u32)z >> -e;
        r8_u32 p = (zn >> 1) * (r8_u32)m;            /* ~ 2^30 */
        TEST_ASSERT_TRUE(m >= 0x8000u);
        TEST_ASSERT_TRUE(zn >= 0x8000UL && zn < 0x10000UL);
        TEST_ASSERT_TRUE(p > 0x40000000UL - 0x10000UL && p < 0x40000000UL + 0x10000UL);
    }
}

static void test_sat16(void)
{
    static const long in[] = {0, 1, -1, 32767, 32768L, -32768L, -32769L, 65535L, 65536L,
                              -65536L, -65537L, 0x7FFF8000L, -0x7FFF8000L, 2147483647L,
                              -2147483647L - 1, 0x18000L, -0x18000L, 0x10000L + 5};
    static const int out[] = {0, 1, -1, 32767, 32767, -32767 - 1, -32767 - 1, 32767, 32767,
                              -32767 - 1, -32767 - 1, 32767, -32767 - 1, 32767,
                              -32767 - 1, 32767, -32767 - 1, 32767};
    unsigned i;
    for (i = 0; i < sizeof in / sizeof in[0]; i++)
        TEST_ASSERT_EQUAL_INT(out[i], r8_sat16(in[i]));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_sat16);
    RUN_TEST(test_mul16_extremes);
    RUN_TEST(test_mulq_rounding_and_saturation);
    RUN_TEST(test_shift_and_division);
    RUN_TEST(test_muldiv_wide);
    RUN_TEST(test_isqrt);
    RUN_TEST(test_sin_cos);
    RUN_TEST(test_cross_dot_extremes);
    RUN_TEST(test_normalize);
    RUN_TEST(test_rotation);
    RUN_TEST(test_projection);
    RUN_TEST(test_projection_precision);
    RUN_TEST(test_recip);
    return UNITY_END();
}
