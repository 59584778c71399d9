/* plat_z80.c - platform layer for the Z80 under ucsim sz80 (sdcc).
 *
 * Memory map (64 KB RAM): crt0 at 0x0000-0x010F, the four I/O bytes
 * below at 0x01FC-0x01FF, code from 0x0200, statics right after the code
 * (ports/z80/z80link.py links twice to place them), stack down from 0xFFFF.
 * (The toolchain notes put the simif byte at 0x7FFF, but the library
 * alone is ~50 KB of sdcc code, so nothing fixed can sit mid-memory.)
 *
 * UART: the simif byte at 0x01FF (sz80 -I 'if=rom[0x1ff],out=FILE'):
 *   'w' then the byte appends it to FILE (binary-safe); 's' stops the run.
 * Markers: the id is written to 0x01FE; emu/sz80run.py sets a write
 *   breakpoint there and reads the tick count at every stop.
 * Stack peak: plat_init paints the free RAM between the end of the
 *   statics (s__HEAP) and the current SP with 0xA5; plat_exit finds the
 *   lowest overwritten byte and stores the peak (bytes below 0x10000,
 *   crt0 starts SP at 0x0000) at 0x01FC (lo) / 0x01FD (hi), where the
 *   runner dumps it.
 */
#include "plat.h"

#define SIF (*(volatile r8_u8 *)0x01FF)
#define MARK (*(volatile r8_u8 *)0x01FE)
#define STK_LO (*(volatile r8_u8 *)0x01FC)
#define STK_HI (*(volatile r8_u8 *)0x01FD)
#define PAINT 0xA5

r8_u16 plat_z80_heap;

static void get_heap(void) __naked
{
    __asm
        ld hl, #s__HEAP
        ld (_plat_z80_heap), hl
        ret
    __endasm;
}

void plat_init(void)
{
    r8_u8 here;
    r8_u16 a, top;
    get_heap();
    top = (r8_u16)&here - 32u;
    for (a = plat_z80_heap; a < top; a++)
        *(r8_u8 *)a = PAINT;
}

void plat_putc(r8_u8 c)
{
    SIF = 'w';
    SIF = c;
}

#ifdef R8_ASM_WIRE
/* The same loop in assembly (p in HL, n in DE; with the wire kernels,
 * whose bytes it writes): ldi copies a byte to the simif address and
 * counts BC down; 4 bytes a round (33 T a byte against the simple
 * loop's 47 and sdcc's 75).  The identity tests (xident-z80) compare
 * every byte it writes with the host's. */
void plat_write(const r8_u8 *p, unsigned n) __naked
{
    __asm
        ld   b, d
        ld   c, e          ; BC = n
        ld   de, #0x01FF   ; the simif byte
1$:     ld   a, c
        and  a, #3
        jr   z, 2$         ; n & 3 bytes one at a time first
        ld   a, #0x77      ; the write command
        ld   (de), a
        ldi                ; (DE) = (HL); HL++, DE++, BC--
        dec  de
        jr   1$
2$:     ld   a, b
        or   a, c
        ret  z
        ld   a, #0x77
3$:     ld   (de), a
        ldi
        dec  de
        ld   (de), a
        ldi
        dec  de
        ld   (de), a
        ldi
        dec  de
        ld   (de), a
        ldi
        dec  de
        jp   pe, 3$        ; BC != 0
        ret
    __endasm;
    (void)p;
    (void)n;
}
#else
void plat_write(const r8_u8 *p, unsigned n)
{
    while (n--) {
        SIF = 'w';
        SIF = *p++;
    }
}
#endif

int plat_getc(void)
{
    return -1;   /* ucsim runs: no receive path */
}

void plat_mark(r8_u8 id)
{
    MARK = id;
}

void plat_exit(int code)
{
    r8_u8 *p = (r8_u8 *)plat_z80_heap;
    r8_u16 peak;
    while (p != 0 && *p == PAINT)
        p++;
    peak = (r8_u16)(0u - (r8_u16)p);
    STK_LO = (r8_u8)(peak & 0xFF);
    STK_HI = (r8_u8)(peak >> 8);
    MARK = (r8_u8)(0xE0 | (code & 0x0F)); /* exit marker: 0xE0 + code */
    SIF = 's';
    for (;;)
        MARK = 0xFF; /* extra 'run' commands stop here at once */
}
