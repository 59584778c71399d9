/* wire.c - the frame encoder (firmware side) of the display protocol,
 * see r8wire.h and docs/protocol.md.
 *
 * Memory: one packet scratch (a band's raw size plus header and CRC, and
 * a byte before and after it) and 4 bytes per band for the dirty-band
 * fingerprints.  A packet's body is built at pkt + 1, COBS-encoded in
 * place (pkt[0] takes the first code byte, each 0x00 the code of the
 * block after it) and handed to put in one call, delimiter included.
 *
 * Speed: with RLE (tx_rle) each band is walked once.  The walk writes
 * the payload (the bytes r8_rle_encode gives) into the packet, feeds the
 * packet CRC with it and links its zeros into the COBS chain.  The CRC
 * of the raw band (from 0) is derived from the packet CRC at each
 * literal run and shifted over each zero run (src/r8crc.h), and the
 * frame CRC takes it with one multiply, so runs of zeros cost no CRC
 * work per byte; they are scanned 4 bytes at a time.
 *
 * Fingerprint of a band: its CRC-16 from 0 (r8_crc16_update(0, ...))
 * and its Fletcher-16.  (The CRC from 0xFFFF differs from it by a
 * constant for a given band size, so the bands sent are the same.)
 *
 * Codecs left out: -DR8_NO_RLE, -DR8_NO_LZ77, -DR8_NO_HUFF, -DR8_NO_LZW
 * (the config is then rejected with R8_E_ARG; raw is always built in).
 * Huffman, LZW and the per-band choice (R8_CODEC_BEST) go through the
 * codec dispatch (tx_more); the target firmwares build this file
 * without them (mk/targets.mk), so their code is unchanged. */
#include "r8crc.h"
#include "r8config.h" /* the Arduino preset: R8_NO_HUFF, R8_NO_LZW (and R8_NO_LZ77) */

/* The hot loops are kept out of line: each then has the registers to
 * itself (avr-gcc spills the pointers otherwise).  `register` on the
 * hot pointers: cc65 (-Or) keeps them in zero page (its 6-byte register
 * bank), where p->field is one indexed load instead of a runtime call;
 * the other compilers allocate registers as they would anyway. */
#if defined(__GNUC__)
#define TX_NOINLINE __attribute__((noinline))
#else
#define TX_NOINLINE
#endif

static const r8_u8 delim = 0;

/* A firmware whose stream is fixed at compile time (the demo firmware,
 * examples/spin/fw_app.c: R8_TXCFG_FORMAT with _WIDTH, _HEIGHT, _BAND,
 * _CODEC, _FULL, _DIRTY, _NPAL): cfg_ok takes that configuration only
 * (r8_tx_init stores no other), and the sizes, the FRAME_START packet
 * and the band checks fold to constants.  Without it (the library) every
 * field is read. */
#ifdef R8_TXCFG_FORMAT
#define TXC_FORMAT(c) R8_TXCFG_FORMAT
#define TXC_WIDTH(c) R8_TXCFG_WIDTH
#define TXC_HEIGHT(c) R8_TXCFG_HEIGHT
#define TXC_BAND(c) R8_TXCFG_BAND
#define TXC_CODEC(c) R8_TXCFG_CODEC
#define TXC_FULL_PERIOD(c) R8_TXCFG_FULL
#define TXC_DIRTY(c) R8_TXCFG_DIRTY
#define TXC_NPAL(c) R8_TXCFG_NPAL
#else
#define TXC_FORMAT(c) ((c)->format)
#define TXC_WIDTH(c) ((c)->width)
#define TXC_HEIGHT(c) ((c)->height)
#define TXC_BAND(c) ((c)->band)
#define TXC_CODEC(c) ((c)->codec)
#define TXC_FULL_PERIOD(c) ((c)->full_period)
#define TXC_DIRTY(c) ((c)->dirty)
#define TXC_NPAL(c) ((c)->npal)
#endif
/* 1: a last band may be shorter than the others (0: the height is fixed
 * to a multiple of the band; not an #if: cc65 evaluates those even where
 * the macros are not defined) */
#ifdef R8_TXCFG_HEIGHT
#define TX_PARTIAL (R8_TXCFG_HEIGHT % R8_TXCFG_BAND != 0)
#else
#define TX_PARTIAL 1
#endif

/* 1: every packet of the fixed stream is under 250 bytes (COBS code
 * byte, body, CRC), so no 0x00 is ever more than 254 bytes after the
 * code before it: the COBS chain never stops (tx_link1's test, tx_send's
 * r8_cobs_write and r8_tx_lit's too-long flag never happen) and those
 * paths fold away (the demo firmware: 128 x 8 bands, 137-byte packets). */
