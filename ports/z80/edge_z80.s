;; edge_z80.s - r8k_edge (include/r8kern.h) for the Z80 (sdcc 4.2, sdas;
;; issue 10): an edge's column DDA for its first row.  In the Z80 archive
;; with -DR8_ASM_EDGE (mk/targets.mk, Z80_ASM "edge"); the C89 reference
;; is r8k_edge in src/kern.c, and tests/targets/test_z80_kern.c (step
;; xkern-z80) compares the two on random edges.
;;
;; r8_s16 r8k_edge(r8_interp *it, const r8_s16 *a, const r8_s16 *b)
;; sdcc's __sdcccall(1): it in HL, a in DE, b on the stack (popped here);
;; the result in DE.  IX is kept.  The same steps as the C: dy, the
;; limits, y0 and s0, q and rd by a 16-step restoring division, then
;; the first column from P = ((ax - 8) & 15) + s0 q (products of s0 and
;; pl, both 0..15, by four shift-add steps).
;; The cube / cull firmware (emu/z80sim, frames 1-3; docs/benchmarks.md,
;; "Z80: round 4"): 11,900 T a frame less than the C reference, 556 B less.
        .module edge_z80
        .area   _CODE
        .globl  _r8k_edge

        .area   _DATA
eit:    .ds     2
eax:    .ds     2
eay:    .ds     2
ebx:    .ds     2
edy:    .ds     2
ey0:    .ds     2
es0:    .ds     1
eneg:   .ds     1
eq:     .ds     2
erd:    .ds     2
eval:   .ds     2

        .area   _CODE

_r8k_edge:
        ld      (eit), hl
        ex      de, hl          ; HL = a
        ld      e, (hl)
        inc     hl
        ld      d, (hl)
        inc     hl
        ld      (eax), de
        ld      e, (hl)
        inc     hl
        ld      d, (hl)
        ld      (eay), de
        pop     bc              ; the return address
        pop     hl              ; b
        push    bc
        ld      e, (hl)
        inc     hl
        ld      d, (hl)
        inc     hl
        ld      (ebx), de
        ld      a, (hl)
        inc     hl
        ld      h, (hl)
        ld      l, a            ; HL = b[1]
        ld      de, (eay)
        or      a, a
        sbc     hl, de          ; dy (16 bits, unsigned)
        ld      (edy), hl
        ld      de, #1424
        or      a, a
        sbc     hl, de
        jp      nc, wide        ; dy >= 1424
        ld      de, #0x4000     ; ax, bx in -16384..16383
        ld      hl, (eax)
        add     hl, de
        bit     7, h
        jp      nz, wide
        ld      hl, (ebx)
        add     hl, de
        bit     7, h
        jp      nz, wide
        ;; y0 = ay > 32760 ? 2048 : floor((ay + 7) / 16)
        ld      hl, (eay)
        ld      a, h
        cp      a, #0x7F
        jr      nz, 1$
        ld      a, l
        cp      a, #0xF9
        jr      c, 1$
        ld      hl, #2048
        jr      2$
1$:     ld      de, #7
        add     hl, de
        sra     h
        rr      l
        sra     h
        rr      l
        sra     h
        rr      l
        sra     h
        rr      l
2$:     ld      (ey0), hl
        ld      a, l            ; s0 = the low byte of 16 y0 + 8 - ay
        add     a, a
        add     a, a
        add     a, a
        add     a, a
        add     a, #8
        ld      hl, #eay
        sub     a, (hl)
        ld      (es0), a
        ;; dx = bx - ax; udx = dx < 0 ? -dx - 1 : dx
        ld      hl, (ebx)
        ld      de, (eax)
        or      a, a
        sbc     hl, de
        ld      a, h
        rla
        sbc     a, a
        ld      (eneg), a
        jr      z, 3$
        ld      a, h
        cpl
        ld      h, a
        ld      a, l
        cpl
        ld      l, a
3$:     ;; q = udx / dy, rd = udx % dy (udx < 2^15, 1 <= dy < 1424)
        ld      a, h
        ld      c, l            ; AC = the dividend, then the quotient
        ld      de, (edy)
        ld      hl, #0
        ld      b, #16
