;; scanband_z80.s - r8k_scanband (src/r8scan.h) for the Z80 (sdcc 4.2,
;; sdas; issue 10): a face's page-1 band once Judd's test has decided,
;; s->y in [fb->y0, lim): the trapezoid state for row s->y (page, bit,
;; dither phase, the level's four patterns), then per run of rows on
;; which no edge ends an edge restart (r8k_estart) where one ended and
;; one r8k_trap call; s->y = lim.  The AVR's ports/avr/trap.S does the
;; same.  In the Z80 archive with Z80_ASM's "scanband", which builds with
;; -DR8_ASM_SCANFILL (mk/targets.mk): src/scanband.c's C89 reference is
;; then left out, and src/render.c's draw_face hands a mesh face's band
;; straight to this one (R8_BANDK, with face_begin) instead of going
;; through r8_scanx_begin and r8_scanx_fill.
;; tests/targets/test_z80_kern.c (step xkern-z80) compares it with the
;; reference on random polygons and bands.
;;
;; sdcc's __sdcccall(1): s in HL, fb in DE, lim and level on the stack
;; (popped here: 3 bytes).  IX is kept (not used).
        .module scanband_z80

        .globl  _r8k_scanband
        .globl  _r8k_estart
        .globl  _r8k_trap
        .globl  _r8_fb_dither_tab

;; r8_scanx, r8_edge (include/r8raster.h), r8_fb (r8fb.h), r8_trapfill
;; (r8kern.h) on sdcc (the AVR's offsets: src/scanband.c asserts them)
SX_Y      = 0x15
SX_L      = 0x19
SX_R      = 0x26
E_YEND    = 0x0A
E_VI      = 0x0C
FB_BUF    = 0x00
FB_WIDTH  = 0x02
FB_Y0     = 0x06
T_PAGE    = 0x00
T_M       = 0x02
T_K       = 0x03
T_PAT     = 0x04
T_W       = 0x08

        .area   _DATA
sx:     .ds     2               ; the r8_scanx
lim:    .ds     2               ; the row to stop at
yy:     .ds     2               ; the next row
stp:    .ds     2               ; the end of a trapezoid
tf:     .ds     10              ; the r8_trapfill

        .area   _CODE
;; void r8k_scanband(r8_scanx *s, const r8_fb *fb, r8_s16 lim,
;;                   r8_u8 level): s HL, fb DE; lim at SP+2, level +4
_r8k_scanband:
        ld      (sx), hl
        pop     bc              ; the return address
        pop     hl
        ld      (lim), hl
        dec     sp
        pop     af              ; A = level (F: lim's high byte)
        push    bc              ; (a plain ret from here on)
        cp      a, #17          ; the patterns of min(level, 16)
        jr      c, 1$
        ld      a, #16
1$:     add     a, a
        add     a, a
        ld      c, a
        ld      b, #0
        ld      hl, #_r8_fb_dither_tab
        add     hl, bc
        push    de              ; fb
        ld      de, #tf+T_PAT
        ldi
        ldi
        ldi
        ldi
        pop     hl              ; fb
        ld      c, (hl)         ; BC = buf
        inc     hl
        ld      b, (hl)
        inc     hl
        ld      e, (hl)         ; DE = w
        inc     hl
        ld      d, (hl)
        ld      (tf+T_W), de
        ld      a, #FB_Y0-FB_WIDTH-1
        add     a, l
        ld      l, a
        adc     a, h
        sub     a, l
        ld      h, a            ; HL = &fb->y0
        push    bc              ; buf
        ld      c, (hl)
        inc     hl
        ld      b, (hl)         ; BC = y0
        ld      hl, (sx)
        ld      a, #SX_Y
        add     a, l
        ld      l, a
        adc     a, h
        sub     a, l
        ld      h, a
        ld      a, (hl)
        inc     hl
        ld      h, (hl)
        ld      l, a            ; HL = y
        ld      (yy), hl
        and     a, #3           ; k = y & 3
        ld      (tf+T_K), a
        or      a, a
        sbc     hl, bc          ; by = y - y0 (0 <= by < rows)
        ld      a, l            ; m = 1 << (by & 7)
        and     a, #7
        ld      b, a
        ld      a, #1
        jr      z, 3$
2$:     add     a, a
        djnz    2$
3$:     ld      (tf+T_M), a
        srl     h               ; by >> 3: the page
        rr      l
        srl     h
        rr      l
        srl     h
        rr      l
        ld      b, h
        ld      c, l            ; BC = the page
        pop     hl              ; HL = buf
4$:     ld      a, b            ; page = buf + (by >> 3) w
        or      a, c
        jr      z, 5$
        add     hl, de
        dec     bc
        jr      4$
5$:     ld      (tf+T_PAGE), hl

;; the trapezoids: restart the edges that ended, fill to the first end.
;; Rows are within +-2048 (R8_ROW_OF of a 12.4 coordinate; y >= 0), so a
;; 16-bit difference never overflows and its sign orders two rows.
loop:   ld      de, #SX_L       ; y >= l->yend: restart l
        call    edge
        ld      (stp), hl       ; stop = l->yend (for now)
        ld      de, #SX_R       ; y >= r->yend: restart r
        call    edge
        ld      de, (stp)       ; stop = min(l->yend, r->yend, lim)
        or      a, a
        sbc     hl, de
        add     hl, de          ; (S kept)
        jp      m, 1$
        ex      de, hl
1$:     ld      de, (lim)
        or      a, a
        sbc     hl, de
        add     hl, de
        jp      m, 2$
        ex      de, hl
2$:     ld      (stp), hl
        ld      de, (yy)        ; r8k_trap(&t, &l->x, &r->x, stop - y)
        or      a, a
        sbc     hl, de
        push    hl
        ld      hl, (sx)
        ld      bc, #SX_R
        add     hl, bc
        push    hl
        ld      hl, (sx)
        ld      bc, #SX_L
        add     hl, bc
        ex      de, hl
        ld      hl, #tf
        call    _r8k_trap       ; (pops r, rows)
        ld      hl, (stp)       ; y = stop
        ld      (yy), hl
        ld      de, (lim)
        or      a, a
        sbc     hl, de
        jp      m, loop         ; y < lim: on
        ld      hl, (sx)        ; s->y = y
        ld      bc, #SX_Y
        add     hl, bc
        ld      de, (yy)
        ld      (hl), e
        inc     hl
        ld      (hl), d
        ret

;; edge s + DE: if y >= its yend, r8k_estart(s, e, y, e->vi); HL = its
;; yend (after the restart)
edge:   ld      hl, (sx)
        add     hl, de
        push    hl              ; e
        ld      de, #E_YEND
        add     hl, de
        ld      e, (hl)
        inc     hl
        ld      d, (hl)         ; DE = yend
        inc     hl
        ld      c, (hl)         ; C = vi
        ld      hl, (yy)
        or      a, a
        sbc     hl, de
        jp      p, 1$           ; y >= yend: restart
        pop     hl              ; (e)
        ex      de, hl          ; HL = yend
        ret
1$:     pop     de              ; DE = e
        push    de
        ld      a, c
        push    af              ; from
        inc     sp
        ld      hl, (yy)        ; y
        push    hl
        ld      hl, (sx)
        call    _r8k_estart     ; (pops y, from)
        pop     hl              ; e
        ld      bc, #E_YEND
        add     hl, bc
        ld      a, (hl)
        inc     hl
        ld      h, (hl)
        ld      l, a
        ret
