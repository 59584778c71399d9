/* wire_avr.S - AVR assembly for the wire encoder's kernels (issue 10).
 *
 * Built into the AVR library with -DR8_ASM_WIRE (mk/targets.mk); the C89
 * reference of each routine is the *_c function of the same name in
 * src/crc16.c and src/wire.c (src/r8crc.h has the contracts), and
 * tests/c/test_wirek.c checks, in the simulator, that both give the
 * same results on random inputs.
 *
 * avr-gcc ABI: arguments in r25:r24, r23:r22, r21:r20, r19:r18 (8-bit
 * ones in the low register), result in r24 (r25:r24); r18-r27, r30, r31
 * and r0 may be changed, r1 is 0, r2-r17 and r28-r29 are kept.
 *
 * The CRC-16/CCITT-FALSE byte step (as R8_CRC16_STEP in src/r8crc.h):
 *   x = hi ^ b;  x ^= x >> 4;
 *   hi' = lo ^ (x << 4) ^ (x >> 3);  lo' = (x << 5) ^ x      (17 cycles)
 * with x, t in upper registers (andi).  By default the step uses a
 * 512-byte table on a 256-byte page instead (11 cycles; flash: the table
 * and up to 255 bytes of padding before it); -DR8_AVR_NO_CRCTAB keeps
 * the table-free step.  STEP(hi, lo, b) is the one the kernels use: it
 * changes r25 and r23 (table-free) or r30 (with the table, r31 = the
 * table's page, set by TABPAGE).
 */
#define CRCSTEP(hi, lo, b, x, t) \
        mov     x, b            $ \
        eor     x, hi           $ \
        mov     t, x            $ \
        swap    t               $ \
        andi    t, 0x0F         $ \
        eor     x, t            $ \
        mov     t, x            $ \
        swap    t               $ \
        andi    t, 0xF0         $ \
        mov     hi, lo          $ \
        eor     hi, t           $ \
        lsl     t               $ \
        mov     lo, t           $ \
        eor     lo, x           $ \
        lsr     x               $ \
        lsr     x               $ \
        lsr     x               $ \
        eor     hi, x

/* The step with the table (r31 = its page): 11 cycles. */
#define CRCTAB(hi, lo, b) \
        mov     r30, b          $ \
        eor     r30, hi         $ \
        lpm     hi, Z           $ \
        eor     hi, lo          $ \
        inc     r31             $ \
        lpm     lo, Z           $ \
        dec     r31

#ifdef R8_AVR_NO_CRCTAB
#define STEP(hi, lo, b) CRCSTEP(hi, lo, b, r25, r23)
#define TABPAGE
#define LOWSECT(name) .section .text.name, "ax", @progbits
#else
#define STEP(hi, lo, b) CRCTAB(hi, lo, b)
#define TABPAGE ldi r31, hi8(r8_crc_tab)

/* r8_crc16_update and r8_tx_zeros (114 bytes) go in the padding before
 * the table: avr-libc's linker script puts the .progmem.gcc* sections
 * right after the interrupt vectors (140 bytes on the ATmega1284P, 104
 * on the 328P), in the order this file makes them, so these two come
 * before the page-aligned table instead of after it, and the flash they
 * take would otherwise be padding. */
#define LOWSECT(name) .section .progmem.gcc_r8a.name, "ax", @progbits
        LOWSECT(r8_crc16_update)
        LOWSECT(r8_tx_zeros)
/* The CRC table: T[i] = i * x^16 mod P; the high bytes, then the low
 * bytes, on a 256-byte page (the step needs no address arithmetic). */
        .section .progmem.gcc_r8crc, "a", @progbits
        .balign 256
