/* zfill.S - r8k_zrows (src/r8zrows.h) for AVR: r8_zfill's rows of the
 * 16-bit z-buffer, edges moved on as they end, in one call; and
 * r8_interp_init_sub (include/r8raster.h) / r8_attr_first
 * (src/r8zrows.h), the edges' depth set-up (below).
 *
 *   int r8k_zrows(r8_zrows *t);
 *
 * Same memory results as the C reference src/zrows.c.  The value and
 * error of the four interpolators (lx, rx, ld, rd) stay in r2..r17 for
 * the whole call and are written back at the end; their q, r, den are
 * read through lx on each row's step (rx, ld, rd lie 13, 27, 47 bytes
 * on).  An edge that ends at row y is moved on here (emove: r8k_estart,
 * then r8_attr_first, or r8_scan_attr_edge in C), and only its two
 * interpolators re-read.  A span's depth step is floor((rd - ld) / n)
 * from r8_rcp256[n] (n = 1..255: q or q - 1, one correction), with an
 * 8-bit error (r < n <= 255) kept as e + 256 - n, so that the carry of
 * e + r says e + r >= n.  Per pixel: depth test, store, page bit set or
 * cleared by bit 7 of the pattern (rotated left per column), DDA step;
 * the drawn and the skipped pixel each with its own copy of the step (no
 * jump back into a shared tail).
 *
 * Everything of the polygon is found from t->lx (= &s->c.l.x: rx, ld,
 * rd, l.yend, r.yend 13, 27, 47, 10, 23 bytes on; t's rx, ld, rd,
 * lyend, ryend are not read), and the dither phase from y (t->k, y & 3,
 * only written at the end).  r8k_zband (below) builds t itself.
 *
 * Each span drawn widens the columns [r8_zcols[0], r8_zcols[1]) to hold
 * it (bytes; 10 cycles a span).
 *
 * Struct offsets (avr-gcc, no padding): r8_interp {val 0, q 2, err 4,
 * r 6, den 8}; r8_zrows {lx 0, rx 2, ld 4, rd 6, z 8, page 10, w 12,
 * m 14, k 15, pat 16, s 18, lyend 20, ryend 22, y 24, lim 26, end 28}.
 */

#define LXVL r2
#define LXVH r3
#define LXEL r4
#define LXEH r5
#define RXVL r6
#define RXVH r7
#define RXEL r8
#define RXEH r9
#define LDVL r10
#define LDVH r11
#define LDEL r12
#define LDEH r13
#define RDVL r14
#define RDVH r15
#define RDEL r16
#define RDEH r17
#define YL_ r22
#define YH_ r23

#include "saves.h"   /* SAVE18, RESTORE18 */

/* one R8_INTERP_STEP: val (vl:vh), err (el:eh) in registers; q, r, den
 * of the interpolator at Z+off (the four lie in one r8_scan:
 * lx, then rx, ld, rd 13, 27 and 47 bytes on, asserted in src/zrows.c) */
.macro STEPZ off, vl, vh, el, eh
        ldd     r18, Z+\off+2
        ldd     r19, Z+\off+3
        add     \vl, r18
        adc     \vh, r19
        ldd     r18, Z+\off+6
        ldd     r19, Z+\off+7
        add     \el, r18
        adc     \eh, r19
        ldd     r18, Z+\off+8
        ldd     r19, Z+\off+9
        cp      \el, r18
        cpc     \eh, r19
        brlo    1f
        sub     \el, r18
        sbc     \eh, r19
        sec
        adc     \vl, r1
        adc     \vh, r1
1:
.endm

/* the same when its den < 256 (err, r < den: their high bytes 0):
 * 8-bit error; e + r past 255 is past den too */
.macro STEPB off, vl, vh, el
        ldd     r18, Z+\off+6
        ldd     r19, Z+\off+8
        add     \el, r18
        brcs    1f
        cp      \el, r19
        brlo    2f
1:      sub     \el, r19
        ldd     r18, Z+\off+2
        ldd     r19, Z+\off+3
        sec
        adc     \vl, r18
        adc     \vh, r19
        rjmp    3f
2:      ldd     r18, Z+\off+2
        ldd     r19, Z+\off+3
        add     \vl, r18
        adc     \vh, r19
3:
.endm

/* t->fast (Y+30) = 0 when the four dens are < 256, else not (Z = lx:
 * their high bytes at 9, 22, 36, 56) */
.macro FASTF
        ldd     r18, Z+9
        ldd     r19, Z+22
        or      r18, r19
        ldd     r19, Z+36
        or      r18, r19
        ldd     r19, Z+56
        or      r18, r19
        std     Y+30, r18
.endm

/* load / store val, err of the interpolator at Z+off (Z = lx: rx, ld,
 * rd, lyend, ryend at 13, 27, 47, 10, 23) */
