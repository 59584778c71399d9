/* test_decoder.c - the byte-at-a-time frame decoder against the encoder:
 * round trips (full and dirty-band frames, each codec), late join,
 * requests, and fault injection (bit flips, dropped and inserted bytes,
 * truncation, garbage): no corrupt frame is ever reported good, and the
 * first clean full frame after a fault decodes. */
#include "unity.h"
#include "r8wire.h"

#define W 16
#define H 16
#define FB_BYTES (W * H / 8)
#define NFRAMES 4

static r8_u8 stream[900];
static unsigned slen;
static r8_u8 scratch[120];
static r8_u8 band[W];
static r8_u8 frames[NFRAMES][FB_BYTES]; /* what each frame should be */
static r8_u8 pkt[R8_WIRE_PKT_BYTES(FB_BYTES, 4)];
static r8_u8 fb[FB_BYTES + 4];
static r8_u8 pal[12];
static r8_dec dec;

void setUp(void) {}
void tearDown(void) {}

static void capture(void *ctx, const r8_u8 *p, unsigned n)
{
    (void)ctx;
    while (n--) {
        if (slen < sizeof stream)
            stream[slen] = *p;
        slen++;
        p++;
    }
}

/* Frame f's content: the top band changes every frame, the bottom band
 * only on frame 2. */
static void make_frames(void)
{
    unsigned f, k;
    for (f = 0; f < NFRAMES; f++)
        for (k = 0; k < FB_BYTES; k++)
            frames[f][k] = (r8_u8)(k < W ? (k + f * 3) & 0x0F : (f == 2 ? 0x81 : 0x18));
}

static void encode(r8_u8 codec, r8_u16 period, r8_u8 dirty)
{
    r8_tx_cfg c;
    r8_tx tx;
    r8_fb b;
    unsigned f, y, k;
    make_frames();
    c.format = R8_FMT_PAGE1;
    c.width = W;
    c.height = H;
    c.band = 8;
    c.codec = codec;
    c.full_period = period;
    c.dirty = dirty;
    c.palette = 0;
    c.npal = 0;
    slen = 0;
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_init(&tx, &c, scratch, sizeof scratch, capture, 0));
    TEST_ASSERT_EQUAL_INT(0, r8_fb_init(&b, band, R8_FMT_PAGE1, W, H, 0, 8));
    r8_tx_sync(&tx);
    for (f = 0; f < NFRAMES; f++) {
        r8_tx_frame_begin(&tx, (r8_u16)(100 + f));
        for (y = 0; y < H; y += 8) {
            r8_fb_set_band(&b, (r8_s16)y);
            for (k = 0; k < W; k++)
                band[k] = frames[f][y / 8 * W + k];
            r8_tx_band(&tx, &b);
        }
        r8_tx_frame_end(&tx);
    }
    TEST_ASSERT_TRUE(slen <= sizeof stream);
}

static unsigned good;      /* good frames reported */
static unsigned wrong;     /* good frames whose content is wrong */
static unsigned last_good; /* frame number of the last good one */

static void dec_reset(void)
{
    unsigned k;
    for (k = 0; k < sizeof fb; k++)
        fb[k] = 0xEE;
    r8_dec_init(&dec, pkt, sizeof pkt, fb, FB_BYTES, pal, sizeof pal);
    good = wrong = 0;
    last_good = 0;
}

static void feed(r8_u8 c)
{
    unsigned k;
    if (r8_dec_feed(&dec, c) == R8_DEC_FRAME) {
        good++;
        last_good = dec.frame;
        if (dec.frame < 100 || dec.frame >= 100 + NFRAMES) {
            wrong++;
            return;
        }
        for (k = 0; k < FB_BYTES; k++)
            if (fb[k] != frames[dec.frame - 100][k]) {
                wrong++;
                break;
            }
    }
    TEST_ASSERT_EQUAL_HEX8(0xEE, fb[FB_BYTES]);
}

static void feed_all(unsigned from)
{
    unsigned i;
    for (i = from; i < slen; i++)
        feed(stream[i]);
}

static void check_clean(r8_u8 codec, r8_u8 dirty)
{
    encode(codec, 0, dirty);
    dec_reset();
    feed_all(0);
    TEST_ASSERT_EQUAL_UINT(NFRAMES, good);
    TEST_ASSERT_EQUAL_UINT(0, wrong);
    TEST_ASSERT_EQUAL_UINT(0, dec.bad_packets);
    TEST_ASSERT_EQUAL_UINT(0, dec.incomplete);
    TEST_ASSERT_EQUAL_UINT(0, dec.dropped);
    TEST_ASSERT_EQUAL_UINT(NFRAMES, dec.frames);
    TEST_ASSERT_EQUAL_UINT(slen, dec.bytes);
}

