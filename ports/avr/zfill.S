/* zfill.S - r8k_zrows (src/r8zrows.h) for AVR: r8_zfill's rows of the
 * 16-bit z-buffer, edges moved on as they end, in one call; r8k_zband,
 * the same from a face's r8_act; and r8_interp_init_sub
 * (include/r8raster.h) / r8_attr_first (src/r8zrows.h), the edges'
 * depth set-up (below).
 *
 *   int r8k_zrows(r8_zrows *t);
 *   int r8k_zband(r8_act *a, const r8_fb *fb, r8_u16 *depth, r8_s16 ylimit);
 *
 * Same memory results as the C references in src/zrows.c.  Both work
 * on one static state, zband_t (the r8_zrows layout; not reentrant, as
 * r8_zcols): r8k_zband builds it from the face and the band, r8k_zrows
 * copies the caller's t in and its results (y, z, page, m, k) out.
 *
 * Registers for the whole of the rows (zbody): the value and the
 * error's low byte of the four interpolators (lx, rx, ld, rd) in r2..r16
 * (written back at the end; an error's high byte, nonzero only when its
 * den is 256 or more, stays in memory); Y the depth row of the current
 * row (stepped by 2w a row); M_ (r22) the row's bit in the page; ROWS
 * (r23) the rows left in the segment (up to the next edge end or the
 * limit, at most 255), this one too; T set when an interpolator's den
 * is 256 or more (the 16-bit step).  The interpolators' q, r, den are
 * read through lx on each row's step (rx, ld, rd lie 13, 27, 47 bytes
 * on).  r5, r9, r13, r17 belong to the span's pixel loop (no saves per
 * row).  An edge that ends at row y is moved on at the segment's start
 * (emove: r8k_estart, then r8_attr_first, or r8_scan_attr_edge in C),
 * and only its two interpolators re-read.  A span's depth step is
 * floor((rd - ld) / n) from r8_rcp256[n] (n = 1..255: q or q - 1, one
 * correction), with an 8-bit error (r < n <= 255) kept as e + 256 - n,
 * so that the carry of e + r says e + r >= n.  Per pixel: depth test,
 * store, page bit set or cleared by bit 7 of the pattern (rotated left
 * per column), DDA step; the drawn and the skipped pixel each with its
 * own copy of the step (no jump back into a shared tail).  The dither
 * phase comes from y (t->k = y & 3 is written at the end, not read).
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
#define LXE  r4
#define RXVL r6
#define RXVH r7
#define RXE  r8
#define LDVL r10
#define LDVH r11
#define LDE  r12
#define RDVL r14
#define RDVH r15
#define RDE  r16
#define PAT  r5                 /* the pixel loop's: the pattern, */
#define NDEN r9                 /* 256 - n, */
#define CNT  r13                /* the columns left, */
#define NM   r17                /* ~M_ */
#define M_   r22
#define ROWS r23

/* zband_t: the r8_zrows layout; the kernel's own fields in the ones it
 * does not read (rx: 2w) */
#define T_LX    zband_t+0
#define T_W2    zband_t+2
#define T_PAGE  zband_t+10
#define T_W     zband_t+12
#define T_PAT   zband_t+16
#define T_S     zband_t+18
#define T_Y     zband_t+24
#define T_LIM   zband_t+26
#define T_END   zband_t+28

#include "saves.h"   /* SAVE18, RESTORE18 */

/* one R8_INTERP_STEP, den of 256 or more: val (vl:vh), the error's low
 * byte el in registers, its high byte in memory; q, r, den of the
 * interpolator at Z+off (the four lie in one r8_scan: lx, then rx, ld,
 * rd 13, 27 and 47 bytes on, asserted in src/zrows.c) */
.macro STEPZ off, vl, vh, el
        ldd     r18, Z+\off+2
        ldd     r19, Z+\off+3
        add     \vl, r18
        adc     \vh, r19
        ldd     r20, Z+\off+5
        ldd     r18, Z+\off+6
        ldd     r19, Z+\off+7
        add     \el, r18
        adc     r20, r19
        ldd     r18, Z+\off+8
        ldd     r19, Z+\off+9
        cp      \el, r18
        cpc     r20, r19
        brlo    1f
        sub     \el, r18
        sbc     r20, r19
        sec
        adc     \vl, r1
        adc     \vh, r1
