/* test_wire.c - CRC-16/CCITT-FALSE, COBS (shared vectors, streaming
 * writer, malformed input), the frame encoder's packets, and the shared
 * decoder (dec) and device-input (dev) vectors. */
#include "unity.h"
#include "r8wire.h"
#include "../vectors/vectors.h"

#define GUARD 0xA5
static r8_u8 buf[300 + 4];
static r8_u8 buf2[300 + 4];
static r8_u8 cap_buf[700];
static unsigned cap_len;

void setUp(void)
{
    unsigned i;
    for (i = 0; i < sizeof buf; i++)
        buf[i] = buf2[i] = GUARD;
    cap_len = 0;
}
void tearDown(void) {}

static void capture(void *ctx, const r8_u8 *p, unsigned n)
{
    (void)ctx;
    while (n--) {
        if (cap_len < sizeof cap_buf)
            cap_buf[cap_len] = *p;
        cap_len++;
        p++;
    }
}

static void test_crc_vectors(void)
{
    unsigned i, seen = 0;
    r8_u16 c;
    for (i = 0; i < TVEC_COUNT; i++) {
        const tvec *v = &tvecs[i];
        if (v->kind != VK_CRC)
            continue;
        seen++;
        c = r8_crc16(v->in, v->in_len);
        TEST_ASSERT_EQUAL_HEX16(((unsigned)v->out[0] << 8) | v->out[1], c);
    }
    TEST_ASSERT_EQUAL_UINT(0x29B1, r8_crc16((const r8_u8 *)"123456789", 9));
    /* incremental = one shot */
    c = r8_crc16_update(R8_CRC16_INIT, (const r8_u8 *)"1234", 4);
    TEST_ASSERT_EQUAL_UINT(0x29B1, r8_crc16_update(c, (const r8_u8 *)"56789", 5));
    TEST_ASSERT_TRUE(seen >= 3);
}

static void test_cobs_vectors(void)
{
    unsigned i, len, seen = 0;
    for (i = 0; i < TVEC_COUNT; i++) {
        const tvec *v = &tvecs[i];
        setUp();
        if (v->kind == VK_COBS) {
            seen++;
            TEST_ASSERT_EQUAL_INT(R8_OK, r8_cobs_encode(v->in, v->in_len, buf, 300, &len));
            TEST_ASSERT_EQUAL_UINT(v->out_len, len);
            TEST_ASSERT_EQUAL_MEMORY(v->out, buf, len);
            TEST_ASSERT_TRUE(len <= R8_COBS_BOUND(v->in_len));
            r8_cobs_write(v->in, v->in_len, capture, 0);
            TEST_ASSERT_EQUAL_UINT(v->out_len, cap_len);
            TEST_ASSERT_EQUAL_MEMORY(v->out, cap_buf, cap_len);
            TEST_ASSERT_EQUAL_INT(R8_OK, r8_cobs_decode(v->out, v->out_len, buf2, 300, &len));
            TEST_ASSERT_EQUAL_UINT(v->in_len, len);
            TEST_ASSERT_EQUAL_MEMORY(v->in, buf2, len);
        } else if (v->kind == VK_COBS_BAD) {
            seen++;
            TEST_ASSERT_EQUAL_INT(v->err, r8_cobs_decode(v->in, v->in_len, buf2, v->limit, &len));
        }
    }
    TEST_ASSERT_TRUE(seen >= 10);
}

static void test_cobs_limits(void)
{
    static const r8_u8 in[] = { 1, 2, 0, 3 };
    unsigned cap, len;
    int rc;
    for (cap = 0; cap < 7; cap++) {
        setUp();
        rc = r8_cobs_encode(in, 4, buf, cap, &len);
        TEST_ASSERT_EQUAL_HEX8(GUARD, buf[cap]);
        TEST_ASSERT_EQUAL_INT(cap >= 5 ? R8_OK : R8_E_SPACE, rc);
    }
}

static const r8_u8 pal[6] = { 0, 0, 0, 255, 255, 255 };
static r8_u8 scratch[200];
static r8_u8 band[64];

static void tx_cfg(r8_tx_cfg *c)
{
    c->format = R8_FMT_PAGE1;
    c->width = 16;
    c->height = 16;
    c->band = 8;
    c->codec = R8_CODEC_RLE;
    c->full_period = 4;
    c->dirty = 1;
    c->palette = 0;
    c->npal = 0;
}

/* Decode the capture's packets in order; returns the count and checks
 * each packet's CRC.  Types go to types[]. */