.macro LDI2 off, vl, vh, el, eh
        ldd     \vl, Z+\off
        ldd     \vh, Z+\off+1
        ldd     \el, Z+\off+4
        ldd     \eh, Z+\off+5
.endm
.macro STI2 off, vl, vh, el, eh
        std     Z+\off, \vl
        std     Z+\off+1, \vh
        std     Z+\off+4, \el
        std     Z+\off+5, \eh
.endm

.macro PUSHALL
        SAVE18
.endm

/* r8k_zband's r8_zrows (31 bytes) */
        .section .bss.zband_t,"aw",@nobits
        .type   zband_t, @object
        .size   zband_t, 31
zband_t:
        .zero   31

/* r8_u8 r8_zcols[2] (src/r8zrows.h) */
        .section .bss.r8_zcols,"aw",@nobits
        .global r8_zcols
        .type   r8_zcols, @object
        .size   r8_zcols, 2
r8_zcols:
        .zero   2

        .section .text.r8k_zrows,"ax",@progbits
        .global r8k_zrows
        .type   r8k_zrows, @function
r8k_zrows:
        PUSHALL
        movw    r28, r24
        rcall   zbody
        rjmp    zrestore

/* int r8k_zband(r8_act *a, const r8_fb *fb, r8_u16 *depth, r8_s16 ylimit)
 * (src/r8zrows.h): the r8_zrows of the reference (src/zrows.c) built in
 * a static 31 bytes (zband_t; no stack frame to make), then zbody;
 * a->s.c.y = t.y on 1 and 2.
 * In: r25:24 a, r23:22 fb, r21:20 depth, r19:18 ylimit.  Offsets
 * (asserted in src/zrows.c): r8_act {level 0, s 2}; r8_scanx {y 21,
 * ybot 23, l.x 25, l.yend 35, r.x 38, r.yend 48}; r8_scan {ld 52,
 * rd 72}; r8_fb {buf 0, width 2, y0 6, rows 8}. */
        .global r8k_zband
        .type   r8k_zband, @function
r8k_zband:
        PUSHALL
        ldi     r28, lo8(zband_t)       /* Y = its r8_zrows (static: */
        ldi     r29, hi8(zband_t)       /* not reentrant, as r8_zcols) */
        movw    r30, r24                /* Z = a */
        ld      r17, Z+                 /* level, min 16: pat */
        cpi     r17, 17
        brlo    1f
        ldi     r17, 16
1:      ldi     r26, 4
        mul     r17, r26
        movw    r26, r0
        clr     r1
        subi    r26, lo8(-(r8_fb_dither_tab))
        sbci    r27, hi8(-(r8_fb_dither_tab))
        std     Y+16, r26
        std     Y+17, r27
        adiw    r30, 1                  /* Z = s */
        std     Y+18, r30
        std     Y+19, r31
        movw    r26, r30                /* lx (the kernel finds rx, ld, */
        adiw    r26, 25                 /* rd, the yends from it) */
        std     Y+0, r26
        std     Y+1, r27
        ldd     r16, Z+21               /* y */
        ldd     r17, Z+22
        std     Y+24, r16
        std     Y+25, r17
        ldd     r14, Z+23               /* lim = min(ybot, ylimit, y0 + rows) */
        ldd     r15, Z+24
        cp      r18, r14
        cpc     r19, r15
        brge    2f
        movw    r14, r18
2:      movw    r30, r22                /* Z = fb */
        ldd     r12, Z+6                /* y0 */
        ldd     r13, Z+7
        ldd     r18, Z+8                /* y0 + rows */
        ldd     r19, Z+9
        add     r18, r12
        adc     r19, r13
        cp      r18, r14
        cpc     r19, r15
        brge    3f
        movw    r14, r18
3:      std     Y+26, r14
        std     Y+27, r15
        ldd     r10, Z+2                /* w */
        ldd     r11, Z+3
        std     Y+12, r10
        std     Y+13, r11
        sub     r16, r12                /* by = y - y0 */
        sbc     r17, r13
        mul     r16, r10                /* r15:r14 = by * w */
        movw    r14, r0
        mul     r16, r11
        add     r15, r0
        mul     r17, r10
        add     r15, r0
        clr     r1
        add     r20, r14                /* z = depth + by * w */
        adc     r21, r15
        add     r20, r14
        adc     r21, r15
        std     Y+8, r20
        std     Y+9, r21
        ldi     r18, 1                  /* m = 1 << (by & 7) */
        sbrc    r16, 1
        ldi     r18, 4
        sbrc    r16, 0
        lsl     r18
        sbrc    r16, 2
        swap    r18
        std     Y+14, r18
        lsr     r17                     /* page = buf + (by >> 3) * w */
        ror     r16
        lsr     r17
        ror     r16
        lsr     r17
        ror     r16
        mul     r16, r10
        movw    r14, r0
        mul     r16, r11
        add     r15, r0
        mul     r17, r10
        add     r15, r0
        clr     r1
        ld      r18, Z
        ldd     r19, Z+1
        add     r18, r14
        adc     r19, r15
        std     Y+10, r18
        std     Y+11, r19
        rcall   zbody
        tst     r24                     /* 1, 2: c.y = t.y */
        breq    4f
        ldd     r30, Y+18
        ldd     r31, Y+19
        ldd     r18, Y+24
        ldd     r19, Y+25
        std     Z+21, r18
        std     Z+22, r19
