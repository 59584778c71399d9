/* rle.c - the seed's run-length codec (see r8codec.h for the format)
 * and the codec dispatch.  -DR8_NO_RLE / -DR8_NO_LZ77 leave a codec out
 * (src/wire.c rejects it too): the dispatch then answers R8_E_ARG for
 * it, as for an unknown codec. */
#include "r8codec.h"

static int streq(const char *a, const char *b)
{
    while (*a && *a == *b) {
        a++;
        b++;
    }
    return *a == *b;
}

static const char *const codec_names[R8_CODEC_COUNT] = { "raw", "rle", "lz77", "huff", "lzw" };

int r8_codec_by_name(const char *name)
{
    int i;
    for (i = 0; i < R8_CODEC_COUNT; i++)
        if (streq(name, codec_names[i]))
            return i;
    if (streq(name, "best"))
        return R8_CODEC_BEST;
    return -1;
}

const char *r8_codec_name(r8_u8 codec)
{
    if (codec == R8_CODEC_BEST)
        return "best";
    return codec < R8_CODEC_COUNT ? codec_names[codec] : 0;
}

#ifndef R8_NO_RLE
/* Emit the pending raw run src[start .. start+len). */
static int put_raw(const r8_u8 *src, unsigned len, r8_u8 *dst, unsigned cap,
                   unsigned *o)
{
    unsigned k;
    if (len == 0)
        return R8_OK;
    if (cap - *o < len + 1u)
        return R8_E_SPACE;
    dst[(*o)++] = (r8_u8)(0x80u | len);
    for (k = 0; k < len; k++)
        dst[(*o)++] = src[k];
    return R8_OK;
}

int r8_rle_encode(const r8_u8 *src, unsigned n, r8_u8 *dst, unsigned cap,
                  unsigned *out_len)
{
    unsigned i = 0, o = 0, lit = 0, run;
    *out_len = 0;
    while (i < n) {
        run = 1;
        while (i + run < n && run < R8_RLE_MAX && src[i + run] == src[i])
            run++;
        if (run >= 3) {
            if (put_raw(src + i - lit, lit, dst, cap, &o) != R8_OK)
                return R8_E_SPACE;
            lit = 0;
            if (cap - o < 2u)
                return R8_E_SPACE;
            dst[o++] = (r8_u8)run;
            dst[o++] = src[i];
            i += run;
        } else {
            lit++;
            i++;
            if (lit == R8_RLE_MAX) {
                if (put_raw(src + i - lit, lit, dst, cap, &o) != R8_OK)
                    return R8_E_SPACE;
                lit = 0;
            }
        }
    }
    if (put_raw(src + i - lit, lit, dst, cap, &o) != R8_OK)
        return R8_E_SPACE;
    *out_len = o;
    return R8_OK;
}

int r8_rle_decode(const r8_u8 *src, unsigned n, r8_u8 *dst, unsigned cap,
                  unsigned *out_len)
{
    unsigned i = 0, o = 0, cnt, k;
    r8_u8 c;
    *out_len = 0;
    while (i < n) {
        c = src[i++];
        cnt = c & 0x7Fu;
        if (cnt == 0)
            return R8_E_MALFORMED;
        if (c & 0x80u) {
            if (n - i < cnt)
                return R8_E_TRUNC;
            if (cap - o < cnt)
                return R8_E_SPACE;
            for (k = 0; k < cnt; k++)
                dst[o++] = src[i++];
        } else {
            if (i >= n)
                return R8_E_TRUNC;
            if (cap - o < cnt)
                return R8_E_SPACE;
            for (k = 0; k < cnt; k++)
                dst[o++] = src[i];
            i++;
        }
        *out_len = o;
    }
    *out_len = o;
    return R8_OK;
}
#endif

static int raw_copy(const r8_u8 *src, unsigned n, r8_u8 *dst, unsigned cap,
                    unsigned *out_len)
{
    unsigned k;
    *out_len = 0;
    if (n > cap)
        return R8_E_SPACE;
    for (k = 0; k < n; k++)
        dst[k] = src[k];
    *out_len = n;
    return R8_OK;
}

int r8_codec_encode(r8_u8 codec, const r8_u8 *src, unsigned n, r8_u8 *dst,
                    unsigned cap, unsigned *out_len)
{
    switch (codec) {
    case R8_CODEC_RAW:
        return raw_copy(src, n, dst, cap, out_len);
#ifndef R8_NO_RLE
    case R8_CODEC_RLE:
        return r8_rle_encode(src, n, dst, cap, out_len);
#endif
#ifndef R8_NO_LZ77
    case R8_CODEC_LZ77:
        return r8_lz77_encode(src, n, dst, cap, out_len);
#endif
#ifndef R8_NO_HUFF
    case R8_CODEC_HUFF:
        return r8_huff_encode(src, n, dst, cap, out_len);
#endif
#ifndef R8_NO_LZW
    case R8_CODEC_LZW:
        return r8_lzw_encode(src, n, dst, cap, out_len);
#endif
    default:
        *out_len = 0;
        return R8_E_ARG;
    }
}

int r8_codec_decode(r8_u8 codec, const r8_u8 *src, unsigned n, r8_u8 *dst,
                    unsigned cap, unsigned *out_len)
{
    switch (codec) {
    case R8_CODEC_RAW:
        return raw_copy(src, n, dst, cap, out_len);
#ifndef R8_NO_RLE
    case R8_CODEC_RLE:
        return r8_rle_decode(src, n, dst, cap, out_len);
#endif
#ifndef R8_NO_LZ77
    case R8_CODEC_LZ77:
        return r8_lz77_decode(src, n, dst, cap, out_len);
#endif
#ifndef R8_NO_HUFF
    case R8_CODEC_HUFF:
        return r8_huff_decode(src, n, dst, cap, out_len);
#endif
#ifndef R8_NO_LZW
    case R8_CODEC_LZW:
        return r8_lzw_decode(src, n, dst, cap, out_len);
#endif
    default:
        *out_len = 0;
        return R8_E_ARG;
    }
}
