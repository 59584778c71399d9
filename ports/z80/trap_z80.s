;; trap_z80.s - r8k_trap for the Z80 (sdcc 4.2, sdas; issue 10).
;;
;; void r8k_trap(r8_trapfill *t, r8_interp *l, r8_interp *r, r8_u16 rows)
;; fills `rows` rows of a trapezoid into a PAGE1 band: on each row the
;; columns [l->val, r->val) clamped to [0, w), pattern pat[k] under the
;; row's bit m; then both column DDAs step, m moves to the next row (and
;; page), k to the next phase (include/r8kern.h has the contract; the C89
;; reference is src/kern.c, left out with -DR8_ASM_TRAP).
;;
;; sdcc's __sdcccall(1): t in HL, l in DE, r and rows on the stack (this
;; function pops them: it returns void).  IX is kept.
;;
;; The call's state (t's page, m, k, pat, w and both DDAs) is copied into
;; static memory (the library is not reentrant) and back at the end.  A
;; span of the pattern 0xFF or 0x00 is a loop of `or m` / `and ~m`, two
;; columns a pass (~30 T a column); a dither span runs a four-column loop
;; (the four column values in registers, ~31 T a column) entered at the
;; first column's phase, and its last columns (after the last phase 3)
;; counted one by one.  The DDAs step with the carry of the err compare
;; (ccf; adc).  Round 6 (k-z80b): cube / cull 282,771 -> 266,571 T in
;; r8k_trap over frames 2-3 (emu/z80sim -P -F 2).
;;
;; The cube / cull firmware (bench/kernz80.py, emu/z80sim, frames 1-3):
;; Z80_ASM="mul16 mullong" 1,612,609 T a frame, with trap 1,336,504
;; (-17%); the image 255 bytes smaller.  tests/targets/test_z80_kern.c
;; (step xkern-z80) compares it with the reference on random inputs.
        .module trap_z80

;; the undocumented halves of IX and IY (sdas has no names for them;
;; ucsim and emu/z80sim run them)
        .macro  LD_IXH_A
        .db     0xDD, 0x67
        .endm
        .macro  LD_IXL_A
        .db     0xDD, 0x6F
        .endm
        .macro  OR_IXH
        .db     0xDD, 0xB4
        .endm
        .macro  OR_IXL
        .db     0xDD, 0xB5
        .endm
        .macro  LD_A_IYH
        .db     0xFD, 0x7C
        .endm
        .macro  LD_IYH_A
        .db     0xFD, 0x67
        .endm
        .macro  LD_A_IYL
        .db     0xFD, 0x7D
        .endm
        .macro  OR_IYL
        .db     0xFD, 0xB5
        .endm
        .macro  LD_IYL_A
        .db     0xFD, 0x6F
        .endm
        .macro  DEC_IYL
        .db     0xFD, 0x2D
        .endm
        .globl  _r8k_trap

        .area   _DATA
ts:                             ; a copy of *t (r8_trapfill: 10 bytes)
ts_page: .ds    2
ts_m:   .ds     1
ts_k:   .ds     1
ts_pat: .ds     4
ts_w:   .ds     2
tl:     .ds     10              ; *l: val +0, q +2, err +4, r +6, den +8
tr:     .ds     10              ; *r
ts_rows: .ds    2
ts_pt:  .ds     2               ; t, l, r themselves
ts_pl:  .ds     2
ts_pr:  .ds     2
ts_ph:  .ds     1               ; a dither span's first phase

        .area   _CODE

_r8k_trap:
        ld      (ts_pt), hl
        ld      (ts_pl), de
        ld      de, #ts
        ld      bc, #10
        ldir
        ld      hl, (ts_pl)
        ld      de, #tl
        ld      c, #10
        ldir
        pop     bc              ; the return address
        pop     hl              ; r
        pop     de              ; rows
        push    bc
        ld      (ts_pr), hl
        ld      (ts_rows), de
        ld      de, #tr
        ld      bc, #10
        ldir
        push    ix
        jp      next

row:    ; ---- the span: xl = max(l.val, 0), xr = min(r.val, w)
        ld      de, (tl)
        bit     7, d
        jr      z, 1$
        ld      de, #0
1$:     ld      hl, (tr)
        bit     7, h
        jp      nz, step        ; xr < 0 <= xl: empty
        ld      bc, (ts_w)
        or      a, a
        sbc     hl, bc
        jr      c, 2$
        ld      h, b            ; xr >= w: w
        ld      l, c
        jr      3$