4:      rjmp    zrestore
        .size   r8k_zband, .-r8k_zband

zrestore:
        ldi     r25, 0
        RESTORE18
        ret

/* the rows: Y = t, the registers saved; r24 the value */
zbody:
        ldd     r30, Y+0                /* Z = lx */
        ldd     r31, Y+1
        LDI2    0, LXVL, LXVH, LXEL, LXEH
        LDI2    13, RXVL, RXVH, RXEL, RXEH
        LDI2    27, LDVL, LDVH, LDEL, LDEH
        LDI2    47, RDVL, RDVH, RDEL, RDEH
        FASTF
        ldd     YL_, Y+24               /* y */
        ldd     YH_, Y+25

.Lcheck:                                /* y < lim, else done */
        ldd     r18, Y+26
        ldd     r19, Y+27
        cp      YL_, r18
        cpc     YH_, r19
        brlt    1f
        ldi     r24, 1
        rjmp    .Lout
1:      ldd     r30, Y+0                /* Z = lx */
        ldd     r31, Y+1
        ldd     r20, Z+10               /* the left edge ends at y: on */
        ldd     r21, Z+11
        cp      YL_, r20
        cpc     YH_, r21
        brlt    2f
        std     Y+24, YL_
        std     Y+25, YH_
        ldi     r19, 0
        rcall   emove
        ldd     r30, Y+0
        ldd     r31, Y+1
        LDI2    0, LXVL, LXVH, LXEL, LXEH
        LDI2    27, LDVL, LDVH, LDEL, LDEH
        FASTF
        ldd     YL_, Y+24
        ldd     YH_, Y+25
2:      ldd     r26, Z+23               /* the right one */
        ldd     r27, Z+24
        cp      YL_, r26
        cpc     YH_, r27
        brlt    3f
        std     Y+24, YL_
        std     Y+25, YH_
        ldi     r19, 1
        rcall   emove
        ldd     r30, Y+0
        ldd     r31, Y+1
        LDI2    13, RXVL, RXVH, RXEL, RXEH
        LDI2    47, RDVL, RDVH, RDEL, RDEH
        FASTF
        ldd     YL_, Y+24
        ldd     YH_, Y+25
3:      ldd     r18, Y+26
        ldd     r19, Y+27
        ldd     r20, Z+10
        ldd     r21, Z+11
        ldd     r26, Z+23
        ldd     r27, Z+24
.Lend:                                  /* end = min(lim, yends), > y */
        cp      r20, r18
        cpc     r21, r19
        brge    4f
        movw    r18, r20
4:      cp      r26, r18
        cpc     r27, r19
        brge    5f
        movw    r18, r26
5:      cp      YL_, r18
        cpc     YH_, r19
        brlt    6f
        movw    r18, YL_
        subi    r18, 0xFF
        sbci    r19, 0xFF
6:      std     Y+28, r18
        std     Y+29, r19

.Lrow:
        cp      LXVL, RXVL              /* xl >= xr: no span */
        cpc     LXVH, RXVH
        brlt    2f
        rjmp    .Lstep
2:      sbrc    LXVH, 7                 /* xl < 0: r8_zfill's */
        rjmp    .Lstop
        movw    r24, RXVL               /* n = xr - xl */
        sub     r24, LXVL
        sbc     r25, LXVH
        tst     r25                     /* n > 255: r8_zfill's */
        breq    3f
        rjmp    .Lstop
3:      ldd     r20, Y+12               /* w */
        ldd     r21, Y+13
        cp      LXVL, r20               /* xl >= w: nothing drawn */
        cpc     LXVH, r21
        brlt    4f
        rjmp    .Lstep
4:      cp      r20, RXVL               /* xb = min(w, xr) */
        cpc     r21, RXVH
        brlt    5f
        movw    r20, RXVL
5:      lds     r18, r8_zcols+1         /* the columns drawn (bytes): */
        cp      r18, r20                /* r8_zcols[1] = max(it, xb), */
        brsh    30f
        sts     r8_zcols+1, r20
30:     lds     r18, r8_zcols           /* r8_zcols[0] = min(it, xl) */
        cp      LXVL, r18
        brsh    31f
        sts     r8_zcols, LXVL
