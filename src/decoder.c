/* decoder.c - the display side of the protocol: a byte-at-a-time
 * decoder in fixed, caller-given memory (a packet buffer and the frame
 * buffer).  COBS is undone as bytes arrive; at each 0x00 the packet's
 * CRC is checked before anything in it is used.  A frame is reported
 * good only when
 *   - its start, every band it announced and its end arrived intact,
 *     bands in increasing y0, every band for a FULL frame;
 *   - it is FULL, or a delta whose number is the last good frame's
 *     number + 1 and the frame buffer still holds that frame;
 *   - the check of the whole assembled frame matches the one in
 *     FRAME_END: CRC-16 in version 1, CRC-32 in version 2 (the packet
 *     CRC's polynomial makes the CRC-16 blind to every error the packet
 *     CRC missed in a band's literal bytes: docs/protocol.md 4.1).
 * Identical repeats of a packet cost nothing; packets of an older frame
 * are ignored.  See docs/protocol.md sections 4 and 5. */
#include "r8wire.h"

static unsigned get16(const r8_u8 *p)
{
    return ((unsigned)p[0] << 8) | p[1];
}

static r8_u32 get32(const r8_u8 *p)
{
    return ((r8_u32)get16(p) << 16) | get16(p + 2);
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
    d->synced = 0;
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
    d->version = 0;
    d->frame = 0;
    d->nbands_got = 0;
    d->width = 0;
    d->height = 0;
    d->band = 0;
    d->next_y = 0;
    d->last_y0 = 0;
    d->start_crc = 0;
    d->band_crc = 0;
    d->last_seen = 0;
    d->have_last = 0;
    d->base_ok = 0;
    d->good_no = 0;
    d->ever_good = 0;
    d->have_failed = 0;
    d->failed_no = 0;
    d->need_full = 0;
    d->frame_bytes = 0;
    d->bytes = 0;
    d->packets = 0;
    d->bad_packets = 0;
    d->frames = 0;
    d->dropped = 0;
    d->incomplete = 0;
    d->skipped = 0;
    d->ignored = 0;
}

static void put_byte(r8_dec *d, r8_u8 v)
{
    if (d->pkt_len < d->pkt_size)
        d->pkt[d->pkt_len++] = v;
    else
        d->overflow = 1;
}

/* Frame number f relative to the newest one seen: 0 same, 1 ahead
 * (by 1..32767), -1 behind (by 1..32768, a late packet or a restart). */
static int relation(const r8_dec *d, unsigned f)
{
    unsigned gap = (f - d->last_seen) & 0xFFFFu;
    if (!d->have_last || gap == 0)
        return d->have_last ? 0 : 1;
    return gap < 0x8000u ? 1 : -1;
}

/* A packet for a new frame number f arrived: count the numbers skipped
 * (a backward jump is a restart, not a loss). */
static void seen_frame(r8_dec *d, unsigned f)
{
    if (d->have_last && relation(d, f) > 0)
        d->dropped += ((f - d->last_seen) & 0xFFFFu) - 1u;
    d->last_seen = (r8_u16)f;
    d->have_last = 1;
}

/* Frame f was not good: counted once per frame number, as skipped when
 * it is a delta before the first good frame (joining a running stream),
 * else as incomplete. */
static void count_lost(r8_dec *d, unsigned f, int delta)
{
    d->need_full = 1;
    if (d->have_failed && d->failed_no == f)
        return;
    d->have_failed = 1;
    d->failed_no = (r8_u16)f;
    if (delta && !d->ever_good)
        d->skipped++;
    else
        d->incomplete++;
}

static void frame_fail(r8_dec *d)
{
    if (d->in_frame)
        count_lost(d, d->frame, !d->full);
    d->in_frame = 0;
}

static int bad(r8_dec *d)
{
    d->bad_packets++;
    return R8_DEC_BAD;
}

static int ignore(r8_dec *d)
{
    d->ignored++;
    return R8_DEC_PACKET;
}

