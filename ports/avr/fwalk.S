/* fwalk.S - r8k_fwalk (include/r8kern.h) for AVR with MUL (ATmega).
 *
 *   r8_u8 r8k_fwalk(r8_fwalk *w);
 *
 * r8_bucket_object's face loop (src/render.c): from face w->f - 1 down,
 * the next face to draw - its n checked, r8k_cull's test (facecull.S's
 * code, inline here) when w->normals is set, its vertices transformed where their x is -32767
 * (R8_VX_TODO: a call of r8k_vertex(st, o, verts + 3 i, vbase + i), r8_tf_vertex's
 * kernel, vertex.S or C), the rows of its
 * vertices' box tested against the frame - returns 1 with w->f, top,
 * bot set (painter's with w->paint: on at r8k_fwpaint, fwpaint.S, which
 * puts the face in its depth bucket); 2 for a face the caller takes (n not 3..4, r8k_cull -1, a
 * vertex x = -32768); 0 at the end.  Reference: src/kern.c, which
 * asserts the offsets of r8_fwalk used here.
 *
 * Registers (avr-gcc ABI): w in r25:r24, then Y.  The walk's state
 * stays in r2-r13 for the whole call: f r3:r2 (stored to w->f only on
 * the way out and before fwpaint.S), faces + 6 f r5:r4, normals - faces
 * r7:r6 (0: no cull, the loop at face_nc), the eye's low 16 bits +
 * 16368 (e', DIFFR) r9:r8, r11:r10, r13:r12.  The cull (r8k_cull's
 * test, sign flipped): Z = v then n, the differences 16 v - e r19:r18,
 * r21:r20, r23:r22, r16 = 7 for their range test, then the sum r27:r24
 * = n . (16 v - e) (DOT3, facemac.h; r17:r16 the normal, r15 zero):
 * a front face when it is negative.  The box (BOXLOOP 4 or 8, the
 * vertex size): Z = the face's vertex indices (flash), r0 = the low
 * byte of their end, X = the vertex, r25:r24 = base; x or y r23:r22;
 * the first vertex sets xmin r19:r18, xmax r17:r16, ymin r15:r14, ymax
 * r21:r20 (kept on the stack around r8k_vertex with Z and r0).  Saves
 * r2-r17, r28, r29; clears r1.  r8k_fwpaint (fwpaint.S) may use r14-r17
 * and must keep r2-r13: it goes on at r8k_fwalk_putk (Y = w, key
 * r23:r22, r1 = 0) or r8k_fwalk_ret1 (Y = w).  Per torus frame
 * (fw-1-0-4, 200 faces, 96 drawn): about 170 cycles a back face, 40 a
 * vertex (about 100 more for one to transform), 60 for the rows, 70 for
 * the bucket.
 */
#ifdef R8_NO_PROGMEM
#define RD(r) ld r, Z+
#define RD0(r) ld r, Z
#else
#define RD(r) lpm r, Z+
#define RD0(r) lpm r, Z
#endif

/* offsets in r8_fwalk */
#define W_BASE   0
#define W_FACES  2
#define W_NORM   4
#define W_VERTS  6
#define W_EYE    8
#define W_F     10
#define W_W     12
#define W_H     14
#define W_TOP   16
#define W_BOT   18
#define W_VSH   20
#define W_ST    21
#define W_O     23
#define W_HEADS 25
#define W_NEXT  27
#define W_SLOT  29
#define W_NPOLY 31
#define W_FBASE 33
#define W_BSH   35
#define W_FID8  36
#define W_VBASE 37
#define W_PAINT 41

#define ZERO r15

#include "facemac.h"   /* DOT3: r8k_cull's sum */
#include "saves.h"     /* SAVE18, RESTORE18 */

/* lo:hi (upper registers) = R8_FLOOR16(v + 7) =
 * ((v + 0x8007) mod 2^16 >> 4) - 2048 */
.macro FLOOR lo, hi
    subi  \lo, 0xF9
    sbci  \hi, 0x7F
    swap  \lo
    andi  \lo, 0x0F
    swap  \hi
    eor   \lo, \hi
    andi  \hi, 0x0F
    eor   \lo, \hi
    subi  \hi, 0x08
.endm

/* X = the vertex of the next index (Z+), base r25:r24, 8 bytes when
 * eight is 1, else 4; its x in r23:r22 */
.macro VADDR eight
    RD(r26)
    clr   r27
    lsl   r26
    rol   r27
    lsl   r26
    rol   r27
.if \eight
    lsl   r26
    rol   r27