#define TX_SHORT 0
#ifdef R8_TXCFG_FORMAT
#if R8_TXCFG_FORMAT == R8_FMT_PAGE1 && R8_TXCFG_NPAL < 64 && \
    (R8_TXCFG_BAND + 7) / 8 * R8_TXCFG_WIDTH + R8_WIRE_BAND_HDR + R8_WIRE_CRC_BYTES < 250
#undef TX_SHORT
#define TX_SHORT 1
#endif
#endif

/* R8_TXBAND_ALL (a port's firmware flag, with R8_ASM_TXBAND and a fixed
 * stream): the port's r8_tx_band takes every valid band of that stream
 * that comes in order, those whose RLE does not pay (sent raw) too.
 * What it hands to r8_tx_band_c is then a band out of order, which the
 * relay at the end of this file makes the expected one and hands back,
 * or a bad one (R8_E_ARG): tx_band and tx_rle, the C band path, leave
 * the firmware. */
#define TX_ASM_ALL 0
#if defined(R8_TXBAND_ALL) && defined(R8_ASM_TXBAND) && defined(R8_TXCFG_FORMAT)
#if !TX_SHORT || R8_TXCFG_CODEC != R8_CODEC_RLE || TX_PARTIAL || \
    (R8_TXCFG_BAND + 7) / 8 * R8_TXCFG_WIDTH < 8
#error "R8_TXBAND_ALL: the port's r8_tx_band takes RLE streams of whole bands of 8..249 bytes only"
#endif
#undef TX_ASM_ALL
#define TX_ASM_ALL 1
#endif

/* R8_ASM_TXPKT (a port's firmware flag, with R8_TXBAND_ALL): the port's
 * r8_tx_pkt (src/r8crc.h) sends the packets tx_send is then left with,
 * FRAME_START and FRAME_END (all = 1, under 250 bytes: TX_SHORT), so
 * tx_send's C leaves the firmware too. */
#define TX_PKT_ASM 0
#if TX_ASM_ALL && defined(R8_ASM_TXPKT)
#undef TX_PKT_ASM
#define TX_PKT_ASM 1
#endif

typedef r8_tx_st tx_st;

/* big-endian 16 bits; PUT16 in line on the per-band paths (v is read
 * twice: no side effects) */
#define PUT16(p, v) ((p)[0] = (r8_u8)((unsigned)(v) >> 8), (p)[1] = (r8_u8)((unsigned)(v) & 0xFFu))

static void put16(r8_u8 *p, unsigned v)
{
    p[0] = (r8_u8)((v >> 8) & 0xFFu);
    p[1] = (r8_u8)(v & 0xFFu);
}

static void out(register r8_tx *tx, const r8_u8 *p, unsigned n)
{
    tx->put(tx->ctx, p, n);
    tx->bytes += n;
}

#if !TX_PKT_ASM
static void count_put(void *ctx, const r8_u8 *p, unsigned n)
{
    out((r8_tx *)ctx, p, n);
}

/* Put back the zeros linked so far: the chain stops (s->code = 0). */
static void tx_unlink(tx_st *s)
{
    r8_u8 *q = s->pkt, *c = s->code, d;
    if (c)
        while (q != c) {
            d = *q;
            *q = 0;
            q += d;
        }
    s->code = 0;
}
#endif

#if !defined(R8_NO_RLE) || !defined(R8_ASM_WIRE)
/* Link the 0x00 at q, after every zero linked so far: it takes the
 * place of a code, and the code before it gets the distance.  Returns 1
 * (nothing done) when that is more than 254: a block of 254 non-zero
 * bytes needs an extra code byte, which does not fit in place. */
static r8_u8 tx_link1(tx_st *s, r8_u8 *q)
{
    r8_u8 *c = s->code;
    if (!c)
        return 0;
    if (q - c > 254)
        return 1;
    *c = (r8_u8)(q - c);
    s->code = q;
    return 0;
}
#endif

#if !TX_PKT_ASM
/* tx_link on the hot paths: inline in the AVR build (where the band
 * walk's glue is the cost), a call elsewhere (where code size is). */
