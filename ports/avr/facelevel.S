/* facelevel.S - r8k_level (include/r8kern.h) for AVR with MUL (ATmega).
 *
 *   r8_u8 r8k_level(const r8_s16 *n, const r8_vec3 *light, r8_s16 amb,
 *                   r8_u8 colour);
 *
 * A face's Lambert dither level, as src/cull.c's r8_face_level computes
 * it through r8_tf_shade, for amb in [0, 16384] and components of n and
 * light within +-16384 (Q1.14):
 *   d = n . light (exact, 32 bits; n three r8_s16 in flash: LPM, or RAM
 *       when R8_NO_PROGMEM is defined; light three r8_s16 in RAM)
 *   i = d > 0 ? (r8_s16)(d >> 14) : 0, set to 16384 if above (signed)
 *   q = amb + bits 14..29 of (16384 - amb) i, in 16 bits
 *   level = bits 14..21 of q colour + 8224
 * (the last line is (((q colour 256 + 8192) >> 14) + 128) >> 8 as
 * r8_tf_shade's truncations give it, in one shift).
 *
 * Registers (avr-gcc ABI): arguments n r25:r24, light r23:r22, amb
 * r21:r20, colour r18.  amb goes to r25:r24, colour to r14; Z = n, X =
 * light, read a component at a time (r23:r22) beside the normal's
 * (r17:r16); the sum r21:r20:r19:r18; r15 zero.  Saves r14..r17 (two
 * fewer than with the light held in six registers); clears r1.  A face
 * turned from the light (d < 0: i = 0, q = amb) skips the w i product.
 */
#ifdef R8_NO_PROGMEM
#define RD(r) ld r, Z+
#else
#define RD(r) lpm r, Z+
#endif

#define ZERO r15
#include "mac16.h"

/* the sum r21:r18 (+)= n component (read here into r17:r16) * light
 * component (read through X into r23:r22), both signed 16 (MULS and
 * MULSU take r16..r23); \first: the first product sets the sum */
.macro LACC first
    RD(r16)
    RD(r17)
    ld    r22, X+
    ld    r23, X+
    MAC16 \first, r18, r19, r20, r21, r16, r17, r22, r23, ZERO
.endm

    .section .text.r8k_level,"ax",@progbits
    .global r8k_level
    .type   r8k_level, @function
r8k_level:
    push  r14
    push  r15
    push  r16
    push  r17
    movw  r30, r24          /* Z = n (flash) */
    movw  r24, r20          /* amb */
    mov   r14, r18          /* colour */
    clr   ZERO
    movw  r26, r22          /* X = light */
    LACC  1
    LACC  0
    LACC  0                 /* r21:r18 = n . light */
    /* i = d > 0 ? min(d >> 14, 16384) : 0 in r23:r22 (d < 3 2^28) */
    movw  r16, r24          /* q = amb when d < 0 */
    sbrc  r21, 7
    rjmp  2f                /* d < 0: i = 0 */
    lsl   r19
    rol   r20
    rol   r21
    lsl   r19
    rol   r20
    rol   r21
    movw  r22, r20          /* d >> 14, as r8_s16 */
    cpi   r22, 0x01
    ldi   r18, 0x40
    cpc   r23, r18
    brlt  1f                /* <= 16384 (signed, as the C) */
    ldi   r22, 0x00
    ldi   r23, 0x40
1:  ldi   r18, 0x00         /* w = 16384 - amb (>= 0) */
    ldi   r19, 0x40
    sub   r18, r24
    sbc   r19, r25
    mul   r18, r22          /* w i, signed 16 x 16 (i may be negative: */
    movw  r20, r0           /* d >> 14 past 32767, as the C) */
    muls  r19, r23
    movw  r16, r0
    mulsu r19, r22
    sbc   r17, ZERO
    add   r21, r0
    adc   r16, r1
    adc   r17, ZERO
    mulsu r23, r18
    sbc   r17, ZERO
    add   r21, r0
    adc   r16, r1
    adc   r17, ZERO
    lsl   r21               /* bits 14..29: r17:r16 */
    rol   r16
    rol   r17
    lsl   r21
    rol   r16
    rol   r17
    add   r16, r24          /* q = amb + w i >> 14 (16 bits) */
    adc   r17, r25
2:  mul   r17, r14          /* T = q colour (< 2^24) in r20:r19:r18 */
    movw  r22, r0
    mul   r16, r14
    movw  r18, r0
    add   r19, r22
    mov   r20, ZERO
    adc   r20, r23
    subi  r18, 0xE0         /* + 8224 */
    sbci  r19, 0xDF
    sbci  r20, 0xFF
    lsl   r19               /* >> 14: r20 */
    rol   r20
    lsl   r19
    rol   r20
    mov   r24, r20
    clr   r1
    pop   r17
    pop   r16
    pop   r15
    pop   r14
    ret
    .size r8k_level, .-r8k_level
