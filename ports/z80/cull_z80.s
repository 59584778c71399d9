;; cull_z80.s - r8k_cull (include/r8kern.h) for the Z80 (sdcc 4.2, sdas;
;; issue 10): a face's 16-bit back-face test.  In the Z80 archive with
;; -DR8_ASM_CULL (mk/targets.mk, Z80_ASM "cull"); the C89 reference is
;; r8k_cull in src/kern.c, and tests/targets/test_z80_kern.c (step
;; xkern-z80) compares the two on random normals, vertices and eyes.
;;
;; int r8k_cull(const r8_s16 *n, const r8_s16 *v, const r8_vec3l *eye)
;; sdcc's __sdcccall(1): n in HL, v in DE, eye on the stack (popped here);
;; the result in DE.  IX is kept.
;;
;; -1 when a component of v lies outside [-1023, 1023]; else 1 if
;; n . (eye - 16 v) > 0, 0 if not (eye's low words, 16-bit differences,
;; the products and their sum in 32 bits, as the reference).  A zero
;; normal component is skipped; one whose low byte is 0 (the axis normals,
;; +-16384) is a single 8 x 16 multiply, its product shifted 8 left.
;; The firmware of a spinning mesh with flash normals (ports/fw_trim.c,
;; R8_CULL16) calls it from render.c in place of r8_cull_front.
;; Round 10 (k-z80g): cube / cull frames 2-3 (emu/z80sim -P -F 2, Zilog
;; T): the back-face tests 26,286 T a frame (r8_cull_front in C, with its
;; r8_mul16 and normal_of calls) -> 11,702 (r8k_cull with its multiplies);
;; the frames with trap_z80.s's round-10 changes 584,856 -> 560,101 T
;; (emu/sz80run.py, the mean of frames 2-3), the image 33,971 -> 33,667 B;
;; with mulz_z80.s's short r8z_mul8 557,541 T, 33,709 B.
        .module cull_z80
        .area   _CODE
        .globl  _r8k_cull
        .globl  r8z_smul16

        .area   _DATA
cd:     .ds     6               ; eye - 16 v, three r8_s16

        .area   _CODE

;; one component: HL = v + 2k (then + 2), DE = cd + 2k (then + 2), IY =
;; eye + 4k (then + 4); carry set when v's component is out of range
comp:   ld      c, (hl)
        inc     hl
        ld      b, (hl)
        inc     hl
        push    hl
        ld      hl, #1023
        add     hl, bc          ; x + 1023 (16 bits)
        ld      a, l
        sub     a, #0xFF
        ld      a, h
        sbc     a, #0x07        ; borrow iff x + 1023 <= 2046
        jr      nc, 1$
        ld      l, c
        ld      h, b
        add     hl, hl
        add     hl, hl
        add     hl, hl
        add     hl, hl          ; 16 x
        ld      c, l
        ld      b, h
        ld      l, 0 (iy)
        ld      h, 1 (iy)
        or      a, a
        sbc     hl, bc          ; eye - 16 x
        ex      de, hl
        ld      (hl), e
        inc     hl
        ld      (hl), d
        inc     hl
        ex      de, hl
        ld      bc, #4
        add     iy, bc
        pop     hl
        or      a, a            ; in range
        ret
1$:     pop     hl
        scf
        ret

;; the product n_k d_k into the sum HL':DE': HL = n + 2k (then + 2)
        .macro  DOT k, l1, l2, l3
        ld      c, (hl)
        inc     hl
        ld      b, (hl)
        inc     hl
        ld      a, b
        or      a, c
        jr      z, l3           ; n_k = 0: nothing to add
        push    hl
        ld      de, (cd + 2 * k)
        ld      a, c
        or      a, a
        jr      nz, l1
        ld      l, b            ; n_k = 256 b: (b d) << 8
        ld      a, b
        rla
        sbc     a, a
        ld      h, a            ; HL = b, signed
        call    r8z_smul16      ; HL:DE = b d (within 24 bits)
        ld      h, l
        ld      l, d
        ld      d, e
        ld      e, #0
        jr      l2
l1:     ld      l, c
        ld      h, b
        call    r8z_smul16      ; HL:DE = n_k d_k
l2:     push    hl
        push    de
        exx
        pop     bc
        ex      de, hl
        add     hl, bc
        ex      de, hl
        pop     bc
        adc     hl, bc
        exx
        pop     hl
l3:
        .endm

_r8k_cull:
        pop     bc              ; the return address
        pop     iy              ; eye
        push    bc
        push    hl              ; n
        ex      de, hl          ; HL = v
        ld      de, #cd
        call    comp
        jp      c, cbad
        call    comp
        jp      c, cbad
        call    comp
        jp      c, cbad
        exx
        ld      hl, #0          ; the sum HL':DE'
        ld      d, h
        ld      e, l
        exx
        pop     hl              ; n
        DOT     0, d0a, d0b, d0c
        DOT     1, d1a, d1b, d1c
        DOT     2, d2a, d2b, d2c
        exx                     ; sum > 0?
        ld      a, h
        exx
        ld      de, #0
        rla
        ret     c               ; negative: 0
        exx
        ld      a, h
        or      a, l
        or      a, d
        or      a, e
        exx
        ret     z               ; zero: 0
        inc     e               ; 1
        ret
cbad:   pop     hl
        ld      de, #-1
        ret