#ifdef R8_ASM_WIRE
#define TX_LINK(s, q)                                          \
    do {                                                       \
        r8_u8 *c_ = (s)->code; /* once (cc65: one load) */     \
        if (c_) {                                              \
            if (!TX_SHORT && (unsigned)((q) - c_) > 254u) {        \
                tx_unlink(s);                                  \
            } else {                                           \
                *c_ = (r8_u8)((q) - c_);                       \
                (s)->code = (q);                               \
            }                                                  \
        }                                                      \
    } while (0)
#else
/* Link the 0x00 at q; if that cannot be, the chain stops and tx_send
 * streams the packet instead. */
static void tx_link(tx_st *s, r8_u8 *q)
{
    if (tx_link1(s, q))
        tx_unlink(s);
}
#define TX_LINK(s, q) tx_link(s, q)
#endif

/* Link the zeros of q .. end. */
static void tx_links(register tx_st *s, register r8_u8 *q, const r8_u8 *end)
{
    for (; q != end; q++)
        if (!*q)
            TX_LINK(s, q);
}

/* Send the packet whose body is pkt[1 .. 1+n): if `all`, it is not
 * linked yet and its CRC is to be computed (s is set up here); else it
 * is linked and its CRC is s->crc.  Then: the CRC bytes, the last code,
 * the delimiter, one put; or, if the chain stopped, r8_cobs_write. */
static void tx_send(register r8_tx *tx, register tx_st *s, unsigned n, r8_u8 all)
{
    r8_u8 *p = tx->pkt, *end = p + n + 3;
    if (all) {
        s->pkt = s->code = p;
        s->crc = r8_crc16(p + 1, n);
        tx_links(s, p + 1, end - 2);
    }
    PUT16(end - 2, s->crc);
    if (!end[-2])
        TX_LINK(s, end - 2);
    if (!end[-1])
        TX_LINK(s, end - 1);
    if (!TX_SHORT && s->code && end - s->code > 255)
        tx_unlink(s);
    if (TX_SHORT || s->code) {
        *s->code = (r8_u8)(end - s->code);
        *end = 0;
        out(tx, p, n + 4);
    } else {
        r8_cobs_write(p + 1, n + 2, count_put, tx);
        out(tx, &delim, 1);
    }
}
#else
/* (s: the caller's, unused; all = 1: the band path is the port's) */
#define tx_send(tx, s, n, all) ((void)(s), (void)(all), r8_tx_pkt(tx, n))
#endif /* !TX_PKT_ASM */

#if !defined(R8_NO_HUFF) || !defined(R8_NO_LZW)
#define TX_MORE
/* Encode band src[0..n) (n >= 1) into the BAND body b's payload with the
 * codec b[5] (HUFF, LZW), or with BEST the codec of the smallest payload
 * (ties to the lower id: the cheaper decoder), storing it in b[5].
 * Returns 1, the length in *len, if the payload is smaller than n. */
static int tx_more(r8_u8 *b, const r8_u8 *src, unsigned n, unsigned *len)
{
    r8_u8 k, best = R8_CODEC_RAW;
    unsigned cap = n - 1u, l;
    r8_u8 *dst = b + R8_WIRE_BAND_HDR;
    if (b[5] != R8_CODEC_BEST)
        return r8_codec_encode(b[5], src, n, dst, cap, len) == R8_OK;
    for (k = R8_CODEC_RLE; k < R8_CODEC_COUNT; k++)
        if (r8_codec_encode(k, src, n, dst, cap, &l) == R8_OK) {
            best = k;
            *len = l;
            if (!l) /* (n >= 1: never) */
                break;
            cap = l - 1u;
        }
    if (best == R8_CODEC_RAW)
        return 0;
    b[5] = best;
    /* the codecs tried after it may have written over its payload */
    if (best != R8_CODEC_COUNT - 1)
        r8_codec_encode(best, src, n, dst, *len, len);
    return 1;
}
#endif

