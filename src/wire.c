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
 * packet CRC with it and links its zeros into the COBS chain; the CRC of
 * the raw band (from 0) is derived from the packet CRC at each literal
 * run and shifted over each zero run (src/r8crc.h), and the frame CRC
 * takes it with one multiply.  Zero runs cost no CRC work per byte and
 * are scanned 4 bytes at a time.
 *
 * Fingerprint of a band: its CRC-16 from 0 (r8_crc16_update(0, ...))
 * and its Fletcher-16.  (The CRC from 0xFFFF differs from it by a
 * constant for a given band size, so the bands sent are the same.)
 *
 * Codecs left out: -DR8_NO_RLE, -DR8_NO_LZ77 (the config is then
 * rejected with R8_E_ARG; raw is always built in). */
#include "r8crc.h"
#include "r8flash.h"

/* The hot loops are kept out of line: each then has the registers to
 * itself (avr-gcc spills the pointers otherwise). */
#if defined(__GNUC__)
#define TX_NOINLINE __attribute__((noinline))
#else
#define TX_NOINLINE
#endif

static const r8_u8 delim = 0;

/* A packet being built: its COBS chain, its CRC, and for a band the
 * running sums of the raw band. */
typedef struct tx_st {
    r8_u8 *pkt;              /* the packet: pkt[0] code, body from pkt[1] */
    r8_u8 *code;             /* last code slot of the COBS chain */
    r8_u8 bad;               /* a block is too long: the chain stops */
    r8_u8 ph, pl;            /* packet CRC */
    r8_u8 f1, f2;            /* Fletcher sums of the band so far */
    r8_u16 g;                /* CRC from 0 of the band so far */
} tx_st;

static void put16(r8_u8 *p, unsigned v)
{
    p[0] = (r8_u8)((v >> 8) & 0xFFu);
    p[1] = (r8_u8)(v & 0xFFu);
}

static void out(r8_tx *tx, const r8_u8 *p, unsigned n)
{
    tx->put(tx->ctx, p, n);
    tx->bytes += n;
}

static void count_put(void *ctx, const r8_u8 *p, unsigned n)
{
    out((r8_tx *)ctx, p, n);
}

/* Start a packet's COBS chain. */
static void tx_start(tx_st *s, r8_u8 *pkt)
{
    s->pkt = pkt;
    s->code = pkt;
    s->bad = 0;
}

/* The 0x00 at q (after every zero linked so far) takes the place of a
 * code: the code before it gets the distance.  A block of 254 or more
 * non-zero bytes needs an extra code byte, which does not fit in place:
 * the chain stops (s->bad) and tx_send streams the packet instead. */
static void tx_link(tx_st *s, r8_u8 *q)
{
    if (s->bad)
        return;
    if (q - s->code > 254) {
        s->bad = 1;
        return;
    }
    *s->code = (r8_u8)(q - s->code);
    s->code = q;
}

/* Link the zeros of q .. end. */
static void tx_links(tx_st *s, r8_u8 *q, const r8_u8 *end)
{
    for (; q != end; q++)
        if (!*q)
            tx_link(s, q);
}

/* Put back the zeros linked so far. */
static void tx_unlink(tx_st *s)
{
    r8_u8 *q = s->pkt, d;
    while (q != s->code) {
        d = *q;
        if (q != s->pkt)
            *q = 0;
        q += d;
    }
    s->code = s->pkt;
}

/* Send the packet whose body is pkt[1 .. 1+n), its zeros linked, with
 * the CRC s->ph:pl: append the CRC, end the chain, add the delimiter,
 * one put; or stream it through r8_cobs_write if the chain stopped. */
static void tx_send(r8_tx *tx, tx_st *s, unsigned n)
{
    r8_u8 *p = s->pkt, *end = p + n + 3;
    p[n + 1] = s->ph;
    p[n + 2] = s->pl;
    tx_links(s, p + n + 1, end);
    if (!s->bad && end - s->code <= 255) {
        *s->code = (r8_u8)(end - s->code);
        *end = 0;
        out(tx, p, n + 4);
    } else {
        tx_unlink(s);
        r8_cobs_write(p + 1, n + 2, count_put, tx);
        out(tx, &delim, 1);
    }
}

