/* plat.h - the small platform layer the demo firmware runs on.
 * One implementation per target: emu/plat_host.c (host emulator),
 * emu/fw_plat_host.c (host reference firmware), ports/avr/plat_avr.c,
 * ports/6502/plat_sim65.c, ports/z80/plat_z80.c.  docs/porting.md says
 * what a new one must do. */
#ifndef PLAT_H
#define PLAT_H

#include "r8types.h"

void plat_init(void);
void plat_putc(r8_u8 c);                     /* one UART byte, binary-safe */
void plat_write(const r8_u8 *p, unsigned n); /* n UART bytes */
int plat_getc(void);                         /* a received UART byte, or -1
                                                when none is waiting */
void plat_mark(r8_u8 id);                    /* cycle marker (GPIOR0 etc.) */
void plat_exit(int code);                    /* end of run */

/* Marker ids the firmware emits. */
#define PLAT_MARK_START 1       /* after init */
#define PLAT_MARK_FRAME_BEGIN 2 /* before r8_render_frame */
#define PLAT_MARK_FRAME_END 3   /* after the frame's last band */
#define PLAT_MARK_DONE 4        /* before plat_exit */

#endif
