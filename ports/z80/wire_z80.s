;; wire_z80.s - the wire encoder's kernels for the Z80 (sdcc 4.2, sdas;
;; issue 10): r8_crc16_update, r8_crc16_mul, r8_tx_zeros, r8_tx_run and
;; r8_tx_lit, in the Z80 archive with -DR8_ASM_WIRE (mk/targets.mk,
;; Z80_ASM).  Their C89 references are the *_c functions of src/crc16.c
;; and src/wire.c (src/r8crc.h has the contracts; ports/avr/wire_avr.S is
;; the AVR version); tests/c/test_wirek.c checks, in the simulator, that
;; both give the same results on random inputs.
;;
;; sdcc's __sdcccall(1): the first argument in HL, a 16-bit second in DE,
;; the rest on the stack (popped here: every result is 8 or 16 bits); an
;; 8-bit result in A, a 16-bit one in DE.  IX is kept; IY and the
;; alternate registers are used.
;;
;; The CRC-16/CCITT-FALSE byte step uses a 512-byte table, T[i] = i *
;; x^16 mod P (the high bytes, then the low bytes), on a 256-byte
;; boundary: its own area _R8TAB, which ports/z80/z80link.py places at
;; 0x0200 (the code then starts after it).  With the crc in B (high) and
;; C (low), H = the table's page:
;;     ld a, byte; xor b; ld l, a; ld a, (hl); xor c; ld b, a;
;;     inc h; ld c, (hl); dec h                                  (46 T)
;; r8_tx_lit copies, CRCs, Fletcher-sums and links its literals in one
;; loop (~120 T a byte; its run-of-3 scan ~31 T a position); r8_tx_run
;; scans ~22 T a byte (16 compares a round); r8_tx_zeros 16
;; bytes at a time (~14.5 T a byte); r8_crc16_mul is 16 shift-xor steps
;; and two table reductions.
;; When these kernels were first written (round 4; bench/kernz80.py,
;; emu/z80sim, frames 1-3) the cube / cull firmware went from 1,612,609
;; to 1,177,491 T a frame (-27%), the image 1,531 bytes larger (512 of
;; them the table); round 8's figures are in docs/benchmarks.md.
        .module wire_z80

        .globl  _r8_crc16_update
        .globl  _r8_crc16_mul
        .globl  _r8_tx_zeros
        .globl  _r8_tx_run
        .globl  _r8_tx_lit
        .globl  _r8_crc16_shift         ; src/crc16.c
        .globl  r8z_crctab              ; (txband_z80.s steps with it too)

;; undocumented halves of IY (sdas has no names for them)
        .macro  LD_A_IYH
        .db     0xFD, 0x7C
        .endm
        .macro  LD_A_IYL
        .db     0xFD, 0x7D
        .endm
        .macro  LD_IYH_A
        .db     0xFD, 0x67
        .endm
        .macro  DEC_IYL
        .db     0xFD, 0x2D
        .endm
        .macro  DEC_IYH
        .db     0xFD, 0x25
        .endm

;; the table step: byte in A, crc in B:C, H = the table's page
        .macro  CRCSTEP
        xor     a, b
        ld      l, a
        ld      a, (hl)
        xor     a, c
        ld      b, a
        inc     h
        ld      c, (hl)
        dec     h
        .endm

        .area   _R8TAB
