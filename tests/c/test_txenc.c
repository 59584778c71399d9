/* test_txenc.c - the frame encoder (src/wire.c, fused for speed in
 * issue 10) against a reference built from the plain parts, byte for
 * byte: r8_codec_encode with the raw fallback, r8_cobs_encode, the frame
 * CRC by r8_crc16_update over the raw bands, and the dirty-band test
 * with the fingerprint the encoder had before (CRC-16 from 0xFFFF and
 * Fletcher-16).  Random frames in every format, several band sizes
 * (short last bands, bands over 254 bytes), every codec, full and delta
 * frames, requests, bands out of order.  Also the CRC algebra the
 * encoder relies on (r8_crc16_mul, r8_crc16_xpow). */
#include "unity.h"
#include "r8wire.h"

void setUp(void) {}
void tearDown(void) {}

/* ---- random numbers (LCG, same sequence on every target) */
static r8_u32 seed;
static r8_u8 rnd8(void)
{
    seed = seed * 1103515245ul + 12345ul;
    return (r8_u8)((seed >> 16) & 0xFFu);
}
static unsigned rnd(unsigned n)
{
    unsigned v = ((unsigned)rnd8() << 8) | rnd8();
    return n ? v % n : 0;
}

/* ---- the CRC algebra */
static r8_u8 zeros[300];

static void test_crc_algebra(void)
{
    unsigned n, k;
    r8_u16 c, a, b;
    TEST_ASSERT_EQUAL_HEX16(1, r8_crc16_xpow(0));
    seed = 7;
    for (n = 0; n < sizeof zeros; n += (n < 140 ? 1 : 37)) {
        c = (r8_u16)(((unsigned)rnd8() << 8) | rnd8());
        /* c followed by n zero bytes */
        TEST_ASSERT_EQUAL_HEX16(r8_crc16_update(c, zeros, n),
                                r8_crc16_mul(c, r8_crc16_xpow(n)));
    }
    /* large n, by pieces */
    c = 0x1234;
    for (k = 0; k < 20; k++)
        c = r8_crc16_update(c, zeros, sizeof zeros);
    TEST_ASSERT_EQUAL_HEX16(c, r8_crc16_mul(0x1234, r8_crc16_xpow(20u * sizeof zeros)));
    TEST_ASSERT_EQUAL_HEX16(r8_crc16_mul(0x1234, r8_crc16_xpow(32767u)),
                            r8_crc16_mul(r8_crc16_mul(0x1234, r8_crc16_xpow(30000u)),
                                         r8_crc16_xpow(2767u)));
    /* mul is commutative and linear, 1 is its unit */
    for (k = 0; k < 200; k++) {
        a = (r8_u16)(((unsigned)rnd8() << 8) | rnd8());
        b = (r8_u16)(((unsigned)rnd8() << 8) | rnd8());
        c = (r8_u16)(((unsigned)rnd8() << 8) | rnd8());
        TEST_ASSERT_EQUAL_HEX16(r8_crc16_mul(a, b), r8_crc16_mul(b, a));
        TEST_ASSERT_EQUAL_HEX16(r8_crc16_mul(a, b) ^ r8_crc16_mul(c, b),
                                r8_crc16_mul((r8_u16)(a ^ c), b));
        TEST_ASSERT_EQUAL_HEX16(a, r8_crc16_mul(a, 1));
        TEST_ASSERT_EQUAL_HEX16(0, r8_crc16_mul(a, 0));
    }
}

/* ---- frames */
#define MAX_FRAME 640
#define MAX_BAND 320
#define MAX_BANDS 8
static r8_u8 frame[MAX_FRAME];
static r8_u8 band_buf[MAX_BAND];
static r8_u8 scratch[R8_TX_SCRATCH_BYTES(MAX_BAND, MAX_BANDS, 4)];

