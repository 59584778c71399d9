/* trap.S - r8k_trap (include/r8kern.h) for AVR.
 *
 *   void r8k_trap(r8_trapfill *t, r8_interp *l, r8_interp *r, r8_u16 rows);
 *
 * Same memory results as the C reference in src/kern.c: per row, the
 * span [max(l->val, 0), min(r->val, w)) of the page row under mask m gets
 * pattern pat[k] (low nibble: column x takes bit 3 - (x & 3); nibble F
 * sets, 0 clears), then both column DDAs step (R8_INTERP_STEP, with the
 * same 16-bit wrap of err + r), m moves up a bit (page += w past bit 7)
 * and k to the next phase.  l->val, l->err, r->val, r->err, t->page,
 * t->m and t->k are written back (t->page as soon as it moves).
 *
 * Calls of 2..255 rows keep the DDA state in registers for the whole
 * call; a call of one row (the commonest: about 40% of the calls from the
 * renderer) leaves it in memory and skips that set-up; 256 rows or more
 * become calls of 255.  A DDA step:
 *     err += r; err -= den (C = borrow: err < den); on borrow err += den
 *     (C stays 1); val -= ~q + C, i.e. val += q + (no borrow).
 * A span: X = page + xl, Z = page + xr, and a loop of 4 columns entered
 * at column (xl - xr) & 3 (Duff's device), so it ends with X == Z after a
 * whole pass.  Dithered spans test bit 7 - j of the nibble repeated in a
 * byte and shifted left by xr & 3, so loop column j has the bit of
 * column xr + j (mod 4).  Per column: 7 cycles, and 4 per pass of 4
 * columns.  Set (nibble F) and clear (0) spans take the same loop (the
 * nibble repeated is 0xFF or 0x00): two loops fewer in flash, for 2
 * cycles a column.
 *
 * Page groups (issue 10): the rows of a call that share a page byte
 * (from bit m to bit 7, or to the last row) form a group; when it has
 * GMIN rows or more, m is one bit, both edges are tame and the first
 * span is IMIN columns wide, the columns every row of the group covers
 * get one read-modify-write per byte for all the group's bits (a plain
 * store on a whole page byte), and each row then fills only its ragged
 * ends (grp below).  The group's interior [A, B), both edges' state on
 * its last row and which ends are the same on every row sit in
 * r8k_trap_ab (14 bytes of .bss) while its rows run: with both ends the
 * same no row but the last has a ragged piece, and the call goes
 * straight to that row; otherwise every row tests both ends (growr; an
 * end that is the same on every row gives an empty piece).
 *
 * Struct offsets (avr-gcc, no padding): r8_interp {val 0, q 2, err 4,
 * r 6, den 8}; r8_trapfill {page 0, m 2, k 3, pat 4..7, w 8}.
 */

/* the page groups' thresholds (grp2 below) */
#ifndef GMIN
#define GMIN 7
#endif
#ifndef IMIN
#define IMIN 16
#endif

#define T0   r0     /* scratch: column byte, loop entry */
#define NM   r1     /* ~m (cleared before returning) */
#define LVL  r2     /* left edge: val, err, ~q, r, den */
#define LVH  r3
#define LEL  r4
#define LEH  r5
#define LNQL r6
#define LNQH r7
#define LRL  r8
#define LRH  r9
#define LDL  r10
#define LDH  r11
#define RVL  r12    /* right edge */
#define RVH  r13
#define REL  r14
#define REH  r15
#define RNQL r16
#define RNQH r17
#define Q    r18    /* the row's pattern */
#define K    r19    /* dither phase */
#define RRL  r20
#define RRH  r21
#define RDL  r22
#define RDH  r23
#define ROWS r24    /* rows left (2..255 at the start) */
#define M    r25    /* the row's bit(s) */
/* X (r27:r26) = column pointer, Y (r29:r28) = t, Z (r31:r30) = span end */

#include "saves.h"   /* SAVE18, RESTORE18 */

/* X = page + xl, Z = page + xr (from X = xl, Z = xr); T0 = n = xr - xl
 * (low byte: the loop is entered at column (-n) & 3) */
.macro SETUP
    ldd   T0, Y+0
    ldd   NM, Y+1
    add   r26, T0
    adc   r27, NM           /* X = page + xl */
    add   r30, T0
    adc   r31, NM           /* Z = page + xr */
    mov   T0, r30
    sub   T0, r26           /* n (low byte) */
.endm

/* jump to column c[(-T0) & 3] of the loop */
.macro ENTER c0, c1, c2, c3
    sbrc  T0, 1
    rjmp  .+6               /* to n & 3 = 2, 3 */
    sbrc  T0, 0
    rjmp  \c3               /* n & 3 = 1 */
    rjmp  \c0               /* n & 3 = 0 */
    sbrc  T0, 0
    rjmp  \c1               /* n & 3 = 3 */
    rjmp  \c2               /* n & 3 = 2 */
.endm

/* one column: set, clear, dither (bit b of Q) */
.macro CSET
    ld    T0, X
    or    T0, M
    st    X+, T0
.endm
.macro CCLR
    ld    T0, X
    and   T0, NM
    st    X+, T0
.endm
.macro CDIT b
    ld    T0, X
    and   T0, NM
    sbrc  Q, \b
    or    T0, M
    st    X+, T0
.endm

/* one DDA step: val, err, ~q, r, den registers (low bytes) */
.macro STEP vl, vh, el, eh, nql, nqh, rl, rh, dl, dh
    add   \el, \rl
    adc   \eh, \rh
    sub   \el, \dl
    sbc   \eh, \dh
    brcc  .+4
    add   \el, \dl
    adc   \eh, \dh
    sbc   \vl, \nql
    sbc   \vh, \nqh
.endm