r8z_crctab:
        .db     0x00, 0x10, 0x20, 0x30, 0x40, 0x50, 0x60, 0x70, 0x81, 0x91, 0xA1, 0xB1, 0xC1, 0xD1, 0xE1, 0xF1
        .db     0x12, 0x02, 0x32, 0x22, 0x52, 0x42, 0x72, 0x62, 0x93, 0x83, 0xB3, 0xA3, 0xD3, 0xC3, 0xF3, 0xE3
        .db     0x24, 0x34, 0x04, 0x14, 0x64, 0x74, 0x44, 0x54, 0xA5, 0xB5, 0x85, 0x95, 0xE5, 0xF5, 0xC5, 0xD5
        .db     0x36, 0x26, 0x16, 0x06, 0x76, 0x66, 0x56, 0x46, 0xB7, 0xA7, 0x97, 0x87, 0xF7, 0xE7, 0xD7, 0xC7
        .db     0x48, 0x58, 0x68, 0x78, 0x08, 0x18, 0x28, 0x38, 0xC9, 0xD9, 0xE9, 0xF9, 0x89, 0x99, 0xA9, 0xB9
        .db     0x5A, 0x4A, 0x7A, 0x6A, 0x1A, 0x0A, 0x3A, 0x2A, 0xDB, 0xCB, 0xFB, 0xEB, 0x9B, 0x8B, 0xBB, 0xAB
        .db     0x6C, 0x7C, 0x4C, 0x5C, 0x2C, 0x3C, 0x0C, 0x1C, 0xED, 0xFD, 0xCD, 0xDD, 0xAD, 0xBD, 0x8D, 0x9D
        .db     0x7E, 0x6E, 0x5E, 0x4E, 0x3E, 0x2E, 0x1E, 0x0E, 0xFF, 0xEF, 0xDF, 0xCF, 0xBF, 0xAF, 0x9F, 0x8F
        .db     0x91, 0x81, 0xB1, 0xA1, 0xD1, 0xC1, 0xF1, 0xE1, 0x10, 0x00, 0x30, 0x20, 0x50, 0x40, 0x70, 0x60
        .db     0x83, 0x93, 0xA3, 0xB3, 0xC3, 0xD3, 0xE3, 0xF3, 0x02, 0x12, 0x22, 0x32, 0x42, 0x52, 0x62, 0x72
        .db     0xB5, 0xA5, 0x95, 0x85, 0xF5, 0xE5, 0xD5, 0xC5, 0x34, 0x24, 0x14, 0x04, 0x74, 0x64, 0x54, 0x44
        .db     0xA7, 0xB7, 0x87, 0x97, 0xE7, 0xF7, 0xC7, 0xD7, 0x26, 0x36, 0x06, 0x16, 0x66, 0x76, 0x46, 0x56
        .db     0xD9, 0xC9, 0xF9, 0xE9, 0x99, 0x89, 0xB9, 0xA9, 0x58, 0x48, 0x78, 0x68, 0x18, 0x08, 0x38, 0x28
        .db     0xCB, 0xDB, 0xEB, 0xFB, 0x8B, 0x9B, 0xAB, 0xBB, 0x4A, 0x5A, 0x6A, 0x7A, 0x0A, 0x1A, 0x2A, 0x3A
        .db     0xFD, 0xED, 0xDD, 0xCD, 0xBD, 0xAD, 0x9D, 0x8D, 0x7C, 0x6C, 0x5C, 0x4C, 0x3C, 0x2C, 0x1C, 0x0C
        .db     0xEF, 0xFF, 0xCF, 0xDF, 0xAF, 0xBF, 0x8F, 0x9F, 0x6E, 0x7E, 0x4E, 0x5E, 0x2E, 0x3E, 0x0E, 0x1E
        .db     0x00, 0x21, 0x42, 0x63, 0x84, 0xA5, 0xC6, 0xE7, 0x08, 0x29, 0x4A, 0x6B, 0x8C, 0xAD, 0xCE, 0xEF
        .db     0x31, 0x10, 0x73, 0x52, 0xB5, 0x94, 0xF7, 0xD6, 0x39, 0x18, 0x7B, 0x5A, 0xBD, 0x9C, 0xFF, 0xDE
        .db     0x62, 0x43, 0x20, 0x01, 0xE6, 0xC7, 0xA4, 0x85, 0x6A, 0x4B, 0x28, 0x09, 0xEE, 0xCF, 0xAC, 0x8D
        .db     0x53, 0x72, 0x11, 0x30, 0xD7, 0xF6, 0x95, 0xB4, 0x5B, 0x7A, 0x19, 0x38, 0xDF, 0xFE, 0x9D, 0xBC
        .db     0xC4, 0xE5, 0x86, 0xA7, 0x40, 0x61, 0x02, 0x23, 0xCC, 0xED, 0x8E, 0xAF, 0x48, 0x69, 0x0A, 0x2B
        .db     0xF5, 0xD4, 0xB7, 0x96, 0x71, 0x50, 0x33, 0x12, 0xFD, 0xDC, 0xBF, 0x9E, 0x79, 0x58, 0x3B, 0x1A
        .db     0xA6, 0x87, 0xE4, 0xC5, 0x22, 0x03, 0x60, 0x41, 0xAE, 0x8F, 0xEC, 0xCD, 0x2A, 0x0B, 0x68, 0x49
        .db     0x97, 0xB6, 0xD5, 0xF4, 0x13, 0x32, 0x51, 0x70, 0x9F, 0xBE, 0xDD, 0xFC, 0x1B, 0x3A, 0x59, 0x78
        .db     0x88, 0xA9, 0xCA, 0xEB, 0x0C, 0x2D, 0x4E, 0x6F, 0x80, 0xA1, 0xC2, 0xE3, 0x04, 0x25, 0x46, 0x67
        .db     0xB9, 0x98, 0xFB, 0xDA, 0x3D, 0x1C, 0x7F, 0x5E, 0xB1, 0x90, 0xF3, 0xD2, 0x35, 0x14, 0x77, 0x56
        .db     0xEA, 0xCB, 0xA8, 0x89, 0x6E, 0x4F, 0x2C, 0x0D, 0xE2, 0xC3, 0xA0, 0x81, 0x66, 0x47, 0x24, 0x05
        .db     0xDB, 0xFA, 0x99, 0xB8, 0x5F, 0x7E, 0x1D, 0x3C, 0xD3, 0xF2, 0x91, 0xB0, 0x57, 0x76, 0x15, 0x34
        .db     0x4C, 0x6D, 0x0E, 0x2F, 0xC8, 0xE9, 0x8A, 0xAB, 0x44, 0x65, 0x06, 0x27, 0xC0, 0xE1, 0x82, 0xA3
        .db     0x7D, 0x5C, 0x3F, 0x1E, 0xF9, 0xD8, 0xBB, 0x9A, 0x75, 0x54, 0x37, 0x16, 0xF1, 0xD0, 0xB3, 0x92
        .db     0x2E, 0x0F, 0x6C, 0x4D, 0xAA, 0x8B, 0xE8, 0xC9, 0x26, 0x07, 0x64, 0x45, 0xA2, 0x83, 0xE0, 0xC1
        .db     0x1F, 0x3E, 0x5D, 0x7C, 0x9B, 0xBA, 0xD9, 0xF8, 0x17, 0x36, 0x55, 0x74, 0x93, 0xB2, 0xD1, 0xF0

        .area   _CODE