r8_crc_tab:
        .byte   0x00, 0x10, 0x20, 0x30, 0x40, 0x50, 0x60, 0x70, 0x81, 0x91, 0xA1, 0xB1, 0xC1, 0xD1, 0xE1, 0xF1
        .byte   0x12, 0x02, 0x32, 0x22, 0x52, 0x42, 0x72, 0x62, 0x93, 0x83, 0xB3, 0xA3, 0xD3, 0xC3, 0xF3, 0xE3
        .byte   0x24, 0x34, 0x04, 0x14, 0x64, 0x74, 0x44, 0x54, 0xA5, 0xB5, 0x85, 0x95, 0xE5, 0xF5, 0xC5, 0xD5
        .byte   0x36, 0x26, 0x16, 0x06, 0x76, 0x66, 0x56, 0x46, 0xB7, 0xA7, 0x97, 0x87, 0xF7, 0xE7, 0xD7, 0xC7
        .byte   0x48, 0x58, 0x68, 0x78, 0x08, 0x18, 0x28, 0x38, 0xC9, 0xD9, 0xE9, 0xF9, 0x89, 0x99, 0xA9, 0xB9
        .byte   0x5A, 0x4A, 0x7A, 0x6A, 0x1A, 0x0A, 0x3A, 0x2A, 0xDB, 0xCB, 0xFB, 0xEB, 0x9B, 0x8B, 0xBB, 0xAB
        .byte   0x6C, 0x7C, 0x4C, 0x5C, 0x2C, 0x3C, 0x0C, 0x1C, 0xED, 0xFD, 0xCD, 0xDD, 0xAD, 0xBD, 0x8D, 0x9D
        .byte   0x7E, 0x6E, 0x5E, 0x4E, 0x3E, 0x2E, 0x1E, 0x0E, 0xFF, 0xEF, 0xDF, 0xCF, 0xBF, 0xAF, 0x9F, 0x8F
        .byte   0x91, 0x81, 0xB1, 0xA1, 0xD1, 0xC1, 0xF1, 0xE1, 0x10, 0x00, 0x30, 0x20, 0x50, 0x40, 0x70, 0x60
        .byte   0x83, 0x93, 0xA3, 0xB3, 0xC3, 0xD3, 0xE3, 0xF3, 0x02, 0x12, 0x22, 0x32, 0x42, 0x52, 0x62, 0x72
        .byte   0xB5, 0xA5, 0x95, 0x85, 0xF5, 0xE5, 0xD5, 0xC5, 0x34, 0x24, 0x14, 0x04, 0x74, 0x64, 0x54, 0x44
        .byte   0xA7, 0xB7, 0x87, 0x97, 0xE7, 0xF7, 0xC7, 0xD7, 0x26, 0x36, 0x06, 0x16, 0x66, 0x76, 0x46, 0x56
        .byte   0xD9, 0xC9, 0xF9, 0xE9, 0x99, 0x89, 0xB9, 0xA9, 0x58, 0x48, 0x78, 0x68, 0x18, 0x08, 0x38, 0x28
        .byte   0xCB, 0xDB, 0xEB, 0xFB, 0x8B, 0x9B, 0xAB, 0xBB, 0x4A, 0x5A, 0x6A, 0x7A, 0x0A, 0x1A, 0x2A, 0x3A
        .byte   0xFD, 0xED, 0xDD, 0xCD, 0xBD, 0xAD, 0x9D, 0x8D, 0x7C, 0x6C, 0x5C, 0x4C, 0x3C, 0x2C, 0x1C, 0x0C
        .byte   0xEF, 0xFF, 0xCF, 0xDF, 0xAF, 0xBF, 0x8F, 0x9F, 0x6E, 0x7E, 0x4E, 0x5E, 0x2E, 0x3E, 0x0E, 0x1E
        .byte   0x00, 0x21, 0x42, 0x63, 0x84, 0xA5, 0xC6, 0xE7, 0x08, 0x29, 0x4A, 0x6B, 0x8C, 0xAD, 0xCE, 0xEF
        .byte   0x31, 0x10, 0x73, 0x52, 0xB5, 0x94, 0xF7, 0xD6, 0x39, 0x18, 0x7B, 0x5A, 0xBD, 0x9C, 0xFF, 0xDE
        .byte   0x62, 0x43, 0x20, 0x01, 0xE6, 0xC7, 0xA4, 0x85, 0x6A, 0x4B, 0x28, 0x09, 0xEE, 0xCF, 0xAC, 0x8D
        .byte   0x53, 0x72, 0x11, 0x30, 0xD7, 0xF6, 0x95, 0xB4, 0x5B, 0x7A, 0x19, 0x38, 0xDF, 0xFE, 0x9D, 0xBC
        .byte   0xC4, 0xE5, 0x86, 0xA7, 0x40, 0x61, 0x02, 0x23, 0xCC, 0xED, 0x8E, 0xAF, 0x48, 0x69, 0x0A, 0x2B
        .byte   0xF5, 0xD4, 0xB7, 0x96, 0x71, 0x50, 0x33, 0x12, 0xFD, 0xDC, 0xBF, 0x9E, 0x79, 0x58, 0x3B, 0x1A
        .byte   0xA6, 0x87, 0xE4, 0xC5, 0x22, 0x03, 0x60, 0x41, 0xAE, 0x8F, 0xEC, 0xCD, 0x2A, 0x0B, 0x68, 0x49
        .byte   0x97, 0xB6, 0xD5, 0xF4, 0x13, 0x32, 0x51, 0x70, 0x9F, 0xBE, 0xDD, 0xFC, 0x1B, 0x3A, 0x59, 0x78
        .byte   0x88, 0xA9, 0xCA, 0xEB, 0x0C, 0x2D, 0x4E, 0x6F, 0x80, 0xA1, 0xC2, 0xE3, 0x04, 0x25, 0x46, 0x67
        .byte   0xB9, 0x98, 0xFB, 0xDA, 0x3D, 0x1C, 0x7F, 0x5E, 0xB1, 0x90, 0xF3, 0xD2, 0x35, 0x14, 0x77, 0x56
        .byte   0xEA, 0xCB, 0xA8, 0x89, 0x6E, 0x4F, 0x2C, 0x0D, 0xE2, 0xC3, 0xA0, 0x81, 0x66, 0x47, 0x24, 0x05
        .byte   0xDB, 0xFA, 0x99, 0xB8, 0x5F, 0x7E, 0x1D, 0x3C, 0xD3, 0xF2, 0x91, 0xB0, 0x57, 0x76, 0x15, 0x34
        .byte   0x4C, 0x6D, 0x0E, 0x2F, 0xC8, 0xE9, 0x8A, 0xAB, 0x44, 0x65, 0x06, 0x27, 0xC0, 0xE1, 0x82, 0xA3
        .byte   0x7D, 0x5C, 0x3F, 0x1E, 0xF9, 0xD8, 0xBB, 0x9A, 0x75, 0x54, 0x37, 0x16, 0xF1, 0xD0, 0xB3, 0x92
        .byte   0x2E, 0x0F, 0x6C, 0x4D, 0xAA, 0x8B, 0xE8, 0xC9, 0x26, 0x07, 0x64, 0x45, 0xA2, 0x83, 0xE0, 0xC1
        .byte   0x1F, 0x3E, 0x5D, 0x7C, 0x9B, 0xBA, 0xD9, 0xF8, 0x17, 0x36, 0x55, 0x74, 0x93, 0xB2, 0xD1, 0xF0
        .text
