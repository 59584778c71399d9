/* test_wirev2.c - the frame encoder built with R8_WIRE_CRC32 (protocol
 * version 2, docs/protocol.md section 4.1): wire.c is compiled here with
 * the switch.  Its FRAME_START says version 2, its FRAME_END carries the
 * CRC-32 of the whole raw frame (clean bands included), the library's
 * decoder shows every frame good and equal to what was sent, and damage
 * that the packet CRC-16 (and so a version-1 frame CRC-16) cannot see
 * - the generator's own bytes XORed into a band's literal bytes - costs
 * the frame instead of showing it wrong. */
#define R8_WIRE_CRC32
/* this file's copies, beside the library's */
#define r8_tx_band_bytes v2_tx_band_bytes
#define r8_tx_scratch v2_tx_scratch
#define r8_tx_init v2_tx_init
#define r8_tx_sync v2_tx_sync
#define r8_tx_request_full v2_tx_request_full
#define r8_tx_rx v2_tx_rx
#define r8_tx_frame_begin v2_tx_frame_begin
#define r8_tx_band v2_tx_band
#define r8_tx_frame_end v2_tx_frame_end
#define r8_tx_zeros_c v2_tx_zeros_c
#define r8_tx_run_c v2_tx_run_c
#define r8_tx_lit_c v2_tx_lit_c
#include "../../src/wire.c"
#include "unity.h"

#define W 32
#define H 16
#define BAND 8
#define FB_BYTES (W * H / 8)

static r8_u8 frame[FB_BYTES];
static r8_u8 scratch[600];
static r8_u8 cap[2048];
static unsigned cap_len;
static r8_u8 dpkt[R8_DEC_PKT_BYTES(FB_BYTES)];
static r8_u8 dfb[FB_BYTES + 4];
static r8_u8 dpal[3];

void setUp(void) { cap_len = 0; }
void tearDown(void) {}

static void capture(void *ctx, const r8_u8 *p, unsigned n)
{
    (void)ctx;
    while (n--) {
        TEST_ASSERT_TRUE(cap_len < sizeof cap);
        cap[cap_len++] = *p++;
    }
}

static void tcfg(r8_tx_cfg *c, r8_u8 codec)
{
    c->format = R8_FMT_PAGE1;
    c->width = W;
    c->height = H;
    c->band = BAND;
    c->codec = codec;
    c->full_period = 0;
    c->dirty = 1;
    c->palette = 0;
    c->npal = 0;
}

static void send_frame(r8_tx *tx, r8_u16 no)
{
    r8_fb b;
    r8_s16 y;
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_frame_begin(tx, no));
    for (y = 0; y < H; y = (r8_s16)(y + BAND)) {
        b.format = R8_FMT_PAGE1;
        b.width = W;
        b.rows = BAND;
        b.y0 = y;
        b.buf = frame + (unsigned)y / 8u * W;
        TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_band(tx, &b));
    }
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_frame_end(tx));
}

static r8_u16 seed = 1234;
static r8_u8 rnd8(void)
{
    seed = (r8_u16)(seed * 25173u + 13849u);
    return (r8_u8)(seed >> 8);
}

/* The i-th packet of cap (COBS-decoded, CRC included) into out; its
 * length, 0 if there is none. */
static unsigned packet(unsigned i, r8_u8 *out, unsigned size, unsigned *at, unsigned *enc_len)
{
    unsigned k = 0, start = 0, len;
    while (k < cap_len && cap[k] == 0)
        k++;
    start = k;
    for (; k < cap_len; k++) {
        if (cap[k] != 0)
            continue;
        if (i == 0) {
            if (r8_cobs_decode(cap + start, k - start, out, size, &len) != R8_OK)
                return 0;
            *at = start;
            *enc_len = k - start;
            return len;
        }
        i--;
        start = k + 1;
    }
    return 0;
}

/* Feed cap to a fresh decoder; the number of good frames.  With check,
 * each good frame must equal frame[] (and say version 2). */
static unsigned decode_all(r8_dec *d, int check)
{
    unsigned k, good = 0;
    r8_dec_init(d, dpkt, sizeof dpkt, dfb, FB_BYTES, dpal, sizeof dpal);
    for (k = 0; k < cap_len; k++)
        if (r8_dec_feed(d, cap[k]) == R8_DEC_FRAME) {
            if (check)
                TEST_ASSERT_EQUAL_MEMORY(frame, dfb, FB_BYTES);
            TEST_ASSERT_EQUAL_UINT(R8_WIRE_VERSION2, d->version);
            good++;
        }
    r8_dec_end(d);
    return good;
}

