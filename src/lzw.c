/* lzw.c - LZW codec with a 128-entry dictionary (docs/protocol.md 3.5,
 * see r8codec.h).
 *
 * Format: 9-bit codes, MSB first, the last byte padded with 0 bits.
 * Code c < 256 is the byte c; code 256 + d is dictionary entry d.  Entry
 * d is made of phrase d (the string of the d-th code) and the first byte
 * of phrase d + 1; entries 0..R8_LZW_DICT-1 are made, then the
 * dictionary stays as it is.  Phrase p may use entries d < p (entry p - 1
 * being then phrase p - 1 followed by its own first byte).
 *
 * Memory: every phrase is a piece of the band (the encoder's input, the
 * decoder's output), phrase d starting where phrase d - 1 ends, so entry
 * d is band[start(d) .. start(d) + len(d)] with start(d) the sum of the
 * lengths before it.  Both sides keep only len(d), one byte each (at
 * most R8_LZW_DICT + 1): R8_LZW_DICT = 128 bytes on the stack, no hash,
 * no trie.  The encoder finds the longest entry by trying each one (the
 * dictionary holds each string once, and every prefix of an entry, so
 * the longest match is the one a trie walk would find).
 * -DR8_NO_LZW leaves it out. */
#include "r8codec.h"

#ifndef R8_NO_LZW

#if R8_LZW_DICT > 254 || R8_LZW_DICT + 256 > (1 << R8_LZW_BITS)
#error "R8_LZW_DICT must fit in one byte of length and in the code"
#endif

int r8_lzw_encode(const r8_u8 *src, unsigned n, r8_u8 *dst, unsigned cap,
                  unsigned *out_len)
{
    r8_u8 plen[R8_LZW_DICT];
    unsigned i = 0, o = 0, p = 0, d, nd, start, best, code, l, el, acc = 0, nb = 0;
    *out_len = 0;
    while (i < n) {
        /* the longest entry that src[i..] starts with */
        best = 1;
        code = src[i];
        nd = p < R8_LZW_DICT ? p : R8_LZW_DICT;
        start = 0;
        for (d = 0; d < nd; d++) {
            el = plen[d] + 1u; /* entry d: src[start .. start + el) */
            if (el > best && el <= n - i && src[start] == src[i]) {
                for (l = 1; l < el && src[start + l] == src[i + l]; l++)
                    ;
                if (l == el) {
                    best = el;
                    code = 256u + d;
                }
            }
            start += plen[d];
        }
        if (p < R8_LZW_DICT)
            plen[p] = (r8_u8)best;
        p++;
        i += best;
        /* 9 bits: acc holds < 8 + 9 bits */
        acc = (acc << R8_LZW_BITS) | code;
        nb += R8_LZW_BITS;
        while (nb >= 8u) {
            nb -= 8u;
            if (o >= cap)
                return R8_E_SPACE;
            dst[o++] = (r8_u8)((acc >> nb) & 0xFFu);
        }
        acc &= (1u << nb) - 1u;
    }
    if (nb) {
        if (o >= cap)
            return R8_E_SPACE;
        dst[o++] = (r8_u8)((acc << (8u - nb)) & 0xFFu);
    }
    *out_len = o;
    return R8_OK;
}

int r8_lzw_decode(const r8_u8 *src, unsigned n, r8_u8 *dst, unsigned cap,
                  unsigned *out_len)
{
    r8_u8 plen[R8_LZW_DICT];
    unsigned i = 0, o = 0, p = 0, d, start, code, el, k, acc = 0, nb = 0;
    *out_len = 0;
    for (;;) {
        while (nb < R8_LZW_BITS && i < n) {
            acc = (acc << 8) | src[i++];
            nb += 8u;
        }
        if (nb < R8_LZW_BITS) {
            /* the padding: fewer than 8 bits, all 0 */
            if (nb >= 8u)
                return R8_E_TRUNC;
            if (acc & ((1u << nb) - 1u))
                return R8_E_MALFORMED;
            break;
        }
        nb -= R8_LZW_BITS;
        code = (acc >> nb) & ((1u << R8_LZW_BITS) - 1u);
        acc &= (1u << nb) - 1u;
        if (code < 256u) {
            if (o >= cap)
                return R8_E_SPACE;
            dst[o++] = (r8_u8)code;
            el = 1;
        } else {
            d = code - 256u;
            /* entries 0..p-1 exist (entry p - 1 ends with this phrase's
             * first byte, which is its own first byte) */
            if (d >= p || d >= R8_LZW_DICT)
                return R8_E_MALFORMED;
            start = 0;
            for (k = 0; k < d; k++)
                start += plen[k];
            el = plen[d] + 1u;
            if (cap - o < el)
                return R8_E_SPACE;
            /* forward, byte by byte: entry p - 1 overlaps its copy */
            for (k = 0; k < el; k++) {
                dst[o] = dst[start + k];
                o++;
            }
        }
        if (p < R8_LZW_DICT)
            plen[p] = (r8_u8)el;
        p++;
        *out_len = o;
    }
    *out_len = o;
    return R8_OK;
}
#else
typedef int r8_lzw_left_out; /* (ISO C wants a declaration in a file) */
#endif
