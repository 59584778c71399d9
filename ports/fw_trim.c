/* fw_trim.c - link-time trimming for the target firmware (included by
 * examples/spin/fw_app.c and tests/targets/fw_sizes.c): library entry points this firmware can never reach are
 * defined here as stubs, so the linker does not pull their modules from
 * the archive.  The 6502 and Z80 images are otherwise over 64 KB.
 *   FW_TRIM_LZ77  the firmware streams with RLE (app_defaults), so the
 *                 LZ77 codec (src/lz77.c) is never called: stubs return
 *                 R8_E_ARG ("codec not built in").
 *   FW_TRIM_SBUF  the method is not R8_VIS_SBUF, and src/render.c calls
 *                 the S-buffer (src/vis_sbuf.c) only for that method.
 * The identity tests prove the stream unchanged against the host build,
 * which links the whole library. */
#ifdef FW_TRIM_LZ77
#include "r8codec.h"
int r8_lz77_encode(const r8_u8 *src, unsigned n, r8_u8 *dst, unsigned cap,
                   unsigned *out_len)
{
    (void)src; (void)n; (void)dst; (void)cap;
    *out_len = 0;
    return R8_E_ARG;
}
int r8_lz77_decode(const r8_u8 *src, unsigned n, r8_u8 *dst, unsigned cap,
                   unsigned *out_len)
{
    (void)src; (void)n; (void)dst; (void)cap;
    *out_len = 0;
    return R8_E_ARG;
}
#endif
#ifdef FW_TRIM_SBUF
#include "r8int.h"
void r8_vis_sbuf_insert(r8_state *st, r8_fb *fb, const r8_poly *p, const r8_span *sp)
{
    (void)st; (void)fb; (void)p; (void)sp;
}
void r8_vis_sbuf_flush(r8_state *st, r8_fb *fb)
{
    (void)st; (void)fb;
}
#endif
