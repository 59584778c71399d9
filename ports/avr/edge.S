/* edge.S - r8k_edge (include/r8kern.h) for AVR with MUL (ATmega).
 *
 *   r8_s16 r8k_edge(r8_interp *it, const r8_s16 *a, const r8_s16 *b);
 *
 * The 16-bit column-DDA set-up of one polygon edge, bit for bit the C
 * reference in src/kern.c: the same R8_EDGE_WIDE cases (dy >= 1424, ax
 * or bx outside [-16384, 16383], |q| >= 2048 after the floor division),
 * *it untouched then; otherwise it->val, q, err, r, den and y0 as the
 * reference computes them (16-bit arithmetic modulo 2^16 where it has).
 *
 *   dy = by - ay, dx = bx - ax, y0 = floor((ay + 7) / 16) (17 bits)
 *   s0 = 16 y0 + 8 - ay = (8 - ay) & 15
 *   udx = dx, or ~dx = -dx - 1 when dx < 0 (T set)
 *   q, rd = udx / dy, udx % dy; when dx < 0: q = ~q, rd = dy - 1 - rd
 *   X = ax - 8 + s0 q (17 bits), pl = X & 15, val = floor(X / 16)
 *     (the reference's p = ((ax - 8) & 15) + s0 q: p & 15 = pl and
 *     floor((ax - 8) / 16) + floor(p / 16) = val)
 *   v = dy pl + s0 rd (< 30 dy): the reference's loop on
 *     u = v + 16 dy - 1 adds ceil(v / 16 dy) (0..2) to val and leaves
 *     err = ((v + 16 dy - 1) mod 16 dy) >> 4: dy - 1 for v = 0; else,
 *     w = v - 1 (< 32 dy), e = w >> 4: val + 1, and once more if
 *     e >= dy (w >= 16 dy); err = e, or e - dy = (w - 16 dy) >> 4
 *
 * Quotients 0 and 1 (udx < 2 dy: most edges of a mesh; the torus: 381
 * and 164 of 720) take no division loop.  Otherwise the division walks
 * the quotient's bits from its top one, as the
 * reference's udivmod: the divisor doubles while it stays <= udx, then
 * one restoring step per doubling (+1).  The quotient register starts
 * all ones but a 0 sentinel at bit 15 that moves right per doubling;
 * each step shifts in the complement of its bit (the carry of the
 * compare/subtract), and the step that shifts the sentinel out is the
 * last one; a final complement leaves the quotient.  udx < 2^15, so the
 * doubled divisor never overflows.
 *
 * Registers (avr-gcc ABI): arguments it r25:r24, a r23:r22, b r21:r20;
 * returns r25:r24.  The public entry loads the four coordinates, keeps
 * ay on the stack and calls the body (.Ledge_body, which r8k_estart
 * enters too), then computes y0 from ay.  In the body: Z = it, r25:r24 =
 * ay, then s0 (r24) and pl (r25), r23:r22 = ax, then X and val, r21:r20
 * = dy, r19:r18 = udx then rd, r27:r26 = q, then v, w and err, r1:r0 =
 * divisor, then MUL products; T = dx < 0, and on return T = wide.
 * r1 is cleared before returning.
 *
 * r8_interp offsets (avr-gcc, no padding): val 0, q 2, err 4, r 6, den 8.
 */

    .section .text.r8k_edge,"ax",@progbits
    .global r8k_edge
    .type   r8k_edge, @function
r8k_edge:                     /* (cold on AVR: r8k_estart enters the body) */
    movw  r26, r22          /* X = a */
    movw  r30, r20          /* Z = b */
    ld    r22, X+           /* ax */
    ld    r23, X+
    ld    r18, Z+           /* bx */
    ld    r19, Z+
    ld    r20, Z+           /* by */
    ld    r21, Z
    movw  r30, r24          /* Z = it */
    ld    r24, X+           /* ay */
    ld    r25, X
    push  r24
    push  r25
    rcall .Ledge_body
    pop   r27
    pop   r26
    brts  41f               /* wide: r25:r24 = R8_EDGE_WIDE */
    movw  r24, r26          /* y0 = floor((ay + 7) / 16); 2048 when */
    adiw  r24, 7            /* ay + 7 passes 32767 */
    brvs  40f
    asr   r25
    ror   r24
    asr   r25
    ror   r24
    asr   r25
    ror   r24
    asr   r25
    ror   r24