/* one DDA step of the r8_interp at Z, in memory (r24-r27 scratch) */
.macro MSTEP
    ldd   r24, Z+4          /* err += r */
    ldd   r25, Z+5
    ldd   r26, Z+6
    ldd   r27, Z+7
    add   r24, r26
    adc   r25, r27
    ldd   r26, Z+8          /* err -= den; on borrow back (C = 1) */
    ldd   r27, Z+9
    sub   r24, r26
    sbc   r25, r27
    brcc  .+4
    add   r24, r26
    adc   r25, r27
    std   Z+4, r24
    std   Z+5, r25
    ld    r24, Z            /* val += q + !C */
    ldd   r25, Z+1
    ldd   r26, Z+2
    ldd   r27, Z+3
    brcs  .+2
    adiw  r24, 1
    add   r24, r26
    adc   r25, r27
    st    Z, r24
    std   Z+1, r25
.endm

    .section .text.r8k_trap,"ax",@progbits
    .global r8k_trap
    .type   r8k_trap, @function
r8k_trap:
    tst   r19
    brne  4f                /* 256 rows or more */
    cpi   r18, 2
    brsh  2f
    tst   r18
    breq  3f                /* no rows: nothing changes */
    rjmp  one               /* one row: the state stays in memory */
3:  ret
4:  rjmp  big               /* in runs of 255 */
2:  push  r2
    push  r3
    push  r4
    push  r5
    push  r6
    push  r7
    push  r8
    push  r9
    push  r10
    push  r11
    push  r12
    push  r13
    push  r14
    push  r15
    push  r16
    push  r17
    push  r28
    push  r29
    push  r22               /* l, r: for the write-back */
    push  r23
    push  r20
    push  r21
    movw  r28, r24          /* Y = t */
    mov   ROWS, r18
    movw  r30, r22
    ld    LVL, Z+
    ld    LVH, Z+
    ld    LNQL, Z+
    ld    LNQH, Z+
    ld    LEL, Z+
    ld    LEH, Z+
    ld    LRL, Z+
    ld    LRH, Z+
    ld    LDL, Z+
    ld    LDH, Z
    com   LNQL
    com   LNQH
    movw  r30, r20
    ld    RVL, Z+
    ld    RVH, Z+
    ld    RNQL, Z+
    ld    RNQH, Z+
    ld    REL, Z+
    ld    REH, Z+
    ld    RRL, Z+
    ld    RRH, Z+
    ld    RDL, Z+
    ld    RDH, Z
    com   RNQL
    com   RNQH
    ldd   M, Y+2
    ldd   K, Y+3
    call  grp               /* the rows (the body below returns at fin) */
    pop   r31               /* r */
    pop   r30
    std   Z+0, RVL
    std   Z+1, RVH
    std   Z+4, REL
    std   Z+5, REH
    pop   r31               /* l */
    pop   r30
    std   Z+0, LVL
    std   Z+1, LVH
    std   Z+4, LEL
    std   Z+5, LEH
    RESTORE18
    clr   r1
    ret
/* rows >= 256 (never from the renderer: a band has 8 rows): calls of 255
 * rows and one of the rest; the state is all in memory between calls */
big:
    push  r12
    push  r13
    push  r14
    push  r15
    push  r16
    push  r17
    push  r28
    push  r29
    movw  r16, r18          /* rows */
    movw  r28, r24          /* t */
    movw  r14, r22          /* l */
    movw  r12, r20          /* r */
7:  movw  r24, r28
    movw  r22, r14
    movw  r20, r12
    ldi   r18, 255
    ldi   r19, 0
    rcall r8k_trap
    subi  r16, 255
    sbci  r17, 0
    tst   r17
    brne  7b                /* still 256 or more */
    movw  r24, r28
    movw  r22, r14
    movw  r20, r12
    movw  r18, r16
    rcall r8k_trap
    pop   r29
    pop   r28
    pop   r17
    pop   r16
    pop   r15
    pop   r14
    pop   r13
    pop   r12
    ret

/* rows == 1 (the commonest call): no state in registers but what the
 * span needs; both DDAs step in memory. */
one:
    push  r28
    push  r29
    movw  r28, r24          /* Y = t */
    movw  r30, r22          /* X = max(l->val, 0) */
    ld    r26, Z
    ldd   r27, Z+1
    sbrc  r27, 7
    rjmp  oneg
1:  movw  r30, r20          /* Z = min(r->val, w) */
    ld    r24, Z
    ldd   r25, Z+1
    ldd   r30, Y+8
    ldd   r31, Y+9
    cp    r24, r30
    cpc   r25, r31
    brge  2f
    movw  r30, r24
2:  cp    r26, r30
    cpc   r27, r31
    ldd   M, Y+2            /* (flags kept) m and k: the span's and */
    ldd   K, Y+3            /* the step's */
    brge  ostep
    set                     /* T set: the span returns */
    call  span
ostep:
    inc   K                 /* k = (k + 1) & 3 */
    andi  K, 3
    std   Y+3, K
    lsl   M                 /* m <<= 1; past bit 7: m = 1, page += w */
    brne  3f
    inc   M
    ldd   r26, Y+0
    ldd   r27, Y+1
    ldd   r18, Y+8
    ldd   r19, Y+9
    add   r26, r18
    adc   r27, r19
    std   Y+0, r26
    std   Y+1, r27
3:  std   Y+2, M
    movw  r30, r22          /* l */
    call  mstz
    movw  r30, r20          /* r */
    call  mstz
    pop   r29
    pop   r28
    clr   r1
    ret
oneg:
    clr   r26
    clr   r27
    rjmp  1b

    .size r8k_trap, .-r8k_trap

