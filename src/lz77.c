/* lz77.c - the seed's LZ77 codec (see r8codec.h for the format).
 * Greedy encoder with a brute-force search over the last R8_LZ77_WINDOW
 * bytes of its own input: no hash table, no memory of its own. */
#include "r8codec.h"

#ifndef R8_NO_LZ77 /* -DR8_NO_LZ77 leaves the codec out (see rle.c) */

#if R8_LZ77_WINDOW < 1 || R8_LZ77_WINDOW > 32767
#error "R8_LZ77_WINDOW must be 1..32767"
#endif

static void put16(r8_u8 *p, unsigned v)
{
    p[0] = (r8_u8)((v >> 8) & 0xFFu);
    p[1] = (r8_u8)(v & 0xFFu);
}

/* Emit src[0..len) as literal runs of at most 32767. */
static int put_lit(const r8_u8 *src, unsigned len, r8_u8 *dst, unsigned cap,
                   unsigned *o)
{
    unsigned k, part;
    while (len > 0) {
        part = len > 32767u ? 32767u : len;
        if (cap - *o < part + 2u)
            return R8_E_SPACE;
        put16(dst + *o, part);
        *o += 2;
        for (k = 0; k < part; k++)
            dst[(*o)++] = src[k];
        src += part;
        len -= part;
    }
    return R8_OK;
}

int r8_lz77_encode(const r8_u8 *src, unsigned n, r8_u8 *dst, unsigned cap,
                   unsigned *out_len)
{
    unsigned i = 0, o = 0, lit = 0, j, l, best, dist, lim, need;
    *out_len = 0;
    while (i < n) {
        best = 0;
        dist = 0;
        lim = n - i;
#if UINT_MAX > 0xFFFFu
        if (lim > 65535u)
            lim = 65535u; /* the length word's limit */
#endif
        j = i > (unsigned)R8_LZ77_WINDOW ? i - (unsigned)R8_LZ77_WINDOW : 0;
        for (; j < i; j++) {
            l = 0;
            while (l < lim && src[j + l] == src[i + l])
                l++;
            /* ties go to the nearest match */
            if (l >= best && l > 0) {
                best = l;
                dist = i - j;
            }
        }
        /* A back-reference costs 4 bytes; breaking a literal run costs
         * 2 more for the next literal word. */
        need = lit ? R8_LZ77_MIN_MATCH + 2u : R8_LZ77_MIN_MATCH;
        if (best >= need) {
            if (put_lit(src + i - lit, lit, dst, cap, &o) != R8_OK)
                return R8_E_SPACE;
            lit = 0;
            if (cap - o < 4u)
                return R8_E_SPACE;
            put16(dst + o, (0u - dist) & 0xFFFFu);
            put16(dst + o + 2, best);
            o += 4;
            i += best;
        } else {
            lit++;
            i++;
        }
    }
    if (put_lit(src + i - lit, lit, dst, cap, &o) != R8_OK)
        return R8_E_SPACE;
    *out_len = o;
    return R8_OK;
}

int r8_lz77_decode(const r8_u8 *src, unsigned n, r8_u8 *dst, unsigned cap,
                   unsigned *out_len)
{
    unsigned i = 0, o = 0, w, len, dist, k;
    *out_len = 0;
    while (i < n) {
        if (n - i < 2u)
            return R8_E_TRUNC;
        w = ((unsigned)src[i] << 8) | src[i + 1];
        i += 2;
        if (w == 0)
            return R8_E_MALFORMED;
        if (w < 0x8000u) {
            if (n - i < w)
                return R8_E_TRUNC;
            if (cap - o < w)
                return R8_E_SPACE;
            for (k = 0; k < w; k++)
                dst[o++] = src[i++];
        } else {
            dist = (0u - w) & 0xFFFFu;
            if (n - i < 2u)
                return R8_E_TRUNC;
            len = ((unsigned)src[i] << 8) | src[i + 1];
            i += 2;
            if (len == 0 || dist > o)
                return R8_E_MALFORMED;
            if (cap - o < len)
                return R8_E_SPACE;
            for (k = 0; k < len; k++) {
                dst[o] = dst[o - dist];
                o++;
            }
        }
        *out_len = o;
    }
    *out_len = o;
    return R8_OK;
}
#else
typedef int r8_lz77_left_out; /* (ISO C wants a declaration in a file) */
#endif