/* A BAND or FRAME_END of frame f that is not the frame in progress. */
static int other_frame(r8_dec *d, unsigned f)
{
    int rel = relation(d, f);
    if (rel < 0 || (rel == 0 && !d->in_frame) || !d->have_last)
        return ignore(d); /* late, a repeat, or joining: changes nothing */
    /* a newer frame whose FRAME_START was lost */
    frame_fail(d);
    seen_frame(d, f);
    count_lost(d, f, 0);
    return R8_DEC_INCOMPLETE;
}

static int on_start(r8_dec *d, const r8_u8 *p, unsigned n, unsigned crc)
{
    unsigned w, h, band, k, npal, f;
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
    if ((p[1] != R8_WIRE_VERSION && p[1] != R8_WIRE_VERSION2) ||
        n != R8_WIRE_START_BYTES + 3u * npal ||
        fmt > R8_FMT_IDX8 || codec >= R8_CODEC_COUNT || w == 0 || h == 0 ||
        w > R8_WIRE_MAX_DIM || h > R8_WIRE_MAX_DIM || band == 0 || band > h ||
        (fmt == R8_FMT_PAGE1 && (band & 7u)))
        return bad(d);
    f = get16(p + 2);
    d->packets++;
    if (d->in_frame && f == d->frame && crc == d->start_crc)
        return ignore(d); /* the same FRAME_START again */
    frame_fail(d); /* the previous frame never ended */
    seen_frame(d, f);
    fbytes = bytes32(fmt, w, h);
    if (w != d->width || h != d->height || fmt != d->format || band != d->band)
        d->base_ok = 0;
    d->frame = (r8_u16)f;
    d->width = (r8_u16)w;
    d->height = (r8_u16)h;
    d->format = fmt;
    d->band = (r8_u16)band;
    d->codec = codec;
    d->version = p[1];
    d->full = (r8_u8)(p[12] & R8_FLAG_FULL);
    d->start_crc = (r8_u16)crc;
    d->nbands_got = 0;
    d->next_y = 0;
    d->in_frame = 1;
    d->valid = 1;
    if (fbytes > (r8_u32)d->fb_size) {
        /* too big for this display: the frame cannot be shown */
        d->valid = 0;
        d->frame_bytes = 0;
    } else {
        d->frame_bytes = (unsigned)fbytes;
    }
    if (!d->full && (!d->base_ok || f != ((d->good_no + 1u) & 0xFFFFu)))
        d->valid = 0; /* a delta without its base: dropped, ask for a full one */
    d->npal = (r8_u8)npal;
    if (d->pal && d->pal_size >= 3u * npal)
        for (k = 0; k < 3u * npal; k++)
            d->pal[k] = p[R8_WIRE_START_BYTES + k];
    return R8_DEC_PACKET;
}

static int on_band(r8_dec *d, const r8_u8 *p, unsigned n, unsigned crc)
{
    unsigned f, y0, rows, len;
    r8_u32 off, bb;
    if (n < R8_WIRE_BAND_HDR || p[5] >= R8_CODEC_COUNT)
        return bad(d);
    f = get16(p + 1);
    y0 = get16(p + 3);
    if (!d->in_frame || f != d->frame) {
        d->packets++;
        return other_frame(d, f);
    }
    if (y0 >= d->height || y0 % d->band) {
        d->valid = 0;
        return bad(d);
    }
    d->packets++;
    if (d->nbands_got && y0 == d->last_y0 && crc == d->band_crc)
        return ignore(d); /* the same BAND again */
    if (y0 < d->next_y) {
        d->valid = 0; /* out of order, or a different band at the same y0 */
        return R8_DEC_PACKET;
    }
    d->nbands_got++;
    d->last_y0 = (r8_u16)y0;
    d->band_crc = (r8_u16)crc;
    d->next_y = (r8_u16)(y0 + d->band);
    if (!d->valid)
        return R8_DEC_PACKET;
    d->base_ok = 0; /* fb no longer holds the last good frame */
    rows = d->height - y0;
    if (rows > d->band)
        rows = d->band;
    off = bytes32(d->format, d->width, y0);
    bb = bytes32(d->format, d->width, rows);
    if (r8_codec_decode(p[5], p + R8_WIRE_BAND_HDR, n - R8_WIRE_BAND_HDR,
                        d->fb + (unsigned)off, (unsigned)bb, &len) != R8_OK ||
        (r8_u32)len != bb) {
        d->valid = 0;
        d->packets--;
        return bad(d);
    }
    return R8_DEC_PACKET;
}

