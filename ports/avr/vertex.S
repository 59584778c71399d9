/* vertex.S - r8k_vertex (include/r8kern.h) for AVR with MUL (ATmega).
 *
 *   void r8k_vertex(r8_state *st, const r8_objx *o, const r8_s16 *mv, r8_u16 g);
 *
 * r8_tf_vertex (src/transform.c) without Gouraud, r8k_fwalk's
 * per-vertex call (fwalk.S): r8k_xform, r8_tf_camera's near test and
 * r8k_project in one, the camera point kept in registers, without the
 * three calls, their register saves and the C between them; for vsh 2
 * (8-byte screen vertices) out[2] then comes from r8k_vdepth(st, m, e)
 * (transform.c: the depth when st->attrs has R8_ATTR_D, else 0), m, e
 * the reciprocal project.S gives.  It takes the common case:
 *
 *   - every model component a signed byte (xform.S's 16 x 8 rows);
 *   - camera x and y within 16 bits, z within [1, 65535] (after the
 *     near test: z < st->zn16 marks the vertex R8_VX_CLIP);
 *
 * and hands any other input, and Gouraud (vsh 2 with R8_ATTR_S), to
 * r8_tf_vertex unchanged (which does the whole vertex again through the
 * general kernels).  Bit for bit: the rows are xform.S's (floor((S +
 * 512) / 1024) + t, S exact in 32 bits), the projection project.S's for
 * 16-bit x, y (its steps 1 to 4).  Reference: r8_tf_vertex
 * (transform.c's r8k_vertex when R8_ASM_VERTEX is not defined);
 * tests/targets/test_avr_kern.c compares the two on random inputs.
 * transform.c asserts the offsets below.
 *
 * Registers (avr-gcc ABI): st r25:r24, o r23:r22, mv r21:r20, g r19:r18.
 * Y = st, Z = o (then the table), r15:r14 = mv then x, r13:r12 = g then
 * the vertex's screen entry, r17:r16 = x then the reciprocal and kk,
 * r11:r10 = y; T set for vsh 2 (then also r9:r8 = m, r21 = e, saved).
 * The rows: vertex bytes r18, r20, r22; matrix entry r21:r19; sum
 * r26:r23:r25:r24 (bytes 3..0), zero r27.  Saves r10..r17, r28, r29
 * (and r8, r9 for vsh 2); clears r1.
 */
#ifdef R8_NO_PROGMEM
#define RDV(r) ld r, Z+
#else
#define RDV(r) lpm r, Z+
#endif

/* r8_state, r8_objx, r8_proj offsets (avr-gcc; transform.c asserts) */
#define ST_CAM   2
#define ST_ATTRS 25
#define ST_VSH  26
#define ST_SV   37
#define ST_ZN16 83
#define O_T     18
#define P_CX     0
#define P_CY     2
#define P_GUARD 10
#define P_FN    12
#define P_FSH   14

/* one matrix row times the vertex, 16 x 8: x (r18, r20 or r22) times
 * the entry r21:r19, added to the sum (xform.S's FAST_ACC) */
.macro FACC x
    mulsu \x, r19           /* s x u, at byte 0; C = its sign */
    sbc   r23, r27          /* the sign extension: -2^16 */
    sbc   r26, r27
    add   r24, r0
    adc   r25, r1
    adc   r23, r27
    adc   r26, r27
    muls  r21, \x           /* s x s, at byte 1 */
    sbc   r26, r27
    add   r25, r0
    adc   r23, r1
    adc   r26, r27
.endm

/* row = floor((m[off/2 ..] . v + 512) / 1024) + t (at o + toff): the
 * 32 bits in r25 (byte 0), r23, r26, r24 (byte 3) */
