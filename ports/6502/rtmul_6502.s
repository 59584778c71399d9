; rtmul_6502.s - cc65's runtime multiplies (int and long `*` in C) from
; the quarter-square tables of mul_6502.s (ca65, issue 10).
;
; cc65 compiles a * b on ints to tosmulax / tosumulax and on longs to
; tosmuleax / tosumuleax / tosmul0ax / tosumul0ax (its sim6502.lib:
; shift-and-add, ~200-700 and ~1100 cycles).  This module defines the
; same entry points with the same contract, so the 6502 library (linked
; before sim6502.lib) replaces them: every C multiply of the library and
; of the application gets them, with no source change.  The C89
; reference is the language's own `*`: tests/c/test_mul.c compares it
; with a model built from 8-bit products on random and extreme operands.
;   tosmulax:  TOS (2 bytes, popped) * A/X -> A/X (the low 16 bits);
;              three byte products, ~110 cycles
;   tosmuleax: TOS (4 bytes, popped) * A/X/sreg -> A/X/sreg (the low 32
;              bits); operands that fit 16 bits (both unsigned, or both
;              signed) take r8m_umul16 / r8m_smul16, others ten byte
;              products (~500 cycles)
;   tosmul0ax: the same with A/X zero-extended
; cc65's code generator takes these to change every register (codeinfo).

        .export         tosmulax, tosumulax
        .export         tosmuleax, tosumuleax, tosmul0ax, tosumul0ax
        .import         r8m_smul16, r8m_umul16
        .importzp       sp, sreg, r8m_a, r8m_b, r8m_p, sq1l, sq1h, sq2l, sq2h

        .zeropage
a23:    .res    2               ; long operands: bytes 2, 3 (0, 1 in r8m_a/b)
b23:    .res    2

        .code

.macro  SETX
        sta     sq1l
        sta     sq1h
        eor     #$FF
        sta     sq2l
        sta     sq2h
.endmacro

; x * Y: the low byte in X, the high byte in A
.macro  MUL8
        sec
        lda     (sq1l),y
        sbc     (sq2l),y
        tax
        lda     (sq1h),y
        sbc     (sq2h),y
.endmacro

; the low byte of x * Y in A
.macro  MULLO
        sec
        lda     (sq1l),y
        sbc     (sq2l),y
.endmacro

; ---- int: TOS * A/X, the low 16 bits
tosmulax:
tosumulax:
        sta     r8m_b
        stx     r8m_b+1
        ldy     #1
        lda     (sp),y
        sta     r8m_a+1
        dey
        lda     (sp),y
        sta     r8m_a
        clc                     ; pop 2
        lda     sp
        adc     #2
        sta     sp
        bcc     :+
        inc     sp+1
:       lda     r8m_a           ; x = a low
        SETX
        ldy     r8m_b
        MUL8                    ; aL * bL
        stx     r8m_p
        sta     r8m_p+1
        ldy     r8m_b+1
        beq     :+
        MULLO                   ; (aL * bH) low
        clc
        adc     r8m_p+1
        sta     r8m_p+1
:       lda     r8m_a+1
        beq     :+
        SETX                    ; x = a high
        ldy     r8m_b
        MULLO                   ; (aH * bL) low
        clc
        adc     r8m_p+1
        sta     r8m_p+1
:       lda     r8m_p
        ldx     r8m_p+1
        rts

; ---- long: TOS * A/X/sreg, the low 32 bits
tosmul0ax:
tosumul0ax:
        ldy     #0
        sty     sreg
        sty     sreg+1
tosmuleax:
tosumuleax:
        sta     r8m_b
        stx     r8m_b+1
        lda     sreg
        sta     b23
        lda     sreg+1
        sta     b23+1
        ldy     #3
        lda     (sp),y
        sta     a23+1
        dey
        lda     (sp),y
        sta     a23
        dey
        lda     (sp),y
        sta     r8m_a+1
        dey
        lda     (sp),y
        sta     r8m_a
        clc                     ; pop 4
        lda     sp
        adc     #4
        sta     sp
        bcc     :+
        inc     sp+1
:       lda     a23             ; both unsigned 16-bit: one 16 x 16
        ora     a23+1
        ora     b23
        ora     b23+1
        bne     @sgn
        jsr     r8m_umul16
        jmp     @ret
@sgn:   ldx     #0              ; both sign-extended 16-bit: signed 16 x 16
        bit     r8m_a+1
        bpl     :+
        dex
:       cpx     a23
        bne     @gen
        cpx     a23+1
        bne     @gen
        ldx     #0
        bit     r8m_b+1
        bpl     :+
        dex
:       cpx     b23
        bne     @gen
        cpx     b23+1
        bne     @gen
        jsr     r8m_smul16
@ret:   lda     r8m_p+2
        sta     sreg
        lda     r8m_p+3
        sta     sreg+1
        lda     r8m_p
        ldx     r8m_p+1
        rts
@gen:   lda     r8m_a           ; x = a0
        SETX
        ldy     r8m_b
        MUL8                    ; a0 b0
        stx     r8m_p
        sta     r8m_p+1
        ldy     r8m_b+1
        MUL8                    ; a0 b1
        sta     r8m_p+2
        txa
        clc
        adc     r8m_p+1
        sta     r8m_p+1
        bcc     :+
        inc     r8m_p+2
:       ldy     b23
        MUL8                    ; a0 b2
        sta     r8m_p+3
        txa
        clc
        adc     r8m_p+2
        sta     r8m_p+2
        bcc     :+
        inc     r8m_p+3
:       ldy     b23+1
        MULLO                   ; a0 b3 (low)
        clc
        adc     r8m_p+3
        sta     r8m_p+3
        lda     r8m_a+1         ; x = a1
        SETX
        ldy     r8m_b
        MUL8                    ; a1 b0
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
        MUL8                    ; a1 b1
        tay
        txa
        clc
        adc     r8m_p+2
        sta     r8m_p+2
        tya
        adc     r8m_p+3
        sta     r8m_p+3
        ldy     b23
        MULLO                   ; a1 b2 (low)
        clc
        adc     r8m_p+3
        sta     r8m_p+3
        lda     a23             ; x = a2
        SETX
        ldy     r8m_b
        MUL8                    ; a2 b0
        tay
        txa
        clc
        adc     r8m_p+2
        sta     r8m_p+2
        tya
        adc     r8m_p+3
        sta     r8m_p+3
        ldy     r8m_b+1
        MULLO                   ; a2 b1 (low)
        clc
        adc     r8m_p+3
        sta     r8m_p+3
        lda     a23+1           ; x = a3
        SETX
        ldy     r8m_b
        MULLO                   ; a3 b0 (low)
        clc
        adc     r8m_p+3
        sta     r8m_p+3
        jmp     @ret
