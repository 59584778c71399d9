; wirec_6502.s - the C entries of wire_6502.s's RLE kernels (src/r8crc.h:
; r8_tx_zeros, r8_tx_run, r8_tx_lit), for src/wire.c's C band path.  A
; module of their own: a firmware built with -DR8_TXBAND_ALL
; (mk/targets.mk FWK_6502) has no C band path, calls none of them, and
; gc65 (which keeps a hand-written module whole once anything in it is
; needed) then leaves this out; txband_6502.s calls txrun and txlit
; directly.  tests/c/test_wirek.c compares them with the C in sim65.

        .export         _r8_tx_zeros, _r8_tx_run, _r8_tx_lit
        .import         txrun, txlit
        .importzp       sp, ptr, optr, sptr, kk, cnt, nlo, nhi

        .code

; pop N bytes of arguments off the C stack
.macro  POPN    n
        clc
        lda     sp
        adc     #n
        sta     sp
        bcc     :+
        inc     sp+1
:
.endmacro

; unsigned r8_tx_zeros(const r8_u8 *p, unsigned n): the 0x00 bytes of
; p[0..n) before the first other.  n in A/X, p at (sp)+0.  ~13 cycles a
; byte.
_r8_tx_zeros:
        sta     nlo
        stx     nhi
        ldy     #1
        lda     (sp),y
        sta     ptr+1
        dey
        lda     (sp),y
        sta     ptr
        POPN    2
        ldx     #0              ; whole pages counted
        ldy     #0
@pg:    cpx     nhi
        beq     @part
@full:  lda     (ptr),y
        bne     @found
        iny
        bne     @full
        inc     ptr+1
        inx
        jmp     @pg
@part:  cpy     nlo
        beq     @found
@lp:    lda     (ptr),y
        bne     @found
        iny
        cpy     nlo
        bne     @lp
@found: tya                     ; X pages + Y
        rts

; load s, o, p from the C stack: p at (sp)+off, o at +2, s at +4
.macro  ARGS3   off
        ldy     #off+5
        lda     (sp),y
        sta     sptr+1
        dey
        lda     (sp),y
        sta     sptr
        dey
        lda     (sp),y
        sta     optr+1
        dey
        lda     (sp),y
        sta     optr
        dey
        lda     (sp),y
        sta     ptr+1
        dey
        lda     (sp),y
        sta     ptr
.endmacro

; r8_u8 r8_tx_run(r8_tx_st *s, r8_u8 *o, const r8_u8 *p, r8_u8 k)
;   k in A; p at (sp)+0, o +2, s +4 (wire_6502.s's txrun)
_r8_tx_run:
        sta     kk
        ARGS3   0
        POPN    6
        jmp     txrun

; r8_u8 r8_tx_lit(r8_tx_st *s, r8_u8 *o, const r8_u8 *p, r8_u8 k, r8_u8 c)
;   c in A; k at (sp)+0, p +1, o +3, s +5 (wire_6502.s's txlit)
_r8_tx_lit:
        sta     cnt
        ldy     #0
        lda     (sp),y
        sta     kk
        ARGS3   1
        POPN    7
        jmp     txlit
