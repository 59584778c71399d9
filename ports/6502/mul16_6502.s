; mul16_6502.s - r8_mul16 (r8fixed.h), the signed 16 x 16 -> 32-bit
; product, for the 6502 (ca65, issue 10), from the quarter squares of
; mul_6502.s.  Built into the 6502 library with -DR8_ASM_MUL16
; (mk/targets.mk): then r8fixed.h's R8_MUL16 calls this instead of
; cc65's 32 x 32 multiply (tosmuleax, ~1100 cycles), and src/fixed.c
; leaves out its C version, the reference (r8_s32 p = a; p *= b).
; tests/c/test_mul.c compares the two on random and extreme inputs in
; sim65.  ~110 cycles with a byte operand, ~200 otherwise, plus the call.

        .export         _r8_mul16
        .import         r8m_smul16
        .importzp       sp, sreg, r8m_a, r8m_b, r8m_p

        .code

; r8_s32 __fastcall__ r8_mul16(r8_s16 a, r8_s16 b): b in A/X, a on the
; C stack; the product in A/X/sreg.
_r8_mul16:
        sta     r8m_b
        stx     r8m_b+1
        ldy     #1
        lda     (sp),y
        sta     r8m_a+1
        dey
        lda     (sp),y
        sta     r8m_a
        jsr     r8m_smul16
        clc                     ; pop a
        lda     sp
        adc     #2
        sta     sp
        bcc     :+
        inc     sp+1
:       lda     r8m_p+2
        sta     sreg
        lda     r8m_p+3
        sta     sreg+1
        lda     r8m_p
        ldx     r8m_p+1
        rts

