/* crc16.c - CRC-16/CCITT-FALSE (a.k.a. CRC-16/IBM-3740): poly 0x1021,
 * init 0xFFFF, no reflection, xorout 0; "123456789" -> 0x29B1.
 * Byte at a time without a table (the 0x1021 polynomial's shift-xor
 * form) on bytes: no constants in RAM, 27 AVR cycles per byte (the nibble
 * table took 80). */
#include "r8wire.h"

r8_u16 r8_crc16_update(r8_u16 crc, const r8_u8 *p, unsigned n)
{
    /* crc' = (crc << 8) ^ (x << 12) ^ (x << 5) ^ x, with
     * x = (crc >> 8) ^ byte, x ^= x >> 4, done on the two bytes */
    r8_u8 hi = (r8_u8)(crc >> 8), lo = (r8_u8)(crc & 0xFFu);
    while (n--) {
        r8_u8 x = (r8_u8)(hi ^ *p++);
        x = (r8_u8)(x ^ (x >> 4));
        hi = (r8_u8)(lo ^ (r8_u8)(x << 4) ^ (r8_u8)(x >> 3));
        lo = (r8_u8)((r8_u8)(x << 5) ^ x);
    }
    return (r8_u16)(((r8_u16)hi << 8) | lo);
}

r8_u16 r8_crc16(const r8_u8 *p, unsigned n)
{
    return r8_crc16_update((r8_u16)R8_CRC16_INIT, p, n);
}
