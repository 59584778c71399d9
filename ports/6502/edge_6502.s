; edge_6502.s - r8k_edge (include/r8kern.h) for the 6502 (ca65, issue 10):
; an edge's column DDA for its first row.  Built into the 6502 library
; with -DR8_ASM_EDGE (mk/targets.mk); the C89 reference is r8k_edge in
; src/kern.c, and tests/c/test_kern.c compares the two in sim65 on
; random edges (every class: wide by dy, by x, by slope; dx < 0, dx = 0,
; dy = 1, slopes near +-2048, y0 = 2048 past 32760).
;
; r8_s16 r8k_edge(r8_interp *it, const r8_s16 *a, const r8_s16 *b)
;   b in A/X; a, it on the C stack (popped here); y0 in A/X.
; The same steps as the reference: the quotient and remainder of |dx| /
; dy by restoring division (5 shifts, then 11 steps: a quotient of 2048
; or more is R8_EDGE_WIDE), the three small products (s0 q, dy pl,
; s0 rd: a nibble times 16 bits, low 16 bits) from mul_6502.s's quarter
; squares.  ~700 cycles an edge (the C: ~3000).

        .export         _r8k_edge
        .importzp       sp, sq1l, sq1h, sq2l, sq2h

; r8_interp: val +0, q +2, err +4, r +6, den +8

        .zeropage
ip:     .res    2               ; it
pp:     .res    2               ; a, b; then a product's high byte
xa:     .res    2               ; a[0], a[1]
ya:     .res    2
xb:     .res    2               ; b[0]; then p
dy:     .res    2               ; b[1] - a[1] (den)
dq:     .res    2               ; |dx|, then q
rd:     .res    2               ; the remainder (r)
y0:     .res    2
s0:     .res    1
neg:    .res    1
val:    .res    2
u:      .res    2
d16:    .res    2
p       = xb

        .code

; the quarter-square table pointers for the multiplier in A (mul_6502.s)
.macro  SETX
        sta     sq1l
        sta     sq1h
        eor     #$FF
        sta     sq2l
        sta     sq2h
.endmacro

; x * Y for the x set by SETX: the low byte in X, the high byte in A
.macro  MUL8
        sec
        lda     (sq1l),y
        sbc     (sq2l),y
        tax
        lda     (sq1h),y
        sbc     (sq2h),y
.endmacro