/* The rows' body, shared by r8k_trap (above) and r8k_scanfill (below),
 * both of which call it at grp with the DDA state in registers; it
 * returns at fin.  Its own section with r8k_scanband and r8k_scanfill,
 * so a firmware that only calls r8k_scanband (the cube's) links neither
 * r8k_trap's entry nor its one-row and 256-row paths. */
    .section .text.r8k_trapbody,"ax",@progbits
/* a call's first page, or a new page (from wrap): a group (grp2) when
 * GMIN rows or more are left, else (T clear) the rows as they are */
grp:
    clt
    cpi   ROWS, GMIN
    brlo  row
    rjmp  grp2

row:
    ldd   r30, Y+8          /* Z = min(r->val, w) */
    ldd   r31, Y+9
    cp    RVL, r30
    cpc   RVH, r31
    brge  1f
    movw  r30, RVL
1:  movw  r26, LVL          /* X = max(l->val, 0) */
    sbrc  LVH, 7
    rjmp  lneg
2:  cp    r26, r30
    cpc   r27, r31
    brlt  span              /* (T clear: back to step) */
step:
    STEP  LVL, LVH, LEL, LEH, LNQL, LNQH, LRL, LRH, LDL, LDH
    STEP  RVL, RVH, REL, REH, RNQL, RNQH, RRL, RRH, RDL, RDH
    inc   K                 /* (only bits 0, 1 count: masked at fin) */
    lsl   M
    breq  wrap
next:
    dec   ROWS
    brne  row
    rjmp  fin

lneg:
    clr   r26
    clr   r27
    rjmp  2b

wrap:                       /* m = 1, page += w */
    inc   M
    ldd   T0, Y+0
    ldd   NM, Y+8
    add   T0, NM
    std   Y+0, T0
    ldd   T0, Y+1
    ldd   NM, Y+9
    adc   T0, NM
    std   Y+1, T0
    dec   ROWS
    brne  grp               /* the next page: a new group */
    rjmp  fin

span:                       /* X = xl < Z = xr */
    sbrc  K, 1              /* Q = pat[k] */
    rjmp  3f
    ldd   Q, Y+4
    sbrc  K, 0
    ldd   Q, Y+5
    rjmp  4f
3:  ldd   Q, Y+6
    sbrc  K, 0
    ldd   Q, Y+7
4:  andi  Q, 0x0F          /* the nibble (0: clear, F: set, as the rest) */
    mov   NM, Q             /* dither: nibble in both halves, */
    swap  NM
    or    Q, NM
    sbrc  r30, 0            /* shifted left by xr & 3 */
    lsl   Q
    sbrc  r30, 1
    lsl   Q
    sbrc  r30, 1
    lsl   Q
    SETUP
    mov   NM, M
    com   NM
    ENTER d0, d1, d2, d3
d0: CDIT  7
d1: CDIT  6
d2: CDIT  5
d3: CDIT  4
    cp    r26, r30
    cpc   r27, r31
    brne  d0
    brts  1f
    rjmp  step
1:  ret

/* A group's last row (grp): the closed form needs den < 0x2000, err <
 * den and r < den (then err + n r < 0x10000 and no step wraps);
 * otherwise no group (gbail). */
.macro GUARD el, eh, rl, rh, dl, dh
    mov   r24, \dh
    cpi   r24, 0x20
    brsh  76f
    cp    \el, \dl
    cpc   \eh, \dh
    brsh  76f
    cp    \rl, \dl
    cpc   \rh, \dh
    brlo  77f
76: rjmp  gbail
77:
.endm

/* The row n = K of a group in closed form: val (in vl:vh) + n q +
 * floor(x / den) and r25:r24 = x mod den (the err of that row), x = err +
 * n r; the quotient 0..n <= 7 in three restoring steps (q in -128..127,
 * from ~q in nql:nqh).  r1:r0 scratch. */
.macro LAST vl, vh, el, eh, nql, nqh, rl, rh, dl, dh
    mul   \rl, K
    movw  r24, r0
    mul   \rh, K
    add   r25, r0
    add   r24, \el
    adc   r25, \eh          /* x = err + n r */
    mov   r1, \nql
    sbrs  \nqh, 7
    rjmp  70f
    com   r1                /* q in 0..127 */
    mul   r1, K
    add   \vl, r0
    adc   \vh, r1
    rjmp  71f
70: inc   r1                /* -q in 1..128 */
    mul   r1, K
    sub   \vl, r0
    sbc   \vh, r1
71: movw  r0, \dl           /* 4 den */
    lsl   r0
    rol   r1
    lsl   r0
    rol   r1
    cp    r24, r0
    cpc   r25, r1
    brlo  72f
    sub   r24, r0
    sbc   r25, r1
    adiw  \vl, 4
72: lsr   r1
    ror   r0
    cp    r24, r0
    cpc   r25, r1
    brlo  73f
    sub   r24, r0
    sbc   r25, r1
    adiw  \vl, 2
73: cp    r24, \dl
    cpc   r25, \dh
    brlo  74f
    sub   r24, \dl
    sbc   r25, \dh
    adiw  \vl, 1
74:
.endm

/* A page group: the rows from bit M of this page byte to bit 7 (or to
 * the last row), g of them.  When g >= GMIN, M is one bit, both edges
 * are tame (|val| < 16384, -128 <= q <= 127: no 16-bit wrap in g rows)
 * and the first span has IMIN columns or more, the columns every row of
 * the group covers, [A, B) with B - A >= IMIN, get one read-modify-write
 * per byte for all the group's bits gm (a plain store when gm = 0xFF),
 * and the rows then fill only [xl, A) and [B, xr) (T set).  A DDA moves
 * by q or q + 1 a row, so it is monotone: A = max(first, last row's
 * left end, 0) and B = min(first, last row's right end, w), the last
 * row's in closed form (val + (g - 1) q + the carries of err, and err
 * as their remainder), for both edges.  Otherwise (T
 * clear) rows fill their whole spans as before.  Column x of the
 * interior gets bit b from pattern row (K0 + b) & 3 (K0 the phase of
 * bit 0; 8 rows are two dither periods), bit 3 - (x & 3).  GMIN and
 * IMIN: the cube / torus / teapot figures (docs/benchmarks.md); smaller
 * groups and narrower spans lose more in set-up than they save. */