/* Send a small packet whose body is pkt[1 .. 1+n). */
static void tx_send_body(r8_tx *tx, unsigned n)
{
    tx_st s;
    r8_u16 crc = r8_crc16(tx->pkt + 1, n);
    tx_start(&s, tx->pkt);
    tx_links(&s, tx->pkt + 1, tx->pkt + 1 + n);
    s.ph = (r8_u8)(crc >> 8);
    s.pl = (r8_u8)(crc & 0xFFu);
    tx_send(tx, &s, n);
}

static int cfg_ok(const r8_tx_cfg *cfg)
{
    if (cfg->format > R8_FMT_IDX8 || cfg->codec >= R8_CODEC_COUNT)
        return 0;
#ifdef R8_NO_RLE
    if (cfg->codec == R8_CODEC_RLE)
        return 0;
#endif
#ifdef R8_NO_LZ77
    if (cfg->codec == R8_CODEC_LZ77)
        return 0;
#endif
    if (cfg->width <= 0 || cfg->height <= 0 || cfg->band <= 0 ||
        cfg->width > R8_WIRE_MAX_DIM || cfg->height > R8_WIRE_MAX_DIM ||
        cfg->band > cfg->height)
        return 0;
    if (cfg->format == R8_FMT_PAGE1 && (cfg->band & 7))
        return 0;
    if (cfg->npal && !cfg->palette)
        return 0;
    return 1;
}

unsigned r8_tx_band_bytes(const r8_tx_cfg *cfg)
{
    r8_u32 b;
    if (!cfg_ok(cfg))
        return 0;
    /* computed in 32 bits: may exceed an unsigned on 16-bit targets */
    b = (r8_u32)cfg->band;
    if (cfg->format == R8_FMT_PAGE1)
        b = (b + 7u) >> 3;
    if (cfg->format == R8_FMT_ROW1)
        b *= (r8_u32)(((unsigned)cfg->width + 7u) >> 3);
    else
        b *= (r8_u32)cfg->width;
    if (b > R8_WIRE_MAX_BAND)
        return 0;
    return (unsigned)b;
}

unsigned r8_tx_scratch(const r8_tx_cfg *cfg)
{
    unsigned bb = r8_tx_band_bytes(cfg);
    if (!bb)
        return 0;
    return R8_TX_SCRATCH_BYTES(bb, R8_WIRE_NBANDS(cfg->height, cfg->band), cfg->npal);
}

int r8_tx_init(r8_tx *tx, const r8_tx_cfg *cfg, r8_u8 *scratch,
               unsigned scratch_size, r8_put_fn put, void *ctx)
{
    unsigned need = r8_tx_scratch(cfg), k;
    if (!need || !put)
        return R8_E_ARG;
    if (scratch_size < need)
        return R8_E_SPACE;
    tx->cfg = *cfg;
    tx->put = put;
    tx->ctx = ctx;
    tx->band_bytes = r8_tx_band_bytes(cfg);
    tx->nbands = R8_WIRE_NBANDS(cfg->height, cfg->band);
    tx->pkt_size = R8_WIRE_PKT_BYTES(tx->band_bytes, cfg->npal) + 2u;
    tx->pkt = scratch;
    tx->xn = r8_crc16_xpow(tx->band_bytes);
    tx->xn_last = r8_crc16_xpow(r8_fb_bytes(cfg->format, cfg->width,
        (r8_s16)(cfg->height - (r8_s16)(tx->nbands - 1u) * cfg->band)));
    tx->next_y = 0;
    tx->next_idx = 0;
    tx->fp = scratch + tx->pkt_size;
    for (k = 0; k < 4u * tx->nbands; k++)
        tx->fp[k] = 0;
    tx->frame = 0;
    tx->since_full = 0;
    tx->sent = 0;
    tx->fcrc = (r8_u16)R8_CRC16_INIT;
    tx->full = 0;
    tx->want_full = 1;
    tx->in_frame = 0;
    tx->rx_len = 0;
    tx->bytes = 0;
    tx->raw_bytes = 0;
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
    r8_u8 body[4];
    unsigned n;
    if (c != 0) {
        if (tx->rx_len < sizeof tx->rx)
            tx->rx[tx->rx_len] = c;
        if (tx->rx_len < 255u)
            tx->rx_len++;
        return 0;
    }
    n = tx->rx_len;
    tx->rx_len = 0;
    if (n > sizeof tx->rx || r8_cobs_decode(tx->rx, n, body, sizeof body, &n) != R8_OK)
        return 0;
    if (n != 1u + R8_WIRE_CRC_BYTES || body[0] != R8_PKT_REQUEST ||
        r8_crc16(body, 1) != (((unsigned)body[1] << 8) | body[2]))
        return 0;
    tx->want_full = 1;
    return 1;
}

