/* test_txband.c - r8_tx_band where a port links its own (R8_ASM_TXBAND:
 * ports/6502/txband_6502.s) against the C89 reference r8_tx_band_c of
 * src/wire.c, elsewhere the C against itself; on every target the
 * stream decoded (r8_dec) back to the frames, the model.  Random frames
 * (zeros, runs, literals, blocks that break the COBS chain or do not
 * compress), widths on both sides of the kernel's 255-byte band, a
 * partial last band, bands out of order, RLE and raw, full and delta
 * frames: the two encoders' streams and states stay equal. */
#include <stddef.h>
#include "unity.h"
#include "../../src/r8crc.h"

#ifndef R8_ASM_TXBAND
#define r8_tx_band_c r8_tx_band
#endif
#define txb_ref r8_tx_band_c

#if defined(R8_ASM_TXBAND) && (defined(__CC65__) || defined(__SDCC))
/* 6502 and Z80: the bands the kernel hands to the C version, counted.  This
 * unit compiles src/wire.c itself (so the library's wire.o is not
 * linked) with its r8_tx_band named txb_c; the kernel's hand-off
 * r8_tx_band_c counts and calls it, the reference side calls it
 * directly.  The kernel takes every whole band in order of an RLE
 * stream of 8..241 bytes, those RLE does not shrink (raw) too. */
#define TXB_COUNT
#define TXB_PKT        /* the port has r8_tx_pkt (R8_ASM_TXPKT) */
#undef txb_ref
#define txb_ref txb_c
#define r8_tx_band txb_c
#include "../../src/wire.c"
#undef r8_tx_band
static unsigned handed;
int r8_tx_band_c(r8_tx *tx, const r8_fb *band)
{
    handed++;
    return txb_c(tx, band);
}
#endif

void setUp(void) {}
void tearDown(void) {}

static r8_u32 seed = 4242;
static r8_u8 rnd8(void)
{
    seed = seed * 1103515245ul + 12345ul;
    return (r8_u8)((seed >> 16) & 0xFFu);
}

#define MAXW 300
#define MAXH 20
#define FBB (MAXW * ((MAXH + 7) / 8))
#define SCR (FBB + 200)
#define STR 1400

static r8_u8 frame[FBB], band_buf[MAXW], scr_a[SCR], scr_b[SCR];
static r8_u8 str_a[STR], str_b[STR];
static unsigned len_a, len_b, raw_bands;
static r8_u8 dpkt[R8_DEC_PKT_BYTES(FBB)], dfb[FBB];
static r8_dec dec;

static void cap_a(void *ctx, const r8_u8 *p, unsigned n)
{
    (void)ctx;
    while (n--) {
        if (len_a < STR)
            str_a[len_a] = *p;
        len_a++;
        p++;
    }
}
static void cap_b(void *ctx, const r8_u8 *p, unsigned n)
{
    (void)ctx;
    while (n--) {
        if (len_b < STR)
            str_b[len_b] = *p;
        len_b++;
        p++;
    }
}

/* n bytes of kind k: 0 zeros, 1 zeros and runs, 2 runs and literals,
 * 3 literals without a run of 3 (no zeros: the COBS chain breaks at 254
 * bytes), 4 a few non-zero bytes in zeros, 5 literals then a run (no
 * zeros: compresses a little, the chain may break), 6 literals with a
 * 0x00 every 4th byte (no run: sent raw, its zeros linked) */
static void fill(r8_u8 *p, unsigned n, unsigned k)
{
    unsigned i = 0, j, len;
    r8_u8 v;
    if (k == 5) {
        len = 3u + rnd8() % 20u;
        fill(p, n, 3);
        for (i = len < n ? n - len : 0; i < n; i++)
            p[i] = 0x55;
        return;
    }
    while (i < n) {
        len = 1u + rnd8() % (k == 1 ? 60u : 6u);
        v = rnd8();
        if (k == 0 || (k == 1 && (v & 1u)) || (k == 4 && (v & 7u)))
            v = 0;
        for (j = 0; j < len && i < n; j++, i++) {
            if (k == 3)
                p[i] = (r8_u8)(1u + (i * 37u + rnd8() % 3u) % 255u);
            else if (k == 6)
                p[i] = (r8_u8)((i & 3u) ? 1u + (i * 37u + rnd8() % 3u) % 255u : 0u);
            else
                p[i] = (k == 2 && !(rnd8() & 3u)) ? rnd8() : v;
        }
    }
}

static void same_state(const r8_tx *a, const r8_tx *b)
{
    TEST_ASSERT_EQUAL_HEX16(a->fcrc, b->fcrc);
    TEST_ASSERT_EQUAL_UINT(a->sent, b->sent);
    TEST_ASSERT_EQUAL_INT(a->next_y, b->next_y);
    TEST_ASSERT_EQUAL_UINT(a->next_idx, b->next_idx);
    TEST_ASSERT_TRUE(a->bytes == b->bytes);
    TEST_ASSERT_TRUE(a->raw_bytes == b->raw_bytes);
    TEST_ASSERT_EQUAL_MEMORY(a->fp, b->fp, 4u * a->nbands);
}