static int on_end(r8_dec *d, const r8_u8 *p, unsigned n)
{
    unsigned f;
    int ok;
    if (n != R8_WIRE_END_BYTES && n != R8_WIRE_END2_BYTES)
        return bad(d);
    f = get16(p + 1);
    d->packets++;
    if (!d->in_frame || f != d->frame)
        return other_frame(d, f);
    ok = d->valid && get16(p + 3) == d->nbands_got &&
         (!d->full || d->nbands_got == R8_WIRE_NBANDS(d->height, d->band));
    if (ok && d->version == R8_WIRE_VERSION2)
        ok = n == R8_WIRE_END2_BYTES && r8_crc32(d->fb, d->frame_bytes) == get32(p + 5);
    else if (ok)
        ok = n == R8_WIRE_END_BYTES && r8_crc16(d->fb, d->frame_bytes) == get16(p + 5);
    if (!ok) {
        frame_fail(d);
        return R8_DEC_INCOMPLETE;
    }
    d->in_frame = 0;
    d->base_ok = 1;
    d->good_no = (r8_u16)f;
    d->ever_good = 1;
    d->need_full = 0;
    d->frames++;
    return R8_DEC_FRAME;
}

static int on_packet(r8_dec *d)
{
    const r8_u8 *p = d->pkt;
    unsigned n = d->pkt_len, crc;
    if (n < 1u + R8_WIRE_CRC_BYTES)
        return bad(d);
    n -= R8_WIRE_CRC_BYTES;
    crc = get16(p + n);
    if (r8_crc16(p, n) != crc)
        return bad(d);
    if (p[0] >= R8_PKT_TO_DEVICE_FIRST && p[0] <= R8_PKT_TO_DEVICE_LAST) {
        d->packets++; /* display -> device (our own echoed back): ignore */
        d->ignored++;
        return R8_DEC_NONE;
    }
    switch (p[0]) {
    case R8_PKT_FRAME_START:
        return on_start(d, p, n, crc);
    case R8_PKT_BAND:
        return on_band(d, p, n, crc);
    case R8_PKT_FRAME_END:
        return on_end(d, p, n);
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
        d->synced = 1;
        return rc;
    }
    if (!d->synced)
        return rc; /* before the first 0x00: part of a packet we joined late */
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

int r8_dec_end(r8_dec *d)
{
    int rc = R8_DEC_NONE;
    if (d->code || d->overflow)
        rc = bad(d); /* an unterminated packet */
    d->pkt_len = 0;
    d->code = 0;
    d->left = 0;
    d->overflow = 0;
    if (d->in_frame) {
        frame_fail(d);
        rc = R8_DEC_INCOMPLETE;
    }
    return rc;
}

/* body[0..n) + CRC, COBS-encoded between two delimiters, into out. */
static unsigned to_device(r8_u8 *out, r8_u8 *body, unsigned n, unsigned cap)
{
    unsigned len = 0;
    r8_u16 crc = r8_crc16(body, n);
    body[n] = (r8_u8)(crc >> 8);
    body[n + 1u] = (r8_u8)(crc & 0xFFu);
    out[0] = 0;
    r8_cobs_encode(body, n + 2u, out + 1, cap - 2u, &len);
    out[1u + len] = 0;
    return len + 2u;
}

unsigned r8_dec_request(r8_u8 *out)
{
    r8_u8 body[3];
    body[0] = R8_PKT_REQUEST;
    return to_device(out, body, 1, R8_DEC_REQUEST_BYTES);
}

unsigned r8_dec_input(r8_u8 *out, r8_u16 keys)
{
    r8_u8 body[5];
    body[0] = R8_PKT_INPUT;
    body[1] = (r8_u8)(keys >> 8);
    body[2] = (r8_u8)(keys & 0xFFu);
    return to_device(out, body, 3, R8_DEC_INPUT_BYTES);
}
