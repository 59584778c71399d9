/* crc16.c - CRC-16/CCITT-FALSE (a.k.a. CRC-16/IBM-3740): poly 0x1021,
 * init 0xFFFF, no reflection, xorout 0; "123456789" -> 0x29B1.
 * Byte at a time without a table (the 0x1021 polynomial's shift-xor
 * form) on bytes: no constants in RAM, 27 AVR cycles per byte (the nibble
 * table took 80).
 *
 * The algebra the wire encoder uses (src/r8crc.h): a CRC state is a
 * polynomial of degree < 16 over GF(2); a zero byte multiplies it by
 * x^8 modulo P = x^16 + x^12 + x^5 + 1.  r8_crc16_mul multiplies two
 * states modulo P (16 shift-xor steps), xp8[m] = x^(8m) mod P. */
#include "r8crc.h"
#include "r8flash.h"

/* With R8_ASM_WIRE, r8_crc16_update and r8_crc16_mul are the AVR
 * assembly (ports/avr/wire_avr.S) and these the reference. */
r8_u16 r8_crc16_update_c(r8_u16 crc, const r8_u8 *p, unsigned n)
{
    r8_u8 hi = (r8_u8)(crc >> 8), lo = (r8_u8)(crc & 0xFFu);
    while (n--) {
        r8_u8 b = *p++;
        R8_CRC16_STEP(hi, lo, b);
    }
    return (r8_u16)(((r8_u16)hi << 8) | lo);
}

r8_u16 r8_crc16(const r8_u8 *p, unsigned n)
{
    return r8_crc16_update((r8_u16)R8_CRC16_INIT, p, n);
}

r8_u16 r8_crc16_mul_c(r8_u16 a, r8_u16 b)
{
    r8_u16 r = 0;
    r8_u8 k, bb = (r8_u8)(b >> 8), half = 2;
    while (half--) {
        for (k = 8; k; k--) {
            if (r & 0x8000u)
                r = (r8_u16)((r8_u16)(r << 1) ^ 0x1021u);
            else
                r = (r8_u16)(r << 1);
            if (bb & 0x80u)
                r ^= a;
            bb = (r8_u8)(bb << 1);
        }
        bb = (r8_u8)(b & 0xFFu);
    }
    return r;
}

/* x^(8m) mod P for m = 0..127: 1 followed by m zero bytes (256 bytes of
 * flash; tests/c/test_wire.c checks every entry against zero bytes). */
static const r8_u16 xp8[128] R8_FLASH = {
    0x0001u, 0x0100u, 0x1021u, 0x3331u, 0x3730u, 0x76B4u, 0xAA51u, 0x45A0u,
    0xB861u, 0x47D3u, 0xEB23u, 0x6F45u, 0xD849u, 0x0375u, 0x4563u, 0x7B61u,
    0xAEFCu, 0xA824u, 0x10E2u, 0xF031u, 0xDE1Fu, 0x35B3u, 0xD5F6u, 0x6DD8u,
    0x650Bu, 0x3703u, 0x45B4u, 0xAC61u, 0x1566u, 0x2494u, 0xF0E6u, 0x091Fu,
    0x8E29u, 0x5946u, 0x8DDCu, 0x9C25u, 0x6735u, 0x2941u, 0xF44Bu, 0xE49Bu,
    0x26AAu, 0xEEA4u, 0xB8E0u, 0xC6D3u, 0x6A8Au, 0x47ECu, 0xD423u, 0xA8F9u,
    0xCDE2u, 0xEAE1u, 0xBD64u, 0x1276u, 0x4473u, 0x7B40u, 0x8FFCu, 0x9C67u,
    0x2535u, 0x41C7u, 0x9FE5u, 0x9756u, 0xA55Eu, 0xBB4Fu, 0x59B0u, 0x7BDCu,
    0x13FCu, 0xDE52u, 0x78B3u, 0x4C9Fu, 0x1648u, 0x3AF7u, 0x6019u, 0x75A6u,
    0x8832u, 0x2280u, 0x8420u, 0xF10Cu, 0xF33Eu, 0xE17Cu, 0x910Fu, 0x9C98u,
    0xDA35u, 0x5F37u, 0x9C1Au, 0x5835u, 0xEEFDu, 0xE1E0u, 0x0D0Fu, 0xDEADu,
    0x87B3u, 0x526Fu, 0x15B7u, 0xF594u, 0x2BBAu, 0x2F09u, 0xDC8Du, 0x87F1u,
    0x106Fu, 0x7D31u, 0x9E3Au, 0x5877u, 0xACFDu, 0x8966u, 0x66A1u, 0xAD60u,
    0x0447u, 0x0784u, 0xF4E7u, 0x489Bu, 0x52CCu, 0xB6B7u, 0x701Du, 0x6397u,
    0xCBC5u, 0xAD27u, 0x4347u, 0x3FA7u, 0x60BCu, 0xD0A6u, 0x6D7Du, 0xC00Bu,
    0xD24Cu, 0xA73Fu, 0xFA0Du, 0x4355u, 0x2DA7u, 0x52CFu, 0xB5B7u, 0x407Eu
};

r8_u16 r8_crc16_shift(r8_u16 c, r8_u8 m)
{
    if (!c)
        return 0;
    return r8_crc16_mul(c, R8_RDU16(&xp8[m & 0x7Fu]));
}

r8_u16 r8_crc16_xpow(unsigned n)
{
    r8_u16 r = R8_RDU16(&xp8[n & 0x7Fu]);
    r8_u16 base = r8_crc16_mul(R8_RDU16(&xp8[127]), 0x0100u); /* x^(8*128) */
    for (n >>= 7; n; n >>= 1) {
        if (n & 1u)
            r = r8_crc16_mul(r, base);
        base = r8_crc16_mul(base, base);
    }
    return r;
}