static unsigned packets(r8_u8 *types, unsigned max)
{
    unsigned i = 0, start = 0, n = 0, len;
    for (i = 0; i < cap_len; i++) {
        if (cap_buf[i] != 0)
            continue;
        if (i > start) {
            TEST_ASSERT_EQUAL_INT(R8_OK, r8_cobs_decode(cap_buf + start, i - start, buf, 300, &len));
            TEST_ASSERT_TRUE(len >= 3);
            TEST_ASSERT_EQUAL_UINT(r8_crc16(buf, len - 2), ((unsigned)buf[len - 2] << 8) | buf[len - 1]);
            if (n < max)
                types[n] = buf[0];
            n++;
        }
        start = i + 1;
    }
    TEST_ASSERT_EQUAL_UINT(cap_len, start); /* ends with a delimiter */
    return n;
}

static void send_frame(r8_tx *tx, r8_u16 no, r8_u8 top, r8_u8 bottom)
{
    r8_fb fb;
    unsigned k;
    TEST_ASSERT_EQUAL_INT(0, r8_fb_init(&fb, band, R8_FMT_PAGE1, 16, 16, 0, 8));
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_frame_begin(tx, no));
    for (k = 0; k < 16; k++)
        band[k] = top;
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_band(tx, &fb));
    r8_fb_set_band(&fb, 8);
    for (k = 0; k < 16; k++)
        band[k] = (r8_u8)(bottom + k);
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_band(tx, &fb));
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_frame_end(tx));
}

static void test_tx_sizes_and_errors(void)
{
    r8_tx_cfg c;
    r8_tx tx;
    tx_cfg(&c);
    TEST_ASSERT_EQUAL_UINT(16, r8_tx_band_bytes(&c));
    TEST_ASSERT_EQUAL_UINT(16 + R8_WIRE_BAND_HDR + 2 + 2 + 4 * 2, r8_tx_scratch(&c));
    TEST_ASSERT_EQUAL_INT(R8_E_SPACE, r8_tx_init(&tx, &c, scratch, 10, capture, 0));
    c.band = 4; /* PAGE1 needs multiples of 8 */
    TEST_ASSERT_EQUAL_UINT(0, r8_tx_scratch(&c));
    TEST_ASSERT_EQUAL_INT(R8_E_ARG, r8_tx_init(&tx, &c, scratch, sizeof scratch, capture, 0));
    tx_cfg(&c);
    c.codec = 7;
    TEST_ASSERT_EQUAL_INT(R8_E_ARG, r8_tx_init(&tx, &c, scratch, sizeof scratch, capture, 0));
    /* the largest bands (R8_WIRE_MAX_BAND) and the scratch macro */
    tx_cfg(&c);
    c.width = 4095;
    c.height = 4095;
    c.band = 64; /* PAGE1: 8 * 4095 */
    TEST_ASSERT_EQUAL_UINT(32760, r8_tx_band_bytes(&c));
    TEST_ASSERT_EQUAL_UINT(R8_TX_SCRATCH_BYTES(32760u, R8_WIRE_NBANDS(4095, 64), 0), r8_tx_scratch(&c));
    c.band = 72;
    TEST_ASSERT_EQUAL_UINT(0, r8_tx_band_bytes(&c));
    c.format = R8_FMT_ROW1; /* 512 bytes a row */
    c.band = 63;
    TEST_ASSERT_EQUAL_UINT(32256, r8_tx_band_bytes(&c));
    c.band = 64;
    TEST_ASSERT_EQUAL_UINT(0, r8_tx_band_bytes(&c));
    c.format = R8_FMT_IDX8;
    c.band = 8;
    TEST_ASSERT_EQUAL_UINT(32760, r8_tx_band_bytes(&c));
    c.band = 9;
    TEST_ASSERT_EQUAL_UINT(0, r8_tx_scratch(&c));
    c.width = 8;
    c.band = 2;
    c.palette = pal;
    c.npal = 200; /* the frame start is the largest packet */
    TEST_ASSERT_EQUAL_UINT(R8_TX_SCRATCH_BYTES(16, R8_WIRE_NBANDS(4095, 2), 200), r8_tx_scratch(&c));
}

