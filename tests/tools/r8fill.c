/* r8fill.c - r8_fill_poly for the reference tests: reads polygons from
 * stdin, one per line: "W H n x0 y0 x1 y1 ..." (12.4 subpixels), and
 * writes for each a W*H byte mask (1 = pixel written) to stdout. */
#include <stdio.h>
#include <string.h>
#include "r8raster.h"
#include "r8fb.h"

static unsigned char buf[1024 * 1024];

int main(void)
{
    int w, h, n;
    while (scanf("%d %d %d", &w, &h, &n) == 3) {
        r8_svert v[255];
        r8_u16 idx[255];
        r8_fb fb;
        int i;
        if (n < 1 || n > 255 || w < 1 || h < 1 || w * h > (int)sizeof buf)
            return 2;
        for (i = 0; i < n; i++) {
            int x, y;
            if (scanf("%d %d", &x, &y) != 2)
                return 2;
            v[i].x = (r8_s16)x;
            v[i].y = (r8_s16)y;
            v[i].d = v[i].s = 0;
            idx[i] = (r8_u16)i;
        }
        if (r8_fb_init(&fb, buf, R8_FMT_IDX8, (r8_s16)w, (r8_s16)h, 0, (r8_s16)h))
            return 2;
        memset(buf, 0, (size_t)(w * h));
        r8_fill_poly(&fb, v, idx, (r8_u8)n, 1);
        fwrite(buf, 1, (size_t)(w * h), stdout);
    }
    return 0;
}
