/* projmac.h - r8k_project's steps, shared by project.S and vertex.S
 * (r8k_vertex): NORM (z normalised for the table), RECIP (the
 * reciprocal's table step), KSETUP (the coordinate scale from the
 * reciprocal and the camera) and COORD (one coordinate). */

/* zn (r23:r22, r23 != 0) normalised to [2^15, 2^16), its shift added to
 * s (r26); r27 scratch; ends at `done` */
.macro NORM done
    cpi   r23, 0x10
    brsh  8f
    swap  r23               /* four bits at once */
    swap  r22
    mov   r27, r22
    andi  r27, 0x0F
    andi  r23, 0xF0
    or    r23, r27
    andi  r22, 0xF0
    subi  r26, -4
8:  tst   r23
    brmi  \done
9:  inc   r26               /* then bit by bit */
    lsl   r22
    rol   r23
    brpl  9b
.endm

/* From m (r17:r16) and e (r26): kk (r17:r16), k = sh - 1 (r27), L (r26),
 * lim (r31:r30), with fn, fsh and guard the camera's fields at Y + those
 * offsets; `zero` is cleared and left 0; to `shzero` when sh = 0.  r0,
 * r1, r18, r19, r22, r23 scratch. */
.macro KSETUP zero, fn, fsh, guard, shzero
    clr   \zero
    ldd   r18, Y+\fn         /* k = m fn: r31:r30:r23:r22 */
    ldd   r19, Y+\fn+1
    mul   r16, r18
    movw  r22, r0
    mul   r17, r19
    movw  r30, r0
    mul   r16, r19
    add   r23, r0
    adc   r30, r1
    adc   r31, \zero
    mul   r17, r18
    add   r23, r0
    adc   r30, r1
    adc   r31, \zero
    ldi   r18, 16
    cpi   r31, 0x40
    brsh  8f
    lsl   r23               /* kk = k >> 15, sh = 16 + fsh - e */
    rol   r30
    rol   r31
    rjmp  9f
8:  dec   r18               /* kk = k >> 16, sh = 15 + fsh - e */
9:  movw  r16, r30
    sub   r18, r26          /* >= 0 (|e| <= 15) */
    ldd   r27, Y+\fsh
    add   r27, r18
    brcs  10f               /* sh > 255 */
    subi  r27, 1
    brcc  11f
    rjmp  \shzero           /* sh = 0 */
11: cpi   r27, 31
    brlo  12f
10: ldi   r27, 30           /* sh > 31: 31 */
12: mov   r26, r27          /* L = 7 - (k & 7) */
    com   r26
    andi  r26, 7
    ldd   r30, Y+\guard      /* lim = 16 guard */
    ldd   r31, Y+\guard+1
    lsl   r30
    rol   r31
    lsl   r30
    rol   r31
    lsl   r30
    rol   r31
    lsl   r30
    rol   r31
.endm

/* q (r24:r23) of the coordinate in r19:r18: kk r17:r16, k r27, L r26,
 * lim r31:r30, `zero` 0; to `out` when out of range */
.macro COORD zero, out
    mul   r18, r16          /* P = v kk: al kl (u x u), at byte 0 */
    movw  r22, r0
    muls  r19, r17          /* ah kh (s x s), at byte 2 */
    movw  r24, r0
    mulsu r19, r16          /* ah kl (s x u), at byte 1; C = its sign */
    sbc   r25, \zero          /* its sign extension: -2^24 */
    add   r23, r0
    adc   r24, r1
    adc   r25, \zero
    mulsu r17, r18          /* kh al (s x u), at byte 1 */
    sbc   r25, \zero
    add   r23, r0
    adc   r24, r1
    adc   r25, \zero
    sbrs  r27, 4            /* k & 16: two bytes off */
    rjmp  1f
    movw  r22, r24
    mov   r24, r23
    lsl   r24
    sbc   r24, r24
    mov   r25, r24
1:  sbrs  r27, 3            /* k & 8: one byte off */
    rjmp  2f
    mov   r22, r23
    mov   r23, r24
    mov   r24, r25
    lsl   r25
    sbc   r25, r25
2:  mov   r0, r26           /* << L; a sign change: far out */
    tst   r0
    breq  4f
3:  lsl   r22
    rol   r23
    rol   r24
    rol   r25
    brvs  \out
    dec   r0
    brne  3b
4:  mov   r0, r24           /* floor(P / 2^sh) = r25:r24:r23 in 16 bits? */
    lsl   r0
    sbc   r0, r0
    cp    r25, r0
    brne  \out
    lsl   r22               /* q = that + bit sh - 1 of P */
    adc   r23, \zero
    adc   r24, \zero
    cp    r30, r23          /* q > lim */
    cpc   r31, r24
    brlt  \out
    add   r23, r30          /* q + lim < 0 (S: the true sign) */
    adc   r24, r31
    brlt  \out
    sub   r23, r30
    sbc   r24, r31
.endm

/* project.S's step 1: m (r17:r16) = t0 - (((t0 - t1) ((zn & 0xFF) >> 1)
 * + 64) >> 7) for zn (r23:r22) in [2^15, 2^16), t0 and t1 r8k_rec_tab's
 * entries i and i + 1, i = (zn >> 8) & 0x7F; r0, r1, r22, r27, r30, r31
 * scratch */
.macro RECIP
    mov   r27, r23          /* Z = rec_tab + 2 ((zn >> 8) & 0x7F) */
    lsl   r27
    ldi   r30, lo8(r8k_rec_tab)
    ldi   r31, hi8(r8k_rec_tab)
    add   r30, r27
    brcc  .+2
    inc   r31
    lpm   r16, Z+           /* t0 (r17:r16), t1 (r1:r0) */
    lpm   r17, Z+
    lpm   r0, Z+
    lpm   r1, Z
    movw  r30, r16          /* t0 - t1 < 512 */
    sub   r30, r0
    sbc   r31, r1
    lsr   r22               /* (zn & 0xFF) >> 1 */
    mul   r30, r22
    sbrc  r31, 0
    add   r1, r22
    movw  r30, r0           /* (that + 64) >> 7 = r27:r31 */
    subi  r30, 0xC0
    sbci  r31, 0xFF
    lsl   r30
    rol   r31
    clr   r27
    rol   r27
    sub   r16, r31          /* m = t0 - that */
    sbc   r17, r27
.endm