static void test_tx_full_then_dirty(void)
{
    r8_tx_cfg c;
    r8_tx tx;
    r8_u8 t[16];
    r8_u32 k;
    tx_cfg(&c);
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_init(&tx, &c, scratch, sizeof scratch, capture, 0));
    r8_tx_sync(&tx);
    send_frame(&tx, 0, 0, 1);   /* first frame: full */
    TEST_ASSERT_EQUAL_UINT(4, packets(t, 16));
    TEST_ASSERT_EQUAL_UINT(R8_PKT_FRAME_START, t[0]);
    TEST_ASSERT_EQUAL_UINT(R8_PKT_BAND, t[1]);
    TEST_ASSERT_EQUAL_UINT(R8_PKT_FRAME_END, t[3]);
    cap_len = 0;
    send_frame(&tx, 1, 0, 1);   /* nothing changed: start + end */
    TEST_ASSERT_EQUAL_UINT(2, packets(t, 16));
    cap_len = 0;
    send_frame(&tx, 2, 0xFF, 1); /* top changed */
    TEST_ASSERT_EQUAL_UINT(3, packets(t, 16));
    cap_len = 0;
    send_frame(&tx, 3, 0xFF, 1);
    TEST_ASSERT_EQUAL_UINT(2, packets(t, 16));
    cap_len = 0;
    send_frame(&tx, 4, 0xFF, 1); /* period 4: full again */
    TEST_ASSERT_EQUAL_UINT(4, packets(t, 16));
    cap_len = 0;
    r8_tx_request_full(&tx);
    send_frame(&tx, 5, 0xFF, 1); /* requested */
    TEST_ASSERT_EQUAL_UINT(4, packets(t, 16));
    /* the encoder counts exactly the bytes it wrote */
    cap_len = 0;
    k = tx.bytes;
    send_frame(&tx, 6, 0xFF, 2);
    TEST_ASSERT_EQUAL_UINT(k + cap_len, tx.bytes);
}

static void test_tx_request_packet(void)
{
    r8_tx_cfg c;
    r8_tx tx;
    r8_u8 req[R8_DEC_REQUEST_BYTES];
    unsigned n, k, acc = 0;
    r8_u8 t[16];
    tx_cfg(&c);
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_init(&tx, &c, scratch, sizeof scratch, capture, 0));
    send_frame(&tx, 0, 0, 1);
    cap_len = 0;
    n = r8_dec_request(req);
    TEST_ASSERT_TRUE(n <= R8_DEC_REQUEST_BYTES);
    TEST_ASSERT_EQUAL_UINT(0, req[0]);
    TEST_ASSERT_EQUAL_UINT(0, req[n - 1]);
    for (k = 0; k < n; k++)
        acc += (unsigned)r8_tx_rx(&tx, req[k]);
    TEST_ASSERT_EQUAL_UINT(1, acc);
    send_frame(&tx, 1, 0, 1);
    TEST_ASSERT_EQUAL_UINT(4, packets(t, 16)); /* full despite no change */
    /* a corrupted request is ignored */
    req[2] ^= 0x10;
    acc = 0;
    for (k = 0; k < n; k++)
        acc += (unsigned)r8_tx_rx(&tx, req[k]);
    TEST_ASSERT_EQUAL_UINT(0, acc);
    cap_len = 0;
    send_frame(&tx, 2, 0, 1);
    TEST_ASSERT_EQUAL_UINT(2, packets(t, 16));
    /* garbage then a good request still works */
    for (k = 0; k < 40; k++)
        r8_tx_rx(&tx, (r8_u8)(k * 7 + 1));
    req[2] ^= 0x10;
    acc = 0;
    for (k = 0; k < n; k++)
        acc += (unsigned)r8_tx_rx(&tx, req[k]);
    TEST_ASSERT_EQUAL_UINT(1, acc);
}

static void test_tx_palette_and_raw_fallback(void)
{
    r8_tx_cfg c;
    r8_tx tx;
    r8_fb fb;
    unsigned k, len;
    r8_u8 t[8];
    tx_cfg(&c);
    c.format = R8_FMT_IDX8;
    c.width = 8;
    c.height = 4;
    c.band = 4;
    c.palette = pal;
    c.npal = 2;
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_init(&tx, &c, scratch, sizeof scratch, capture, 0));
    TEST_ASSERT_EQUAL_INT(0, r8_fb_init(&fb, band, R8_FMT_IDX8, 8, 4, 0, 4));
    for (k = 0; k < 32; k++)
        band[k] = (r8_u8)(k * 37 + 11); /* no runs: RLE would grow */
    r8_tx_frame_begin(&tx, 9);
    r8_tx_band(&tx, &fb);
    r8_tx_frame_end(&tx);
    TEST_ASSERT_EQUAL_UINT(3, packets(t, 8));
    /* the band packet went raw: codec byte 0, payload = the band */
    {
        unsigned i, start = 0, seen = 0;
        for (i = 0; i < cap_len; i++) {
            if (cap_buf[i])
                continue;
            r8_cobs_decode(cap_buf + start, i - start, buf, 300, &len);
            if (buf[0] == R8_PKT_FRAME_START) {
                TEST_ASSERT_EQUAL_UINT(R8_WIRE_START_BYTES + 6 + 2, len);
                TEST_ASSERT_EQUAL_UINT(2, buf[13]);
                TEST_ASSERT_EQUAL_MEMORY(pal, buf + 14, 6);
            }
            if (buf[0] == R8_PKT_BAND) {
                seen = 1;
                TEST_ASSERT_EQUAL_UINT(R8_CODEC_RAW, buf[5]);
                TEST_ASSERT_EQUAL_UINT(R8_WIRE_BAND_HDR + 32 + 2, len);
                TEST_ASSERT_EQUAL_MEMORY(band, buf + R8_WIRE_BAND_HDR, 32);
            }
            start = i + 1;
        }
        TEST_ASSERT_TRUE(seen);
    }
}

