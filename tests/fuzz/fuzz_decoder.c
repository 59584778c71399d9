/* fuzz_decoder.c - libFuzzer target: the streaming protocol decoder
 * (r8_dec_feed) fed arbitrary bytes, with packet, frame and palette
 * buffers of exactly the sizes given (heap: ASan sees any write past
 * them).  The first two bytes pick the frame buffer size. */
#include <stdlib.h>
#include <string.h>
#include "r8wire.h"

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
    unsigned fbsz, pktsz, i;
    unsigned char *pkt, *fb, *pal;
    r8_dec d;
    if (size < 2)
        return 0;
    fbsz = 1u + ((unsigned)data[0] | ((unsigned)data[1] & 0x1F) << 8);   /* 1..8192 */
    pktsz = R8_DEC_PKT_BYTES(fbsz);
    pkt = (unsigned char *)malloc(pktsz);
    fb = (unsigned char *)malloc(fbsz);
    pal = (unsigned char *)malloc(3 * 256);
    r8_dec_init(&d, pkt, pktsz, fb, fbsz, (data[1] & 0x80) ? pal : 0, (data[1] & 0x80) ? 3 * 256 : 0);
    for (i = 2; i < size; i++) {
        int r = r8_dec_feed(&d, data[i]);
        if (r < R8_DEC_NONE || r > R8_DEC_INCOMPLETE)
            abort();
        if (d.pkt_len > pktsz)
            abort();
    }
    if (r8_dec_end(&d) > R8_DEC_INCOMPLETE || d.in_frame)
        abort();
    if (d.frames > d.packets)
        abort();
    free(pkt);
    free(fb);
    free(pal);
    return 0;
}