static const r8_s16 widths[] = { 8, 16, 40, 128, 255, 256, 300 };

static void run(unsigned cfgno)
{
    r8_tx_cfg c;
    r8_tx ta, tb;
    r8_fb fb;
    unsigned f, i, idx, n, k, good = 0, order[3], nb, lb;
    int ra, rb, d;
#ifdef TXB_COUNT
    unsigned h0, take, hand;
#endif
    c.format = R8_FMT_PAGE1;
    c.width = widths[cfgno % (sizeof widths / sizeof widths[0])];
    c.height = (cfgno & 1u) ? 20 : 16;
    c.band = 8;
    c.codec = (cfgno % 5u == 4u) ? R8_CODEC_RAW : R8_CODEC_RLE;
    c.full_period = (r8_u16)(cfgno % 3u);
    c.dirty = (r8_u8)((cfgno >> 1) & 1u);
    c.palette = 0;
    c.npal = 0;
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_init(&ta, &c, scr_a, sizeof scr_a, cap_a, 0));
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_init(&tb, &c, scr_b, sizeof scr_b, cap_b, 0));
    r8_dec_init(&dec, dpkt, sizeof dpkt, dfb, sizeof dfb, 0, 0);
    nb = ta.nbands;
    for (f = 0; f < 6; f++) {
        len_a = len_b = 0;
        /* some bands keep last frame's content (delta frames skip them) */
        for (i = 0; i < nb; i++) {
            n = ta.band_bytes;
            if (i == nb - 1u && c.height % 8)
                n = (unsigned)c.width; /* the partial band: one page */
            if (f == 0 || (rnd8() & 1u))
                fill(frame + i * ta.band_bytes, n, rnd8() % 7u);
        }
        for (i = 0; i < nb; i++)
            order[i] = i;
        if (f == 5 && nb > 1) { /* out of order: the C version's case
                                  * (and no frame for the decoder) */
            order[0] = 1;
            order[1] = 0;
        }
        r8_tx_sync(&ta);
        r8_tx_sync(&tb);
        TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_frame_begin(&ta, (r8_u16)(500 + f)));
        TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_frame_begin(&tb, (r8_u16)(500 + f)));
        for (i = 0; i < nb; i++) {
            idx = order[i];
            TEST_ASSERT_EQUAL_INT(0, r8_fb_init(&fb, band_buf, R8_FMT_PAGE1, c.width,
                                                c.height, 0, c.band));
            r8_fb_set_band(&fb, (r8_s16)(idx * 8u));
            for (k = 0; k < ta.band_bytes; k++)
                band_buf[k] = frame[idx * ta.band_bytes + k];
            n = ta.band_bytes;
            lb = len_b;
#ifdef TXB_COUNT
            /* taken: in order, whole, RLE, 8..241 bytes; handed: out of
             * order, the partial band, raw codec, over 255 bytes (242..255:
             * either, as RLE pays and the COBS chain holds) */
            take = fb.y0 == ta.next_y && fb.y0 + 8 <= c.height && c.codec == R8_CODEC_RLE &&
                   n >= 8u && n < 242u;
            hand = fb.y0 != ta.next_y || fb.y0 + 8 > c.height || c.codec != R8_CODEC_RLE ||
                   n > 255u;
            h0 = handed;
#endif
            ra = r8_tx_band(&ta, &fb);
            rb = txb_ref(&tb, &fb);
            TEST_ASSERT_EQUAL_INT(rb, ra);
            TEST_ASSERT_EQUAL_INT(R8_OK, ra);
            same_state(&ta, &tb);
            TEST_ASSERT_EQUAL_UINT(len_b, len_a);
            /* a band sent raw in an RLE stream (RLE did not shrink it):
             * header, n bytes, CRC, code and delimiter (no COBS extra) */
            if (c.codec == R8_CODEC_RLE && n < 242u && len_b - lb == n + 10u &&
                fb.y0 + 8 <= c.height)
                raw_bands++;
#ifdef TXB_COUNT
            if (take)
                TEST_ASSERT_EQUAL_UINT(h0, handed);
            if (hand)
                TEST_ASSERT_EQUAL_UINT(h0 + 1u, handed);
#endif
        }
        /* a band the kernel refuses: not in a frame after the end */
        TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_frame_end(&ta));
        TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_frame_end(&tb));
#ifdef TXB_COUNT
        h0 = handed;
#endif
        TEST_ASSERT_EQUAL_INT(R8_E_ARG, r8_tx_band(&ta, &fb));
#ifdef TXB_COUNT
        TEST_ASSERT_EQUAL_UINT(h0 + 1u, handed);
