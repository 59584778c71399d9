/* Arduino.h - a minimal stand-in for the Arduino AVR core, just enough
 * to compile and link rast8's example sketches for an ATmega328P with
 * avr-gcc when no real core is installed (tests/arduino/check.py).
 * Not a core: setup()/loop(), the integer types, and Serial (polled
 * USART0, HardwareSerial.h). */
#ifndef Arduino_h
#define Arduino_h

#include <stdint.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <avr/io.h>
#include <avr/pgmspace.h>
#include <avr/interrupt.h>

typedef uint8_t byte;
typedef bool boolean;

#ifdef __cplusplus
extern "C" {
#endif
void setup(void);
void loop(void);
#ifdef __cplusplus
}
#include "HardwareSerial.h"
#endif

#endif