1:      std     Z+\off+5, r20
.endm

/* the same when its den < 256 (err, r < den: their high bytes 0):
 * 8-bit error; e + r past 255 is past den too */
.macro STEPB off, vl, vh, el
        ldd     r18, Z+\off+6
        ldd     r19, Z+\off+8
        ldd     r20, Z+\off+2
        ldd     r21, Z+\off+3
        add     \el, r18
        brcs    1f
        cp      \el, r19
        brlo    2f
1:      sub     \el, r19
        subi    r20, 0xFF               /* q + 1 */
        sbci    r21, 0xFF
2:      add     \vl, r20
        adc     \vh, r21
.endm

/* T = a den of the four is 256 or more (Z = lx: their high bytes at 9,
 * 22, 36, 56) */
.macro FASTT
        ldd     r18, Z+9
        ldd     r19, Z+22
        or      r18, r19
        ldd     r19, Z+36
        or      r18, r19
        ldd     r19, Z+56
        or      r18, r19
        clt
        breq    1f
        set
1:
.endm

/* load / store val and the error's low byte of the interpolator at
 * Z+off (Z = lx: rx, ld, rd, lyend, ryend at 13, 27, 47, 10, 23) */
.macro LDI3 off, vl, vh, el
        ldd     \vl, Z+\off
        ldd     \vh, Z+\off+1
        ldd     \el, Z+\off+4
.endm
.macro STI3 off, vl, vh, el
        std     Z+\off, \vl
        std     Z+\off+1, \vh
        std     Z+\off+4, \el
.endm

/* the kernel's r8_zrows (31 bytes) */
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

/* int r8k_zrows(r8_zrows *t): t's lx, z, page, w, m, pat, s, y, lim
 * in (zband_t, or the registers), its y, z, page, m, k out */
        .section .text.r8k_zrows,"ax",@progbits
        .global r8k_zrows
        .type   r8k_zrows, @function
r8k_zrows:
        SAVE18
        push    r24
        push    r25
        movw    r26, r24                /* X = t */
        ld      r18, X+                 /* 0: lx */
        ld      r19, X+
        sts     T_LX, r18
        sts     T_LX+1, r19
        adiw    r26, 6
        ld      r28, X+                 /* 8: z, in Y */
        ld      r29, X+
        ld      r18, X+                 /* 10: page */
        ld      r19, X+
        sts     T_PAGE, r18
        sts     T_PAGE+1, r19
        ld      r18, X+                 /* 12: w, 2w */
        ld      r19, X+
        sts     T_W, r18
        sts     T_W+1, r19
        lsl     r18
        rol     r19
        sts     T_W2, r18
        sts     T_W2+1, r19
        ld      M_, X+                  /* 14: m */
        adiw    r26, 1
        ld      r18, X+                 /* 16: pat */
        ld      r19, X+
        sts     T_PAT, r18
        sts     T_PAT+1, r19
        ld      r18, X+                 /* 18: s */
        ld      r19, X+
        sts     T_S, r18
        sts     T_S+1, r19
        adiw    r26, 4
        ld      r24, X+                 /* 24: y, in r25:r24 */
        ld      r25, X+
        ld      r18, X+                 /* 26: lim */
        ld      r19, X+
        sts     T_LIM, r18
        sts     T_LIM+1, r19
        lds     r30, T_LX               /* Z = lx */
        lds     r31, T_LX+1
        rcall   zbody
        pop     r27
        pop     r26
        adiw    r26, 8
        st      X+, r28                 /* 8: z */
        st      X+, r29
        lds     r18, T_PAGE             /* 10: page */
        st      X+, r18
        lds     r18, T_PAGE+1
        st      X+, r18
        adiw    r26, 2
        st      X+, M_                  /* 14: m */
        lds     r18, T_Y                /* 15: k = y & 3 */
        andi    r18, 3
        st      X+, r18
        adiw    r26, 8
        lds     r18, T_Y                /* 24: y */
        st      X+, r18
        lds     r18, T_Y+1
        st      X+, r18
        rjmp    zrestore

