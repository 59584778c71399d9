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
        .globl  _r8k_scanband

;; r8_render (r8.h), r8_state (src/r8int.h), r8_fb (r8fb.h) on sdcc
R_STATE   = 21
ST_NBANDS = 33
ST_NEXT   = 41
ST_HEADS  = 43
ST_FIRST  = 47
ST_SLOT   = 49
ST_POOL   = 53
ST_ESIZE  = 57
ST_PUSED  = 60
ST_PFREE  = 61
NO_SLOT   = 0xFF
;; r8_acthead (src/r8int.h): level, used, then its r8_scanx
E_LEVEL   = 0
E_USED    = 1
E_BACK    = 2 + 0x13
E_Y       = 2 + 0x15
E_YBOT    = 2 + 0x17
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
ev:     .ds     2               ; its pool entry (a face with a slot)
kp:     .ds     2               ; &st->slot[g]
kv:     .ds     1               ; its slot

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
        jp      z, done
3$:     ld      (gv), hl        ; g = a; a = st->next[a]
        call    nextof
        ld      (av), de
        jr      4$
2$:     ex      de, hl          ; g = n; n = st->next[n]
        ld      (gv), hl
        call    nextof
        ld      (nv), de
;; a face with a pool slot (one going on from the band above): draw_face's
;; going-on path here: its entry, lim = min(ybot, y1), r8k_scanband when
;; y < lim, done = y >= ybot || backface, and the release when done
4$:     ld      hl, (stp)
        ld      bc, #ST_SLOT
        add     hl, bc
        ld      a, (hl)
        inc     hl
        ld      h, (hl)
        ld      l, a            ; HL = st->slot
        or      a, h            ; (no pool: draw_face)
        jp      z, slow
        ld      de, (gv)
        add     hl, de
        ld      a, (hl)         ; A = k = st->slot[g]
        cp      a, #NO_SLOT
        jp      z, slow
        ld      (kp), hl
        ld      (kv), a
        ld      hl, (stp)       ; e = st->pool + k * st->esize
        ld      bc, #ST_POOL
        add     hl, bc
        ld      e, (hl)
        inc     hl
        ld      d, (hl)
        inc     hl
        inc     hl
        inc     hl
        ld      c, (hl)
        inc     hl
        ld      b, (hl)         ; BC = esize
        ex      de, hl          ; HL = pool
        or      a, a
        jr      z, 6$
5$:     add     hl, bc
        dec     a
        jr      nz, 5$
6$:     ld      (ev), hl
        ld      bc, #E_YBOT
        add     hl, bc
        ld      e, (hl)
        inc     hl
        ld      d, (hl)         ; DE = ybot
        ld      hl, (y1v)       ; lim = ybot < y1 ? ybot : y1
        ld      a, e
        sub     a, l
        ld      a, d
        sbc     a, h
        jp      po, 7$
        xor     a, #0x80
7$:     jp      p, 8$
        ex      de, hl
8$:     ex      de, hl          ; DE = lim
        ld      hl, (ev)
        ld      bc, #E_Y
        add     hl, bc
        ld      a, (hl)         ; y < lim (signed): r8k_scanband
        sub     a, e
        inc     hl
        ld      a, (hl)
        sbc     a, d
        jp      po, 9$
        xor     a, #0x80
9$:     jp      p, 10$
        ld      hl, (ev)        ; r8k_scanband(&e->c, fb, lim, e->level)
        ld      a, (hl)
        push    af
        inc     sp
        push    de
        inc     hl
        inc     hl
        ld      de, (fbp)
        call    _r8k_scanband   ; (pops lim, level)
10$:    ld      hl, (ev)        ; done = y >= ybot || backface
        ld      bc, #E_BACK
        add     hl, bc
        ld      a, (hl)
        or      a, a
        jr      nz, 12$
        inc     hl
        inc     hl
        ld      e, (hl)
        inc     hl
        ld      d, (hl)         ; DE = y
        inc     hl
        ld      a, e            ; y - ybot
        sub     a, (hl)
        inc     hl
        ld      a, d
        sbc     a, (hl)
        jp      po, 11$
        xor     a, #0x80
11$:    jp      m, golink       ; y < ybot: goes on
12$:    ld      hl, (ev)        ; release: e->used = 0
        ld      a, (kv)
        ld      c, a            ; C = k
        ld      de, (stp)
        ld      a, e
        add     a, #ST_PFREE
        ld      e, a
        ld      a, d
        adc     a, #0
        ld      d, a            ; DE = &st->pool_free
        ld      a, (de)
        ld      (hl), a         ; e->level = st->pool_free
        inc     hl
        ld      (hl), #0        ; e->used = 0
        ld      a, c
        ld      (de), a         ; st->pool_free = k
        dec     de
        ex      de, hl
        dec     (hl)            ; st->pool_used--
        ld      hl, (kp)
        ld      (hl), #NO_SLOT  ; st->slot[g] = R8_NO_SLOT
        jp      loop

;; d = r8_band_face(st, g, y0, y1, fb)
slow:   ld      hl, (fbp)
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
        jp      z, loop
golink: ld      hl, (link)      ; *link = g; link = &st->next[g]
        ld      de, (gv)
        ld      (hl), e
        inc     hl
        ld      (hl), d
        ex      de, hl
        call    nextp
        ld      (link), hl
        jp      loop

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
