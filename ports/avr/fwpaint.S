/* fwpaint.S - r8k_fwpaint (include/r8kern.h): r8k_fwalk's painter's part
 * (ports/avr/fwalk.S jumps here through w->paint, set by the C only in
 * builds with painter's: without them this object, r8k_zsum and
 * __mulsi3 stay out of the firmware).
 *
 * Entered by ijmp from r8k_fwalk with a face that passed the frame test
 * (bsh < 0, w->top and w->bot set): Y = w, r1 = 0, r14-r17 saved by
 * r8k_fwalk.  The face's depth sum is r8k_zsum's (facez.S) done here
 * inline: the vertex indices read from flash into r26-r29, the model
 * vertices summed per component in 16 bits; a signed overflow on the
 * way (V) sends the face to r8k_zsum itself (its exact 24-bit sums,
 * vi and out on the stack); a sum of -32768 (or r8k_zsum's 0) goes back
 * to r8k_fwalk_ret1 (the caller buckets the face).  Then the product
 * with pk->row, the depth key from pk (src/kern.c's reference;
 * render.c's depth_key) - z kmul inline when both fit 16 bits, else
 * __mulsi3 - and ftop[id] when pk->ftop is set; on at r8k_fwalk_putk
 * with the key in r23:r22 (the links, slot, npoly, the next face).
 *
 * Registers: w in r14:r15 throughout.  The sums: r16 = 6, r17 = n
 * (then T = n is 4), r25:r24 = verts, indices r26-r29, Z the vertex,
 * sums r19:r18, r21:r20, r23:r22.  The product: Y = pk, Z = row, r17:r16
 * its component, r18 zero after the first cross product, sum
 * r27:r24.  zs (and z) bytes 0..3 in r25, r26, r27, r24.  About 400
 * cycles for a quad (r8k_zsum call, index copy and __mulsi3 took 570).
 */
#ifdef R8_NO_PROGMEM
#define RD(r) ld r, Z+
#else
#define RD(r) lpm r, Z+
#endif

/* offsets in r8_fwalk (as fwalk.S) and r8_fwpk (asserted in src/kern.c) */
#define W_FACES  2
#define W_VERTS  6
#define W_F     10
#define W_TOP   16
#define W_FBASE 33
#define W_FID8  36
#define W_PK    39
#define P_ROW   24
#define P_FTOP  26
#define P_FBSH  28

#define SPL_IO  0x3D
#define SPH_IO  0x3E

#include "mac16.h"

/* Z = w->faces + 6 w->f + 2 (the vertex indices), r17 = n; Y = w;
 * r16 = 6; r19:r18 and r1 changed */
.macro FACE
    ldi   r16, 6
    ldd   r18, Y+W_F
    ldd   r19, Y+W_F+1
    mul   r18, r16
    movw  r30, r0
    mul   r19, r16
    add   r31, r0
    ldd   r18, Y+W_FACES
    ldd   r19, Y+W_FACES+1
    add   r30, r18
    adc   r31, r19
    RD(r17)                 /* n */
    adiw  r30, 1
.endm

/* the sums += vertex \i (r16 = 6, r25:r24 = verts); a signed overflow
 * to zslow (through \ov) */
.macro VADD i, ov
    mul   \i, r16
    movw  r30, r0
    add   r30, r24
    adc   r31, r25
    RD(r0)                  /* (lpm and ld leave C and V) */
    add   r18, r0
    RD(r0)
    adc   r19, r0
    brvs  \ov
    RD(r0)
    add   r20, r0
    RD(r0)
    adc   r21, r0
    brvs  \ov
    RD(r0)
    add   r22, r0
    RD(r0)
    adc   r23, r0
    brvs  \ov
.endm

/* the sum r27:r24 += row component (read through Z) * \dh:\dl, both
 * signed 16, mod 2^32; r18 zero */
.macro ACC dl, dh
    ld    r16, Z+
    ld    r17, Z+
    MAC16 0, r24, r25, r26, r27, r16, r17, \dl, \dh, r18
