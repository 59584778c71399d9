; trap_6502.s - r8k_trap (include/r8kern.h) for the 6502 (ca65, issue 10):
; the rows of a trapezoid between two column DDAs into an SSD1306 page
; band.  Built into the 6502 library with -DR8_ASM_TRAP (mk/targets.mk);
; the C89 reference is r8k_trap in src/kern.c (with r8_fb_page_run,
; src/fb.c), and tests/c/test_kern.c compares the two in sim65 on random
; trapezoids, patterns and widths.
;
; void r8k_trap(r8_trapfill *t, r8_interp *l, r8_interp *r, r8_u16 rows)
;   rows in A/X; r, l, t on the C stack (popped here).
; Per row: the span [max(l, 0), min(r, w)) gets (byte & ~m) | (m if bit
; 3 - (x & 3) of pat[k]); four columns per loop pass, ~24 cycles a byte.
; Then both DDAs step, k = (k + 1) & 3, m <<= 1 (at 0: m = 1, page += w).
; Spans longer than 252 columns go in pieces (any width).

        .export         _r8k_trap
        .importzp       sp

; r8_trapfill: page +0, m +2, k +3, pat[4] +4, w +8
T_PAGE  = 0
T_M     = 2
T_K     = 3
T_PAT   = 4
T_W     = 8
; r8_interp: val +0, q +2, err +4, r +6, den +8
I_VAL   = 0
I_Q     = 2
I_ERR   = 4
I_R     = 6
I_DEN   = 8

        .zeropage
tp:     .res    2               ; t
lp:     .res    2               ; l
rp:     .res    2               ; r
rows:   .res    2
page:   .res    2
w:      .res    2
lv:     .res    2               ; left edge: val, q, err, r, den
lq:     .res    2
le:     .res    2
lr:     .res    2
ld:     .res    2
rv:     .res    2               ; right edge
rq:     .res    2
re:     .res    2
rr:     .res    2
rd:     .res    2
m:      .res    1
nm:     .res    1
k:      .res    1
l0:     .res    4               ; the row's byte for columns x & 3 = 0..3
bp:     .res    2               ; page + (xl & ~3)
sp4:    .res    2               ; columns from bp to xr (16 bits)
e:      .res    1               ; this piece's end (y)

        .code

_r8k_trap:
        sta     rows
        stx     rows+1
        ldy     #5              ; the stack: r (0), l (2), t (4)
        lda     (sp),y
        sta     tp+1
        dey
        lda     (sp),y
        sta     tp
        dey
        lda     (sp),y
        sta     lp+1
        dey
        lda     (sp),y
        sta     lp
        dey
        lda     (sp),y
        sta     rp+1
        dey
        lda     (sp),y
        sta     rp
        clc                     ; pop 6 bytes
        lda     sp
        adc     #6
        sta     sp
        bcc     :+
        inc     sp+1
:
        ; t and the edges into zero page
        ldy     #T_PAGE
        lda     (tp),y
        sta     page
        iny
        lda     (tp),y
        sta     page+1
        ldy     #T_M
        lda     (tp),y
        sta     m
        iny                     ; T_K
        lda     (tp),y
        sta     k
        ldy     #T_W
        lda     (tp),y
        sta     w
        iny
        lda     (tp),y
        sta     w+1
        ldy     #9
:       lda     (lp),y
        sta     lv,y
        lda     (rp),y
        sta     rv,y
        dey
        bpl     :-

row:    lda     rows            ; while (rows--)
        bne     :+
        lda     rows+1
        bne     :++
        jmp     done
:       dec     rows
        jmp     span
:       dec     rows+1
        dec     rows

        ; xl = max(lv, 0) & ~3 -> bp = page + that; y = xl & 3
span:   lda     lv+1
        bpl     :+
        lda     #0              ; lv < 0: xl = 0
        tay
        tax
        beq     @xl
:       lda     lv
        and     #3
        tay                     ; y = xl & 3
        lda     lv
        and     #$FC
        ldx     lv+1
@xl:    sta     bp              ; xl & ~3 in A (low), X (high)
        stx     bp+1
        ; xr = min(rv, w): sp4 = xr - (xl & ~3)
        lda     rv              ; rv < w (signed)?
        cmp     w
        lda     rv+1
        sbc     w+1
        bvc     :+
        eor     #$80
:       bmi     @rv
        sec                     ; xr = w
        lda     w
        sbc     bp
        sta     sp4
        lda     w+1
        sbc     bp+1
        sta     sp4+1
        jmp     @cnt
@rv:    sec                     ; xr = rv
        lda     rv
        sbc     bp
        sta     sp4
        lda     rv+1
        sbc     bp+1
        sta     sp4+1
