/* HardwareSerial.h - Serial of the minimal core stub: USART0, polled
 * (the real core buffers and uses interrupts; the bytes on the line are
 * the same). */
#ifndef HardwareSerial_h
#define HardwareSerial_h

#include <stdint.h>
#include <stddef.h>

class HardwareSerial {
public:
    void begin(unsigned long baud);
    void end(void);
    int available(void);
    int read(void);
    size_t write(uint8_t c);
    size_t write(const uint8_t *buf, size_t n);
    void flush(void);
    operator bool() { return true; }
};

extern HardwareSerial Serial;

#endif
