/* fw_codecs.c - the band codecs' cost on the target (bench/bench.py, the
 * "codecs" piece: ATmega1284P, 6502, Z80).  A rendered frame (the cube,
 * PAGE1 128x64, bench/codec_frame.h) is encoded band by band (8 bands of
 * 128 bytes, output capped at 127 bytes as src/wire.c does: a codec that
 * would not make a band smaller stops there) with each codec, then
 * decoded.  Each piece is bracketed by plat_mark(10 + 2k) /
 * plat_mark(11 + 2k) (avrsim and prof65 log the cycles between markers,
 * sz80run the T-states); the stream gets "NAME bytes=1024 out=N" per
 * piece, N the payload bytes (raw for a band no codec shrinks), with
 * the CRC-16 of the codec ids and payloads: bench/bench.py checks it
 * equals the Python codecs' (host/rast8/codec.py) on every CPU.
 * "best" is src/wire.c's per-band choice (tx_more): every codec tried
 * with the cap the best so far leaves, then the winner encoded again
 * unless it was the last one tried.
 * Last, the frame is sent through the wire encoder (src/wire.c, built
 * into this program with the per-band choice, which the target archives
 * leave out) as one full frame with R8_CODEC_BEST: "stream bytes=N
 * crc=C", the CRC-16 of the stream, which bench/codec_bench.py checks
 * against the Python encoder's (the same frame on every CPU). */
#include "plat.h"
#include "r8flash.h"
#include "r8codec.h"
#include "r8wire.h"
#include "codec_frame.h"
#include "wire.c" /* with Huffman, LZW and the choice (-Isrc) */

#define NB 8
#define BB 128
static r8_u8 buf[NB * BB];
static r8_u8 back[BB];
static unsigned enc_len[NB];
static r8_u8 enc_codec[NB];
static r8_u8 enc_buf[NB][BB];

static void put_s(const char *s)
{
    while (*s)
        plat_putc((r8_u8)*s++);
}

static void put_u(unsigned long v)
{
    char d[12];
    int n = 0;
    do {
        d[n++] = (char)('0' + (int)(v % 10u));
        v /= 10u;
    } while (v);
    while (n)
        plat_putc((r8_u8)d[--n]);
}

static r8_u16 crc;

static void line(const char *name, unsigned long outb, unsigned bad)
{
    put_s(name);
    put_s(" bytes=");
    put_u((unsigned long)sizeof buf);
    put_s(" out=");
    put_u(outb);
    put_s(" bad=");
    put_u(bad);
    put_s(" crc=");
    put_u(crc);
    plat_putc('\n');
}

/* src/wire.c's tx_more with R8_CODEC_BEST */
static r8_u8 best(const r8_u8 *src, unsigned n, r8_u8 *dst, unsigned *len)
{
    r8_u8 k, b = R8_CODEC_RAW;
    unsigned cap = n - 1u, l;
    for (k = R8_CODEC_RLE; k < R8_CODEC_COUNT; k++)
        if (r8_codec_encode(k, src, n, dst, cap, &l) == R8_OK) {
            b = k;
            *len = l;
            cap = l - 1u;
        }
    if (b != R8_CODEC_RAW && b != R8_CODEC_COUNT - 1)
        r8_codec_encode(b, src, n, dst, *len, len);
    return b;
}

static r8_u16 scrc;
static r8_u16 slen;
static void sput(void *ctx, const r8_u8 *p, unsigned n)
{
    (void)ctx;
    scrc = r8_crc16_update(scrc, p, n);
    slen = (r8_u16)(slen + n);
}

static r8_tx tx;
static r8_u8 scratch[R8_TX_SCRATCH_BYTES(BB, NB, 0)];

static void stream(void)
{
    r8_tx_cfg cfg;
    r8_fb fb;
    unsigned k;
    cfg.format = R8_FMT_PAGE1;
    cfg.width = 128;
    cfg.height = 64;
    cfg.band = 8;
    cfg.codec = R8_CODEC_BEST;
    cfg.full_period = 0;
    cfg.dirty = 1;
    cfg.palette = 0;
    cfg.npal = 0;
    scrc = R8_CRC16_INIT;
    slen = 0;
    if (r8_tx_init(&tx, &cfg, scratch, sizeof scratch, sput, 0) != R8_OK)
        return;
    plat_mark(40);
    r8_tx_frame_begin(&tx, 0);
    for (k = 0; k < NB; k++) {
        r8_fb_init(&fb, buf + k * BB, R8_FMT_PAGE1, 128, 64, (r8_s16)(k * 8u), 8);
        r8_tx_band(&tx, &fb);
    }
    r8_tx_frame_end(&tx);
    plat_mark(41);
}

int main(void)
{
    unsigned i, k, len, bad;
    unsigned long tot;
    r8_u8 c, mk = 10;
    plat_init();
    for (i = 0; i < sizeof buf; i++)
        buf[i] = R8_RDU8(&frame_raw[i]);
    /* encode: codecs 1..4, then best (ids 1..5 in marker order) */
    for (c = R8_CODEC_RLE; c <= R8_CODEC_COUNT; c++) {
        tot = 0;
        plat_mark(mk);
        for (k = 0; k < NB; k++) {
            if (c == R8_CODEC_COUNT) {
                enc_codec[k] = best(buf + k * BB, BB, enc_buf[k], &len);
            } else {
                enc_codec[k] = c;
                if (r8_codec_encode(c, buf + k * BB, BB, enc_buf[k], BB - 1u, &len) != R8_OK)
                    enc_codec[k] = R8_CODEC_RAW;
            }
            if (enc_codec[k] == R8_CODEC_RAW)
                len = BB;
            enc_len[k] = len;
            tot += len;
        }
        plat_mark((r8_u8)(mk + 1));
        mk = (r8_u8)(mk + 2);
        /* the payloads' CRC (the same on every CPU and the host) */
        crc = R8_CRC16_INIT;
        for (k = 0; k < NB; k++) {
            crc = r8_crc16_update(crc, &enc_codec[k], 1);
            if (enc_codec[k] == R8_CODEC_RAW)
                crc = r8_crc16_update(crc, buf + k * BB, BB);
            else
                crc = r8_crc16_update(crc, enc_buf[k], enc_len[k]);
        }
        /* decode what was sent (raw bands are copied by the display) */
        bad = 0;
        plat_mark(mk);
        for (k = 0; k < NB; k++)
            if (enc_codec[k] != R8_CODEC_RAW &&
                (r8_codec_decode(enc_codec[k], enc_buf[k], enc_len[k], back, BB, &len) != R8_OK ||
                 len != BB))
                bad++;
        plat_mark((r8_u8)(mk + 1));
        mk = (r8_u8)(mk + 2);
        for (k = 0; k < NB; k++)
            if (enc_codec[k] != R8_CODEC_RAW) {
                r8_codec_decode(enc_codec[k], enc_buf[k], enc_len[k], back, BB, &len);
                for (i = 0; i < BB; i++)
                    if (back[i] != buf[k * BB + i])
                        bad++;
            }
        if (c == R8_CODEC_COUNT) /* (cc65: no ?: on pointers) */
            line("best", tot, bad);
        else
            line(r8_codec_name(c), tot, bad);
    }
    crc = 0;
    stream();
    crc = scrc;
    line("stream", slen, 0);
    plat_exit(0);
    return 0;
}