int r8_tx_frame_begin(r8_tx *tx, r8_u16 frame)
{
    r8_u8 *p = tx->pkt + 1;
    unsigned k;
    if (tx->in_frame)
        return R8_E_ARG;
    if (tx->cfg.full_period && tx->since_full >= tx->cfg.full_period)
        tx->want_full = 1;
    tx->full = (r8_u8)(tx->want_full || !tx->cfg.dirty);
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
    /* the CRC of the first 3 bytes of this frame's BAND packets */
    p[0] = R8_PKT_BAND;
    put16(p + 1, frame);
    tx->hcrc = r8_crc16(p, 3);
    p[0] = R8_PKT_FRAME_START;
    p[1] = R8_WIRE_VERSION;
    put16(p + 2, frame);
    put16(p + 4, (unsigned)tx->cfg.width);
    put16(p + 6, (unsigned)tx->cfg.height);
    p[8] = tx->cfg.format;
    put16(p + 9, (unsigned)tx->cfg.band);
    p[11] = tx->cfg.codec;
    p[12] = (r8_u8)(tx->full ? R8_FLAG_FULL : 0);
    p[13] = tx->cfg.npal;
    for (k = 0; k < 3u * tx->cfg.npal; k++)
        p[R8_WIRE_START_BYTES + k] = tx->cfg.palette[k];
    tx_send_body(tx, R8_WIRE_START_BYTES + 3u * tx->cfg.npal);
    return R8_OK;
}

/* Fingerprint of the band src[0..n) into f[4]: CRC-16 from 0 (big-
 * endian), Fletcher-16 sums f1, f2.  Leading zeros change neither. */
static void tx_fingerprint(const r8_u8 *p, unsigned n, r8_u8 *f)
{
    const r8_u8 *end = p + n;
    r8_u16 g;
    r8_u8 f1 = 0, f2 = 0;
    while (p != end && !*p)
        p++;
    g = r8_crc16_update(0, p, (unsigned)(end - p));
    while (p != end) {
        f1 = (r8_u8)(f1 + *p++);
        f2 = (r8_u8)(f2 + f1);
    }
    f[0] = (r8_u8)(g >> 8);
    f[1] = (r8_u8)(g & 0xFFu);
    f[2] = f1;
    f[3] = f2;
}

#ifndef R8_NO_RLE
/* A literal token is walked once: its bytes go into the packet CRC
 * behind a stand-in count byte 0x80, and once the count L is known the
 * CRC is put right: the CRC is affine, so replacing 0x80 by 0x80 | L
 * changes it by crc(0, L followed by L zero bytes) = lit_fix[L]. */