31:     sub     r20, LXVL               /* columns (1..255) */
        cpi     r20, 1                  /* one: its depth is ld's, no */
        brne    6f                      /* step, no division */
        rjmp    .Lone
6:
        push    r4
        push    r5
        push    r6
        push    r7
        mov     r4, r20                 /* r4: columns */
        mov     r20, YL_                /* r5: pat[y & 3] (flash) */
        andi    r20, 3
        ldd     r30, Y+16
        ldd     r31, Y+17
        add     r30, r20
        adc     r31, r1
        lpm     r5, Z
        mov     r20, LXVL               /* rotated left by xl & 7: */
        sbrc    r20, 2                  /* 4 (swap), then xl & 3 */
        swap    r5
        andi    r20, 3
        breq    7f
6:      lsl     r5
        adc     r5, r1
        dec     r20
        brne    6b
7:      movw    r18, RDVL               /* diff = rd - ld; T: diff < 0 */
        sub     r18, LDVL
        sbc     r19, LDVH
        bst     r19, 7
        brtc    8f
        com     r18                     /* un = -diff - 1 */
        com     r19
8:      ldi     r30, lo8(r8_rcp256)
        ldi     r31, hi8(r8_rcp256)
        add     r30, r24
        adc     r31, r25                /* r25 = 0 */
        add     r30, r24
        adc     r31, r25
        lpm     r20, Z+
        lpm     r21, Z
        tst     r19                     /* un < 256: two products */
        brne    20f
        mul     r18, r20                /* q' = (un * rcp) >> 16 < 256 */
        mov     r26, r1
        mul     r18, r21
        add     r26, r0
        adc     r1, r25
        mov     r30, r1
        ldi     r31, 0
        mul     r30, r24                /* rr = un - q' * n */
        sub     r18, r0
        sbc     r19, r1
        clr     r1
        rjmp    21f
        /* q' = (un * rcp) >> 16 in r31:r30 */
20:     mul     r19, r21
        movw    r30, r0
        mul     r18, r20
        mov     r26, r1
        mul     r18, r21
        add     r26, r0
        adc     r30, r1
        adc     r31, r25
        mul     r19, r20
        add     r26, r0
        adc     r30, r1
        adc     r31, r25
        /* rr = un - q' * n (low 16 bits) */
        mul     r30, r24
        movw    r20, r0
        mul     r31, r24
        add     r21, r0
        clr     r1
        sub     r18, r20
        sbc     r19, r21
21:     cp      r18, r24
        cpc     r19, r25
        brlo    9f
        sub     r18, r24
        adiw    r30, 1
9:      brtc    10f
        com     r30                     /* q = -q' - 1, r = n - 1 - rr */
        com     r31
        mov     r0, r24
        dec     r0
        sub     r0, r18
        mov     r18, r0
10:     movw    r20, r30                /* DQ */
        mov     r25, r18                /* DR */
        mov     r6, r24                 /* -DN: 256 - n */
        neg     r6
        mov     r24, r6                 /* DE + 256 - n (DE = 0) */
        movw    r18, LDVL               /* DV */
        ldd     r26, Y+10               /* X = page + xl */
        ldd     r27, Y+11
        add     r26, LXVL
        adc     r27, LXVH
        ldd     r30, Y+8                /* Z = z + xl */
        ldd     r31, Y+9
        add     r30, LXVL
        adc     r31, LXVH
        add     r30, LXVL
        adc     r31, LXVH
        ldd     r7, Y+14                /* M */
        mov     r1, r4                  /* r1: columns (0 again at the end) */
        mov     r4, r7                  /* NM */
        com     r4
.Lpx:
        ld      r0, Z
        cp      r18, r0
        ldd     r0, Z+1
        cpc     r19, r0
        brlo    .Lskip
        st      Z+, r18                 /* nearer or equal: depth, pixel */
        st      Z+, r19
        ld      r0, X
        and     r0, r4
        lsl     r5
        brcc    11f
        inc     r5
        or      r0, r7
11:     st      X+, r0
        add     r24, r25                /* the DDA (twice: no jump); the */
        brcc    13f                     /* error kept as e + 256 - n: */
        add     r24, r6                 /* carry when e + r >= n, then */
        sec                             /* dv += q + 1 */
13:     adc     r18, r20
        adc     r19, r21
        dec     r1
        brne    .Lpx
        rjmp    .Lpxend
.Lskip:
        lsl     r5
        brcc    16f
        inc     r5
16:     adiw    r26, 1
        adiw    r30, 2
        add     r24, r25
        brcc    18f
        add     r24, r6
        sec
18:     adc     r18, r20
        adc     r19, r21
        dec     r1
        brne    .Lpx
.Lpxend:
        pop     r7
        pop     r6
        pop     r5
        pop     r4