static void test_v2_frames_decode(void)
{
    r8_tx_cfg c;
    r8_tx tx;
    r8_dec d;
    r8_u8 p[64];
    unsigned i, n, at, el, ends = 0;
    r8_u32 crc;
    tcfg(&c, R8_CODEC_RLE);
    TEST_ASSERT_TRUE(r8_tx_scratch(&c) <= sizeof scratch);
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_init(&tx, &c, scratch, sizeof scratch, capture, 0));
    for (i = 0; i < FB_BYTES; i++)
        frame[i] = (r8_u8)(i < W ? 0xF0 : rnd8());
    r8_tx_sync(&tx);
    send_frame(&tx, 0);
    TEST_ASSERT_EQUAL_UINT(1, decode_all(&d, 1));
    /* FRAME_START's version byte, FRAME_END's CRC-32 of the frame */
    n = packet(0, p, sizeof p, &at, &el);
    TEST_ASSERT_TRUE(n >= 2);
    TEST_ASSERT_EQUAL_HEX8(R8_PKT_FRAME_START, p[0]);
    TEST_ASSERT_EQUAL_HEX8(R8_WIRE_VERSION2, p[1]);
    crc = r8_crc32(frame, FB_BYTES);
    for (i = 1; (n = packet(i, p, sizeof p, &at, &el)) != 0; i++) {
        if (p[0] != R8_PKT_FRAME_END)
            continue;
        ends++;
        TEST_ASSERT_EQUAL_UINT(R8_WIRE_END2_BYTES + 2u, n);
        TEST_ASSERT_EQUAL_HEX16((unsigned)(crc >> 16), ((unsigned)p[5] << 8) | p[6]);
        TEST_ASSERT_EQUAL_HEX16((unsigned)(crc & 0xFFFFu), ((unsigned)p[7] << 8) | p[8]);
    }
    TEST_ASSERT_EQUAL_UINT(1, ends);
    /* delta frames after it: none changed, one band changed, none; the
     * CRC-32 covers the clean bands the decoder keeps */
    send_frame(&tx, 1);
    frame[FB_BYTES - 1] ^= 0x5A;
    send_frame(&tx, 2);
    send_frame(&tx, 3);
    TEST_ASSERT_EQUAL_UINT(4, decode_all(&d, 0));
    TEST_ASSERT_EQUAL_MEMORY(frame, dfb, FB_BYTES);
    TEST_ASSERT_EQUAL_UINT(0, d.bad_packets);
    TEST_ASSERT_EQUAL_UINT(4, d.frames);
}

/* The generator 0x11021 as bytes (01 10 21) XORed into a raw band's
 * payload: the packet keeps its CRC-16, so only the frame CRC-32 can
 * refuse the frame - and it does: no frame shown, none wrong. */
static void test_v2_literal_damage_refused(void)
{
    r8_tx_cfg c;
    r8_tx tx;
    r8_dec d;
    r8_u8 p[200], enc[220];
    unsigned i, n, at = 0, el = 0, len, k, o, good = 0, found = 0;
    tcfg(&c, R8_CODEC_RAW);
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_init(&tx, &c, scratch, sizeof scratch, capture, 0));
    for (i = 0; i < FB_BYTES; i++)
        frame[i] = rnd8();
    r8_tx_sync(&tx);
    send_frame(&tx, 0);
    for (i = 1; (n = packet(i, p, sizeof p, &at, &el)) != 0; i++)
        if (p[0] == R8_PKT_BAND) {
            found = 1;
            break;
        }
    TEST_ASSERT_TRUE(found);
    TEST_ASSERT_TRUE(n > 6 + 2 + 8);
    TEST_ASSERT_EQUAL_HEX8(R8_CODEC_RAW, p[5]);
    /* three payload bytes that are not 0 before or after, so the COBS
     * framing stays as it was */
    for (o = 6; o + 3 <= n - 2; o++)
        if (p[o] && p[o + 1] && p[o + 2] && (p[o] ^ 0x01) && (p[o + 1] ^ 0x10) && (p[o + 2] ^ 0x21))
            break;
    TEST_ASSERT_TRUE(o + 3 <= n - 2);
    p[o] ^= 0x01;
    p[o + 1] ^= 0x10;
    p[o + 2] ^= 0x21;
    /* the packet CRC still holds */
    TEST_ASSERT_EQUAL_HEX16(((unsigned)p[n - 2] << 8) | p[n - 1], r8_crc16(p, n - 2));
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_cobs_encode(p, n, enc, sizeof enc, &len));
    TEST_ASSERT_EQUAL_UINT(el, len);   /* no zero byte appeared or left */
    for (k = 0; k < len; k++)
        cap[at + k] = enc[k];
    r8_dec_init(&d, dpkt, sizeof dpkt, dfb, FB_BYTES, dpal, sizeof dpal);
    for (k = 0; k < cap_len; k++)
        if (r8_dec_feed(&d, cap[k]) == R8_DEC_FRAME)
            good++;
    r8_dec_end(&d);
    TEST_ASSERT_EQUAL_UINT(0, good);
    TEST_ASSERT_EQUAL_UINT(0, d.bad_packets);   /* every packet passed its CRC */
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_v2_frames_decode);
    RUN_TEST(test_v2_literal_damage_refused);
    return UNITY_END();
}