;; r8_u16 r8_crc16_update(r8_u16 crc, const r8_u8 *p, unsigned n)
;;   crc HL, p DE, n on the stack -> DE                     ~71 T a byte
_r8_crc16_update:
        pop     bc              ; the return address
        pop     iy              ; n
        push    bc
        ld      b, h
        ld      c, l
        LD_A_IYL                ; the count: IYL (0 = 256), IYH passes
        or      a, a
        LD_A_IYH
        jr      z, 1$
        inc     a
1$:     or      a, a
        jr      z, 3$           ; n = 0
        LD_IYH_A
        ld      h, #>r8z_crctab
2$:     ld      a, (de)
        inc     de
        CRCSTEP
        DEC_IYL
        jr      nz, 2$
        DEC_IYH
        jr      nz, 2$
3$:     ld      d, b
        ld      e, c
        ret

;; r8_u16 r8_crc16_mul(r8_u16 a, r8_u16 b): a * b modulo x^16 + x^12 +
;; x^5 + 1.  a HL, b DE -> DE.  Horner over b's two bytes, each a
;; carry-less 16 x 8 product into 24 bits with the reduction left to the
;; end: E holds the multiplier byte; add hl, hl; rl e shifts the 24-bit
;; E:H:L, the multiplier's next bit into carry and the product's top bit
;; into E's bottom, so after 8 steps E is the product's top byte (x^16 to
;; x^23), which the CRC table reduces (T[E] = E * x^16 mod P).  The
;; second byte starts from the first's result: r * x^8 + a * bl.
;;                                        ~800 T (was ~1100 bit by bit)
;; the top byte reduced by the table: from E:H:L, D = the high byte of
;; the result and A its low byte (H, L changed)
        .macro  REDUCE
        ex      de, hl          ; D:E = the low 16 bits, L = the top byte
        ld      h, #>r8z_crctab
        ld      a, (hl)
        xor     a, d
        ld      d, a
        inc     h
        ld      a, (hl)
        xor     a, e
        .endm
        .macro  MULBIT
        add     hl, hl          ; E:H:L * x, b's next bit into carry
        rl      e
        jr      nc, .+8         ; (. is the jr itself: 2 + 6 bytes)
        ld      a, h            ; + a
        xor     a, b
        ld      h, a
        ld      a, l
        xor     a, c
        ld      l, a
        .endm