.Lstep:
        ldd     r30, Y+0                /* Z = lx: rx, ld, rd at 13, 27, 47 */
        ldd     r31, Y+1
        ldd     r18, Y+30               /* all dens < 256: 8-bit errors */
        tst     r18
        breq    4f
        rjmp    .Lslow
4:      STEPB   0, LXVL, LXVH, LXEL
        STEPB   13, RXVL, RXVH, RXEL
        STEPB   27, LDVL, LDVH, LDEL
        STEPB   47, RDVL, RDVH, RDEL
.Lbook:
        ldd     r18, Y+12               /* w */
        ldd     r19, Y+13
        ldd     r30, Y+8                /* z += w */
        ldd     r31, Y+9
        add     r30, r18
        adc     r31, r19
        add     r30, r18
        adc     r31, r19
        std     Y+8, r30
        std     Y+9, r31
        ldd     r20, Y+14               /* m <<= 1; past bit 7: page += w */
        lsl     r20
        brne    14f
        ldi     r20, 1
        ldd     r30, Y+10
        ldd     r31, Y+11
        add     r30, r18
        adc     r31, r19
        std     Y+10, r30
        std     Y+11, r31
14:     std     Y+14, r20
        subi    YL_, 0xFF               /* y++; on below end */
        sbci    YH_, 0xFF
        ldd     r18, Y+28
        ldd     r19, Y+29
        cp      YL_, r18
        cpc     YH_, r19
        brge    15f
        rjmp    .Lrow
15:     rjmp    .Lcheck
.Lone:                                  /* one column, depth ld */
        ldd     r30, Y+8                /* Z = z + xl */
        ldd     r31, Y+9
        add     r30, LXVL
        adc     r31, LXVH
        add     r30, LXVL
        adc     r31, LXVH
        ld      r0, Z
        cp      LDVL, r0
        ldd     r0, Z+1
        cpc     LDVH, r0
        brsh    3f                      /* farther: not drawn */
        rjmp    .Lstep
3:
        st      Z, LDVL
        std     Z+1, LDVH
        mov     r20, YL_                /* pat[y & 3] (flash) */
        andi    r20, 3
        ldd     r30, Y+16
        ldd     r31, Y+17
        add     r30, r20
        adc     r31, r1
        lpm     r21, Z
        mov     r20, LXVL               /* its bit 7 - (xl & 7) to bit 7 */
        sbrc    r20, 2
        swap    r21
        andi    r20, 3
        breq    2f
1:      lsl     r21
        dec     r20
        brne    1b
2:      ldd     r26, Y+10               /* X = page + xl */
        ldd     r27, Y+11
        add     r26, LXVL
        adc     r27, LXVH
        ldd     r20, Y+14               /* m: set, then cleared where */
        ld      r0, X                   /* the pattern's bit is 0 */
        or      r0, r20
        sbrs    r21, 7
        eor     r0, r20
        st      X, r0
        rjmp    .Lstep

.Lslow:                                 /* a den of 256 or more */
        STEPZ   0, LXVL, LXVH, LXEL, LXEH
        STEPZ   13, RXVL, RXVH, RXEL, RXEH
        STEPZ   27, LDVL, LDVH, LDEL, LDEH
        STEPZ   47, RDVL, RDVH, RDEL, RDEH
        rjmp    .Lbook

.Lstop:
        ldi     r24, 2                  /* row y: the caller's */
.Lout:
        std     Y+24, YL_
        std     Y+25, YH_
        mov     r20, YL_                /* k = y & 3 */
        andi    r20, 3
        std     Y+15, r20
        ldd     r30, Y+0
        ldd     r31, Y+1
        STI2    0, LXVL, LXVH, LXEL, LXEH
        STI2    13, RXVL, RXVH, RXEL, RXEH
        STI2    27, LDVL, LDVH, LDEL, LDEH
        STI2    47, RDVL, RDVH, RDEL, RDEH
        ret
/* emove: r8_scan_row_attrs(s, y, 0)'s work for one edge (r19: 0 the
 * left, 1 the right; y in t->y): r8k_estart moves it on; when its vi
 * changed, the depth interpolator (t->ld or t->rd) is set up again by
 * r8_attr_first(it, vp[back(vi)], vp[vi], y, 2) (depth alone), or by
 * r8_scan_attr_edge (src/r8zrows.h: attr_start, the general one).
 * Offsets (asserted in src/zrows.c, scankern.c): r8_scanx {vp 0, n 18,
 * l 25, r 38}, r8_edge {yend 10, vi 12}, r8_scan {c 0, attrs 51}.
 * Keeps r2..r17, Y; the interpolators in memory are the truth after. */
emove:
        push    r19
        ldd     r22, Y+0                /* e = lx - 0 (left), rx - 13 */
        ldd     r23, Y+1
        sbrs    r19, 0
        rjmp    1f
        subi    r22, 0xF3               /* + 13 */
        sbci    r23, 0xFF
