/* saves.h - the AVR kernels' full save and restore of the call-saved
 * registers (avr-gcc's ABI: r2..r17, r28, r29), for kernels that use
 * them all (fwalk.S, trap.S, zfill.S). */
#ifndef R8_AVR_SAVES_H
#define R8_AVR_SAVES_H

.macro SAVE18
    .irp  r, r2, r3, r4, r5, r6, r7, r8, r9, r10, r11, r12, r13, r14, r15, r16, r17, r28, r29
    push  \r
    .endr
.endm

.macro RESTORE18
    .irp  r, r29, r28, r17, r16, r15, r14, r13, r12, r11, r10, r9, r8, r7, r6, r5, r4, r3, r2
    pop   \r
    .endr
.endm

#endif
