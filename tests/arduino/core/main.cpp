/* main.cpp - the core's entry point: setup() once, then loop() forever. */
#include "Arduino.h"

int main(void)
{
    sei();
    setup();
    for (;;)
        loop();
    return 0;
}