/* The shared protocol stream vector (docs/protocol.md section 7). */
static void test_stream_vector(void)
{
    r8_tx_cfg c;
    r8_tx tx;
    r8_fb fb;
    unsigned i, k, seen = 0;
    for (i = 0; i < TVEC_COUNT; i++) {
        const tvec *v = &tvecs[i];
        if (v->kind != VK_STREAM)
            continue;
        seen++;
        tx_cfg(&c);
        c.width = 16;
        c.height = 8;
        c.full_period = 32;
        TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_init(&tx, &c, scratch, sizeof scratch, capture, 0));
        TEST_ASSERT_EQUAL_INT(0, r8_fb_init(&fb, band, R8_FMT_PAGE1, 16, 8, 0, 8));
        cap_len = 0;
        r8_tx_sync(&tx);
        for (k = 0; k < 2; k++) {
            unsigned j;
            for (j = 0; j < 16; j++)
                band[j] = v->in[j];
            r8_tx_frame_begin(&tx, (r8_u16)k);
            r8_tx_band(&tx, &fb);
            r8_tx_frame_end(&tx);
        }
        TEST_ASSERT_EQUAL_UINT(v->out_len, cap_len);
        TEST_ASSERT_EQUAL_MEMORY(v->out, cap_buf, cap_len);
    }
    TEST_ASSERT_EQUAL_UINT(1, seen);
}

static unsigned get16v(const unsigned char *p)
{
    return ((unsigned)p[0] << 8) | p[1];
}

/* Decoder vectors: the good frames' numbers and the counters after the
 * end of input; nothing written past the frame buffer. */
#define DV_FB 32
static r8_u8 dv_pkt[R8_DEC_PKT_BYTES(DV_FB)];
static r8_u8 dv_fb[DV_FB + 4];
static r8_u8 dv_pal[3 * 256];
static void test_decoder_vectors(void)
{
    unsigned i, k, seen = 0;
    for (i = 0; i < TVEC_COUNT; i++) {
        const tvec *v = &tvecs[i];
        const unsigned char *e = v->out, *cnt;
        unsigned fb, nf, got = 0;
        r8_dec d;
        if (v->kind != VK_DEC)
            continue;
        fb = get16v(e);
        nf = e[2];
        cnt = e + 3 + 2 * nf;
        seen++;
        TEST_ASSERT_TRUE(fb <= DV_FB);
        for (k = 0; k < sizeof dv_fb; k++)
            dv_fb[k] = GUARD;
        r8_dec_init(&d, dv_pkt, R8_DEC_PKT_BYTES(fb), dv_fb, fb, dv_pal, sizeof dv_pal);
        for (k = 0; k < v->in_len; k++) {
            if (r8_dec_feed(&d, v->in[k]) == R8_DEC_FRAME) {
                if (got >= nf || d.frame != get16v(e + 3 + 2 * got)) {
                    unity_print(v->name);
                    unity_print(": unexpected good frame\n");
                    TEST_ASSERT_TRUE(0);
                }
                got++;
            }
        }
        r8_dec_end(&d);
        for (k = fb; k < sizeof dv_fb; k++)
            TEST_ASSERT_EQUAL_HEX8(GUARD, dv_fb[k]);
        if (got != nf || d.bad_packets != get16v(cnt) || d.dropped != get16v(cnt + 2) ||
            d.incomplete != get16v(cnt + 4) || d.skipped != get16v(cnt + 6) ||
            d.ignored != get16v(cnt + 8)) {
            unity_print(v->name);
            unity_print(": frames/counters differ\n");
            TEST_ASSERT_EQUAL_UINT(nf, got);
            TEST_ASSERT_EQUAL_UINT(get16v(cnt), d.bad_packets);
            TEST_ASSERT_EQUAL_UINT(get16v(cnt + 2), d.dropped);
            TEST_ASSERT_EQUAL_UINT(get16v(cnt + 4), d.incomplete);
            TEST_ASSERT_EQUAL_UINT(get16v(cnt + 6), d.skipped);
            TEST_ASSERT_EQUAL_UINT(get16v(cnt + 8), d.ignored);
        }
        TEST_ASSERT_EQUAL_UINT(nf, d.frames);
    }
    TEST_ASSERT_TRUE(seen >= 15);
}

