;; project_z80.s - r8k_project (include/r8kern.h) for the Z80 (sdcc 4.2,
;; sdas; issue 10): a camera-space point to 12.4 screen coordinates.  In
;; the Z80 archive with -DR8_ASM_PROJECT (mk/targets.mk, Z80_ASM
;; "project"); the C89 reference is r8k_project in src/kern.c (r8_recip,
;; then r8_project_recip of src/proj.c), and tests/targets/test_z80_kern.c
;; (step xkern-z80) compares the two on random points and projections.
;;
;; int r8k_project(const r8_proj *p, const r8_vec3l *c, r8_s16 *out,
;;                 r8_u16 *m, r8_s8 *e)
;; sdcc's __sdcccall(1): p in HL, c in DE, out, m, e on the stack (popped
;; here); the result in DE.  IX is kept.
;;
;; *m, *e = r8_recip(c->z) (the library's C).  The usual case, x and y in
;; -32767..32767, the guard band below 1024 px and 16 focal / z not below
;; 2^-16 (sh >= 1), is done here as r8_project_recip does it: k = m * fn,
;; kk its top 15 bits, then for x and y round(v * kk * 2^-sh) (proj_round:
;; the floor of a negative product through its complement) checked
;; against the guard band.  Other points go to r8_project_recip itself.
;; The cube / cull firmware (emu/z80sim, frames 1-3; docs/benchmarks.md,
;; "Z80: round 4"): 27,596 T a frame less than the C reference, 348 B more.
        .module project_z80
        .area   _CODE
        .globl  _r8k_project
        .globl  _r8_recip
        .globl  _r8_project_recip
        .globl  r8z_umul16
        .globl  r8z_smul16

        .area   _DATA
pp:     .ds     2               ; p
pc:     .ds     2               ; c
pout:   .ds     2               ; out
pm:     .ds     2               ; m
pe:     .ds     2               ; e
pkk:    .ds     2               ; kk
psh:    .ds     1               ; sh - 1 (the shift of proj_round)
plim:   .ds     2               ; the guard band in 12.4
pq:     .ds     2               ; qx

        .area   _CODE

_r8k_project:
        ld      (pp), hl
        ld      (pc), de
        pop     bc              ; the return address
        pop     hl
        ld      (pout), hl
        pop     hl
        ld      (pm), hl
        pop     hl
        ld      (pe), hl
        push    bc
        ;; *m = r8_recip(c->z, e)
        ld      hl, (pe)
        push    hl
        ld      hl, (pc)
        ld      de, #8
        add     hl, de
        ld      e, (hl)
        inc     hl
        ld      d, (hl)         ; DE = z's low word
        inc     hl
        ld      a, (hl)
        inc     hl
        ld      h, (hl)
        ld      l, a            ; HL = its high word
        call    _r8_recip       ; (pops e) -> DE
        ld      hl, (pm)
        ld      (hl), e
        inc     hl
        ld      (hl), d
        ;; x and y within -32767..32767?
        ld      hl, (pc)
        call    fits16
        jp      nz, slow
        ld      hl, (pc)
        ld      bc, #4
        add     hl, bc
        call    fits16
        jp      nz, slow
        ;; lim = guard * 16 < 0x3FFF?
        ld      hl, (pp)
        ld      bc, #10
        add     hl, bc
        ld      a, (hl)
        inc     hl
        ld      h, (hl)
        ld      l, a
        add     hl, hl
        add     hl, hl
        add     hl, hl
        add     hl, hl          ; (r8_s16)(guard * 16)
        ld      (plim), hl
        ld      a, h
        xor     a, #0x80
        cp      a, #0xBF        ; signed lim < 0x3F00: fine; else look closer
        jr      c, 1$
        jp      nz, slow        ; lim >= 0x4000 (signed)
        ld      a, l
        cp      a, #0xFF
        jp      z, slow         ; lim = 0x3FFF
1$:     ;; k = m * fn
        ld      hl, (pm)
        ld      e, (hl)
        inc     hl
        ld      d, (hl)
        ld      hl, (pp)
        ld      bc, #12
        add     hl, bc
        ld      a, (hl)
        inc     hl
        ld      h, (hl)
        ld      l, a            ; HL = fn
        call    r8z_umul16      ; HL:DE = k
        ld      (pkk), hl       ; kh
        ld      b, d            ; bit 7: k's bit 15
        ld      hl, (pp)        ; sh = 31 + fsh - e, 16 bits
        ld      de, #14
        add     hl, de
        ld      e, (hl)
        ld      d, #0
        ld      hl, #31
        add     hl, de
        ex      de, hl          ; DE = 31 + fsh
        ld      hl, (pe)
        ld      a, (hl)
        ld      l, a
        rla
        sbc     a, a
        ld      h, a            ; HL = e
        ex      de, hl
        or      a, a
        sbc     hl, de
        ex      de, hl          ; DE = sh
        ld      hl, (pkk)
        ld      a, h
        and     a, #0xC0
        jr      z, 3$
        ld      a, #16          ; kh >= 0x4000: kk = kh, sh -= 16
        jr      4$
3$:     sla     b               ; kk = kh << 1 | k >> 15, sh -= 15
        adc     hl, hl
        ld      (pkk), hl
        ld      a, #15
4$:     ld      l, a
        ld      h, #0
        ex      de, hl
        or      a, a
        sbc     hl, de          ; HL = sh
        bit     7, h            ; sh <= 0: r8_project_recip
        jp      nz, slow
        ld      a, h
        or      a, l
        jp      z, slow
        ld      a, h            ; sh > 31: 31
        or      a, a
        jr      nz, 6$
        ld      a, l
        cp      a, #32
        jr      c, 7$
6$:     ld      l, #31
7$:     dec     l
        ld      a, l
        ld      (psh), a
        ;; qx, qy
        ld      hl, (pc)
        call    round1          ; DE = qx, or CY: outside
        jp      c, out1
        ld      (pq), de
        ld      hl, (pc)
        ld      bc, #4
        add     hl, bc
        call    round1
        jp      c, out1
        ld      hl, (pp)        ; out[1] = cy + qy
        inc     hl
        inc     hl
        ld      a, (hl)
        inc     hl
        ld      h, (hl)
        ld      l, a
        add     hl, de
        ex      de, hl
        ld      hl, (pout)
        inc     hl
        inc     hl
        ld      (hl), e
        inc     hl
        ld      (hl), d
        ld      hl, (pp)        ; out[0] = cx + qx
        ld      a, (hl)
        inc     hl
        ld      h, (hl)
        ld      l, a
        ld      de, (pq)
        add     hl, de
        ex      de, hl
        ld      hl, (pout)
        ld      (hl), e
        inc     hl
        ld      (hl), d
        ld      de, #0
        ret
out1:   ld      de, #1
        ret

;; slow: return r8_project_recip(p, c, *m, *e, &out[0], &out[1])
slow:   pop     bc              ; the return address
        ld      hl, (pout)
        inc     hl
        inc     hl
        push    hl              ; sy
        dec     hl
        dec     hl
        push    hl              ; sx
        ld      hl, (pe)
        ld      a, (hl)
        push    af
        inc     sp              ; e
        ld      hl, (pm)
        ld      e, (hl)
        inc     hl
        ld      d, (hl)
        push    de              ; m
        push    bc
        ld      hl, (pp)
        ld      de, (pc)
        jp      _r8_project_recip   ; (pops its arguments; returns to ours)

;; fits16: Z if the r8_s32 at HL is in -32767..32767
fits16: ld      e, (hl)
        inc     hl
        ld      d, (hl)
        inc     hl
        ld      a, d
        rla
        sbc     a, a            ; the low word's sign, as a byte
        cp      a, (hl)
        ret     nz
        inc     hl
        cp      a, (hl)
        ret     nz
        ld      a, d            ; -32768 (0x8000) is out
        xor     a, #0x80
        or      a, e
        jr      z, 1$
        xor     a, a
        ret
1$:     inc     a               ; NZ
        ret

;; round1: the coordinate (r8_s32, 16-bit value) at HL: DE = round(v *
;; kk * 2^-sh) (proj_round with k = psh), CY set when it is outside the
;; guard band or too large
round1: ld      a, (hl)
        inc     hl
        ld      h, (hl)
        ld      l, a
        ld      de, (pkk)
        call    r8z_smul16      ; HL:DE = p
        ld      a, h
        rla                     ; CY: negative
        push    af
        jr      nc, 1$
        ld      a, h            ; u = ~p
        cpl
        ld      h, a
        ld      a, l
        cpl
        ld      l, a
        ld      a, d
        cpl
        ld      d, a
        ld      a, e
        cpl
        ld      e, a
1$:     ld      a, (psh)        ; u >>= k: 16, 8, then bits
        bit     4, a
        jr      z, 2$
        ex      de, hl
        ld      hl, #0
2$:     bit     3, a
        jr      z, 3$
        ld      e, d
        ld      d, l
        ld      l, h
        ld      h, #0
3$:     and     a, #7
        jr      z, 5$
        ld      b, a
4$:     srl     h
        rr      l
        rr      d
        rr      e
        djnz    4$
5$:     pop     af              ; CY: negative
        sbc     a, a
        ld      c, a            ; (bit 0 of C)
        ld      a, h
        or      a, l
        jr      nz, 9$          ; u >= 2^16
        ld      a, d            ; u >= 0x7FFE?
        cp      a, #0x7F
        jr      c, 6$
        jr      nz, 9$
        ld      a, e
        cp      a, #0xFE
        jr      nc, 9$
6$:     bit     0, c
        jr      z, 7$
        ld      a, d            ; t = ~t
        cpl
        ld      d, a
        ld      a, e
        cpl
        ld      e, a
7$:     ld      hl, #0x8001     ; t = ((t + 0x8001) >> 1) - 0x4000
        add     hl, de
        srl     h
        rr      l
        ld      a, h
        sub     a, #0x40
        ld      h, a
        ex      de, hl          ; DE = t
        ld      hl, (plim)      ; t > lim?  lim - t < 0
        or      a, a
        sbc     hl, de
        bit     7, h
        jr      nz, 9$
        ld      hl, (plim)      ; t < -lim?  lim + t < 0
        add     hl, de
        bit     7, h
        jr      nz, 9$
        or      a, a            ; CY clear: inside
        ret
9$:     scf
        ret
