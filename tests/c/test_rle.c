/* test_rle.c - the seed's RLE: shared vectors (tests/vectors/codec.txt),
 * malformed input, output limits and random round trips. */
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

static r8_u16 seed = 1;
static r8_u8 rnd(void)
{
    seed = (r8_u16)(seed * 25173u + 13849u);
    return (r8_u8)(seed >> 8);
}

static void test_vectors_encode_decode(void)
{
    unsigned i, len, seen = 0;
    for (i = 0; i < TVEC_COUNT; i++) {
        const tvec *v = &tvecs[i];
        if (v->kind != VK_RLE)
            continue;
        seen++;
        setUp();
        TEST_ASSERT_EQUAL_INT(R8_OK, r8_rle_encode(v->in, v->in_len, enc, 320, &len));
        TEST_ASSERT_EQUAL_UINT(v->out_len, len);
        TEST_ASSERT_EQUAL_MEMORY(v->out, enc, len);
        TEST_ASSERT_EQUAL_HEX8(GUARD, enc[len]);
        TEST_ASSERT_TRUE(len <= R8_RLE_BOUND(v->in_len));
        TEST_ASSERT_EQUAL_INT(R8_OK, r8_rle_decode(v->out, v->out_len, dec, 300, &len));
        TEST_ASSERT_EQUAL_UINT(v->in_len, len);
        TEST_ASSERT_EQUAL_MEMORY(v->in, dec, len);
    }
    TEST_ASSERT_TRUE(seen >= 10);
}

static void test_vectors_bad(void)
{
    unsigned i, len, seen = 0;
    for (i = 0; i < TVEC_COUNT; i++) {
        const tvec *v = &tvecs[i];
        if (v->kind != VK_RLE_BAD)
            continue;
        seen++;
        setUp();
        TEST_ASSERT_EQUAL_INT(v->err, r8_rle_decode(v->in, v->in_len, dec, v->limit, &len));
        TEST_ASSERT_TRUE(len <= v->limit);
        if (v->limit < 300)
            TEST_ASSERT_EQUAL_HEX8(GUARD, dec[v->limit]);
    }
    TEST_ASSERT_TRUE(seen >= 5);
}

/* The seed's printed example: its output is what eight 03s code as. */
static void test_seed_inconsistency(void)
{
    static const r8_u8 printed[] = { 0x81, 0x01, 0x08, 0x03, 0x84, 0x08, 0x07, 0x06, 0x05 };
    unsigned len, k, n03 = 0;
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_rle_decode(printed, sizeof printed, dec, 300, &len));
    TEST_ASSERT_EQUAL_UINT(13, len);
    for (k = 0; k < len; k++)
        n03 += dec[k] == 3;
    TEST_ASSERT_EQUAL_UINT(8, n03);
}

static void test_encoder_never_overflows(void)
{
    unsigned n, cap, len, i;
    int rc;
    for (i = 0; i < 64; i++)
        src[i] = (r8_u8)(i & 1 ? rnd() : 7);
    for (n = 1; n <= 64; n += 7) {
        for (cap = 0; cap < R8_RLE_BOUND(n) + 2; cap++) {
            setUp();
            rc = r8_rle_encode(src, n, enc, cap, &len);
            TEST_ASSERT_TRUE(rc == R8_OK || rc == R8_E_SPACE);
            TEST_ASSERT_EQUAL_HEX8(GUARD, enc[cap]);
            if (cap >= R8_RLE_BOUND(n))
                TEST_ASSERT_EQUAL_INT(R8_OK, rc);
        }
    }
}

static void test_random_round_trips(void)
{
    unsigned t, n, i, len, len2;
    for (t = 0; t < 200; t++) {
        n = rnd() + (unsigned)(rnd() & 0x1F);
        for (i = 0; i < n; i++) {
            r8_u8 r = rnd();
            /* mix runs and noise */
            src[i] = (r & 0xC0) ? (i ? src[i - 1] : 0) : r;
        }
        setUp();
        TEST_ASSERT_EQUAL_INT(R8_OK, r8_rle_encode(src, n, enc, 320, &len));
        TEST_ASSERT_TRUE(len <= R8_RLE_BOUND(n));
        TEST_ASSERT_EQUAL_INT(R8_OK, r8_rle_decode(enc, len, dec, n, &len2));
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
            enc[i] = rnd();
        for (i = 0; i < sizeof dec; i++)
            dec[i] = GUARD;
        rc = r8_rle_decode(enc, n, dec, 100, &len);
        TEST_ASSERT_TRUE(rc == R8_OK || rc == R8_E_MALFORMED || rc == R8_E_TRUNC || rc == R8_E_SPACE);
        TEST_ASSERT_TRUE(len <= 100);
        for (i = 100; i < sizeof dec; i++)
            TEST_ASSERT_EQUAL_HEX8(GUARD, dec[i]);
    }
}

static void test_codec_names(void)
{
    TEST_ASSERT_EQUAL_INT(R8_CODEC_RLE, r8_codec_by_name("rle"));
    TEST_ASSERT_EQUAL_INT(R8_CODEC_LZ77, r8_codec_by_name("lz77"));
    TEST_ASSERT_EQUAL_INT(R8_CODEC_RAW, r8_codec_by_name("raw"));
    TEST_ASSERT_EQUAL_INT(-1, r8_codec_by_name("zip"));
    TEST_ASSERT_NULL(r8_codec_name(9));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_vectors_encode_decode);
    RUN_TEST(test_vectors_bad);
    RUN_TEST(test_seed_inconsistency);
    RUN_TEST(test_encoder_never_overflows);
    RUN_TEST(test_random_round_trips);
    RUN_TEST(test_random_garbage_decodes_safely);
    RUN_TEST(test_codec_names);
    return UNITY_END();
}
