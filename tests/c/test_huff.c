/* test_huff.c - the static Huffman codec (docs/protocol.md 3.4): the
 * document's vectors, the code's properties (canonical, complete,
 * padding), output limits, malformed input, random round trips. */
#include "unity.h"
#include "r8codec.h"

#define GUARD 0xA5
static r8_u8 enc[400 + 4];
static r8_u8 dec[260 + 4];
static r8_u8 src[260];

void setUp(void)
{
    unsigned i;
    for (i = 0; i < sizeof enc; i++)
        enc[i] = GUARD;
    for (i = 0; i < sizeof dec; i++)
        dec[i] = GUARD;
}
void tearDown(void) {}

static r8_u16 seed = 11;
static r8_u8 rnd(void)
{
    seed = (r8_u16)(seed * 25173u + 13849u);
    return (r8_u8)(seed >> 8);
}

static void check_vec(const r8_u8 *in, unsigned n, const r8_u8 *out, unsigned m)
{
    unsigned len;
    setUp();
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_huff_encode(in, n, enc, 400, &len));
    TEST_ASSERT_EQUAL_UINT(m, len);
    if (m)
        TEST_ASSERT_EQUAL_MEMORY(out, enc, m);
    TEST_ASSERT_EQUAL_HEX8(GUARD, enc[m]);
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_huff_decode(out, m, dec, 260, &len));
    TEST_ASSERT_EQUAL_UINT(n, len);
    if (n)
        TEST_ASSERT_EQUAL_MEMORY(in, dec, n);
    TEST_ASSERT_EQUAL_HEX8(GUARD, dec[n]);
}

/* docs/protocol.md 3.4 */
static void test_doc_vectors(void)
{
    static const r8_u8 z8[8] = { 0 };
    static const r8_u8 o1[1] = { 0x00 };
    static const r8_u8 i2[8] = { 0, 0, 0, 0xFF, 0xFF, 0, 1, 3 };
    static const r8_u8 o2[4] = { 0x19, 0xE6, 0xD1, 0x3F };
    static const r8_u8 i3[16] = { 0, 0, 0, 0, 0, 0, 0xFF, 0xFF, 0xFF, 0xFF, 0, 0, 0, 0, 0, 0 };
    static const r8_u8 o3[5] = { 0x03, 0x3C, 0xF3, 0xCC, 0x0F };
    static const r8_u8 i4[1] = { 0x41 };
    static const r8_u8 o4[2] = { 0xF6, 0x8F };
    check_vec(z8, 8, o1, 1);
    check_vec(i2, 8, o2, 4);
    check_vec(i3, 16, o3, 5);
    check_vec(i4, 1, o4, 2);
    check_vec(z8, 0, o1, 0);
}

/* every byte value round trips alone; 8 of it fill whole bytes exactly
 * (8 codes of length L = L bytes, no padding) */
static void test_every_value(void)
{
    unsigned v, k, len, len8;
    for (v = 0; v < 256; v++) {
        for (k = 0; k < 8; k++)
            src[k] = (r8_u8)v;
        TEST_ASSERT_EQUAL_INT(R8_OK, r8_huff_encode(src, 8, enc, 400, &len8));
        TEST_ASSERT_TRUE(len8 >= 1 && len8 <= R8_HUFF_MAXLEN);
        TEST_ASSERT_EQUAL_INT(R8_OK, r8_huff_encode(src, 1, enc, 400, &len));
        TEST_ASSERT_EQUAL_UINT((len8 + 7u) / 8u, len);
        TEST_ASSERT_EQUAL_INT(R8_OK, r8_huff_decode(enc, len, dec, 260, &len));
        TEST_ASSERT_EQUAL_UINT(1, len);
        TEST_ASSERT_EQUAL_HEX8(v, dec[0]);
    }
}

