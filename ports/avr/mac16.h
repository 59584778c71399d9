/* mac16.h - the AVR kernels' signed 16 x 16 -> 32 multiply-accumulate
 * (facemac.h's ACC and DOT3, facez.S, fwpaint.S, facelevel.S):
 *     s3:s2:s1:s0 (+)= ah:al * bh:bl   (both signed 16, mod 2^32)
 * with `first` 1 to set the sum instead of adding to it, `zero` a
 * register holding 0; r1:r0 left dirty.  MULS and MULSU take r16..r23,
 * so ah and bh must lie there. */
#ifndef R8_AVR_MAC16_H
#define R8_AVR_MAC16_H

.macro MAC16 first, s0, s1, s2, s3, al, ah, bl, bh, zero
    mul   \al, \bl          /* u x u, at byte 0 */
.if \first
    movw  \s0, r0
    muls  \ah, \bh          /* s x s, at byte 2 */
    movw  \s2, r0
.else
    add   \s0, r0
    adc   \s1, r1
    adc   \s2, \zero
    adc   \s3, \zero
    muls  \ah, \bh          /* s x s, at byte 2 */
    add   \s2, r0
    adc   \s3, r1
.endif
    mulsu \ah, \bl          /* s x u, at byte 1; C = its sign */
    sbc   \s3, \zero        /* the sign extension: -2^24 */
    add   \s1, r0
    adc   \s2, r1
    adc   \s3, \zero
    mulsu \bh, \al          /* s x u, at byte 1 */
    sbc   \s3, \zero
    add   \s1, r0
    adc   \s2, r1
    adc   \s3, \zero
.endm

#endif