static int cfg_ok(const r8_tx_cfg *cfg)
{
#ifdef R8_TXCFG_FORMAT
    if (cfg->format != R8_TXCFG_FORMAT || cfg->width != R8_TXCFG_WIDTH ||
        cfg->height != R8_TXCFG_HEIGHT || cfg->band != R8_TXCFG_BAND ||
        cfg->codec != R8_TXCFG_CODEC || cfg->full_period != R8_TXCFG_FULL ||
        cfg->dirty != R8_TXCFG_DIRTY || cfg->npal != R8_TXCFG_NPAL)
        return 0;      /* the one stream this firmware is built for */
#endif
#ifdef TX_MORE
    if (TXC_FORMAT(cfg) > R8_FMT_IDX8 ||
        (TXC_CODEC(cfg) >= R8_CODEC_COUNT && TXC_CODEC(cfg) != R8_CODEC_BEST))
        return 0;
#ifdef R8_NO_HUFF
    if (TXC_CODEC(cfg) == R8_CODEC_HUFF)
        return 0;
#endif
#ifdef R8_NO_LZW
    if (TXC_CODEC(cfg) == R8_CODEC_LZW)
        return 0;
#endif
#else
    if (TXC_FORMAT(cfg) > R8_FMT_IDX8 || TXC_CODEC(cfg) > R8_CODEC_LZ77)
        return 0;
#endif
#ifdef R8_NO_RLE
    if (TXC_CODEC(cfg) == R8_CODEC_RLE)
        return 0;
#endif
#ifdef R8_NO_LZ77
    if (TXC_CODEC(cfg) == R8_CODEC_LZ77)
        return 0;
#endif
    if (TXC_WIDTH(cfg) <= 0 || TXC_HEIGHT(cfg) <= 0 || TXC_BAND(cfg) <= 0 ||
        TXC_WIDTH(cfg) > R8_WIRE_MAX_DIM || TXC_HEIGHT(cfg) > R8_WIRE_MAX_DIM ||
        TXC_BAND(cfg) > TXC_HEIGHT(cfg))
        return 0;
    if (TXC_FORMAT(cfg) == R8_FMT_PAGE1 && (TXC_BAND(cfg) & 7))
        return 0;
    if (TXC_NPAL(cfg) && !cfg->palette)
        return 0;
    return 1;
}

unsigned r8_tx_band_bytes(const r8_tx_cfg *cfg)
{
    unsigned b, w;
    if (!cfg_ok(cfg))
        return 0;
    b = (unsigned)TXC_BAND(cfg);   /* both <= R8_WIRE_MAX_DIM */
    w = (unsigned)TXC_WIDTH(cfg);
    if (TXC_FORMAT(cfg) == R8_FMT_PAGE1)
        b = (b + 7u) >> 3;
    if (TXC_FORMAT(cfg) == R8_FMT_ROW1)
        w = (w + 7u) >> 3;
    /* b * w may exceed an unsigned on 16-bit targets */
    if (b > R8_WIRE_MAX_BAND / w)
        return 0;
    return b * w;
}

/* The packet scratch (R8_WIRE_PKT_BYTES + 2) for band bytes bb; 0 if
 * cfg is invalid.  (Computed here with an if: the macro's form, which
 * constant expressions need, costs a multiply on the 8-bit targets.) */
static unsigned tx_pkt_bytes(const r8_tx_cfg *cfg, unsigned bb)
{
    unsigned p = 3u * (unsigned)TXC_NPAL(cfg) + R8_WIRE_START_BYTES;
    (void)cfg;         /* (a fixed stream: no field read) */
    if (!bb)
        return 0;
    if (bb + R8_WIRE_BAND_HDR > p)
        p = bb + R8_WIRE_BAND_HDR;
    return p + R8_WIRE_CRC_BYTES + 2u;
}

unsigned r8_tx_scratch(const r8_tx_cfg *cfg)
{
    unsigned p = tx_pkt_bytes(cfg, r8_tx_band_bytes(cfg));
    if (!p)
        return 0;
    return p + 4u * R8_WIRE_NBANDS(TXC_HEIGHT(cfg), TXC_BAND(cfg));
}

int r8_tx_init(r8_tx *tx, const r8_tx_cfg *cfg, r8_u8 *scratch,
               unsigned scratch_size, r8_put_fn put, void *ctx)
{
    unsigned need = r8_tx_scratch(cfg), k;
    r8_u8 *q = (r8_u8 *)tx;
    if (!need || !put)
        return R8_E_ARG;
    if (scratch_size < need)
        return R8_E_SPACE;
    for (k = sizeof *tx; k; k--) /* every counter and flag 0 */
        *q++ = 0;
    tx->cfg = *cfg;
    tx->put = put;
    tx->ctx = ctx;
    tx->band_bytes = r8_tx_band_bytes(cfg);
    tx->nbands = R8_WIRE_NBANDS(TXC_HEIGHT(cfg), TXC_BAND(cfg));
    tx->pkt_size = tx_pkt_bytes(cfg, tx->band_bytes);
    tx->pkt = scratch;
    tx->fp = scratch + tx->pkt_size;
    for (k = 0; k < 4u * tx->nbands; k++)
        tx->fp[k] = 0;
    tx->xn = r8_crc16_xpow(tx->band_bytes);
    tx->fcrc = (r8_u16)R8_CRC16_INIT;
    tx->want_full = 1;
    return R8_OK;
}