_r8_crc16_mul:
        ld      b, h
        ld      c, l            ; BC = a
        push    de              ; b's low byte for the second pass
        ld      e, d            ; E = b's high byte
        ld      hl, #0
        .rept   8
        MULBIT
        .endm
        REDUCE
        ld      l, a
        ld      h, d            ; HL = a * bh mod P
        pop     de              ; E = b's low byte
        .rept   8
        MULBIT
        .endm
        REDUCE
        ld      e, a            ; DE = a * b mod P
        ret

;; unsigned r8_tx_zeros(const r8_u8 *p, unsigned n): how many bytes of
;; p[0..n) are 0x00 before the first other.  p HL, n DE -> DE.
;; 16 bytes a pass (`or (hl); inc hl`, ~14.5 T a byte; was 8 a pass with
;; a 16-bit count, ~24 T), the pass with a non-zero again byte by byte
;; (it stops there: no count), then the n mod 16 left.
        .macro  OR2
        or      a, (hl)
        inc     hl
        or      a, (hl)
        inc     hl
        .endm
_r8_tx_zeros:
        push    hl
        ld      a, e
        and     a, #0x0F
        ld      c, a            ; C = n mod 16
        srl     d
        rr      e
        srl     d
        rr      e
        srl     d
        rr      e
        srl     d
        rr      e               ; DE = the passes
        ld      a, d
        or      a, e
        jr      z, 3$
        ld      b, e            ; B: the passes of the first round (0 = 256),
        ld      a, e            ; D: the rounds
        or      a, a
        jr      z, 1$
        inc     d
1$:     xor     a, a
        OR2
        OR2
        OR2
        OR2
        OR2
        OR2
        OR2
        OR2
        jr      nz, 4$
        djnz    1$
        dec     d
        jr      nz, 1$
3$:     ld      a, c            ; the n mod 16 left
        or      a, a
        jr      z, 6$
        ld      b, a
2$:     ld      a, (hl)
        or      a, a
        jr      nz, 6$
        inc     hl
        djnz    2$
        jr      6$
4$:     ld      de, #-16        ; a non-zero among these 16: it ends the scan
        add     hl, de
5$:     ld      a, (hl)
        or      a, a
        jr      nz, 6$
        inc     hl
        jr      5$
6$:     pop     de              ; HL - p
        or      a, a
        sbc     hl, de
        ex      de, hl
        ret

;; r8_u8 r8_tx_run(r8_tx_st *s, r8_u8 *o, const r8_u8 *p, r8_u8 k)
;;   s HL, o DE, p and k on the stack -> A (the count)
;; r8_tx_st: +0 crc (low, high), +2 f1, +3 f2, +6 code, +8 g.
        .macro  SCANV           ; 4 compares with v (A), HL on
        cp      a, (hl)
        jr      nz, scanv_out
        inc     hl
        cp      a, (hl)
        jr      nz, scanv_out
        inc     hl
        cp      a, (hl)
        jr      nz, scanv_out
        inc     hl
        cp      a, (hl)
        jr      nz, scanv_out
        inc     hl
        .endm
_r8_tx_run:
        push    hl
        pop     iy              ; IY = s
        ld      hl, #2
        add     hl, sp
        ld      a, (hl)
        inc     hl
        ld      h, (hl)
        ld      l, a            ; HL = p
        ld      a, (hl)         ; v
        push    hl              ; p
        ld      hl, #6
        add     hl, sp
        ld      b, (hl)         ; k
        pop     hl
        inc     hl
        inc     hl
        inc     hl              ; p + 3
        ld      c, a            ; v
        ld      a, b
        sub     a, #3           ; the bytes left to look at: k - 3
        jr      z, scanv_cnt
        ;; 16 compares unrolled a round (~22 T a byte; a djnz loop took
        ;; 33): the first round enters the run at its (k - 3) mod 16th
        ;; compare from the end (through the stack and ret)
        push    de              ; o
        ld      b, a
        neg
        and     a, #0x0F        ; the compares the first round skips
        add     a, a
        add     a, a            ; (4 bytes each)
        add     a, #<scanv
        ld      e, a
        ld      a, #>scanv
        adc     a, #0
        ld      d, a
        push    de
        ld      a, b
        add     a, #15
        rrca
        rrca
        rrca
        rrca
        and     a, #0x0F
        ld      b, a            ; the rounds: (k - 3 + 15) / 16 (k <= 127)
        ld      a, c
        ret                     ; into the round