1:      movw    r30, r22
        ldd     r18, Z+12               /* from = e->vi */
        push    r18
        push    r22
        push    r23
        ldd     r24, Y+18               /* r8k_estart(&s->c, e, y, from) */
        ldd     r25, Y+19
        ldd     r20, Y+24
        ldd     r21, Y+25
        call    r8k_estart
        pop     r31                     /* Z = e */
        pop     r30
        pop     r18                     /* from */
        pop     r19                     /* side */
        ldd     r20, Z+12               /* vi */
        cp      r20, r18
        breq    .Lemret                 /* vi unchanged: no attributes */
        ldd     r30, Y+18               /* Z = s */
        ldd     r31, Y+19
        ldd     r0, Z+51                /* attrs: depth alone, else C */
        dec     r0
        brne    .Lemgen
        ldd     r21, Z+18               /* n */
        mov     r18, r20                /* back(vi): left i + 1 (0 past */
        sbrc    r19, 0                  /* n - 1), right i - 1 (n - 1 */
        rjmp    2f                      /* before 0) */
        inc     r18
        cp      r18, r21
        brne    3f
        clr     r18
        rjmp    3f
2:      tst     r18
        brne    4f
        mov     r18, r21
4:      dec     r18
3:      push    r19
        movw    r26, r30                /* a = vp[back], b = vp[vi] */
        add     r26, r18
        adc     r27, r1
        add     r26, r18
        adc     r27, r1
        ld      r22, X+
        ld      r23, X
        add     r30, r20
        adc     r31, r1
        add     r30, r20
        adc     r31, r1
        ld      r0, Z
        ldd     r21, Z+1
        mov     r20, r0
        ldd     r24, Y+0                /* it = ld = lx + 27 (rd + 47) */
        ldd     r25, Y+1
        adiw    r24, 27
        sbrc    r19, 0
        adiw    r24, 20
        ldd     r18, Y+24               /* y */
        ldd     r19, Y+25
        push    r16
        ldi     r16, 2
        call    r8_attr_first
        pop     r16
        pop     r19
        or      r24, r25
        brne    .Lemret
.Lemgen:
        ldd     r24, Y+18               /* r8_scan_attr_edge(s, side, y) */
        ldd     r25, Y+19
        mov     r22, r19
        ldi     r23, 0
        ldd     r20, Y+24
        ldd     r21, Y+25
        call    r8_scan_attr_edge
.Lemret:
        ret
        .size   r8k_zrows, .-r8k_zrows

/* void r8_interp_init_sub(r8_interp *it, r8_s16 base, r8_u16 s0,
 *                         r8_s16 dv, r8_u16 n)       (include/r8raster.h)
 *
 * The C reference is src/zrows.c's: for 0 <= s0 < 16, n = 1..256,
 * |dv| < 4096, it = r8_interp_init_mul(it, base, s0, dv, dv * 16, n):
 *     val = sat16(base + floor(s0 * dv / n)), err the remainder,
 *     q = sat16(floor(16 * dv / n)), r its remainder, den = n.
 * A floor quotient of num = un or -un - 1 (un < 65536) is that of un
 * (DIVN: r8_rcp256[n], read once for both, one correction),
 * complemented when negative; the remainder then n - 1 - rr.  val is
 * summed in 24 bits, then saturated.
 * In: r25:24 it, r23:22 base, r21:20 s0, r19:18 dv, r17:16 n; on to
 * isub (X it, r23:22 base, r18 s0, r25:24 dv, r21:20 n). */
        .section .text.r8_interp_init_sub,"ax",@progbits
        .global r8_interp_init_sub
        .type   r8_interp_init_sub, @function
r8_interp_init_sub:
        movw    r26, r24                /* X = it */
        mov     r0, r20
        movw    r24, r18                /* dv */
        movw    r20, r16                /* n */
        mov     r18, r0                 /* s0 */

/* q (r31:r30) = un / n, rr (r29:r28) = un % n for un = r29:r28,
 * n = r21:r20 (1..256), rcp = r17:r16 = r8_rcp256[n]: q' = (un * rcp)
 * >> 16 is q or q - 1.  Uses r18, r0; r1 = 0 after. */
.macro DIVN
        mul     r29, r17
        movw    r30, r0
        mul     r28, r16
        mov     r18, r1
        mul     r28, r17
        add     r18, r0
        adc     r30, r1
        brcc    1f
        inc     r31
1:      mul     r29, r16
        add     r18, r0
        adc     r30, r1
        brcc    2f
        inc     r31
