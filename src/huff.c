/* huff.c - static canonical Huffman codec (docs/protocol.md 3.4, see
 * r8codec.h).  One table for every band (src/huff_tab.h, tuned by
 * tools/huff_tune.py): nothing is sent but the codes, nothing is kept
 * but the buffers.  Codes are written MSB first; the last byte is padded
 * with 1 bits, a strict prefix of the all-ones longest code, so a decoder
 * knows the end without a count.  -DR8_NO_HUFF leaves it out. */
#include "r8codec.h"

#ifndef R8_NO_HUFF
#include "r8flash.h"
#include "huff_tab.h"

#if HUFF_MAXLEN != R8_HUFF_MAXLEN
#error "src/huff_tab.h does not match R8_HUFF_MAXLEN"
#endif

int r8_huff_encode(const r8_u8 *src, unsigned n, r8_u8 *dst, unsigned cap,
                   unsigned *out_len)
{
    unsigned i, o = 0, acc = 0, nb = 0, code, len, k;
    *out_len = 0;
    for (i = 0; i < n; i++) {
        code = R8_RDU16(&huff_code[src[i]]);
        len = R8_RDU8(&huff_len[src[i]]);
        /* at most 8 bits at a time: acc holds < 8 + 8 bits */
        while (len) {
            k = len > 8u ? len - 8u : len;
            len -= k;
            acc = (acc << k) | ((code >> len) & ((1u << k) - 1u));
            nb += k;
            if (nb >= 8u) {
                nb -= 8u;
                if (o >= cap)
                    return R8_E_SPACE;
                dst[o++] = (r8_u8)((acc >> nb) & 0xFFu);
                acc &= (1u << nb) - 1u;
            }
        }
    }
    if (nb) {
        if (o >= cap)
            return R8_E_SPACE;
        dst[o++] = (r8_u8)(((acc << (8u - nb)) | (0xFFu >> nb)) & 0xFFu);
    }
    *out_len = o;
    return R8_OK;
}

int r8_huff_decode(const r8_u8 *src, unsigned n, r8_u8 *dst, unsigned cap,
                   unsigned *out_len)
{
    unsigned i = 0, o = 0, code, first, index, count, len;
    r8_u8 byte = 0, left = 0; /* bits of src[i - 1] not used yet */
    *out_len = 0;
    for (;;) {
        /* the end: no bits left, or fewer than 8 left (in the last
         * byte), all 1 (the padding) */
        if (i == n && (!left || byte == (r8_u8)(0xFFu << (8u - left))))
            break;
        code = first = index = 0;
        for (len = 1;; len++) {
            if (!left) {
                if (i == n)
                    return R8_E_TRUNC;
                byte = src[i++];
                left = 8;
            }
            code |= (unsigned)(byte >> 7);
            byte = (r8_u8)(byte << 1);
            left--;
            count = R8_RDU16(&huff_cnt[len]);
            if (code - first < count)
                break;
            if (len == R8_HUFF_MAXLEN)
                return R8_E_MALFORMED; /* cannot happen: the code is complete */
            index += count;
            first = (first + count) << 1;
            code <<= 1;
        }
        if (o >= cap)
            return R8_E_SPACE;
        dst[o++] = R8_RDU8(&huff_sym[index + code - first]);
        *out_len = o;
    }
    *out_len = o;
    return R8_OK;
}
#else
typedef int r8_huff_left_out; /* (ISO C wants a declaration in a file) */
#endif
