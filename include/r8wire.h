/* r8wire.h - the serial display protocol (docs/protocol.md, versions 1, 2):
 * CRC-16/CCITT-FALSE, COBS framing, the band-by-band frame encoder
 * (firmware side) and the byte-at-a-time frame decoder (display side).
 *
 * A packet is  body || CRC-16/CCITT-FALSE(body) (big-endian), COBS
 * encoded, followed by one 0x00 delimiter.  Multi-byte fields are
 * big-endian.  Bodies:
 *   FRAME_START 01 ver frame:2 width:2 height:2 format band:2 codec
 *               flags npal pal[npal*3]           (flags bit 0 = full)
 *   BAND        02 frame:2 y0:2 codec payload...  (payload = the band
 *               buffer's bytes, encoded with codec)
 *   FRAME_END   03 frame:2 nbands:2 fcrc:2        (bands sent, CRC of
 *               the whole raw frame, clean bands included; version 2:
 *               fcrc:4, a CRC-32)
 *   REQUEST     10                                (display -> device:
 *               send a full frame next)
 *   INPUT       11 keys:2                         (display -> device: the
 *               state of the keys, R8_KEY_* bits, 1 = pressed)
 * Kinds 10..1F go from the display to the device; a display decoder
 * ignores them (an echo), a device ignores the ones it does not know.
 */
#ifndef R8WIRE_H
#define R8WIRE_H

#include "r8types.h"
#include "r8fb.h"
#include "r8codec.h"

#define R8_WIRE_VERSION 1
/* Version 2 (docs/protocol.md section 4.1): FRAME_END carries a CRC-32
 * of the frame (fcrc:4, R8_WIRE_END2_BYTES) instead of the CRC-16, whose
 * polynomial is the packet CRC's and so misses every error the packet
 * CRC misses in a band's literal bytes.  Decoders accept both. */
#define R8_WIRE_VERSION2 2

#define R8_PKT_FRAME_START 0x01
#define R8_PKT_BAND 0x02
#define R8_PKT_FRAME_END 0x03
#define R8_PKT_REQUEST 0x10
#define R8_PKT_INPUT 0x11
#define R8_PKT_TO_DEVICE_FIRST 0x10     /* kinds 10..1F: display -> device */
#define R8_PKT_TO_DEVICE_LAST 0x1F

/* INPUT key bits (docs/protocol.md section 2.1) */
#define R8_KEY_UP 0x0001u
#define R8_KEY_DOWN 0x0002u
#define R8_KEY_LEFT 0x0004u
#define R8_KEY_RIGHT 0x0008u
#define R8_KEY_A 0x0010u
#define R8_KEY_B 0x0020u
#define R8_KEY_START 0x0040u
#define R8_KEY_SELECT 0x0080u
#define R8_KEY_X 0x0100u
#define R8_KEY_Y 0x0200u
#define R8_KEY_L 0x0400u
#define R8_KEY_R 0x0800u

#define R8_FLAG_FULL 0x01               /* bits 1..7 reserved: sent 0, ignored */

#define R8_WIRE_CRC_BYTES 2
#define R8_WIRE_START_BYTES 14          /* FRAME_START body without palette */
#define R8_WIRE_BAND_HDR 6              /* BAND body before the payload */
#define R8_WIRE_END_BYTES 7             /* FRAME_END body */
#define R8_WIRE_END2_BYTES 9            /* FRAME_END body, version 2 */
#define R8_WIRE_MAX_BAND 32767u         /* largest raw band in bytes */
#define R8_WIRE_MAX_DIM 4095            /* largest width/height */

/* ---- CRC-16/CCITT-FALSE: poly 0x1021, init 0xFFFF, no reflection,
 * xorout 0; check("123456789") = 0x29B1. */
