;; xform_z80.s - r8k_xform (include/r8kern.h) for the Z80 (sdcc 4.2, sdas;
;; issue 10): a model vertex into camera space.  In the Z80 archive with
;; -DR8_ASM_XFORM (mk/targets.mk, Z80_ASM "xform"); the C89 reference is
;; r8k_xform in src/kern.c, and tests/targets/test_z80_kern.c (step
;; xkern-z80) compares the two on random matrices, offsets and vertices.
;;
;; void r8k_xform(const r8_mat3 *m, const r8_vec3l *t, const r8_s16 *v,
;;                r8_vec3l *out)
;; out[i] = floor((m[3i] v[0] + m[3i+1] v[1] + m[3i+2] v[2] + 512) / 1024)
;;          + t[i], the sum in 32 bits (wrapping as the C's); the products
;; from r8z_smul16 (mulz_z80.s: one 16 x 8 pass for a model coordinate in
;; -255..255).  v is read with plain loads (R8_RDS16 on the Z80).
;;
;; sdcc's __sdcccall(1): m in HL, t in DE, v and out on the stack (popped
;; here: it returns void).  IX is kept.
;; The cube / cull firmware (emu/z80sim, frames 1-3; docs/benchmarks.md,
;; "Z80: round 4"): 9,002 T a frame less than the C reference, 572 B less.
;; Round 10: a vertex with all three coordinates in -255..255 (every
;; model vertex) takes the fast path: |v| and v's signs once a vertex,
;; each term one r8z_mul8 of |m| and |v| added to or subtracted from a
;; 32-bit sum in DE':HL' (no r8z_smul16, no 32-bit negation, no sum in
;; memory); other vertices the r8z_smul16 path as before.  Cube / cull
;; frames 2-3 (emu/sz80run.py): 529,030 -> 523,403 T a frame.
        .module xform_z80
        .area   _CODE
        .globl  _r8k_xform
        .globl  r8z_smul16
        .globl  r8z_mul8

        .area   _DATA
xm:     .ds     2               ; the next m element
xt:     .ds     2               ; t[row]
xo:     .ds     2               ; out[row]
xv:     .ds     6               ; v[0..2]
xrow:   .ds     1               ; rows left
xacc:   .ds     4               ; the row's sum
xmag:   .ds     3               ; |v[0..2]| when all are below 256

        .area   _CODE

;; the fast path's term: DE':HL' += m[k] * v[k] for the row at IY, from
;; |v[k]| (xmag + k, below 256) and v[k]'s high byte (0 or 0xFF: its
;; sign), one r8z_mul8 of |m[k]| and a 32-bit add or subtract of the
;; 24-bit product (so no 32-bit negation).  C = 0 on entry and exit.
        .macro  FTERM k
        ld      e, 2*k (iy)
        ld      d, 2*k+1 (iy)
        ld      a, (xv + 2*k + 1)
        xor     a, d
        ld      b, a            ; bit 7: the term is negative
        bit     7, d
        jr      z, .+8
        xor     a, a            ; DE = |m[k]| (0x8000: 32768 unsigned)
        sub     a, e
        ld      e, a
        sbc     a, a
        sub     a, d
        ld      d, a
        ld      a, (xmag + k)
        call    r8z_mul8        ; A:HL = |m[k]| * |v[k]|, B and C kept
        bit     7, b
        push    hl
        exx
        pop     bc              ; BC' = the product's low 16 bits
        jr      nz, .+12
        add     hl, bc
        ex      de, hl
        ld      c, a
        ld      b, #0
        adc     hl, bc
        ex      de, hl
        jr      .+12
        or      a, a
        sbc     hl, bc
        ex      de, hl
        ld      c, a
        ld      b, #0
        sbc     hl, bc
        ex      de, hl
        exx
        .endm

;; xacc += m[..] * v[off / 2]
        .macro  XTERM off
        ld      hl, (xm)
        ld      e, (hl)
        inc     hl
        ld      d, (hl)
        inc     hl
        ld      (xm), hl
        ld      hl, (xv + off)
        call    r8z_smul16      ; HL:DE = the product
        ex      de, hl
        ld      bc, (xacc)
        add     hl, bc
        ld      (xacc), hl
        ex      de, hl
        ld      bc, (xacc + 2)
        adc     hl, bc
        ld      (xacc + 2), hl
        .endm

_r8k_xform:
        ld      (xm), hl
        ld      (xt), de
        pop     bc              ; the return address
        pop     hl              ; v
        pop     de              ; out
        push    bc
        ld      (xo), de
        ld      de, #xv
        ld      bc, #6
        ldir
        ld      a, #3
        ld      (xrow), a
        ;; all three of v in -255..255: the fast path (the model's
        ;; vertices); otherwise r8z_smul16 for each term
        ld      hl, #xv
        ld      de, #xmag
        ld      b, #3
4$:     ld      c, (hl)         ; the low byte
        inc     hl
        ld      a, (hl)         ; the high byte
        inc     hl
        or      a, a
        jr      nz, 8$
        ld      a, c            ; v >= 0: |v| = the low byte
        jr      5$
8$:     inc     a
        jp      nz, 1$          ; high byte neither 0 nor 0xFF
        sub     a, c            ; |v| (v = -256: 0, the slow path)
        jp      z, 1$
5$:     ld      (de), a
        inc     de
        djnz    4$
        ld      iy, (xm)
6$:     exx                     ; DE':HL' = 512, the rounding
        ld      hl, #512
        ld      de, #0
        exx
        ld      c, #0
        FTERM   0
        FTERM   1
        FTERM   2
        ld      bc, #6
        add     iy, bc
        exx
        ld      l, h            ; (sum >> 8) as A:H:L
        ld      h, e
        ld      a, d
        push    hl
        exx
        pop     hl
        call    xtail
        ld      hl, #xrow
        dec     (hl)
        jp      nz, 6$
        ret
1$:     ld      hl, #512        ; the rounding, in the sum from the start
        ld      (xacc), hl
        ld      hl, #0
        ld      (xacc + 2), hl
        XTERM   0
        XTERM   2
        XTERM   4
        ld      hl, (xacc + 1)  ; (sum >> 8) as A:H:L, then 2 more
        ld      a, (xacc + 3)
        call    xtail
        ld      hl, #xrow
        dec     (hl)
        jp      nz, 1$
        ret

;; out[row] = (A:H:L >> 2) + t[row], sign-extended (A:H:L the row's sum
;; >> 8); xt and xo step to the next row
xtail:  sra     a
        rr      h
        rr      l
        sra     a
        rr      h
        rr      l
        ex      de, hl          ; DE: bits 0-15 of the quotient
        ld      c, a            ; BC: bits 16-31 (B the sign)
        rla
        sbc     a, a
        ld      b, a
        ld      hl, (xt)        ; + t[row]
        ld      a, (hl)
        add     a, e
        ld      e, a
        inc     hl
        ld      a, (hl)
        adc     a, d
        ld      d, a
        inc     hl
        ld      a, (hl)
        adc     a, c
        ld      c, a
        inc     hl
        ld      a, (hl)
        adc     a, b
        ld      b, a
        inc     hl
        ld      (xt), hl
        ld      hl, (xo)        ; out[row]
        ld      (hl), e
        inc     hl
        ld      (hl), d
        inc     hl
        ld      (hl), c
        inc     hl
        ld      (hl), b
        inc     hl
        ld      (xo), hl
        ret