static const r8_u16 lit_fix[128] R8_FLASH = {
    0x0000u, 0x3331u, 0x6E60u, 0x9BDCu, 0x8906u, 0x4301u, 0xA125u, 0xC718u,
    0x29FFu, 0x250Eu, 0x023Du, 0x1E37u, 0x0EF7u, 0x6DAFu, 0xF12Eu, 0x791Au,
    0x1E01u, 0x02CEu, 0x9C42u, 0x3586u, 0xE976u, 0x77DFu, 0x7E6Du, 0xC55Au,
    0x1626u, 0xF896u, 0xC7BDu, 0x303Fu, 0xFBA3u, 0xF46Bu, 0x46C1u, 0xB044u,
    0xB990u, 0x3AD7u, 0xE946u, 0x0346u, 0x9BD0u, 0x0649u, 0x4238u, 0xBE22u,
    0xE973u, 0xD9D4u, 0x31CAu, 0xAB9Eu, 0x962Au, 0x6186u, 0xBC80u, 0x0CB6u,
    0xA97Du, 0x4BB5u, 0x803Au, 0xD0C8u, 0x9CEAu, 0x3452u, 0x4B88u, 0x3068u,
    0x0E27u, 0x5198u, 0x2D17u, 0x5980u, 0xD7EDu, 0x2D46u, 0x87CBu, 0xF43Du,
    0xDF3Fu, 0x490Du, 0xEE35u, 0x1317u, 0x053Cu, 0x1903u, 0x086Fu, 0xCC88u,
    0x5DC7u, 0xBD54u, 0x2715u, 0xA0F9u, 0x8BA4u, 0x187Bu, 0x9647u, 0xFB48u,
    0x028Cu, 0xF477u, 0xFBBDu, 0x0294u, 0x976Fu, 0x42F3u, 0x0372u, 0x100Cu,
    0xDB8Cu, 0x0382u, 0xCEADu, 0xBA8Bu, 0xBA70u, 0xF160u, 0xAF8Fu, 0xB634u,
    0x3F17u, 0x88CBu, 0x3EA6u, 0xF8FBu, 0xB451u, 0x1B3Fu, 0x9093u, 0x173Du,
    0x66FEu, 0xBAFBu, 0x0AC5u, 0xD2FDu, 0x564Du, 0x14A4u, 0xBADBu, 0x70B6u,
    0x5EEDu, 0x699Cu, 0xC04Bu, 0x42EAu, 0x90D4u, 0x97B2u, 0x27ABu, 0x58BAu,
    0x0713u, 0x20B2u, 0xE08Bu, 0x24E1u, 0xBD80u, 0xB608u, 0x9451u, 0x00A8u
};

/* The literal token at p (no run of 3 starts at p): up to c bytes,
 * stopping where a run of 3 starts; run starts are looked for in the
 * first k <= c positions only (p[0 .. k+1] are read; the other c - k,
 * at most 2, are the last bytes of the band).  Copies the literals to
 * o + 1, feeding the packet CRC, the Fletcher sums and the COBS chain;
 * returns the count L >= 1. */
static r8_u8 TX_NOINLINE tx_lit(tx_st *s, r8_u8 *o, const r8_u8 *p,
                                r8_u8 k, r8_u8 c)
{
    r8_u8 ph = s->ph, pl = s->pl, f1 = s->f1, f2 = s->f2, v, w = 0, j = k;
    v = *p++;
    if (k || c > 1u)
        w = *p++;
    o++;
    if (j) {
        do {
            if (w == v && *p == v)
                break;
            *o = v;
            R8_CRC16_STEP(ph, pl, v);
            f1 = (r8_u8)(f1 + v);
            f2 = (r8_u8)(f2 + f1);
            if (!v && !s->bad) {
                if (o - s->code > 254) {
                    s->bad = 1;
                } else {
                    *s->code = (r8_u8)(o - s->code);
                    s->code = o;
                }
            }
            o++;
            v = w;
            w = *p++;
        } while (--j);
    }
    j = (r8_u8)(k - j);
    if (j == k) {
        /* no run in the k positions: the last c - k bytes are v, w */
        while (j < c) {
            *o = v;
            R8_CRC16_STEP(ph, pl, v);
            f1 = (r8_u8)(f1 + v);
            f2 = (r8_u8)(f2 + f1);
            if (!v && !s->bad) {
                if (o - s->code > 254) {
                    s->bad = 1;
                } else {
                    *s->code = (r8_u8)(o - s->code);
                    s->code = o;
                }
            }
            o++;
            v = w;
            j++;
        }
    }
    s->ph = ph;
    s->pl = pl;
    s->f1 = f1;
    s->f2 = f2;
    return j;
}

/* How many of the k bytes from q equal v (stops at the first other);
 * zeros 4 at a time. */
static r8_u8 TX_NOINLINE tx_same(const r8_u8 *q, r8_u8 k, r8_u8 v)
{
    r8_u8 j = k;
    if (!v)
        while (j >= 4u && !(q[0] | q[1] | q[2] | q[3])) {
            q += 4;
            j = (r8_u8)(j - 4u);
        }
    while (j && *q == v) {
        q++;
        j--;
    }
    return (r8_u8)(k - j);
}

