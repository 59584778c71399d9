/* test_nolz77.c - a firmware built without the LZ77 codec (-DR8_NO_LZ77,
 * see src/rle.c): the codec dispatch and the frame encoder of this file
 * are compiled from the sources with the switch.  LZ77 is refused like
 * an unknown codec; RLE and raw still encode, and the LZ77 functions are
 * not needed to link. */
#define R8_NO_LZ77
/* this file's copies, beside the library's (the sanitizer build links
 * the library's sources too) */
#define r8_codec_by_name nl_codec_by_name
#define r8_codec_name nl_codec_name
#define r8_rle_encode nl_rle_encode
#define r8_rle_decode nl_rle_decode
#define r8_codec_encode nl_codec_encode
#define r8_codec_decode nl_codec_decode
#define r8_tx_band_bytes nl_tx_band_bytes
#define r8_tx_scratch nl_tx_scratch
#define r8_tx_init nl_tx_init
#define r8_tx_sync nl_tx_sync
#define r8_tx_request_full nl_tx_request_full
#define r8_tx_rx nl_tx_rx
#define r8_tx_frame_begin nl_tx_frame_begin
#define r8_tx_band nl_tx_band
#define r8_tx_frame_end nl_tx_frame_end
#define r8_tx_zeros_c nl_tx_zeros_c
#define r8_tx_run_c nl_tx_run_c
#define r8_tx_lit_c nl_tx_lit_c
#include "../../src/rle.c"
#include "../../src/wire.c"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

static r8_u8 src[40], dst[64], back[40], scratch[128], band[16];
static unsigned sent;

static void count(void *ctx, const r8_u8 *p, unsigned n)
{
    (void)ctx;
    (void)p;
    sent += n;
}

static void test_dispatch(void)
{
    unsigned k, len = 99;
    for (k = 0; k < sizeof src; k++)
        src[k] = (r8_u8)(k < 20 ? 0 : k);
    TEST_ASSERT_EQUAL_INT(R8_E_ARG, r8_codec_encode(R8_CODEC_LZ77, src, sizeof src, dst, sizeof dst, &len));
    TEST_ASSERT_EQUAL_UINT(0, len);
    TEST_ASSERT_EQUAL_INT(R8_E_ARG, r8_codec_decode(R8_CODEC_LZ77, dst, 4, src, sizeof src, &len));
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_codec_encode(R8_CODEC_RLE, src, sizeof src, dst, sizeof dst, &len));
    TEST_ASSERT_EQUAL_UINT(2 + 1 + 20, len); /* a run of 20 zeros, 20 literals */
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_codec_decode(R8_CODEC_RLE, dst, len, back, sizeof back, &len));
    TEST_ASSERT_EQUAL_UINT(sizeof src, len);
    TEST_ASSERT_EQUAL_MEMORY(src, back, sizeof src);
}

static void test_encoder(void)
{
    r8_tx_cfg c;
    r8_tx tx;
    r8_fb fb;
    c.format = R8_FMT_PAGE1;
    c.width = 16;
    c.height = 8;
    c.band = 8;
    c.codec = R8_CODEC_LZ77;
    c.full_period = 0;
    c.dirty = 1;
    c.palette = 0;
    c.npal = 0;
    TEST_ASSERT_EQUAL_UINT(0, r8_tx_scratch(&c));
    TEST_ASSERT_EQUAL_INT(R8_E_ARG, r8_tx_init(&tx, &c, scratch, sizeof scratch, count, 0));
    c.codec = R8_CODEC_RLE;
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_init(&tx, &c, scratch, sizeof scratch, count, 0));
    TEST_ASSERT_EQUAL_INT(0, r8_fb_init(&fb, band, R8_FMT_PAGE1, 16, 8, 0, 8));
    sent = 0;
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_frame_begin(&tx, 1));
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_band(&tx, &fb));
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_frame_end(&tx));
    TEST_ASSERT_EQUAL_UINT(sent, tx.bytes);
    TEST_ASSERT_EQUAL_UINT(1, tx.sent);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_dispatch);
    RUN_TEST(test_encoder);
    return UNITY_END();
}