#endif

/* r8_u16 r8_crc16_update(r8_u16 crc, const r8_u8 *p, unsigned n)
 *   crc r25:r24, p r23:r22, n r21:r20 -> r25:r24  17 (23) cycles/byte
 * (Each routine has its own section: --gc-sections drops the unused.) */
        LOWSECT(r8_crc16_update)
        .global r8_crc16_update
        .type   r8_crc16_update, @function
r8_crc16_update:
        movw    r26, r22
        cp      r20, r1
        cpc     r21, r1
        breq    2f
        movw    r18, r24        /* crc: the step changes r25 */
        TABPAGE
1:      ld      r22, X+
        STEP(r19, r18, r22)
        subi    r20, 1
        sbci    r21, 0
        brne    1b
        movw    r24, r18
2:      ret
        .size   r8_crc16_update, . - r8_crc16_update

/* r8_u16 r8_crc16_mul(r8_u16 a, r8_u16 b): a * b modulo x^16 + x^12 +
 * x^5 + 1.  a r25:r24, b r23:r22 -> r25:r24.  Shift and add over the
 * bits of b, most significant first, 4 bits a loop.    ~150 cycles */
#define MULBIT \
        lsl     r24             $ \
        rol     r25             $ \
        brcc    .+4             $ \
        eor     r24, r20        $ \
        eor     r25, r21        $ \
        lsl     r22             $ \
        rol     r23             $ \
        brcc    .+4             $ \
        eor     r24, r26        $ \
        eor     r25, r27

        .section .text.r8_crc16_mul, "ax", @progbits
        .global r8_crc16_mul
        .type   r8_crc16_mul, @function
r8_crc16_mul:
        movw    r26, r24        /* X = a */
        clr     r24
        clr     r25             /* r = 0 */
        ldi     r20, 0x21
        ldi     r21, 0x10       /* the polynomial */
        ldi     r18, 4
1:      MULBIT
        MULBIT
        MULBIT
        MULBIT
        dec     r18
        brne    1b
        ret
        .size   r8_crc16_mul, . - r8_crc16_mul

