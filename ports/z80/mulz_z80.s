;; mulz_z80.s - the Z80 multiplies the assembly kernels share (sdcc 4.2,
;; sdas; issue 10): in the Z80 archive with any of them (mk/targets.mk).
;;
;;   r8z_mul8    DE * A -> A:HL (24 bits), unsigned; needs C = 0
;;   r8z_umul16  DE * HL -> HL:DE (32 bits), unsigned
;;   r8z_smul16  HL * DE -> HL:DE (32 bits), signed: r8_mul16's body
;;               (mul16_z80.s), C-callable as r8_s32 r8z_mul16s(r8_s16,
;;               r8_s16) for tests/targets/test_z80_kern.c
;;
;; sdcc's __sdcccall(1): a in HL, b in DE; a 32-bit result in HL (high
;; word) : DE (low word).  AF, BC, DE, HL, IY and the alternate set may be
;; changed, IX (the caller's frame pointer) is kept.  These use AF' to
;; hold the result's sign (sdcc's code never keeps anything there).
;;
;; Speed (Zilog T-states, emu/z80sim): the multiplier's bits are shifted
;; out of A while the 24-bit product A:HL shifts in, 8 unrolled steps of
;; 27 or 37 T.  r8z_smul16 takes the magnitudes, and when either is below
;; 256 one such pass (~330 T with call and return); otherwise two
;; (~640 T).  sdcc's `r8_s32 p = a; p *= b;` (__mullong) took ~3900 T.
        .module mulz_z80
        .area   _CODE

        .globl  _r8z_mul16s
        .globl  r8z_mul8
        .globl  r8z_umul16
        .globl  r8z_smul16

;; one step of the 16x8 multiply: A:HL = 2 * A:HL (the next multiplier
;; bit into carry), plus DE if it was set
        .macro  MSTEP
        add     hl, hl
        rla
        jr      nc, .+4
        add     hl, de
        adc     a, c
        .endm

;; r8z_mul8: A:HL = DE * A (unsigned 16 x 8 -> 24 bits), C = 0 on entry
;; and exit; B and DE kept.  217..287 T with the call; a multiplier below
;; 64 (its top two bits 0: most of the cube's) two steps less, 190..240 T.
r8z_mul8:
        ld      hl, #0
        cp      a, #0x40
        jr      c, 2$
        add     a, a            ; the first step: HL = 0 or DE
        jr      nc, 1$
        ld      h, d
        ld      l, e
1$:     MSTEP
        MSTEP
        MSTEP
        MSTEP
        MSTEP
        MSTEP
        MSTEP
        ret
2$:     add     a, a            ; bits 7 and 6 are 0: from bit 5 (the
        add     a, a            ; bits shifted in below are 0, as are
        add     a, a            ; the product's above bit 21)
        jr      nc, 3$
        ld      h, d
        ld      l, e
3$:     MSTEP
        MSTEP
        MSTEP
        MSTEP
        MSTEP
        ret

;; r8z_umul16: HL:DE = DE * HL (unsigned 16 x 16 -> 32).  AF, BC changed.
;; One 16x8 pass when either factor is below 256.
r8z_umul16:
        ld      c, #0
        ld      a, h
        or      a, a
        jr      z, 2$           ; the multiplier HL is below 256
        ld      a, d
        or      a, a
        jr      nz, 3$
        ex      de, hl          ; DE was: it is the multiplier
2$:     ld      a, l
        call    r8z_mul8        ; A:HL = DE * L
        ex      de, hl
        ld      l, a
        ld      h, c
        ret
3$:     ; both 16 bits: DE * H (P1), DE * L (P2), P1 << 8 + P2
        push    hl
        ld      a, h
        call    r8z_mul8        ; A:HL = P1
        ex      (sp), hl        ; P1's low 16 bits saved, HL = the multiplier
        push    af              ; P1's top byte
        ld      a, l
        call    r8z_mul8        ; A:HL = P2
        ld      e, l            ; byte 0
        ld      c, a            ; P2's top byte
        ld      a, h
        pop     hl              ; H = P1's top byte
        ld      b, h
        pop     hl              ; P1's low 16 bits
        add     a, l
        ld      d, a            ; byte 1
        ld      a, c
        adc     a, h
        ld      l, a            ; byte 2
        ld      a, b
        adc     a, #0
        ld      h, a            ; byte 3
        ret

;; r8z_smul16: HL:DE = HL * DE, signed 16 x 16 -> 32.
_r8z_mul16s:
r8z_smul16:
        ld      a, h
        xor     a, d
        ex      af, af'         ; bit 7: the product is negative
        bit     7, h
        jr      z, 1$
        xor     a, a            ; HL = -HL (0x8000 stays: 32768 unsigned)
        sub     a, l
        ld      l, a
        sbc     a, a
        sub     a, h
        ld      h, a
1$:     bit     7, d
        jr      z, 2$
        xor     a, a
        sub     a, e
        ld      e, a
        sbc     a, a
        sub     a, d
        ld      d, a
2$:     call    r8z_umul16
        ex      af, af'
        add     a, a
        ret     nc
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
        ret
