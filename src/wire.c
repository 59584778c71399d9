/* wire.c - the frame encoder (firmware side) of the display protocol,
 * see r8wire.h and docs/protocol.md.  Memory: one packet scratch (a
 * band's raw size plus header and CRC) and 4 bytes per band for the
 * dirty-band fingerprints; bands are encoded straight into the packet
 * and COBS-streamed out without another buffer. */
#include "r8wire.h"

static const r8_u8 delim = 0;

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

/* Append the CRC to the body tx->pkt[0..n) and send the packet. */
static void send_pkt(r8_tx *tx, unsigned n)
{
    put16(tx->pkt + n, r8_crc16(tx->pkt, n));
    r8_cobs_write(tx->pkt, n + R8_WIRE_CRC_BYTES, count_put, tx);
    out(tx, &delim, 1);
}

static int cfg_ok(const r8_tx_cfg *cfg)
{
    if (cfg->format > R8_FMT_IDX8 || cfg->codec >= R8_CODEC_COUNT)
        return 0;
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
    tx->pkt_size = R8_WIRE_PKT_BYTES(tx->band_bytes, cfg->npal);
    tx->pkt = scratch;
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
    tx->keys = 0;
    tx->inputs = 0;
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
    r8_u8 body[6];
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
    if (n > sizeof tx->rx || r8_cobs_decode(tx->rx, n, body, sizeof body, &n) != R8_OK ||
        n < 1u + R8_WIRE_CRC_BYTES ||
        r8_crc16(body, n - R8_WIRE_CRC_BYTES) !=
            (((unsigned)body[n - 2u] << 8) | body[n - 1u]))
        return 0;
    n -= R8_WIRE_CRC_BYTES;
    if (body[0] == R8_PKT_REQUEST && n == 1u) {
        tx->want_full = 1;
        return R8_RX_REQUEST;
    }
    if (body[0] == R8_PKT_INPUT && n == 3u) {
        tx->keys = (r8_u16)(((unsigned)body[1] << 8) | body[2]);
        tx->inputs++;
        return R8_RX_INPUT;
    }
    return 0; /* unknown kind or length: ignored */
}

int r8_tx_frame_begin(r8_tx *tx, r8_u16 frame)
{
    r8_u8 *p = tx->pkt;
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
    tx->in_frame = 1;
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
    send_pkt(tx, R8_WIRE_START_BYTES + 3u * tx->cfg.npal);
    return R8_OK;
}

int r8_tx_band(r8_tx *tx, const r8_fb *band)
{
    unsigned idx, n, len, rows;
    r8_u8 *fp, f1 = 0, f2 = 0;
    r8_u16 h;
    r8_u8 codec = tx->cfg.codec;
    int changed, rc;
    if (!tx->in_frame || band->y0 < 0 || band->y0 >= tx->cfg.height ||
        band->y0 % tx->cfg.band || band->width != tx->cfg.width ||
        band->format != tx->cfg.format)
        return R8_E_ARG;
    idx = (unsigned)band->y0 / (unsigned)tx->cfg.band;
    rows = (unsigned)(tx->cfg.height - band->y0);
    if (rows > (unsigned)tx->cfg.band)
        rows = (unsigned)tx->cfg.band;
    n = r8_fb_bytes(tx->cfg.format, tx->cfg.width, (r8_s16)rows);
    tx->fcrc = r8_crc16_update(tx->fcrc, band->buf, n);
    tx->raw_bytes += n;
    /* fingerprint: CRC-16 and a Fletcher-16 of the band's bytes */
    h = r8_crc16(band->buf, n);
    for (len = 0; len < n; len++) {
        f1 = (r8_u8)(f1 + band->buf[len]);
        f2 = (r8_u8)(f2 + f1);
    }
    fp = tx->fp + 4u * idx;
    changed = fp[0] != (r8_u8)(h >> 8) || fp[1] != (r8_u8)(h & 0xFFu) ||
              fp[2] != f1 || fp[3] != f2;
    fp[0] = (r8_u8)(h >> 8);
    fp[1] = (r8_u8)(h & 0xFFu);
    fp[2] = f1;
    fp[3] = f2;
    if (!tx->full && !changed)
        return R8_OK;
    tx->pkt[0] = R8_PKT_BAND;
    put16(tx->pkt + 1, tx->frame);
    put16(tx->pkt + 3, (unsigned)band->y0);
    /* encode; fall back to raw when the codec does not make it smaller */
    rc = R8_E_SPACE;
    if (codec != R8_CODEC_RAW)
        rc = r8_codec_encode(codec, band->buf, n, tx->pkt + R8_WIRE_BAND_HDR,
                             n - 1u, &len);
    if (rc != R8_OK) {
        codec = R8_CODEC_RAW;
        r8_codec_encode(codec, band->buf, n, tx->pkt + R8_WIRE_BAND_HDR, n, &len);
    }
    tx->pkt[5] = codec;
    send_pkt(tx, R8_WIRE_BAND_HDR + len);
    tx->sent++;
    return R8_OK;
}

int r8_tx_frame_end(r8_tx *tx)
{
    r8_u8 *p = tx->pkt;
    if (!tx->in_frame)
        return R8_E_ARG;
    p[0] = R8_PKT_FRAME_END;
    put16(p + 1, tx->frame);
    put16(p + 3, tx->sent);
    put16(p + 5, tx->fcrc);
    send_pkt(tx, R8_WIRE_END_BYTES);
    tx->in_frame = 0;
    return R8_OK;
}
