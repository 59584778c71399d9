; mul_6502.s - the 6502 multiplies (ca65, issue 10) from quarter squares,
; for the other kernels: mul16_6502.s (r8_mul16, R8_ASM_MUL16),
; xform_6502.s, proj_6502.s and rtmul_6502.s (cc65's runtime multiplies).
;
; a * b = f(a + b) - f(a - b), f(x) = floor(x^2 / 4), for bytes a, b
; (a + b and a - b have the same parity, so the floors cancel).  Four
; 512-entry tables in RAM (2 KB in R8PAGE, page-aligned, see rast8.cfg),
; built before main by a constructor: sq1 = f(x), sq2 = f(x - 255), each
; as low and high bytes.  With the zero-page pointers' low bytes = a
; (sq1) and ~a (sq2), (ptr),y with y = b reads f(a + b) and f(b - a).
; An 8 x 8 product then takes ~28 cycles, the signed 16 x 16 ~190.
;
; Internal entry for the other kernels: r8m_smul16 multiplies r8m_a by
; r8m_b (signed) into r8m_p (4 bytes, little-endian); A, X, Y, r8m_a and
; r8m_b changed.  0 takes ~30 cycles; an operand in -128..127 two byte
; products (~110 cycles), any other four (~200).

        .export         r8m_smul16, r8m_umul16
        .exportzp       r8m_a, r8m_b, r8m_p, sq1l, sq1h, sq2l, sq2h
        .importzp       sp, sreg
        .constructor    r8m_init

        .zeropage
sq1l:   .res    2               ; f(x) low bytes  + a
sq1h:   .res    2               ; f(x) high bytes + a
sq2l:   .res    2               ; f(x - 255) low  + ~a
sq2h:   .res    2               ; f(x - 255) high + ~a
r8m_a:  .res    2
r8m_b:  .res    2
r8m_p:  .res    4

        .segment "R8PAGE"
tab:    .res    2048            ; sq1 lo, sq1 hi, sq2 lo, sq2 hi: 512 each
SQ1L    = tab
SQ1H    = tab + $200
SQ2L    = tab + $400
SQ2H    = tab + $600

        .code

; the table pointers' low bytes = A (sq1) and ~A (sq2)
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

r8m_smul16:
        lda     r8m_b           ; b = 0 or a = 0: 0
        ora     r8m_b+1
        beq     @zero
        lda     r8m_a
        ora     r8m_a+1
        bne     @nz
@zero:  sta     r8m_p           ; (A = 0)
        sta     r8m_p+1
        sta     r8m_p+2
        sta     r8m_p+3
        rts
@nz:    lda     r8m_b           ; b in -128..127 (its high byte = its sign)?
        asl     a
        lda     r8m_b+1
        adc     #0
        bne     :+
        jmp     small
:       lda     r8m_a           ; a in -128..127: swap, then the same
        asl     a
        lda     r8m_a+1
        adc     #0
        bne     @gen
        ldx     r8m_a
        ldy     r8m_b
        stx     r8m_b
        sty     r8m_a
        ldx     r8m_a+1
        ldy     r8m_b+1
        stx     r8m_b+1
        sty     r8m_a+1
        jmp     small
@gen:   jsr     r8m_umul16
        ; signed: a < 0 takes b off the high word, b < 0 takes a off
        bit     r8m_a+1
        bpl     :+
        sec
        lda     r8m_p+2
        sbc     r8m_b
        sta     r8m_p+2
        lda     r8m_p+3
        sbc     r8m_b+1
        sta     r8m_p+3
:       bit     r8m_b+1
        bpl     :+
        sec
        lda     r8m_p+2
        sbc     r8m_a
        sta     r8m_p+2
        lda     r8m_p+3
        sbc     r8m_a+1
        sta     r8m_p+3
:       rts

; unsigned 16 x 16: r8m_a * r8m_b -> r8m_p (4 bytes)
r8m_umul16:
        lda     r8m_a           ; x = a low
        SETX
        ldy     r8m_b
        MUL8                    ; aL * bL
        stx     r8m_p
        sta     r8m_p+1
        ldy     r8m_b+1
        MUL8                    ; aL * bH
        sta     r8m_p+2
        txa
        clc
        adc     r8m_p+1
        sta     r8m_p+1
        bcc     :+
        inc     r8m_p+2         ; (aL * bH) >> 8 <= $FE: no carry out
:       lda     #0
        sta     r8m_p+3
        lda     r8m_a+1         ; x = a high
        SETX
        ldy     r8m_b
        MUL8                    ; aH * bL
        tay
        txa
        clc
        adc     r8m_p+1
        sta     r8m_p+1
        tya
        adc     r8m_p+2
        sta     r8m_p+2
        bcc     :+
        inc     r8m_p+3
:       ldy     r8m_b+1
        MUL8                    ; aH * bH
        tay
        txa
        clc
        adc     r8m_p+2
        sta     r8m_p+2
        tya
        adc     r8m_p+3
        sta     r8m_p+3
        rts

; a (16 bits) * b (-128..127, its low byte): 2 byte products; with
; a = a_u - 2^16 [a < 0], b = b_l - 2^8 [b < 0]:
; a * b = a_u * b_l - 2^16 [a < 0] b_l - 2^8 [b < 0] a   (mod 2^32)
small:  lda     r8m_b
        SETX
        ldy     r8m_a
        MUL8                    ; aL * bL
        stx     r8m_p
        sta     r8m_p+1
        ldy     r8m_a+1
        MUL8                    ; aH * bL
        tay
        txa
        clc
        adc     r8m_p+1
        sta     r8m_p+1
        tya
        adc     #0
        sta     r8m_p+2
        lda     #0
        sta     r8m_p+3
        bit     r8m_a+1         ; a < 0: b_l off bytes 2..3
        bpl     :+
        sec
        lda     r8m_p+2
        sbc     r8m_b
        sta     r8m_p+2
        lda     #0
        sbc     #0
        sta     r8m_p+3
:       bit     r8m_b           ; b < 0: a (sign-extended) off bytes 1..3
        bpl     @done
        ldx     #0
        bit     r8m_a+1
        bpl     :+
        dex
:       sec
        lda     r8m_p+1
        sbc     r8m_a
        sta     r8m_p+1
        lda     r8m_p+2
        sbc     r8m_a+1
        sta     r8m_p+2
        stx     r8m_b           ; (the extension byte; b's low byte is done)
        lda     r8m_p+3
        sbc     r8m_b
        sta     r8m_p+3
@done:  rts

; The tables, before main: f(x + 1) = f(x) + ((x + 1) >> 1); sq1[x] =
; f(x) for x = 0..511, sq2[255 + d] = sq2[255 - d] = f(d) (d = 0..256).
        .segment "ONCE"
r8m_init:
        lda     #>SQ1L          ; the pointers' pages (constant)
        sta     sq1l+1
        lda     #>SQ1H
        sta     sq1h+1
        lda     #>SQ2L
        sta     sq2l+1
        lda     #>SQ2H
        sta     sq2h+1
        ; sq1: x in r8m_a (16 bits), f in r8m_p (16 bits), store via r8m_b
        lda     #0
        sta     r8m_a
        sta     r8m_a+1
        sta     r8m_p
        sta     r8m_p+1
@sq1:   lda     r8m_a           ; store f(x) at SQ1L + x, SQ1H + x
        sta     r8m_b
        lda     r8m_a+1
        clc
        adc     #>SQ1L
        sta     r8m_b+1
        ldy     #0
        lda     r8m_p
        sta     (r8m_b),y
        lda     r8m_b+1
        clc
        adc     #2              ; SQ1H = SQ1L + $200
        sta     r8m_b+1
        lda     r8m_p+1
        sta     (r8m_b),y
        ; sq2 for x <= 256: d = x at SQ2 + 255 + d and SQ2 + 255 - d
        lda     r8m_a+1
        beq     @d
        lda     r8m_a
        bne     @next           ; x > 256: sq1 only
@d:     clc                     ; SQ2L + 255 + x
        lda     r8m_a
        adc     #255
        sta     r8m_b
        lda     r8m_a+1
        adc     #>SQ2L
        sta     r8m_b+1
        lda     r8m_p
        sta     (r8m_b),y
        lda     r8m_b+1
        clc
        adc     #2
        sta     r8m_b+1
        lda     r8m_p+1
        sta     (r8m_b),y
        lda     r8m_a+1         ; x = 256: no 255 - x
        bne     @next
        lda     #255            ; SQ2L + 255 - x
        sec
        sbc     r8m_a
        sta     r8m_b
        lda     #>SQ2L
        sta     r8m_b+1
        lda     r8m_p
        sta     (r8m_b),y
        lda     #>SQ2H
        sta     r8m_b+1
        lda     r8m_p+1
        sta     (r8m_b),y
@next:  inc     r8m_a           ; x + 1
        bne     :+
        inc     r8m_a+1
:       lda     r8m_a+1         ; f += (x + 1) >> 1 (x + 1 now in r8m_a;
        lsr     a               ; < 256 while x + 1 < 512)
        lda     r8m_a
        ror     a
        clc
        adc     r8m_p
        sta     r8m_p
        lda     r8m_p+1
        adc     #0
        sta     r8m_p+1
        lda     r8m_a+1
        cmp     #2              ; x = 512: done
        bne     @sq1
        rts