41: ret
40: ldi   r24, 0x00
    ldi   r25, 0x08
    ret

.Lwide:                       /* (before the body: in branch range) */
    set
    ldi   r24, 0x00         /* R8_EDGE_WIDE = -32768 */
    ldi   r25, 0x80
    ret
/* The body: ax r23:r22, ay r25:r24, bx r19:r18, by r21:r20, Z = it,
 * r1 = 0.  T = 1: R8_EDGE_WIDE (r25:r24 = 0x8000, *it untouched);
 * T = 0: *it set.  Z kept, r1 = 0, r0 and r18..r27 clobbered. */
.Ledge_body:
    sub   r20, r24          /* dy = by - ay */
    sbc   r21, r25
    ldi   r26, hi8(1424)    /* dy >= 1424: wide */
    cpi   r20, lo8(1424)
    cpc   r21, r26
    brsh  .Lwide
    mov   r26, r23          /* ax + 0x4000 negative: ax outside */
    subi  r26, 0xC0         /* [-16384, 16383], wide */
    brmi  .Lwide
    mov   r26, r19          /* the same for bx */
    subi  r26, 0xC0
    brmi  .Lwide
    sub   r18, r22          /* dx = bx - ax (no overflow) */
    sbc   r19, r23
    clt
    brpl  1f
    set                     /* dx < 0: udx = ~dx */
    com   r18
    com   r19
1:
    /* q, rd = udx / dy, udx % dy */
    cp    r18, r20
    cpc   r19, r21
    brsh  2f
    ldi   r26, 0            /* udx < dy: q = 0, rd = udx */
    ldi   r27, 0
    brtc  7f
    ldi   r26, 0xFF         /* (dx < 0: q = -1) */
    ldi   r27, 0xFF
    rjmp  64f
.Lwide2:                      /* after the division: r1 back to 0 */
    clr   r1
    rjmp  .Lwide
2:  sub   r18, r20          /* udx < 2 dy: q = 1, rd = udx - dy */
    sbc   r19, r21
    cp    r18, r20
    cpc   r19, r21
    brsh  25f
    ldi   r26, 1
    ldi   r27, 0
    brtc  7f
    ldi   r26, 0xFE         /* (dx < 0: q = -2) */
    ldi   r27, 0xFF
    rjmp  64f
25: add   r18, r20          /* else udx back, the general division */
    adc   r19, r21
    movw  r0, r20           /* divisor D = dy */
    ldi   r26, 0xFF         /* all ones, the sentinel 0 at bit 15 */
    ldi   r27, 0x7F
3:  lsl   r0                /* D doubles while 2 D <= udx */
    rol   r1
    cp    r18, r0
    cpc   r19, r1
    brlo  4f
    sec                     /* one more quotient bit: sentinel right */
    ror   r27
    ror   r26
    rjmp  3b
4:  lsr   r1                /* back to the largest D <= udx */
    ror   r0
5:  cp    r18, r0           /* one quotient bit: C = 1 when it is 0 */
    cpc   r19, r1
    brlo  .+4
    sub   r18, r0           /* (no borrow: C = 0) */
    sbc   r19, r1
    rol   r26               /* the bit's complement in, the top out */
    rol   r27
    brcc  55f               /* that was the sentinel: done */
    lsr   r1
    ror   r0
    rjmp  5b
55: com   r26
    com   r27
6:  cpi   r27, 8            /* q >= 2048: wide */
    brsh  .Lwide2
    brtc  7f
    com   r26               /* dx < 0: q = -q - 1 */
    com   r27
    cpi   r26, 0            /* q == -2048: wide */
    brne  .+4
    cpi   r27, 0xF8
    breq  .Lwide2
64: com   r18               /* rd = dy - 1 - rd = dy + ~rd */
    com   r19
    add   r18, r20
    adc   r19, r21
