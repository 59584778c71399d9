/* plat_sim65.c - platform layer for the 6502 under sim65 (cc65).
 *
 * UART: write(1, ...) -> sim65's stdout (binary-safe).
 * Markers: sim65 2.19 has no cycle counter a program can read, so
 *   plat_mark does nothing; bench/bench.py times frames with differential
 *   builds (N and 2N frames, sim65 -c totals, subtracted).
 * Exit: exit(code) -> sim65's exit status.
 * Stack peak: plat_init paints the C stack (the __STACKSIZE__ bytes below
 *   the top of MAIN, down from the current sp) and the unused part of
 *   the hardware stack page with 0xA5; plat_exit scans both and writes
 *   "STACK c=N hw=N\n" to stderr (write(2, ...)), apart from the stream.
 */
#include <unistd.h>
#include <stdlib.h>
#include "plat.h"

#define PAINT 0xA5

extern char _MAIN_START__[], _MAIN_SIZE__[], _STACKSIZE__[];
static r8_u8 hw_s0;
static r8_u8 *c_lo;

static unsigned c_sp;

void plat_init(void)
{
    r8_u8 *p, *top;
    r8_u8 s;
    c_lo = (r8_u8 *)((unsigned)_MAIN_START__ + (unsigned)_MAIN_SIZE__);
    /* the C stack pointer itself (locals are static with -Cl: no local's
     * address tells where the stack is) */
    __asm__("lda sp");
    __asm__("sta %v", c_sp);
    __asm__("lda sp+1");
    __asm__("sta %v+1", c_sp);
    top = (r8_u8 *)c_sp - 32;
    for (p = c_lo; p < top; p++)
        *p = PAINT;
    __asm__("tsx");
    __asm__("stx %v", hw_s0);
    for (s = 0; s < (r8_u8)(hw_s0 - 16); s++)
        ((r8_u8 *)0x100)[s] = PAINT;
}

void plat_putc(r8_u8 c)
{
    write(1, &c, 1);
}

void plat_write(const r8_u8 *p, unsigned n)
{
    write(1, p, n);
}

int plat_getc(void)
{
    return -1;   /* sim65: no receive path */
}

void plat_mark(r8_u8 id)
{
    (void)id;
}

static void put_u(unsigned v)
{
    char d[6];
    int n = 0;
    do {
        d[n++] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v);
    while (n)
        write(2, &d[--n], 1);
}

void plat_exit(int code)
{
    r8_u8 *p = c_lo;
    r8_u8 s = 0;
    unsigned top = (unsigned)_MAIN_START__ + (unsigned)_MAIN_SIZE__ + (unsigned)_STACKSIZE__;
    while (*p == PAINT)
        p++;
    while (((r8_u8 *)0x100)[s] == PAINT)
        s++;
    write(2, "STACK c=", 8);
    put_u(top - (unsigned)p);
    write(2, " hw=", 4);
    put_u(0x100u - s);
    write(2, "\n", 1);
    exit(code);
}