/* r8_u8 r8_tx_run(r8_tx_st *s, r8_u8 *o, const r8_u8 *p, r8_u8 k)
 *   s r25:r24, o r23:r22, p r21:r20, k r18 -> r24 (the count)
 * r8_tx_st: +0 crc (low, high), +2 f1, +3 f2, +8 g (low, high).
 * The run: zeros 8 at a time (~3.6 cycles a byte), others one by one. */
        .section .text.r8_tx_run, "ax", @progbits
        .global r8_tx_run
        .type   r8_tx_run, @function
r8_tx_run:
        push    r16
        push    r28
        push    r29
        movw    r28, r24        /* Y = s */
        movw    r26, r20        /* X = p */
        ld      r20, X          /* v */
        adiw    r26, 3
        mov     r19, r18
        subi    r19, 3          /* bytes left to look at */
        tst     r20
        brne    3f
1:      cpi     r19, 8
        brlo    3f
        ld      r21, X+
        ld      r25, X+
        or      r21, r25
        ld      r25, X+
        or      r21, r25
        ld      r25, X+
        or      r21, r25
        ld      r25, X+
        or      r21, r25
        ld      r25, X+
        or      r21, r25
        ld      r25, X+
        or      r21, r25
        ld      r25, X+
        or      r21, r25
        brne    2f
        subi    r19, 8
        rjmp    1b
2:      sbiw    r26, 8          /* a non-zero among these 8 */
3:      tst     r19
        breq    5f
4:      ld      r21, X+
        cp      r21, r20
        brne    5f
        dec     r19
        brne    4b
5:      mov     r16, r18
        sub     r16, r19        /* the count */
        movw    r30, r22
        st      Z, r16
        std     Z+1, r20
        TABPAGE
        ld      r18, Y
        ldd     r19, Y+1
        STEP(r19, r18, r16)
        STEP(r19, r18, r20)
        st      Y, r18
        std     Y+1, r19
        ldd     r22, Y+2        /* f1 */
        tst     r20
        brne    6f
        ldd     r23, Y+3        /* zeros: f2 += count * f1 */
        mul     r22, r16
        add     r23, r0
        clr     r1
        std     Y+3, r23
        ldd     r24, Y+8        /* g = g * x^(8 count) */
        ldd     r25, Y+9
        mov     r22, r16
        call    r8_crc16_shift
        std     Y+8, r24
        std     Y+9, r25
        rjmp    8f
6:      ldd     r18, Y+8        /* another byte: count steps of it */
        ldd     r19, Y+9
        ldd     r0, Y+3
        mov     r21, r16
7:      STEP(r19, r18, r20)
        add     r22, r20
        add     r0, r22
        dec     r21
        brne    7b
        std     Y+8, r18
        std     Y+9, r19
        std     Y+2, r22
        std     Y+3, r0
8:      mov     r24, r16
        pop     r29
        pop     r28
        pop     r16
        ret
        .size   r8_tx_run, . - r8_tx_run

/* r8_u8 r8_tx_lit(r8_tx_st *s, r8_u8 *o, const r8_u8 *p, r8_u8 k, r8_u8 c)
 *   s r25:r24, o r23:r22, p r21:r20, k r18, c r16 -> r24
 * r8_tx_st: +0 crc, +2 f1, +3 f2, +6 code, +8 g.
 * Scan (~6 cycles a byte), then the count byte and the literals: copy,
 * CRC, Fletcher (22 (28) cycles a byte), each 0x00 linked into the COBS
 * chain (bit 7 of the result: a block got too long, the caller undoes
 * the chain); then g = (g ^ Pb) * x^(8L) ^ Pa. */
        .section .text.r8_tx_lit, "ax", @progbits
        .global r8_tx_lit
        .type   r8_tx_lit, @function
r8_tx_lit:
        push    r2
        push    r3
        push    r4
        push    r5
        push    r16
        push    r17
        push    r28
        push    r29
        movw    r28, r24        /* Y = s */
        movw    r30, r22        /* Z = o */
        movw    r2, r20         /* p */
        movw    r26, r20        /* X = p */
        mov     r19, r16        /* L = c unless a run starts */
        tst     r18
        breq    3f
        ld      r20, X+         /* p[i] */
        mov     r21, r18        /* positions left */
        /* two positions a loop, p[i] and p[i+1] in r20 and r22 in turn */
1:      ld      r22, X+         /* p[i+1] */
        cp      r22, r20
        breq    4f
2:      dec     r21
        breq    3f
        ld      r20, X+         /* p[i+2] */
        cp      r20, r22
        breq    5f
6:      dec     r21
        brne    1b
        rjmp    3f
