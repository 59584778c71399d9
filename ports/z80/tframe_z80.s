;; tframe_z80.s - r8_tf_frame's per-object arithmetic for the Z80 (sdcc
;; 4.2, sdas; issue 10).  In the Z80 archive with -DR8_ASM_TFRAME
;; (mk/targets.mk, Z80_ASM "tframe"); the C89 references are in
;; src/r8tfref.h (rot_offset, which src/transform.c uses without the
;; macro, and src/fixed.c's r8_mat_apply_t14 and r8_mat_rotate), and
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
;; void r8_mat_rotate(r8_mat3 *m, r8_u8 ax, r8_u8 ay, r8_u8 az)
;;   src/fixed.c's entries: the six sines and cosines from r8_sin (C),
;;   then the 14 rounded products (rmul, rmul2: floor((sum + 8192) /
;;   2^14), saturated) from r8z_smul16, the same sums in the same order.
;;
;; sdcc's __sdcccall(1): the first two pointers in HL and DE, the rest on
;; the stack (popped here: all return void); r8_mat_rotate: m in HL, ax,
;; ay, az one byte each on the stack.  IX is kept.
        .module tframe_z80
        .area   _CODE
        .globl  _r8k_rotoff
        .globl  _r8_mat_apply_t14
        .globl  _r8_mat_rotate
        .globl  _r8_sin
        .globl  r8z_umul16
        .globl  r8z_smul16

        .area   _DATA
fe:     .ds     2               ; the row's first element
fstep:  .ds     2               ; bytes from a row's first element to the next row's
fcol:   .ds     2               ; bytes between a row's elements
fp:     .ds     2               ; the next element
fm:     .ds     2               ; m (r8_mat_rotate)
fo:     .ds     2               ; the next output
fd:     .ds     12              ; d[0..2] (r8k_rotoff), v (r8_mat_apply_t14)
frow:   .ds     1               ; rows left
facc:   .ds     4               ; the row's sum
fa:     .ds     2               ; |e|
fb:     .ds     4               ; |d[j]|
fsg:    .ds     1               ; bit 7: the product is negative
fang:   .ds     3               ; ax, ay, az
fsa:    .ds     2               ; sin ax, cos ax, ... (r8_mat_rotate)
fca:    .ds     2
fsb:    .ds     2
fcb:    .ds     2
fsc:    .ds     2
fcc:    .ds     2
fnsa:   .ds     2               ; -sin ax, -sin ay, -sin az
fnsb:   .ds     2
fnsc:   .ds     2
ft6:    .ds     2               ; rmul(-sb, cc), rmul(sb, sc)
ft7:    .ds     2

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
        call    fsat
        ex      de, hl
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

;; HL = r8_sat16(floor(facc / 2^14)) (sat_asr14: hi * 4 + (lo >> 14) when
;; hi, facc's high word, is in -2^13 .. 2^13 - 1)
fsat:
        ld      hl, (facc + 2)
        ld      bc, #0x2000
        add     hl, bc
        ld      a, h
        cp      a, #0x40
        jr      nc, 1$          ; out of range: saturate
        ld      hl, (facc + 2)
        ld      a, (facc + 1)
        add     a, a
        adc     hl, hl
        add     a, a
        adc     hl, hl
        ret
1$:     ld      a, (facc + 3)
        ld      hl, #0x7FFF
        add     a, a
        ret     nc
        inc     hl              ; -32768
        ret

;; facc += HL * DE (signed)
fmac:
        call    r8z_smul16
        FACC
        ret

;; facc = 8192 + (p1) * (p2)
        .macro  RM1 p1, p2
        ld      hl, #8192
        ld      (facc), hl
        ld      hl, #0
        ld      (facc + 2), hl
        ld      hl, (p1)
        ld      de, (p2)
        call    fmac
        .endm

;; facc += (p1) * (p2)
        .macro  RM2 p1, p2
        ld      hl, (p1)
        ld      de, (p2)
        call    fmac
        .endm

;; m[k] = HL
        .macro  MPUT k
        ex      de, hl
        ld      hl, (fm)
        ld      bc, #2 * k
        add     hl, bc
        ld      (hl), e
        inc     hl
        ld      (hl), d
        .endm

;; (q1) = r8_sin((q2) + q3)
        .macro  SINOF q1, q2, q3
        ld      a, (q2)
        add     a, #q3
        call    _r8_sin
        ld      (q1), de
        .endm

;; (q1) = -(q2)
        .macro  NEGOF q1, q2
        ld      de, (q2)
        xor     a, a
        ld      h, a
        ld      l, a
        sbc     hl, de
        ld      (q1), hl
        .endm

_r8_mat_rotate:
        ld      (fm), hl
        pop     bc              ; the return address
        pop     de              ; E = ax, D = ay
        ld      hl, #0
        add     hl, sp
        ld      a, (hl)         ; az
        inc     sp
        push    bc
        ld      (fang), de
        ld      (fang + 2), a
        SINOF   fsa, fang, 0
        SINOF   fca, fang, 64   ; r8_cos(a) = r8_sin(a + 64)
        SINOF   fsb, fang+1, 0
        SINOF   fcb, fang+1, 64
        SINOF   fsc, fang+2, 0
        SINOF   fcc, fang+2, 64
        NEGOF   fnsa, fsa
        NEGOF   fnsb, fsb
        NEGOF   fnsc, fsc
        RM1     fcb, fcc        ; m[0] = t0 = rmul(cb, cc)
        call    fsat
        MPUT    0
        RM1     fcb, fnsc       ; m[1] = t1 = rmul(cb, -sc)
        call    fsat
        MPUT    1
        ld      hl, (fsb)       ; m[2] = sb
        MPUT    2
        RM1     fnsb, fcc       ; t6 = rmul(-sb, cc)
        call    fsat
        ld      (ft6), hl
        RM1     fsb, fsc        ; t7 = rmul(sb, sc)
        call    fsat
        ld      (ft7), hl
        RM1     fca, fsc        ; m[3] = rmul2(ca, sc, -sa, t6)
        RM2     fnsa, ft6
        call    fsat
        MPUT    3
        RM1     fca, fcc        ; m[4] = rmul2(ca, cc, -sa, t7)
        RM2     fnsa, ft7
        call    fsat
        MPUT    4
        RM1     fnsa, fcb       ; m[5] = rmul(-sa, cb)
        call    fsat
        MPUT    5
        RM1     fsa, fsc        ; m[6] = rmul2(sa, sc, ca, t6)
        RM2     fca, ft6
        call    fsat
        MPUT    6
        RM1     fsa, fcc        ; m[7] = rmul2(sa, cc, ca, t7)
        RM2     fca, ft7
        call    fsat
        MPUT    7
        RM1     fca, fcb        ; m[8] = rmul(ca, cb)
        call    fsat
        MPUT    8
        ret
