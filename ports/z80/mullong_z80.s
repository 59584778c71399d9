;; mullong_z80.s - sdcc's 32-bit multiply helper __mullong, in assembly
;; (issue 10).  In the Z80 archive (mk/targets.mk, Z80_ASM) ahead of
;; sdcc's z80.lib, so every `r8_s32 p = a; p *= b;` of the library links
;; this one; sdcc's own (device/lib/_mullong.c, C: ~3900 T for 16-bit
;; factors) is the reference, and tests/targets/test_z80_kern.c checks
;; the two products equal (against a C89 schoolbook model) on random
;; factors.
;;
;;   long __mullong(long a, long b): a in HL (high word) : DE (low), b on
;;   the stack (low word first), left there for the caller; the low 32
;;   bits of a * b in HL:DE.
;;
;; Factors that are sign-extended 16-bit values (the library's products
;; of two r8_s16) take r8_mul16's path (r8z_smul16, mulz_z80.s): ~400-700 T.  Others:
;; a_lo * b_lo + ((a_lo * b_hi + a_hi * b_lo) << 16), up to three 16x16
;; passes (a zero high word skips its pass).
        .module mullong_z80
        .area   _CODE

        .globl  __mullong
        .globl  r8z_umul16
        .globl  r8z_smul16

__mullong:
        push    hl              ; a_hi
        ld      hl, #4
        add     hl, sp
        ld      c, (hl)
        inc     hl
        ld      b, (hl)         ; BC = b_lo
        inc     hl
        ld      a, b
        rlca
        sbc     a, a            ; b_lo's sign fill
        cp      a, (hl)
        jr      nz, 9$
        inc     hl
        cp      a, (hl)
        jr      nz, 9$          ; b_hi is not b_lo's sign extension
        ld      a, d
        rlca
        sbc     a, a            ; a_lo's sign fill
        pop     hl
        cp      a, h
        jr      nz, 8$
        cp      a, l
        jr      nz, 8$
        ld      h, b
        ld      l, c
        jp      r8z_smul16      ; HL:DE = b_lo * a_lo, signed
8$:     push    hl
9$:     ; the general case.  Stack: a_lo +0, a_hi +2, return +4, b_lo +6,
        ; b_hi +8 (IY)
        push    de
        ld      iy, #0
        add     iy, sp
        ld      hl, #0
        push    hl              ; the cross terms' sum
        ld      l, 8 (iy)
        ld      h, 9 (iy)
        ld      a, h
        or      a, l
        jr      z, 1$           ; b_hi = 0
        call    r8z_umul16      ; DE = low16(a_lo * b_hi)
        pop     hl
        add     hl, de
        push    hl
1$:     ld      e, 2 (iy)
        ld      d, 3 (iy)
        ld      a, d
        or      a, e
        jr      z, 2$           ; a_hi = 0
        ld      l, 6 (iy)
        ld      h, 7 (iy)
        call    r8z_umul16      ; DE = low16(a_hi * b_lo)
        pop     hl
        add     hl, de
        push    hl
2$:     ld      e, 0 (iy)
        ld      d, 1 (iy)
        ld      l, 6 (iy)
        ld      h, 7 (iy)
        call    r8z_umul16      ; HL:DE = a_lo * b_lo
        pop     bc
        add     hl, bc          ; + the cross terms << 16
        pop     bc
        pop     bc
        ret
