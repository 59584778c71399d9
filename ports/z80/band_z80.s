;; band_z80.s - r8_render_band (src/render.c) for the Z80 (sdcc 4.2,
;; sdas; issue 10), r8k_band, in the configuration the demo firmware fixes for the
;; cull method: page-1 bands of 8 rows, the fused fill alone (R8_BANDK_ONLY),
;; no painter's, depth, S-buffer, wireframe, ray or portal (render.c's
;; R8_BAND_Z80).  Clear the band (r8k_fill), then merge, in scene order,
;; the faces going on from the band above (st->first) with the band's
;; bucket, draw each (r8_band_face: render.c's draw_face), and link the
;; ones that go on into the next band's list.  In the Z80 archive with
;; Z80_ASM's "band" (-DR8_ASM_BAND); render.c then names its C89 version
;; r8_render_band_c (the reference, what every other build runs),
;; r8_render_band calls this one, and the offsets below are asserted.  tests/c/test_bandz80.c compares the two
;; on random lists; the Z80 identity tests run it in every cull firmware.
;;
;; sdcc's __sdcccall(1): r in HL, fb in DE.  IX is kept (not used).
        .module band_z80

        .globl  _r8k_band
        .globl  _r8_band_face
        .globl  _r8k_fill

;; r8_render (r8.h), r8_state (src/r8int.h), r8_fb (r8fb.h) on sdcc
R_STATE   = 21
ST_NBANDS = 33
ST_NEXT   = 41
ST_HEADS  = 43
ST_FIRST  = 47
FB_BUF    = 0

        .area   _DATA
stp:    .ds     2               ; the r8_state
fbp:    .ds     2               ; the r8_fb
y0v:    .ds     2               ; the band's first row
y1v:    .ds     2               ; its end
av:     .ds     2               ; the list from above
nv:     .ds     2               ; the band's bucket
gv:     .ds     2               ; the face being drawn
head:   .ds     2               ; the next band's list
link:   .ds     2               ; where its next face goes

        .area   _CODE
;; void r8k_band(r8_render *r, r8_fb *fb): r HL, fb DE
_r8k_band:
        ld      (fbp), de
        ld      bc, #R_STATE
        add     hl, bc
        ld      a, (hl)
        inc     hl
        ld      h, (hl)
        ld      l, a
        ld      (stp), hl
        ex      de, hl          ; HL = fb: buf, width, height, y0, rows
        ld      c, (hl)
        inc     hl
        ld      b, (hl)
        inc     hl
        push    bc              ; buf
        ld      c, (hl)
        inc     hl
        ld      b, (hl)
        inc     hl
        push    bc              ; width
        ld      c, (hl)
        inc     hl
        ld      b, (hl)         ; BC = height
        inc     hl
        ld      e, (hl)
        inc     hl
        ld      d, (hl)         ; DE = y0
        inc     hl
        ld      (y0v), de
        ld      a, (hl)
        inc     hl
        ld      h, (hl)
        ld      l, a            ; HL = rows
        push    hl              ; rows
        add     hl, de          ; y1 = y0 + rows
        ld      (y1v), hl
        or      a, a            ; y1 > height (signed): y1 = height
        sbc     hl, bc
        jr      z, 2$
        jp      po, 1$
        jp      m, 3$           ; (overflow: the sign is flipped)
        jr      2$
1$:     jp      m, 2$
3$:     ld      (y1v), bc
2$:     pop     hl              ; rows: R8_FB_PAGE1_BYTES = w ((rows + 7) >> 3)
        ld      bc, #7
        add     hl, bc
        srl     h
        rr      l
        srl     h
        rr      l
        srl     h
        rr      l
        ld      b, h
        ld      c, l            ; BC = pages
        pop     de              ; DE = width
        ld      hl, #0
4$:     ld      a, b
        or      a, c
        jr      z, 5$
        add     hl, de
        dec     bc
        jr      4$
5$:     pop     de              ; buf
        push    hl              ; r8k_fill(buf, 0, bytes)
        xor     a, a
        push    af
        inc     sp
        ex      de, hl
        call    _r8k_fill       ; (pops v, n)

;; a = st->first; n = b < st->nbands ? st->heads[b] : END, b = y0 >> 3
;; (0 above the frame)
        ld      hl, (stp)
        ld      bc, #ST_FIRST
        add     hl, bc
        ld      e, (hl)
        inc     hl
        ld      d, (hl)
        ld      (av), de
        ld      hl, #0xFFFF
        ld      (nv), hl
        ld      hl, (y0v)
        bit     7, h
        jr      z, 6$
        ld      hl, #0
6$:     srl     h
        rr      l
        srl     h
        rr      l
        srl     h
        rr      l
        ex      de, hl          ; DE = b
        ld      hl, (stp)
        ld      bc, #ST_NBANDS
        add     hl, bc
        ld      a, e            ; b < nbands (unsigned)
        sub     a, (hl)
        inc     hl
        ld      a, d
        sbc     a, (hl)
        jr      nc, 7$
        ld      hl, (stp)
        ld      bc, #ST_HEADS
        add     hl, bc
        ld      a, (hl)
        inc     hl
        ld      h, (hl)
        ld      l, a
        add     hl, de
        add     hl, de
        ld      e, (hl)
        inc     hl
        ld      d, (hl)
        ld      (nv), de
7$:     ld      hl, #head       ; link = &head
        ld      (link), hl

;; the merge: the smaller id first (an END list last)
loop:   ld      hl, (av)
        ld      de, (nv)
        ld      a, h            ; n == END: take a
        and     a, l
        ld      b, a            ; (B: a == END when 0xFF)
        ld      a, d
        and     a, e
        inc     a
        jr      z, 1$
        ld      a, b            ; a == END: take n
        inc     a
        jr      z, 2$
        ld      a, l            ; a < n: take a
        sub     a, e
        ld      a, h
        sbc     a, d
        jr      nc, 2$
        jr      3$
1$:     ld      a, b            ; both END: done
        inc     a
        jr      z, done
3$:     ld      (gv), hl        ; g = a; a = st->next[a]
        call    nextof
        ld      (av), de
        jr      4$
2$:     ex      de, hl          ; g = n; n = st->next[n]
        ld      (gv), hl
        call    nextof
        ld      (nv), de
;; d = r8_band_face(st, g, y0, y1, fb)
4$:     ld      hl, (fbp)
        push    hl
        ld      hl, (y1v)
        push    hl
        ld      hl, (y0v)
        push    hl
        ld      de, (gv)
        ld      hl, (stp)
        call    _r8_band_face   ; (pops y0, y1, fb; d in DE)
        ld      a, e            ; d == 1: finished, out of the list
        dec     a
        or      a, d
        jr      z, loop
        ld      hl, (link)      ; *link = g; link = &st->next[g]
        ld      de, (gv)
        ld      (hl), e
        inc     hl
        ld      (hl), d
        ex      de, hl
        call    nextp
        ld      (link), hl
        jr      loop

done:   ld      hl, (link)      ; *link = END
        ld      (hl), #0xFF
        inc     hl
        ld      (hl), #0xFF
        ld      hl, (stp)       ; st->first = head
        ld      bc, #ST_FIRST
        add     hl, bc
        ld      de, (head)
        ld      (hl), e
        inc     hl
        ld      (hl), d
        ret

;; DE = st->next[HL]
nextof: call    nextp
        ld      e, (hl)
        inc     hl
        ld      d, (hl)
        ret

;; HL = &st->next[HL] (BC changed)
nextp:  ld      b, h
        ld      c, l
        ld      hl, (stp)
        push    bc
        ld      bc, #ST_NEXT
        add     hl, bc
        pop     bc
        ld      a, (hl)
        inc     hl
        ld      h, (hl)
        ld      l, a
        add     hl, bc
        add     hl, bc
        ret
