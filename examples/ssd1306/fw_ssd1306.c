/* fw_ssd1306.c - the SSD1306 example's firmware main for the ATmega328P:
 * the display driven over SPI, no UART stream.  `make test` runs it in
 * emu/ssd1306sim.c (simavr's SSD1306 part on the SPI port) and compares
 * the display RAM after every frame with the host.
 *   OLED_FRAMES  frames to draw, then stop (default 16; 0 = forever)
 *   OLED_STEP    frame n shows the cube's pose n * OLED_STEP (default 1)
 *   OLED_RAM     the arena: oled_cube_ram() measured on the target (the
 *                build runs this file with OLED_SIZE_ONLY first)
 *   OLED_SIZE_ONLY  print oled_cube_ram() on the UART and stop
 * Markers (plat.h, GPIOR0): PLAT_MARK_FRAME_BEGIN before a frame,
 * PLAT_MARK_FRAME_END once its last page has left the SPI port.  Exit
 * code 0, or 2 when the arena is too small (nothing drawn).  Renderer
 * parts the example never uses are left out (mk/examples.mk's R8_NO_*):
 * render.c and scan.c are compiled in here with them. */
#include "plat.h"
#include "oled_cube.h"
#include "ssd1306_spi.h"
#ifdef OLED_TRIM
#include "render.c"
#include "scan.c"
#endif

#ifndef OLED_FRAMES
#define OLED_FRAMES 16
#endif
#ifndef OLED_STEP
#define OLED_STEP 1
#endif

#ifdef OLED_SIZE_ONLY
int main(void)
{
    char d[6];
    int n = 0;
    unsigned v = oled_cube_ram();
    plat_init();
    do {
        d[n++] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v);
    while (n)
        plat_putc((r8_u8)d[--n]);
    plat_putc('\n');
    plat_exit(0);
    return 0;
}
#else
#ifndef OLED_RAM
#define OLED_RAM 1
#endif
static r8_u8 arena[OLED_RAM];

int main(void)
{
    r8_u16 i;
    ssd1306_init();
    if (oled_cube_init(arena, sizeof arena))
        plat_exit(2);
    plat_mark(PLAT_MARK_START);
    for (i = 0; !OLED_FRAMES || i < OLED_FRAMES; i++) {
        plat_mark(PLAT_MARK_FRAME_BEGIN);
        oled_cube_frame((r8_u16)(i * OLED_STEP));
        plat_mark(PLAT_MARK_FRAME_END);
    }
    plat_mark(PLAT_MARK_DONE);
    plat_exit(0);
    return 0;
}
#endif
