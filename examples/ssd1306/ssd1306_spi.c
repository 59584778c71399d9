/* ssd1306_spi.c - the SSD1306 over the ATmega328P's SPI (ssd1306_spi.h). */
#include <avr/io.h>
#include <util/delay_basic.h>   /* _delay_loop_2: 4 cycles a count, no floating point */
#include "r8flash.h"
#include "ssd1306_spi.h"

#define CS (1 << PB2)
#define DC (1 << PB1)
#define RES (1 << PB0)
#define MOSI (1 << PB3)
#define SCK (1 << PB5)

/* After a hardware reset every register holds its default (start line
 * 0, no offset, page addressing); these set what a 128x64 module needs. */
static const r8_u8 init_cmds[] R8_FLASH = {
    0xAE,       /* display off */
    0xD5, 0x80, /* clock divide / oscillator: the datasheet's default */
    0xA8, 0x3F, /* multiplex: 64 rows */
    0xD3, 0x00, /* display offset 0 */
    0x8D, 0x14, /* charge pump on (modules without an external VCC) */
    0x20, 0x02, /* page addressing: a data byte advances the column only */
    0xA1,       /* column 127 on SEG0 and */
    0xC8,       /* COM scan from COM63: the image upright on a usual module */
    0xDA, 0x12, /* COM pins: alternative configuration (128x64) */
    0x81, 0xCF, /* contrast */
    0xD9, 0xF1, /* pre-charge */
    0xDB, 0x40, /* VCOMH deselect level */
    0xA4,       /* show the RAM */
    0xA6,       /* not inverted */
    0xAF        /* display on */
};

#ifndef F_CPU
#define F_CPU 16000000UL
#endif
#define US10 ((r8_u16)(F_CPU / 400000UL))   /* _delay_loop_2 counts in 10 us */

/* One byte out, waiting until it has gone (out of line: the simulator
 * runner finds it by name and counts the cycles spent waiting here). */
void ssd1306_spi_byte(r8_u8 b) __attribute__((noinline));
void ssd1306_spi_byte(r8_u8 b)
{
    SPDR = b;
    while (!(SPSR & (1 << SPIF)))
        ;
}
#define spi ssd1306_spi_byte

void ssd1306_init(void)
{
    r8_u8 i;
    PORTB |= CS | RES;
    DDRB |= CS | DC | RES | MOSI | SCK;     /* SS (PB2) an output: master stays master */
    SPCR = (1 << SPE) | (1 << MSTR);        /* mode 0, MSB first */
    SPSR = (1 << SPI2X);                    /* f/2: 8 MHz at 16 MHz */
    _delay_loop_2(100 * US10);              /* 1 ms: VDD up */
    PORTB &= (r8_u8)~RES;                   /* reset: at least 3 us low */
    _delay_loop_2(US10);
    PORTB |= RES;
    _delay_loop_2(US10);
    PORTB &= (r8_u8)~(CS | DC);             /* select, commands */
    for (i = 0; i < sizeof init_cmds; i++)
        spi(R8_RDU8(&init_cmds[i]));
    PORTB |= CS;
}

void ssd1306_page(r8_u8 page, const r8_u8 *data, r8_u8 n)
{
    PORTB &= (r8_u8)~(CS | DC);
    spi((r8_u8)(0xB0 | (page & 7)));        /* page address */
    spi(0x00);                              /* column 0: low nibble */
    spi(0x10);                              /* and high nibble */
    PORTB |= DC;
    while (n--)
        spi(*data++);
    PORTB |= CS;
}