/* a row of a group with an interior [A, B) (T set): its pieces [xl, A)
 * and [B, xr) (xl <= A < B <= xr) */
growr:
    lds   r30, r8k_trap_ab  /* left piece [max(l->val, 0), A): */
    lds   r31, r8k_trap_ab+1  /* none when l->val >= A */
    cp    LVL, r30
    cpc   LVH, r31
    brge  7f
    movw  r26, LVL
    sbrc  LVH, 7
    clr   r26
    sbrc  LVH, 7
    clr   r27
    cp    r26, r30
    cpc   r27, r31
    brge  7f
    rcall span
7:
    lds   r26, r8k_trap_ab+2  /* right piece [B, min(r->val, w)): */
    lds   r27, r8k_trap_ab+3  /* none when r->val <= B */
    cp    r26, RVL
    cpc   r27, RVH
    brge  8f
    ldd   r30, Y+8
    ldd   r31, Y+9
    cp    RVL, r30
    cpc   RVH, r31
    brge  1f
    movw  r30, RVL
1:  cp    r26, r30
    cpc   r27, r31
    brge  8f
    rcall span
8:  STEP  LVL, LVH, LEL, LEH, LNQL, LNQH, LRL, LRH, LDL, LDH
    STEP  RVL, RVH, REL, REH, RNQL, RNQH, RRL, RRH, RDL, RDH
    inc   K
    lsl   M
    breq  9f
    dec   ROWS
    brne  growr
    rjmp  fin
9:  rjmp  wrap

nogrp:
    clt                     /* the rows: whole spans */
    rjmp  row
grp2:                       /* GMIN rows or more left: on the page too? */
    cpi   M, (1 << (8 - GMIN)) + 1
    brsh  nogrp
#if GMIN == 7
    /* M is 1 or 2 here: g = 8 (M = 1, 8 rows or more left) or 7 */
    ldi   r30, 7
    ldi   Q, 0xFE           /* gm: bits 1..7 */
    cpi   M, 1
    brne  2f
    ldi   Q, 0x7F           /* bits 0..6 */
    cpi   ROWS, 8
    brlo  2f
    ldi   Q, 0xFF
    ldi   r30, 8
2:  mov   T0, r30
#else
    clr   T0                /* T0 = g, Q = M << g (0 past bit 7) */
    mov   Q, M
1:  inc   T0
    lsl   Q
    breq  2f
    cp    T0, ROWS
    brne  1b
2:  sub   Q, M              /* gm */
    ldi   r30, GMIN
    cp    T0, r30
    brlo  nogrp
    mov   r30, M            /* one bit */
    dec   r30
    and   r30, M
    brne  nogrp
#endif
    movw  r26, LVL          /* the first row's span: IMIN columns or more */
    movw  r30, RVL
    sub   r30, r26
    sbc   r31, r27
    brlt  nogrp
    sbiw  r30, IMIN
    brlt  nogrp
    mov   r30, LVH          /* -64 <= val high byte <= 63 */
    subi  r30, 0xC0
    brmi  nogrp
    mov   r30, RVH
    subi  r30, 0xC0
    brmi  nogrp
    mov   r30, LNQL         /* ~q (so q) in -128..127 */
    lsl   r30
    sbc   r30, r30
    cp    r30, LNQH
    brne  nogrp
    mov   r30, RNQL
    lsl   r30
    sbc   r30, r30
    cp    r30, RNQH
    brne  nogrp
    push  K                 /* both edges' row g - 1 in closed form */
    push  ROWS
    push  M
    mov   K, T0
    dec   K                 /* n = g - 1 */
    GUARD LEL, LEH, LRL, LRH, LDL, LDH
    GUARD REL, REH, RRL, RRH, RDL, RDH
    sts   r8k_trap_ab+12, K
    movw  r26, LVL
    LAST  r26, r27, LEL, LEH, LNQL, LNQH, LRL, LRH, LDL, LDH
    sts   r8k_trap_ab+4, r26
    sts   r8k_trap_ab+5, r27
    sts   r8k_trap_ab+6, r24
    sts   r8k_trap_ab+7, r25
    movw  r30, RVL
    LAST  r30, r31, REL, REH, RNQL, RNQH, RRL, RRH, RDL, RDH
    sts   r8k_trap_ab+8, r30
    sts   r8k_trap_ab+9, r31
    sts   r8k_trap_ab+10, r24
    sts   r8k_trap_ab+11, r25
    sbrs  r27, 7            /* A = max(first, last, 0); T: the left */
    rjmp  1f                /* end the same on every row */
    clr   r26
    clr   r27
1:  movw  r24, LVL
    sbrs  r25, 7
    rjmp  2f
    clr   r24
    clr   r25
2:  clt
    cp    r24, r26
    cpc   r25, r27
    brne  3f
    set
3:  brlt  4f
    movw  r26, r24
4:  movw  r24, RVL          /* B = min(first, last, w) */
    ldd   r0, Y+8
    ldd   r1, Y+9
    cp    r24, r0
    cpc   r25, r1
    brlt  5f
    movw  r24, r0
5:  cp    r30, r0
    cpc   r31, r1
    brlt  1f
    movw  r30, r0
1:  clr   r0                /* flags: bit 0 the left end, bit 1 the */
    bld   r0, 0             /* right end the same on every row */
    cp    r24, r30
    cpc   r25, r31
    brlt  3f
    brne  2f
    set
    bld   r0, 1
    rjmp  2f
