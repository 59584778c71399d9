/* fwpaint.S - r8k_fwpaint (include/r8kern.h): r8k_fwalk's painter's part
 * (ports/avr/fwalk.S jumps here through w->paint, set by the C only in
 * builds with painter's: without them this object, r8k_zsum and
 * __mulsi3 stay out of the firmware).
 *
 * Entered by ijmp from r8k_fwalk with a face that passed the frame test
 * (bsh < 0, w->top and w->bot set): Y = w, r1 = 0, r14-r17 saved by
 * r8k_fwalk.  Copies the face's vertex indices to pk->vi, calls
 * r8k_zsum (0: back to r8k_fwalk_ret1, the caller buckets the face),
 * computes the depth key from pk (src/kern.c's reference; render.c's
 * depth_key), stores ftop[id] when pk->ftop is set, and goes on at
 * r8k_fwalk_putk with the key in r23:r22 (the links, slot, npoly, the
 * next face).  Y = pk meanwhile, w in r14:r15; r16, r17 (n after the
 * call), r20 (fbsh) scratch.
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
#define P_VI    29
#define P_ZS    33

    .section .text.r8k_fwpaint,"ax",@progbits
    .global r8k_fwpaint
    .type   r8k_fwpaint, @function
r8k_fwpaint:
    movw  r14, r28          /* w */
    ldd   r24, Y+W_F
    ldd   r25, Y+W_F+1
    lsl   r24               /* 6 f */
    rol   r25
    movw  r18, r24
    lsl   r24
    rol   r25
    add   r24, r18
    adc   r25, r19
    ldd   r30, Y+W_FACES
    ldd   r31, Y+W_FACES+1
    add   r30, r24
    adc   r31, r25
    RD(r20)                 /* n */
    adiw  r30, 1            /* Z = the vertex indices */
    ldd   r24, Y+W_VERTS
    ldd   r25, Y+W_VERTS+1
    ldd   r26, Y+W_PK
    ldd   r27, Y+W_PK+1
    movw  r28, r26          /* Y = pk */
    adiw  r26, P_VI
    mov   r21, r20
1:  RD(r0)                  /* pk->vi */
    st    X+, r0
    dec   r21
    brne  1b
    movw  r22, r28
    subi  r22, lo8(-(P_VI))
    sbci  r23, hi8(-(P_VI))
    ldd   r18, Y+P_ROW
    ldd   r19, Y+P_ROW+1
    movw  r16, r28
    subi  r16, lo8(-(P_ZS))
    sbci  r17, hi8(-(P_ZS))
    push  r20
    call  r8k_zsum
    pop   r17               /* n */
    or    r24, r25
    brne  1f
    movw  r28, r14
    jmp   r8k_fwalk_ret1    /* a sum past 16 bits: the caller's */
1:  movw  r26, r28          /* X = the constants for n */
    cpi   r17, 4
    brne  1f
    adiw  r26, 12
1:  ldd   r22, Y+P_ZS       /* z = zs + zc */
    ldd   r23, Y+P_ZS+1
    ldd   r24, Y+P_ZS+2
    ldd   r25, Y+P_ZS+3
    ld    r0, X+
    add   r22, r0
    ld    r0, X+
    adc   r23, r0
    ld    r0, X+
    adc   r24, r0
    ld    r0, X+
    adc   r25, r0
    sbrs  r25, 7
    rjmp  2f
    clr   r22               /* < 0: 0 */
    clr   r23
    movw  r24, r22
2:  ld    r16, X+           /* z >= zr: key 0 */
    ld    r18, X+
    ld    r19, X+
    ld    r21, X+
    cp    r22, r16
    cpc   r23, r18
    cpc   r24, r19
    cpc   r25, r21
    brge  key0
    ld    r18, X+           /* kmul */
    ld    r19, X+
    ld    r20, X+
    ld    r21, X
    clr   r1
    call  __mulsi3          /* r25:r22 = z kmul (mod 2^32) */
    clr   r1
    cpi   r17, 4
    brne  3f
    lsr   r25
    ror   r24
    lsr   r25
    ror   r24
3:  tst   r25
    brne  4f
    cpi   r24, 64
    brlo  5f
4:  ldi   r24, 63
5:  ldi   r22, 63
    sub   r22, r24
    rjmp  6f
key0:
    clr   r22
6:  clr   r23
    /* ftop[id] = min(255, top >> fbsh; 0 for top < 0) */
    ldd   r30, Y+P_FTOP
    ldd   r31, Y+P_FTOP+1
    mov   r24, r30
    or    r24, r31
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
    jmp   r8k_fwalk_putk
    .size r8k_fwpaint, .-r8k_fwpaint
