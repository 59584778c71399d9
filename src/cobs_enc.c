/* cobs_enc.c - COBS into a buffer (see cobs.c); its own file so that a
 * firmware, which streams (r8_cobs_write) or encodes in place (wire.c),
 * does not carry it. */
#include "r8wire.h"

int r8_cobs_encode(const r8_u8 *src, unsigned n, r8_u8 *dst, unsigned cap,
                   unsigned *out_len)
{
    unsigned i, o = 1, code_at = 0;
    r8_u8 code = 1;
    *out_len = 0;
    if (cap < 1u)
        return R8_E_SPACE;
    for (i = 0; i < n; i++) {
        if (src[i] == 0) {
            dst[code_at] = code;
            if (o >= cap)
                return R8_E_SPACE;
            code_at = o++;
            code = 1;
        } else {
            if (o >= cap)
                return R8_E_SPACE;
            dst[o++] = src[i];
            code++;
            if (code == 0xFF && i + 1 < n) {
                dst[code_at] = code;
                if (o >= cap)
                    return R8_E_SPACE;
                code_at = o++;
                code = 1;
            }
        }
    }
    dst[code_at] = code;
    *out_len = o;
    return R8_OK;
}
