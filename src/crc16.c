/* crc16.c - CRC-16/CCITT-FALSE (a.k.a. CRC-16/IBM-3740): poly 0x1021,
 * init 0xFFFF, no reflection, xorout 0; "123456789" -> 0x29B1.
 * Nibble table: 32 bytes of constants, two lookups per byte. */
#include "r8wire.h"

static const r8_u16 crc_nib[16] = {
    0x0000, 0x1021, 0x2042, 0x3063, 0x4084, 0x50A5, 0x60C6, 0x70E7,
    0x8108, 0x9129, 0xA14A, 0xB16B, 0xC18C, 0xD1AD, 0xE1CE, 0xF1EF
};

r8_u16 r8_crc16_update(r8_u16 crc, const r8_u8 *p, unsigned n)
{
    while (n--) {
        crc = (r8_u16)(crc ^ ((r8_u16)*p++ << 8));
        crc = (r8_u16)((r8_u16)(crc << 4) ^ crc_nib[(crc >> 12) & 0x0F]);
        crc = (r8_u16)((r8_u16)(crc << 4) ^ crc_nib[(crc >> 12) & 0x0F]);
    }
    return crc;
}

r8_u16 r8_crc16(const r8_u8 *p, unsigned n)
{
    return r8_crc16_update((r8_u16)R8_CRC16_INIT, p, n);
}