@cnt:   ; empty unless xr - xlb > y (signed)
        bmi     @skip0
        bne     @fill
        cpy     sp4
        bcc     @fill
@skip0: jmp     @skip
@fill:  clc                     ; bp = page + (xl & ~3)
        lda     bp
        adc     page
        sta     bp
        lda     bp+1
        adc     page+1
        sta     bp+1
        ; the row's four column bytes: l[j] = m if pat[k] bit 3 - j
        lda     m
        eor     #$FF
        sta     nm
        lda     k
        clc
        adc     #T_PAT
        sty     e               ; (keep y)
        tay
        lda     (tp),y          ; pat[k]
        ldy     e
        ldx     #0
        lsr     a               ; bit 0 -> column 3
        bcc     :+
        ldx     m
:       stx     l0+3
        ldx     #0
        lsr     a               ; bit 1 -> column 2
        bcc     :+
        ldx     m
:       stx     l0+2
        ldx     #0
        lsr     a               ; bit 2 -> column 1
        bcc     :+
        ldx     m
:       stx     l0+1
        ldx     #0
        lsr     a               ; bit 3 -> column 0
        bcc     :+
        ldx     m
:       stx     l0
        ; pieces of at most 252 columns from bp
@piece: lda     sp4+1
        bne     @long
        lda     sp4
        cmp     #253
        bcc     @last
@long:  lda     #252
        sta     e
        jsr     run
        clc                     ; bp += 252, 252 columns fewer
        lda     bp
        adc     #252
        sta     bp
        bcc     :+
        inc     bp+1
:       sec
        lda     sp4
        sbc     #252
        sta     sp4
        bcs     :+
        dec     sp4+1
:       ldy     #0
        lda     sp4+1
        bmi     @skip
        ora     sp4
        beq     @skip
        jmp     @piece
@last:  sta     e
        jsr     run
@skip:
        ; the DDAs: val += q; err += r; if err >= den: err -= den, val++
        clc
        lda     lv
        adc     lq
        sta     lv
        lda     lv+1
        adc     lq+1
        sta     lv+1
        clc
        lda     le
        adc     lr
        sta     le
        tax
        lda     le+1
        adc     lr+1
        sta     le+1
        cpx     ld              ; err >= den (unsigned)?
        sbc     ld+1
        bcc     @r
        sta     le+1            ; err -= den (carry set: no borrow in)
        txa
        sbc     ld
        sta     le
        inc     lv
        bne     @r
        inc     lv+1
@r:     clc
        lda     rv
        adc     rq
        sta     rv
        lda     rv+1
        adc     rq+1
        sta     rv+1
        clc
        lda     re
        adc     rr
        sta     re
        tax
        lda     re+1
        adc     rr+1
        sta     re+1
        cpx     rd
        sbc     rd+1
        bcc     @k
        sta     re+1
        txa
        sbc     rd
        sta     re
        inc     rv
        bne     @k
        inc     rv+1
@k:     lda     k               ; k = (k + 1) & 3
        clc
        adc     #1
        and     #3
        sta     k
        asl     m               ; the next row's bit, and page
        bne     :+
        inc     m
        clc
        lda     page
        adc     w
        sta     page
        lda     page+1
        adc     w+1
        sta     page+1
:       jmp     row

done:   ldy     #T_PAGE         ; write the state back
        lda     page
        sta     (tp),y
        iny
        lda     page+1
        sta     (tp),y
        ldy     #T_M
        lda     m
        sta     (tp),y
        iny
        lda     k
        sta     (tp),y
        ldy     #I_VAL
        lda     lv
        sta     (lp),y
        lda     rv
        sta     (rp),y
        iny
        lda     lv+1
        sta     (lp),y
        lda     rv+1
        sta     (rp),y
        ldy     #I_ERR
        lda     le
        sta     (lp),y
        lda     re
        sta     (rp),y
        iny
        lda     le+1
        sta     (lp),y
        lda     re+1
        sta     (rp),y
        rts

; columns y .. e-1 of bp (e <= 252): (byte & nm) | l[y & 3]
run:    tya
        and     #3
        beq     c0
        cmp     #2
        bcc     c1
        beq     c2
        bcs     c3
c0:     cpy     e
        beq     rdone
        lda     (bp),y
        and     nm
        ora     l0
        sta     (bp),y
        iny
c1:     cpy     e
        beq     rdone
        lda     (bp),y
        and     nm
        ora     l0+1
        sta     (bp),y
        iny
c2:     cpy     e
        beq     rdone
        lda     (bp),y
        and     nm
        ora     l0+2
        sta     (bp),y
        iny
c3:     cpy     e
        beq     rdone
        lda     (bp),y
        and     nm
        ora     l0+3
        sta     (bp),y
        iny
        bne     c0
rdone:  rts
