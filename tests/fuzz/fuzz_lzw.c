/* fuzz_lzw.c - libFuzzer target: the LZW decoder on arbitrary input into
 * an output buffer of exactly `cap` bytes (heap, so ASan sees any write
 * past it), and encode -> decode round trips of arbitrary data. */
#include <stdlib.h>
#include <string.h>
#include "r8codec.h"

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
    unsigned cap, out = 0, n2 = 0, i;
    unsigned char *dst, *enc, *dec;
    int rc;
    if (size < 2 || size > 65535)
        return 0;
    cap = (unsigned)data[0] | ((unsigned)data[1] & 0x0F) << 8;   /* 0..4095 */
    data += 2;
    size -= 2;
    dst = (unsigned char *)malloc(cap ? cap : 1);
    rc = r8_lzw_decode(data, (unsigned)size, dst, cap, &out);
    if (rc == R8_OK && out > cap)
        abort();
    if (rc != R8_OK && rc != R8_E_SPACE && rc != R8_E_MALFORMED && rc != R8_E_TRUNC && rc != R8_E_ARG)
        abort();
    free(dst);
    /* round trip */
    enc = (unsigned char *)malloc(R8_LZW_BOUND(size) + 1);
    dec = (unsigned char *)malloc(size + 1);
    rc = r8_lzw_encode(data, (unsigned)size, enc, R8_LZW_BOUND(size), &out);
    if (rc != R8_OK || out > R8_LZW_BOUND(size))
        abort();
    rc = r8_lzw_decode(enc, out, dec, (unsigned)size, &n2);
    if (rc != R8_OK || n2 != size)
        abort();
    for (i = 0; i < size; i++)
        if (dec[i] != data[i])
            abort();
    free(enc);
    free(dec);
    return 0;
}