2$:     add     hl, bc
3$:     or      a, a            ; both >= 0 here
        sbc     hl, de          ; n = xr - xl
        jp      c, step
        jp      z, step
        ld      b, h
        ld      c, l            ; BC = n
        ld      hl, (ts_page)
        add     hl, de          ; HL = page + xl
        push    de              ; xl (its phase)
        ex      de, hl          ; DE = the first byte
        ld      a, (ts_k)
        ld      hl, #ts_pat
        add     a, l
        ld      l, a
        adc     a, h
        sub     a, l
        ld      h, a
        ld      a, (hl)         ; pat[k]
        ex      de, hl          ; HL = the first byte
        pop     de              ; E: xl's low byte
        inc     a
        jr      z, fset         ; 0xFF
        dec     a
        jr      z, fclr         ; 0x00
        jp      fdith

        ;; ---- the pattern 0xFF: or m; BC = n >= 1, HL = the first byte
fset:   ld      a, (ts_m)
        ld      e, a
        srl     b
        rr      c               ; BC = pairs, carry: n is odd
        jr      nc, 1$
        ld      a, (hl)
        or      a, e
        ld      (hl), a
        inc     hl
1$:     ld      a, b
        or      a, c
        jr      z, step
        call    cnt2            ; B, C: the two-level count of the pairs
2$:     ld      a, (hl)
        or      a, e
        ld      (hl), a
        inc     hl
        ld      a, (hl)
        or      a, e
        ld      (hl), a
        inc     hl
        djnz    2$
        dec     c
        jr      nz, 2$
        jr      step

        ;; ---- the pattern 0x00: and ~m
fclr:   ld      a, (ts_m)
        cpl
        ld      e, a
        srl     b
        rr      c
        jr      nc, 1$
        ld      a, (hl)
        and     a, e
        ld      (hl), a
        inc     hl
1$:     ld      a, b
        or      a, c
        jr      z, step
        call    cnt2
2$:     ld      a, (hl)
        and     a, e
        ld      (hl), a
        inc     hl
        ld      a, (hl)
        and     a, e
        ld      (hl), a
        inc     hl
        djnz    2$
        dec     c
        jr      nz, 2$
        jr      step

        ;; ---- step both DDAs, then m, page and k.  err += r; when the
        ;; 16-bit sum is >= den: err -= den and val += q + 1, else val +=
        ;; q.  After `sbc hl, de` a borrow (no step) is undone by `add hl,
        ;; de`, which then always carries (err + r - den wrapped below 0):
        ;; so the carry is 1 exactly when val gets q alone, and `ccf; adc`
        ;; adds q plus the step.
step:   ld      hl, (tl + 4)    ; l: err += r
        ld      de, (tl + 6)
        add     hl, de
        ld      de, (tl + 8)
        or      a, a
        sbc     hl, de          ; >= den (the 16-bit sum, as the C)?
        jr      nc, 1$
        add     hl, de          ; below: back, carry set
1$:     ld      (tl + 4), hl
        ld      hl, (tl)
        ld      de, (tl + 2)
        ccf
        adc     hl, de
        ld      (tl), hl
        ld      hl, (tr + 4)    ; r: the same
        ld      de, (tr + 6)
        add     hl, de
        ld      de, (tr + 8)
        or      a, a
        sbc     hl, de
        jr      nc, 3$
        add     hl, de
3$:     ld      (tr + 4), hl
        ld      hl, (tr)
        ld      de, (tr + 2)
        ccf
        adc     hl, de
        ld      (tr), hl
4$:     ld      a, (ts_k)
        inc     a
        and     a, #3
        ld      (ts_k), a
        ld      a, (ts_m)
        add     a, a
        jr      nz, 5$
        ld      hl, (ts_page)   ; past the page's last row: the next page
        ld      de, (ts_w)
        add     hl, de
        ld      (ts_page), hl
        inc     a
5$:     ld      (ts_m), a
next:   ld      hl, (ts_rows)
        ld      a, h
        or      a, l
        jr      z, done
        dec     hl
        ld      (ts_rows), hl
        jp      row