.endm

    .section .text.r8k_fwpaint,"ax",@progbits
    .global r8k_fwpaint
    .type   r8k_fwpaint, @function
r8k_fwpaint:
    movw  r14, r28          /* w */
    FACE
    ldd   r24, Y+W_VERTS
    ldd   r25, Y+W_VERTS+1
    bst   r17, 2            /* T: n = 4 (n is 3 or 4 here) */
    RD(r26)                 /* the indices */
    RD(r27)
    RD(r28)
    brtc  1f
    RD(r29)
1:  mul   r26, r16          /* the first vertex sets the sums */
    movw  r30, r0
    add   r30, r24
    adc   r31, r25
    RD(r18)
    RD(r19)
    RD(r20)
    RD(r21)
    RD(r22)
    RD(r23)
    VADD  r27, zslow1
    VADD  r28, zslow1
    brts  7f
    rjmp  2f
zslow1:
    rjmp  zslow
zfail:
    movw  r28, r14          /* a sum past 16 bits: the caller's */
    clr   r1
    jmp   r8k_fwalk_ret1
7:  VADD  r29, zslow1
2:  tst   r18               /* a sum of -32768: r8k_zsum's 0 */
    brne  3f
    cpi   r19, 0x80
    breq  zfail
3:  tst   r20
    brne  3f
    cpi   r21, 0x80
    breq  zfail
3:  tst   r22
    brne  3f
    cpi   r23, 0x80
    breq  zfail
3:  movw  r30, r14
    ldd   r28, Z+W_PK       /* Y = pk */
    ldd   r29, Z+W_PK+1
    ldd   r30, Y+P_ROW      /* Z = row */
    ldd   r31, Y+P_ROW+1
    ld    r16, Z+           /* the first product sets the sum */
    ld    r17, Z+
    mul   r16, r18
    movw  r24, r0
    muls  r17, r19
    movw  r26, r0
    mulsu r17, r18
    clr   r18               /* (C kept) zero from here */
    sbc   r27, r18
    add   r25, r0
    adc   r26, r1
    adc   r27, r18
    mulsu r19, r16
    sbc   r27, r18
    add   r25, r0
    adc   r26, r1
    adc   r27, r18
    ACC   r20, r21
    ACC   r22, r23
    subi  r25, 0xFE         /* + 512 */
    sbci  r26, 0xFF
    sbci  r27, 0xFF
    asr   r27               /* >> 10, floor: r27:r26:r25 after two */
    ror   r26
    ror   r25
    asr   r27
    ror   r26
    ror   r25
    mov   r24, r27          /* the sign byte */
    lsl   r24
    sbc   r24, r24
zkey:
    /* z = zs + zc (r24:r27:r26:r25), 0 when negative; Z = pk->k
     * for n */
    movw  r30, r28
    brtc  1f
    adiw  r30, 12
1:  ld    r16, Z+
    add   r25, r16
    ld    r16, Z+
    adc   r26, r16
    ld    r16, Z+
    adc   r27, r16
    ld    r16, Z+
    adc   r24, r16
    brpl  2f
    clr   r24
    clr   r25
    movw  r26, r24
2:  ld    r16, Z+           /* z >= zr: key 0 */
    cp    r25, r16
    ld    r16, Z+
    cpc   r26, r16
    ld    r16, Z+
    cpc   r27, r16
    ld    r16, Z+
    cpc   r24, r16
    brge  key0
    ld    r20, Z+           /* kmul */
    ld    r21, Z+
    ld    r22, Z+
    ld    r23, Z
    mov   r16, r22
    or    r16, r23
    or    r16, r27
    or    r16, r24
    brne  kslow             /* z or kmul past 16 bits */
    mul   r25, r20          /* bytes 2, 3 of z kmul (r16 = 0) */
    mov   r17, r1
    mul   r26, r21
    movw  r22, r0
    mul   r25, r21
    add   r17, r0
    adc   r22, r1
    adc   r23, r16
    mul   r26, r20
    add   r17, r0
    adc   r22, r1
    adc   r23, r16
