/* facemac.h - the face kernels' shared macros (facecull.S, facelevel.S,
 * fwalk.S): the including file defines RD(r) (a flash or RAM read
 * through Z+) and ZERO (a register holding 0). */

/* d = eye component - 16 v component (X advances to the next r8_s32);
 * out of range: to `out` */
.macro DIFF dl, dh, out
    RD(\dl)
    RD(\dh)
    movw  r16, \dl
    subi  r16, 0x01
    sbci  r17, 0xFC         /* v + 1023 */
    cpi   r16, 0xFF
    sbci  r17, 0x07         /* C iff v + 1023 <= 2046 (unsigned) */
    brcc  \out
    swap  \dh               /* v << 4 (fits: |v| <= 1023) */
    swap  \dl
    andi  \dh, 0xF0
    eor   \dh, \dl
    andi  \dl, 0xF0
    eor   \dh, \dl
    ld    r16, X+
    ld    r17, X
    adiw  r26, 3
    sub   r16, \dl
    sbc   r17, \dh
    movw  \dl, r16
.endm

/* the sum r27:r24 += n component (r17:r16, read here) * d, both
 * signed 16 */
.macro ACC dl, dh
    RD(r16)
    RD(r17)
    mul   r16, \dl          /* u x u, at byte 0 */
    add   r24, r0
    adc   r25, r1
    adc   r26, ZERO
    adc   r27, ZERO
    muls  r17, \dh          /* s x s, at byte 2 */
    add   r26, r0
    adc   r27, r1
    mulsu r17, \dl          /* s x u, at byte 1; C = its sign */
    sbc   r27, ZERO         /* the sign extension: -2^24 */
    add   r25, r0
    adc   r26, r1
    adc   r27, ZERO
    mulsu \dh, r16          /* s x u, at byte 1 */
    sbc   r27, ZERO
    add   r25, r0
    adc   r26, r1
    adc   r27, ZERO
.endm

/* the sum r27:r24 = n . d, both signed 16: n read through RD from Z,
 * d in r19:r18, r21:r20, r23:r22 (the first product sets the sum);
 * ZERO cleared here, r1 left dirty */
.macro DOT3
    clr   ZERO
    RD(r16)                 /* the first product sets the sum */
    RD(r17)
    mul   r16, r18
    movw  r24, r0
    muls  r17, r19
    movw  r26, r0
    mulsu r17, r18
    sbc   r27, ZERO
    add   r25, r0
    adc   r26, r1
    adc   r27, ZERO
    mulsu r19, r16
    sbc   r27, ZERO
    add   r25, r0
    adc   r26, r1
    adc   r27, ZERO
    ACC   r20, r21
    ACC   r22, r23
.endm