#define R8_CRC16_INIT 0xFFFFu
r8_u16 r8_crc16_update(r8_u16 crc, const r8_u8 *p, unsigned n);
r8_u16 r8_crc16(const r8_u8 *p, unsigned n);
/* CRC algebra: a CRC state is a polynomial over GF(2) modulo P = 0x11021.
 * r8_crc16_mul(a, b) = a * b mod P; r8_crc16_xpow(n) = x^(8n) mod P, so
 * r8_crc16_mul(c, r8_crc16_xpow(n)) = r8_crc16_update(c, <n zero bytes>),
 * and r8_crc16_update(c, d) = that ^ r8_crc16_update(0, d) for n = |d|. */
r8_u16 r8_crc16_mul(r8_u16 a, r8_u16 b);
r8_u16 r8_crc16_xpow(unsigned n);
/* CRC-32 (ISO-HDLC, zlib's crc32): "123456789" -> 0xCBF43926.  The
 * version-2 frame check.  r8_crc32_update(r8_crc32(a), b) = CRC of a||b;
 * start from 0. */
r8_u32 r8_crc32_update(r8_u32 crc, const r8_u8 *p, unsigned n);
r8_u32 r8_crc32(const r8_u8 *p, unsigned n);

/* ---- COBS (Cheshire & Baker).  Encoded size of n bytes is at most
 * R8_COBS_BOUND(n) (no delimiter included). */
#define R8_COBS_BOUND(n) ((unsigned)(n) + (unsigned)(n) / 254u + 1u)

typedef void (*r8_put_fn)(void *ctx, const r8_u8 *p, unsigned n);

int r8_cobs_encode(const r8_u8 *src, unsigned n, r8_u8 *dst, unsigned cap,
                   unsigned *out_len);
/* src holds one packet without its delimiter; a 0x00 inside is malformed. */
int r8_cobs_decode(const r8_u8 *src, unsigned n, r8_u8 *dst, unsigned cap,
                   unsigned *out_len);
/* Stream the COBS encoding of src through put (no buffer; no delimiter). */
void r8_cobs_write(const r8_u8 *src, unsigned n, r8_put_fn put, void *ctx);

/* ---- sizes */
/* Bands in a frame. */
#define R8_WIRE_NBANDS(height, band) \
    (((unsigned)(height) + (unsigned)(band) - 1u) / (unsigned)(band))
/* Largest packet body (+CRC) for a raw band of band_bytes, with a
 * palette of npal entries in the frame start.  No ?: (cc65 cannot use
 * it in the constant expression of a static array size). */
#define R8_WIRE_MAX_(a, b) ((a) + ((b) > (a)) * ((b) - (a)))
#define R8_WIRE_PKT_BYTES(band_bytes, npal) \
    (R8_WIRE_MAX_((unsigned)(band_bytes) + R8_WIRE_BAND_HDR, \
                  R8_WIRE_START_BYTES + 3u * (unsigned)(npal)) + R8_WIRE_CRC_BYTES)
/* Encoder scratch: one packet with a byte before it and one after it
 * (the packet is COBS-encoded in place and sent with its delimiter in
 * one put call), plus 4 bytes of fingerprint per band. */
#define R8_TX_SCRATCH_BYTES(band_bytes, nbands, npal) \
    (R8_WIRE_PKT_BYTES(band_bytes, npal) + 2u + 4u * (unsigned)(nbands))

/* ---- the frame encoder (firmware side) */
typedef struct r8_tx_cfg {
    r8_u8 format;            /* R8_FMT_* */
    r8_s16 width, height;
    r8_s16 band;             /* rows per band (multiple of 8 for PAGE1) */
    r8_u8 codec;             /* R8_CODEC_*; raw is used per band if smaller */
    r8_u16 full_period;      /* full frame every N frames; 0 = only the
                                first and requested ones */
    r8_u8 dirty;             /* 1: send only changed bands in between */
    const r8_u8 *palette;    /* npal RGB triples (IDX8), or 0 */
    r8_u8 npal;
} r8_tx_cfg;

