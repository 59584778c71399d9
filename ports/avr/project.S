/* project.S - r8k_project (include/r8kern.h) for AVR with MUL (ATmega).
 *
 *   int r8k_project(const r8_proj *p, const r8_vec3l *c, r8_s16 *out,
 *                   r8_u16 *m, r8_s8 *e);
 *
 * Bit for bit the C reference in src/kern.c, r8_recip then
 * r8_project_recip (src/proj.c):
 *
 * 1. The reciprocal: z normalised to zn in [2^15, 2^16) by a shift s
 *    (z <= 0 taken as 1; z >= 2^16 shifted right, s < 0, truncating),
 *    then m = t0 - (((t0 - t1) ((zn & 0xFF) >> 1) + 64) >> 7) with t0, t1
 *    = rec_tab[i], rec_tab[i + 1], i = (zn >> 8) & 0x7F (this file's copy
 *    of the table in proj.c, which is static there).  *m = m, *e = s.
 * 2. kk, sh: k = m fn (32 bits); kk = k >> 16, sh = 15 + fsh - e when
 *    k >= 2^30, else kk = k >> 15, sh = 16 + fsh - e; sh > 31 is 31.
 *    kk is a signed 16-bit factor (in [2^14, 2^15) for an r8_proj from
 *    r8_proj_init; any fn and fsh give the reference's result too).
 * 3. sh <= 0: only x = y = 0 projects (to cx, cy).
 * 4. Per coordinate v (x, then y): q = floor((v kk + 2^(sh-1)) / 2^sh)
 *    (proj_round's round(p 2^-(k+1)), k = sh - 1), out of range (1) when
 *    q > lim or q < -lim, lim = 16 guard (16 bits: guard within
 *    +-2047, as the C needs); out = cx + qx, cy + qy.
 *
 * Step 4 as done here: P = v kk (signed 16 x 16), whole bytes off first
 * (floor(P / 2^(8 (k >> 3))), sign-filled), then a left shift by
 * L = 7 - (k & 7) (a sign change means |q| >= 2^23: out), so that
 * floor(P / 2^sh) is bytes 3..1 and the rounding bit (bit k of P) bit 7
 * of byte 0; q itself overflowing 16 bits fails the lim test.
 *
 * The reference runs proj_round when |x|, |y| <= 32767 and lim < 0x3FFF,
 * proj_wide otherwise.  For coordinates of 16 bits both are step 4:
 * proj_wide computes the same q and tests the same bounds; proj_round
 * also rejects floor(P / 2^k) outside [-0x7FFE, 0x7FFD], which with
 * lim < 0x3FFF only a q outside [-lim, lim] has.  (A negative lim, a
 * guard below 0, rejects every q either way.)  So this file does every
 * input whose x and y fit 16 bits; for the others (T set) it still takes
 * the reciprocal, and r8_project_recip (C: proj_wide) does the rest.
 *
 * Registers (avr-gcc ABI): arguments p r25:r24, c r23:r22, out r21:r20,
 * m r19:r18, e r17:r16; returns r25:r24.  Y = p; r15:r14 = c (for the
 * C call), then zero; r25:r24 = x, r13:r12 = y, then qx; z in
 * r1:r0:r23:r22, s r26; m r17:r16, then kk; k r27, L r26; lim r31:r30;
 * the coordinate in r19:r18 (MULS operands in r16..r23), P in
 * r25:r24:r23:r22.  Saves r12..r17, r28, r29; r1 is cleared before
 * returning.
 *
 * Offsets (avr-gcc, no padding): r8_proj {cx 0, cy 2, focal 4, znear 6,
 * guard 10, fn 12, fsh 14}; r8_vec3l {x 0, y 4, z 8}.
 */

/* v (byte 1 hi, bytes 2, 3 in r0, r1) fits 16 bits, else to fail */
.macro FIT16 hi, fail
    cp    r0, r1            /* bytes 2, 3 equal ... */
    brne  \fail
    sbrc  \hi, 7            /* ... and the sign of byte 1 */
    com   r0
    tst   r0
    brne  \fail
.endm

#include "projmac.h"   /* NORM, RECIP, KSETUP, COORD */

    .section .text.r8k_project,"ax",@progbits
    .global r8k_project
    .type   r8k_project, @function
r8k_project:
    push  r12
    push  r13
    push  r14
    push  r15
    push  r16
    push  r17
    push  r28
    push  r29
    movw  r14, r22          /* c, for the C call */
    movw  r28, r24          /* Y = p */
    movw  r30, r22          /* Z = c */

    /* T clear when x and y fit 16 bits */
    clt
    ldd   r24, Z+0          /* x */
    ldd   r25, Z+1
    ldd   r0, Z+2
    ldd   r1, Z+3
    FIT16 r25, 1f
    ldd   r26, Z+4          /* y */
    ldd   r27, Z+5
    ldd   r0, Z+6
    ldd   r1, Z+7
    FIT16 r27, 1f
    rjmp  2f
