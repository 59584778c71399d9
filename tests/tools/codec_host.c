/* codec_host.c - rast8-codec: the C library's codecs and frame decoder
 * as a filter (stdin -> stdout), so tests can check that C and Python
 * agree byte for byte on any input.
 *
 *   rast8-codec rle|lz77|raw|cobs encode|decode [LIMIT]
 *   rast8-codec crc                 prints the CRC-16 as 4 hex digits
 *   rast8-codec dec [FB_BYTES [--no-end]]
 *                                   protocol stream -> good frames in the
 *                                   emulator's --dump format; counters as
 *                                   one JSON line on stderr (after
 *                                   r8_dec_end unless --no-end)
 * exit: 0 ok, 2 usage, 3 malformed, 4 truncated, 5 output limit */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "r8codec.h"
#include "r8wire.h"

static unsigned char *slurp(size_t *n)
{
    size_t cap = 1 << 16, len = 0, r;
    unsigned char *b = malloc(cap);
    while (b && (r = fread(b + len, 1, cap - len, stdin)) > 0) {
        len += r;
        if (len == cap)
            b = realloc(b, cap *= 2);
    }
    *n = len;
    return b;
}

static int rc_exit(int rc)
{
    switch (rc) {
    case R8_OK: return 0;
    case R8_E_MALFORMED: return 3;
    case R8_E_TRUNC: return 4;
    case R8_E_SPACE: return 5;
    default: return 1;
    }
}

static int dec_main(unsigned fb_bytes, int no_end)
{
    static r8_dec d;
    unsigned char *pkt = malloc(R8_DEC_PKT_BYTES(fb_bytes)), *fb = malloc(fb_bytes);
    unsigned char pal[768];
    int c, r;
    r8_dec_init(&d, pkt, R8_DEC_PKT_BYTES(fb_bytes), fb, fb_bytes, pal, sizeof pal);
    while ((c = getchar()) != EOF) {
        r = r8_dec_feed(&d, (r8_u8)c);
        if (r == R8_DEC_FRAME) {
            unsigned char h[12];
            memcpy(h, "R8FB", 4);
            h[4] = (unsigned char)(d.frame >> 8); h[5] = (unsigned char)d.frame;
            h[6] = (unsigned char)(d.width >> 8); h[7] = (unsigned char)d.width;
            h[8] = (unsigned char)(d.height >> 8); h[9] = (unsigned char)d.height;
            h[10] = d.format; h[11] = 0;
            fwrite(h, 1, 12, stdout);
            fwrite(fb, 1, d.frame_bytes, stdout);
        }
    }
    if (!no_end)
        r8_dec_end(&d);
    fprintf(stderr, "{\"bytes\": %lu, \"packets\": %lu, \"bad_packets\": %lu, "
            "\"frames\": %lu, \"dropped\": %lu, \"incomplete\": %lu, "
            "\"skipped\": %lu, \"ignored\": %lu}\n",
            (unsigned long)d.bytes, (unsigned long)d.packets,
            (unsigned long)d.bad_packets, (unsigned long)d.frames,
            (unsigned long)d.dropped, (unsigned long)d.incomplete,
            (unsigned long)d.skipped, (unsigned long)d.ignored);
    return 0;
}

int main(int argc, char **argv)
{
    size_t n;
    unsigned char *in, *out;
    unsigned cap, len;
    int rc, codec = -1, enc;
    if (argc >= 2 && !strcmp(argv[1], "dec"))
        return dec_main(argc > 2 ? (unsigned)strtoul(argv[2], 0, 0) : 65536u,
                        argc > 3 && !strcmp(argv[3], "--no-end"));
    in = slurp(&n);
    if (!in)
        return 1;
    if (argc == 2 && !strcmp(argv[1], "crc")) {
        printf("%04X\n", (unsigned)r8_crc16(in, (unsigned)n));
        return 0;
    }
    if (argc < 3) {
        fprintf(stderr, "usage: rast8-codec rle|lz77|raw|cobs encode|decode [LIMIT] | crc | dec [FB_BYTES [--no-end]]\n");
        return 2;
    }
    enc = !strcmp(argv[2], "encode");
    if (!enc && strcmp(argv[2], "decode"))
        return 2;
    cap = argc > 3 ? (unsigned)strtoul(argv[3], 0, 0) : (unsigned)(n * 2 + 1024 + n / 2);
    if (!enc && argc <= 3)
        cap = 1u << 24;
    out = malloc(cap ? cap : 1);
    if (!strcmp(argv[1], "cobs")) {
        rc = enc ? r8_cobs_encode(in, (unsigned)n, out, cap, &len)
                 : r8_cobs_decode(in, (unsigned)n, out, cap, &len);
    } else {
        codec = r8_codec_by_name(argv[1]);
        if (codec < 0)
            return 2;
        rc = enc ? r8_codec_encode((r8_u8)codec, in, (unsigned)n, out, cap, &len)
                 : r8_codec_decode((r8_u8)codec, in, (unsigned)n, out, cap, &len);
    }
    if (rc == R8_OK)
        fwrite(out, 1, len, stdout);
    return rc_exit(rc);
}
