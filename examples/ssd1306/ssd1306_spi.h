/* ssd1306_spi.h - an SSD1306 128x64 OLED on the ATmega328P's hardware SPI
 * (4-wire: SCLK, SDIN, CS, D/C, plus RES), driven directly: no library,
 * no frame buffer (the renderer's band buffer is one display page).
 *
 * Wiring (Arduino Uno pin in brackets):
 *     SCK  PB5 (D13) -> D0/SCLK       MOSI PB3 (D11) -> D1/SDIN
 *     PB2 (D10) -> CS                 PB1 (D9) -> D/C
 *     PB0 (D8)  -> RES
 * SPI rather than I2C: at f/2 (8 MHz) a whole frame (1024 bytes) leaves
 * in ~1.1 ms against ~23 ms on 400 kHz I2C, and the AVR's SPI needs only
 * a poll of SPIF per byte (I2C needs the TWI state machine).
 *
 * The host build of the example (ssd1306_host.c) defines these two
 * calls over a memory image instead. */
#ifndef SSD1306_SPI_H
#define SSD1306_SPI_H

#include "r8types.h"

/* Reset the controller (RES), set it up (page addressing, charge pump,
 * 128x64, normal orientation as the common modules are mounted) and
 * switch the panel on. */
void ssd1306_init(void);
/* n bytes (n <= 128) into page `page` (0..7, rows 8*page..8*page+7)
 * from column 0: the SSD1306 page layout, byte x = column x, bit k =
 * row 8*page+k.  Returns when the last byte has left the SPI port. */
void ssd1306_page(r8_u8 page, const r8_u8 *data, r8_u8 n);

#endif