.macro ROW off, toff
    ldd   r19, Z+\off
    ldd   r21, Z+\off+1
    mulsu r18, r19
    movw  r24, r0
    sbc   r23, r23
    mov   r26, r23
    muls  r21, r18
    sbc   r26, r27
    add   r25, r0
    adc   r23, r1
    adc   r26, r27
    ldd   r19, Z+\off+2
    ldd   r21, Z+\off+3
    FACC  r20
    ldd   r19, Z+\off+4
    ldd   r21, Z+\off+5
    FACC  r22
    asr   r26               /* >> 10; C = bit 9 */
    ror   r23
    ror   r25
    asr   r26
    ror   r23
    ror   r25
    clr   r24               /* the sign byte (clr, dec keep C) */
    sbrc  r26, 7
    dec   r24
    ldd   r0, Z+\toff
    adc   r25, r0
    ldd   r0, Z+\toff+1
    adc   r23, r0
    ldd   r0, Z+\toff+2
    adc   r26, r0
    ldd   r0, Z+\toff+3
    adc   r24, r0
.endm

/* to \fail unless the row (r26, r24 its high bytes) fits 16 bits */
.macro FIT16 fail
    mov   r0, r23
    lsl   r0
    sbc   r0, r0
    cp    r26, r0
    brne  1f
    cp    r24, r0
    breq  2f
1:  rjmp  \fail
2:
.endm

#include "projmac.h"   /* project.S's NORM, RECIP, KSETUP, COORD */

    .section .text.r8k_vertex,"ax",@progbits
    .global r8k_vertex
    .type   r8k_vertex, @function
r8k_vertex:
    movw  r30, r24
    ldd   r26, Z+ST_VSH
    clt                     /* T: vsh 2 */
    cpi   r26, 1
    breq  1f
    ldd   r26, Z+ST_ATTRS
    sbrc  r26, 1            /* R8_ATTR_S: Gouraud, the C */
    jmp   r8_tf_vertex
    set
1:  push  r10
    push  r11
    push  r12
    push  r13
    push  r14
    push  r15
    push  r16
    push  r17
    push  r28
    push  r29
    brtc  1f
    push  r8                /* vsh 2: m r9:r8, e r21 for the depth */
    push  r9
1:  movw  r28, r24          /* Y = st */
    movw  r12, r18          /* g */
    movw  r14, r20          /* mv */
    movw  r26, r22          /* o */
    movw  r30, r20          /* the vertex (flash): r19:r18, r21:r20, r23:r22 */
    RDV(r18)
    RDV(r19)
    RDV(r20)
    RDV(r21)
    RDV(r22)
    RDV(r23)
    movw  r30, r26          /* Z = o */
    sbrc  r18, 7            /* every high byte the sign of its low byte? */
    com   r19
    sbrc  r20, 7
    com   r21
    sbrc  r22, 7
    com   r23
    or    r19, r21
    or    r19, r23
    breq  2f
    rjmp  .Lfall
2:  clr   r27
    ROW   0, O_T            /* x */
    FIT16 .Lfall
    mov   r16, r25
    mov   r17, r23
    ROW   6, O_T+4          /* y */
    FIT16 .Lfall
    mov   r10, r25
    mov   r11, r23
    ROW   12, O_T+8         /* z */
    mov   r0, r26           /* z < 2^16 ... */
    or    r0, r24
    brne  1f
    mov   r0, r25           /* ... and not 0 */
    or    r0, r23
    brne  2f
1:  rjmp  .Lfall
2:
    lsl   r12               /* the entry: sv + 4 g (8 g: vsh 2) */
    rol   r13
    lsl   r12
    rol   r13
    brtc  1f
    lsl   r12
    rol   r13
1:
    ldd   r0, Y+ST_SV
    add   r12, r0
    ldd   r0, Y+ST_SV+1
    adc   r13, r0
    movw  r14, r16          /* x */
    adiw  r28, 32           /* z < zn16 (32 bits): the near plane */
    ldd   r0, Y+ST_ZN16-32
    cp    r25, r0
    ldd   r0, Y+ST_ZN16-31
    cpc   r23, r0
    ldd   r0, Y+ST_ZN16-30
    cpc   r26, r0
    ldd   r0, Y+ST_ZN16-29
    cpc   r24, r0
    brge  3f
    sbiw  r28, 32
    rjmp  .Lclip