3:  movw  r30, r24
2:  sts   r8k_trap_ab+13, r0
6:  pop   M
    pop   ROWS
    pop   K
    sub   r30, r26          /* B - A >= IMIN columns, else no interior */
    sbc   r31, r27
    brlt  8f
    sbiw  r30, IMIN
    brge  9f
8:  rjmp  nogrp
gbail:                      /* (an edge the closed form does not take) */
    pop   M
    pop   ROWS
    pop   K
    rjmp  nogrp
9:  adiw  r30, IMIN
    add   r30, r26
    adc   r31, r27
    push  r2
    push  r3
    push  r4
    push  r5
    push  r12
    push  r13
    push  r14
7:  sts   r8k_trap_ab, r26
    sts   r8k_trap_ab+1, r27
    sts   r8k_trap_ab+2, r30
    sts   r8k_trap_ab+3, r31
    /* the column bytes: C_c (r2 + c) bit b = bit 3 - c of pat[(K0 + b) & 3] */
    mov   r31, M            /* r30 = K0 + 3 = K - bitpos(M) + 3 */
    mov   r30, K
    subi  r30, -3
1:  lsr   r31
    breq  2f
    dec   r30
    rjmp  1b
2:  clr   r1
    clr   r2
    clr   r3
    clr   r4
    clr   r5
    ldi   r31, 4
    mov   r13, r31
3:  mov   r26, r30          /* b = 3 down to 0: pat[(K0 + b) & 3] */
    andi  r26, 3
    subi  r26, -4
    add   r26, r28
    mov   r27, r29
    adc   r27, r1
    ld    r14, X
    lsr   r14               /* its bit 0 -> column 3, ... bit 3 -> 0 */
    rol   r5
    lsr   r14
    rol   r4
    lsr   r14
    rol   r3
    lsr   r14
    rol   r2
    dec   r30
    dec   r13
    brne  3b
    mov   r0, r2            /* the nibble twice, under gm */
    swap  r0
    or    r2, r0
    and   r2, Q
    mov   r0, r3
    swap  r0
    or    r3, r0
    and   r3, Q
    mov   r0, r4
    swap  r0
    or    r4, r0
    and   r4, Q
    mov   r0, r5
    swap  r0
    or    r5, r0
    and   r5, Q
    mov   r12, Q
    com   r12
    lds   r30, r8k_trap_ab+2  /* loop column j: column byte (B + j) & 3 */
    sbrs  r30, 1
    rjmp  4f
    movw  r26, r2
    movw  r2, r4
    movw  r4, r26
4:  sbrs  r30, 0
    rjmp  5f
    mov   r26, r2
    mov   r2, r3
    mov   r3, r4
    mov   r4, r5
    mov   r5, r26
5:  lds   r26, r8k_trap_ab
    lds   r27, r8k_trap_ab+1
    lds   r31, r8k_trap_ab+3
    SETUP
    cpi   Q, 0xFF
    breq  ifull
    ENTER i0, i1, i2, i3
i0: ld    T0, X
    and   T0, r12
    or    T0, r2
    st    X+, T0
i1: ld    T0, X
    and   T0, r12
    or    T0, r3
    st    X+, T0
i2: ld    T0, X
    and   T0, r12
    or    T0, r4
    st    X+, T0
i3: ld    T0, X
    and   T0, r12
    or    T0, r5
    st    X+, T0
    cp    r26, r30
    cpc   r27, r31
    brne  i0
    rjmp  idone
ifull:
    ENTER f0, f1, f2, f3
f0: st    X+, r2
f1: st    X+, r3
f2: st    X+, r4
f3: st    X+, r5
    cp    r26, r30
    cpc   r27, r31
    brne  f0
idone:
    pop   r14
    pop   r13
    pop   r12
    pop   r5
    pop   r4
    pop   r3
    pop   r2
    set                     /* the rows: their ragged ends */
    lds   r0, r8k_trap_ab+13
    sbrs  r0, 0
    rjmp  4f
    sbrs  r0, 1
    rjmp  growr             /* only right ends: growr's left piece is empty */
    lds   LVL, r8k_trap_ab+4  /* no row but the last can have a */
    lds   LVH, r8k_trap_ab+5  /* ragged end: on to row g - 1 */
    lds   LEL, r8k_trap_ab+6
    lds   LEH, r8k_trap_ab+7
    lds   RVL, r8k_trap_ab+8
    lds   RVH, r8k_trap_ab+9
    lds   REL, r8k_trap_ab+10
    lds   REH, r8k_trap_ab+11
    lds   r0, r8k_trap_ab+12
    sub   ROWS, r0
    add   K, r0
1:  lsl   M
    dec   r0
    brne  1b
    rjmp  growr
4:  rjmp  growr             /* (only left ends: its right piece is empty) */

fin:
    andi  K, 3
    std   Y+2, M
    std   Y+3, K
    ret


/* one DDA step of the r8_interp at Z (Z kept; r24-r27 changed): for
 * `one` and r8k_scanfill's one-row trapezoids */
mstz:
    MSTEP
    ret

/* r8k_scanband (src/r8scan.h): r8_scanx_fill's page-1 set-up, then
 * r8k_scanfill; its C reference in src/kern.c.
 *
 *   void r8k_scanband(r8_scanx *s, const r8_fb *fb, r8_s16 lim, r8_u8 level);
 *
 * s->y in [fb->y0, lim); t (r8k_sft, static) gets page = fb->buf +
 * ((s->y - fb->y0) >> 3) fb->width (16-bit arithmetic: rows - y0 <
 * 2048), m = r8_fb_bit[by & 7], k = s->y & 3, w = fb->width and
 * pat[0..3] = r8_fb_dither_tab[4 min(level, 16) + 0..3]; then on to
 * r8k_scanfill(s, &r8k_sft, lim).  r8_fb offsets: buf 0, width 2, y0 6. */
    .global r8k_scanband
    .type   r8k_scanband, @function
