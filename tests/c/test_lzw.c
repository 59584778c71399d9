/* test_lzw.c - the LZW codec (docs/protocol.md 3.5): the document's
 * vectors, the KwKwK case, the frozen dictionary, output limits,
 * malformed input, random round trips. */
#include "unity.h"
#include "r8codec.h"

#define GUARD 0xA5
static r8_u8 enc[400 + 4];
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

static r8_u16 seed = 5;
static r8_u8 rnd(void)
{
    seed = (r8_u16)(seed * 25173u + 13849u);
    return (r8_u8)(seed >> 8);
}

static void check_vec(const r8_u8 *in, unsigned n, const r8_u8 *out, unsigned m)
{
    unsigned len;
    setUp();
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_lzw_encode(in, n, enc, 400, &len));
    TEST_ASSERT_EQUAL_UINT(m, len);
    if (m)
        TEST_ASSERT_EQUAL_MEMORY(out, enc, m);
    TEST_ASSERT_EQUAL_HEX8(GUARD, enc[m]);
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_lzw_decode(out, m, dec, 300, &len));
    TEST_ASSERT_EQUAL_UINT(n, len);
    if (n)
        TEST_ASSERT_EQUAL_MEMORY(in, dec, n);
    TEST_ASSERT_EQUAL_HEX8(GUARD, dec[n]);
}

/* docs/protocol.md 3.5 */
static void test_doc_vectors(void)
{
    static const r8_u8 z8[8] = { 0 };
    static const r8_u8 oz8[5] = { 0x00, 0x40, 0x20, 0x30, 0x00 };
    static const r8_u8 tobe[24] = "TOBEORNOTTOBEORTOBEORNOT";
    static const r8_u8 otobe[18] = { 0x2A, 0x13, 0xC8, 0x44, 0x52, 0x79, 0x48, 0x9C, 0x4F,
                                     0x2A, 0x40, 0x20, 0x50, 0x48, 0x4C, 0x0E, 0x0B, 0x07 };
    static const r8_u8 a7[7] = { 0x61, 0x61, 0x61, 0x61, 0x61, 0x61, 0x61 };
    static const r8_u8 oa7[5] = { 0x30, 0xC0, 0x20, 0x26, 0x10 };
    static const r8_u8 i1[1] = { 0x41 };
    static const r8_u8 o1[2] = { 0x20, 0x80 };
    check_vec(z8, 8, oz8, 5);
    check_vec(tobe, 24, otobe, 18);
    check_vec(a7, 7, oa7, 5); /* codes 61 100 101 61: KwKwK twice */
    check_vec(i1, 1, o1, 2);
    check_vec(z8, 0, o1, 0);
}

/* More phrases than entries: the dictionary stops at R8_LZW_DICT, and
 * a code past it is malformed. */
static void test_frozen_dictionary(void)
{
    unsigned i, len, len2;
    for (i = 0; i < 300; i++)
        src[i] = rnd(); /* ~1 byte a phrase: ~290 phrases */
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_lzw_encode(src, 300, enc, 400, &len));
    TEST_ASSERT_TRUE(len * 8u / R8_LZW_BITS > R8_LZW_DICT + 2u);
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_lzw_decode(enc, len, dec, 300, &len2));
    TEST_ASSERT_EQUAL_UINT(300, len2);
    TEST_ASSERT_EQUAL_MEMORY(src, dec, 300);
    /* codes 00, 01, ..., then 256 + 128: never an entry */
    for (i = 0; i < 400; i++)
        enc[i] = 0;
    /* 200 codes of 9 bits = 225 bytes, the last one 0x180 (384) */
    enc[223] = 0x01; /* bits 199*9 = 1791 .. 1799: code 1 1000 0000 */
    enc[224] = 0x80;
    TEST_ASSERT_EQUAL_INT(R8_E_MALFORMED, r8_lzw_decode(enc, 225, dec, 300, &len));
    TEST_ASSERT_EQUAL_UINT(199, len);
}

