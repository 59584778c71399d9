/* facez.S - r8k_zsum (include/r8kern.h) for AVR with MUL (ATmega).
 *
 *   int r8k_zsum(const r8_s16 *verts, const r8_u8 *vi, r8_u8 n,
 *                const r8_s16 *row, r8_s32 *out);
 *
 * The painter's depth sum of src/render.c's face_zsum: the model
 * vertices verts[3 vi[k] ..] (flash: LPM, RAM when R8_NO_PROGMEM is
 * defined; vi in RAM, n >= 1) summed per component exactly (24 bits);
 * 0 when a sum lies outside [-32767, 32767] (out unset: the caller's
 * 32-bit path); else 1 and *out = floor((row . sums + 512) / 1024), the
 * dot product exact in 32 bits (row three Q1.14 r8_s16 in RAM).
 *
 * Registers (avr-gcc ABI): arguments verts r25:r24, vi r23:r22, n r20,
 * row r19:r18, out r17:r16 (call-saved: pushed, and popped back into
 * r17:r16 to be used).  First the sums in 16 bits: X = vi, r16 = 6, r17
 * counts, Z the vertex, sums r11:r10, r13:r12, r15:r14; a signed
 * overflow (V) starts again with the 24-bit sums (the arguments are
 * still there): X = vi, then row; Z = the vertex; the sums
 * r14:r19:r18, r15:r21:r20, r13:r23:r22; n in r12; row in r11:r10.
 * Then Z = row, the product sum r27:r26:r25:r24 of the sums in r19:r18,
 * r21:r20, r23:r22; r15 zero.  Saves r10..r17; clears r1.
 */
#ifdef R8_NO_PROGMEM
#define RD(r) ld r, Z+
#else
#define RD(r) lpm r, Z+
#endif

#define ZERO r15
#include "mac16.h"

/* sum (hi:l1:l0) += the next vertex component (r1 = 0) */
.macro ADDV l0, l1, hi
    RD(r16)
    RD(r17)
    add   \l0, r16
    adc   \l1, r17
    adc   \hi, r1
    sbrc  r17, 7
    dec   \hi
.endm

/* sum (hi:l1:l0) in [-32767, 32767]?  else to `out` */
.macro RANGE l0, l1, hi
    movw  r16, \l0
    mov   r30, \hi
    subi  r16, 0x01         /* + 32767 (24 bits) */
    sbci  r17, 0x80
    sbci  r30, 0xFF
    tst   r30
    brne  out
    cpi   r16, 0xFF
    ldi   r31, 0xFF
    cpc   r17, r31
    breq  out               /* 32768 */
.endm

/* the product sum += row component (r17:r16, read here: Z) * s, signed 16 */
.macro ACC dl, dh
    ld    r16, Z+
    ld    r17, Z+
    MAC16 0, r24, r25, r26, r27, r16, r17, \dl, \dh, ZERO
.endm

    .section .text.r8k_zsum,"ax",@progbits
    .global r8k_zsum
    .type   r8k_zsum, @function
r8k_zsum:
    push  r10
    push  r11
    push  r12
    push  r13
    push  r14
    push  r15
    push  r17               /* out (popped back at the end) */
    push  r16
    movw  r26, r22          /* X = vi */
    ldi   r16, 6
    mov   r17, r20
    ld    r30, X+           /* the first vertex sets the 16-bit sums */
    mul   r30, r16
    movw  r30, r0
    add   r30, r24
    adc   r31, r25
    RD(r10)
    RD(r11)
    RD(r12)
    RD(r13)
    RD(r14)
    RD(r15)
    dec   r17
    breq  4f
3:  ld    r30, X+
    mul   r30, r16
    movw  r30, r0
    add   r30, r24
    adc   r31, r25
    RD(r0)                  /* (lpm and ld leave C and V) */
    add   r10, r0
    RD(r0)
    adc   r11, r0
    brvs  z24
    RD(r0)
    add   r12, r0
    RD(r0)
    adc   r13, r0
    brvs  z24
    RD(r0)
    add   r14, r0
    RD(r0)
    adc   r15, r0
    brvs  z24
    dec   r17
    brne  3b
4:  movw  r30, r18          /* Z = row */
    movw  r18, r10
    movw  r20, r12
    movw  r22, r14
    ldi   r16, 0x80         /* a sum of -32768: out */
    tst   r18
    brne  5f
    cp    r19, r16
    breq  zo
5:  tst   r20
    brne  5f
    cp    r21, r16
    breq  zo
5:  tst   r22
    brne  prod
    cp    r23, r16
    brne  prod
zo: rjmp  out
z24:
    movw  r26, r22          /* X = vi */
    movw  r10, r18          /* row */
    mov   r12, r20          /* n */
    clr   r18
    clr   r19
    clr   r20
    clr   r21
    clr   r22
    clr   r23
    clr   r13
    clr   r14
    clr   r15
1:  ld    r30, X+           /* Z = verts + 6 vi[k] */
    ldi   r31, 6
    mul   r30, r31
    movw  r30, r0
    clr   r1
    add   r30, r24
    adc   r31, r25
    ADDV  r18, r19, r14
    ADDV  r20, r21, r15
    ADDV  r22, r23, r13
    dec   r12
    brne  1b
    rjmp  z24r
z24p:
    movw  r30, r10          /* Z = row */
prod:
    clr   ZERO
    ld    r16, Z+           /* the first product sets the sum */
    ld    r17, Z+
    MAC16 1, r24, r25, r26, r27, r16, r17, r18, r19, ZERO
    ACC   r20, r21
    ACC   r22, r23
    subi  r25, 0xFE         /* + 512 */
    sbci  r26, 0xFF
    sbci  r27, 0xFF
    asr   r27               /* >> 10, floor: r27:r26:r25 after two */
    ror   r26
    ror   r25
    asr   r27
    ror   r26
    ror   r25
    mov   r24, r27          /* the sign byte */
    lsl   r24
    sbc   r24, r24
    pop   r16               /* out */
    pop   r17
    movw  r30, r16
    st    Z+, r25
    st    Z+, r26
    st    Z+, r27
    st    Z, r24
    ldi   r24, 1
done:
    ldi   r25, 0
    clr   r1
    pop   r15
    pop   r14
    pop   r13
    pop   r12
    pop   r11
    pop   r10
    ret
z24r:                       /* (the 24-bit sums' tests, out of the way) */
    RANGE r18, r19, r14
    RANGE r20, r21, r15
    RANGE r22, r23, r13
    rjmp  z24p
out:
    pop   r16               /* 0: a sum needs more than 16 bits */
    pop   r17
    ldi   r24, 0
    rjmp  done
    .size r8k_zsum, .-r8k_zsum