4$:     sla     c
        rla
        adc     hl, hl
        sbc     hl, de
        jr      nc, 5$
        add     hl, de
        djnz    4$
        jr      6$
5$:     inc     c
        djnz    4$
6$:     ld      b, a            ; BC = q, HL = rd
        ld      a, (eneg)
        or      a, a
        jr      z, 7$
        ld      a, b            ; q = -q - 1, rd = dy - 1 - rd
        cpl
        ld      b, a
        ld      a, c
        cpl
        ld      c, a
        ex      de, hl          ; DE = rd, HL = dy
        scf
        sbc     hl, de
7$:     ld      (erd), hl
        ld      (eq), bc
        ;; -2048 < q < 2048: B in 0xF8..0x07
        ld      a, b
        add     a, #8
        cp      a, #16
        jp      nc, wide
        ld      a, b            ; and q = -2048 too
        cp      a, #0xF8
        jr      nz, 10$
        ld      a, c
        or      a, a
        jp      z, wide
10$:
        ;; it->q, r, den
        ld      hl, (eit)
        inc     hl
        inc     hl
        ld      (hl), c
        inc     hl
        ld      (hl), b
        inc     hl
        inc     hl
        inc     hl              ; (err later)
        ld      de, (erd)
        ld      (hl), e
        inc     hl
        ld      (hl), d
        inc     hl
        ld      de, (edy)
        ld      (hl), e
        inc     hl
        ld      (hl), d
        ;; p = ((ax - 8) & 15) + s0 q
        ld      de, (eq)
        ld      a, (es0)
        call    mul4            ; HL = s0 q
        ld      a, (eax)
        sub     a, #8
        and     a, #15
        ld      e, a
        ld      d, #0
        add     hl, de          ; HL = p
        ld      a, l
        and     a, #15
        push    af              ; pl
        sra     h               ; floor(p / 16)
        rr      l
        sra     h
        rr      l
        sra     h
        rr      l
        sra     h
        rr      l
        ex      de, hl
        ld      hl, (eax)       ; + floor((ax - 8) / 16)
        ld      bc, #-8
        add     hl, bc
        sra     h
        rr      l
        sra     h
        rr      l
        sra     h
        rr      l
        sra     h
        rr      l
        add     hl, de
        ld      (eval), hl
        ;; u = dy pl + s0 rd + 16 dy - 1
        pop     af              ; pl
        ld      de, (edy)
        call    mul4            ; dy pl
        push    hl
        ld      de, (erd)
        ld      a, (es0)
        call    mul4            ; s0 rd
        pop     de
        add     hl, de
        ld      de, (edy)
        ex      de, hl
        add     hl, hl
        add     hl, hl
        add     hl, hl
        add     hl, hl          ; d16
        ld      b, h
        ld      c, l
        ex      de, hl
        add     hl, de
        dec     hl              ; u
        ld      de, (eval)
8$:     or      a, a            ; while u >= d16: u -= d16, val++
        sbc     hl, bc
        jr      c, 9$
        inc     de
        jr      8$
9$:     add     hl, bc
        srl     h               ; err = u >> 4
        rr      l
        srl     h
        rr      l
        srl     h
        rr      l
        srl     h
        rr      l
        ex      de, hl          ; DE = err, HL = val
        ld      b, h
        ld      c, l
        ld      hl, (eit)
        ld      (hl), c
        inc     hl
        ld      (hl), b
        inc     hl
        inc     hl
        inc     hl
        ld      (hl), e
        inc     hl
        ld      (hl), d
        ld      de, (ey0)
        ret
wide:   ld      de, #0x8000     ; R8_EDGE_WIDE
        ret

;; mul4: HL = A * DE (low 16 bits), A in 0..15
mul4:   ld      hl, #0
        add     a, a
        add     a, a
        add     a, a
        add     a, a
        ld      b, #4
1$:     add     hl, hl
        add     a, a
        jr      nc, 2$
        add     hl, de
2$:     djnz    1$
        ret