/* A run token: count c (3..127) and value v at o; into the packet CRC,
 * the COBS chain, the band's CRC and Fletcher sums. */
static void TX_NOINLINE tx_run(tx_st *s, r8_u8 *o, r8_u8 c, r8_u8 v)
{
    r8_u8 ph = s->ph, pl = s->pl, gh, gl, f1 = s->f1, f2 = s->f2;
    o[0] = c;
    o[1] = v;
    R8_CRC16_STEP(ph, pl, c);
    R8_CRC16_STEP(ph, pl, v);
    s->ph = ph;
    s->pl = pl;
    if (!v) {
        tx_link(s, o + 1);
        s->g = r8_crc16_shift(s->g, c);
        s->f2 = (r8_u8)(f2 + (r8_u8)(c * f1));
        return;
    }
    gh = (r8_u8)(s->g >> 8);
    gl = (r8_u8)(s->g & 0xFFu);
    do {
        R8_CRC16_STEP(gh, gl, v);
        f1 = (r8_u8)(f1 + v);
        f2 = (r8_u8)(f2 + f1);
    } while (--c);
    s->g = (r8_u16)(((r8_u16)gh << 8) | gl);
    s->f1 = f1;
    s->f2 = f2;
}

/* RLE-encode the band p[0..n) into o (the bytes r8_rle_encode gives, see
 * r8codec.h), at most cap bytes: the payload goes on s's packet CRC and
 * COBS chain, s gets the band's CRC from 0 and Fletcher sums.  Returns
 * the payload length, or cap + 1 when it does not fit (o then holds
 * garbage; nothing is written past o + cap). */
static unsigned TX_NOINLINE tx_rle(tx_st *s, const r8_u8 *p, unsigned n,
                                   r8_u8 *o, unsigned cap)
{
    const r8_u8 *end = p + n;
    r8_u8 *o0 = o, gh, gl, v;
    unsigned room = cap, left;
    r8_u8 c, k, full;
    r8_u16 pb;
    s->f1 = s->f2 = 0;
    s->g = 0;
    while (p != end) {
        left = (unsigned)(end - p);
        c = R8_RLE_MAX;
        if (left < R8_RLE_MAX)
            c = (r8_u8)left;
        v = *p;
        if (left >= 3u && p[1] == v && p[2] == v) {
            /* a run of 3..c equal bytes */
            if (room < 2u)
                return cap + 1u;
            room -= 2u;
            c = (r8_u8)(3u + tx_same(p + 3, (r8_u8)(c - 3u), v));
            tx_run(s, o, c, v);
            o += 2;
            p += c;
            continue;
        }
        /* literals: k = the positions with two bytes after them, where
         * a run of 3 may start */
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
        v = 0x80u;
        R8_CRC16_STEP(s->ph, s->pl, v);
        pb = (r8_u16)(((r8_u16)s->ph << 8) | s->pl);
        c = tx_lit(s, o, p, k, c);
        if (c == full)
            return cap + 1u;
        room -= c + 1u;
        *o = (r8_u8)(0x80u | c);
        /* the band's CRC: g * x^(8c) ^ crc(0, literals), where
         * crc(0, literals) = the packet CRC after them ^ the one before
         * them * x^(8c); few literals are cheaper one by one */
        if (c < 8u) {
            gh = (r8_u8)(s->g >> 8);
            gl = (r8_u8)(s->g & 0xFFu);
            for (k = 0; k < c; k++) {
                v = p[k];
                R8_CRC16_STEP(gh, gl, v);
            }
            s->g = (r8_u16)(((r8_u16)gh << 8) | gl);
        } else {
            s->g = (r8_u16)(r8_crc16_shift((r8_u16)(s->g ^ pb), c) ^
                            (((r8_u16)s->ph << 8) | s->pl));
        }
        pb = R8_RDU16(&lit_fix[c]);
        s->ph = (r8_u8)(s->ph ^ (r8_u8)(pb >> 8));
        s->pl = (r8_u8)(s->pl ^ (r8_u8)(pb & 0xFFu));
        o += c + 1u;
        p += c;
    }
    return (unsigned)(o - o0);
}
#endif