3:  sbiw  r28, 32
    mov   r22, r25          /* zn = z normalised to [2^15, 2^16): r23:r22, s r26 */
    clr   r26
    tst   r23
    brne  4f
    mov   r23, r22          /* a byte at once */
    clr   r22
    ldi   r26, 8
4:
    NORM  7f
7:  RECIP
    brtc  1f
    movw  r8, r16           /* vsh 2: m, e kept */
    mov   r21, r26
1:
    /* kk (r17:r16), k = sh - 1 (r27), L (r26), lim (r31:r30) */
    KSETUP r20, ST_CAM+P_FN, ST_CAM+P_FSH, ST_CAM+P_GUARD, .Lshzero
    movw  r18, r14          /* qx (r15:r14) */
    COORD r20, .Lclip
    mov   r14, r23
    mov   r15, r24
    movw  r18, r10          /* qy (r24:r23) */
    rjmp  13f
.Lclip:                     /* x = R8_VX_CLIP (here: both COORDs reach) */
    movw  r30, r12
    clr   r1
    st    Z, r1
    ldi   r24, 0x80
    std   Z+1, r24
    rjmp  .Lret
13: COORD r20, .Lclip
.Lstore:                    /* out = cx + qx, cy + qy */
    ldd   r0, Y+ST_CAM+P_CX
    ldd   r1, Y+ST_CAM+P_CX+1
    add   r14, r0
    adc   r15, r1
    ldd   r0, Y+ST_CAM+P_CY
    ldd   r1, Y+ST_CAM+P_CY+1
    add   r23, r0
    adc   r24, r1
    movw  r30, r12
    st    Z, r14
    std   Z+1, r15
    std   Z+2, r23
    std   Z+3, r24
    brtc  .Lret1
    /* vsh 2: out[2] = r8k_vdepth(st, m, e) (transform.c: the depth when
     * st->attrs has R8_ATTR_D, else 0) */
    movw  r24, r28
    movw  r22, r8
    mov   r20, r21
    clr   r1
    call  r8k_vdepth
    movw  r30, r12
    std   Z+4, r24
    std   Z+5, r25
    pop   r9
    pop   r8
    rjmp  .Lret1
.Lret:
    brtc  .Lret1
    pop   r9
    pop   r8
.Lret1:
    clr   r1
    pop   r29
    pop   r28
    pop   r17
    pop   r16
    pop   r15
    pop   r14
    pop   r13
    pop   r12
    pop   r11
    pop   r10
    ret
.Lshzero:                   /* sh <= 0: only x = y = 0 projects, to cx, cy */
    mov   r0, r14
    or    r0, r15
    or    r0, r10
    or    r0, r11
    breq  1f
    rjmp  .Lclip
1:
    clr   r23
    clr   r24
    rjmp  .Lstore
.Lfall:                     /* r8_tf_vertex(st, o, mv, g) */
    movw  r24, r28
    movw  r22, r30
    movw  r20, r14
    movw  r18, r12
    clr   r1
    brtc  1f
    pop   r9
    pop   r8
1:  pop   r29
    pop   r28
    pop   r17
    pop   r16
    pop   r15
    pop   r14
    pop   r13
    pop   r12
    pop   r11
    pop   r10
    jmp   r8_tf_vertex
    .size r8k_vertex, .-r8k_vertex

/* r8k_vdepth for builds without depth or texture (transform.c defines
 * it otherwise): their screen vertices are 4 bytes, vsh 1, and this is
 * never called; its being weak keeps r8_tf_depth out of them */
    .section .text.r8k_vdepth,"ax",@progbits
    .weak   r8k_vdepth
    .type   r8k_vdepth, @function
r8k_vdepth:
    ldi   r24, 0
    ldi   r25, 0
    ret
    .size r8k_vdepth, .-r8k_vdepth

