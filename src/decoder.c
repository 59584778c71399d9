/* decoder.c - the display side of the protocol: a byte-at-a-time
 * decoder in fixed, caller-given memory (a packet buffer and the frame
 * buffer).  COBS is undone as bytes arrive; at each 0x00 the packet's
 * CRC is checked before anything in it is used.  A frame is reported
 * good only when its start, every band it announced and its end arrived
 * intact, its base (for a delta frame) was the previous good frame, and
 * the CRC of the whole assembled frame matches the one in FRAME_END.
 * See docs/protocol.md. */
#include "r8wire.h"

static unsigned get16(const r8_u8 *p)
{
    return ((unsigned)p[0] << 8) | p[1];
}

/* Bytes of `rows` rows in format, in 32 bits (may not fit an int). */
static r8_u32 bytes32(r8_u8 format, unsigned width, unsigned rows)
{
    r8_u32 b = rows;
    if (format == R8_FMT_PAGE1)
        b = (b + 7u) >> 3;
    if (format == R8_FMT_ROW1)
        b *= (r8_u32)((width + 7u) >> 3);
    else
        b *= (r8_u32)width;
    return b;
}

void r8_dec_init(r8_dec *d, r8_u8 *pkt, unsigned pkt_size, r8_u8 *fb,
                 unsigned fb_size, r8_u8 *pal, unsigned pal_size)
{
    d->pkt = pkt;
    d->pkt_size = pkt_size;
    d->pkt_len = 0;
    d->code = 0;
    d->left = 0;
    d->overflow = 0;
    d->fb = fb;
    d->fb_size = fb_size;
    d->pal = pal;
    d->pal_size = pal_size;
    d->in_frame = 0;
    d->full = 0;
    d->format = 0;
    d->codec = 0;
    d->valid = 0;
    d->npal = 0;
    d->frame = 0;
    d->nbands_got = 0;
    d->width = 0;
    d->height = 0;
    d->band = 0;
    d->last_seen = 0;
    d->have_last = 0;
    d->base_ok = 0;
    d->need_full = 0;
    d->frame_bytes = 0;
    d->bytes = 0;
    d->packets = 0;
    d->bad_packets = 0;
    d->frames = 0;
    d->dropped = 0;
    d->incomplete = 0;
}

static void put_byte(r8_dec *d, r8_u8 v)
{
    if (d->pkt_len < d->pkt_size)
        d->pkt[d->pkt_len++] = v;
    else
        d->overflow = 1;
}

/* A packet for frame `f` arrived: count frame numbers skipped since the
 * last one seen (a jump back or of 32768+ is a restart, not a loss). */
static void seen_frame(r8_dec *d, unsigned f)
{
    unsigned gap;
    if (d->have_last) {
        gap = (f - d->last_seen - 1u) & 0xFFFFu;
        if (f != d->last_seen && gap < 0x8000u)
            d->dropped += gap;
    }
    d->last_seen = (r8_u16)f;
    d->have_last = 1;
}

static void frame_fail(r8_dec *d)
{
    if (d->in_frame)
        d->incomplete++;
    d->in_frame = 0;
    d->base_ok = 0;
    d->need_full = 1;
}

/* A BAND or FRAME_END of frame f outside that frame: its FRAME_START
 * was lost (or it is a stray repeat of the frame just finished). */
static int orphan(r8_dec *d, unsigned f)
{
    if (d->in_frame)
        frame_fail(d);
    else if (d->have_last && f == d->last_seen)
        return R8_DEC_PACKET; /* already counted, or a repeat */
    seen_frame(d, f);
    d->incomplete++;
    d->base_ok = 0;
    d->need_full = 1;
    return R8_DEC_INCOMPLETE;
}

static int bad(r8_dec *d)
{
    d->bad_packets++;
    return R8_DEC_BAD;
}

static int on_start(r8_dec *d, const r8_u8 *p, unsigned n)
{
    unsigned w, h, band, k, npal;
    r8_u8 fmt, codec;
    r8_u32 fbytes;
    if (n < R8_WIRE_START_BYTES)
        return bad(d);
    npal = p[13];
    w = get16(p + 4);
    h = get16(p + 6);
    fmt = p[8];
    band = get16(p + 9);
    codec = p[11];
    if (p[1] != R8_WIRE_VERSION || n != R8_WIRE_START_BYTES + 3u * npal ||
        fmt > R8_FMT_IDX8 || codec >= R8_CODEC_COUNT || w == 0 || h == 0 ||
        w > R8_WIRE_MAX_DIM || h > R8_WIRE_MAX_DIM || band == 0 || band > h ||
        (fmt == R8_FMT_PAGE1 && (band & 7u)))
        return bad(d);
    if (d->in_frame)
        frame_fail(d); /* the previous frame never ended */
    seen_frame(d, get16(p + 2));
    d->packets++;
    fbytes = bytes32(fmt, w, h);
    if (w != d->width || h != d->height || fmt != d->format || band != d->band)
        d->base_ok = 0;
    d->frame = (r8_u16)get16(p + 2);
    d->width = (r8_u16)w;
    d->height = (r8_u16)h;
    d->format = fmt;
    d->band = (r8_u16)band;
    d->codec = codec;
    d->full = (r8_u8)(p[12] & R8_FLAG_FULL);
    d->nbands_got = 0;
    d->in_frame = 1;
    d->valid = 1;
    if (fbytes > (r8_u32)d->fb_size) {
        /* too big for this display: the frame cannot be shown */
        d->valid = 0;
        d->frame_bytes = 0;
    } else {
        d->frame_bytes = (unsigned)fbytes;
    }
    if (!d->full && !d->base_ok)
        d->valid = 0; /* a delta without its base */
    d->npal = (r8_u8)npal;
    if (d->pal && d->pal_size >= 3u * npal)
        for (k = 0; k < 3u * npal; k++)
            d->pal[k] = p[R8_WIRE_START_BYTES + k];
    return R8_DEC_PACKET;
}

