/* wire_avr.S - AVR assembly for the wire encoder's kernels (issue 10).
 *
 * Built into the AVR library with -DR8_ASM_AVR (mk/targets.mk); the C89
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
 * with x, t in upper registers (andi).
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

        .text

/* r8_u16 r8_crc16_update(r8_u16 crc, const r8_u8 *p, unsigned n)
 *   crc r25:r24, p r23:r22, n r21:r20 -> r25:r24         23 cycles/byte */
        .global r8_crc16_update
        .type   r8_crc16_update, @function
r8_crc16_update:
        movw    r26, r22
        cp      r20, r1
        cpc     r21, r1
        breq    2f
1:      ld      r18, X+
        CRCSTEP(r25, r24, r18, r19, r23)
        subi    r20, 1
        sbci    r21, 0
        brne    1b
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
        ld      r24, Y
        ldd     r25, Y+1
        CRCSTEP(r25, r24, r16, r21, r23)
        CRCSTEP(r25, r24, r20, r21, r23)
        st      Y, r24
        std     Y+1, r25
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
6:      ldd     r24, Y+8        /* another byte: count steps of it */
        ldd     r25, Y+9
        ldd     r0, Y+3
        mov     r19, r16
7:      CRCSTEP(r25, r24, r20, r21, r23)
        add     r22, r20
        add     r0, r22
        dec     r19
        brne    7b
        std     Y+8, r24
        std     Y+9, r25
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
 * CRC, Fletcher (28 cycles a byte), each 0x00 linked into the COBS
 * chain (bit 7 of the result: a block got too long, the caller undoes
 * the chain); then g = (g ^ Pb) * x^(8L) ^ Pa. */
        .global r8_tx_lit
        .type   r8_tx_lit, @function
r8_tx_lit:
        push    r2
        push    r3
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
        CRCSTEP(r21, r20, r24, r25, r23)
        movw    r16, r20        /* Pb */
        ldd     r22, Y+2        /* f1 */
        ldd     r0, Y+3         /* f2 */
        movw    r26, r2         /* X = p */
        ldd     r2, Y+6         /* the COBS chain's last code */
        ldd     r3, Y+7
        mov     r18, r19
        clt                     /* T: the chain got too long */
4:      ld      r24, X+
        st      Z+, r24
        add     r22, r24
        add     r0, r22
        CRCSTEP(r21, r20, r24, r25, r23)
        tst     r24
        breq    6f
5:      dec     r18
        brne    4b
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
        pop     r3
        pop     r2
        ret
6:      /* a 0x00 at q = Z - 1: link it unless the chain has stopped */
        brts    5b
        cp      r2, r1
        cpc     r3, r1
        breq    5b
        push    r26
        push    r27
        movw    r26, r2         /* X = code */
        movw    r24, r30
        sbiw    r24, 1          /* q */
        sub     r24, r26
        sbc     r25, r27        /* q - code */
        cpi     r24, 255
        cpc     r25, r1
        brsh    7f
        st      X, r24          /* *code = q - code */
        movw    r2, r30
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