void r8_tx_sync(r8_tx *tx)
{
    out(tx, &delim, 1);
}

void r8_tx_request_full(r8_tx *tx)
{
    tx->want_full = 1;
}

int r8_tx_rx(r8_tx *tx, r8_u8 c)
{
    r8_u8 *b = tx->rx;
    unsigned n, i;
    if (c != 0) {
        if (tx->rx_len < sizeof tx->rx)
            tx->rx[tx->rx_len] = c;
        if (tx->rx_len < 255u)
            tx->rx_len++;
        return 0;
    }
    n = tx->rx_len;
    tx->rx_len = 0;
    if (n > sizeof tx->rx || n < 2u + R8_WIRE_CRC_BYTES)
        return 0;
    /* COBS, decoded in place (what r8_cobs_decode gives for packets this
     * short: no 0xFF block fits in 8 bytes, and no stored byte is 0x00):
     * each code byte after the first stands for a 0x00; the chain of
     * codes must end at the packet's end.  The body is then b[1..n). */
    for (i = 0; i < n; i += c) {
        c = b[i];
        b[i] = 0;
    }
    if (i != n)
        return 0;
    b++;
    n--;
    if (r8_crc16(b, n - R8_WIRE_CRC_BYTES) !=
            (((unsigned)b[n - 2u] << 8) | b[n - 1u]))
        return 0;
    n -= R8_WIRE_CRC_BYTES;
    if (b[0] == R8_PKT_REQUEST && n == 1u) {
        tx->want_full = 1;
        return R8_RX_REQUEST;
    }
    if (b[0] == R8_PKT_INPUT && n == 3u) {
        tx->keys = (r8_u16)(((unsigned)b[1] << 8) | b[2]);
        tx->inputs++;
        return R8_RX_INPUT;
    }
    return 0; /* unknown kind or length: ignored */
}

int r8_tx_frame_begin(r8_tx *tx, r8_u16 frame)
{
    r8_u8 *p = tx->pkt + 1;
#if !defined(R8_TXCFG_NPAL) || R8_TXCFG_NPAL > 0
    unsigned k;
#endif
    tx_st s;
    if (tx->in_frame)
        return R8_E_ARG;
    if (TXC_FULL_PERIOD(&tx->cfg) && tx->since_full >= TXC_FULL_PERIOD(&tx->cfg))
        tx->want_full = 1;
    tx->full = (r8_u8)(tx->want_full || !TXC_DIRTY(&tx->cfg));
    if (tx->full) {
        tx->want_full = 0;
        tx->since_full = 0;
    }
    tx->since_full++;
    tx->frame = frame;
    tx->sent = 0;
    tx->fcrc = (r8_u16)R8_CRC16_INIT;
    tx->next_y = 0;
    tx->next_idx = 0;
    tx->in_frame = 1;
    p[0] = R8_PKT_FRAME_START;
#ifdef R8_WIRE_CRC32
    tx->fcrc32 = 0;
    p[1] = R8_WIRE_VERSION2;
#else
    p[1] = R8_WIRE_VERSION;
#endif
    put16(p + 2, frame);
    /* the CRC of the first 3 bytes of this frame's BAND packets:
     * R8_PKT_BAND (0xC1B2 from 0xFFFF) and the frame number */
    tx->hcrc = r8_crc16_update(0xC1B2u, p + 2, 2);
    put16(p + 4, (unsigned)TXC_WIDTH(&tx->cfg));
    put16(p + 6, (unsigned)TXC_HEIGHT(&tx->cfg));
    p[8] = TXC_FORMAT(&tx->cfg);
    put16(p + 9, (unsigned)TXC_BAND(&tx->cfg));
    p[11] = TXC_CODEC(&tx->cfg);
#ifdef TX_MORE
    if (p[11] == R8_CODEC_BEST)
        p[11] = R8_CODEC_RAW; /* no one codec: each BAND says its own */
#endif
    p[12] = (r8_u8)(tx->full ? R8_FLAG_FULL : 0);
    p[13] = TXC_NPAL(&tx->cfg);
#if !defined(R8_TXCFG_NPAL) || R8_TXCFG_NPAL > 0
    for (k = 0; k < 3u * TXC_NPAL(&tx->cfg); k++)
        p[R8_WIRE_START_BYTES + k] = tx->cfg.palette[k];
#endif
    tx_send(tx, &s, R8_WIRE_START_BYTES + 3u * TXC_NPAL(&tx->cfg), 1);
    return R8_OK;
}