r8k_scanband:
    movw  r30, r24          /* y */
    ldd   r26, Z+21
    ldd   r27, Z+22
    mov   r19, r26          /* k = y & 3 */
    andi  r19, 3
    sts   r8k_sft+3, r19
    movw  r30, r22          /* by = y - fb->y0 */
    ldd   r19, Z+6
    sub   r26, r19
    ldd   r19, Z+7
    sbc   r27, r19
    ldd   r22, Z+2          /* w */
    ldd   r23, Z+3
    sts   r8k_sft+8, r22
    sts   r8k_sft+9, r23
    ld    r0, Z             /* buf */
    ldd   r31, Z+1
    mov   r30, r0
    ldi   r27, 1            /* m = 1 << (by & 7), in 7 cycles: */
    sbrc  r26, 1            /* 1 or 4 by bit 1, times 2 by bit 0, */
    ldi   r27, 4            /* times 16 (swap) by bit 2 */
    sbrc  r26, 0
    lsl   r27
    sbrc  r26, 2
    swap  r27
    sts   r8k_sft+2, r27
    lsr   r26               /* page = buf + (by >> 3) w (by < 2048) */
    lsr   r26
    lsr   r26
    mul   r26, r22
    add   r30, r0
    adc   r31, r1
    mul   r26, r23
    add   r31, r0
    clr   r1
    sts   r8k_sft, r30
    sts   r8k_sft+1, r31
    cpi   r18, 17           /* the level's 4 rows */
    brlo  3f
    ldi   r18, 16
3:  ldi   r30, lo8(r8_fb_dither_tab)
    ldi   r31, hi8(r8_fb_dither_tab)
    lsl   r18
    lsl   r18
    add   r30, r18
    adc   r31, r1
    lpm   r0, Z+
    sts   r8k_sft+4, r0
    lpm   r0, Z+
    sts   r8k_sft+5, r0
    lpm   r0, Z+
    sts   r8k_sft+6, r0
    lpm   r0, Z
    sts   r8k_sft+7, r0
    ldi   r22, lo8(r8k_sft)
    ldi   r23, hi8(r8k_sft)
    rjmp  r8k_scanfill
    .size r8k_scanband, .-r8k_scanband

/* r8k_scanfill (src/r8scan.h): the trapezoid loop of scan.c's
 * r8_scanx_fill, its C reference in src/kern.c.
 *
 *   void r8k_scanfill(r8_scanx *s, r8_trapfill *t, r8_s16 lim);
 *
 * From row s->y (< lim) to lim: restart an edge that ended (r8k_estart,
 * edge.S), fill the rows to the first end of either edge or lim (at
 * most 255 at a time) as r8k_trap does, and on; s->y = lim at the end.
 * A one-row trapezoid is `one`'s span and t step inline (its state in
 * memory), its edges' DDA steps left to .Lsf_next1; longer ones go
 * through the register body above, called at grp (it returns at fin),
 * then on to .Lsf_fin; r8k_trap's entry calls it the same way and
 * writes back itself, so a firmware that only calls r8k_scanband links
 * no r8k_trap entry (its own section).  One stop calculation for all
 * (.Lsf_stop; r19 says which edge .Lsf_fin kept in registers).  Both skip the work on an edge that ends at y < lim, since
 * r8k_estart then rewrites all five of its r8_interp fields (the step
 * of a one-row trapezoid, the write-back of a longer one); at y = lim
 * both edges are stepped or written, so s ends as the C reference
 * leaves it.  After a longer trapezoid that restarts one edge only, the
 * next longer one loads only what r8k_estart did not keep (.Lsf_rowsA,
 * .Lsf_rowsB).  r2..r17 are saved at the first longer trapezoid of a call
 * (a call of one-row trapezoids saves none), which sets that flag.
 * r8k_sf: s (2 bytes), lim (2), the flag (1).
 * r8_scanx offsets: y 21, l 25 (x 25, yend 35, vi 37), r 38 (x 38,
 * yend 48, vi 50) (src/kern.c asserts them). */
    .global r8k_scanfill
    .type   r8k_scanfill, @function
r8k_scanfill:
    push  r28
    push  r29
    sts   r8k_sf, r24
    sts   r8k_sf+1, r25
    sts   r8k_sf+2, r20
    sts   r8k_sf+3, r21
    sts   r8k_sf+4, r1      /* r2..r17 not saved yet */
    movw  r28, r22          /* Y = t */
    movw  r30, r24          /* Z = s, r21:r20 = y */
    ldd   r20, Z+21
    ldd   r21, Z+22
.Lsf_top:
    ldd   r24, Z+35         /* y >= l->yend: restart l */
    ldd   r25, Z+36
    cp    r20, r24
    cpc   r21, r25
    brlt  1f
    movw  r24, r30
    movw  r22, r30
    subi  r22, lo8(-25)
    sbci  r23, hi8(-25)
    ldd   r18, Z+37
    call  r8k_estart
    lds   r30, r8k_sf
    lds   r31, r8k_sf+1
    ldd   r20, Z+21
    ldd   r21, Z+22
1:  ldd   r24, Z+48         /* y >= r->yend: restart r */
    ldd   r25, Z+49
    cp    r20, r24
    cpc   r21, r25
    brlt  .Lsf_stop
.Lsf_rre:
    movw  r24, r30
    movw  r22, r30
    subi  r22, lo8(-38)
    sbci  r23, hi8(-38)
    ldd   r18, Z+50
    call  r8k_estart
    lds   r30, r8k_sf
    lds   r31, r8k_sf+1
    ldd   r20, Z+21
    ldd   r21, Z+22
    ldd   r24, Z+48
    ldd   r25, Z+49
