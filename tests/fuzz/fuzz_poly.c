/* fuzz_poly.c - libFuzzer target: the polygon entry points with arbitrary
 * vertices: r8_scan_begin/r8_scan_next (attributes, Judd, band limits)
 * and r8_fill_poly into a band of exactly r8_fb_bytes (heap: ASan sees a
 * write past it).  Checks the spans' invariants: rows inside the band
 * limits and increasing, x0 < x1. */
#include <stdlib.h>
#include <string.h>
#include "r8raster.h"
#include "r8fb.h"

static r8_s16 s16at(const unsigned char *p)
{
    return (r8_s16)(short)(unsigned short)((unsigned)p[0] | (unsigned)p[1] << 8);
}

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
    r8_svert v[32];
    r8_u16 idx[32];
    r8_u8 n, fmt, attrs, i;
    r8_s16 w, h, y0, rows, ystart, last = -32768;
    r8_fb fb;
    r8_scan sc;
    r8_span sp;
    unsigned bytes;
    unsigned char *buf;
    int judd;
    if (size < 8)
        return 0;
    fmt = (r8_u8)(data[0] % 3);
    w = (r8_s16)(1 + data[1] % 160);
    h = (r8_s16)(8 * (1 + data[2] % 12));
    rows = (r8_s16)(fmt == R8_FMT_PAGE1 ? 8 * (1 + data[3] % 4) : 1 + data[3] % 40);
    y0 = (r8_s16)(fmt == R8_FMT_PAGE1 ? 8 * (data[4] % 14) : data[4] % 100);
    attrs = (r8_u8)(data[5] & 3);
    judd = data[5] >> 7;
    ystart = (r8_s16)((signed char)data[6]);
    n = (r8_u8)(data[7] % 33);
    data += 8;
    size -= 8;
    if (size < (size_t)n * 8u || n == 0)
        return 0;
    for (i = 0; i < n; i++) {
        v[i].x = s16at(data + 8 * i);
        v[i].y = s16at(data + 8 * i + 2);
        v[i].d = (r8_s16)(s16at(data + 8 * i + 4) & 0x7FFF);
        v[i].s = (r8_s16)(s16at(data + 8 * i + 6) & 0x1FFF);
        idx[i] = (r8_u16)(n - 1 - i);
    }
    if (r8_scan_begin(&sc, v, idx, n, attrs, ystart)) {
        r8_s16 lim = (r8_s16)(ystart + 16);
        int k;
        for (k = 0; k < 3; k++, lim = (r8_s16)(lim + 300)) {
            while (r8_scan_next(&sc, lim, judd, &sp)) {
                if (sp.y < ystart || sp.y >= lim || sp.y <= last || sp.x0 >= sp.x1)
                    abort();
                last = sp.y;
            }
        }
    }
    bytes = r8_fb_bytes(fmt, w, rows);
    buf = (unsigned char *)malloc(bytes ? bytes : 1);
    if (r8_fb_init(&fb, buf, fmt, w, h, y0, rows) == 0) {
        r8_s32 cnt;
        r8_fb_clear(&fb, 0);
        cnt = r8_fill_poly(&fb, v, idx, n, (r8_u8)(data[0] | 1));
        if (cnt < 0 || cnt > (r8_s32)w * rows)
            abort();
    }
    free(buf);
    return 0;
}