static void test_limits(void)
{
    unsigned i, len, full, cap;
    for (i = 0; i < 200; i++)
        src[i] = (r8_u8)(i & 0x0Fu);
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_lzw_encode(src, 200, enc, 400, &full));
    TEST_ASSERT_TRUE(full <= R8_LZW_BOUND(200));
    for (cap = 0; cap < full; cap += 7) {
        setUp();
        TEST_ASSERT_EQUAL_INT(R8_E_SPACE, r8_lzw_encode(src, 200, enc, cap, &len));
        TEST_ASSERT_EQUAL_HEX8(GUARD, enc[cap]);
    }
    setUp();
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_lzw_encode(src, 200, enc, full, &len));
    for (cap = 0; cap < 200; cap += 9) {
        dec[cap] = GUARD;
        TEST_ASSERT_EQUAL_INT(R8_E_SPACE, r8_lzw_decode(enc, full, dec, cap, &len));
        TEST_ASSERT_TRUE(len <= cap);
        TEST_ASSERT_EQUAL_HEX8(GUARD, dec[cap]);
    }
}

static void test_malformed(void)
{
    static const r8_u8 first_entry[2] = { 0x80, 0x00 }; /* code 256 first */
    static const r8_u8 ahead[3] = { 0x20, 0xC0, 0x40 }; /* 41, then 257 */
    static const r8_u8 pad1[2] = { 0x20, 0x81 };         /* padding not 0 */
    static const r8_u8 cut[1] = { 0x00 };                /* 8 bits: neither a code nor padding */
    unsigned len;
    TEST_ASSERT_EQUAL_INT(R8_E_MALFORMED, r8_lzw_decode(first_entry, 2, dec, 300, &len));
    TEST_ASSERT_EQUAL_INT(R8_E_MALFORMED, r8_lzw_decode(ahead, 3, dec, 300, &len));
    TEST_ASSERT_EQUAL_UINT(1, len);
    TEST_ASSERT_EQUAL_INT(R8_E_MALFORMED, r8_lzw_decode(pad1, 2, dec, 300, &len));
    TEST_ASSERT_EQUAL_INT(R8_E_TRUNC, r8_lzw_decode(cut, 1, dec, 300, &len));
}

static void test_random_round_trips(void)
{
    unsigned t, n, i, len, len2;
    for (t = 0; t < 60; t++) {
        setUp();
        n = rnd() + (unsigned)(rnd() & 0x1Fu);
        for (i = 0; i < n; i++) {
            r8_u8 r = rnd();
            src[i] = (r8_u8)(r < 150 ? 0 : (r < 200 ? 0xFF : (r & 7u)));
        }
        TEST_ASSERT_EQUAL_INT(R8_OK, r8_lzw_encode(src, n, enc, 400, &len));
        TEST_ASSERT_TRUE(len <= R8_LZW_BOUND(n));
        TEST_ASSERT_EQUAL_HEX8(GUARD, enc[len]);
        TEST_ASSERT_EQUAL_INT(R8_OK, r8_lzw_decode(enc, len, dec, n, &len2));
        TEST_ASSERT_EQUAL_UINT(n, len2);
        TEST_ASSERT_EQUAL_MEMORY(src, dec, n);
        TEST_ASSERT_EQUAL_HEX8(GUARD, dec[n]);
    }
}

static void test_dispatch(void)
{
    unsigned len;
    src[0] = 0x41;
    TEST_ASSERT_EQUAL_INT(R8_CODEC_LZW, r8_codec_by_name("lzw"));
    TEST_ASSERT_EQUAL_INT(R8_CODEC_LZW, r8_codec_by_name(r8_codec_name(R8_CODEC_LZW)));
    TEST_ASSERT_EQUAL_INT(R8_CODEC_BEST, r8_codec_by_name("best"));
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_codec_encode(R8_CODEC_LZW, src, 1, enc, 400, &len));
    TEST_ASSERT_EQUAL_UINT(2, len);
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_codec_decode(R8_CODEC_LZW, enc, 2, dec, 300, &len));
    TEST_ASSERT_EQUAL_UINT(1, len);
    TEST_ASSERT_EQUAL_INT(R8_E_ARG, r8_codec_decode(R8_CODEC_BEST, enc, 2, dec, 300, &len));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_doc_vectors);
    RUN_TEST(test_frozen_dictionary);
    RUN_TEST(test_limits);
    RUN_TEST(test_malformed);
    RUN_TEST(test_random_round_trips);
    RUN_TEST(test_dispatch);
    return UNITY_END();
}