/* Device-side vectors: what r8_tx_rx makes of display -> device bytes. */
static void test_device_input_vectors(void)
{
    r8_tx_cfg c;
    r8_tx tx;
    unsigned i, k, seen = 0, req, inp;
    for (i = 0; i < TVEC_COUNT; i++) {
        const tvec *v = &tvecs[i];
        if (v->kind != VK_DEV)
            continue;
        seen++;
        tx_cfg(&c);
        TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_init(&tx, &c, scratch, sizeof scratch, capture, 0));
        send_frame(&tx, 0, 0, 1);
        req = inp = 0;
        for (k = 0; k < v->in_len; k++) {
            int r = r8_tx_rx(&tx, v->in[k]);
            req += r == R8_RX_REQUEST;
            inp += r == R8_RX_INPUT;
        }
        if (req != v->out[0] || inp != v->out[1] || tx.keys != get16v(v->out + 2) ||
            tx.inputs != inp || tx.want_full != (req != 0)) {
            unity_print(v->name);
            unity_print(": device input differs\n");
            TEST_ASSERT_EQUAL_UINT(v->out[0], req);
            TEST_ASSERT_EQUAL_UINT(v->out[1], inp);
            TEST_ASSERT_EQUAL_HEX16(get16v(v->out + 2), tx.keys);
            TEST_ASSERT_EQUAL_UINT(inp, tx.inputs);
            TEST_ASSERT_EQUAL_UINT(req != 0, tx.want_full);
        }
    }
    TEST_ASSERT_TRUE(seen >= 5);
}

/* r8_dec_input writes the INPUT packet r8_tx_rx accepts, for every key
 * bit, and r8_dec_request the REQUEST. */
static void test_input_packet_round_trip(void)
{
    r8_tx_cfg c;
    r8_tx tx;
    r8_u8 out[R8_DEC_INPUT_BYTES + 2];
    unsigned b, k, n;
    tx_cfg(&c);
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_init(&tx, &c, scratch, sizeof scratch, capture, 0));
    TEST_ASSERT_EQUAL_UINT(0, tx.keys);
    send_frame(&tx, 0, 0, 1); /* the first (full) frame clears want_full */
    TEST_ASSERT_EQUAL_UINT(0, tx.want_full);
    for (b = 0; b <= 16; b++) {
        r8_u16 keys = (r8_u16)(b == 16 ? 0xFFFFu : (1u << b));
        int last = 0;
        out[R8_DEC_INPUT_BYTES] = GUARD;
        n = r8_dec_input(out, keys);
        TEST_ASSERT_TRUE(n <= R8_DEC_INPUT_BYTES);
        TEST_ASSERT_EQUAL_HEX8(GUARD, out[R8_DEC_INPUT_BYTES]);
        TEST_ASSERT_EQUAL_UINT(0, out[0]);
        TEST_ASSERT_EQUAL_UINT(0, out[n - 1]);
        for (k = 0; k < n; k++)
            last = r8_tx_rx(&tx, out[k]);
        TEST_ASSERT_EQUAL_INT(R8_RX_INPUT, last);
        TEST_ASSERT_EQUAL_HEX16(keys, tx.keys);
    }
    TEST_ASSERT_EQUAL_UINT(17, tx.inputs);
    TEST_ASSERT_EQUAL_UINT(0, tx.want_full); /* inputs do not ask for a full frame */
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_crc_vectors);
    RUN_TEST(test_cobs_vectors);
    RUN_TEST(test_cobs_limits);
    RUN_TEST(test_tx_sizes_and_errors);
    RUN_TEST(test_tx_full_then_dirty);
    RUN_TEST(test_tx_request_packet);
    RUN_TEST(test_tx_palette_and_raw_fallback);
    RUN_TEST(test_stream_vector);
    RUN_TEST(test_decoder_vectors);
    RUN_TEST(test_device_input_vectors);
    RUN_TEST(test_input_packet_round_trip);
    return UNITY_END();
}
