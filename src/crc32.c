/* crc32.c - CRC-32 (ISO-HDLC, as zlib and Ethernet): poly 0x04C11DB7
 * reflected (0xEDB88320), init and xorout 0xFFFFFFFF; "123456789" ->
 * 0xCBF43926.  The version-2 frame check (docs/protocol.md section 4.1):
 * a different polynomial from the packet CRC-16, so an error the packet
 * CRC misses is not missed by the frame check as well.  A nibble at a
 * time from a 16-entry table in flash (64 bytes), kept as two 16-bit
 * halves so that R8_RDU16 reads it on every target. */
#include "r8wire.h"
#include "r8flash.h"

static const r8_u16 crc32_hi[16] R8_FLASH = {
    0x0000u, 0x1DB7u, 0x3B6Eu, 0x26D9u, 0x76DCu, 0x6B6Bu, 0x4DB2u, 0x5005u,
    0xEDB8u, 0xF00Fu, 0xD6D6u, 0xCB61u, 0x9B64u, 0x86D3u, 0xA00Au, 0xBDBDu
};
static const r8_u16 crc32_lo[16] R8_FLASH = {
    0x0000u, 0x1064u, 0x20C8u, 0x30ACu, 0x4190u, 0x51F4u, 0x6158u, 0x713Cu,
    0x8320u, 0x9344u, 0xA3E8u, 0xB38Cu, 0xC2B0u, 0xD2D4u, 0xE278u, 0xF21Cu
};

static r8_u32 nibble(r8_u32 c)
{
    unsigned i = (unsigned)(c & 15u);
    return (c >> 4) ^ ((r8_u32)R8_RDU16(&crc32_hi[i]) << 16) ^
           (r8_u32)R8_RDU16(&crc32_lo[i]);
}

r8_u32 r8_crc32_update(r8_u32 crc, const r8_u8 *p, unsigned n)
{
    crc ^= (r8_u32)0xFFFFFFFFuL;
    while (n--) {
        crc ^= *p++;
        crc = nibble(crc);
        crc = nibble(crc);
    }
    return crc ^ (r8_u32)0xFFFFFFFFuL;
}

r8_u32 r8_crc32(const r8_u8 *p, unsigned n)
{
    return r8_crc32_update(0, p, n);
}