1:  set
2:  movw  r12, r26          /* y */

    /* zn = z normalised to [2^15, 2^16) (r23:r22), s (r26) */
    ldd   r22, Z+8
    ldd   r23, Z+9
    ldd   r0, Z+10
    ldd   r1, Z+11
    clr   r26
    tst   r1
    brmi  .Lzone              /* z < 0: as 1 */
    mov   r27, r0
    or    r27, r1
    brne  .Lzbig
    tst   r23
    brne  3f
    tst   r22
    breq  .Lzone              /* z = 0: as 1 */
    mov   r23, r22          /* a byte at once */
    clr   r22
    ldi   r26, 8
3:
    NORM  .Lnorm
    rjmp  .Lnorm
.Lzone:
    ldi   r22, 0x00         /* zn = 2^15, s = 15 */
    ldi   r23, 0x80
    ldi   r26, 15
    rjmp  .Lnorm
.Lzbig:                       /* z >= 2^16: right shifts, s < 0 */
    tst   r1
    breq  6f
    mov   r22, r23
    mov   r23, r0
    mov   r0, r1
    ldi   r26, 0xF8         /* -8 */
6:  dec   r26
    lsr   r0
    ror   r23
    ror   r22
    tst   r0
    brne  6b

.Lnorm:                       /* m from the table, *e = s, *m = m */
    movw  r30, r16
    st    Z, r26
    RECIP
    movw  r30, r18
    st    Z, r16
    std   Z+1, r17
    brtc  7f
    rjmp  .Lwide

    /* kk (r17:r16), k = sh - 1 (r27), L (r26), lim (r31:r30) */
7:
    KSETUP r15, 12, 14, 10, .Lshzero

    /* qx, qy */
    movw  r18, r24
    rcall .Lcoord
    brcs  .Lreject
    movw  r18, r12
    mov   r12, r23
    mov   r13, r24
    rcall .Lcoord
    brcc  20f
.Lreject:
    ldi   r24, 1
    rjmp  .Lret01
20:
    ldd   r0, Y+0           /* out = cx + qx, cy + qy */
    ldd   r1, Y+1
    add   r12, r0
    adc   r13, r1
    ldd   r0, Y+2
    ldd   r1, Y+3
    add   r23, r0
    adc   r24, r1
    movw  r30, r20
    st    Z, r12
    std   Z+1, r13
    std   Z+2, r23
    std   Z+3, r24
    ldi   r24, 0
.Lret01:
    ldi   r25, 0
.Lretp:
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

.Lshzero:                     /* sh <= 0: only x = y = 0 projects */
    or    r24, r25
    or    r24, r12
    or    r24, r13
    breq  13f
    rjmp  .Lreject
13: ldd   r12, Y+0
    ldd   r13, Y+1
    ldd   r22, Y+2
    ldd   r23, Y+3
    movw  r30, r20
    st    Z, r12
    std   Z+1, r13
    std   Z+2, r22
    std   Z+3, r23
    ldi   r24, 0
    rjmp  .Lret01

.Lwide:                       /* r8_project_recip(p, c, m, e, out, out + 1) */
    movw  r30, r20
    movw  r20, r16          /* m */
    mov   r18, r26          /* e */
    movw  r24, r28          /* p */
    movw  r22, r14          /* c */
    movw  r16, r30          /* sx */
    adiw  r30, 2
    movw  r14, r30          /* sy */
    clr   r1
    call  r8_project_recip
    rjmp  .Lretp

/* qx, then qy: one copy of COORD (C set: out of range) */
.Lcoord:
    COORD r15, 21f
    clc
    ret
21: sec
    ret
    .size r8k_project, .-r8k_project

/* round(2^31 / (32768 + 256 i)), i = 0..128 (the first clamped to 16
 * bits): the table of src/proj.c */
    .section .progmem.data.r8k_rec_tab,"a",@progbits
    .global r8k_rec_tab     /* (vertex.S reads it too) */
    .type   r8k_rec_tab, @object
r8k_rec_tab:
    .word 65535, 65028, 64528, 64035, 63550, 63072, 62602, 62138, 61681, 61231
    .word 60787, 60350, 59919, 59494, 59075, 58662, 58254, 57852, 57456, 57065
    .word 56680, 56299, 55924, 55554, 55188, 54828, 54471, 54120, 53773, 53431
    .word 53092, 52759, 52429, 52103, 51782, 51464, 51150, 50840, 50534, 50231
    .word 49932, 49637, 49345, 49056, 48771, 48489, 48210, 47935, 47663, 47393
    .word 47127, 46864, 46603, 46346, 46091, 45839, 45590, 45344, 45100, 44859
    .word 44620, 44384, 44151, 43919, 43691, 43464, 43240, 43019, 42799, 42582
    .word 42367, 42154, 41943, 41734, 41528, 41323, 41121, 40920, 40721, 40525
    .word 40330, 40137, 39946, 39756, 39569, 39383, 39199, 39017, 38836, 38657
    .word 38480, 38304, 38130, 37958, 37787, 37617, 37449, 37283, 37118, 36954
    .word 36792, 36631, 36472, 36314, 36158, 36003, 35849, 35696, 35545, 35395
    .word 35246, 35099, 34953, 34808, 34664, 34521, 34380, 34239, 34100, 33962
    .word 33825, 33689, 33554, 33421, 33288, 33157, 33026, 32897, 32768
    .size r8k_rec_tab, .-r8k_rec_tab