static int on_band(r8_dec *d, const r8_u8 *p, unsigned n)
{
    unsigned f, y0, rows, len;
    r8_u32 off, bb;
    if (n < R8_WIRE_BAND_HDR || p[5] >= R8_CODEC_COUNT)
        return bad(d);
    f = get16(p + 1);
    y0 = get16(p + 3);
    d->packets++;
    if (!d->in_frame || f != d->frame)
        return orphan(d, f);
    if (y0 >= d->height || y0 % d->band) {
        d->packets--;
        d->valid = 0;
        return bad(d);
    }
    d->nbands_got++;
    if (!d->valid)
        return R8_DEC_PACKET;
    rows = d->height - y0;
    if (rows > d->band)
        rows = d->band;
    off = bytes32(d->format, d->width, y0);
    bb = bytes32(d->format, d->width, rows);
    if (r8_codec_decode(p[5], p + R8_WIRE_BAND_HDR, n - R8_WIRE_BAND_HDR,
                        d->fb + (unsigned)off, (unsigned)bb, &len) != R8_OK ||
        (r8_u32)len != bb) {
        d->valid = 0;
        d->bad_packets++;
        return R8_DEC_BAD;
    }
    return R8_DEC_PACKET;
}

static int on_end(r8_dec *d, const r8_u8 *p, unsigned n)
{
    unsigned f;
    if (n != R8_WIRE_END_BYTES)
        return bad(d);
    f = get16(p + 1);
    d->packets++;
    if (!d->in_frame || f != d->frame)
        return orphan(d, f) == R8_DEC_PACKET ? R8_DEC_PACKET : R8_DEC_INCOMPLETE;
    if (!d->valid || get16(p + 3) != d->nbands_got ||
        r8_crc16(d->fb, d->frame_bytes) != get16(p + 5)) {
        frame_fail(d);
        return R8_DEC_INCOMPLETE;
    }
    d->in_frame = 0;
    d->base_ok = 1;
    d->need_full = 0;
    d->frames++;
    return R8_DEC_FRAME;
}

static int on_packet(r8_dec *d)
{
    const r8_u8 *p = d->pkt;
    unsigned n = d->pkt_len;
    if (n < 1u + R8_WIRE_CRC_BYTES ||
        r8_crc16(p, n - R8_WIRE_CRC_BYTES) != get16(p + n - R8_WIRE_CRC_BYTES))
        return bad(d);
    n -= R8_WIRE_CRC_BYTES;
    switch (p[0]) {
    case R8_PKT_FRAME_START:
        return on_start(d, p, n);
    case R8_PKT_BAND:
        return on_band(d, p, n);
    case R8_PKT_FRAME_END:
        return on_end(d, p, n);
    case R8_PKT_REQUEST:
        return R8_DEC_NONE; /* our own request echoed back: ignore */
    default:
        return bad(d);
    }
}

int r8_dec_feed(r8_dec *d, r8_u8 c)
{
    int rc = R8_DEC_NONE;
    d->bytes++;
    if (c == 0) {
        if (d->left || d->overflow)
            rc = bad(d);
        else if (d->code)
            rc = on_packet(d);
        d->pkt_len = 0;
        d->code = 0;
        d->left = 0;
        d->overflow = 0;
        return rc;
    }
    if (d->left == 0) {
        if (d->code && d->code != 0xFF)
            put_byte(d, 0);
        d->code = c;
        d->left = (r8_u8)(c - 1u);
    } else {
        put_byte(d, c);
        d->left--;
    }
    return rc;
}

unsigned r8_dec_request(r8_u8 *out)
{
    r8_u8 body[3];
    unsigned n;
    body[0] = R8_PKT_REQUEST;
    body[1] = (r8_u8)(r8_crc16(body, 1) >> 8);
    body[2] = (r8_u8)(r8_crc16(body, 1) & 0xFFu);
    out[0] = 0;
    r8_cobs_encode(body, 3, out + 1, R8_DEC_REQUEST_BYTES - 2, &n);
    out[1 + n] = 0;
    return n + 2u;
}