typedef struct r8_tx {
    r8_tx_cfg cfg;
    r8_put_fn put;
    void *ctx;
    r8_u8 *pkt;              /* packet scratch: code byte, body, CRC, 0 */
    unsigned pkt_size;
    r8_u8 *fp;               /* 4-byte fingerprint per band */
    unsigned nbands;
    unsigned band_bytes;     /* raw bytes of a full band */
    r8_u16 xn;               /* x^(8n) mod P, n = band_bytes */
    r8_s16 next_y;           /* y0 of the band expected next */
    unsigned next_idx;       /* its index */
    r8_u16 frame;            /* current frame number */
    r8_u16 since_full;       /* frames since the last full frame */
    r8_u16 sent;             /* bands sent in this frame */
    r8_u16 fcrc;             /* running CRC of the raw frame */
    r8_u16 hcrc;             /* CRC of this frame's BAND header bytes 0..2 */
    r8_u8 full;              /* this frame is full */
    r8_u8 want_full;         /* a full frame was requested / is due */
    r8_u8 in_frame;
    r8_u8 rx[8];             /* request/input parser */
    r8_u8 rx_len;
    r8_u16 keys;             /* last INPUT key state (R8_KEY_* bits) */
    r8_u16 inputs;           /* INPUT packets accepted (wraps) */
    r8_u32 bytes;            /* bytes written, delimiters included */
    r8_u32 raw_bytes;        /* raw frame bytes rendered */
} r8_tx;

/* Scratch bytes r8_tx_init needs for cfg; 0 if cfg is invalid. */
unsigned r8_tx_scratch(const r8_tx_cfg *cfg);
/* Raw bytes of one band buffer for cfg; 0 if invalid. */
unsigned r8_tx_band_bytes(const r8_tx_cfg *cfg);
/* 0, R8_E_ARG for a bad cfg, R8_E_SPACE if scratch is too small.
 * Writes nothing; call r8_tx_sync to start a stream. */
int r8_tx_init(r8_tx *tx, const r8_tx_cfg *cfg, r8_u8 *scratch,
               unsigned scratch_size, r8_put_fn put, void *ctx);
/* One 0x00: ends any partial packet a listener may hold. */
void r8_tx_sync(r8_tx *tx);
/* Ask for a full frame at the next r8_tx_frame_begin. */
void r8_tx_request_full(r8_tx *tx);
/* Feed one byte received from the display.  A valid REQUEST packet
 * calls r8_tx_request_full and returns 1; a valid INPUT packet stores
 * its key state in tx->keys, counts it in tx->inputs and returns 2;
 * anything else (partial packet, bad CRC, unknown kind, wrong length)
 * returns 0 and changes nothing. */
#define R8_RX_REQUEST 1
#define R8_RX_INPUT 2
int r8_tx_rx(r8_tx *tx, r8_u8 c);
/* Begin frame `frame`: decides full/delta and sends FRAME_START. */
int r8_tx_frame_begin(r8_tx *tx, r8_u16 frame);
/* One rendered band (bands in order, top to bottom, each exactly once):
 * sent if the frame is full or the band changed. */
int r8_tx_band(r8_tx *tx, const r8_fb *band);
/* Sends FRAME_END. */
int r8_tx_frame_end(r8_tx *tx);

/* ---- the frame decoder (display side): byte at a time, fixed memory.
 * Rules (docs/protocol.md section 4): a frame is good only when its
 * start, every band it announced (every band for a FULL frame, in
 * increasing y0) and its end arrived intact, a delta frame's number is
 * the last good frame's number + 1, and the CRC of the assembled frame
 * matches (CRC-16 in version 1, CRC-32 in version 2).  Identical repeats
 * of a packet are ignored. */
