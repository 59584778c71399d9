; xform_6502.s - r8k_xform (include/r8kern.h) for the 6502 (ca65, issue
; 10): a model vertex into camera space.  Built into the 6502 library
; with -DR8_ASM_XFORM (mk/targets.mk); the C89 reference is r8k_xform in
; src/kern.c, and tests/c/test_kern.c compares the two in sim65 on
; random matrices, offsets and vertices.
;
; void r8k_xform(const r8_mat3 *m, const r8_vec3l *t, const r8_s16 *v,
;                r8_vec3l *out)
;   out in A/X; v, t, m on the C stack (popped here).
; out[i] = floor((m[3i] v[0] + m[3i+1] v[1] + m[3i+2] v[2] + 512) / 1024)
;          + t[i], the sum exact in 32 bits; the products from
; ports/6502/mul_6502.s (two byte products for model coordinates in
; -128..127).

        .export         _r8k_xform
        .import         r8m_smul16
        .importzp       sp, r8m_a, r8m_b, r8m_p

        .zeropage
mp:     .res    2
tp:     .res    2
vp:     .res    2
op:     .res    2
acc:    .res    4
vv:     .res    6               ; v[0..2]
row:    .res    1               ; 0, 1, 2
mi:     .res    1               ; offset of m[3 row + j]
ti:     .res    1               ; offset of t[row], out[row]
ext:    .res    1

        .code

_r8k_xform:
        sta     op
        stx     op+1
        ldy     #5              ; the stack: v (0), t (2), m (4)
        lda     (sp),y
        sta     mp+1
        dey
        lda     (sp),y
        sta     mp
        dey
        lda     (sp),y
        sta     tp+1
        dey
        lda     (sp),y
        sta     tp
        dey
        lda     (sp),y
        sta     vp+1
        dey
        lda     (sp),y
        sta     vp
        clc
        lda     sp
        adc     #6
        sta     sp
        bcc     :+
        inc     sp+1
:       ldy     #5              ; v (flash: plain loads on the 6502)
:       lda     (vp),y
        sta     vv,y
        dey
        bpl     :-
        lda     #0
        sta     row
        sta     mi
        sta     ti
@row:   lda     #<512           ; acc = 512
        sta     acc
        lda     #>512
        sta     acc+1
        lda     #0
        sta     acc+2
        sta     acc+3
        ldx     #0              ; j * 2
@col:   stx     ext
        lda     vv,x            ; b = v[j]
        sta     r8m_b
        lda     vv+1,x
        sta     r8m_b+1
        ldy     mi              ; a = m[3 row + j]
        lda     (mp),y
        sta     r8m_a
        iny
        lda     (mp),y
        sta     r8m_a+1
        iny
        sty     mi
        jsr     r8m_smul16
        clc                     ; acc += the product
        lda     acc
        adc     r8m_p
        sta     acc
        lda     acc+1
        adc     r8m_p+1
        sta     acc+1
        lda     acc+2
        adc     r8m_p+2
        sta     acc+2
        lda     acc+3
        adc     r8m_p+3
        sta     acc+3
        ldx     ext
        inx
        inx
        cpx     #6
        bne     @col
        ; acc >> 10 (floor): bytes 1..3, two arithmetic shifts, sign byte
        lda     acc+3
        cmp     #$80            ; carry = the sign
        ror     acc+3
        ror     acc+2
        ror     acc+1
        lda     acc+3
        cmp     #$80
        ror     acc+3
        ror     acc+2
        ror     acc+1
        ldx     #0
        lda     acc+3
        bpl     :+
        dex
:       stx     ext
        ldy     ti              ; out[row] = that + t[row]
        clc
        lda     acc+1
        adc     (tp),y
        sta     (op),y
        iny
        lda     acc+2
        adc     (tp),y
        sta     (op),y
        iny
        lda     acc+3
        adc     (tp),y
        sta     (op),y
        iny
        lda     ext
        adc     (tp),y
        sta     (op),y
        iny
        sty     ti
        inc     row
        lda     row
        cmp     #3
        beq     :+
        jmp     @row
:       rts