; (before the entry: the profile's cycles from _r8k_edge on are its own)
wide:   lda     #$00            ; R8_EDGE_WIDE, *it untouched
        ldx     #$80
        rts

_r8k_edge:
        sta     pp
        stx     pp+1
        ldy     #0              ; b[0], b[1]
        lda     (pp),y
        sta     xb
        iny
        lda     (pp),y
        sta     xb+1
        iny
        lda     (pp),y
        sta     dy
        iny
        lda     (pp),y
        sta     dy+1
        ldy     #0              ; the stack: a (0), it (2)
        lda     (sp),y
        sta     pp
        iny
        lda     (sp),y
        sta     pp+1
        iny
        lda     (sp),y
        sta     ip
        iny
        lda     (sp),y
        sta     ip+1
        clc                     ; pop 4 bytes
        lda     sp
        adc     #4
        sta     sp
        bcc     :+
        inc     sp+1
:       ldy     #0              ; a[0], a[1]
        lda     (pp),y
        sta     xa
        iny
        lda     (pp),y
        sta     xa+1
        iny
        lda     (pp),y
        sta     ya
        iny
        lda     (pp),y
        sta     ya+1
        sec                     ; dy = b[1] - a[1] (unsigned)
        lda     dy
        sbc     ya
        sta     dy
        lda     dy+1
        sbc     ya+1
        sta     dy+1
        lda     dy              ; dy >= 1424: wide
        cmp     #<1424
        lda     dy+1
        sbc     #>1424
        bcs     wide
        lda     xa+1            ; a[0], b[0] outside -16384..16383: wide
        clc
        adc     #$40
        bmi     wide
        lda     xb+1
        clc
        adc     #$40
        bmi     wide
        ; y0 = R8_ROW_OF(ay): 2048 past 32760, else floor((ay + 7) / 16)
        lda     ya
        cmp     #<32761
        lda     ya+1
        sbc     #>32761
        bvc     :+
        eor     #$80
:       bmi     @fl
        lda     #$00
        sta     y0
        lda     #$08
        sta     y0+1
        bne     @s0
@fl:    clc
        lda     ya
        adc     #7
        sta     y0
        lda     ya+1
        adc     #0
        ldx     #4
:       cmp     #$80
        ror     a
        ror     y0
        dex
        bne     :-
        sta     y0+1
@s0:    lda     y0              ; s0 = (y0 * 16 + 8 - ay) & 255
        asl     a
        asl     a
        asl     a
        asl     a
        clc
        adc     #8
        sec
        sbc     ya
        sta     s0
        ldx     #0
        sec                     ; dx = b[0] - a[0] (no overflow: both in range)
        lda     xb
        sbc     xa
        sta     dq
        lda     xb+1
        sbc     xa+1
        sta     dq+1
        bpl     :+              ; dx < 0: |dx| - 1 = ~dx
        dex
        eor     #$FF
        sta     dq+1
        lda     dq
        eor     #$FF
        sta     dq
:       stx     neg
        ; dq / dy by restoring division: dq's bits shift out into rd at
        ; the top, the quotient's shift in at the bottom
        lda     #0
        sta     rd
        sta     rd+1
        ldx     #5              ; bits 15..11: rd < 2^4, no subtraction yet
:       asl     dq
        rol     dq+1
        rol     rd
        dex
        bne     :-
        lda     rd              ; dq >> 11 >= dy: a quotient of 2048 or more
        cmp     dy
        lda     #0
        sbc     dy+1
        bcc     :+
        jmp     wide
:       ldx     #11
@div:   asl     dq
        rol     dq+1
        rol     rd
        rol     rd+1
        lda     rd
        sec
        sbc     dy
        tay
        lda     rd+1
        sbc     dy+1
        bcc     :+
        sta     rd+1
        sty     rd
        inc     dq              ; (bit 0 is 0 after the shift)
:       dex
        bne     @div
        bit     neg             ; dx < 0: q = -q - 1, rd = dy - 1 - rd
        bpl     @pos
        lda     dq
        eor     #$FF
        sta     dq
        lda     dq+1
        eor     #$FF
        sta     dq+1
        clc                     ; dy + ~rd = dy - 1 - rd
        lda     rd
        eor     #$FF
        adc     dy
        sta     rd
        lda     rd+1
        eor     #$FF
        adc     dy+1
        sta     rd+1
        lda     dq              ; q = -2048 (the quotient 2047): wide
        bne     @pos
        lda     dq+1
        cmp     #$F8
        bne     @pos
        jmp     wide
        ; p = ((ax - 8) & 15) + s0 q (the low 16 bits)
@pos:   lda     s0
        SETX
        ldy     dq
        MUL8
        stx     p
        sta     p+1
        ldy     dq+1
        MUL8
        txa
        clc
        adc     p+1
        sta     p+1
        lda     xa
        sec
        sbc     #8
        and     #15
        clc
        adc     p
        sta     p
        bcc     :+
        inc     p+1
        ; val = floor((ax - 8) / 16) + floor(p / 16)
:       sec
        lda     xa
        sbc     #8
        sta     val
        lda     xa+1
        sbc     #0
        ldx     #4
:       cmp     #$80
        ror     a
        ror     val
        dex
        bne     :-
        sta     val+1
        lda     p
        sta     u
        lda     p+1
        ldx     #4
:       cmp     #$80
        ror     a
        ror     u
        dex
        bne     :-
        tax
        clc
        lda     val
        adc     u
        sta     val
        txa
        adc     val+1
        sta     val+1
        lda     dy              ; d16 = dy * 16 (< 2^15)
        sta     d16
        lda     dy+1
        asl     d16
        rol     a
        asl     d16
        rol     a
        asl     d16
        rol     a
        asl     d16
        rol     a
        sta     d16+1
        ; u = dy pl + s0 rd + d16 - 1 (< 46 dy)
        lda     p
        and     #15
        SETX
        ldy     dy
        MUL8
        stx     u
        sta     u+1
        ldy     dy+1
        MUL8
        txa
        clc
        adc     u+1
        sta     u+1
        lda     s0
        SETX
        ldy     rd
        MUL8
        sta     pp
        txa
        clc
        adc     u
        sta     u
        lda     pp
        adc     u+1
        sta     u+1
        ldy     rd+1
        MUL8
        txa
        clc
        adc     u+1
        sta     u+1
        clc
        lda     u
        adc     d16
        sta     u
        lda     u+1
        adc     d16+1
        sta     u+1
        lda     u               ; - 1
        bne     :+
        dec     u+1
:       dec     u
@w:     lda     u               ; while u >= d16: u -= d16, val++
        cmp     d16
        lda     u+1
        sbc     d16+1
        bcc     @out
        sta     u+1
        lda     u
        sbc     d16
        sta     u
        inc     val
        bne     @w
        inc     val+1
        jmp     @w
@out:   lda     u+1             ; err = u >> 4
        lsr     a
        ror     u
        lsr     a
        ror     u
        lsr     a
        ror     u
        lsr     a
        ror     u
        sta     u+1
        ldy     #0              ; *it: val, q, err, r, den
        lda     val
        sta     (ip),y
        iny
        lda     val+1
        sta     (ip),y
        iny
        lda     dq
        sta     (ip),y
        iny
        lda     dq+1
        sta     (ip),y
        iny
        lda     u
        sta     (ip),y
        iny
        lda     u+1
        sta     (ip),y
        iny
        lda     rd
        sta     (ip),y
        iny
        lda     rd+1
        sta     (ip),y
        iny
        lda     dy
        sta     (ip),y
        iny
        lda     dy+1
        sta     (ip),y
        lda     y0
        ldx     y0+1
        rts
