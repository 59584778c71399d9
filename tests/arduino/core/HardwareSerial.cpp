/* HardwareSerial.cpp - USART0, polled, 8N1, with U2X like the real core's
 * begin() (UBRR = (F_CPU / 4 / baud - 1) / 2). */
#include "Arduino.h"

HardwareSerial Serial;

void HardwareSerial::begin(unsigned long baud)
{
    uint16_t ubrr = (uint16_t)((F_CPU / 4 / baud - 1) / 2);
    UCSR0A = (1 << U2X0);
    UBRR0H = (uint8_t)(ubrr >> 8);
    UBRR0L = (uint8_t)ubrr;
    UCSR0C = (1 << UCSZ01) | (1 << UCSZ00);
    UCSR0B = (1 << TXEN0) | (1 << RXEN0);
}

void HardwareSerial::end(void)
{
    flush();
    UCSR0B = 0;
}

int HardwareSerial::available(void)
{
    return (UCSR0A & (1 << RXC0)) ? 1 : 0;
}

int HardwareSerial::read(void)
{
    if (!(UCSR0A & (1 << RXC0)))
        return -1;
    return UDR0;
}

size_t HardwareSerial::write(uint8_t c)
{
    while (!(UCSR0A & (1 << UDRE0)))
        ;
    UDR0 = c;
    return 1;
}

size_t HardwareSerial::write(const uint8_t *buf, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        write(buf[i]);
    return n;
}

void HardwareSerial::flush(void)
{
    while (!(UCSR0A & (1 << UDRE0)))
        ;
}
