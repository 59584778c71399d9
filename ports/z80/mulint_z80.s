;; mulint_z80.s - sdcc's 16-bit multiply helpers __mulint and __mul16 in
;; unrolled assembly (issue 10).  In the Z80 archive (mk/targets.mk,
;; Z80_ASM "mulint") ahead of sdcc's z80.lib, so every int * int of the
;; library (band and page offsets, the edge set-up's products) links this
;; one; sdcc's own (device/lib/z80/mul.s: a 16- or 8-pass shift-add loop,
;; ~460 T for a factor below 256) is the reference, and
;; tests/targets/test_z80_kern.c checks the products against a C89
;; shift-and-add model on random factors.
;;
;;   int __mulint(int a, int b): a in HL, b in DE; the low 16 bits of
;;   a * b in DE.  __mul16: BC * DE in DE (sdcc's __mulschar and friends,
;;   mulchar.s, jump there).  AF, BC, DE, HL changed; IX, IY kept.
;;
;; A factor below 256 is the multiplier of one unrolled 16 x 8 pass
;; (~300 T with call and return); else BC * E + ((C * D) << 8).
;; The cube / cull firmware (emu/z80sim, frames 1-3; docs/benchmarks.md,
;; "Z80: round 4"): 9,195 T a frame less than sdcc's, 63 B more.
        .module mulint_z80
        .area   _CODE

        .globl  __mulint
        .globl  __mul16

;; HL = 2 HL, plus DE if the next multiplier bit (out of A) is set
        .macro  ISTEP
        add     hl, hl
        add     a, a
        jr      nc, .+3
        add     hl, de
        .endm

__mulint:
        ld      c, l
        ld      b, h
__mul16:
        ld      a, b
        or      a, a
        jr      nz, 1$
        ld      a, c            ; BC < 256: DE * C
        jr      m8
1$:     ld      a, d
        or      a, a
        jr      nz, 2$
        ld      a, e            ; DE < 256: BC * E
        ld      e, c
        ld      d, b
        jr      m8
2$:     push    de              ; D: the multiplier's high byte
        ld      a, e
        ld      e, c
        ld      d, b
        call    m8              ; DE = BC * E, HL = BC
        pop     bc              ; B: the high byte
        ld      c, b
        ld      b, #8
        xor     a, a            ; A = the low byte of C * L
3$:     add     a, a
        sla     c
        jr      nc, 4$
        add     a, l
4$:     djnz    3$
        add     a, d
        ld      d, a
        ret

;; DE = DE * A (low 16 bits), HL = the DE it got
m8:     ld      hl, #0
        add     a, a            ; the first bit: HL = 0 or DE
        jr      nc, 5$
        ld      h, d
        ld      l, e
5$:     ISTEP
        ISTEP
        ISTEP
        ISTEP
        ISTEP
        ISTEP
        ISTEP
        ex      de, hl
        ret