scanv:  SCANV
        SCANV
        SCANV
        SCANV
        djnz    scanv
scanv_out:
        pop     de              ; o
scanv_cnt:
        ld      a, l            ; the count: HL - p (< 128)
        ld      hl, #2
        add     hl, sp
        sub     a, (hl)
        ld      b, a            ; B = count, C = v
        ex      de, hl
        ld      (hl), b         ; o[0] = count
        inc     hl
        ld      (hl), c         ; o[1] = v
        push    bc              ; count, v
        ld      d, b
        ld      e, c
        ld      c, 0 (iy)       ; the packet CRC over them
        ld      b, 1 (iy)
        ld      h, #>r8z_crctab
        ld      a, d
        CRCSTEP
        ld      a, e
        CRCSTEP
        ld      0 (iy), c
        ld      1 (iy), b
        ld      a, e
        or      a, a
        jr      z, 5$
        ;; another byte: count steps of it in the band's CRC and Fletcher
        ld      c, 8 (iy)
        ld      b, 9 (iy)
3$:     ld      a, e
        CRCSTEP
        dec     d
        jr      nz, 3$
        ld      8 (iy), c
        ld      9 (iy), b
        pop     de              ; D = count, E = v
        push    de
        ld      c, 2 (iy)       ; f1
        ld      b, 3 (iy)       ; f2
4$:     ld      a, c
        add     a, e
        ld      c, a
        add     a, b
        ld      b, a
        dec     d
        jr      nz, 4$
        ld      2 (iy), c
        ld      3 (iy), b
        jr      7$
5$:     ;; zeros: f2 += count * f1; g = g * x^(8 count)
        ld      a, 2 (iy)       ; f1
        ld      e, d            ; count (< 128)
        ld      d, #0
        ld      b, #0
        ld      hl, #0          ; HL = f1 * count (8 shift-add steps)
        ld      c, a
6$:     srl     c
        jr      nc, 61$
        add     hl, de
61$:    sla     e
        rl      d
        ld      a, c
        or      a, a
        jr      nz, 6$
        ld      a, 3 (iy)
        add     a, l
        ld      3 (iy), a
        pop     de              ; D = count
        push    de
        push    iy
        ld      l, 8 (iy)
        ld      h, 9 (iy)
        push    de
        inc     sp              ; the count, one byte on the stack
        call    _r8_crc16_shift ; (pops it) -> DE
        pop     iy
        ld      8 (iy), e
        ld      9 (iy), d
7$:     pop     bc              ; B = count
        ld      a, b
        pop     hl              ; the return address; p, k popped
        pop     bc
        inc     sp
        jp      (hl)

;; r8_u8 r8_tx_lit(r8_tx_st *s, r8_u8 *o, const r8_u8 *p, r8_u8 k, r8_u8 c)
;;   s HL, o DE, p, k and c on the stack -> A
;; The literals: up to the first run of 3 among the first k positions,
;; else c; [0x80 | L, the L bytes] at o; the packet CRC, the band's CRC
;; (g = (g ^ Pb) * x^(8L) ^ Pa) and Fletcher sums; every 0x00 linked into
;; the COBS chain unless it has stopped (bit 7 of the result: a block got
;; too long, the caller undoes the chain).
        .macro  LITPOS          ; p[i + 1] = p[i] (in A)? HL = p + i on
        inc     hl
        cp      a, (hl)
        call    z, litcand
        ld      a, (hl)
        .endm
_r8_tx_lit:
        push    hl
        pop     iy              ; IY = s
        ld      hl, #2
        add     hl, sp
        ld      a, (hl)
        inc     hl
        ld      b, (hl)
        inc     hl
        push    de              ; o
        ld      e, a
        ld      d, b            ; DE = p
        ld      b, (hl)         ; k
        inc     hl
        ld      c, (hl)         ; c
        ex      de, hl          ; HL = p
        push    hl
        ld      a, b            ; scan: the first run of 3 among k positions,
        or      a, a            ; 16 unrolled a round (~31 T a position; a
        jp      z, lit_scanned  ; djnz loop took 40), the first round
        neg                     ; entered at its k mod 16th position from
        and     a, #0x0F        ; the end (through the stack and ret)
        ld      e, a
        add     a, a
        add     a, e
        add     a, a            ; (6 bytes each)
        add     a, #<litscan
        ld      e, a
        ld      a, #>litscan
        adc     a, #0
        ld      d, a
        ld      a, b
        add     a, #15
        rrca
        rrca
        rrca
        rrca
        and     a, #0x0F
        ld      b, a            ; the rounds: (k + 15) / 16 (k <= 127)
        ld      a, (hl)         ; p[0]
        push    de
        ret                     ; into the round