/* r8k_depth (include/r8kern.h, R8_ASM_DEPTH): r8_tf_depth's arithmetic,
 * bit for bit the C reference in src/kern.c:
 *
 *   r8_s16 r8k_depth(r8_u16 m, r8_u16 znm, r8_s16 sh, r8_u32 wf, r8_u32 gh);
 *
 * p = m znm (32 bits); w = 2^20 for sh <= 0, 0 for sh > 31, else p
 * shifted right arithmetically by sh (whole bytes, then bits), at most
 * 2^20; 0 when w <= wf; else bits 16..31 of (w - wf) gh + 2^15 (modulo
 * 2^32: w - wf <= 2^20 has three bytes, so nine MULs make the low four
 * bytes of the product).  Registers: m r25:r24, znm r23:r22, sh r21:r20,
 * wf r19:r16, gh r15:r12; p and w r27:r26:r31:r30; the product r25..r22;
 * zero r21.  Clears r1. */
    .section .text.r8k_depth,"ax",@progbits
    .global r8k_depth
    .type   r8k_depth, @function
r8k_depth:
    tst   r21
    brmi  .Ldnear           /* sh < 0 */
    breq  1f
.Ldzero0:                   /* sh > 31: w = 0 <= wf */
    ldi   r24, 0
    ldi   r25, 0
    ret
1:  tst   r20
    breq  .Ldnear           /* sh = 0 */
    cpi   r20, 32
    brsh  .Ldzero0
    mul   r24, r22          /* p = m znm */
    movw  r30, r0
    mul   r25, r23
    movw  r26, r0
    mul   r24, r23
    add   r31, r0
    adc   r26, r1
    adc   r27, r21
    mul   r25, r22
    add   r31, r0
    adc   r26, r1
    adc   r27, r21
    sbrs  r20, 4            /* >> 16 */
    rjmp  1f
    movw  r30, r26
    lsl   r27
    sbc   r27, r27
    mov   r26, r27
1:  sbrs  r20, 3            /* >> 8 */
    rjmp  2f
    mov   r30, r31
    mov   r31, r26
    mov   r26, r27
    lsl   r27
    sbc   r27, r27
2:  andi  r20, 7            /* then bit by bit */
    breq  4f
3:  asr   r27
    ror   r26
    ror   r31
    ror   r30
    dec   r20
    brne  3b
4:  cpi   r30, 0x01         /* w > 2^20 (unsigned): 2^20 */
    cpc   r31, r21
    ldi   r20, 0x10
    cpc   r26, r20
    cpc   r27, r21
    brlo  .Ldw
.Ldnear:
    clr   r21
    clr   r30               /* w = 2^20 */
    clr   r31
    ldi   r26, 0x10
    clr   r27
.Ldw:
    cp    r16, r30          /* w <= wf: 0 */
    cpc   r17, r31
    cpc   r18, r26
    cpc   r19, r27
    brsh  .Ldzero
    sub   r30, r16          /* dw = w - wf: r26:r31:r30 */
    sbc   r31, r17
    sbc   r26, r18
    mul   r30, r12          /* dw gh, the low four bytes */
    movw  r22, r0
    mul   r30, r14
    movw  r24, r0
    mul   r30, r13
    add   r23, r0
    adc   r24, r1
    adc   r25, r21
    mul   r31, r12
    add   r23, r0
    adc   r24, r1
    adc   r25, r21
    mul   r31, r13
    add   r24, r0
    adc   r25, r1
    mul   r26, r12
    add   r24, r0
    adc   r25, r1
    mul   r30, r15
    add   r25, r0
    mul   r31, r14
    add   r25, r0
    mul   r26, r13
    add   r25, r0
    ldi   r20, 0x80         /* + 2^15, bits 16..31 */
    add   r23, r20
    adc   r24, r21
    adc   r25, r21
    clr   r1
    ret
.Ldzero:
    clr   r1
    ldi   r24, 0
    ldi   r25, 0
    ret
    .size r8k_depth, .-r8k_depth
