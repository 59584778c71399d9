/* test_lz77.c - the seed's LZ77: shared vectors (tests/vectors/codec.txt),
 * malformed input, output limits, overlapping copies, random round trips. */
#include "unity.h"
#include "r8codec.h"
#include "../vectors/vectors.h"

#define GUARD 0xA5
static r8_u8 enc[320 + 4];
static r8_u8 dec[300 + 4];
static r8_u8 src[300];

void setUp(void)
{
    unsigned i;
    for (i = 0; i < sizeof enc; i++)
        enc[i] = GUARD;
    for (i = 0; i < sizeof dec; i++)
        dec[i] = GUARD;
}
void tearDown(void) {}

static r8_u16 seed = 7;
static r8_u8 rnd(void)
{
    seed = (r8_u16)(seed * 25173u + 13849u);
    return (r8_u8)(seed >> 8);
}

static void test_vectors(void)
{
    unsigned i, len, seen = 0;
    for (i = 0; i < TVEC_COUNT; i++) {
        const tvec *v = &tvecs[i];
        setUp();
        if (v->kind == VK_LZ77) {
            seen++;
            TEST_ASSERT_EQUAL_INT(R8_OK, r8_lz77_encode(v->in, v->in_len, enc, 320, &len));
            TEST_ASSERT_EQUAL_UINT(v->out_len, len);
            TEST_ASSERT_EQUAL_MEMORY(v->out, enc, len);
            TEST_ASSERT_EQUAL_HEX8(GUARD, enc[len]);
            TEST_ASSERT_EQUAL_INT(R8_OK, r8_lz77_decode(v->out, v->out_len, dec, 300, &len));
            TEST_ASSERT_EQUAL_UINT(v->in_len, len);
            TEST_ASSERT_EQUAL_MEMORY(v->in, dec, len);
        } else if (v->kind == VK_LZ77_DEC) {
            seen++;
            TEST_ASSERT_EQUAL_INT(R8_OK, r8_lz77_decode(v->in, v->in_len, dec, 300, &len));
            TEST_ASSERT_EQUAL_UINT(v->out_len, len);
            TEST_ASSERT_EQUAL_MEMORY(v->out, dec, len);
        } else if (v->kind == VK_LZ77_BAD) {
            seen++;
            TEST_ASSERT_EQUAL_INT(v->err, r8_lz77_decode(v->in, v->in_len, dec, v->limit, &len));
            TEST_ASSERT_TRUE(len <= v->limit);
            if (v->limit < 300)
                TEST_ASSERT_EQUAL_HEX8(GUARD, dec[v->limit]);
        }
    }
    TEST_ASSERT_TRUE(seen >= 12);
}

static void test_overlapping_copy(void)
{
    /* "AB" then copy 7 from 2 back: ABABABABA */
    static const r8_u8 in[] = { 0x00, 0x02, 'A', 'B', 0xFF, 0xFE, 0x00, 0x07 };
    unsigned len;
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_lz77_decode(in, sizeof in, dec, 300, &len));
    TEST_ASSERT_EQUAL_UINT(9, len);
    TEST_ASSERT_EQUAL_MEMORY("ABABABABA", dec, 9);
}

static void test_encoder_never_overflows(void)
{
    unsigned n, cap, len, i;
    int rc;
    for (i = 0; i < 80; i++)
        src[i] = (r8_u8)((i % 9) < 5 ? i % 9 : rnd());
    for (n = 1; n <= 80; n += 9) {
        for (cap = 0; cap < R8_LZ77_BOUND(n) + 2; cap++) {
            setUp();
            rc = r8_lz77_encode(src, n, enc, cap, &len);
            TEST_ASSERT_TRUE(rc == R8_OK || rc == R8_E_SPACE);
            TEST_ASSERT_EQUAL_HEX8(GUARD, enc[cap]);
            if (cap >= R8_LZ77_BOUND(n))
                TEST_ASSERT_EQUAL_INT(R8_OK, rc);
        }
    }
}

static void test_random_round_trips(void)
{
    unsigned t, n, i, len, len2;
    for (t = 0; t < 120; t++) {
        n = rnd() + (unsigned)(rnd() & 0x1F);
        for (i = 0; i < n; i++) {
            r8_u8 r = rnd();
            if ((r & 0xE0) == 0 && i >= 8)
                src[i] = src[i - 1 - (r & 7)]; /* repeats at short distances */
            else
                src[i] = (r & 0x10) ? r : 0;
        }
        setUp();
        TEST_ASSERT_EQUAL_INT(R8_OK, r8_lz77_encode(src, n, enc, 320, &len));
        TEST_ASSERT_TRUE(len <= R8_LZ77_BOUND(n));
        TEST_ASSERT_EQUAL_INT(R8_OK, r8_lz77_decode(enc, len, dec, n, &len2));
        TEST_ASSERT_EQUAL_UINT(n, len2);
        TEST_ASSERT_EQUAL_MEMORY(src, dec, n);
        TEST_ASSERT_EQUAL_HEX8(GUARD, dec[n]);
    }
}

static void test_random_garbage_decodes_safely(void)
{
    unsigned t, n, i, len;
    int rc;
    for (t = 0; t < 300; t++) {
        n = rnd() & 0x3F;
        for (i = 0; i < n; i++)
            enc[i] = (r8_u8)(rnd() & ((i & 1) ? 0xFF : 0x80 | (rnd() & 1)));
        for (i = 0; i < sizeof dec; i++)
            dec[i] = GUARD;
        rc = r8_lz77_decode(enc, n, dec, 100, &len);
        TEST_ASSERT_TRUE(rc == R8_OK || rc == R8_E_MALFORMED || rc == R8_E_TRUNC || rc == R8_E_SPACE);
        TEST_ASSERT_TRUE(len <= 100);
        for (i = 100; i < sizeof dec; i++)
            TEST_ASSERT_EQUAL_HEX8(GUARD, dec[i]);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_vectors);
    RUN_TEST(test_overlapping_copy);
    RUN_TEST(test_encoder_never_overflows);
    RUN_TEST(test_random_round_trips);
    RUN_TEST(test_random_garbage_decodes_safely);
    return UNITY_END();
}