/* Fill p[0..n) with one of several kinds of content. */
static void fill(r8_u8 *p, unsigned n, unsigned kind)
{
    unsigned i = 0, len, k;
    r8_u8 v;
    if (kind == 0) { /* all zero */
        for (; i < n; i++)
            p[i] = 0;
        return;
    }
    if (kind == 1) { /* random bytes, no zero */
        for (; i < n; i++)
            p[i] = (r8_u8)(rnd8() | 1u);
        return;
    }
    if (kind == 6) {
        /* 250..270 non-zero bytes (RLE literals back to back), then a
         * zero inside literals or a zero run: a COBS block too long */
        len = 250u + rnd(21);
        for (; i < n && i < len; i++)
            p[i] = (r8_u8)(rnd8() | 1u);
        for (; i < n; i++)
            p[i] = (r8_u8)(rnd(3) ? 0 : rnd8());
        if (len + 5u < n) {
            p[len] = p[len + 2u] = p[len + 3u] = 0;
            p[len + 1u] = (r8_u8)(rnd(2) ? 0 : 0x21); /* a zero run or a literal 0 */
        }
        return;
    }
    while (i < n) {
        len = 1u + rnd(kind == 2 ? 140u : 9u);
        if (len > n - i)
            len = n - i;
        switch (rnd(6)) {
        case 0:
        case 1: /* zeros */
            for (k = 0; k < len; k++)
                p[i + k] = 0;
            break;
        case 2: /* a run */
            v = rnd8();
            for (k = 0; k < len; k++)
                p[i + k] = v;
            break;
        case 3: /* a dither pattern */
            for (k = 0; k < len; k++)
                p[i + k] = (r8_u8)((k & 1u) ? 0x55u : ((k & 2u) ? 0xBBu : 0xFFu));
            break;
        default: /* literals, a few zeros and pairs among them */
            for (k = 0; k < len; k++) {
                v = rnd8();
                if (v < 40u)
                    v = 0;
                else if (v < 60u && k)
                    v = p[i + k - 1];
                p[i + k] = v;
            }
            break;
        }
        i += len;
    }
}

/* ---- the reference encoder: the unfused algorithm */
typedef struct ref_tx {
    r8_tx_cfg c;
    unsigned nbands, band_bytes;
    r8_u8 fp[4 * MAX_BANDS];
    r8_u16 since_full;
    r8_u8 want_full;
} ref_tx;

static r8_u8 ref_out[2000], got_out[2000];
static unsigned ref_len, got_len;
static r8_u8 body[MAX_BAND + 32], enc[MAX_BAND + 40];

static void capture(void *ctx, const r8_u8 *p, unsigned n)
{
    (void)ctx;
    while (n--) {
        if (got_len < sizeof got_out)
            got_out[got_len] = *p;
        got_len++;
        p++;
    }
}

static void ref_packet(unsigned n)
{
    unsigned len, k;
    r8_u16 crc = r8_crc16(body, n);
    body[n] = (r8_u8)(crc >> 8);
    body[n + 1] = (r8_u8)(crc & 0xFFu);
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_cobs_encode(body, n + 2, enc, sizeof enc, &len));
    TEST_ASSERT_TRUE(ref_len + len + 1 <= sizeof ref_out);
    for (k = 0; k < len; k++)
        ref_out[ref_len++] = enc[k];
    ref_out[ref_len++] = 0;
}

static unsigned band_len(const r8_tx_cfg *c, unsigned idx)
{
    unsigned rows = (unsigned)c->height - idx * (unsigned)c->band;
    if (rows > (unsigned)c->band)
        rows = (unsigned)c->band;
    return r8_fb_bytes(c->format, c->width, (r8_s16)rows);
}