static void test_round_trip_rle(void) { check_clean(R8_CODEC_RLE, 0); }
static void test_round_trip_lz77(void) { check_clean(R8_CODEC_LZ77, 0); }
static void test_round_trip_raw(void) { check_clean(R8_CODEC_RAW, 0); }
static void test_round_trip_dirty(void)
{
    unsigned full_len;
    check_clean(R8_CODEC_RLE, 0);
    full_len = slen;
    check_clean(R8_CODEC_RLE, 1);
    TEST_ASSERT_TRUE(slen < full_len);
}

/* Joining after the first (full) frame: delta frames have no base and
 * are not reported good; a request is wanted. */
static void test_late_join_needs_full(void)
{
    unsigned i, zeros = 0;
    encode(R8_CODEC_RLE, 0, 1);
    dec_reset();
    /* skip to the start of frame 1: after the 1 + 4 packets' delimiters */
    for (i = 0; i < slen && zeros < 5; i++)
        zeros += stream[i] == 0;
    feed_all(i);
    TEST_ASSERT_EQUAL_UINT(0, good);
    /* joining: the bytes before the first 0x00 (frame 101's start) are
     * dropped, its other packets ignored; the deltas after it, before
     * any good frame, are skipped: not errors */
    TEST_ASSERT_EQUAL_UINT(NFRAMES - 2, dec.skipped);
    TEST_ASSERT_TRUE(dec.ignored >= 2);
    TEST_ASSERT_EQUAL_UINT(0, dec.incomplete);
    TEST_ASSERT_TRUE(dec.need_full);
    TEST_ASSERT_EQUAL_UINT(0, dec.bad_packets);
}

/* Frame numbers that never arrive are counted as dropped. */
static void test_dropped_frames(void)
{
    unsigned i, zeros = 0, cut0 = 0, cut1 = 0;
    encode(R8_CODEC_RLE, 0, 0);
    /* frame 1 is packets 5..8 (delimiters 5..8 end them) */
    for (i = 0; i < slen; i++) {
        if (stream[i])
            continue;
        zeros++;
        if (zeros == 5)
            cut0 = i + 1;
        if (zeros == 9)
            cut1 = i + 1;
    }
    dec_reset();
    for (i = 0; i < slen; i++)
        if (i < cut0 || i >= cut1)
            feed(stream[i]);
    TEST_ASSERT_EQUAL_UINT(NFRAMES - 1, good);
    TEST_ASSERT_EQUAL_UINT(0, wrong);
    TEST_ASSERT_EQUAL_UINT(1, dec.dropped);
    TEST_ASSERT_EQUAL_UINT(0, dec.incomplete);
}

/* Frames (all full, 4 packets each after the leading sync 0x00) that a
 * damaged byte at i takes with it: its own packet's frame, and when the
 * byte was a delimiter, the next packet's frame too. */
static unsigned lost_frames(unsigned i, int delim_lost)
{
    unsigned k = 0, s, fa, fb2, n = 0;
    for (s = 0; s < i; s++)
        k += stream[s] == 0;
    /* byte i is in packet k (packet 0 = the bytes before the sync) */
    fa = k ? (k - 1) / 4 : NFRAMES;
    if (fa < NFRAMES)
        n++;
    if (delim_lost && stream[i] == 0) {
        fb2 = k / 4; /* packet k+1 */
        if (fb2 < NFRAMES && fb2 != fa)
            n++;
    }
    return n;
}

/* Every single-bit flip, all full frames: no wrong frame, and the frames
 * after the damaged one all decode. */
static void test_bit_flips(void)
{
    unsigned i, bit, s;
    encode(R8_CODEC_RLE, 1, 1);
    for (i = 0; i < slen; i++) {
        for (bit = 0; bit < 8; bit += 3) {
            dec_reset();
            for (s = 0; s < slen; s++)
                feed(s == i ? (r8_u8)(stream[s] ^ (1u << bit)) : stream[s]);
            TEST_ASSERT_EQUAL_UINT(0, wrong);
            TEST_ASSERT_EQUAL_UINT(NFRAMES - lost_frames(i, 1), good);
            /* (a flipped leading sync only delays the sync: the first
             * packet is then a late join, dropped silently) */
            if (i > 0 && i + 1 < slen)
                TEST_ASSERT_TRUE(dec.bad_packets >= 1);
        }
    }
}

