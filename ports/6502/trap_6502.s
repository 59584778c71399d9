; trap_6502.s - r8k_trap (include/r8kern.h) for the 6502 (ca65, issue 10):
; the rows of a trapezoid between two column DDAs into an SSD1306 page
; band.  Built into the 6502 library with -DR8_ASM_TRAP (mk/targets.mk);
; the C89 reference is r8k_trap in src/kern.c (with r8_fb_page_run,
; src/fb.c), and tests/c/test_kern.c compares the two in sim65 on random
; trapezoids, patterns and widths.
;
; void r8k_trap(r8_trapfill *t, r8_interp *l, r8_interp *r, r8_u16 rows)
;   rows in A/X; r, l, t on the C stack (popped here).
; The result of the reference: on each row the span [max(l, 0), min(r,
; w)) gets (byte & ~m) | (m if bit 3 - (x & 3) of pat[k]); then both
; DDAs step, k = (k + 1) & 3, m <<= 1 (at 0: m = 1, page += w).
; Done a page byte at a time: the rows of the trapezoid that share a
; page (up to 8) are stepped first, then the columns all of them cover
; get one read-modify-write for all their bits (a plain store when all
; 8 bits are rows of it), and only each row's ragged ends are done row
; by row.  The rows' bits of column x come from colbyte[x & 3]: bit b
; set when pattern row (K + b) & 3 has bit 3 - (x & 3), K the phase of
; bit 0 (the same on every page: 8 rows are two dither periods).
; A fill: ~24 cycles a byte (~16 for a whole page byte); spans longer
; than 252 columns go in pieces (any width).

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
I_ERR   = 4

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
k:      .res    1
nm:     .res    1               ; a fill: ~mask
l0:     .res    4               ; a fill: colbyte[j] & mask
colb:   .res    4               ; colbyte[0..3]
bp:     .res    2               ; a fill: page + (x0 & ~3)
cnt:    .res    2               ; a fill: columns from bp to x1
e:      .res    1               ; a piece's end (y)
x0:     .res    2               ; a fill's columns [x0, x1)
x1:     .res    2
aa:     .res    2               ; the group's max left, min right
bb:     .res    2
g:      .res    1               ; rows in the group
gi:     .res    1               ; one of them
gm:     .res    1               ; their bits

        .bss
xll:    .res    8               ; the group's rows: clamped left, right
xlh:    .res    8
xrl:    .res    8
xrh:    .res    8
mb:     .res    8               ; and bits

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
:       ldy     #T_PAGE         ; t and the edges into zero page
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
        ; colbyte[j], bit b: bit 3 - j of pat[(K + b) & 3], K = k - bitpos(m);
        ; bits 4..7 repeat bits 0..3 (the same pattern rows)
        lda     m               ; K: k, less one per bit below m
        ldx     k
:       lsr     a
        beq     :+
        dex
        jmp     :-
:       txa
        clc
        adc     #3              ; b = 3 down to 0: pattern row (K + b) & 3
        sta     e
        ldx     #4
@cb:    lda     e
        and     #3
        clc
        adc     #T_PAT
        tay
        lda     (tp),y          ; its bit 0 -> column 3, ... bit 3 -> column 0
        lsr     a
        rol     colb+3
        lsr     a
        rol     colb+2
        lsr     a
        rol     colb+1
        lsr     a
        rol     colb
        dec     e
        dex
        bne     @cb
        ldx     #3
:       lda     colb,x          ; the nibble twice
        and     #$0F
        sta     nm
        asl     a
        asl     a
        asl     a
        asl     a
        ora     nm
        sta     colb,x
        dex
        bpl     :-

; ---- a group: the rows of this page byte
grp:    lda     rows
        ora     rows+1
        bne     :+
        jmp     done
:       ldx     #0              ; g = min(rows, bits from m to bit 7)
        lda     m
:       inx
        asl     a
        bne     :-
        stx     g
        lda     rows+1
        bne     :+
        cpx     rows
        bcc     :+
        lda     rows
        sta     g
:       sec                     ; rows -= g
        lda     rows
        sbc     g
        sta     rows
        bcs     :+
        dec     rows+1
:       lda     #0
        sta     gm
        ldx     #0
        ; row x: its clamped span, its bit; then the DDAs step
@row:   lda     lv+1            ; xl = max(lv, 0)
        bpl     :+
        lda     #0
        sta     xll,x
        sta     xlh,x
        beq     @xr
:       sta     xlh,x
        lda     lv
        sta     xll,x
@xr:    lda     rv              ; xr = min(rv, w)
        cmp     w
        lda     rv+1
        sbc     w+1
        bvc     :+
        eor     #$80
:       bmi     :+
        lda     w
        sta     xrl,x
        lda     w+1
        sta     xrh,x
        jmp     @bit
:       lda     rv
        sta     xrl,x
        lda     rv+1
        sta     xrh,x
@bit:   lda     m
        sta     mb,x
        ora     gm
        sta     gm
        asl     m
        clc                     ; val += q; err += r; if err >= den: err -= den, val++
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
        tay
        lda     le+1
        adc     lr+1
        sta     le+1
        cpy     ld
        sbc     ld+1
        bcc     :+
        sta     le+1            ; (carry set: no borrow in)
        tya
        sbc     ld
        sta     le
        inc     lv
        bne     :+
        inc     lv+1
:       clc
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
        tay
        lda     re+1
        adc     rr+1
        sta     re+1
        cpy     rd
        sbc     rd+1
        bcc     :+
        sta     re+1
        tya
        sbc     rd
        sta     re
        inc     rv
        bne     :+
        inc     rv+1