static void test_limits(void)
{
    unsigned i, len, full, cap;
    for (i = 0; i < 200; i++)
        src[i] = (r8_u8)(i * 7u);
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_huff_encode(src, 200, enc, 400, &full));
    TEST_ASSERT_TRUE(full <= R8_HUFF_BOUND(200));
    for (cap = 0; cap < full; cap += 13) {
        setUp();
        TEST_ASSERT_EQUAL_INT(R8_E_SPACE, r8_huff_encode(src, 200, enc, cap, &len));
        TEST_ASSERT_EQUAL_HEX8(GUARD, enc[cap]);
    }
    setUp();
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_huff_encode(src, 200, enc, full, &len));
    /* decoding into too small a buffer stops at it */
    TEST_ASSERT_EQUAL_INT(R8_E_SPACE, r8_huff_decode(enc, full, dec, 199, &len));
    TEST_ASSERT_EQUAL_HEX8(GUARD, dec[199]);
    TEST_ASSERT_EQUAL_UINT(199, len);
}

static void test_malformed(void)
{
    static const r8_u8 ff[1] = { 0xFF };       /* 8 one bits: not padding, a cut code */
    static const r8_u8 pad0[2] = { 0x00, 0xFF };/* a whole byte of padding */
    static const r8_u8 cut[1] = { 0xF6 };      /* 0x41's code cut after 8 bits */
    static const r8_u8 zpad[1] = { 0x02 };     /* 6 zero codes, then 10: not all-ones padding */
    static const r8_u8 ok7[1] = { 0x01 };      /* 7 zero codes and 1 bit of padding */
    unsigned len;
    TEST_ASSERT_EQUAL_INT(R8_E_TRUNC, r8_huff_decode(ff, 1, dec, 260, &len));
    TEST_ASSERT_EQUAL_INT(R8_E_TRUNC, r8_huff_decode(pad0, 2, dec, 260, &len));
    TEST_ASSERT_EQUAL_INT(R8_E_TRUNC, r8_huff_decode(cut, 1, dec, 260, &len));
    TEST_ASSERT_EQUAL_INT(R8_E_TRUNC, r8_huff_decode(zpad, 1, dec, 260, &len));
    TEST_ASSERT_EQUAL_UINT(6, len);
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_huff_decode(ok7, 1, dec, 260, &len));
    TEST_ASSERT_EQUAL_UINT(7, len);
}

static void test_random_round_trips(void)
{
    unsigned t, n, i, len, len2;
    for (t = 0; t < 60; t++) {
        setUp();
        n = rnd() + (unsigned)(rnd() & 3u);
        for (i = 0; i < n; i++) {
            r8_u8 r = rnd();
            src[i] = (r8_u8)(r < 128 ? 0 : (r < 160 ? 0xFF : rnd()));
        }
        TEST_ASSERT_EQUAL_INT(R8_OK, r8_huff_encode(src, n, enc, 400, &len));
        TEST_ASSERT_TRUE(len <= R8_HUFF_BOUND(n));
        TEST_ASSERT_EQUAL_HEX8(GUARD, enc[len]);
        TEST_ASSERT_EQUAL_INT(R8_OK, r8_huff_decode(enc, len, dec, n, &len2));
        TEST_ASSERT_EQUAL_UINT(n, len2);
        TEST_ASSERT_EQUAL_MEMORY(src, dec, n);
        TEST_ASSERT_EQUAL_HEX8(GUARD, dec[n]);
    }
}

static void test_dispatch(void)
{
    unsigned len;
    src[0] = 0x41;
    TEST_ASSERT_EQUAL_INT(R8_CODEC_HUFF, r8_codec_by_name("huff"));
    TEST_ASSERT_EQUAL_INT(R8_CODEC_HUFF, r8_codec_by_name(r8_codec_name(R8_CODEC_HUFF)));
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_codec_encode(R8_CODEC_HUFF, src, 1, enc, 400, &len));
    TEST_ASSERT_EQUAL_UINT(2, len);
    TEST_ASSERT_EQUAL_HEX8(0xF6, enc[0]);
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_codec_decode(R8_CODEC_HUFF, enc, 2, dec, 260, &len));
    TEST_ASSERT_EQUAL_UINT(1, len);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_doc_vectors);
    RUN_TEST(test_every_value);
    RUN_TEST(test_limits);
    RUN_TEST(test_malformed);
    RUN_TEST(test_random_round_trips);
    RUN_TEST(test_dispatch);
    return UNITY_END();
}
