; fill_6502.s - r8k_fill (include/r8kern.h) for the 6502 (ca65, issue
; 10): the band and depth clears.  Built into the 6502 library with
; -DR8_ASM_FILL (mk/targets.mk): src/kern.c then leaves out its C89
; version (memset), the reference, which tests/c/test_kern.c compares
; with this one in sim65 (lengths 0..300 at random offsets, the bytes
; around kept).  Whole pages 8 stores a turn upwards, the rest 8 a turn
; downwards: ~8.4 cycles a byte (cc65's memset behind the C call: ~11).

        .export         _r8k_fill
        .importzp       sp, ptr1

        .zeropage
nlo:    .res    1
val:    .res    1

        .code

; void r8k_fill(r8_u8 *p, r8_u8 v, unsigned n): n in A/X, v at (sp)+0,
; p at (sp)+1
_r8k_fill:
        sta     nlo
        ldy     #0
        lda     (sp),y
        sta     val
        iny
        lda     (sp),y
        sta     ptr1
        iny
        lda     (sp),y
        sta     ptr1+1
        clc                     ; pop p and v
        lda     sp
        adc     #3
        sta     sp
        bcc     :+
        inc     sp+1
:       lda     val
        cpx     #0              ; X: whole pages
        beq     @part
        ldy     #0
@pg:    sta     (ptr1),y
        iny
        sta     (ptr1),y
        iny
        sta     (ptr1),y
        iny
        sta     (ptr1),y
        iny
        sta     (ptr1),y
        iny
        sta     (ptr1),y
        iny
        sta     (ptr1),y
        iny
        sta     (ptr1),y
        iny
        bne     @pg
        inc     ptr1+1
        dex
        bne     @pg
@part:  ldy     nlo             ; p[0 .. nlo) from the top down
        beq     @done
        lda     nlo
        and     #7
        tax
        lda     val
        cpx     #0
        beq     @g
@s:     dey                     ; nlo & 7 one at a time
        sta     (ptr1),y
        dex
        bne     @s
        cpy     #0
        beq     @done
@g:     dey                     ; then 8 a turn (Y a multiple of 8)
        sta     (ptr1),y
        dey
        sta     (ptr1),y
        dey
        sta     (ptr1),y
        dey
        sta     (ptr1),y
        dey
        sta     (ptr1),y
        dey
        sta     (ptr1),y
        dey
        sta     (ptr1),y
        dey
        sta     (ptr1),y
        bne     @g
@done:  rts