:       inx
        cpx     g
        beq     :+
        jmp     @row
:       lda     k               ; k += g
        clc
        adc     g
        and     #3
        sta     k
        ; aa = max left, bb = min right (signed)
        lda     xll
        sta     aa
        lda     xlh
        sta     aa+1
        lda     xrl
        sta     bb
        lda     xrh
        sta     bb+1
        ldx     g
        dex
        beq     @ab
@mx:    lda     aa              ; xl[x] > aa?
        cmp     xll,x
        lda     aa+1
        sbc     xlh,x
        bvc     :+
        eor     #$80
:       bpl     :+
        lda     xll,x
        sta     aa
        lda     xlh,x
        sta     aa+1
:       lda     xrl,x           ; xr[x] < bb?
        cmp     bb
        lda     xrh,x
        sbc     bb+1
        bvc     :+
        eor     #$80
:       bpl     :+
        lda     xrl,x
        sta     bb
        lda     xrh,x
        sta     bb+1
:       dex
        bne     @mx
@ab:    lda     aa              ; interior: aa < bb?
        cmp     bb
        lda     aa+1
        sbc     bb+1
        bvc     :+
        eor     #$80
:       bmi     @inner
        ; none: each row whole
        ldx     #0
@whole: stx     gi
        jsr     rowspan         ; x0, x1 = the row's span
        jsr     fill1
        ldx     gi
        inx
        cpx     g
        bne     @whole
        jmp     @next
@inner: lda     aa              ; the columns all the rows cover
        sta     x0
        lda     aa+1
        sta     x0+1
        lda     bb
        sta     x1
        lda     bb+1
        sta     x1+1
        lda     gm
        jsr     fill
        ldx     #0              ; each row's ragged ends
@rag:   stx     gi
        jsr     rowspan
        lda     aa              ; left: [xl, min(xr, aa)) = [xl, aa) (xr > aa)
        sta     x1
        lda     aa+1
        sta     x1+1
        ldx     gi
        lda     mb,x
        jsr     fill
        ldx     gi
        lda     bb              ; right: [max(xl, bb), xr) = [bb, xr)
        sta     x0
        lda     bb+1
        sta     x0+1
        lda     xrl,x
        sta     x1
        lda     xrh,x
        sta     x1+1
        lda     mb,x
        jsr     fill
        ldx     gi
        inx
        cpx     g
        bne     @rag
@next:  lda     m               ; the next page
        bne     :+
        inc     m
        clc
        lda     page
        adc     w
        sta     page
        lda     page+1
        adc     w+1
        sta     page+1
:       jmp     grp

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

; x0, x1 = row X's clamped span (X kept)
rowspan:
        lda     xll,x
        sta     x0
        lda     xlh,x
        sta     x0+1
        lda     xrl,x
        sta     x1
        lda     xrh,x
        sta     x1+1
        rts

; fill1: row X's span with its bit
fill1:  lda     mb,x
; fill [x0, x1) (nothing unless x0 < x1, signed) with the bits in A:
; (byte & ~A) | (colbyte[x & 3] & A)
fill:   sta     nm              ; (the mask, for now)
        lda     x0              ; x0 < x1?
        cmp     x1
        lda     x0+1
        sbc     x1+1
        bvc     :+
        eor     #$80
:       bmi     :+
        rts
:       ldx     #3              ; l[j] = colbyte[j] & mask
:       lda     colb,x
        and     nm
        sta     l0,x
        dex
        bpl     :-
        lda     nm
        eor     #$FF
        sta     nm
        lda     x0              ; bp = page + (x0 & ~3), y = x0 & 3
        and     #$FC
        clc
        adc     page
        sta     bp
        lda     x0+1
        adc     page+1
        sta     bp+1
        lda     x0
        and     #$FC
        sta     cnt
        sec                     ; cnt = x1 - (x0 & ~3)
        lda     x1
        sbc     cnt
        sta     cnt
        lda     x1+1
        sbc     x0+1
        sta     cnt+1
        lda     x0
        and     #3
        tay
@piece: lda     cnt+1           ; pieces of at most 252 columns
        bne     @long
        lda     cnt
        cmp     #253
        bcc     @last
@long:  lda     #252
        sta     e
        jsr     run
        clc
        lda     bp
        adc     #252
        sta     bp
        bcc     :+
        inc     bp+1
:       sec
        lda     cnt
        sbc     #252
        sta     cnt
        bcs     :+
        dec     cnt+1
:       ldy     #0
        lda     cnt+1
        bmi     @end
        ora     cnt
        beq     @end
        jmp     @piece
@last:  sta     e
        jmp     run
@end:   rts

; columns y .. e-1 of bp (e <= 252): (byte & nm) | l[y & 3]; nm = 0
; (all 8 bits): plain stores
run:    lda     nm
        beq     srun
        tya
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
srun:   tya
        and     #3
        beq     s0
        cmp     #2
        bcc     s1
        beq     s2
        bcs     s3
s0:     cpy     e
        beq     rdone
        lda     l0
        sta     (bp),y
        iny
s1:     cpy     e
        beq     rdone
        lda     l0+1
        sta     (bp),y
        iny
s2:     cpy     e
        beq     rdone
        lda     l0+2
        sta     (bp),y
        iny
s3:     cpy     e
        beq     rdone
        lda     l0+3
        sta     (bp),y
        iny
        bne     s0
        rts
