;; tframe_z80.s - r8_tf_frame's per-object arithmetic for the Z80 (sdcc
;; 4.2, sdas; issue 10).  In the Z80 archive with -DR8_ASM_TFRAME
;; (mk/targets.mk, Z80_ASM "tframe"); the C89 references are in
;; src/r8tfref.h (rot_offset, which src/transform.c uses without the
;; macro, and r8_mat_apply_t14, src/fixed.c's), and
;; tests/targets/test_z80_kern.c (step xkern-z80) compares them on random
;; matrices and vectors.
;;
;; void r8k_rotoff(const r8_mat3 *m, const r8_s32 *d, r8_vec3l *out,
;;                 int transpose)
;;   out[i] = (sum over j of e(i,j) * d[j] + 512) >> 10 (floor), with
;;   e(i,j) = m[3i + j] (transpose 0) or m[3j + i]; the Q1.14 x r8_s32
;;   products and their sum in 32 bits, wrapping as the C's.  A product
;;   is |e| * |d| from r8z_umul16 (|e| times d's low 16 bits; d's high
;;   word adds |e| (when 1) or the low word of a second product), negated
;;   when the signs differ; a zero d or e costs no multiply.
;; void r8_mat_apply_t14(const r8_mat3 *m, const r8_vec3 *v, r8_vec3 *out)
;;   out[k] = r8_sat16(floor((m[k] v.x + m[k+3] v.y + m[k+6] v.z + 8192)
;;            / 2^14)), the products from r8z_smul16, the sum in 32 bits.
;;
;; sdcc's __sdcccall(1): the first two pointers in HL and DE, the rest on
;; the stack (popped here: both return void).  IX is kept.
        .module tframe_z80
        .area   _CODE
        .globl  _r8k_rotoff
        .globl  _r8_mat_apply_t14
        .globl  r8z_umul16
        .globl  r8z_smul16

        .area   _DATA
fe:     .ds     2               ; the row's first element
fstep:  .ds     2               ; bytes from a row's first element to the next row's
fcol:   .ds     2               ; bytes between a row's elements
fp:     .ds     2               ; the next element
fo:     .ds     2               ; the next output
fd:     .ds     12              ; d[0..2] (r8k_rotoff), v (r8_mat_apply_t14)
frow:   .ds     1               ; rows left
facc:   .ds     4               ; the row's sum
fa:     .ds     2               ; |e|
fb:     .ds     4               ; |d[j]|
fsg:    .ds     1               ; bit 7: the product is negative

        .area   _CODE

;; facc += HL:DE
        .macro  FACC
        ex      de, hl
        ld      bc, (facc)
        add     hl, bc
        ld      (facc), hl
        ex      de, hl
        ld      bc, (facc + 2)
        adc     hl, bc
        ld      (facc + 2), hl
        .endm

;; facc = n (32 bits, n below 32768); fp = fe
        .macro  FSTART n
        ld      hl, #n
        ld      (facc), hl
        ld      hl, #0
        ld      (facc + 2), hl
        ld      hl, (fe)
        ld      (fp), hl
        .endm

_r8k_rotoff:
        ld      (fe), hl
        ex      de, hl          ; HL = d
        ld      de, #fd
        ld      bc, #12
        ldir
        pop     bc              ; the return address
        pop     hl              ; out
        ld      (fo), hl
        pop     hl              ; transpose
        push    bc
        ld      a, h
        or      a, l
        ld      hl, #6          ; rows 3 elements apart, columns 1
        ld      de, #2
        jr      z, 1$
        ex      de, hl          ; the transpose: rows 1 apart, columns 3
1$:     ld      (fstep), hl
        ld      (fcol), de
        ld      a, #3
        ld      (frow), a
2$:     FSTART  512             ; the rounding, in the sum from the start
        ld      hl, #fd
        call    rterm
        ld      hl, #fd + 4
        call    rterm
        ld      hl, #fd + 8
        call    rterm
        ld      hl, (facc + 1)  ; (sum >> 8) as A:H:L, then 2 more
        ld      a, (facc + 3)
        sra     a
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
        ld      hl, (fo)
        ld      (hl), e
        inc     hl
        ld      (hl), d
        inc     hl
        ld      (hl), c
        inc     hl
        ld      (hl), b
        inc     hl
        ld      (fo), hl
        ld      hl, (fe)        ; the next row
        ld      de, (fstep)
        add     hl, de
        ld      (fe), hl
        ld      hl, #frow
        dec     (hl)
        jp      nz, 2$
        ret

;; facc += e * d[j], e = *fp (fp moves on by fcol), HL = &d[j]
rterm:
        ld      de, #fb
        ld      bc, #4
        ldir                    ; fb = d[j]
        ld      hl, (fp)
        ld      e, (hl)
        inc     hl
        ld      d, (hl)         ; DE = e
        dec     hl
        ld      bc, (fcol)
        add     hl, bc
        ld      (fp), hl
        ld      a, d
        or      a, e
        ret     z               ; e = 0: no product
        ld      a, (fb + 3)
        xor     a, d
        ld      (fsg), a
        bit     7, d
        jr      z, 1$
        xor     a, a            ; DE = -DE (0x8000 stays: 32768 unsigned)
        sub     a, e
        ld      e, a
        sbc     a, a
        sub     a, d
        ld      d, a
1$:     ld      (fa), de
        ld      hl, #fb + 3
        bit     7, (hl)
        jr      z, 2$
        ld      hl, #fb         ; fb = -fb (2^31 stays: unsigned)
        xor     a, a
        sub     a, (hl)
        ld      (hl), a
        inc     hl
        ld      a, #0
        sbc     a, (hl)
        ld      (hl), a
        inc     hl
        ld      a, #0
        sbc     a, (hl)
        ld      (hl), a
        inc     hl
        ld      a, #0
        sbc     a, (hl)
        ld      (hl), a
2$:     ld      hl, (fb)
        ld      bc, (fb + 2)
        ld      a, h
        or      a, l
        or      a, b
        or      a, c
        ret     z               ; d[j] = 0: no product
        call    r8z_umul16      ; HL:DE = |e| * (|d| & 0xFFFF)
        ld      bc, (fb + 2)
        ld      a, b
        or      a, a
        jr      nz, 3$
        or      a, c
        jr      z, 4$           ; |d| < 2^16: done
        dec     a
        jr      nz, 3$
        ld      bc, (fa)        ; |d| >> 16 = 1: + |e| << 16
        add     hl, bc
        jr      4$
3$:     push    hl              ; + (|e| * (|d| >> 16)) << 16, mod 2^32
        push    de
        ld      de, (fa)
        ld      hl, (fb + 2)
        call    r8z_umul16      ; DE = its low word
        pop     bc
        pop     hl
        add     hl, de
        ld      d, b
        ld      e, c
4$:     ld      a, (fsg)
        add     a, a
        jr      nc, 5$
        xor     a, a            ; HL:DE = -HL:DE
        sub     a, e
        ld      e, a
        ld      a, #0
        sbc     a, d
        ld      d, a
        ld      a, #0
        sbc     a, l
        ld      l, a
        sbc     a, a
        sub     a, h
        ld      h, a
5$:     FACC
        ret

_r8_mat_apply_t14:
        ld      (fe), hl
        ex      de, hl          ; HL = v
        ld      de, #fd
        ld      bc, #6
        ldir
        pop     bc              ; the return address
        pop     hl              ; out
        push    bc
        ld      (fo), hl
        ld      a, #3
        ld      (frow), a
1$:     FSTART  8192            ; the rounding, in the sum from the start
        ld      hl, (fd)
        call    tterm
        ld      hl, (fd + 2)
        call    tterm
        ld      hl, (fd + 4)
        call    tterm
        ld      hl, (facc + 2)  ; hi: the quotient is hi * 4 + (lo >> 14)
        ld      bc, #0x2000
        add     hl, bc
        ld      a, h
        cp      a, #0x40
        jr      nc, 2$          ; hi outside -2^13 .. 2^13 - 1: saturate
        ld      hl, (facc + 2)
        ld      a, (facc + 1)
        add     a, a
        adc     hl, hl
        add     a, a
        adc     hl, hl
        jr      3$
2$:     ld      a, (facc + 3)
        ld      hl, #0x7FFF
        add     a, a
        jr      nc, 3$
        inc     hl              ; -32768
3$:     ex      de, hl
        ld      hl, (fo)
        ld      (hl), e
        inc     hl
        ld      (hl), d
        inc     hl
        ld      (fo), hl
        ld      hl, (fe)        ; the next column
        inc     hl
        inc     hl
        ld      (fe), hl
        ld      hl, #frow
        dec     (hl)
        jp      nz, 1$
        ret

;; facc += *fp * HL (fp moves on 3 elements)
tterm:
        ex      de, hl
        ld      hl, (fp)
        ld      c, (hl)
        inc     hl
        ld      b, (hl)
        inc     hl
        inc     hl
        inc     hl
        inc     hl
        inc     hl
        ld      (fp), hl
        ld      h, b
        ld      l, c
        call    r8z_smul16      ; HL:DE = m * v
        FACC
        ret
