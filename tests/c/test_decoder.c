/* test_decoder.c - the byte-at-a-time frame decoder against the encoder:
 * round trips (full and dirty-band frames, each codec), late join,
 * requests, and fault injection (bit flips, dropped and inserted bytes,
 * truncation, garbage): no corrupt frame is ever reported good, and the
 * first clean full frame after a fault decodes. */
#include <string.h>

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

/* CRC-32 (the version-2 frame check): the check value, and pieces chain. */
static void test_crc32(void)
{
    static const r8_u8 nine[] = "123456789";
    TEST_ASSERT_EQUAL_UINT32(0xCBF43926uL, r8_crc32(nine, 9));
    TEST_ASSERT_EQUAL_UINT32(0xCBF43926uL, r8_crc32_update(r8_crc32(nine, 4), nine + 4, 5));
    TEST_ASSERT_EQUAL_UINT32(0, r8_crc32(nine, 0));
}

/* The wrong frame of the soak (issue 12, docs/protocol.md 4.1): band y0 8
 * of frame 3548 as sent, and as a burst left it.  The error (14 bytes in
 * an RLE literal run) is a multiple of the CRC polynomial: both packets
 * have a good CRC-16, both bands decode to 64 bytes, and a frame holding
 * either has the same CRC-16.  In a version-1 stream the decoder reports
 * the wrong frame good; in version 2 the CRC-32 fails it. */
static const r8_u8 band3548[40] = {
    0x02, 0x0D, 0xDC, 0x00, 0x08, 0x01, 0x12, 0x00, 0x9B, 0x40,
    0xE0, 0x50, 0xF8, 0x54, 0xFF, 0x55, 0xFF, 0x55, 0xFF, 0x55,
    0xFA, 0x55, 0xAA, 0x55, 0xAA, 0x55, 0xAA, 0x55, 0xAA, 0x55,
    0xAA, 0x55, 0xAA, 0x50, 0xA0, 0x40, 0x13, 0x00, 0x07, 0xD3
};
static const r8_u8 band3548_hit[40] = {
    0x02, 0x0D, 0xDC, 0x00, 0x08, 0x01, 0x12, 0x00, 0x9B, 0x6B,
    0xF2, 0xD3, 0xC5, 0xA8, 0x91, 0xEA, 0x03, 0xE0, 0xBD, 0x0A,
    0x5C, 0x8D, 0xF7, 0x55, 0xAA, 0x55, 0xAA, 0x55, 0xAA, 0x55,
    0xAA, 0x55, 0xAA, 0x50, 0xA0, 0x40, 0x13, 0x00, 0x07, 0xD3
};

static unsigned put_pkt(r8_u8 *out, r8_u8 *body, unsigned n)
{
    unsigned len = 0;
    r8_u16 c = r8_crc16(body, n);
    body[n] = (r8_u8)(c >> 8);
    body[n + 1] = (r8_u8)c;
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_cobs_encode(body, n + 2, out, 200, &len));
    out[len] = 0;
    return len + 1;
}

/* Frame 0x0DDC, 64x32 PAGE1, full: bands 0, 16, 24 raw `fill`, band 8
 * the given packet; FRAME_END with the check of `frame` for `version`.
 * Returns what the decoder said at FRAME_END. */
static int feed_3548(int version, const r8_u8 *band8, const r8_u8 *frame)
{
    static r8_u8 s[600], body[80], p2[R8_DEC_PKT_BYTES(256)], f2[256];
    unsigned n = 0, k, y;
    int rc = R8_DEC_NONE;
    r8_u32 c;
    r8_dec d2;
    s[n++] = 0;
    memcpy(body, "\x01\x01\x0d\xdc\x00\x40\x00\x20\x00\x00\x08\x01\x01\x00", 14);
    body[1] = (r8_u8)version;
    n += put_pkt(s + n, body, 14);
    for (y = 0; y < 32; y += 8) {
        if (y == 8) {
            memcpy(body, band8, 38);
            n += put_pkt(s + n, body, 38);
            continue;
        }
        memcpy(body, "\x02\x0d\xdc\x00\x00\x00", 6);
        body[4] = (r8_u8)y;
        memcpy(body + 6, frame + y / 8 * 64, 64);
        n += put_pkt(s + n, body, 70);
    }
    memcpy(body, "\x03\x0d\xdc\x00\x04", 5);
    if (version == 2) {
        c = r8_crc32(frame, 256);
        for (k = 0; k < 4; k++)
            body[5 + k] = (r8_u8)(c >> (24 - 8 * k));
        n += put_pkt(s + n, body, 9);
    } else {
        c = r8_crc16(frame, 256);
        body[5] = (r8_u8)(c >> 8);
        body[6] = (r8_u8)c;
        n += put_pkt(s + n, body, 7);
    }
    r8_dec_init(&d2, p2, sizeof p2, f2, sizeof f2, 0, 0);
    for (k = 0; k < n; k++) {
        int r = r8_dec_feed(&d2, s[k]);
        if (r == R8_DEC_FRAME || r == R8_DEC_INCOMPLETE)
            rc = r;
    }
    TEST_ASSERT_EQUAL_UINT(0, d2.bad_packets);
    if (rc == R8_DEC_FRAME)
        TEST_ASSERT_EQUAL_MEMORY(frame, f2, 64); /* band 0 as sent */
    if (rc == R8_DEC_FRAME && band8 == band3548_hit) {
        /* what was accepted: band 8 as the burst left it */
        TEST_ASSERT_TRUE(memcmp(f2 + 64, frame + 64, 64) != 0);
    }
    return rc;
}

static void test_soak_wrong_frame_3548(void)
{
    static r8_u8 frame[256], band_hit[64];
    unsigned k, len;
    for (k = 0; k < 256; k++)
        frame[k] = (r8_u8)(k * 7u);
    TEST_ASSERT_EQUAL_HEX16(r8_crc16(band3548, 38), (band3548[38] << 8) | band3548[39]);
    TEST_ASSERT_EQUAL_HEX16(r8_crc16(band3548_hit, 38),
                            (band3548_hit[38] << 8) | band3548_hit[39]);
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_codec_decode(1, band3548 + 6, 32, frame + 64, 64, &len));
    TEST_ASSERT_EQUAL_UINT(64, len);
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_codec_decode(1, band3548_hit + 6, 32, band_hit, 64, &len));
    TEST_ASSERT_EQUAL_UINT(64, len);
    TEST_ASSERT_TRUE(memcmp(band_hit, frame + 64, 64) != 0);
    /* version 1: the wrong band passes both CRC-16s and the frame is good */
    TEST_ASSERT_EQUAL_INT(R8_DEC_FRAME, feed_3548(1, band3548, frame));
    TEST_ASSERT_EQUAL_INT(R8_DEC_FRAME, feed_3548(1, band3548_hit, frame));
    /* version 2: the CRC-32 sees it */
    TEST_ASSERT_EQUAL_INT(R8_DEC_FRAME, feed_3548(2, band3548, frame));
    TEST_ASSERT_EQUAL_INT(R8_DEC_INCOMPLETE, feed_3548(2, band3548_hit, frame));
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
    RUN_TEST(test_crc32);
    RUN_TEST(test_soak_wrong_frame_3548);
    return UNITY_END();
}