/* int r8k_zband(r8_act *a, const r8_fb *fb, r8_u16 *depth, r8_s16 ylimit)
 * (src/r8zrows.h): the r8_zrows of the reference (src/zrows.c) built in
 * zband_t and the registers, then zbody; a->s.c.y = t.y on 1 and 2.
 * In: r25:24 a, r23:22 fb, r21:20 depth, r19:18 ylimit.  Offsets
 * (asserted in src/zrows.c): r8_act {level 0, s 2}; r8_scanx {y 21,
 * ybot 23, l.x 25, l.yend 35, r.x 38, r.yend 48}; r8_scan {ld 52,
 * rd 72}; r8_fb {buf 0, width 2, y0 6, rows 8}. */
        .global r8k_zband
        .type   r8k_zband, @function
r8k_zband:
        SAVE18
        movw    r30, r24                /* Z = a */
        ld      r17, Z+                 /* level, min 16: pat */
        cpi     r17, 17
        brlo    1f
        ldi     r17, 16
1:      lsl     r17
        lsl     r17
        ldi     r26, lo8(r8_fb_dither_tab)
        ldi     r27, hi8(r8_fb_dither_tab)
        add     r26, r17
        adc     r27, r1
        sts     T_PAT, r26
        sts     T_PAT+1, r27
        adiw    r30, 1                  /* Z = s */
        sts     T_S, r30
        sts     T_S+1, r31
        movw    r26, r30                /* lx (the kernel finds rx, ld, */
        adiw    r26, 25                 /* rd, the yends from it) */
        sts     T_LX, r26
        sts     T_LX+1, r27
        ldd     r24, Z+21               /* y, in r25:r24 */
        ldd     r25, Z+22
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
3:      sts     T_LIM, r14
        sts     T_LIM+1, r15
        ldd     r10, Z+2                /* w, 2w (stored when not the */
        ldd     r11, Z+3                /* last call's) */
        lds     r18, T_W2
        lds     r19, T_W2+1
        lds     r16, T_W
        lds     r17, T_W+1
        cp      r16, r10
        cpc     r17, r11
        breq    5f
        sts     T_W, r10
        sts     T_W+1, r11
        movw    r18, r10
        lsl     r18
        rol     r19
        sts     T_W2, r18
        sts     T_W2+1, r19
5:
        movw    r16, r24                /* by = y - y0 (>= 0) */
        sub     r16, r12
        sbc     r17, r13
        mul     r16, r18                /* Y = depth + by * 2w */
        movw    r28, r0
        mul     r16, r19
        add     r29, r0
        mul     r17, r18
        add     r29, r0
        clr     r1
        add     r28, r20
        adc     r29, r21
        ldi     M_, 1                   /* m = 1 << (by & 7) */
        sbrc    r16, 1
        ldi     M_, 4
        sbrc    r16, 0
        lsl     M_
        sbrc    r16, 2
        swap    M_
        ld      r18, Z                  /* page = buf + (by >> 3) * w */
        ldd     r19, Z+1
        cpi     r16, 8                  /* (by < 8: buf) */
        cpc     r17, r1
        brlo    6f
        lsr     r17
        ror     r16
        lsr     r17
        ror     r16
        lsr     r17
        ror     r16
        mul     r16, r10
        add     r18, r0
        adc     r19, r1
        mul     r16, r11
        add     r19, r0
        mul     r17, r10
        add     r19, r0
        clr     r1
6:      sts     T_PAGE, r18
        sts     T_PAGE+1, r19
        movw    r30, r26                /* Z = lx */
        rcall   zbody
        tst     r24                     /* 1, 2: c.y = t.y (r19:r18) */
        breq    4f
        lds     r30, T_S
        lds     r31, T_S+1
        std     Z+21, r18
        std     Z+22, r19
4:      rjmp    zrestore
        .size   r8k_zband, .-r8k_zband

zrestore:
        ldi     r25, 0
        RESTORE18
        ret

/* the rows: zband_t's lx, page, w, 2w, pat, s, lim set, Z = lx, Y =
 * the depth row of row y, M_ its bit, r25:r24 = y; the registers saved.
 * Returns r24 (1: y reached lim, 2: row y is the caller's), y in T_Y
 * and r19:r18. */
