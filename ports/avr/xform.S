/* xform.S - r8k_xform (include/r8kern.h) for AVR with MUL (ATmega).
 *
 *   void r8k_xform(const r8_mat3 *m, const r8_vec3l *t, const r8_s16 *v,
 *                  r8_vec3l *out);
 *
 * out[i] = floor((m[i][0] v0 + m[i][1] v1 + m[i][2] v2 + 512) / 1024) + t[i]
 * with the sum exact modulo 2^32, as the C reference in src/kern.c
 * computes it on avr-gcc.  m (9 Q1.14 r8_s16) and t in RAM, v (three
 * r8_s16) in flash (LPM; read from RAM when R8_NO_PROGMEM is defined,
 * as R8_RDS16 does then).
 *
 * Two row loops: when every vertex component fits in a signed byte (all
 * built-in meshes but the wall), each product is 16 x 8 (2 MULs, "fast");
 * otherwise 16 x 16 (4 MULs, "slow").  The sum is kept in 32 bits either
 * way, so both give the reference's result for every input.  Rounding:
 * floor((S + 512) / 1024) = (S >> 10) + bit 9 of S, the last bit the
 * shift drops, which enters the addition of t as the carry.
 *
 * Registers (avr-gcc ABI): arguments m r25:r24, t r23:r22, v r21:r20,
 * out r19:r18.  X = t, Y = out, Z = v then m.  The vertex is read into
 * r18..r23 (x0 r19:r18, x1 r21:r20, x2 r23:r22).  The fast loop saves
 * Y, r12, r13, r15; the slow one also r14, r16, r17.  r1 is cleared
 * before returning.
 */
#ifdef R8_NO_PROGMEM
#define RDV(r) ld r, Z+
#else
#define RDV(r) lpm r, Z+
#endif

#define A0  r24     /* the 32-bit sum; A1:A0 takes MOVW */
#define A1  r25
#define A3  r15
#define ZERO r13
#define CNT r12     /* rows left */

/* slow: 16x16 signed product m * (xh:xl) added to A3..A0 (A2 = r14,
 * m in r17:r16; MULS/MULSU operands all in r16..r23) */
.macro SLOW_ACC xl, xh
    ld    r16, Z+
    ld    r17, Z+
    mul   r16, \xl          /* u x u, at byte 0 */
    add   A0, r0
    adc   A1, r1
    adc   r14, ZERO
    adc   A3, ZERO
    muls  r17, \xh          /* s x s, at byte 2 */
    add   r14, r0
    adc   A3, r1
    mulsu r17, \xl          /* s x u, at byte 1; C = its sign */
    sbc   A3, ZERO          /* the sign extension: -2^24 */
    add   A1, r0
    adc   r14, r1
    adc   A3, ZERO
    mulsu \xh, r16          /* s x u, at byte 1 */
    sbc   A3, ZERO
    add   A1, r0
    adc   r14, r1
    adc   A3, ZERO
.endm

/* fast: 16x8 signed product m * x (x a signed byte) added to A3..A0
 * (A2 = r23, m in r21:r19) */
.macro FAST_ACC x
    ld    r19, Z+
    ld    r21, Z+
    mulsu \x, r19           /* s x u, at byte 0; C = its sign */
    sbc   r23, ZERO         /* the sign extension: -2^16 */
    sbc   A3, ZERO
    add   A0, r0
    adc   A1, r1
    adc   r23, ZERO
    adc   A3, ZERO
    muls  r21, \x           /* s x s, at byte 1 */
    sbc   A3, ZERO
    add   A1, r0
    adc   r23, r1
    adc   A3, ZERO
.endm

/* out row = (A >> 10) + bit 9 of A + t row; X -> t, Y -> out advance */
.macro TAIL a2
    asr   A3
    ror   \a2
    ror   A1
    asr   A3
    ror   \a2
    ror   A1                /* A3:A2:A1 = S >> 10, C = bit 9 of S */
    clr   A0                /* the sign byte (clr and dec keep C) */
    sbrc  A3, 7
    dec   A0
    ld    r0, X+
    adc   A1, r0
    ld    r0, X+
    adc   \a2, r0
    ld    r0, X+
    adc   A3, r0
    ld    r0, X+
    adc   A0, r0
    st    Y+, A1
    st    Y+, \a2
    st    Y+, A3
    st    Y+, A0
.endm

    .section .text.r8k_xform,"ax",@progbits
    .global r8k_xform
    .type   r8k_xform, @function
r8k_xform:
    push  r12
    push  r13
    push  r15
    push  r28
    push  r29
    movw  r28, r18          /* Y = out */
    movw  r26, r22          /* X = t */
    movw  r30, r20          /* Z = v (flash) */
    RDV(r18)
    RDV(r19)
    RDV(r20)
    RDV(r21)
    RDV(r22)
    RDV(r23)
    movw  r30, r24          /* Z = m */
    clr   ZERO
    ldi   A0, 3
    mov   CNT, A0
    /* every high byte the sign of its low byte?  (the high bytes are
     * complemented where the low byte is negative; undone if not) */
    sbrc  r18, 7
    com   r19
    sbrc  r20, 7
    com   r21
    sbrc  r22, 7
    com   r23
    mov   r0, r19
    or    r0, r21
    or    r0, r23
    breq  fast
    rjmp  slow

fast:                       /* one row, 16 x 8: x0 r18, x1 r20, x2 r22 */
    ld    r19, Z+
    ld    r21, Z+
    mulsu r18, r19
    movw  A0, r0
    sbc   r23, r23
    mov   A3, r23
    muls  r21, r18
    sbc   A3, ZERO
    add   A1, r0
    adc   r23, r1
    adc   A3, ZERO
    FAST_ACC r20
    FAST_ACC r22
    TAIL  r23
    dec   CNT
    brne  fast
    rjmp  done

slow:                       /* x0 r19:r18, x1 r21:r20, x2 r23:r22 */
    sbrc  r18, 7            /* undo the complements */
    com   r19
    sbrc  r20, 7
    com   r21
    sbrc  r22, 7
    com   r23
    push  r14
    push  r16
    push  r17
1:  ld    r16, Z+           /* one row, 16 x 16 */
    ld    r17, Z+
    mul   r16, r18
    movw  A0, r0
    muls  r17, r19
    movw  r14, r0
    mulsu r17, r18
    sbc   A3, ZERO
    add   A1, r0
    adc   r14, r1
    adc   A3, ZERO
    mulsu r19, r16
    sbc   A3, ZERO
    add   A1, r0
    adc   r14, r1
    adc   A3, ZERO
    SLOW_ACC r20, r21
    SLOW_ACC r22, r23
    TAIL  r14
    dec   CNT
    breq  2f
    rjmp  1b
2:  pop   r17
    pop   r16
    pop   r14

done:
    clr   r1
    pop   r29
    pop   r28
    pop   r15
    pop   r13
    pop   r12
    ret
    .size r8k_xform, .-r8k_xform