2:      mul     r30, r20                /* rr = un - q' n (16 bits) */
        sub     r28, r0
        sbc     r29, r1
        mul     r31, r20
        sub     r29, r0
        mul     r30, r21
        sub     r29, r0
        clr     r1
        cp      r28, r20
        cpc     r29, r21
        brlo    3f
        sub     r28, r20
        sbc     r29, r21
        adiw    r30, 1
3:
.endm
/* r29:r28 = n - 1 - r29:r28 (n in r21:r20) */
.macro NREM
        mov     r0, r20
        mov     r1, r21
        sub     r0, r28
        sbc     r1, r29
        movw    r28, r0
        sbiw    r28, 1
        clr     r1
.endm

isub:
        push    r16
        push    r17
        push    r28
        push    r29
        clt
        sbrs    r25, 7
        rjmp    1f
        set                             /* T: dv < 0 */
        com     r25                     /* m = -dv */
        neg     r24
        sbci    r25, 0xFF
1:      ldi     r30, lo8(r8_rcp256)     /* rcp = r8_rcp256[n] */
        ldi     r31, hi8(r8_rcp256)
        add     r30, r20
        adc     r31, r21
        add     r30, r20
        adc     r31, r21
        lpm     r16, Z+
        lpm     r17, Z
        mul     r18, r24                /* un = s0 * m */
        movw    r28, r0
        mul     r18, r25
        add     r29, r0
        clr     r1
        clr     r19                     /* r19: 0xFF when s0 * dv < 0 */
        brtc    2f
        mov     r0, r28
        or      r0, r29
        breq    2f
        sbiw    r28, 1
        ldi     r19, 0xFF
2:      swap    r24                     /* r25:24 = 16 m (- 1 when dv < 0) */
        swap    r25                     /* (m < 4096) */
        mov     r0, r24
        andi    r24, 0xF0
        andi    r25, 0xF0
        mov     r18, r0
        andi    r18, 0x0F
        or      r25, r18
        brtc    3f
        sbiw    r24, 1
3:      DIVN
        tst     r19
        breq    4f
        com     r30                     /* q = -q - 1 */
        com     r31
        NREM                            /* rr = n - 1 - rr */
4:      sbrc    r23, 7                  /* r19:r31:r30 += base (24 bits) */
        dec     r19
        add     r30, r22
        adc     r31, r23
        adc     r19, r1
        mov     r0, r31                 /* fits 16 bits: r19 = sign of r31 */
        lsl     r0
        sbc     r0, r0
        cp      r0, r19
        breq    5f
        ldi     r30, 0xFF
        ldi     r31, 0x7F
        sbrs    r19, 7
        rjmp    5f
        ldi     r30, 0x00
        ldi     r31, 0x80
5:      st      X+, r30                 /* val */
        st      X+, r31
        movw    r22, r28                /* err */
        movw    r28, r24
        DIVN
        brtc    7f
        NREM
        sbrc    r31, 7                  /* q >= 32768: -q - 1 < -32768 */
        rjmp    6f
        com     r30
        com     r31
        rjmp    8f
6:      ldi     r30, 0x00
        ldi     r31, 0x80
        rjmp    8f
7:      sbrs    r31, 7                  /* q >= 32768: 32767 */
        rjmp    8f
        ldi     r30, 0xFF
        ldi     r31, 0x7F
8:      st      X+, r30                 /* q */
        st      X+, r31
        st      X+, r22                 /* err */
        st      X+, r23
        st      X+, r28                 /* r */
        st      X+, r29
        st      X+, r20                 /* den */
        st      X+, r21
        pop     r29
        pop     r28
        pop     r17
        pop     r16
        ldi     r24, 1                  /* (r8_attr_first's 1) */
        ldi     r25, 0
        ret
        .size   r8_interp_init_sub, .-r8_interp_init_sub

/* int r8_attr_first(r8_interp *it, const r8_s16 *a, const r8_s16 *b,
 *                   r8_s16 y, r8_u8 k)                 (src/r8zrows.h)
 * In: r25:24 it, r23:22 a, r21:20 b, r19:18 y, r16 k.  The checks of
 * src/zrows.c's reference, then r8_interp_init_sub(it, a[k], s0, dv, n)
 * (isub, which returns the 1); or 0 with it untouched. */
        .global r8_attr_first
        .type   r8_attr_first, @function
r8_attr_first:
        cpi     r19, 8                  /* y < 2048 (unsigned) */
        brsh    .Lafail
        movw    r30, r22                /* X = ay */
        ldd     r26, Z+2
        ldd     r27, Z+3
        add     r30, r16                /* r23:r22 = a[k] */
        adc     r31, r1
        add     r30, r16
        adc     r31, r1
        ld      r22, Z
        ldd     r23, Z+1
        lsl     r18                     /* s0 = 16 y + 8 - ay */
        rol     r19
        lsl     r18
        rol     r19
        lsl     r18
        rol     r19
        lsl     r18
        rol     r19
        subi    r18, 0xF8
        sbci    r19, 0xFF
        sub     r18, r26
        sbc     r19, r27
        tst     r19                     /* s0 < 16 */
        brne    .Lafail
        cpi     r18, 16
        brsh    .Lafail
        movw    r30, r20                /* n = by - ay, or 1 */
        ldd     r20, Z+2
        ldd     r21, Z+3
        cp      r26, r20
        cpc     r27, r21
        brlt    1f
        ldi     r20, 1
        ldi     r21, 0
        rjmp    2f