4:      ld      r23, X          /* p[i+1] = p[i]: p[i+2] too? */
        cp      r23, r20
        brne    2b
        rjmp    7f
5:      ld      r23, X          /* p[i+2] = p[i+1]: p[i+3] too? */
        cp      r23, r22
        brne    6b
7:      mov     r19, r18
        sub     r19, r21        /* a run starts at k - left */
3:      mov     r24, r19
        ori     r24, 0x80
        st      Z+, r24
        ld      r20, Y          /* crc low */
        ldd     r21, Y+1        /* crc high */
        movw    r4, r28         /* s */
        movw    r28, r30        /* Y = o + 1 */
        TABPAGE
        STEP(r21, r20, r24)
        movw    r16, r20        /* Pb */
        movw    r30, r28
        movw    r28, r4         /* Y = s */
        ldd     r22, Y+2        /* f1 */
        ldd     r0, Y+3         /* f2 */
        movw    r26, r2         /* X = p */
        ldd     r2, Y+6         /* the COBS chain's last code */
        ldd     r3, Y+7
        mov     r18, r19
        clt                     /* T: the chain got too long */
        movw    r28, r30        /* Y = o + 1 */
        TABPAGE
4:      ld      r24, X+
        st      Y+, r24
        add     r22, r24
        add     r0, r22
        STEP(r21, r20, r24)
        tst     r24
        breq    6f
5:      dec     r18
        brne    4b
        movw    r28, r4         /* Y = s */
        st      Y, r20
        std     Y+1, r21
        std     Y+2, r22
        std     Y+3, r0
        std     Y+6, r2
        std     Y+7, r3
        ldd     r24, Y+8
        ldd     r25, Y+9
        eor     r24, r16
        eor     r25, r17
        mov     r22, r19
        bld     r19, 7          /* the T flag into bit 7 of L */
        mov     r16, r19
        call    r8_crc16_shift
        ld      r18, Y
        ldd     r19, Y+1
        eor     r24, r18
        eor     r25, r19
        std     Y+8, r24
        std     Y+9, r25
        mov     r24, r16
        pop     r29
        pop     r28
        pop     r17
        pop     r16
        pop     r5
        pop     r4
        pop     r3
        pop     r2
        ret
6:      /* a 0x00 at q = Y - 1: link it unless the chain has stopped */
        brts    5b
        cp      r2, r1
        cpc     r3, r1
        breq    5b
        push    r26
        push    r27
        movw    r26, r2         /* X = code */
        movw    r24, r28
        sbiw    r24, 1          /* q */
        sub     r24, r26
        sbc     r25, r27        /* q - code */
        cpi     r24, 255
        cpc     r25, r1
        brsh    7f
        st      X, r24          /* *code = q - code */
        movw    r2, r28
        ldi     r24, 1
        sub     r2, r24
        sbc     r3, r1          /* code = q */
        pop     r27
        pop     r26
        rjmp    5b
7:      set                     /* too long: the caller undoes the chain */
        pop     r27
        pop     r26
        rjmp    5b
        .size   r8_tx_lit, . - r8_tx_lit

/* unsigned r8_tx_zeros(const r8_u8 *p, unsigned n)
 *   p r25:r24, n r23:r22 -> r25:r24: how many bytes of p[0..n) are 0x00
 * before the first other.  8 at a time: ~3.6 cycles a byte. */
        LOWSECT(r8_tx_zeros)
        .global r8_tx_zeros
        .type   r8_tx_zeros, @function
r8_tx_zeros:
        movw    r26, r24        /* X = p */
        movw    r20, r22        /* bytes left */
1:      cpi     r20, 8
        cpc     r21, r1
        brlo    3f
        ld      r18, X+
        ld      r19, X+
        or      r18, r19
        ld      r19, X+
        or      r18, r19
        ld      r19, X+
        or      r18, r19
        ld      r19, X+
        or      r18, r19
        ld      r19, X+
        or      r18, r19
        ld      r19, X+
        or      r18, r19
        ld      r19, X+
        or      r18, r19
        brne    2f
        subi    r20, 8
        sbc     r21, r1
        rjmp    1b
2:      sbiw    r26, 8
3:      cp      r20, r1
        cpc     r21, r1
        breq    5f
4:      ld      r18, X+
        tst     r18
        brne    5f
        subi    r20, 1
        sbc     r21, r1
        brne    4b
5:      movw    r24, r22        /* n - left */
        sub     r24, r20
        sbc     r25, r21
        ret
        .size   r8_tx_zeros, . - r8_tx_zeros
