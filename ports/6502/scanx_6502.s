; scanx_6502.s - r8_scanx_fill (include/r8raster.h) for the 6502 (ca65,
; issue 10): a polygon's rows in one PAGE1 band as trapezoids, without
; the C glue.  Built into the 6502 library with -DR8_ASM_SCANX
; (mk/targets.mk): src/scan.c then names its C89 version
; r8_scanx_fill_c, the reference, and gives edge_start to this one as
; r8_scanx_edge.  This one takes the common case: PAGE1, no Judd test
; pending (judd == 0 or the face known front), the polygon's next row
; inside the band or below it; every other call goes to the C version
; untouched.  Then, as src/scan.c: the trapezoid state (the row's page
; and bit, the dither phase and the level's four patterns), and per run
; of rows on which no edge ends, an edge restart where one ended and
; one r8k_trap call.
; tests/c/test_scanx.c compares the two on random polygons in sim65 and
; the offsets below with the C compiler's (r8_scanx_offs).

        .export         _r8_scanx_fill, _r8_scanx_offs
        .import         _r8_scanx_fill_c, _r8_scanx_edge, _r8k_trap
        .import         _r8_fb_dither_tab
        .import         pushax
        .importzp       sp

; r8_scanx, r8_edge (include/r8raster.h), r8_fb (r8fb.h), r8_trapfill
; (r8kern.h) on cc65
SX_FRONT  = $14
SX_Y      = $15
SX_YBOT   = $17
SX_L      = $19
SX_R      = $26
E_YEND    = $0A
FB_BUF    = $00
FB_WIDTH  = $02
FB_Y0     = $06
FB_ROWS   = $08
FB_FORMAT = $0A
T_PAGE    = $00
T_M       = $02
T_K       = $03
T_PAT     = $04
T_W       = $08

        .rodata
_r8_scanx_offs:
        .byte   SX_FRONT, SX_Y, SX_YBOT, SX_L, SX_R, E_YEND
        .byte   FB_BUF, FB_WIDTH, FB_Y0, FB_ROWS, FB_FORMAT
        .byte   T_PAGE, T_M, T_K, T_PAT, T_W

        .zeropage
sx:     .res    2               ; the r8_scanx
fbp:    .res    2               ; the r8_fb
lim:    .res    2               ; the row to stop at
yy:     .res    2               ; the next row
stp:    .res    2               ; the end of a trapezoid
lev:    .res    1
tmp:    .res    2

        .bss
tf:     .res    10              ; the r8_trapfill

        .code

; N set when the signed 16-bit a < b (A changed)
.macro  SLT     va, vb
        lda     va
        cmp     vb
        lda     va+1
        sbc     vb+1
        bvc     :+
        eor     #$80
:
.endmacro

; void r8_scanx_fill(r8_scanx *s, r8_s16 ylimit, int judd, r8_fb *fb,
;                    r8_u8 level): level in A; fb at (sp)+0, judd +2,
; ylimit +4, s +6
_r8_scanx_fill:
        sta     lev
        ldy     #7
        lda     (sp),y
        sta     sx+1
        dey
        lda     (sp),y
        sta     sx
        dey
        lda     (sp),y
        sta     lim+1           ; ylimit, for now
        dey
        lda     (sp),y
        sta     lim
        dey
        lda     (sp),y          ; judd and not known front: C
        dey
        ora     (sp),y
        beq     :+
        ldy     #SX_FRONT
        lda     (sx),y
        beq     slow
:       ldy     #1
        lda     (sp),y
        sta     fbp+1
        dey
        lda     (sp),y
        sta     fbp
        ldy     #FB_FORMAT      ; PAGE1 only (R8_FMT_PAGE1 = 0)
        lda     (fbp),y
        bne     slow
        ldy     #SX_Y
        lda     (sx),y
        sta     yy
        iny
        lda     (sx),y
        sta     yy+1
        ldy     #FB_Y0          ; y < the band: C
        lda     yy
        cmp     (fbp),y
        iny
        lda     yy+1
        sbc     (fbp),y
        bvc     :+
        eor     #$80
:       bpl     fast
slow:   lda     lev             ; the arguments are still on the stack
        jmp     _r8_scanx_fill_c

fast:   ldy     #SX_YBOT        ; lim = min(ylimit, ybot, y0 + rows)
        lda     (sx),y
        sta     tmp
        iny
        lda     (sx),y
        sta     tmp+1
        SLT     tmp, lim
        bpl     :+
        lda     tmp
        sta     lim
        lda     tmp+1
        sta     lim+1
:       ldy     #FB_Y0
        lda     (fbp),y
        ldy     #FB_ROWS
        clc
        adc     (fbp),y
        sta     tmp
        ldy     #FB_Y0+1
        lda     (fbp),y
        ldy     #FB_ROWS+1
        adc     (fbp),y
        sta     tmp+1
        SLT     tmp, lim
        bpl     :+
        lda     tmp
        sta     lim
        lda     tmp+1
        sta     lim+1
:       SLT     yy, lim
        bmi     setup
        jmp     done            ; nothing in this band

; the row's page, bit and dither phase; the level's patterns
setup:  ldy     #FB_Y0          ; by = y - y0 (0 <= by < rows)
        sec
        lda     yy
        sbc     (fbp),y
        sta     tmp
        iny
        lda     yy+1
        sbc     (fbp),y
        sta     tmp+1
        lda     tmp             ; m = 1 << (by & 7)
        and     #7
        tax
        lda     #1
        cpx     #0
        beq     :++
:       asl     a
        dex
        bne     :-
:       sta     tf+T_M
        lda     yy              ; k = y & 3
        and     #3
        sta     tf+T_K
        ldy     #FB_WIDTH       ; w
        lda     (fbp),y
        sta     tf+T_W
        iny
        lda     (fbp),y
        sta     tf+T_W+1
        ldy     #FB_BUF         ; page = buf + (by >> 3) w
        lda     (fbp),y
        sta     tf+T_PAGE
        iny
        lda     (fbp),y
        sta     tf+T_PAGE+1
        lsr     tmp+1
        ror     tmp
        lsr     tmp+1
        ror     tmp
        lsr     tmp+1
        ror     tmp
@pg:    lda     tmp
        ora     tmp+1
        beq     @pgd
        clc
        lda     tf+T_PAGE
        adc     tf+T_W
        sta     tf+T_PAGE
        lda     tf+T_PAGE+1
        adc     tf+T_W+1
        sta     tf+T_PAGE+1
        lda     tmp
        bne     :+
        dec     tmp+1
:       dec     tmp
        jmp     @pg
@pgd:   lda     lev             ; the patterns of min(level, 16)
        cmp     #17
        bcc     :+
        lda     #16
:       asl     a
        asl     a
        tax
        lda     _r8_fb_dither_tab,x
        sta     tf+T_PAT
        lda     _r8_fb_dither_tab+1,x
        sta     tf+T_PAT+1
        lda     _r8_fb_dither_tab+2,x
        sta     tf+T_PAT+2
        lda     _r8_fb_dither_tab+3,x
        sta     tf+T_PAT+3

; the trapezoids: restart the edges that ended, fill to the first end
loop:   ldy     #SX_L+E_YEND    ; y >= l->yend: restart l
        lda     yy
        cmp     (sx),y
        iny
        lda     yy+1
        sbc     (sx),y
        bvc     :+
        eor     #$80
:       bmi     :+
        lda     #<(SX_L)
        ldx     #$FF            ; dir -1
        jsr     restart
:       ldy     #SX_R+E_YEND    ; y >= r->yend: restart r
        lda     yy
        cmp     (sx),y
        iny
        lda     yy+1
        sbc     (sx),y
        bvc     :+
        eor     #$80
:       bmi     :+
        lda     #<(SX_R)
        ldx     #$01            ; dir 1
        jsr     restart
:       lda     lim             ; stop = min(lim, l->yend, r->yend)
        sta     stp
        lda     lim+1
        sta     stp+1
        ldy     #SX_L+E_YEND
        jsr     minend
        ldy     #SX_R+E_YEND
        jsr     minend
        lda     #<tf            ; r8k_trap(&t, &l->x, &r->x, stop - y)
        ldx     #>tf
        jsr     pushax
        lda     sx
        clc
        adc     #SX_L
        pha
        lda     sx+1
        adc     #0
        tax
        pla
        jsr     pushax
        lda     sx
        clc
        adc     #SX_R
        pha
        lda     sx+1
        adc     #0
        tax
        pla
        jsr     pushax
        sec
        lda     stp
        sbc     yy
        pha
        lda     stp+1
        sbc     yy+1
        tax
        pla
        jsr     _r8k_trap
        lda     stp             ; y = stop
        sta     yy
        lda     stp+1
        sta     yy+1
        SLT     yy, lim
        bpl     :+
        jmp     loop
:       ldy     #SX_Y           ; s->y = y
        lda     yy
        sta     (sx),y
        iny
        lda     yy+1
        sta     (sx),y
done:   lda     sp              ; pop the 8 bytes of arguments
        clc
        adc     #8
        sta     sp
        bcc     :+
        inc     sp+1
:       rts

; r8_scanx_edge(s, s + A, dir = X (-1 or 1), y)
restart:
        clc
        adc     sx
        sta     tmp
        lda     sx+1
        adc     #0
        sta     tmp+1
        txa
        pha                     ; dir's low byte
        lda     sx
        ldx     sx+1
        jsr     pushax
        lda     tmp
        ldx     tmp+1
        jsr     pushax
        pla
        ldx     #0
        cmp     #1
        beq     :+
        dex                     ; -1: $FFFF
:       jsr     pushax
        lda     yy
        ldx     yy+1
        jmp     _r8_scanx_edge

; stp = min(stp, the r8_s16 at (sx),y)
minend: lda     (sx),y
        sta     tmp
        iny
        lda     (sx),y
        sta     tmp+1
        SLT     tmp, stp
        bpl     :+
        lda     tmp
        sta     stp
        lda     tmp+1
        sta     stp+1
:       rts