7:  std   Z+2, r26          /* it->q, it->r, it->den */
    std   Z+3, r27
    std   Z+6, r18
    std   Z+7, r19
    std   Z+8, r20
    std   Z+9, r21

    /* X = ax - 8 + s0 q (17 bits: S is its sign); pl = X & 15 (that is
     * p & 15), val = floor(X / 16) (the reference's two floors) */
    neg   r24               /* s0 = (8 - ay) & 15 */
    subi  r24, 0xF8
    andi  r24, 15
    mul   r24, r27          /* s0 q, modulo 2^16 */
    mov   r27, r0
    mul   r24, r26
    add   r1, r27
    subi  r22, 8            /* ax - 8 */
    sbci  r23, 0
    add   r22, r0
    adc   r23, r1
    mov   r25, r22          /* (pl) */
    brvs  22f
    asr   r23
    ror   r22
21: asr   r23
    ror   r22
    asr   r23
    ror   r22
    asr   r23
    ror   r22
    andi  r25, 15           /* pl */

    /* v = dy pl + s0 rd (< 30 dy); val += ceil(v / (16 dy)) (0..2),
     * err = ((v + 16 dy - 1) mod 16 dy) >> 4: for v > 0, w = v - 1,
     * e = w >> 4: val + 1, err = e, and when e >= dy (w >= 16 dy)
     * val + 2, err = e - dy ((w - 16 dy) >> 4) */
    mul   r24, r19          /* s0 rd */
    mov   r19, r0
    mul   r24, r18
    add   r1, r19
    movw  r26, r0
    mul   r20, r25          /* + dy pl */
    add   r26, r0
    adc   r27, r1
    mul   r21, r25
    add   r27, r0
    sbiw  r26, 1            /* w = v - 1 */
    brcs  30f               /* v = 0: err = dy - 1 */
    swap  r26               /* e = w >> 4 */
    andi  r26, 0x0F
    swap  r27
    mov   r25, r27
    andi  r25, 0xF0
    or    r26, r25
    andi  r27, 0x0F
    subi  r22, 0xFF         /* val++ */
    sbci  r23, 0xFF
    cp    r26, r20
    cpc   r27, r21
    brlo  32f
    sub   r26, r20          /* w >= 16 dy: once more */
    sbc   r27, r21
    subi  r22, 0xFF
    sbci  r23, 0xFF
32: st    Z, r22
    std   Z+1, r23
    std   Z+4, r26
    std   Z+5, r27
    clr   r1
    clt
    ret

30: movw  r26, r20          /* v = 0: err = dy - 1 */
    sbiw  r26, 1
    rjmp  32b
22: sec                     /* X beyond 16 bits: the first shift */
    sbrc  r23, 7            /* brings in !N, the true sign */
    clc
    ror   r23
    ror   r22
    rjmp  21b
    .size r8k_edge, .-r8k_edge

/* r8k_estart (src/r8scan.h): scan.c's edge_start, its C reference.
 *
 *   void r8k_estart(r8_scanx *s, r8_edge *e, r8_s16 y, r8_u8 from);
 *
 * e is &s->l (the left chain: positions backwards) or &s->r (forwards).
 * Walk from `from` to the first vertex `to` whose row R8_ROW_OF(y) is
 * below row y (with y < s->ybot one is found within n - 1 steps, so the
 * reference's guard never stops the walk), set e->vi = to, e->yend =
 * that row, then the edge's DDA from a = s->vp[from] to b = s->vp[to]
 * through r8k_edge's body (above, by RCALL: the same section).  The
 * rare cases go to the reference's r8_edge_rare(e, a, b, y) (scan.c),
 * which does what the reference does after r8k_edge: an edge whose
 * first row R8_ROW_OF(ay) is above y (tested before the DDA, so that y
 * need not outlive it; rare: the torus has none), an empty edge (b[1]
 * <= a[1]) and R8_EDGE_WIDE (the body leaves *it as it was: a, b and y
 * are parked in it->val, it->q and it->err for that).  No register is
 * saved.
 *
 * Registers: s r25:r24, e r23:r22, y r21:r20, from r18; r19 = to, r0 =
 * n, T = the left chain, X = a row, Z = a vertex; then Z = e, r1:r0 = b
 * (r1 cleared before the body), r25:r24 = &s->vp[from], a; then the
 * body's registers: r23:r22 = ax, r25:r24 = ay, r19:r18 = bx, r21:r20 =
 * by, Z = it = e.
 * r8_scanx offsets: vp 0, n 18, l 25, r 38; r8_edge: x 0, yend 10,
 * vi 12 (scan.c asserts them). */
    .section .text.r8k_edge,"ax",@progbits
    .global r8k_estart
    .type   r8k_estart, @function