zbody:
        LDI3    0, LXVL, LXVH, LXE
        LDI3    13, RXVL, RXVH, RXE
        LDI3    27, LDVL, LDVH, LDE
        LDI3    47, RDVL, RDVH, RDE
        FASTT
        rjmp    .Lcheck

.Lmove:                                 /* y in T_Y for emove */
        sts     T_Y, r24
        sts     T_Y+1, r25
        cp      r24, r20
        cpc     r25, r21
        brlt    2f
        ldi     r19, 0
        rcall   emove
        LDI3    0, LXVL, LXVH, LXE
        LDI3    27, LDVL, LDVH, LDE
        FASTT
2:      ldd     r20, Z+23               /* the right one */
        ldd     r21, Z+24
        cp      r24, r20
        cpc     r25, r21
        brlt    3f
        ldi     r19, 1
        rcall   emove
        LDI3    13, RXVL, RXVH, RXE
        LDI3    47, RDVL, RDVH, RDE
        FASTT
3:      lds     r18, T_LIM
        lds     r19, T_LIM+1
        ldd     r20, Z+10
        ldd     r21, Z+11
        ldd     r26, Z+23
        ldd     r27, Z+24
        rjmp    .Lseg
.Ldone:                                 /* y reached lim */
        sts     T_Y, r24
        sts     T_Y+1, r25
        movw    r18, r24
        ldi     r24, 1
        rjmp    .Lout

.Lcheck:                                /* a segment from y: r25:r24, Z = lx */
        lds     r18, T_LIM              /* y < lim, else done */
        lds     r19, T_LIM+1
        cp      r24, r18
        cpc     r25, r19
        brge    .Ldone
        ldd     r20, Z+10               /* an edge ends at y: on */
        ldd     r21, Z+11
        ldd     r26, Z+23
        ldd     r27, Z+24
        cp      r24, r20
        cpc     r25, r21
        brge    9f
        cp      r24, r26
        cpc     r25, r27
        brlt    .Lseg
9:      rjmp    .Lmove
.Lstept:                                /* (the row's branches' far */
        rjmp    .Lstep                  /* targets, in their reach) */
.Lstopt:
        rjmp    .Lstop
.Lclip:                                 /* w < xr: xb = w, unless */
        cp      LXVL, r18               /* xl >= w: nothing drawn */
        cpc     LXVH, r19
        brge    .Lstept
        movw    r20, r18
        rjmp    .Lclipped
.Lonet:
        rjmp    .Lone
.Lzc1:  sts     r8_zcols+1, r20
        rjmp    .Lzc1b
.Lzc0:  sts     r8_zcols, LXVL
        rjmp    .Lzc0b
.Lseg:                                  /* end = min(lim, yends) */
        cp      r20, r18
        cpc     r21, r19
        brge    4f
        movw    r18, r20
4:      cp      r26, r18
        cpc     r27, r19
        brge    5f
        movw    r18, r26
5:      movw    r20, r18                /* ROWS = end - y: 1..255 */
        sub     r20, r24
        sbc     r21, r25
        breq    6f
        brlt    6f
        tst     r21
        breq    8f
        ldi     r20, 255                /* 256 or more: 255, then again */
        rjmp    7f
6:      ldi     r20, 1                  /* end <= y (an edge that did not */
7:      movw    r18, r24                /* move on): one row */
        add     r18, r20
        adc     r19, r1
8:      mov     ROWS, r20
        sts     T_END, r18
        sts     T_END+1, r19

.Lrow:
        cp      LXVL, RXVL              /* xl >= xr: no span */
        cpc     LXVH, RXVH
        brge    .Lstept
        movw    r24, RXVL               /* n = xr - xl */
        sub     r24, LXVL
        sbc     r25, LXVH
        sbrc    LXVH, 7                 /* xl < 0: r8_zfill's */
        rjmp    .Lstop
        tst     r25                     /* n > 255: r8_zfill's */
        brne    .Lstopt
        lds     r18, T_W                /* xb = xr when xr <= w */
        lds     r19, T_W+1
        movw    r20, RXVL
        cp      r18, r20
        cpc     r19, r21
        brlt    .Lclip