/* One frame, bands in the order order[0..nbands) (band indices). */
static void ref_frame(ref_tx *r, r8_u16 no, const unsigned *order)
{
    unsigned i, k, idx, n, off, len;
    r8_u8 full, f1, f2, changed, codec;
    r8_u16 h, fcrc = R8_CRC16_INIT, sent = 0;
    if (r->c.full_period && r->since_full >= r->c.full_period)
        r->want_full = 1;
    full = (r8_u8)(r->want_full || !r->c.dirty);
    if (full) {
        r->want_full = 0;
        r->since_full = 0;
    }
    r->since_full++;
    body[0] = R8_PKT_FRAME_START;
    body[1] = R8_WIRE_VERSION;
    body[2] = (r8_u8)(no >> 8);
    body[3] = (r8_u8)no;
    body[4] = (r8_u8)((unsigned)r->c.width >> 8);
    body[5] = (r8_u8)r->c.width;
    body[6] = (r8_u8)((unsigned)r->c.height >> 8);
    body[7] = (r8_u8)r->c.height;
    body[8] = r->c.format;
    body[9] = (r8_u8)((unsigned)r->c.band >> 8);
    body[10] = (r8_u8)r->c.band;
    body[11] = r->c.codec;
    body[12] = (r8_u8)(full ? R8_FLAG_FULL : 0);
    body[13] = r->c.npal;
    for (k = 0; k < 3u * r->c.npal; k++)
        body[14 + k] = r->c.palette[k];
    ref_packet(14 + 3u * r->c.npal);
    for (i = 0; i < r->nbands; i++) {
        idx = order[i];
        off = idx * r->band_bytes;
        n = band_len(&r->c, idx);
        fcrc = r8_crc16_update(fcrc, frame + off, n);
        h = r8_crc16(frame + off, n);
        f1 = f2 = 0;
        for (k = 0; k < n; k++) {
            f1 = (r8_u8)(f1 + frame[off + k]);
            f2 = (r8_u8)(f2 + f1);
        }
        changed = (r8_u8)(r->fp[4 * idx] != (r8_u8)(h >> 8) ||
                          r->fp[4 * idx + 1] != (r8_u8)h ||
                          r->fp[4 * idx + 2] != f1 || r->fp[4 * idx + 3] != f2);
        r->fp[4 * idx] = (r8_u8)(h >> 8);
        r->fp[4 * idx + 1] = (r8_u8)h;
        r->fp[4 * idx + 2] = f1;
        r->fp[4 * idx + 3] = f2;
        if (!full && !changed)
            continue;
        codec = r->c.codec;
        body[0] = R8_PKT_BAND;
        body[1] = (r8_u8)(no >> 8);
        body[2] = (r8_u8)no;
        k = idx * (unsigned)r->c.band;
        body[3] = (r8_u8)(k >> 8);
        body[4] = (r8_u8)k;
        k = (unsigned)R8_E_SPACE;
        if (codec != R8_CODEC_RAW &&
            r8_codec_encode(codec, frame + off, n, body + 6, n - 1u, &len) == R8_OK)
            k = 0;
        if (k) {
            codec = R8_CODEC_RAW;
            TEST_ASSERT_EQUAL_INT(R8_OK, r8_codec_encode(codec, frame + off, n, body + 6, n, &len));
        }
        body[5] = codec;
        ref_packet(6 + len);
        sent++;
    }
    body[0] = R8_PKT_FRAME_END;
    body[1] = (r8_u8)(no >> 8);
    body[2] = (r8_u8)no;
    body[3] = (r8_u8)(sent >> 8);
    body[4] = (r8_u8)sent;
    body[5] = (r8_u8)(fcrc >> 8);
    body[6] = (r8_u8)fcrc;
    ref_packet(7);
}

static void tx_frame(r8_tx *tx, r8_u16 no, const unsigned *order)
{
    r8_fb fb;
    unsigned i, k, idx, n;
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_frame_begin(tx, no));
    for (i = 0; i < tx->nbands; i++) {
        idx = order[i];
        n = band_len(&tx->cfg, idx);
        TEST_ASSERT_EQUAL_INT(0, r8_fb_init(&fb, band_buf, tx->cfg.format, tx->cfg.width,
                                            tx->cfg.height, 0, tx->cfg.band));
        r8_fb_set_band(&fb, (r8_s16)(idx * (unsigned)tx->cfg.band));
        for (k = 0; k < n; k++)
            band_buf[k] = frame[idx * tx->band_bytes + k];
        TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_band(tx, &fb));
    }
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_frame_end(tx));
}

static void check_fp(const r8_u8 *fp, const r8_u8 *p, unsigned n)
{
    r8_u16 g = r8_crc16_update(0, p, n);
    r8_u8 f1 = 0, f2 = 0;
    while (n--) {
        f1 = (r8_u8)(f1 + *p++);
        f2 = (r8_u8)(f2 + f1);
    }
    TEST_ASSERT_EQUAL_HEX8(g >> 8, fp[0]);
    TEST_ASSERT_EQUAL_HEX8(g & 0xFFu, fp[1]);
    TEST_ASSERT_EQUAL_HEX8(f1, fp[2]);
    TEST_ASSERT_EQUAL_HEX8(f2, fp[3]);
}

static const r8_u8 pal3[9] = { 0, 0, 0, 128, 0, 0, 255, 255, 255 };