.endif
    add   r26, r24
    adc   r27, r25
    ld    r22, X+
    ld    r23, X+
.endm

/* r8k_vertex(st, o, verts + 3 i, vbase + i) for the index before Z */
.macro TFV
    sbiw  r30, 1
    RD0(r22)                /* i */
    ldi   r23, 6
    mul   r22, r23
    ldd   r20, Y+W_VERTS    /* mv = verts + 3 i */
    ldd   r21, Y+W_VERTS+1
    add   r20, r0
    adc   r21, r1
    clr   r1
    ldd   r18, Y+W_VBASE    /* g = vbase + i */
    ldd   r19, Y+W_VBASE+1
    add   r18, r22
    adc   r19, r1
    ldd   r24, Y+W_ST
    ldd   r25, Y+W_ST+1
    ldd   r22, Y+W_O
    ldd   r23, Y+W_O+1
    call  r8k_vertex        /* (vertex.S; else transform.c: r8_tf_vertex) */
.endm

/* back to the index before Z, r25:r24 again */
.macro VAGAIN
    sbiw  r30, 1
    ldd   r24, Y+W_BASE
    ldd   r25, Y+W_BASE+1
.endm

/* the box of the face's vertices (base r25:r24, Z the indices, r0 their
 * end), vertices of 8 bytes when eight is 1, else 4; the labels end in
 * sfx */
.macro BOXLOOP sfx, eight
v0\sfx:                     /* the first vertex sets the box */
    VADDR \eight
    cpi   r23, 0x80
    breq  m0\sfx             /* x in [-32768, -32513] */
x0\sfx:
    movw  r18, r22          /* xmin */
    movw  r16, r22          /* xmax */
    ld    r22, X+
    ld    r23, X
    movw  r14, r22          /* ymin */
    movw  r20, r22          /* ymax */
    rjmp  vt\sfx
m0\sfx:
    cpi   r22, 2
    brsh  x0\sfx              /* an ordinary x */
    cpi   r22, 1
    breq  1f
    rjmp  other             /* -32768: the clipper's */
1:
    push  r0
    push  r30
    push  r31
    TFV
    pop   r31
    pop   r30
    pop   r0
    VAGAIN
    rjmp  v0\sfx
m\sfx:
    cpi   r22, 2
    brsh  xk\sfx               /* an ordinary x */
    cpi   r22, 1
    breq  1f
    rjmp  other             /* -32768: the clipper's */
1:
    /* -32767: r8k_vertex(st, o, verts + 3 i, vbase + i), the box kept on the stack, then this
     * vertex again */
    push  r0
    push  r18
    push  r19
    push  r20
    push  r21
    push  r30
    push  r31
    TFV
    pop   r31
    pop   r30
    pop   r21
    pop   r20
    pop   r19
    pop   r18
    pop   r0
    VAGAIN
vt1\sfx:
    VADDR \eight
    cpi   r23, 0x80
    breq  m\sfx              /* x in [-32768, -32513] */
xk\sfx:
    cp    r22, r18
    cpc   r23, r19
    brge  3f
    movw  r18, r22
3:  cp    r16, r22
    cpc   r17, r23
    brge  4f
    movw  r16, r22
4:  ld    r22, X+
    ld    r23, X
    cp    r22, r14
    cpc   r23, r15
    brge  5f
    movw  r14, r22
5:  cp    r20, r22
    cpc   r21, r23
    brge  vt\sfx
    movw  r20, r22
vt\sfx:
    cp    r30, r0
    brne  vt1\sfx
.endm

/* dl:dh = 16 v - e (v read through Z+; el:eh = e' = the eye component's
 * low 16 bits + 16368, r16 = 7): 16 (v + 1023) - e'; v out of range: to
 * `out` (r8k_cull's -1) */
.macro DIFFR dl, dh, el, eh, out
    RD(\dl)
    RD(\dh)
    subi  \dl, 0x01
    sbci  \dh, 0xFC        /* r = v + 1023 */
    cpi   \dl, 0xFF
    cpc   \dh, r16         /* C iff r <= 2046 (unsigned) */
    brcc  \out
    swap  \dh              /* r << 4 (fits: r < 2048) */
    swap  \dl
    andi  \dh, 0xF0
    eor   \dh, \dl
    andi  \dl, 0xF0
    eor   \dh, \dl
    sub   \dl, \el        /* 16 r - e' = 16 v - e (exact: |16 v - e| < 2^15) */
    sbc   \dh, \eh
.endm

    .section .text.r8k_fwalk,"ax",@progbits
    .global r8k_fwalk
    .type   r8k_fwalk, @function