.Lclipped:
        lds     r18, r8_zcols+1         /* the columns drawn (bytes): */
        cp      r18, r20                /* r8_zcols[1] = max(it, xb), */
        brlo    .Lzc1                   /* (the stores out of line) */
.Lzc1b: lds     r18, r8_zcols           /* r8_zcols[0] = min(it, xl) */
        cp      LXVL, r18
        brlo    .Lzc0
.Lzc0b: sub     r20, LXVL               /* columns (1..255) */
        cpi     r20, 1                  /* one: its depth is ld's, no */
        breq    .Lonet                  /* step, no division */
7:      mov     CNT, r20
        lds     r20, T_END              /* pattern: pat[y & 3] (flash), */
        sub     r20, ROWS               /* y = end - ROWS */
        andi    r20, 3
        lds     r30, T_PAT
        lds     r31, T_PAT+1
        add     r30, r20
        adc     r31, r1
        lpm     PAT, Z
        sbrc    LXVL, 2                 /* rotated left by xl & 7: 4 */
        swap    PAT                     /* (swap), 2, 1 */
        sbrs    LXVL, 1
        rjmp    8f
        lsl     PAT
        adc     PAT, r1
        lsl     PAT
        adc     PAT, r1
8:      sbrs    LXVL, 0
        rjmp    9f
        lsl     PAT
        adc     PAT, r1
9:      movw    r18, RDVL               /* diff = rd - ld; r27: its sign */
        sub     r18, LDVL
        sbc     r19, LDVH
        mov     r27, r19
        sbrs    r27, 7
        rjmp    10f
        com     r18                     /* un = -diff - 1 */
        com     r19
10:     ldi     r30, lo8(r8_rcp256)
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
        brlo    22f
        sub     r18, r24
        adiw    r30, 1
22:     sbrs    r27, 7
        rjmp    23f
        com     r30                     /* q = -q' - 1, r = n - 1 - rr */
        com     r31                     /* (= n + ~rr, 8 bits) */
        com     r18
        add     r18, r24
23:     movw    r20, r30                /* DQ */
        mov     r25, r18                /* DR */
        neg     r24                     /* DE + 256 - n (DE = 0), */
        mov     NDEN, r24               /* NDEN = 256 - n */
        movw    r18, LDVL               /* DV */
        lds     r26, T_PAGE             /* X = page + xl */
        lds     r27, T_PAGE+1
        add     r26, LXVL
        adc     r27, LXVH
        movw    r30, r28                /* Z = z + 2 xl */
        add     r30, LXVL
        adc     r31, LXVH
        add     r30, LXVL
        adc     r31, LXVH
        mov     NM, M_
        com     NM
.Lpx:                                   /* two pixels a turn (A, B): */
        lsr     CNT                     /* CNT = pairs; odd: from B */
        brcc    .Lpa
        inc     CNT
        rjmp    .Lpb
.Lpa:                                   /* depth >= the stored one: */
        ldd     r0, Z+1                 /* the high bytes decide, but */
        cp      r19, r0                 /* when equal (.Leqa) */
        brlo    .Lska
        breq    .Leqa
.Ldra:  st      Z+, r18                 /* nearer or equal: depth, pixel */
        st      Z+, r19
        ld      r0, X
        and     r0, NM
        lsl     PAT
        brcc    2f
        inc     PAT
        or      r0, M_
2:      st      X+, r0
        add     r24, r25                /* the DDA; the error kept as */
        brcc    3f                      /* e + 256 - n: carry when */
        add     r24, NDEN               /* e + r >= n, then dv += q + 1 */
        sec
3:      adc     r18, r20
        adc     r19, r21
.Lpb:
        ldd     r0, Z+1
        cp      r19, r0
        brlo    .Lskb
        breq    .Leqb
.Ldrb:  st      Z+, r18
        st      Z+, r19
        ld      r0, X
        and     r0, NM
        lsl     PAT
        brcc    5f
        inc     PAT
        or      r0, M_
5:      st      X+, r0
        add     r24, r25
        brcc    6f
        add     r24, NDEN
        sec
