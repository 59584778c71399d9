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
 * r21:r20, colour r18.  amb goes to r13:r12, colour to r14, the light to
 * r19:r18, r21:r20, r23:r22; Z = n; the sum r27:r26:r25:r24; the normal
 * component r17:r16; r15 zero.  Saves r12..r17; clears r1.
 */
#ifdef R8_NO_PROGMEM
#define RD(r) ld r, Z+
#else
#define RD(r) lpm r, Z+
#endif

#define ZERO r15

#include "facemac.h"   /* ACC: the sum += n component * l */


    .section .text.r8k_level,"ax",@progbits
    .global r8k_level
    .type   r8k_level, @function
r8k_level:
    push  r12
    push  r13
    push  r14
    push  r15
    push  r16
    push  r17
    movw  r12, r20          /* amb */
    mov   r14, r18          /* colour */
    movw  r26, r22          /* X = light */
    ld    r18, X+
    ld    r19, X+
    ld    r20, X+
    ld    r21, X+
    ld    r22, X+
    ld    r23, X
    movw  r30, r24          /* Z = n (flash) */
    DOT3                    /* r27:r24 = n . d (facemac.h) */
    /* i = d > 0 ? min(d >> 14, 16384) : 0 in r23:r22 (d < 3 2^28) */
    clr   r22
    clr   r23
    sbrc  r27, 7
    rjmp  1f                /* d < 0: i = 0 */
    lsl   r25
    rol   r26
    rol   r27
    lsl   r25
    rol   r26
    rol   r27
    movw  r22, r26          /* d >> 14, as r8_s16 */
    cpi   r22, 0x01
    ldi   r16, 0x40
    cpc   r23, r16
    brlt  1f                /* <= 16384 (signed, as the C) */
    ldi   r22, 0x00
    ldi   r23, 0x40
1:  ldi   r16, 0x00         /* w = 16384 - amb (>= 0) */
    ldi   r17, 0x40
    sub   r16, r12
    sbc   r17, r13
    mul   r16, r22          /* w i, signed 16 x 16 */
    movw  r24, r0
    muls  r17, r23
    movw  r26, r0
    mulsu r17, r22
    sbc   r27, ZERO
    add   r25, r0
    adc   r26, r1
    adc   r27, ZERO
    mulsu r23, r16
    sbc   r27, ZERO
    add   r25, r0
    adc   r26, r1
    adc   r27, ZERO
    lsl   r25               /* bits 14..29: r27:r26 */
    rol   r26
    rol   r27
    lsl   r25
    rol   r26
    rol   r27
    add   r26, r12          /* q = amb + w i >> 14 (16 bits) */
    adc   r27, r13
    mul   r27, r14          /* T = q colour (< 2^24) in r26:r25:r24 */
    movw  r22, r0
    mul   r26, r14
    movw  r24, r0
    add   r25, r22
    clr   r26
    adc   r26, r23
    subi  r24, 0xE0         /* + 8224 */
    sbci  r25, 0xDF
    sbci  r26, 0xFF
    lsl   r25               /* >> 14: r26 */
    rol   r26
    lsl   r25
    rol   r26
    mov   r24, r26
    clr   r1
    pop   r17
    pop   r16
    pop   r15
    pop   r14
    pop   r13
    pop   r12
    ret
    .size r8k_level, .-r8k_level