int r8_tx_band(r8_tx *tx, const r8_fb *band)
{
    unsigned idx, n, len, k;
    r8_u8 *b = tx->pkt + 1, *fp, f[4], codec = tx->cfg.codec, changed;
    const r8_u8 *src = band->buf;
    r8_u16 crc, xn;
    int rc = R8_E_SPACE;
    tx_st s;
    if (!tx->in_frame || band->y0 < 0 || band->y0 >= tx->cfg.height ||
        band->width != tx->cfg.width || band->format != tx->cfg.format)
        return R8_E_ARG;
    if (band->y0 == tx->next_y) {
        idx = tx->next_idx;
    } else {
        if (band->y0 % tx->cfg.band)
            return R8_E_ARG;
        idx = (unsigned)band->y0 / (unsigned)tx->cfg.band;
    }
    tx->next_y = (r8_s16)(band->y0 + tx->cfg.band);
    tx->next_idx = idx + 1u;
    if (tx->cfg.height - band->y0 < tx->cfg.band) {
        n = r8_fb_bytes(tx->cfg.format, tx->cfg.width,
                        (r8_s16)(tx->cfg.height - band->y0));
        xn = tx->xn_last;
    } else {
        n = tx->band_bytes;
        xn = tx->xn;
    }
    tx->raw_bytes += n;
    /* header; bytes 0..2 are in tx->hcrc */
    b[0] = R8_PKT_BAND;
    put16(b + 1, tx->frame);
    put16(b + 3, (unsigned)band->y0);
    b[5] = codec;
    tx_start(&s, tx->pkt);
    len = n;
#ifndef R8_NO_RLE
    if (codec == R8_CODEC_RLE) {
        crc = r8_crc16_update(tx->hcrc, b + 3, 3);
        s.ph = (r8_u8)(crc >> 8);
        s.pl = (r8_u8)(crc & 0xFFu);
        tx_links(&s, b + 1, b + 5);
        len = tx_rle(&s, src, n, b + R8_WIRE_BAND_HDR, n - 1u);
        if (len < n) {
            rc = R8_OK;
            f[0] = (r8_u8)(s.g >> 8);
            f[1] = (r8_u8)(s.g & 0xFFu);
            f[2] = s.f1;
            f[3] = s.f2;
        } else {
            tx_unlink(&s);
        }
    }
#endif
    if (rc != R8_OK)
        tx_fingerprint(src, n, f);
    fp = tx->fp + 4u * idx;
    changed = 0;
    for (k = 0; k < 4u; k++) {
        changed |= (r8_u8)(fp[k] ^ f[k]);
        fp[k] = f[k];
    }
    /* frame CRC: fcrc * x^(8n) ^ the band's CRC from 0 */
    tx->fcrc = (r8_u16)(r8_crc16_mul(tx->fcrc, xn) ^
                        (((r8_u16)f[0] << 8) | f[1]));
    if (!tx->full && !changed)
        return R8_OK;
    if (rc != R8_OK) {
#ifndef R8_NO_LZ77
        if (codec == R8_CODEC_LZ77)
            rc = r8_lz77_encode(src, n, b + R8_WIRE_BAND_HDR, n - 1u, &len);
#endif
        if (rc != R8_OK) {
            /* raw: the codec would not make the band smaller */
            b[5] = R8_CODEC_RAW;
            len = n;
            for (k = 0; k < n; k++)
                b[R8_WIRE_BAND_HDR + k] = src[k];
        }
        crc = r8_crc16(b, R8_WIRE_BAND_HDR + len);
        s.ph = (r8_u8)(crc >> 8);
        s.pl = (r8_u8)(crc & 0xFFu);
        tx_links(&s, b, b + R8_WIRE_BAND_HDR + len);
    }
    tx_send(tx, &s, R8_WIRE_BAND_HDR + len);
    tx->sent++;
    return R8_OK;
}

int r8_tx_frame_end(r8_tx *tx)
{
    r8_u8 *p = tx->pkt + 1;
    if (!tx->in_frame)
        return R8_E_ARG;
    p[0] = R8_PKT_FRAME_END;
    put16(p + 1, tx->frame);
    put16(p + 3, tx->sent);
    put16(p + 5, tx->fcrc);
    tx_send_body(tx, R8_WIRE_END_BYTES);
    tx->in_frame = 0;
    return R8_OK;
}