done:   pop     ix
        ld      hl, (ts_pl)     ; l->val, l->err
        ld      de, (tl)
        ld      (hl), e
        inc     hl
        ld      (hl), d
        inc     hl
        inc     hl
        inc     hl
        ld      de, (tl + 4)
        ld      (hl), e
        inc     hl
        ld      (hl), d
        ld      hl, (ts_pr)     ; r->val, r->err
        ld      de, (tr)
        ld      (hl), e
        inc     hl
        ld      (hl), d
        inc     hl
        inc     hl
        inc     hl
        ld      de, (tr + 4)
        ld      (hl), e
        inc     hl
        ld      (hl), d
        ld      de, (ts_pt)     ; t->page, t->m, t->k
        ld      hl, #ts
        ld      bc, #4
        ldir
        ret

;; cnt2: BC = a count >= 1 as B (the low byte, 0 = 256) and C (the
;; passes of djnz plus one per 256) for `djnz; dec c; jr nz`
cnt2:   ld      a, c
        ld      c, b
        ld      b, a
        or      a, a
        ret     z
        inc     c
        ret

        ;; ---- a dither: column x gets m where bit 3 - (x & 3) of the
        ;; pattern's low nibble is set, ~m elsewhere.  A = pat, BC = n,
        ;; HL = the first byte, E = xl's low byte.  The four column values
        ;; go to E, IXH, IXL, D (phases 0..3).  With ph = xl & 3, the span
        ;; passes phase 3 G = (ph + n) / 4 times: the unchecked loop g0..g3
        ;; is entered at phase ph and runs G times (B, then IYL passes of
        ;; 256), then the T = (ph + n) & 3 columns left (IYH) go through
        ;; d0.., which counts each column in B; a span that never reaches
        ;; phase 3 (G = 0, n < 4) goes there too, entered at ph.
fdith:  ld      d, a            ; D = pat
        ld      a, e
        and     a, #3
        ld      (ts_ph), a
        push    hl              ; the first byte
        ld      l, a
        ld      h, #0
        add     hl, bc          ; ph + n
        ld      a, l
        and     a, #3
        LD_IYH_A                ; T
        srl     h
        rr      l
        srl     h
        rr      l               ; HL = G
        ld      a, h
        or      a, l
        jr      nz, 1$
        ld      a, c            ; G = 0: the count is n; carry set
        scf
        jr      2$
1$:     ld      a, l            ; B = G's low byte (0 = 256), IYL the
        or      a, a            ; passes of djnz
        ld      a, h
        jr      z, 3$
        inc     a
3$:     LD_IYL_A
        ld      a, l
        or      a, a            ; carry clear
2$:     pop     hl
        push    af              ; the count for B, and the carry
        ld      a, (ts_m)
        ld      c, a            ; C = m
        ld      b, d            ; the nibble's bits from bit 0 (phase 3)
        srl     b
        sbc     a, a
        and     a, c
        ld      d, a            ; phase 3
        srl     b
        sbc     a, a
        and     a, c
        LD_IXL_A                ; phase 2
        srl     b
        sbc     a, a
        and     a, c
        LD_IXH_A                ; phase 1
        srl     b
        sbc     a, a
        and     a, c
        ld      e, a            ; phase 0
        ld      a, c
        cpl
        ld      c, a            ; C = ~m
        pop     af
        ld      b, a
        ld      a, (ts_ph)
        jr      c, dsh
        or      a, a            ; G >= 1: enter the loop at ph
        jr      z, g0
        dec     a
        jr      z, g1
        dec     a
        jr      z, g2
        jr      g3
g0:     ld      a, (hl)
        and     a, c
        or      a, e
        ld      (hl), a
        inc     hl
g1:     ld      a, (hl)
        and     a, c
        OR_IXH
        ld      (hl), a
        inc     hl
g2:     ld      a, (hl)
        and     a, c
        OR_IXL
        ld      (hl), a
        inc     hl
g3:     ld      a, (hl)
        and     a, c
        or      a, d
        ld      (hl), a
        inc     hl
        djnz    g0
        DEC_IYL
        jr      nz, g0
        LD_A_IYH                ; T columns left, from phase 0
        or      a, a
        jp      z, step
        ld      b, a
        jr      d0
dsh:    or      a, a            ; G = 0: n columns from ph (ph + n <= 3)
        jr      z, d0
        dec     a
        jr      z, d1
        jr      d2
d0:     ld      a, (hl)         ; (never past phase 2 here)
        and     a, c
        or      a, e
        ld      (hl), a
        inc     hl
        dec     b
        jp      z, step
d1:     ld      a, (hl)
        and     a, c
        OR_IXH
        ld      (hl), a
        inc     hl
        dec     b
        jp      z, step
d2:     ld      a, (hl)
        and     a, c
        OR_IXL
        ld      (hl), a
        jp      step
