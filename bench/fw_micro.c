/* fw_micro.c - inner-loop micro-benchmarks on the target (used by
 * bench/bench.py on the ATmega1284P).  Each measured piece is bracketed
 * by plat_mark(10 + k) / plat_mark(11 + k); emu/avrsim reports the cycles
 * between consecutive markers.  The stream gets one line per piece with
 * the unit count it covers, so cycles / units gives the per-unit cost:
 *   span   r8_fb_span_dither, PAGE1, 120-px spans x 64 rows   (pixels)
 *   fill   r8_scanx_fill of a 100x56-px triangle, PAGE1 band   (pixels)
 *   edges  r8_scan_next over a 56-row triangle                 (rows)
 *   vert   r8_mat_apply16 + r8_project, 64 vertices            (vertices)
 *   crc    r8_crc16_update over 1024 bytes                     (bytes)
 *   rle    r8_rle_encode of a 1024-byte rendered-like frame    (bytes)
 *   crc32  r8_crc32_update over 1024 bytes (the protocol-version-2 frame
 *          check, R8_WIRE_CRC32)                               (bytes)
 *   line   r8_line, 32 lines of 128 px across the PAGE1 frame  (pixels)
 *   wu     r8_wu_line, 16 lines of 128 steps, PAGE1 dithered   (steps)
 *   circle r8_circle, radius 30, PAGE1                         (circles)
 *   disc   r8_circle_fill, radius 30, PAGE1                    (circles)
 */
#include "plat.h"
#include "r8fb.h"
#include "r8raster.h"
#include "r8fixed.h"
#include "r8wire.h"
#include "r8codec.h"

static r8_u8 buf[1024];
static r8_u8 out[1100];
static r8_fb fb;
static r8_scan sc;
static r8_span sp;
static r8_svert sv[3];
static const r8_u16 idx[3] = {0, 1, 2};
static r8_proj cam;
static r8_mat3 m;
static r8_vec3 v;
static r8_vec3l vl;
static volatile r8_u16 sink;

static void put_u(const char *tag, unsigned long v)
{
    char d[12];
    int n = 0;
    while (*tag)
        plat_putc((r8_u8)*tag++);
    do {
        d[n++] = (char)('0' + (int)(v % 10u));
        v /= 10u;
    } while (v);
    while (n)
        plat_putc((r8_u8)d[--n]);
    plat_putc('\n');
}

static void tri(void)
{
    sv[0].x = 10 * 16; sv[0].y = 4 * 16;
    sv[1].x = 110 * 16; sv[1].y = 30 * 16;
    sv[2].x = 40 * 16; sv[2].y = 60 * 16;
}

int main(void)
{
    r8_s16 y;
    int i, rows = 0;
    unsigned len = 0;
    r8_u16 crc;
    plat_init();
    r8_fb_init(&fb, buf, R8_FMT_PAGE1, 128, 64, 0, 64);
    r8_fb_clear(&fb, 0);

    plat_mark(10);
    for (y = 0; y < 64; y++)
        r8_fb_span_dither(&fb, y, 4, 124, 7, 0);
    plat_mark(11);
    put_u("span px=", 64L * 120);

    tri();
    r8_fb_clear(&fb, 0);
    r8_scan_begin(&sc, sv, idx, 3, 0, 0);
    plat_mark(12);
    r8_scanx_fill(&sc.c, 64, 1, &fb, 7);
    plat_mark(13);
    r8_fb_clear(&fb, 0);
    put_u("fill px=", (unsigned long)r8_fill_poly(&fb, sv, idx, 3, 1));

    tri();
    r8_scan_begin(&sc, sv, idx, 3, R8_ATTR_D | R8_ATTR_S, 0);
    plat_mark(14);
    while (r8_scan_next(&sc, 64, 1, &sp))
        rows++;
    plat_mark(15);
    put_u("edges rows=", (unsigned long)rows);

    r8_proj_init(&cam, 128, 64, 100, 16L << R8_CFRAC);
    r8_mat_rotate(&m, 10, 20, 30);
    plat_mark(16);
    for (i = 0; i < 64; i++) {
        r8_s16 sx, sy;
        v.x = (r8_s16)(i - 32);
        v.y = (r8_s16)(20 - i);
        v.z = (r8_s16)(i * 2 - 60);
        r8_mat_apply16(&m, &v, &vl);
        vl.z += 220L << R8_CFRAC;
        r8_project(&cam, &vl, &sx, &sy);
        sink = (r8_u16)(sx + sy);
    }
    plat_mark(17);
    put_u("vert n=", 64);

    plat_mark(18);
    crc = r8_crc16_update(R8_CRC16_INIT, buf, sizeof buf);
    plat_mark(19);
    sink = crc;
    put_u("crc bytes=", sizeof buf);

    r8_fb_clear(&fb, 0);
    r8_fill_poly(&fb, sv, idx, 3, 1);
    plat_mark(20);
    r8_rle_encode(buf, sizeof buf, out, sizeof out, &len);
    plat_mark(21);
    put_u("rle bytes=", sizeof buf);

    plat_mark(22);
    sink = (r8_u16)r8_crc32_update(0, buf, sizeof buf);
    plat_mark(23);
    put_u("crc32 bytes=", sizeof buf);

    r8_fb_clear(&fb, 0);
    plat_mark(24);
    for (i = 0; i < 32; i++)
        r8_line(&fb, 0, (r8_s16)(2 * i), 127, (r8_s16)(63 - 2 * i), 1);
    plat_mark(25);
    put_u("line px=", 32L * 128);

    r8_fb_clear(&fb, 0);
    plat_mark(26);
    for (i = 0; i < 16; i++)
        r8_wu_line(&fb, 0, (r8_s16)(4 * i), 127, (r8_s16)(63 - 4 * i), 0);
    plat_mark(27);
    put_u("wu steps=", 16L * 128);

    r8_fb_clear(&fb, 0);
    plat_mark(28);
    r8_circle(&fb, 64, 32, 30, 1);
    plat_mark(29);
    put_u("circle n=", 1);

    plat_mark(30);
    r8_circle_fill(&fb, 64, 32, 30, 1);
    plat_mark(31);
    put_u("disc n=", 1);
    plat_exit(0);
    return 0;
}