/* Fletcher-16 sums of p[0..n) on from s->f1, s->f2. */
static void tx_fletcher(tx_st *s, const r8_u8 *p, unsigned n)
{
    r8_u8 f1 = s->f1, f2 = s->f2;
    while (n--) {
        f1 = (r8_u8)(f1 + *p++);
        f2 = (r8_u8)(f2 + f1);
    }
    s->f1 = f1;
    s->f2 = f2;
}

#ifndef R8_NO_RLE
r8_u8 r8_tx_run_c(r8_tx_st *s, r8_u8 *o, const r8_u8 *p, r8_u8 k)
{
    r8_u8 v = *p, c = 3;
    while (c < k && p[c] == v)
        c++;
    o[0] = c;
    o[1] = v;
    s->crc = r8_crc16_update(s->crc, o, 2);
    if (v) {
        s->g = r8_crc16_update(s->g, p, c);
        tx_fletcher(s, p, c);
    } else {
        s->g = r8_crc16_shift(s->g, c);
        s->f2 = (r8_u8)(s->f2 + (r8_u8)(c * s->f1));
    }
    return c;
}

r8_u8 r8_tx_lit_c(r8_tx_st *s, r8_u8 *o, const r8_u8 *p, r8_u8 k, r8_u8 c)
{
    r8_u8 i, v, ph, pl, stop = 0;
    r8_u16 pb;
    for (i = 0; i < k; i++)
        if (p[i + 1] == p[i] && p[i + 2] == p[i]) {
            c = i;
            break;
        }
    *o = (r8_u8)(0x80u | c);
    s->crc = pb = r8_crc16_update(s->crc, o, 1);
    ph = (r8_u8)(pb >> 8);
    pl = (r8_u8)(pb & 0xFFu);
    for (i = 0; i < c; i++) {
        v = p[i];
        *++o = v;
        R8_CRC16_STEP(ph, pl, v);
        if (!v && !stop)
            stop = tx_link1(s, o);
    }
    s->crc = (r8_u16)(((r8_u16)ph << 8) | pl);
    tx_fletcher(s, p, c);
    /* the band's CRC: g * x^(8c) ^ crc(0, literals), where crc(0,
     * literals) = the packet CRC after them ^ the one before them *
     * x^(8c) */
    s->g = (r8_u16)(r8_crc16_shift((r8_u16)(s->g ^ pb), c) ^ s->crc);
    return (r8_u8)(c | (stop << 7));
}

#if !TX_ASM_ALL
/* RLE-encode the band p[0..n) into o (the bytes r8_rle_encode gives, see
 * r8codec.h), at most cap bytes: the payload goes on s's packet CRC and
 * COBS chain, s gets the band's CRC from 0 and Fletcher sums.  Returns
 * the payload length, or cap + 1 when it does not fit (nothing is
 * written past o + cap). */
static unsigned tx_rle(register tx_st *s, register const r8_u8 *p, unsigned n, register r8_u8 *o,
                       unsigned cap, unsigned z)
{
    const r8_u8 *end = p + n;
    r8_u8 *o0 = o;
    unsigned room = cap, left;
    r8_u8 c, k, full;
    s->f1 = s->f2 = 0;
    s->g = 0;
    /* the z leading zeros: runs of up to 127 (a band's CRC from 0 and its
     * Fletcher sums stay 0); fewer than 3 left join the next token */
    while (z >= 3u) {
        c = R8_RLE_MAX;
        if (z < R8_RLE_MAX)
            c = (r8_u8)z;
        if (room < 2u)
            return cap + 1u;
        room -= 2u;
        o[0] = c;
        o[1] = 0;
        s->crc = r8_crc16_update(s->crc, o, 2);
        TX_LINK(s, o + 1);
        o += 2;
        p += c;
        z -= c;
    }
    while (p != end) {
        left = (unsigned)(end - p);
        c = R8_RLE_MAX; /* the most bytes a token takes */
        if (left < R8_RLE_MAX)
            c = (r8_u8)left;
        if (c >= 3u && p[1] == *p && p[2] == *p) {
            /* a run of 3..c equal bytes */
            if (room < 2u)
                return cap + 1u;
            room -= 2u;
            c = r8_tx_run(s, o, p, c);
            if (!o[1])
                TX_LINK(s, o + 1);
            o += 2;
        } else {
            /* literals; k: the positions a run of 3 may start at */
            k = R8_RLE_MAX;
            if (left < R8_RLE_MAX + 2u)
                k = (r8_u8)(left >= 2u ? left - 2u : 0u);
            full = 0;
            if (room <= c) {
                /* at most room - 1 literals fit: if that many come, more
                 * come after them (or a run, which does not fit either) */
                if (room < 2u)
                    return cap + 1u;
                c = (r8_u8)(room - 1u);
                if (k > c)
                    k = c;
                full = c;
            }
            c = r8_tx_lit(s, o, p, k, c);
            if (!TX_SHORT && (c & 0x80u)) {   /* (TX_SHORT: never set) */
                c &= 0x7Fu;
                tx_unlink(s);
            }
            if (c == full)
                return cap + 1u;
            room -= c + 1u;
            o += c + 1u;
        }
        p += c;
    }
    return (unsigned)(o - o0);
}
#endif
#endif /* !TX_ASM_ALL */

