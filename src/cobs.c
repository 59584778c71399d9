/* cobs.c - Consistent Overhead Byte Stuffing (Cheshire & Baker 1999).
 * A block is a code byte k (1..255) and k-1 non-zero bytes; a code
 * below 255 stands for a 0x00 after its block, except at the end of the
 * packet.  No 0x00 appears in the output, so 0x00 delimits packets.
 * r8_cobs_encode is in cobs_enc.c: the firmware does not need it (the
 * 6502 and Z80 linkers take whole files). */
#include "r8wire.h"

int r8_cobs_decode(const r8_u8 *src, unsigned n, r8_u8 *dst, unsigned cap,
                   unsigned *out_len)
{
    unsigned i = 0, o = 0, k;
    r8_u8 code;
    *out_len = 0;
    while (i < n) {
        code = src[i++];
        if (code == 0)
            return R8_E_MALFORMED;
        if (n - i < (unsigned)code - 1u)
            return R8_E_TRUNC;
        if (cap - o < (unsigned)code - 1u)
            return R8_E_SPACE;
        for (k = 1; k < code; k++) {
            if (src[i] == 0)
                return R8_E_MALFORMED;
            dst[o++] = src[i++];
        }
        if (code != 0xFF && i < n) {
            if (o >= cap)
                return R8_E_SPACE;
            dst[o++] = 0;
        }
    }
    *out_len = o;
    return R8_OK;
}

void r8_cobs_write(const r8_u8 *src, unsigned n, r8_put_fn put, void *ctx)
{
    unsigned i = 0, k;
    r8_u8 code;
    for (;;) {
        /* block: up to 254 non-zero bytes from i */
        k = 0;
        while (i + k < n && k < 254u && src[i + k] != 0)
            k++;
        code = (r8_u8)(k + 1u);
        put(ctx, &code, 1);
        if (k)
            put(ctx, src + i, k);
        i += k;
        if (k == 254u) {
            if (i >= n)
                return;
            continue; /* 0xFF block: no implied zero */
        }
        if (i >= n)
            return;
        i++; /* skip the zero this block stands for */
        /* a zero as the last byte still needs a final (empty) block */
    }
}
