;; scanx_z80.s - r8_scanx_fill (include/r8raster.h) for the Z80 (sdcc
;; 4.2, sdas; issue 10): a polygon's rows in one PAGE1 band as
;; trapezoids, without the C glue, as ports/6502/scanx_6502.s.  In the
;; Z80 archive with Z80_ASM's "scanx", which builds the library with
;; -DR8_ASM_SCANX (mk/targets.mk): src/scan.c then names its C89 version
;; r8_scanx_fill_c, the reference, and gives edge_start to this one as
;; r8_scanx_edge.  This one takes the common case: PAGE1, no Judd test
;; pending (judd == 0 or the face known front), the polygon's next row
;; inside the band or below it; every other call goes to the C version
;; untouched.  Then, as src/scan.c: the trapezoid state (the row's page
;; and bit, the dither phase and the level's four patterns), and per run
;; of rows on which no edge ends, an edge restart where one ended and
;; one r8k_trap call.
;; tests/c/test_scanx.c compares the two on random polygons in ucsim and
;; the offsets below with the C compiler's (r8_scanx_offs).
;;
;; sdcc's __sdcccall(1): s in HL, ylimit in DE, judd, fb and level on the
;; stack (popped here: 5 bytes).  IX is kept (not used).
        .module scanx_z80

        .globl  _r8_scanx_fill
        .globl  _r8_scanx_offs
        .globl  _r8_scanx_fill_c
        .globl  _r8_scanx_edge
        .globl  _r8k_trap
        .globl  _r8_fb_dither_tab

;; r8_scanx, r8_edge (include/r8raster.h), r8_fb (r8fb.h), r8_trapfill
;; (r8kern.h) on sdcc
SX_FRONT  = 0x14
SX_Y      = 0x15
SX_YBOT   = 0x17
SX_L      = 0x19
SX_R      = 0x26
E_YEND    = 0x0A
FB_BUF    = 0x00
FB_WIDTH  = 0x02
FB_Y0     = 0x06
FB_ROWS   = 0x08
FB_FORMAT = 0x0A
T_PAGE    = 0x00
T_M       = 0x02
T_K       = 0x03
T_PAT     = 0x04
T_W       = 0x08

        .area   _DATA
sx:     .ds     2               ; the r8_scanx
fbp:    .ds     2               ; the r8_fb
ylim:   .ds     2               ; the ylimit argument
lim:    .ds     2               ; the row to stop at
yy:     .ds     2               ; the next row
stp:    .ds     2               ; the end of a trapezoid
lev:    .ds     1
tf:     .ds     10              ; the r8_trapfill

        .area   _CODE
_r8_scanx_offs:
        .db     SX_FRONT, SX_Y, SX_YBOT, SX_L, SX_R, E_YEND
        .db     FB_BUF, FB_WIDTH, FB_Y0, FB_ROWS, FB_FORMAT
        .db     T_PAGE, T_M, T_K, T_PAT, T_W

;; void r8_scanx_fill(r8_scanx *s, r8_s16 ylimit, int judd, r8_fb *fb,
;;                    r8_u8 level): s HL, ylimit DE; judd at SP+2, fb +4,
;; level +6
_r8_scanx_fill:
        ld      (sx), hl
        ld      (ylim), de
        ld      iy, #0
        add     iy, sp
        ld      a, 6 (iy)
        ld      (lev), a
        ld      a, 2 (iy)       ; judd and not known front: C
        or      a, 3 (iy)
        jr      z, 1$
        ld      bc, #SX_FRONT
        add     hl, bc
        ld      a, (hl)
        or      a, a
        jr      z, slow
1$:     ld      l, 4 (iy)
        ld      h, 5 (iy)
        ld      (fbp), hl
        ld      bc, #FB_FORMAT  ; PAGE1 only (R8_FMT_PAGE1 = 0)
        add     hl, bc
        ld      a, (hl)
        or      a, a
        jr      nz, slow
        ld      hl, (sx)
        ld      bc, #SX_Y
        add     hl, bc
        ld      e, (hl)
        inc     hl
        ld      d, (hl)
        ld      (yy), de
        inc     hl
        ld      c, (hl)
        inc     hl
        ld      b, (hl)         ; BC = ybot
        ld      hl, (fbp)
        ld      de, #FB_Y0
        add     hl, de
        ld      e, (hl)
        inc     hl
        ld      d, (hl)         ; DE = y0
        inc     hl
        ld      a, (hl)
        inc     hl
        ld      h, (hl)
        ld      l, a            ; HL = rows
        add     hl, de
        ld      (stp), hl       ; y0 + rows, for now
        ld      hl, (yy)
        call    slt             ; y < y0: C
        jr      nc, fast
slow:   ld      hl, (sx)        ; the arguments are still on the stack
        ld      de, (ylim)
        jp      _r8_scanx_fill_c

fast:   ld      hl, (ylim)      ; lim = min(ylimit, ybot, y0 + rows)
        ld      d, b
        ld      e, c
        call    smin
        ld      de, (stp)
        call    smin
        ld      (lim), hl
        ex      de, hl
        ld      hl, (yy)
        call    slt
        jp      nc, done        ; nothing in this band

;; the row's page, bit and dither phase; the level's patterns
        ld      hl, (fbp)
        ld      bc, #FB_Y0
        add     hl, bc
        ld      e, (hl)
        inc     hl
        ld      d, (hl)
        ld      hl, (yy)
        or      a, a
        sbc     hl, de          ; by = y - y0 (0 <= by < rows)
        ld      a, l            ; m = 1 << (by & 7)
        and     a, #7
        ld      b, a
        ld      a, #1
        jr      z, 2$
1$:     add     a, a
        djnz    1$
2$:     ld      (tf+T_M), a
        ld      a, (yy)         ; k = y & 3
        and     a, #3
        ld      (tf+T_K), a
        srl     h               ; by >> 3: the page
        rr      l
        srl     h
        rr      l
        srl     h
        rr      l
        push    hl
        ld      hl, (fbp)       ; FB_BUF, FB_WIDTH
        ld      c, (hl)
        inc     hl
        ld      b, (hl)
        inc     hl
        ld      e, (hl)
        inc     hl
        ld      d, (hl)         ; DE = w
        ld      (tf+T_W), de
        ld      h, b
        ld      l, c            ; HL = buf
        pop     bc              ; BC = the page
3$:     ld      a, b            ; page = buf + (by >> 3) w
        or      a, c
        jr      z, 4$
        add     hl, de
        dec     bc
        jr      3$
4$:     ld      (tf+T_PAGE), hl
        ld      a, (lev)        ; the patterns of min(level, 16)
        cp      a, #17
        jr      c, 5$
        ld      a, #16
5$:     add     a, a
        add     a, a
        ld      e, a
        ld      d, #0
        ld      hl, #_r8_fb_dither_tab
        add     hl, de
        ld      de, #tf+T_PAT
        ld      bc, #4
        ldir

;; the trapezoids: restart the edges that ended, fill to the first end
loop:   ld      bc, #SX_L+E_YEND ; y >= l->yend: restart l
        call    yend
        ld      hl, (yy)
        call    slt
        jr      c, 1$
        ld      de, #SX_L
        ld      bc, #-1
        call    restart
1$:     ld      bc, #SX_R+E_YEND ; y >= r->yend: restart r
        call    yend
        ld      hl, (yy)
        call    slt
        jr      c, 2$
        ld      de, #SX_R
        ld      bc, #1
        call    restart
2$:     ld      bc, #SX_L+E_YEND ; stop = min(lim, l->yend, r->yend)
        call    yend
        ld      hl, (lim)
        call    smin
        push    hl
        ld      bc, #SX_R+E_YEND
        call    yend
        pop     hl
        call    smin
        ld      (stp), hl
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
        call    slt
        jp      c, loop
        ld      hl, (sx)        ; s->y = y
        ld      bc, #SX_Y
        add     hl, bc
        ld      de, (yy)
        ld      (hl), e
        inc     hl
        ld      (hl), d
done:   pop     hl              ; the return address; judd, fb, level
        pop     bc
        pop     bc
        inc     sp
        jp      (hl)

;; DE = the r8_s16 at s + BC (HL changed)
yend:   ld      hl, (sx)
        add     hl, bc
        ld      e, (hl)
        inc     hl
        ld      d, (hl)
        ret

;; r8_scanx_edge(s, s + DE, dir = BC, y)
restart:
        ld      hl, (yy)
        push    hl
        push    bc
        ld      hl, (sx)
        add     hl, de
        ex      de, hl
        ld      hl, (sx)
        call    _r8_scanx_edge  ; (pops dir, y)
        ret

;; carry set when HL < DE (signed); HL, DE kept, A changed
slt:    ld      a, h
        xor     a, d
        jp      m, 1$
        ld      a, l            ; the same signs: unsigned
        sub     a, e
        ld      a, h
        sbc     a, d
        ret
1$:     ld      a, h            ; different signs: HL < DE if HL < 0
        rla
        ret

;; HL = min(HL, DE) (signed); DE the other
smin:   call    slt
        ret     c
        ex      de, hl
        ret