r8k_fwalk:
    SAVE18
    movw  r28, r24          /* Y = w */
    ldd   r2, Y+W_F         /* f */
    ldd   r3, Y+W_F+1
    movw  r24, r2           /* r17:r16 = 6 f */
    lsl   r24
    rol   r25
    movw  r16, r24
    lsl   r24
    rol   r25
    add   r16, r24
    adc   r17, r25
    ldd   r4, Y+W_FACES     /* faces + 6 f */
    ldd   r5, Y+W_FACES+1
    add   r4, r16
    adc   r5, r17
    ldd   r6, Y+W_NORM      /* normals - faces, or 0: no cull */
    ldd   r7, Y+W_NORM+1
    cp    r6, r1
    cpc   r7, r1
    brne  1f
    rjmp  face_nc
1:  ldd   r24, Y+W_FACES
    ldd   r25, Y+W_FACES+1
    sub   r6, r24
    sbc   r7, r25
    ldd   r26, Y+W_EYE      /* the eye's low 16 bits */
    ldd   r27, Y+W_EYE+1
    ld    r8, X+
    ld    r9, X
    adiw  r26, 3
    ld    r10, X+
    ld    r11, X
    adiw  r26, 3
    ld    r12, X+
    ld    r13, X
    ldi   r24, 0xF0         /* e' = e + 16368 (DIFFR) */
    ldi   r25, 0x3F
    add   r8, r24
    adc   r9, r25
    add   r10, r24
    adc   r11, r25
    add   r12, r24
    adc   r13, r25
    rjmp  face
none:
    std   Y+W_F, r2         /* (0) */
    std   Y+W_F+1, r3
    ldi   r24, 0
    rjmp  out
other:
    std   Y+W_F, r2
    std   Y+W_F+1, r3
    ldi   r24, 2            /* R8_FW_OTHER */
    rjmp  out
face:
    movw  r24, r2
    sbiw  r24, 1
    brcs  none              /* no face left (f = 0) */
    movw  r2, r24
    movw  r30, r4           /* Z = faces + 6 f */
    sbiw  r30, 6
    movw  r4, r30
    RD(r20)                 /* n */
    subi  r20, 3
    cpi   r20, 2
    brsh  other             /* n not 3 or 4 */
    /* r8k_cull (facecull.S) inline with the eye in registers: the
     * differences 16 v - eye (-1 when a component of v lies outside
     * [-1023, 1023]), their dot product with n negative for a front
     * face */
    adiw  r30, 1            /* Z = the vertex indices */
    RD0(r22)                /* v = verts + 3 v[0] */
    ldi   r23, 6
    mul   r22, r23
    ldd   r30, Y+W_VERTS
    ldd   r31, Y+W_VERTS+1
    add   r30, r0
    adc   r31, r1
    ldi   r16, 7
    DIFFR r18, r19, r8, r9, other
    DIFFR r20, r21, r10, r11, other
    DIFFR r22, r23, r12, r13, other
    movw  r30, r4           /* Z = n = normals + 6 f */
    add   r30, r6
    adc   r31, r7
    DOT3                    /* r27:r24 = n . (16 v - eye) (facemac.h) */
    sbrs  r27, 7
    rjmp  face              /* >= 0: a back face */
    movw  r30, r4           /* Z = the vertex indices, r20 = n */
    RD(r20)
    adiw  r30, 1
    rjmp  box
face_nc:                    /* no cull */
    movw  r24, r2
    sbiw  r24, 1
    brcc  1f
    rjmp  none
1:
    movw  r2, r24
    movw  r30, r4
    sbiw  r30, 6
    movw  r4, r30
    RD(r20)                 /* n */
    mov   r21, r20
    subi  r21, 3
    cpi   r21, 2
    brsh  1f
    adiw  r30, 1            /* Z = the vertex indices */
    rjmp  box
1:  rjmp  other
box:
    /* Z = the vertex indices, r20 = n */
    mov   r0, r30
    add   r0, r20           /* the end: lo(Z + n) */
    ldd   r24, Y+W_BASE
    ldd   r25, Y+W_BASE+1
    ldd   r18, Y+W_VSH
    sbrc  r18, 1
    rjmp  box8
    BOXLOOP 4, 0