#define R8_DEC_NONE 0       /* nothing finished */
#define R8_DEC_FRAME 1      /* a complete, CRC-checked frame is in fb */
#define R8_DEC_PACKET 2     /* a packet was accepted (not a frame end) */
#define R8_DEC_BAD 3        /* a packet was rejected (CRC, framing, ...) */
#define R8_DEC_INCOMPLETE 4 /* a frame ended but is not good */

typedef struct r8_dec {
    r8_u8 *pkt;              /* packet buffer */
    unsigned pkt_size;
    unsigned pkt_len;
    r8_u8 code;              /* COBS: current block code */
    r8_u8 left;              /* COBS: bytes left in the block */
    r8_u8 overflow;          /* packet did not fit: drop it */
    r8_u8 synced;            /* a 0x00 has been seen */
    r8_u8 *fb;               /* the display frame (caller's) */
    unsigned fb_size;
    r8_u8 *pal;              /* caller's palette store (3 * 256) or 0 */
    unsigned pal_size;
    /* current frame */
    r8_u8 in_frame, full, format, codec, valid, npal;
    r8_u8 version;           /* its FRAME_START's version (1 or 2) */
    r8_u16 frame, nbands_got, width, height, band;
    r8_u16 next_y;           /* smallest y0 the next band may have */
    r8_u16 last_y0;          /* y0 of the last band accepted */
    r8_u16 start_crc;        /* packet CRC of this frame's FRAME_START */
    r8_u16 band_crc;         /* packet CRC of the last band accepted */
    r8_u16 last_seen;        /* newest frame number seen */
    r8_u8 have_last;         /* last_seen is set */
    r8_u8 base_ok;           /* fb holds good frame good_no (this geometry) */
    r8_u16 good_no;          /* number of the last good frame */
    r8_u8 ever_good;         /* a good frame has been seen (joined) */
    r8_u8 have_failed;       /* failed_no is set */
    r8_u16 failed_no;        /* last frame counted incomplete/skipped */
    r8_u8 need_full;         /* ask the device for a full frame */
    unsigned frame_bytes;
    /* counters (docs/protocol.md section 5) */
    r8_u32 bytes;            /* bytes fed */
    r8_u32 packets;          /* packets accepted (good CRC, well formed) */
    r8_u32 bad_packets;      /* CRC/COBS/format/size failures */
    r8_u32 frames;           /* good frames */
    r8_u32 dropped;          /* frame numbers never seen */
    r8_u32 incomplete;       /* frames started but not good */
    r8_u32 skipped;          /* delta frames before the first good frame */
    r8_u32 ignored;          /* accepted packets that changed nothing */
} r8_dec;

/* Packet buffer bytes a decoder needs for frames up to fb_bytes raw
 * (one band may be the whole frame) and a 256-entry palette. */
#define R8_DEC_PKT_BYTES(fb_bytes) R8_WIRE_PKT_BYTES(fb_bytes, 256)

void r8_dec_init(r8_dec *d, r8_u8 *pkt, unsigned pkt_size, r8_u8 *fb,
                 unsigned fb_size, r8_u8 *pal, unsigned pal_size);
/* Feed one byte; returns R8_DEC_*. */
int r8_dec_feed(r8_dec *d, r8_u8 c);
/* End of input: an unterminated packet counts as bad, an open frame as
 * incomplete.  Returns R8_DEC_BAD, R8_DEC_INCOMPLETE or R8_DEC_NONE. */
int r8_dec_end(r8_dec *d);
/* Body of the REQUEST packet, COBS-encoded with delimiters, into out
 * (at least R8_DEC_REQUEST_BYTES); returns its length. */
#define R8_DEC_REQUEST_BYTES 6
unsigned r8_dec_request(r8_u8 *out);
/* The INPUT packet for key state `keys`, COBS-encoded with delimiters,
 * into out (at least R8_DEC_INPUT_BYTES); returns its length. */
#define R8_DEC_INPUT_BYTES 8
unsigned r8_dec_input(r8_u8 *out, r8_u16 keys);

#endif