kjoin:
    brtc  3f                /* n = 4: >> 2 */
    lsr   r23
    ror   r22
    lsr   r23
    ror   r22
3:  tst   r23
    brne  4f
    cpi   r22, 64
    brlo  5f
4:  ldi   r22, 63
5:  com   r22               /* 63 - key */
    andi  r22, 63
    rjmp  6f
kslow:
    /* __mulsi3: r25:r22 = z (r25:r22) kmul (r21:r18); T in r17 */
    movw  r18, r20
    movw  r20, r22
    mov   r22, r25
    mov   r23, r26
    mov   r25, r24
    mov   r24, r27
    clr   r17
    bld   r17, 0
    clr   r1
    call  __mulsi3
    clr   r1
    bst   r17, 0
    movw  r22, r24          /* z kmul >> 16 */
    rjmp  kjoin
key0:
    clr   r22
6:  clr   r23
    /* ftop[id] = min(255, top >> fbsh; 0 for top < 0) */
    ldd   r30, Y+P_FTOP
    ldd   r31, Y+P_FTOP+1
    sbiw  r30, 0
    breq  9f
    ldd   r20, Y+P_FBSH
    movw  r28, r14          /* Y = w */
    ldd   r18, Y+W_F
    ldd   r19, Y+W_F+1
    ldd   r24, Y+W_FBASE
    ldd   r25, Y+W_FBASE+1
    add   r18, r24
    adc   r19, r25
    ldd   r24, Y+W_FID8
    tst   r24
    breq  1f
    clr   r19               /* 8-bit ids */
1:  add   r30, r18
    adc   r31, r19
    ldd   r24, Y+W_TOP
    ldd   r25, Y+W_TOP+1
    sbrs  r25, 7
    rjmp  2f
    clr   r24
    clr   r25
2:  tst   r20
    breq  4f
3:  lsr   r25
    ror   r24
    dec   r20
    brne  3b
4:  tst   r25
    breq  5f
    ldi   r24, 0xFF
5:  st    Z, r24
9:  movw  r28, r14          /* Y = w */
    clr   r1
    jmp   r8k_fwalk_putk

zslow:
    /* r8k_zsum(verts, vi, n, pk->row, out): vi and out 8 bytes on the
     * stack; 0: zfail; else zs popped into r25, r26, r27, r24 */
    movw  r28, r14          /* Y = w */
    FACE
    mov   r14, r17          /* n (w is in Y meanwhile) */
    push  r1
    push  r1
    push  r1
    push  r1
    push  r1
    push  r1
    push  r1
    push  r1
    in    r26, SPL_IO
    in    r27, SPH_IO
    adiw  r26, 1            /* X = vi, out at vi + 4 */
    movw  r22, r26
    mov   r20, r17
1:  RD(r0)
    st    X+, r0
    dec   r17
    brne  1b
    movw  r16, r22
    subi  r16, 0xFC         /* + 4 */
    sbci  r17, 0xFF
    ldd   r24, Y+W_VERTS
    ldd   r25, Y+W_VERTS+1
    ldd   r30, Y+W_PK
    ldd   r31, Y+W_PK+1
    ldd   r18, Z+P_ROW
    ldd   r19, Z+P_ROW+1
    clr   r1
    call  r8k_zsum
    bst   r14, 2            /* T: n = 4 */
    movw  r14, r28          /* w */
    pop   r0                /* vi */
    pop   r0
    pop   r0
    pop   r0
    tst   r24
    brne  1f
    pop   r0
    pop   r0
    pop   r0
    pop   r0
    rjmp  zfail
1:  pop   r25               /* zs */
    pop   r26
    pop   r27
    pop   r24
    ldd   r16, Y+W_PK
    ldd   r17, Y+W_PK+1
    movw  r28, r16          /* Y = pk */
    rjmp  zkey
    .size r8k_fwpaint, .-r8k_fwpaint
