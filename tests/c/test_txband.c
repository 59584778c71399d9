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

#ifdef R8_ASM_TXBAND
/* src/wire.c compiled here (so the library's wire object is not linked)
 * with its C r8_tx_band named ref_band; the r8_tx_band_c below, to which
 * the kernel hands the bands it does not take, counts them */
#define r8_tx_band_c ref_band
#include "../../src/wire.c"
#undef r8_tx_band_c
#undef r8_tx_band
static unsigned handed;
int r8_tx_band_c(r8_tx *tx, const r8_fb *band)
{
    handed++;
    return ref_band(tx, band);
}
/* 1: the port's kernel sends a band raw when its RLE does not pay (the
 * Z80's); 0: it hands such a band on */
#ifdef __SDCC
#define TXBAND_RAW 1
#else
#define TXBAND_RAW 0
#endif
#else
#define ref_band r8_tx_band
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
static unsigned len_a, len_b;
static r8_u8 dpkt[R8_DEC_PKT_BYTES(FBB)], dfb[FBB];
static r8_dec dec;
#ifdef R8_ASM_TXBAND
static r8_u8 rle_buf[MAXW];
static unsigned raw_taken; /* bands the kernel took and sent raw */
#endif

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
 * zeros: compresses a little, the chain may break), 6 literals with
 * zeros, 0..4 of them leading, no run of 3 after them (RLE pays for 4
 * leading zeros only: the raw path's zeros) */
static void fill(r8_u8 *p, unsigned n, unsigned k)
{
    unsigned i = 0, j, len;
    r8_u8 v;
    if (k == 6) {
        len = rnd8() % 5u;
        j = rnd8() % 4u;
        fill(p, n, 3);
        for (i = 0; i < n; i++)
            if (i < len || i % 4u == j)
                p[i] = 0;
        return;
    }
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
    unsigned f, i, idx, n, k, good = 0, order[3], nb;
#ifdef R8_ASM_TXBAND
    unsigned h0, raw, must;
#endif
    int ra, rb, d;
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
#ifdef R8_ASM_TXBAND
            /* the kernel takes every band that comes in order, whole,
             * codec RLE, in a packet (n + 6 + 2 bytes) under 250 bytes
             * (unless, !TXBAND_RAW, its RLE does not pay): it hands on
             * only bands out of order, a partial last one, codec raw,
             * longer ones (and bands out of a frame, below) */
            n = ta.band_bytes;
            raw = r8_rle_encode(band_buf, n, rle_buf, n - 1u, &k) != R8_OK;
            must = (r8_s16)(idx * 8u) == ta.next_y && !(idx == nb - 1u && c.height % 8) &&
                   c.codec == R8_CODEC_RLE && n + 8u < 250u && (TXBAND_RAW || !raw);
            h0 = handed;
#endif
            ra = r8_tx_band(&ta, &fb);
            rb = ref_band(&tb, &fb);
#ifdef R8_ASM_TXBAND
            if (must) {
                TEST_ASSERT_EQUAL_UINT(h0, handed);
                raw_taken += raw;
            }
#endif
            TEST_ASSERT_EQUAL_INT(rb, ra);
            TEST_ASSERT_EQUAL_INT(R8_OK, ra);
            same_state(&ta, &tb);
            TEST_ASSERT_EQUAL_UINT(len_b, len_a);
        }
        /* a band the kernel refuses: not in a frame after the end */
        TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_frame_end(&ta));
        TEST_ASSERT_EQUAL_INT(R8_OK, r8_tx_frame_end(&tb));
#ifdef R8_ASM_TXBAND
        h0 = handed;
#endif
        TEST_ASSERT_EQUAL_INT(R8_E_ARG, r8_tx_band(&ta, &fb));
#ifdef R8_ASM_TXBAND
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
    for (i = 0; i < 14; i++)
        run(i);
#ifdef R8_ASM_TXBAND
    if (TXBAND_RAW) /* the kernel sent some raw (22 with this seed) */
        TEST_ASSERT_TRUE(raw_taken >= 10u);
#endif
}

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
#ifdef R8_ASM_TXBAND
    RUN_TEST(test_offsets);
#endif
    return UNITY_END();
}