#endif
        TEST_ASSERT_TRUE(len_a <= STR);
        TEST_ASSERT_EQUAL_UINT(len_b, len_a);
        TEST_ASSERT_EQUAL_MEMORY(str_b, str_a, len_a);
        same_state(&ta, &tb);
        /* the model: the stream decodes to the frame */
        for (k = 0; k < len_a && (f < 5 || nb == 1); k++) {
            d = r8_dec_feed(&dec, str_a[k]);
            if (d == R8_DEC_FRAME) {
                good++;
                TEST_ASSERT_EQUAL_UINT(500 + f, dec.frame);
                TEST_ASSERT_EQUAL_MEMORY(frame, dfb, (unsigned)c.width * (((unsigned)c.height + 7u) / 8u));
            }
            TEST_ASSERT_TRUE(d != R8_DEC_BAD && d != R8_DEC_INCOMPLETE);
        }
    }
    TEST_ASSERT_EQUAL_UINT(nb == 1 ? 6 : 5, good);
}

static void test_txband(void)
{
    unsigned i;
    raw_bands = 0;
    for (i = 0; i < 14; i++)
        run(i);
    /* fill() makes bands RLE cannot shrink (kinds 3, 5 and 6) */
    TEST_ASSERT_TRUE(raw_bands >= 30u); /* (39 with this seed) */
}

#ifdef TXB_PKT
/* r8_tx_pkt (the firmware's packet send, R8_ASM_TXPKT) against tx_send
 * (tx, s, n, 1): random bodies of 0..246 bytes, zeros at random places
 * (none to all): the same bytes in one put, the same tx->bytes */
static void test_pkt(void)
{
    r8_tx_cfg c;
    r8_tx ta, tb;
    tx_st s;
    unsigned i, k, n, zr;
    c.format = R8_FMT_PAGE1;
    c.width = 255;
    c.height = 16;
    c.band = 8;
    c.codec = R8_CODEC_RLE;
    c.full_period = 0;
    c.dirty = 0;
    c.palette = 0;
    c.npal = 0;
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_init(&ta, &c, scr_a, sizeof scr_a, cap_a, 0));
    TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_init(&tb, &c, scr_b, sizeof scr_b, cap_b, 0));
    TEST_ASSERT_TRUE(ta.pkt_size >= 251u);
    for (i = 0; i < 300; i++) {
        n = (i < 5) ? i : (unsigned)rnd8() % 247u;
        if (i == 5)
            n = 246;
        zr = 1u + rnd8() % 9u; /* 1: every byte 0; 9: no 0 */
        for (k = 1; k <= n; k++)
            ta.pkt[k] = tb.pkt[k] = (zr < 9u && rnd8() % zr == 0u) ? 0u : (r8_u8)(1u + rnd8() % 255u);
        len_a = len_b = 0;
        ta.bytes = tb.bytes = 1000ul * i;
        r8_tx_pkt(&ta, n);
        tx_send(&tb, &s, n, 1);
        TEST_ASSERT_EQUAL_UINT(n + 4u, len_a);
        TEST_ASSERT_EQUAL_UINT(len_b, len_a);
        TEST_ASSERT_EQUAL_MEMORY(str_b, str_a, len_a);
        TEST_ASSERT_TRUE(ta.bytes == tb.bytes);
    }
}
#endif

#ifdef R8_ASM_TXBAND
extern const r8_u8 r8_txband_offs[];
/* the kernel's offsets of r8_tx and r8_fb are the compiler's */
static void test_offsets(void)
{
    static const r8_u8 want[] = {
        offsetof(r8_tx, cfg.format), offsetof(r8_tx, cfg.width), offsetof(r8_tx, cfg.height),
        offsetof(r8_tx, cfg.band), offsetof(r8_tx, cfg.codec), offsetof(r8_tx, put),
        offsetof(r8_tx, ctx), offsetof(r8_tx, pkt), offsetof(r8_tx, fp),
        offsetof(r8_tx, band_bytes), offsetof(r8_tx, xn), offsetof(r8_tx, next_y),
        offsetof(r8_tx, next_idx), offsetof(r8_tx, frame), offsetof(r8_tx, sent),
        offsetof(r8_tx, fcrc), offsetof(r8_tx, hcrc), offsetof(r8_tx, full),
        offsetof(r8_tx, in_frame), offsetof(r8_tx, bytes), offsetof(r8_tx, raw_bytes),
        offsetof(r8_fb, buf), offsetof(r8_fb, width), offsetof(r8_fb, y0),
        offsetof(r8_fb, format)
    };
    TEST_ASSERT_EQUAL_MEMORY(want, r8_txband_offs, sizeof want);
}
#endif

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_txband);
#ifdef TXB_PKT
    RUN_TEST(test_pkt);
#endif
#ifdef R8_ASM_TXBAND
    RUN_TEST(test_offsets);
#endif
    return UNITY_END();
}