6:      adc     r18, r20
        adc     r19, r21
        dec     CNT
        brne    .Lpa
        rjmp    .Lstep
.Leqa:                                  /* high bytes equal: the low */
        ld      r0, Z
        cp      r18, r0
        brlo    .Lska
        rjmp    .Ldra
.Leqb:
        ld      r0, Z
        cp      r18, r0
        brlo    .Lskb
        rjmp    .Ldrb
.Lska:                                  /* farther: not drawn (each its */
        lsl     PAT                     /* own copy of the step) */
        adc     PAT, r1
        adiw    r26, 1
        adiw    r30, 2
        add     r24, r25
        brcc    7f
        add     r24, NDEN
        sec
7:      adc     r18, r20
        adc     r19, r21
        rjmp    .Lpb
.Lskb:
        lsl     PAT
        adc     PAT, r1
        adiw    r26, 1
        adiw    r30, 2
        add     r24, r25
        brcc    8f
        add     r24, NDEN
        sec
8:      adc     r18, r20
        adc     r19, r21
        dec     CNT
        breq    .Lstep
        rjmp    .Lpa
.Lslowt:
        rjmp    .Lslow

.Lstep:
        lds     r30, T_LX               /* Z = lx: rx, ld, rd at 13, 27, 47 */
        lds     r31, T_LX+1
        brts    .Lslowt                 /* a den >= 256: 16-bit errors */
        STEPB   0, LXVL, LXVH, LXE
        STEPB   13, RXVL, RXVH, RXE
        STEPB   27, LDVL, LDVH, LDE
        STEPB   47, RDVL, RDVH, RDE
.Lbook:
        lds     r18, T_W2               /* the next depth row */
        lds     r19, T_W2+1
        add     r28, r18
        adc     r29, r19
        lsl     M_                      /* past bit 7: page += w */
        breq    .Lpage
.Lnext:
        dec     ROWS
        breq    14f
        rjmp    .Lrow
14:     lds     r24, T_END              /* the segment's end: y = end */
        lds     r25, T_END+1
        lds     r30, T_LX
        lds     r31, T_LX+1
        rjmp    .Lcheck
.Lpage:
        ldi     M_, 1
        lds     r30, T_PAGE
        lds     r31, T_PAGE+1
        lds     r18, T_W
        lds     r19, T_W+1
        add     r30, r18
        adc     r31, r19
        sts     T_PAGE, r30
        sts     T_PAGE+1, r31
        rjmp    .Lnext

.Lone:                                  /* one column, depth ld */
        movw    r30, r28                /* Z = z + 2 xl */
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
3:      st      Z, LDVL
        std     Z+1, LDVH
        lds     r20, T_END              /* pat[y & 3] (flash) */
        sub     r20, ROWS
        andi    r20, 3
        lds     r30, T_PAT
        lds     r31, T_PAT+1
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
2:      lds     r26, T_PAGE             /* X = page + xl */
        lds     r27, T_PAGE+1
        add     r26, LXVL
        adc     r27, LXVH
        ld      r0, X                   /* m: set, then cleared where */
        or      r0, M_                  /* the pattern's bit is 0 */
        sbrs    r21, 7
        eor     r0, M_
        st      X, r0
        rjmp    .Lstep

.Lslow:                                 /* a den of 256 or more */
        STEPZ   0, LXVL, LXVH, LXE
        STEPZ   13, RXVL, RXVH, RXE
        STEPZ   27, LDVL, LDVH, LDE
        STEPZ   47, RDVL, RDVH, RDE
        rjmp    .Lbook

.Lstop:                                 /* row y = end - ROWS: the caller's */
        lds     r18, T_END
        lds     r19, T_END+1
        sub     r18, ROWS
        sbc     r19, r1
        sts     T_Y, r18
        sts     T_Y+1, r19
        ldi     r24, 2
.Lout:
        lds     r30, T_LX
        lds     r31, T_LX+1
        STI3    0, LXVL, LXVH, LXE
        STI3    13, RXVL, RXVH, RXE
        STI3    27, LDVL, LDVH, LDE
        STI3    47, RDVL, RDVH, RDE
        ret

