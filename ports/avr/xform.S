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
 * built-in meshes), each product is 16 x 8 (2 MULs); otherwise 16 x 16
 * (4 MULs).  The sum is kept in 32 bits either way, so both give the
 * reference's result for every input.  Rounding: floor((S + 512) / 1024)
 * = (S >> 10) + bit 9 of S, the last bit the shift drops, which enters
 * the addition of t as the carry.
 *
 * Registers (avr-gcc ABI): arguments m r25:r24, t r23:r22, v r21:r20,
 * out r19:r18; r12-r17 and Y are saved; r1 is cleared before returning.
 */
#ifdef R8_NO_PROGMEM
#define RDV(r) ld r, Z+
#else
#define RDV(r) lpm r, Z+
#endif

#define X0L r16     /* the vertex; MULS/MULSU need r16..r23 */
#define X0H r17
#define X1L r18
#define X1H r19
#define X2L r20
#define X2H r21
#define ML  r22     /* the matrix entry */
#define MH  r23
#define A0  r24     /* the 32-bit sum, A1:A0 and A3:A2 take MOVW */
#define A1  r25
#define A2  r14
#define A3  r15
#define ZERO r13
#define CNT r12     /* rows left */

/* 16x16 signed product m * (xh:xl) added to A3..A0 */
.macro GEN_ACC xl, xh
    ld    ML, Z+
    ld    MH, Z+
    mul   ML, \xl           /* u x u, at byte 0 */
    add   A0, r0
    adc   A1, r1
    adc   A2, ZERO
    adc   A3, ZERO
    muls  MH, \xh           /* s x s, at byte 2 */
    add   A2, r0
    adc   A3, r1
    mulsu MH, \xl           /* s x u, at byte 1; C = its sign */
    sbc   A3, ZERO          /* the sign extension: -2^24 */
    add   A1, r0
    adc   A2, r1
    adc   A3, ZERO
    mulsu \xh, ML           /* s x u, at byte 1 */
    sbc   A3, ZERO
    add   A1, r0
    adc   A2, r1
    adc   A3, ZERO
.endm

/* 16x8 signed product m * x (x a signed byte) added to A3..A0 */
.macro FAST_ACC x
    ld    ML, Z+
    ld    MH, Z+
    mulsu \x, ML            /* s x u, at byte 0; C = its sign */
    sbc   A2, ZERO          /* the sign extension: -2^16 */
    sbc   A3, ZERO
    add   A0, r0
    adc   A1, r1
    adc   A2, ZERO
    adc   A3, ZERO
    muls  MH, \x            /* s x s, at byte 1 */
    sbc   A3, ZERO
    add   A1, r0
    adc   A2, r1
    adc   A3, ZERO
.endm

/* out row = (A >> 10) + bit 9 of A + t row; X -> t, Y -> out advance */
.macro TAIL
    asr   A3
    ror   A2
    ror   A1
    asr   A3
    ror   A2
    ror   A1                /* A3:A2:A1 = S >> 10, C = bit 9 of S */
    clr   A0                /* the sign byte (clr and dec keep C) */
    sbrc  A3, 7
    dec   A0
    ld    r0, X+
    adc   A1, r0
    ld    r0, X+
    adc   A2, r0
    ld    r0, X+
    adc   A3, r0
    ld    r0, X+
    adc   A0, r0
    st    Y+, A1
    st    Y+, A2
    st    Y+, A3
    st    Y+, A0
.endm

    .section .text.r8k_xform,"ax",@progbits
    .global r8k_xform
    .type   r8k_xform, @function
r8k_xform:
    push  r12
    push  r13
    push  r14
    push  r15
    push  r16
    push  r17
    push  r28
    push  r29
    movw  r28, r18          /* Y = out */
    movw  r26, r22          /* X = t */
    movw  r30, r20          /* Z = v (flash) */
    RDV(X0L)
    RDV(X0H)
    RDV(X1L)
    RDV(X1H)
    RDV(X2L)
    RDV(X2H)
    movw  r30, r24          /* Z = m */
    clr   ZERO
    ldi   A0, 3
    mov   CNT, A0
    /* every high byte the sign of its low byte?  (the high bytes are
     * complemented where the low byte is negative; undone if not) */
    sbrc  X0L, 7
    com   X0H
    sbrc  X1L, 7
    com   X1H
    sbrc  X2L, 7
    com   X2H
    mov   r0, X0H
    or    r0, X1H
    or    r0, X2H
    breq  fast
    rjmp  slow

fast:                       /* one row, 16 x 8 */
    ld    ML, Z+
    ld    MH, Z+
    mulsu X0L, ML
    movw  A0, r0
    sbc   A2, A2
    mov   A3, A2
    muls  MH, X0L
    sbc   A3, ZERO
    add   A1, r0
    adc   A2, r1
    adc   A3, ZERO
    FAST_ACC X1L
    FAST_ACC X2L
    TAIL
    dec   CNT
    brne  fast
    rjmp  done

slow:                       /* undo the complements */
    sbrc  X0L, 7
    com   X0H
    sbrc  X1L, 7
    com   X1H
    sbrc  X2L, 7
    com   X2H

gen:                        /* one row, 16 x 16 */
    ld    ML, Z+
    ld    MH, Z+
    mul   ML, X0L
    movw  A0, r0
    muls  MH, X0H
    movw  A2, r0
    mulsu MH, X0L
    sbc   A3, ZERO
    add   A1, r0
    adc   A2, r1
    adc   A3, ZERO
    mulsu X0H, ML
    sbc   A3, ZERO
    add   A1, r0
    adc   A2, r1
    adc   A3, ZERO
    GEN_ACC X1L, X1H
    GEN_ACC X2L, X2H
    TAIL
    dec   CNT
    breq  done
    rjmp  gen

done:
    clr   r1
    pop   r29
    pop   r28
    pop   r17
    pop   r16
    pop   r15
    pop   r14
    pop   r13
    pop   r12
    ret
    .size r8k_xform, .-r8k_xform