static void test_dropped_inserted_bytes(void)
{
    unsigned i, s;
    encode(R8_CODEC_LZ77, 1, 1);
    for (i = 0; i < slen; i++) {
        dec_reset(); /* drop byte i */
        for (s = 0; s < slen; s++)
            if (s != i)
                feed(stream[s]);
        TEST_ASSERT_EQUAL_UINT(0, wrong);
        /* without the leading sync the first packet looks like a late
         * join: it is dropped, and with it frame 100 */
        TEST_ASSERT_EQUAL_UINT(i ? NFRAMES - lost_frames(i, 1) : NFRAMES - 1, good);
        dec_reset(); /* insert a byte before i */
        for (s = 0; s < slen; s++) {
            if (s == i)
                feed((r8_u8)(i * 13 + 5));
            feed(stream[s]);
        }
        TEST_ASSERT_EQUAL_UINT(0, wrong);
        if ((r8_u8)(i * 13 + 5) == 0 && (stream[i] == 0 || (i && stream[i - 1] == 0)))
            TEST_ASSERT_EQUAL_UINT(NFRAMES, good); /* an extra delimiter is harmless */
        else if (good != NFRAMES - lost_frames(i, 0)) {
            unity_print("insert before ");
            unity_print_long((long)i);
            unity_print("\n");
            TEST_ASSERT_EQUAL_UINT(NFRAMES - lost_frames(i, 0), good);
        }
    }
}

static void test_truncation_everywhere(void)
{
    unsigned i, s, prev = 0;
    encode(R8_CODEC_RLE, 0, 1);
    for (i = 0; i <= slen; i++) {
        dec_reset();
        for (s = 0; s < i; s++)
            feed(stream[s]);
        TEST_ASSERT_EQUAL_UINT(0, wrong);
        TEST_ASSERT_TRUE(good >= prev); /* more input, never fewer frames */
        prev = good;
    }
    TEST_ASSERT_EQUAL_UINT(NFRAMES, prev);
}

static void test_garbage_then_stream(void)
{
    unsigned i;
    r8_u16 x = 1;
    encode(R8_CODEC_RLE, 0, 1);
    dec_reset();
    for (i = 0; i < 3000; i++) {
        x = (r8_u16)(x * 25173u + 13849u);
        feed((r8_u8)(x >> 8));
    }
    TEST_ASSERT_EQUAL_UINT(0, good);
    TEST_ASSERT_TRUE(dec.bad_packets > 0);
    feed_all(0);
    TEST_ASSERT_EQUAL_UINT(0, wrong);
    TEST_ASSERT_EQUAL_UINT(NFRAMES, good);
}

static void test_oversized_packet_is_dropped(void)
{
    unsigned i, bad0;
    dec_reset();
    feed(0);
    for (i = 0; i < sizeof pkt + 50; i++)
        feed((r8_u8)(i % 200 + 1));
    bad0 = dec.bad_packets;
    feed(0);
    TEST_ASSERT_EQUAL_UINT(bad0 + 1, dec.bad_packets);
    encode(R8_CODEC_RLE, 0, 0);
    feed_all(0);
    TEST_ASSERT_EQUAL_UINT(NFRAMES, good);
}

static void test_frame_too_big_for_display(void)
{
    encode(R8_CODEC_RLE, 0, 0);
    r8_dec_init(&dec, pkt, sizeof pkt, fb, FB_BYTES - 1, pal, sizeof pal);
    good = wrong = 0;
    feed_all(0);
    TEST_ASSERT_EQUAL_UINT(0, good);
    TEST_ASSERT_EQUAL_UINT(NFRAMES, dec.incomplete);
}

/* A REQUEST echoed back into the display's input is ignored. */
static void test_echoed_request_is_ignored(void)
{
    r8_u8 req[R8_DEC_REQUEST_BYTES];
    unsigned k, n = r8_dec_request(req);
    encode(R8_CODEC_RLE, 0, 1);
    dec_reset();
    for (k = 0; k < n; k++)
        feed(req[k]);
    feed_all(0);
    for (k = 0; k < n; k++)
        feed(req[k]);
    TEST_ASSERT_EQUAL_UINT(NFRAMES, good);
    TEST_ASSERT_EQUAL_UINT(0, dec.bad_packets);
    TEST_ASSERT_EQUAL_UINT(0, wrong);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_round_trip_rle);
    RUN_TEST(test_round_trip_lz77);
    RUN_TEST(test_round_trip_raw);
    RUN_TEST(test_round_trip_dirty);
    RUN_TEST(test_late_join_needs_full);
    RUN_TEST(test_dropped_frames);
    RUN_TEST(test_bit_flips);
    RUN_TEST(test_dropped_inserted_bytes);
    RUN_TEST(test_truncation_everywhere);
    RUN_TEST(test_garbage_then_stream);
    RUN_TEST(test_oversized_packet_is_dropped);
    RUN_TEST(test_frame_too_big_for_display);
    RUN_TEST(test_echoed_request_is_ignored);
    return UNITY_END();
}