/* emove: r8_scan_row_attrs(s, y, 0)'s work for one edge (r19: 0 the
 * left, 1 the right; y in T_Y): r8k_estart moves it on; when its vi
 * changed, the depth interpolator (ld or rd) is set up again by
 * r8_attr_first(it, vp[back(vi)], vp[vi], y, 2) (depth alone), or by
 * r8_scan_attr_edge (src/r8zrows.h: attr_start, the general one).
 * Offsets (asserted in src/zrows.c, scankern.c): r8_scanx {vp 0, n 18,
 * l 25, r 38}, r8_edge {yend 10, vi 12}, r8_scan {c 0, attrs 51}.
 * Keeps r2..r4, r6..r8, r10..r12, r14..r16, Y, M_; holds its own in r5
 * (side), r9 (the old vi), r13 (M_) (call-saved).  Returns Z = lx,
 * r25:r24 = y; the interpolators in memory are the truth after. */
emove:
        mov     r13, M_
        mov     r5, r19
        lds     r22, T_LX               /* e = lx (left), lx + 13 */
        lds     r23, T_LX+1
        sbrs    r19, 0
        rjmp    1f
        subi    r22, 0xF3
        sbci    r23, 0xFF
1:      movw    r30, r22
        ldd     r18, Z+12               /* from = e->vi */
        mov     r9, r18
        lds     r24, T_S                /* r8k_estart(&s->c, e, y, from) */
        lds     r25, T_S+1
        lds     r20, T_Y
        lds     r21, T_Y+1
        call    r8k_estart
        lds     r30, T_LX               /* Z = e (a jump, not a skip: */
        lds     r31, T_LX+1             /* simavr takes adiw r30, 13, */
        sbrs    r5, 0                   /* 0x963D, for a 2-word JMP and */
        rjmp    5f                      /* would skip the ldd too) */
        adiw    r30, 13
5:      ldd     r20, Z+12               /* vi */
        cp      r20, r9
        breq    .Lemret                 /* vi unchanged: no attributes */
        movw    r24, r30                /* it = e + 27 (ld), e + 34 (rd) */
        adiw    r24, 27
        sbrc    r5, 0
        adiw    r24, 7
        lds     r30, T_S                /* Z = s */
        lds     r31, T_S+1
        ldd     r0, Z+51                /* attrs: depth alone, else C */
        dec     r0
        brne    .Lemgen
        ldd     r21, Z+18               /* n */
        mov     r18, r20                /* back(vi): left i + 1 (0 past */
        sbrc    r5, 0                   /* n - 1), right i - 1 (n - 1 */
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
3:      movw    r26, r30                /* a = vp[back], b = vp[vi] */
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
        lds     r18, T_Y                /* y */
        lds     r19, T_Y+1
        call    afirst_d
        or      r24, r25
        brne    .Lemret
.Lemgen:
        lds     r24, T_S                /* r8_scan_attr_edge(s, side, y) */
        lds     r25, T_S+1
        mov     r22, r5
        ldi     r23, 0
        lds     r20, T_Y
        lds     r21, T_Y+1
        call    r8_scan_attr_edge
.Lemret:
        mov     M_, r13
        lds     r30, T_LX
        lds     r31, T_LX+1
        lds     r24, T_Y
        lds     r25, T_Y+1
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

/* afirst_d: r8_attr_first(it, a, b, y, 2) for this file's callers
 * (depth alone: k fixed, not in r16), the same registers otherwise */
afirst_d:
        cpi     r19, 8                  /* y < 2048 (unsigned) */
        brsh    .Ldfail
        movw    r30, r22                /* X = ay */
        ldd     r26, Z+2
        ldd     r27, Z+3
        ldd     r22, Z+4                /* r23:r22 = a[2] */
        ldd     r23, Z+5
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
        brne    .Ldfail
        cpi     r18, 16
        brsh    .Ldfail
        movw    r30, r20                /* n = by - ay, or 1 */
        ldd     r20, Z+2
        ldd     r21, Z+3
        cp      r26, r20
        cpc     r27, r21
        brlt    1f
        ldi     r20, 1
        ldi     r21, 0
        rjmp    2f
.Ldfail:                                /* (here: in reach of every branch) */
        ldi     r24, 0
        ldi     r25, 0
        ret
