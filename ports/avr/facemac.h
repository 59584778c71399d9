/* facemac.h - the face kernels' shared macros (facecull.S, facelevel.S,
 * fwalk.S): the including file defines RD(r) (a flash or RAM read
 * through Z+) and ZERO (a register holding 0). */
#include "mac16.h"

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
    MAC16 0, r24, r25, r26, r27, r16, r17, \dl, \dh, ZERO
.endm

/* the sum r27:r24 = n . d, both signed 16: n read through RD from Z,
 * d in r19:r18, r21:r20, r23:r22 (the first product sets the sum);
 * ZERO cleared here, r1 left dirty */
.macro DOT3
    clr   ZERO
    RD(r16)                 /* the first product sets the sum */
    RD(r17)
    MAC16 1, r24, r25, r26, r27, r16, r17, r18, r19, ZERO
    ACC   r20, r21
    ACC   r22, r23
.endm