/* frames of cfg c: kinds picks the content; frames change band by band */
static void run_cfg(const r8_tx_cfg *c, unsigned frames, unsigned kinds)
{
    r8_tx tx;
    ref_tx r;
    unsigned order[MAX_BANDS], f, i, k, n, fsize;
    TEST_ASSERT_TRUE(r8_tx_scratch(c) <= sizeof scratch);
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_init(&tx, c, scratch, r8_tx_scratch(c), capture, 0));
    TEST_ASSERT_TRUE(tx.nbands <= MAX_BANDS);
    r.c = *c;
    r.nbands = tx.nbands;
    r.band_bytes = tx.band_bytes;
    for (i = 0; i < sizeof r.fp; i++)
        r.fp[i] = 0;
    r.since_full = 0;
    r.want_full = 1;
    fsize = tx.band_bytes * (tx.nbands - 1u) + band_len(c, tx.nbands - 1u);
    TEST_ASSERT_TRUE(fsize <= MAX_FRAME);
    for (i = 0; i < tx.nbands; i++)
        fill(frame + i * tx.band_bytes, band_len(c, i), rnd(kinds));
    for (f = 0; f < frames; f++) {
        /* change some bands; sometimes none */
        if (f && rnd(4))
            for (i = 0; i < tx.nbands; i++)
                if (!rnd(2)) {
                    n = band_len(c, i);
                    if (rnd(3))
                        fill(frame + i * tx.band_bytes, n, rnd(kinds));
                    else /* one byte changes */
                        frame[i * tx.band_bytes + rnd(n)] ^= (r8_u8)(1u << rnd(8));
                }
        for (i = 0; i < tx.nbands; i++)
            order[i] = i;
        if (f % 7 == 5) /* bands out of order */
            for (i = 0; i < tx.nbands; i++)
                order[i] = tx.nbands - 1u - i;
        if (f % 11 == 6) {
            r8_tx_request_full(&tx);
            r.want_full = 1;
        }
        ref_len = got_len = 0;
        ref_frame(&r, (r8_u16)(f * 251u), order);
        tx_frame(&tx, (r8_u16)(f * 251u), order);
        TEST_ASSERT_EQUAL_UINT(ref_len, got_len);
        TEST_ASSERT_EQUAL_MEMORY(ref_out, got_out, ref_len);
        /* the fingerprints kept: CRC-16 from 0 and Fletcher-16 */
        for (i = 0; i < tx.nbands; i++)
            check_fp(tx.fp + 4 * i, frame + i * tx.band_bytes, band_len(c, i));
    }
    k = fsize; /* raw bytes counted */
    TEST_ASSERT_EQUAL_UINT32((r8_u32)k * frames, tx.raw_bytes);
}

static void cfg(r8_tx_cfg *c, r8_u8 format, r8_s16 w, r8_s16 h, r8_s16 band, r8_u8 codec)
{
    c->format = format;
    c->width = w;
    c->height = h;
    c->band = band;
    c->codec = codec;
    c->full_period = 9;
    c->dirty = 1;
    c->palette = 0;
    c->npal = 0;
}

static void test_page1(void)
{
    r8_tx_cfg c;
    seed = 1;
    cfg(&c, R8_FMT_PAGE1, 64, 24, 8, R8_CODEC_RLE);
    run_cfg(&c, 30, 6);
    cfg(&c, R8_FMT_PAGE1, 100, 40, 16, R8_CODEC_RLE); /* last band 8 rows */
    run_cfg(&c, 20, 6);
    cfg(&c, R8_FMT_PAGE1, 128, 8, 8, R8_CODEC_RLE); /* one band: 128 B */
    c.dirty = 0;
    run_cfg(&c, 12, 4);
}

static void test_row1_idx8(void)
{
    r8_tx_cfg c;
    seed = 2;
    cfg(&c, R8_FMT_ROW1, 40, 13, 3, R8_CODEC_RLE); /* 15 B bands, last 5 */
    run_cfg(&c, 25, 6);
    cfg(&c, R8_FMT_IDX8, 20, 9, 4, R8_CODEC_RLE); /* last band 20 B */
    c.palette = pal3;
    c.npal = 3;
    c.full_period = 0;
    run_cfg(&c, 25, 6);
}

/* Bands over 254 bytes: RLE that does not fit (raw, blocks of 254
 * non-zero bytes for COBS), literal runs back to back with no zero. */
static void test_big_bands(void)
{
    r8_tx_cfg c;
    seed = 3;
    cfg(&c, R8_FMT_IDX8, 40, 16, 8, R8_CODEC_RLE);
    run_cfg(&c, 16, 6);
    cfg(&c, R8_FMT_IDX8, 40, 16, 8, R8_CODEC_RLE);
    run_cfg(&c, 10, 2); /* all zero or no zero at all */
    cfg(&c, R8_FMT_IDX8, 40, 16, 8, R8_CODEC_RLE);
    run_cfg(&c, 20, 7); /* and kind 6 */
    cfg(&c, R8_FMT_IDX8, 40, 16, 8, R8_CODEC_RAW);
    run_cfg(&c, 6, 6);
}

static void test_other_codecs(void)
{
    r8_tx_cfg c;
    seed = 4;
    cfg(&c, R8_FMT_PAGE1, 64, 24, 8, R8_CODEC_RAW);
    run_cfg(&c, 12, 6);
    cfg(&c, R8_FMT_PAGE1, 64, 24, 8, R8_CODEC_LZ77);
    run_cfg(&c, 12, 6);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_crc_algebra);
    RUN_TEST(test_page1);
    RUN_TEST(test_row1_idx8);
    RUN_TEST(test_big_bands);
    RUN_TEST(test_other_codecs);
    return UNITY_END();
}