1:      sub     r20, r26
        sbc     r21, r27
2:      cpi     r21, 1                  /* n <= 256 */
        brlo    3f
        brne    .Ldfail
        cpi     r20, 0
        brne    .Ldfail
3:      ldd     r26, Z+4                /* dv = b[2] - a[2] */
        ldd     r27, Z+5
        sub     r26, r22
        sbc     r27, r23
        brvs    .Ldfail                 /* |dv| >= 32768 */
        cpi     r26, 0x00               /* dv < 4096 */
        ldi     r30, 0x10
        cpc     r27, r30
        brge    .Ldfail
        cpi     r26, 0x01               /* dv >= -4095 */
        ldi     r30, 0xF0
        cpc     r27, r30
        brlt    .Ldfail
        movw    r30, r26                /* on to isub: X = it, r25:24 = dv, */
        movw    r26, r24                /* r18 = s0 (r19 = 0), r21:20 = n, */
        movw    r24, r30                /* r23:22 = a[2] */
        rjmp    isub
        .size   afirst_d, .-afirst_d

/* void r8_scan_attrs(r8_scan *s)                       (include/r8raster.h)
 * The C reference is src/zrows.c's: nothing without attributes; depth
 * alone: each edge's from r8_attr_first(&s->ld (rd), vp[from], vp[vi],
 * c.y, 2), from = the left edge's vi + 1 (0 past n - 1), the right's
 * vi - 1 (n - 1 before 0); else, or on its 0, r8_scan_attr_edge(s, side,
 * c.y).  Offsets (asserted in src/zrows.c): r8_scan {vp 0, n 18, y 21,
 * l.vi 37, r.vi 50, attrs 51, ld 52, rd 72}.  The two sides written
 * out; Y = s (afirst_d, r8_scan_attr_edge keep it). */
/* a = vp[r18], b = vp[r20], y = c.y (Y = s), then afirst_d (it in
 * r25:r24); Z flag set when it returned 0 */
.macro SAAB
        movw    r30, r28
        add     r30, r18
        adc     r31, r1
        add     r30, r18
        adc     r31, r1
        ld      r22, Z
        ldd     r23, Z+1
        movw    r30, r28
        add     r30, r20
        adc     r31, r1
        add     r30, r20
        adc     r31, r1
        ld      r20, Z
        ldd     r21, Z+1
        ldd     r18, Y+21
        ldd     r19, Y+22
        call    afirst_d
        or      r24, r25
.endm
/* r8_scan_attr_edge(s, side, c.y) (Y = s) */
.macro SAGEN side
        movw    r24, r28
        ldi     r22, \side
        ldi     r23, 0
        ldd     r20, Y+21
        ldd     r21, Y+22
        call    r8_scan_attr_edge
.endm
        .section .text.r8_scan_attrs,"ax",@progbits
        .global r8_scan_attrs
        .type   r8_scan_attrs, @function
r8_scan_attrs:
        movw    r30, r24
        ldd     r0, Z+51                /* attrs */
        tst     r0
        brne    1f
        ret
1:      push    r28
        push    r29
        movw    r28, r24
        dec     r0                      /* depth alone? */
        brne    5f
        ldd     r21, Y+18               /* n */
        ldd     r20, Y+37               /* the left: vi, from = vi + 1 */
        mov     r18, r20
        inc     r18
        cp      r18, r21
        brne    2f
        clr     r18
2:      movw    r24, r28                /* it = s + 52 */
        adiw    r24, 52
        SAAB
        brne    6f
5:      SAGEN   0
6:      ldd     r0, Y+51
        dec     r0
        brne    8f
        ldd     r21, Y+18
        ldd     r20, Y+50               /* the right: from = vi - 1 */
        mov     r18, r20
        tst     r18
        brne    7f
        mov     r18, r21
7:      dec     r18
        movw    r24, r28                /* it = s + 72 */
        subi    r24, lo8(-72)
        sbci    r25, hi8(-72)
        SAAB
        brne    9f
8:      SAGEN   1
9:      pop     r29
        pop     r28
        ret
        .size   r8_scan_attrs, .-r8_scan_attrs