rows:
    /* the rows: bot r21:r20, top r23:r22 */
    clr   r1
    FLOOR r20, r21
    movw  r22, r14
    FLOOR r22, r23
    cp    r22, r20
    cpc   r23, r21
    brge  next              /* top >= bot */
    cp    r1, r20
    cpc   r1, r21
    brge  next              /* bot <= 0 */
    ldd   r24, Y+W_H
    ldd   r25, Y+W_H+1
    cp    r22, r24
    cpc   r23, r25
    brge  next              /* top >= h */
    subi  r16, 0xF9         /* floor(xmax) > 0: (xmax + 0x8007) mod 2^16 */
    sbci  r17, 0x7F         /* >= 0x8010 (unsigned), see FLOOR */
    cpi   r16, 0x10
    ldi   r24, 0x80
    cpc   r17, r24
    brlo  next              /* floor(xmax) <= 0 */
    FLOOR r18, r19
    ldd   r24, Y+W_W
    ldd   r25, Y+W_W+1
    cp    r18, r24
    cpc   r19, r25
    brge  next              /* floor(xmin) >= w */
    ldd   r24, Y+W_BSH
    sbrs  r24, 7
    rjmp  put               /* bsh >= 0: into its bucket here */
    std   Y+W_F, r2
    std   Y+W_F+1, r3
    std   Y+W_TOP, r22
    std   Y+W_TOP+1, r23
    std   Y+W_BOT, r20
    std   Y+W_BOT+1, r21
    ldd   r30, Y+W_PAINT
    ldd   r31, Y+W_PAINT+1
    sbiw  r30, 0
    breq  r8k_fwalk_ret1
    ijmp                    /* painter's: r8k_fwpaint (fwpaint.S) */
next:                       /* (r1 = 0) */
    cp    r6, r1            /* normals - faces: 0 without the cull */
    cpc   r7, r1
    breq  1f
    rjmp  face
1:  rjmp  face_nc
    .global r8k_fwalk_ret1
r8k_fwalk_ret1:
    ldi   r24, 1
out:
    clr   r1
    ldi   r25, 0
    RESTORE18
    ret
box8:
    BOXLOOP 8, 1
    rjmp  rows
put:
    /* key = top >> bsh (0 for top < 0) in r23:r22, id = fbase + f in
     * r19:r18 (r1 = 0) */
    tst   r23
    brne  6f                /* top < 0 or >= 256 */
    tst   r24
    breq  3f
2:  lsr   r22               /* 8 bits */
    dec   r24
    brne  2b
3:  movw  r18, r2
    rjmp  putf
6:  brpl  7f
    clr   r22               /* top < 0: 0 */
    clr   r23
    rjmp  3b
7:  tst   r24
    breq  3b
8:  lsr   r23               /* 16 bits */
    ror   r22
    dec   r24
    brne  8b
    rjmp  3b
    .global r8k_fwalk_putk
r8k_fwalk_putk:             /* (fwpaint.S: key r23:r22, r1 = 0, r2-r13 as they were) */
    ldd   r18, Y+W_F
    ldd   r19, Y+W_F+1
putf:
    ldd   r20, Y+W_FBASE
    ldd   r21, Y+W_FBASE+1
    add   r18, r20
    adc   r19, r21
    ldd   r30, Y+W_HEADS
    ldd   r31, Y+W_HEADS+1
    ldd   r26, Y+W_NEXT
    ldd   r27, Y+W_NEXT+1
    ldd   r24, Y+W_FID8
    tst   r24
    breq  4f
    clr   r19               /* 8-bit ids */
    add   r30, r22          /* next[id] = heads[key], heads[key] = id */
    adc   r31, r23
    ld    r20, Z
    st    Z, r18
    add   r26, r18
    adc   r27, r1
    st    X, r20
    rjmp  5f
4:  lsl   r22               /* 16-bit ids */
    rol   r23
    add   r30, r22
    adc   r31, r23
    ld    r20, Z
    ldd   r21, Z+1
    st    Z, r18
    std   Z+1, r19
    movw  r24, r18
    lsl   r24
    rol   r25
    add   r26, r24
    adc   r27, r25
    st    X+, r20
    st    X, r21
5:  ldd   r30, Y+W_SLOT     /* slot[id] = R8_NO_SLOT */
    ldd   r31, Y+W_SLOT+1
    mov   r24, r30
    or    r24, r31
    breq  6f
    add   r30, r18
    adc   r31, r19
    ldi   r24, 0xFF
    st    Z, r24
6:  ldd   r24, Y+W_NPOLY
    ldd   r25, Y+W_NPOLY+1
    adiw  r24, 1
    std   Y+W_NPOLY, r24
    std   Y+W_NPOLY+1, r25
    rjmp  next
    .size r8k_fwalk, .-r8k_fwalk