unsigned r8_tx_zeros_c(const r8_u8 *p, unsigned n)
{
    const r8_u8 *q = p, *end = p + n;
    while (q != end && !*q)
        q++;
    return (unsigned)(q - p);
}

#if !TX_ASM_ALL
/* Encode and send band src[0..n) at row y0: the packet, the fingerprint
 * fp[4] (changed: whether it did) and the frame CRC; z = its leading
 * zeros. */
static void TX_NOINLINE tx_band(register r8_tx *tx, const r8_u8 *src, unsigned n,
                                unsigned y0, register r8_u8 *fp, r8_u16 xn, unsigned z)
{
    register r8_u8 *b = tx->pkt + 1;
    r8_u8 *from = b, changed, f[4];
    unsigned len = n, k;
    tx_st s;
    /* header; the CRC of bytes 0..2 is tx->hcrc */
    b[0] = R8_PKT_BAND;
    PUT16(b + 1, tx->frame);
    PUT16(b + 3, y0);
    b[5] = TXC_CODEC(&tx->cfg);
#ifndef R8_NO_RLE
    if (TXC_CODEC(&tx->cfg) == R8_CODEC_RLE) {   /* (R8_TXCFG_CODEC: folded) */
        s.pkt = s.code = tx->pkt;
        s.crc = r8_crc16_update(tx->hcrc, b + 3, 3);
        /* header zeros (no code is more than 5 bytes back) */
        for (from = b + 1; from != b + 5; from++)
            if (!*from) {
                *s.code = (r8_u8)(from - s.code);
                s.code = from;
            }
        from = b + R8_WIRE_BAND_HDR;
        len = tx_rle(&s, src, n, from, n - 1u, z);
        from += len;
        if (len >= n) {
            tx_unlink(&s);
            from = b;
        }
    }
    if (from == b)
#endif
    {
        /* the fingerprint (leading zeros change it not) */
        s.f1 = s.f2 = 0;
        s.g = r8_crc16_update(0, src + z, n - z);
        tx_fletcher(&s, src + z, n - z);
    }
    if (z != n) { /* (a band of zeros is done by the caller) */
        f[0] = (r8_u8)(s.g >> 8);
        f[1] = (r8_u8)(s.g & 0xFFu);
        f[2] = s.f1;
        f[3] = s.f2;
        changed = (r8_u8)((fp[0] ^ f[0]) | (fp[1] ^ f[1]) | (fp[2] ^ f[2]) | (fp[3] ^ f[3]));
        fp[0] = f[0];
        fp[1] = f[1];
        fp[2] = f[2];
        fp[3] = f[3];
        /* frame CRC: fcrc * x^(8n) ^ the band's CRC from 0 */
        tx->fcrc = (r8_u16)(r8_crc16_mul(tx->fcrc, xn) ^ s.g);
        if (!tx->full && !changed)
            return;
    }
#ifndef R8_NO_RLE
    if (from == b)
#endif
#ifndef R8_NO_LZ77
    if (b[5] != R8_CODEC_LZ77 ||
        r8_lz77_encode(src, n, b + R8_WIRE_BAND_HDR, n - 1u, &len) != R8_OK)
#endif
#ifdef TX_MORE
    if (b[5] <= R8_CODEC_LZ77 || !tx_more(b, src, n, &len))
#endif
    {
        /* raw: the codec is raw, or would not make the band smaller */
        b[5] = R8_CODEC_RAW;
        len = n;
        for (k = 0; k < n; k++)
            b[R8_WIRE_BAND_HDR + k] = src[k];
    }
    tx_send(tx, &s, R8_WIRE_BAND_HDR + len, (r8_u8)(from == b));
    tx->sent++;
}