litscan:
        LITPOS
        LITPOS
        LITPOS
        LITPOS
        LITPOS
        LITPOS
        LITPOS
        LITPOS
        LITPOS
        LITPOS
        LITPOS
        LITPOS
        LITPOS
        LITPOS
        LITPOS
        LITPOS
        djnz    litscan
        jr      lit_scanned
;; p[i + 1] = p[i] = A, HL = p + i + 1: p[i + 2] too?
litcand:
        inc     hl
        cp      a, (hl)
        dec     hl
        ret     nz              ; no: on with the scan
        ld      a, l            ; a run at i: L = i = HL - 1 - p (< 128)
        pop     de              ; (the scan's return address: dropped)
        pop     hl              ; p
        push    hl
        sub     a, l
        dec     a
        ld      c, a
lit_scanned:
        pop     hl              ; HL = p
        pop     de              ; DE = o
        ld      a, c
        or      a, #0x80
        ld      (de), a         ; o[0] = 0x80 | L
        inc     de
        exx
        ld      c, 0 (iy)       ; the packet CRC
        ld      b, 1 (iy)
        ld      h, #>r8z_crctab
        CRCSTEP
        push    bc              ; Pb
        ld      e, 2 (iy)       ; f1
        ld      d, 3 (iy)       ; f2
        exx
        ld      a, c
        ld      (lit_n), a
        ld      b, a            ; the count
        ld      c, #0           ; bit 7: the chain got too long
        or      a, a
        jr      z, 7$
        ;; the literals: main HL = p, DE = o + 1 + i, B = left, C = stop;
        ;; alternate: B:C = crc, E = f1, D = f2, H = the table
5$:     ld      a, (hl)
        ld      (de), a
        or      a, a
        jr      z, 8$
6$:     inc     hl
        inc     de
        exx
        ld      l, a
        add     a, e
        ld      e, a
        add     a, d
        ld      d, a
        ld      a, l
        CRCSTEP
        exx
        djnz    5$
7$:     ld      a, c
        ld      (lit_stop), a
        exx
        ld      0 (iy), c       ; s->crc
        ld      1 (iy), b
        ld      2 (iy), e
        ld      3 (iy), d
        ld      l, 8 (iy)       ; g ^ Pb
        ld      h, 9 (iy)
        pop     de
        ld      a, l
        xor     a, e
        ld      l, a
        ld      a, h
        xor     a, d
        ld      h, a
        push    iy
        ld      a, (lit_n)
        push    af
        inc     sp              ; L, one byte on the stack
        call    _r8_crc16_shift ; (pops it) -> DE
        pop     iy
        ld      a, 0 (iy)       ; ^ Pa
        xor     a, e
        ld      8 (iy), a
        ld      a, 1 (iy)
        xor     a, d
        ld      9 (iy), a
        ld      a, (lit_n)
        ld      hl, #lit_stop
        or      a, (hl)
        pop     hl              ; the return address; p, k, c popped
        pop     bc
        pop     bc
        jp      (hl)
8$:     ;; a 0x00 at q = DE: link it unless the chain has stopped
        bit     7, c
        jp      nz, 6$
        push    hl
        ld      l, 6 (iy)
        ld      h, 7 (iy)       ; code
        ld      a, h
        or      a, l
        jr      z, 10$          ; no chain
        push    de
        ex      de, hl          ; HL = q, DE = code
        or      a, a
        sbc     hl, de          ; q - code
        ld      a, h
        or      a, a
        jr      nz, 9$
        ld      a, l
        cp      a, #255
        jr      nc, 9$
        ld      (de), a         ; *code = q - code
        pop     de
        ld      6 (iy), e       ; code = q
        ld      7 (iy), d
        pop     hl
        xor     a, a
        jp      6$
9$:     pop     de              ; too far: stop (the caller undoes)
        ld      c, #0x80
10$:    pop     hl
        xor     a, a
        jp      6$

        .area   _DATA
lit_n:  .ds     1
lit_stop: .ds   1
