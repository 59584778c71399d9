/* plat_avr.c - platform layer for ATmega328P / ATmega1284P (avr-gcc).
 *
 * UART: USART0, polled, 8N1, both ways (emu/avrsim -i feeds the receiver).  UBRR0 = 0 without U2X gives 1 Mbaud at
 * 16 MHz (exact); simavr charges ~11 bit-times per byte, so the runner
 * (emu/avrsim.c) subtracts the cycles spent in plat_avr_txwait() and
 * reports compute cycles separately from link time.
 * Markers: the id is written to GPIOR0 (data address 0x3E on both MCUs);
 * emu/avrsim.c timestamps every write.
 * Exit: the code goes to GPIOR1, then cli + sleep (simavr: cpu_Done).
 * Stack peak: emu/avrsim.c paints free RAM before reset and scans it at
 * the end (no firmware code needed).
 */
#include <avr/io.h>
#include <avr/interrupt.h>
#include <avr/sleep.h>
#include "plat.h"

/* Kept out of line so the runner can find (and discount) the busy-wait. */
void plat_avr_txwait(void) __attribute__((noinline));
void plat_avr_txwait(void)
{
    while (!(UCSR0A & (1 << UDRE0)))
        ;
}

void plat_init(void)
{
    UBRR0H = 0;
    UBRR0L = 0;
    UCSR0A = 0;
    UCSR0C = (1 << UCSZ01) | (1 << UCSZ00); /* 8N1 */
    UCSR0B = (1 << TXEN0) | (1 << RXEN0);
}

void plat_putc(r8_u8 c)
{
    plat_avr_txwait();
    UDR0 = c;
}

void plat_write(const r8_u8 *p, unsigned n)
{
    while (n--) {
        plat_avr_txwait();
        UDR0 = *p++;
    }
}

int plat_getc(void)
{
    if (!(UCSR0A & (1 << RXC0)))
        return -1;
    return UDR0;
}

void plat_mark(r8_u8 id)
{
    GPIOR0 = id;
}

void plat_exit(int code)
{
    plat_avr_txwait();
    GPIOR1 = (r8_u8)code;
    cli();
    set_sleep_mode(SLEEP_MODE_PWR_DOWN);
    sleep_enable();
    for (;;)
        sleep_cpu();
}
