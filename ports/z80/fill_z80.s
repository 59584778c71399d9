;; fill_z80.s - void r8k_fill(r8_u8 *p, r8_u8 v, unsigned n) for the Z80
;; (sdcc 4.2, sdas; issue 10): p[0..n) = v, the band clear of
;; r8_render_band.  Its C89 reference is src/kern.c's (memset), left out
;; of the library with -DR8_ASM_FILL (mk/targets.mk, Z80_ASM "fill");
;; tests/targets/test_z80_kern.c (step xkern-z80) compares the two on
;; random lengths and offsets, the bytes around them included.
;;
;; sdcc's __sdcccall(1): p in HL, v and n on the stack (one byte, then two;
;; this function pops them: it returns void).  IX is kept.
;;
;; n mod 16 bytes one at a time, then 16 unrolled `ld (hl), a; inc hl`
;; a pass: 13.2 T a byte against 21 for sdcc's memset (ldir).
;; The cube / cull firmware (emu/z80sim, frames 1-3; docs/benchmarks.md,
;; "Z80: round 4"): 8,014 T a frame less than the C reference, 51 B more.
        .module fill_z80
        .area   _CODE
        .globl  _r8k_fill

_r8k_fill:
        pop     bc              ; the return address
        dec     sp
        pop     af              ; A = v (F: the byte below it)
        pop     de              ; DE = n
        push    bc
        ld      c, a
        ld      a, e
        and     a, #0x0F
        jr      z, 2$
        ld      b, a
1$:     ld      (hl), c         ; n mod 16 bytes
        inc     hl
        djnz    1$
2$:     srl     d               ; DE = n / 16 passes
        rr      e
        srl     d
        rr      e
        srl     d
        rr      e
        srl     d
        rr      e
        ld      a, e
        or      a, d
        ret     z
        ld      b, e            ; B: the passes of the first round (0 = 256),
        ld      a, e            ; D: the rounds
        or      a, a
        jr      z, 3$
        inc     d
3$:     ld      a, c
4$:     ld      (hl), a
        inc     hl
        ld      (hl), a
        inc     hl
        ld      (hl), a
        inc     hl
        ld      (hl), a
        inc     hl
        ld      (hl), a
        inc     hl
        ld      (hl), a
        inc     hl
        ld      (hl), a
        inc     hl
        ld      (hl), a
        inc     hl
        ld      (hl), a
        inc     hl
        ld      (hl), a
        inc     hl
        ld      (hl), a
        inc     hl
        ld      (hl), a
        inc     hl
        ld      (hl), a
        inc     hl
        ld      (hl), a
        inc     hl
        ld      (hl), a
        inc     hl
        ld      (hl), a
        inc     hl
        djnz    4$
        dec     d
        jr      nz, 4$
        ret
