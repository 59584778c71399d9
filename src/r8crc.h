/* r8crc.h - private to the wire encoder (src/crc16.c, src/wire.c): the
 * CRC-16/CCITT-FALSE byte step on two byte registers, the shift of a CRC
 * state over a run of zero bytes, and the encoder's kernels.
 *
 * The CRC is affine in its input: crc(c, d) = shift(c, len d) ^ crc(0, d),
 * where shift(c, m) = crc(c, m zero bytes) = c * x^(8m) mod the
 * polynomial.  wire.c uses this to get the raw band's CRC, the frame CRC
 * and the packet CRC from one CRC pass over the encoded band. */
#ifndef R8CRC_H
#define R8CRC_H

#include "r8wire.h"

/* One byte b into the CRC held as hi:lo (all r8_u8 lvalues):
 * crc' = (crc << 8) ^ (x << 12) ^ (x << 5) ^ x, x = (crc >> 8) ^ b,
 * x ^= x >> 4, done on bytes (no table). */
#define R8_CRC16_STEP(hi, lo, b)                                     \
    do {                                                             \
        r8_u8 x_ = (r8_u8)((hi) ^ (b));                              \
        x_ = (r8_u8)(x_ ^ (x_ >> 4));                                \
        (hi) = (r8_u8)((lo) ^ (r8_u8)(x_ << 4) ^ (r8_u8)(x_ >> 3));  \
        (lo) = (r8_u8)((r8_u8)(x_ << 5) ^ x_);                       \
    } while (0)

/* c followed by m zero bytes (m <= R8_RLE_MAX = 127): c * x^(8m). */
r8_u16 r8_crc16_shift(r8_u16 c, r8_u8 m);

/* ---- the band walk's kernels (one RLE token each).  The C89 versions,
 * the reference, are the r8_*_c functions.  A port that links its own
 * (assembly) versions of all five defines R8_ASM_WIRE: the names without
 * _c are then those (the AVR builds in mk/targets.mk: ports/avr/
 * wire_avr.S); otherwise they are the C versions.
 * tests/c/test_wirek.c checks that the two agree on random inputs. */
typedef struct r8_tx_st {    /* a packet being built (layout: the asm) */
    r8_u16 crc;              /* +0 packet CRC (so far) */
    r8_u8 f1, f2;            /* +2 Fletcher-16 sums of the raw band */
    r8_u8 *pkt;              /* +4 the packet: pkt[0] code, body from pkt[1] */
    r8_u8 *code;             /* +6 last code slot of the COBS chain (0: none) */
    r8_u16 g;                /* +8 CRC from 0 of the raw band so far */
} r8_tx_st;

/* A run token at p (p[0] = p[1] = p[2]): the run, at most k >= 3 bytes,
 * as [count, value] at o[0..1]; feeds the packet CRC, the band's CRC
 * and Fletcher sums (not the COBS chain).  Returns the count. */
r8_u8 r8_tx_run_c(r8_tx_st *s, r8_u8 *o, const r8_u8 *p, r8_u8 k);
/* A literal token at p (no run of 3 equal bytes starts at p): L bytes,
 * up to where the first run of 3 starts among the first k positions,
 * else c (k <= c; the other c - k positions, at most 2, start none);
 * [0x80 | L, the L bytes] at o[0..L]; feeds the packet CRC, the band's
 * CRC and Fletcher sums, and links the 0x00 among the L bytes into the
 * COBS chain.  Returns L, | 0x80 if a block got too long for the chain
 * (s->code is then the last code linked: the caller undoes the chain).
 * Reads p[0 .. k+1] and p[0 .. c-1]. */
r8_u8 r8_tx_lit_c(r8_tx_st *s, r8_u8 *o, const r8_u8 *p, r8_u8 k, r8_u8 c);

/* How many bytes of p[0..n) are 0x00 before the first other. */
unsigned r8_tx_zeros_c(const r8_u8 *p, unsigned n);

#ifdef R8_ASM_TXBAND
/* src/wire.c's r8_tx_band when a port links its own (R8_ASM_TXBAND) */
int r8_tx_band_c(r8_tx *tx, const r8_fb *band);
/* the port's packet send (with its r8_tx_band; src/wire.c R8_ASM_TXPKT):
 * the body tx->pkt[1 .. 1+n), n + 4 < 255, gets its CRC-16 (from
 * R8_CRC16_INIT, big-endian), is COBS-encoded in place (pkt[0] the first
 * code) with the delimiter, and goes out in one put; tx->bytes += n + 4 */
void r8_tx_pkt(r8_tx *tx, unsigned n);
#endif

#if defined(R8_ASM_WIRE)
unsigned r8_tx_zeros(const r8_u8 *p, unsigned n);
r8_u8 r8_tx_run(r8_tx_st *s, r8_u8 *o, const r8_u8 *p, r8_u8 k);
r8_u8 r8_tx_lit(r8_tx_st *s, r8_u8 *o, const r8_u8 *p, r8_u8 k, r8_u8 c);
r8_u16 r8_crc16_update_c(r8_u16 crc, const r8_u8 *p, unsigned n);
r8_u16 r8_crc16_mul_c(r8_u16 a, r8_u16 b);
#else
#define r8_tx_zeros r8_tx_zeros_c
#define r8_tx_run r8_tx_run_c
#define r8_tx_lit r8_tx_lit_c
#define r8_crc16_update_c r8_crc16_update
#define r8_crc16_mul_c r8_crc16_mul
#endif

#endif
