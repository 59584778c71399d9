/* ssd1306_host.c - the SSD1306 example on the host (build/examples/ssd1306):
 * oled_cube.c unchanged, with ssd1306_init/ssd1306_page writing a
 * 1024-byte image of the display RAM instead of the SPI port.
 *   ssd1306 [FRAMES [STEP]]   (default 16 1)
 * writes the image after every frame to stdout: FRAMES x 1024 bytes, the
 * same bytes emu/ssd1306sim -o writes from simavr's SSD1306 part. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "oled_cube.h"
#include "ssd1306_spi.h"

static r8_u8 ram[OLED_H / 8][OLED_W];
static r8_u8 arena[1 << 16];

void ssd1306_init(void)
{
    memset(ram, 0, sizeof ram);
}

void ssd1306_page(r8_u8 page, const r8_u8 *data, r8_u8 n)
{
    memcpy(ram[page & 7], data, n);
}

int main(int argc, char **argv)
{
    long frames = argc > 1 ? strtol(argv[1], 0, 0) : 16, step = argc > 2 ? strtol(argv[2], 0, 0) : 1;
    long i;
    unsigned need = oled_cube_ram();
    if (argc > 3 || frames < 0 || frames > 65535 || step < 0 || step > 255) {
        fprintf(stderr, "usage: ssd1306 [FRAMES [STEP]]  (display RAM per frame to stdout)\n");
        return 2;
    }
    ssd1306_init();
    if (oled_cube_init(arena, need)) {   /* exactly oled_cube_ram() bytes */
        fprintf(stderr, "ssd1306: the library refuses the configuration\n");
        return 3;
    }
    for (i = 0; i < frames; i++) {
        oled_cube_frame((r8_u16)(i * step));
        if (fwrite(ram, 1, sizeof ram, stdout) != sizeof ram)
            return 5;
    }
    return 0;
}