.Lsf_stop:
    clr   r19               /* both edges to load (r19: 1 l kept, 2 r kept) */
.Lsf_stopK:
    lds   r26, r8k_sf+2     /* stop = min(lim, r->yend, l->yend) */
    lds   r27, r8k_sf+3
    cp    r24, r26
    cpc   r25, r27
    brlt  3f
    movw  r24, r26
3:  ldd   r26, Z+35
    ldd   r27, Z+36
    cp    r26, r24
    cpc   r27, r25
    brge  4f
    movw  r24, r26
4:  movw  r26, r24          /* rows = stop - y (>= 1), at most 255 */
    sub   r26, r20
    sbc   r27, r21
    tst   r27
    breq  5f
    ldi   r26, 255
    movw  r24, r20
    subi  r24, lo8(-255)
    sbci  r25, hi8(-255)
5:  std   Z+21, r24         /* s->y = stop */
    std   Z+22, r25
    movw  r22, r30          /* l, r */
    subi  r22, lo8(-25)
    sbci  r23, hi8(-25)
    movw  r20, r30
    subi  r20, lo8(-38)
    sbci  r21, hi8(-38)
    cpi   r26, 1
    brne  .Lsf_rows
.Lsf_one:
    /* one row: `one`'s span and t step (r2..r17 untouched); its edges'
     * DDA steps wait for .Lsf_next1, which skips the step of an edge
     * that r8k_estart is about to rewrite (all five fields) */
    movw  r30, r22          /* X = max(l->val, 0) */
    ld    r26, Z
    ldd   r27, Z+1
    sbrc  r27, 7
    rjmp  .Lsf_oneg
.Lsf_o1:
    movw  r30, r20          /* Z = min(r->val, w) */
    ld    r24, Z
    ldd   r25, Z+1
    ldd   r30, Y+8
    ldd   r31, Y+9
    cp    r24, r30
    cpc   r25, r31
    brge  1f
    movw  r30, r24
1:  cp    r26, r30
    cpc   r27, r31
    ldd   M, Y+2            /* (flags kept) */
    ldd   K, Y+3
    brge  2f
    set                     /* T set: the span returns */
    rcall span
2:  inc   K                 /* k = (k + 1) & 3 */
    andi  K, 3
    std   Y+3, K
    lsl   M                 /* m <<= 1; past bit 7: m = 1, page += w */
    brne  3f
    inc   M
    ldd   r26, Y+0
    ldd   r27, Y+1
    ldd   r18, Y+8
    ldd   r19, Y+9
    add   r26, r18
    adc   r27, r19
    std   Y+0, r26
    std   Y+1, r27
3:  std   Y+2, M
    rjmp  .Lsf_next1
.Lsf_oneg:
    clr   r26
    clr   r27
    rjmp  .Lsf_o1
.Lsf_kept:
    cpi   r19, 1
    breq  .Lsf_rowsA
    rjmp  .Lsf_rowsB
.Lsf_rows:
    mov   ROWS, r26
    tst   r19               /* an edge kept in registers (after .Lsf_fin) */
    brne  .Lsf_kept
    lds   r30, r8k_sf+4     /* the first of these rows in this call: */
    tst   r30               /* save r2..r17 now */
    brne  6f
    push  r2
    push  r3
    push  r4
    push  r5
    push  r6
    push  r7
    push  r8
    push  r9
    push  r10
    push  r11
    push  r12
    push  r13
    push  r14
    push  r15
    push  r16
    push  r17
    ldi   r30, 1            /* saved: restored at .Lsf_out */
    sts   r8k_sf+4, r30
6:  movw  r30, r22
    ld    LVL, Z+
    ld    LVH, Z+
    ld    LNQL, Z+
    ld    LNQH, Z+
    ld    LEL, Z+
    ld    LEH, Z+
    ld    LRL, Z+
    ld    LRH, Z+
    ld    LDL, Z+
    ld    LDH, Z
    com   LNQL
    com   LNQH
.Lsf_rowsA:                 /* (l in r2..r11 already) */
    movw  r30, r20
    ld    RVL, Z+
    ld    RVH, Z+
    ld    RNQL, Z+
    ld    RNQH, Z+
    ld    REL, Z+
    ld    REH, Z+
    ld    RRL, Z+
    ld    RRH, Z+
    ld    RDL, Z+
    ld    RDH, Z
    com   RNQL
    com   RNQH
    ldd   M, Y+2
    ldd   K, Y+3
    rcall grp
    rjmp  .Lsf_fin
/* after a one-row trapezoid: y = s->y; each edge's pending DDA step,
 * unless the edge ends here and a trapezoid follows (r8k_estart
 * rewrites it: the step would be lost) */
.Lsf_next1:
    clr   r1
    lds   r30, r8k_sf
    lds   r31, r8k_sf+1
    ldd   r20, Z+21
    ldd   r21, Z+22
    lds   r24, r8k_sf+2
    lds   r25, r8k_sf+3
    cp    r20, r24
    cpc   r21, r25
    brlt  1f
    adiw  r30, 25           /* y = lim: both steps, and out */
    rcall mstz
    adiw  r30, 13
    rcall mstz
    sbiw  r30, 38
    rjmp  .Lsf_out
1:  ldd   r24, Z+35         /* y >= l->yend: restart l, no step */
    ldd   r25, Z+36
    cp    r20, r24
    cpc   r21, r25
    brlt  2f
    movw  r24, r30
    movw  r22, r30
    subi  r22, lo8(-25)
    sbci  r23, hi8(-25)
    ldd   r18, Z+37
    call  r8k_estart
    lds   r30, r8k_sf
    lds   r31, r8k_sf+1
    ldd   r20, Z+21
    ldd   r21, Z+22
    rjmp  3f