r8k_estart:
    movw  r30, r24
    ldd   r0, Z+18          /* n */
    adiw  r30, 25           /* &s->l */
    clt
    cp    r30, r22
    cpc   r31, r23
    brne  .Le_walk
    set                     /* the left chain */
.Le_walk:
    mov   r19, r18          /* to = wrap(from) */
    brts  2f
    inc   r19
    cp    r19, r0
    brne  3f
    clr   r19
    rjmp  3f
2:  cpse  r19, r1
    rjmp  4f
    mov   r19, r0
4:  dec   r19
3:  movw  r30, r24          /* Z = s->vp[to] */
    add   r30, r19
    adc   r31, r1
    add   r30, r19
    adc   r31, r1
    ld    r26, Z
    ldd   r27, Z+1
    movw  r30, r26
    ldd   r26, Z+2          /* its y */
    ldd   r27, Z+3
    adiw  r26, 7            /* R8_ROW_OF: 2048 past 32760 */
    brvs  5f
    asr   r27
    ror   r26
    asr   r27
    ror   r26
    asr   r27
    ror   r26
    asr   r27
    ror   r26
6:  cp    r20, r26          /* y < row: this edge */
    cpc   r21, r27
    brlt  7f
    mov   r18, r19          /* else on to the next one */
    rjmp  .Le_walk
5:  ldi   r26, 0x00
    ldi   r27, 0x08
    rjmp  6b

7:  movw  r0, r30           /* r1:r0 = b (r1 is 0 again below) */
    movw  r30, r22          /* Z = e */
    std   Z+10, r26         /* e->yend, e->vi */
    std   Z+11, r27
    std   Z+12, r19
    std   Z+2, r0           /* b parked in it->q */
    std   Z+3, r1
    lsl   r18               /* a = s->vp[from] */
    clr   r19
    add   r24, r18
    adc   r25, r19
    movw  r26, r24
    ld    r24, X+
    ld    r25, X
    std   Z+0, r24          /* a parked in it->val */
    std   Z+1, r25
    movw  r26, r24          /* ax, ay */
    ld    r22, X+
    ld    r23, X+
    ld    r24, X+
    ld    r25, X
    movw  r26, r24          /* R8_ROW_OF(ay) < y: the rare path (the */
    adiw  r26, 7            /* edge starts above row y) */
    brvs  8f
    asr   r27
    ror   r26
    asr   r27
    ror   r26
    asr   r27
    ror   r26
    asr   r27
    ror   r26
9:  cp    r26, r20
    cpc   r27, r21
    brlt  .Le_rare_y
    std   Z+4, r20          /* y parked in it->err */
    std   Z+5, r21
    movw  r26, r0           /* bx, by */
    clr   r1
    ld    r18, X+
    ld    r19, X+
    ld    r20, X+
    ld    r21, X
    cp    r24, r20
    cpc   r25, r21
    brge  .Le_wide          /* by <= ay: empty edge */
    rcall .Ledge_body       /* r8k_edge past its loads (Z = it = e) */
    brts  .Le_wide
    ret

8:  ldi   r26, 0x00         /* (ay + 7 past 32767: row 2048) */
    ldi   r27, 0x08
    rjmp  9b
.Le_rare_y:
    movw  r18, r20          /* y */
    clr   r1
    rjmp  .Le_rare
.Le_wide:
    ldd   r18, Z+4          /* y, a, b back from their parks */
    ldd   r19, Z+5
.Le_rare:                     /* r8_edge_rare(e, a, b, y) */
    movw  r24, r30
    ld    r22, Z
    ldd   r23, Z+1
    ldd   r20, Z+2
    ldd   r21, Z+3
    jmp   r8_edge_rare
    .size r8k_estart, .-r8k_estart
