/* facecull.S - r8k_cull (include/r8kern.h) for AVR with MUL (ATmega).
 *
 *   int r8k_cull(const r8_s16 *n, const r8_s16 *v, const r8_vec3l *eye);
 *
 * The 16-bit backface test of src/cull.c (r8_cull_front's fast path):
 * -1 when a component of the face's first vertex v lies outside
 * [-1023, 1023]; else 1 when n . (eye - 16 v) > 0, 0 otherwise, the dot
 * product exact in 32 bits.  n (the face's unit normal, Q1.14) and v are
 * three r8_s16 in flash (LPM; RAM when R8_NO_PROGMEM is defined, as
 * R8_RDS16 reads then); eye in RAM, of which only each component's low
 * 16 bits are read (the caller guarantees |eye| <= 16383).  |eye - 16 v|
 * < 2^15 and |n| <= 2^14, so the sum of the three products is < 2^31.
 *
 * Registers (avr-gcc ABI): arguments n r25:r24, v r23:r22, eye r21:r20.
 * X = eye, Z = v then n.  The differences d0 r19:r18, d1 r21:r20,
 * d2 r23:r22; the sum r27:r26:r25:r24; the normal component r17:r16;
 * r15 zero.  Saves r15, r16, r17; clears r1 before returning.
 */
#ifdef R8_NO_PROGMEM
#define RD(r) ld r, Z+
#else
#define RD(r) lpm r, Z+
#endif

#define ZERO r15

#include "facemac.h"


    .section .text.r8k_cull,"ax",@progbits
    .global r8k_cull
    .type   r8k_cull, @function
r8k_cull:
    push  r15
    push  r16
    push  r17
    movw  r26, r20          /* X = eye */
    movw  r30, r22          /* Z = v (flash) */
    rcall .Ldiff            /* d0, parked in r23:r22 */
    brcc  out
    movw  r22, r18
    rcall .Ldiff            /* d1 */
    brcc  out
    movw  r20, r18
    rcall .Ldiff            /* d2, and d0 back to r19:r18 */
    brcc  out
    movw  r16, r18
    movw  r18, r22
    movw  r22, r16
    rjmp  dot
out:
    ldi   r24, 0xFF         /* -1: the caller's 32-bit path */
    ldi   r25, 0xFF
    rjmp  done
dot:
    movw  r30, r24          /* Z = n (flash) */
    DOT3                    /* r27:r24 = n . d (facemac.h) */
    mov   r0, r24           /* > 0: not zero and the sign clear */
    or    r0, r25
    or    r0, r26
    or    r0, r27
    ldi   r24, 0
    breq  1f
    sbrs  r27, 7
    ldi   r24, 1
1:  ldi   r25, 0
done:
    clr   r1
    pop   r17
    pop   r16
    pop   r15
    ret

/* one component: facemac.h's DIFF into r19:r18, as a subroutine (one
 * copy for the three); C clear when v is out of range */
.Ldiff:
    DIFF  r18, r19, 1f
    sec
1:  ret
    .size r8k_cull, .-r8k_cull