.Lafail:                                /* (here: in reach of every branch) */
        ldi     r24, 0
        ldi     r25, 0
        ret
1:      sub     r20, r26
        sbc     r21, r27
2:      cpi     r21, 1                  /* n <= 256 */
        brlo    3f
        brne    .Lafail
        cpi     r20, 0
        brne    .Lafail
3:      add     r30, r16                /* dv = b[k] - a[k] */
        adc     r31, r1
        add     r30, r16
        adc     r31, r1
        ld      r26, Z
        ldd     r27, Z+1
        sub     r26, r22
        sbc     r27, r23
        brvs    .Lafail                 /* |dv| >= 32768 */
        cpi     r26, 0x00               /* dv < 4096 */
        ldi     r30, 0x10
        cpc     r27, r30
        brge    .Lafail
        cpi     r26, 0x01               /* dv >= -4095 */
        ldi     r30, 0xF0
        cpc     r27, r30
        brlt    .Lafail
        movw    r30, r26                /* on to isub: X = it, r25:24 = dv, */
        movw    r26, r24                /* r18 = s0 (r19 = 0), r21:20 = n, */
        movw    r24, r30                /* r23:22 = a[k] */
        rjmp    isub
        .size   r8_attr_first, .-r8_attr_first

/* void r8_scan_attrs(r8_scan *s)                       (include/r8raster.h)
 * The C reference is src/zrows.c's: nothing without attributes; depth
 * alone: each edge's from r8_attr_first(&s->ld (rd), vp[from], vp[vi],
 * c.y, 2), from = the left edge's vi + 1 (0 past n - 1), the right's
 * vi - 1 (n - 1 before 0); else, or on its 0, r8_scan_attr_edge(s, side,
 * c.y).  Offsets (asserted in src/zrows.c): r8_scan {vp 0, n 18, y 21,
 * l.vi 37, r.vi 50, attrs 51, ld 52, rd 72}.  r17 = the side, Y = s
 * (r8_attr_first, r8_scan_attr_edge keep both). */
        .section .text.r8_scan_attrs,"ax",@progbits
        .global r8_scan_attrs
        .type   r8_scan_attrs, @function
r8_scan_attrs:
        movw    r30, r24
        ldd     r0, Z+51                /* attrs */
        tst     r0
        brne    1f
        ret
1:      push    r16
        push    r17
        push    r28
        push    r29
        movw    r28, r24
        ldi     r17, 0
.Lsaside:
        ldd     r0, Y+51                /* depth alone? */
        dec     r0
        brne    .Lsagen
        ldd     r21, Y+18               /* n */
        ldd     r20, Y+37               /* the left: vi, from = vi + 1 */
        mov     r18, r20
        inc     r18
        cp      r18, r21
        brne    2f
        clr     r18
2:      ldi     r24, 52                 /* it = s + 52 */
        sbrs    r17, 0
        rjmp    3f
        ldd     r20, Y+50               /* the right: from = vi - 1 */
        mov     r18, r20
        tst     r18
        brne    4f
        mov     r18, r21
4:      dec     r18
        ldi     r24, 72                 /* it = s + 72 */
3:      movw    r30, r28                /* a = vp[from] */
        add     r30, r18
        adc     r31, r1
        add     r30, r18
        adc     r31, r1
        ld      r22, Z
        ldd     r23, Z+1
        movw    r30, r28                /* b = vp[vi] */
        add     r30, r20
        adc     r31, r1
        add     r30, r20
        adc     r31, r1
        ld      r20, Z
        ldd     r21, Z+1
        ldi     r25, 0
        add     r24, r28
        adc     r25, r29
        ldd     r18, Y+21               /* y */
        ldd     r19, Y+22
        ldi     r16, 2
        call    r8_attr_first
        or      r24, r25
        brne    .Lsanext
.Lsagen:
        movw    r24, r28                /* r8_scan_attr_edge(s, side, y) */
        mov     r22, r17
        ldi     r23, 0
        ldd     r20, Y+21
        ldd     r21, Y+22
        call    r8_scan_attr_edge
.Lsanext:
        inc     r17
        cpi     r17, 2
        brne    .Lsaside
        pop     r29
        pop     r28
        pop     r17
        pop     r16
        ret
        .size   r8_scan_attrs, .-r8_scan_attrs
