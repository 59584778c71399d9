/* fw_plat_host.c - plat.h on the host for the firmware reference builds:
 * UART bytes to stdout (binary), markers ignored. */
#include <stdio.h>
#include <stdlib.h>
#include "plat.h"

void plat_init(void)
{
}

void plat_putc(r8_u8 c)
{
    putchar(c);
}

void plat_write(const r8_u8 *p, unsigned n)
{
    fwrite(p, 1, n, stdout);
}

int plat_getc(void)
{
    return -1;   /* the reference builds get no input */
}

void plat_mark(r8_u8 id)
{
    (void)id;
}

void plat_exit(int code)
{
    fflush(stdout);
    exit(code);
}
