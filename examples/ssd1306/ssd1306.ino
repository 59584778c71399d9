/* ssd1306 - rast8 on a 128x64 SSD1306 OLED, no PC needed: a shaded cube
 * spins on the display, rendered band by band on the board, each band
 * sent straight to the display as one of its 8 pages (no frame buffer).
 *
 * Wiring, Arduino Uno (ATmega328P) to an SPI SSD1306 module:
 *     D13 (SCK) -> D0/CLK     D11 (MOSI) -> D1/DIN     D10 -> CS
 *     D9 -> DC                D8 -> RES                5V/3V3, GND
 * The driver (ssd1306_spi.c) uses the AVR's SPI registers directly (no
 * SPI library); the application (oled_cube.c) owns the mesh, the pose
 * and the camera.  RAM: the renderer's work memory and one 128-byte page.
 */
#include <r8render.h>
extern "C" {
#include "oled_cube.h"
#include "ssd1306_spi.h"
}

#ifndef OLED_RAM
/* oled_cube_ram() on AVR: oled_cube_init refuses a smaller arena */
#define OLED_RAM 604
#endif
#ifndef OLED_FRAMES
#define OLED_FRAMES 0   /* frames to draw; 0 = forever */
#endif

static r8_u8 arena[OLED_RAM];
static r8_u16 frame;
static bool ready;

void setup()
{
    ssd1306_init();
    ready = oled_cube_init(arena, sizeof arena) == 0;
}

void loop()
{
#if OLED_FRAMES
    if (frame >= OLED_FRAMES)
        return;
#endif
    if (ready)
        oled_cube_frame(frame++);
}
