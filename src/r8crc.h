/* r8crc.h - private to the wire encoder (src/crc16.c, src/wire.c): the
 * CRC-16/CCITT-FALSE byte step on two byte registers, and the shift of
 * a CRC state over a run of zero bytes.
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

#endif