#endif /* !TX_ASM_ALL */

#if TX_ASM_ALL
/* What the port's r8_tx_band hands on (R8_TXBAND_ALL, above): a band of
 * the frame out of order becomes the expected one, as r8_tx_band below
 * finds its index, and goes back; any other is bad (one the kernel takes
 * it never hands on: R8_E_ARG, never a loop). */
int r8_tx_band_c(register r8_tx *tx, const r8_fb *band)
{
    r8_s16 y0 = band->y0;
    if (!tx->in_frame || y0 < 0 || y0 >= R8_TXCFG_HEIGHT || y0 == tx->next_y ||
        (unsigned)y0 % R8_TXCFG_BAND != 0 || band->width != R8_TXCFG_WIDTH ||
        band->format != R8_TXCFG_FORMAT)
        return R8_E_ARG;
    tx->next_y = y0;
    tx->next_idx = (unsigned)y0 / R8_TXCFG_BAND;
    return r8_tx_band(tx, band);
}
#else
#if defined(R8_ASM_TXBAND) && !defined(r8_tx_band)
/* a port's r8_tx_band (6502: ports/6502/txband_6502.s) hands the bands
 * it does not take to this one, the reference (r8crc.h; a test that
 * compiles this file under other names keeps them) */
#define r8_tx_band r8_tx_band_c
#endif
int r8_tx_band(register r8_tx *tx, const r8_fb *band)
{
    unsigned idx, n, z;
    r8_s16 y0 = band->y0;
    r8_u8 *fp, changed;
    r8_u16 xn;
    if (!tx->in_frame || y0 < 0 || y0 >= TXC_HEIGHT(&tx->cfg) ||
        band->width != TXC_WIDTH(&tx->cfg) || band->format != TXC_FORMAT(&tx->cfg))
        return R8_E_ARG;
    if (y0 == tx->next_y) {
        idx = tx->next_idx;
    } else {
        if (y0 % TXC_BAND(&tx->cfg))
            return R8_E_ARG;
        idx = (unsigned)y0 / (unsigned)TXC_BAND(&tx->cfg);
    }
    tx->next_y = (r8_s16)(y0 + TXC_BAND(&tx->cfg));
    tx->next_idx = idx + 1u;
    n = tx->band_bytes;
    xn = tx->xn;
    if (TX_PARTIAL && TXC_HEIGHT(&tx->cfg) - y0 < TXC_BAND(&tx->cfg)) {
        n = r8_fb_bytes(TXC_FORMAT(&tx->cfg), TXC_WIDTH(&tx->cfg), (r8_s16)(TXC_HEIGHT(&tx->cfg) - y0));
        xn = r8_crc16_xpow(n);
    }
    tx->raw_bytes += n;
#ifdef R8_WIRE_CRC32
    tx->fcrc32 = r8_crc32_update(tx->fcrc32, band->buf, n);
#endif
    fp = tx->fp + 4u * idx;
    /* a band of zeros (blank screen): its fingerprint is 0, its CRC from
     * 0 is 0; unchanged in a delta frame, it costs nothing more */
    z = r8_tx_zeros(band->buf, n);
    if (z == n) {
        changed = (r8_u8)(fp[0] | fp[1] | fp[2] | fp[3]);
        fp[0] = fp[1] = fp[2] = fp[3] = 0;
        tx->fcrc = r8_crc16_mul(tx->fcrc, xn);
        if (!tx->full && !changed)
            return R8_OK;
    }
    tx_band(tx, band->buf, n, (unsigned)y0, fp, xn, z);
    return R8_OK;
}
#endif /* TX_ASM_ALL */

int r8_tx_frame_end(r8_tx *tx)
{
    r8_u8 *p = tx->pkt + 1;
    tx_st s;
    if (!tx->in_frame)
        return R8_E_ARG;
    p[0] = R8_PKT_FRAME_END;
    put16(p + 1, tx->frame);
    put16(p + 3, tx->sent);
#ifdef R8_WIRE_CRC32
    put16(p + 5, (unsigned)(tx->fcrc32 >> 16));
    put16(p + 7, (unsigned)(tx->fcrc32 & 0xFFFFu));
    tx_send(tx, &s, R8_WIRE_END2_BYTES, 1);
#else
    put16(p + 5, tx->fcrc);
    tx_send(tx, &s, R8_WIRE_END_BYTES, 1);
#endif
    tx->in_frame = 0;
    return R8_OK;
}