2:  adiw  r30, 25
    rcall mstz
    sbiw  r30, 25
3:  ldd   r24, Z+48         /* y >= r->yend: restart r, no step */
    ldd   r25, Z+49
    cp    r20, r24
    cpc   r21, r25
    brlt  4f
    rjmp  .Lsf_rre
4:  adiw  r30, 38
    rcall mstz
    sbiw  r30, 38
    ldd   r24, Z+48
    ldd   r25, Z+49
    rjmp  .Lsf_stop
/* after a trapezoid of several rows (from fin: the edges' val and err
 * still in r2..r5, r12..r15, which r8k_estart keeps): each edge's write
 * back, unless it ends here and a trapezoid follows (r8k_estart
 * rewrites it) */
.Lsf_fin:
    clr   r1
    lds   r30, r8k_sf
    lds   r31, r8k_sf+1
    ldd   r20, Z+21
    ldd   r21, Z+22
    lds   r24, r8k_sf+2
    lds   r25, r8k_sf+3
    cp    r20, r24
    cpc   r21, r25
    brlt  1f
    std   Z+25, LVL         /* y = lim: both, and out */
    std   Z+26, LVH
    std   Z+29, LEL
    std   Z+30, LEH
    std   Z+38, RVL
    std   Z+39, RVH
    std   Z+42, REL
    std   Z+43, REH
    rjmp  .Lsf_out
1:  ldd   r24, Z+35         /* y >= l->yend: restart l, no write */
    ldd   r25, Z+36
    cp    r20, r24
    cpc   r21, r25
    brge  2f
    rjmp  .Lsf_lgo
2:  movw  r24, r30
    movw  r22, r30
    subi  r22, lo8(-25)
    sbci  r23, hi8(-25)
    ldd   r18, Z+37
    call  r8k_estart
    lds   r30, r8k_sf
    lds   r31, r8k_sf+1
    ldd   r20, Z+21
    ldd   r21, Z+22
    ldd   r24, Z+48         /* y >= r->yend: restart r too (all */
    ldd   r25, Z+49         /* loaded again) */
    cp    r20, r24
    cpc   r21, r25
    brlt  3f
    rjmp  .Lsf_rre
3:  std   Z+38, RVL         /* r goes on: its val, err, ~q stay in */
    std   Z+39, RVH         /* r12..r17 (r25:r24 = r->yend) */
    std   Z+42, REL
    std   Z+43, REH
    ldi   r19, 2            /* on with l loaded (r kept) */
    rjmp  .Lsf_stopK
.Lsf_lgo:                   /* l goes on */
    std   Z+25, LVL
    std   Z+26, LVH
    std   Z+29, LEL
    std   Z+30, LEH
    ldd   r24, Z+48         /* y >= r->yend: restart r, no write */
    ldd   r25, Z+49
    cp    r20, r24
    cpc   r21, r25
    brge  4f
    std   Z+38, RVL         /* neither ends (a 255-row trapezoid) */
    std   Z+39, RVH
    std   Z+42, REL
    std   Z+43, REH
    rjmp  .Lsf_stop
4:  movw  r24, r30          /* l's state stays in r2..r11 */
    movw  r22, r30
    subi  r22, lo8(-38)
    sbci  r23, hi8(-38)
    ldd   r18, Z+50
    call  r8k_estart
    lds   r30, r8k_sf
    lds   r31, r8k_sf+1
    ldd   r20, Z+21
    ldd   r21, Z+22
    ldd   r24, Z+48
    ldd   r25, Z+49
    ldi   r19, 1            /* on with r loaded (l kept) */
    rjmp  .Lsf_stopK
/* the next trapezoid after .Lsf_fin restarted one edge only: l still
 * in r2..r11 (A), or r's val, err, ~q in r12..r17 (B) */
.Lsf_rowsB:
    movw  r30, r22
    ld    LVL, Z+
    ld    LVH, Z+
    ld    LNQL, Z+
    ld    LNQH, Z+
    ld    LEL, Z+
    ld    LEH, Z+
    ld    LRL, Z+
    ld    LRH, Z+
    ld    LDL, Z+
    ld    LDH, Z
    com   LNQL
    com   LNQH
    movw  r30, r20
    ldd   RRL, Z+6
    ldd   RRH, Z+7
    ldd   RDL, Z+8
    ldd   RDH, Z+9
    ldd   M, Y+2
    ldd   K, Y+3
    rcall grp
    rjmp  .Lsf_fin
.Lsf_out:
7:  lds   r0, r8k_sf+4
    tst   r0
    breq  8f
    sts   r8k_sf+4, r1
    pop   r17
    pop   r16
    pop   r15
    pop   r14
    pop   r13
    pop   r12
    pop   r11
    pop   r10
    pop   r9
    pop   r8
    pop   r7
    pop   r6
    pop   r5
    pop   r4
    pop   r3
    pop   r2
8:  pop   r29
    pop   r28
    ret
    .size r8k_scanfill, .-r8k_scanfill

/* r8k_scanfill's s, lim and flag (fin returns to it when set) */
    .section .bss.r8k_sf,"aw",@nobits
    .type   r8k_sf, @object
    .size   r8k_sf, 5
r8k_sf:
    .zero   5
/* r8k_scanband's r8_trapfill */
    .section .bss.r8k_sft,"aw",@nobits
    .type   r8k_sft, @object
    .size   r8k_sft, 10
r8k_sft:
    .zero   10

/* a group's interior [A, B) for its rows (A, B: 2 bytes each), its row
 * g - 1 (left val, err, right val, err), n = g - 1 and the flags of
 * the ends that are the same on every row */
    .section .bss.r8k_trap_ab,"aw",@nobits
    .type   r8k_trap_ab, @object
    .size   r8k_trap_ab, 14
r8k_trap_ab:
    .zero   14
