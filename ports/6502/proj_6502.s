; proj_6502.s - r8k_project (include/r8kern.h) for the 6502 (ca65, issue
; 10): a camera-space point to 12.4 screen coordinates.  Built into the
; 6502 library with -DR8_ASM_PROJECT (mk/targets.mk); the C89 reference
; is r8k_project in src/kern.c (r8_recip and r8_project_recip of
; src/proj.c), and tests/c/test_kern.c compares the two in sim65 on
; random points and projections.
;
; int r8k_project(const r8_proj *p, const r8_vec3l *c, r8_s16 *out,
;                 r8_u16 *m, r8_s8 *e)
;   e in A/X; m, out, c, p on the C stack (popped here).
; *m, *e = the reciprocal of c->z as r8_recip gives it (its table, the
; same linear interpolation); then the usual case of r8_project_recip
; here: x, y within +-32767, a guard band under 1024 px and a shift
; sh = 31 + fsh - e - (15 or 16) in 1..31 (two signed 16 x 16 products
; and the rounding of proj_round); any other case calls the C
; r8_project_recip.  ~1100 cycles.

        .export         _r8k_project
        .import         _r8_project_recip, r8m_smul16, r8m_umul16, pushax, pusha
        .importzp       sp, r8m_a, r8m_b, r8m_p

; r8_proj: cx +0, cy +2, focal +4, znear +6, guard +10, fn +12, fsh +14
P_CX    = 0
P_CY    = 2
P_GUARD = 10
P_FN    = 12
P_FSH   = 14
; r8_vec3l: x +0, y +4, z +8

        .zeropage
pp:     .res    2
cp:     .res    2
op:     .res    2
mp:     .res    2
ep:     .res    2
zn:     .res    4               ; z, normalised to [2^15, 2^16) in its low half
ss:     .res    1               ; the exponent s (r8_recip's *e)
mm:     .res    2               ; m
kk:     .res    2
sh:     .res    1
lim:    .res    2
qx:     .res    2
qy:     .res    2
ng:     .res    1

        .rodata
; round(2^31 / (32768 + 256 i)), i = 0..128, the first clamped (proj.c)
rec_lo: .lobytes 65535, 65028, 64528, 64035, 63550, 63072, 62602, 62138, 61681, 61231
        .lobytes 60787, 60350, 59919, 59494, 59075, 58662, 58254, 57852, 57456, 57065
        .lobytes 56680, 56299, 55924, 55554, 55188, 54828, 54471, 54120, 53773, 53431
        .lobytes 53092, 52759, 52429, 52103, 51782, 51464, 51150, 50840, 50534, 50231
        .lobytes 49932, 49637, 49345, 49056, 48771, 48489, 48210, 47935, 47663, 47393
        .lobytes 47127, 46864, 46603, 46346, 46091, 45839, 45590, 45344, 45100, 44859
        .lobytes 44620, 44384, 44151, 43919, 43691, 43464, 43240, 43019, 42799, 42582
        .lobytes 42367, 42154, 41943, 41734, 41528, 41323, 41121, 40920, 40721, 40525
        .lobytes 40330, 40137, 39946, 39756, 39569, 39383, 39199, 39017, 38836, 38657
        .lobytes 38480, 38304, 38130, 37958, 37787, 37617, 37449, 37283, 37118, 36954
        .lobytes 36792, 36631, 36472, 36314, 36158, 36003, 35849, 35696, 35545, 35395
        .lobytes 35246, 35099, 34953, 34808, 34664, 34521, 34380, 34239, 34100, 33962
        .lobytes 33825, 33689, 33554, 33421, 33288, 33157, 33026, 32897, 32768
rec_hi: .hibytes 65535, 65028, 64528, 64035, 63550, 63072, 62602, 62138, 61681, 61231
        .hibytes 60787, 60350, 59919, 59494, 59075, 58662, 58254, 57852, 57456, 57065
        .hibytes 56680, 56299, 55924, 55554, 55188, 54828, 54471, 54120, 53773, 53431
        .hibytes 53092, 52759, 52429, 52103, 51782, 51464, 51150, 50840, 50534, 50231
        .hibytes 49932, 49637, 49345, 49056, 48771, 48489, 48210, 47935, 47663, 47393
        .hibytes 47127, 46864, 46603, 46346, 46091, 45839, 45590, 45344, 45100, 44859
        .hibytes 44620, 44384, 44151, 43919, 43691, 43464, 43240, 43019, 42799, 42582
        .hibytes 42367, 42154, 41943, 41734, 41528, 41323, 41121, 40920, 40721, 40525
        .hibytes 40330, 40137, 39946, 39756, 39569, 39383, 39199, 39017, 38836, 38657
        .hibytes 38480, 38304, 38130, 37958, 37787, 37617, 37449, 37283, 37118, 36954
        .hibytes 36792, 36631, 36472, 36314, 36158, 36003, 35849, 35696, 35545, 35395
        .hibytes 35246, 35099, 34953, 34808, 34664, 34521, 34380, 34239, 34100, 33962
        .hibytes 33825, 33689, 33554, 33421, 33288, 33157, 33026, 32897, 32768

        .code

_r8k_project:
        sta     ep
        stx     ep+1
        ldy     #7              ; the stack: m (0), out (2), c (4), p (6)
        lda     (sp),y
        sta     pp+1
        dey
        lda     (sp),y
        sta     pp
        dey
        lda     (sp),y
        sta     cp+1
        dey
        lda     (sp),y
        sta     cp
        dey
        lda     (sp),y
        sta     op+1
        dey
        lda     (sp),y
        sta     op
        dey
        lda     (sp),y
        sta     mp+1
        dey
        lda     (sp),y
        sta     mp
        clc
        lda     sp
        adc     #8
        sta     sp
        bcc     :+
        inc     sp+1
:
; ---- r8_recip(c->z, e): normalise z to [2^15, 2^16), s the shift
        ldy     #11
        ldx     #3
:       lda     (cp),y
        sta     zn,x
        dey
        dex
        bpl     :-
        lda     #0
        sta     ss
        lda     zn+3
        bmi     @small          ; z < 0: as z = 1
        ora     zn+2
        beq     @small
@big8:  lda     zn+3            ; >= 2^24: whole bytes down
        beq     @big1
        lda     zn+1
        sta     zn
        lda     zn+2
        sta     zn+1
        lda     zn+3
        sta     zn+2
        lda     #0
        sta     zn+3
        lda     ss
        sec
        sbc     #8
        sta     ss
        jmp     @big8
@big1:  lda     zn+2            ; >= 2^16: bits down
        beq     @norm
        lsr     zn+2
        ror     zn+1
        ror     zn
        dec     ss
        jmp     @big1
@small: lda     zn+3            ; z <= 0 (or < 2^16 with a sign): 1
        bmi     @one
        lda     zn
        ora     zn+1
        bne     :+
@one:   lda     #1
        sta     zn
        lda     #0
        sta     zn+1
:       lda     zn+1            ; < 0x80: a byte up
        bne     @up1
        lda     zn
        cmp     #$80
        bcs     @up1
        sta     zn+1
        lda     #0
        sta     zn
        lda     #8
        sta     ss
@up1:   lda     zn+1            ; < 0x8000: bits up
        bmi     @norm
        asl     zn
        rol     zn+1
        inc     ss
        jmp     @up1
@norm:  lda     zn+1            ; i = (zn >> 8) & 0x7F
        and     #$7F
        tax
        sec                     ; d = t0 - t1 (< 512)
        lda     rec_lo,x
        sbc     rec_lo+1,x
        sta     r8m_a
        lda     rec_hi,x
        sbc     rec_hi+1,x
        sta     r8m_a+1
        lda     zn              ; f = (zn & 0xFF) >> 1
        lsr     a
        sta     r8m_b
        lda     #0
        sta     r8m_b+1
        txa
        pha
        jsr     r8m_umul16      ; d * f (< 2^16)
        pla
        tax
        clc                     ; q = (d * f + 64) >> 7 (9 bits)
        lda     r8m_p
        adc     #64
        sta     r8m_p
        lda     r8m_p+1
        adc     #0
        asl     r8m_p           ; bit 7 of the low byte
        rol     a
        sta     r8m_p           ; q low
        lda     #0
        rol     a
        sta     r8m_p+2         ; q high
        ; m = t0 - q, q = ((d f + 64) >> 7) < 512: q = p+2 : p
        sec
        lda     rec_lo,x
        sbc     r8m_p
        sta     mm
        lda     rec_hi,x
        sbc     r8m_p+2
        sta     mm+1
        ldy     #0              ; *m, *e
        lda     mm
        sta     (mp),y
        lda     ss
        sta     (ep),y
        iny
        lda     mm+1
        sta     (mp),y
; ---- k = m * fn (u32 in [2^29, 2^31)); kk = its top 15 bits, sh
        lda     mm
        sta     r8m_a
        lda     mm+1
        sta     r8m_a+1
        ldy     #P_FN
        lda     (pp),y
        sta     r8m_b
        iny
        lda     (pp),y
        sta     r8m_b+1
        jsr     r8m_umul16
        ldy     #P_FSH          ; sh = 31 + fsh - e
        lda     (pp),y
        clc
        adc     #31
        sec
        sbc     ss
        sta     sh
        lda     r8m_p+3
        cmp     #$40
        bcc     @k15
        sta     kk+1            ; kk = k >> 16, sh -= 16
        lda     r8m_p+2
        sta     kk
        lda     sh
        sec
        sbc     #16
        jmp     @sh
@k15:   lda     r8m_p+1         ; kk = k >> 15, sh -= 15
        asl     a
        lda     r8m_p+2
        rol     a
        sta     kk
        lda     r8m_p+3
        rol     a
        sta     kk+1
        lda     sh
        sec
        sbc     #15
@sh:    sta     sh
        bmi     @slow           ; sh <= 0 (signed: fsh - e in -128..127)
        beq     @slow
        cmp     #32
        bcc     :+
        lda     #31
        sta     sh
:       ldy     #P_GUARD        ; lim = guard * 16 (r8_s16)
        lda     (pp),y
        sta     lim
        iny
        lda     (pp),y
        ldx     #4
:       asl     lim
        rol     a
        dex
        bne     :-
        sta     lim+1
        bmi     @slow           ; lim < 0x3FFF (signed) or the C
        cmp     #$3F
        bcc     :+
        bne     @slow
        lda     lim
        cmp     #$FF
        bcs     @slow
:       ldy     #0              ; x, y within +-32767 (16 bits, not -32768)
        jsr     fits16
        bcs     @slow
        ldy     #4
        jsr     fits16
        bcs     @slow
; ---- the usual case
        ldy     #0
        jsr     round1          ; qx
        bcs     @out1
        lda     r8m_p
        sta     qx
        lda     r8m_p+1
        sta     qx+1
        ldy     #4
        jsr     round1          ; qy
        bcs     @out1
        ldy     #P_CX           ; out = (cx + qx, cy + qy)
        clc
        lda     (pp),y
        adc     qx
        sta     (op),y
        iny
        lda     (pp),y
        adc     qx+1
        sta     (op),y
        iny                     ; P_CY
        clc
        lda     (pp),y
        adc     r8m_p
        sta     (op),y
        iny
        lda     (pp),y
        adc     r8m_p+1
        sta     (op),y
        lda     #0
        tax
        rts
@out1:  lda     #1
        ldx     #0
        rts
; ---- any other case: r8_project_recip(p, c, m, e, &out[0], &out[1])
@slow:  lda     pp
        ldx     pp+1
        jsr     pushax
        lda     cp
        ldx     cp+1
        jsr     pushax
        lda     mm
        ldx     mm+1
        jsr     pushax
        lda     ss
        jsr     pusha
        lda     op
        ldx     op+1
        jsr     pushax
        clc
        lda     op
        adc     #2
        pha
        lda     op+1
        adc     #0
        tax
        pla
        jmp     _r8_project_recip

; carry clear if c's 32-bit coordinate at offset Y is in -32767..32767
fits16: iny
        iny
        iny
        lda     (cp),y          ; byte 3
        tax
        dey
        lda     (cp),y          ; byte 2
        bne     @neg
        cpx     #0
        bne     @no
        dey                     ; 0 .. 0xFFFF: byte 1 < 0x80
        lda     (cp),y
        cmp     #$80
        rts
@neg:   cmp     #$FF
        bne     @no
        cpx     #$FF
        bne     @no
        dey                     ; -65536 .. -1: byte 1 >= 0x80, not -32768
        lda     (cp),y
        cmp     #$80
        bcc     @no
        bne     @yes
        dey
        lda     (cp),y
        beq     @no             ; -32768
@yes:   clc
        rts
@no:    sec
        rts

; r8m_p (16 bits) = proj_round(coordinate at offset Y * kk, sh - 1):
; carry set if beyond lim (then 1 is returned)
round1: lda     (cp),y
        sta     r8m_a
        iny
        lda     (cp),y
        sta     r8m_a+1
        lda     kk
        sta     r8m_b
        lda     kk+1
        sta     r8m_b+1
        jsr     r8m_smul16      ; p = c * kk
        lda     r8m_p+3         ; u = p < 0 ? ~p : p
        and     #$80
        sta     ng
        beq     :+
        ldx     #3
@inv:   lda     r8m_p,x
        eor     #$FF
        sta     r8m_p,x
        dex
        bpl     @inv
:       ldx     sh              ; u >>= sh - 1: whole bytes, then bits
        dex
@byte:  cpx     #8
        bcc     @bits
        lda     r8m_p+1
        sta     r8m_p
        lda     r8m_p+2
        sta     r8m_p+1
        lda     r8m_p+3
        sta     r8m_p+2
        lda     #0
        sta     r8m_p+3
        txa
        sbc     #8              ; (carry set)
        tax
        jmp     @byte
@bits:  txa
        beq     @shd
:       lsr     r8m_p+3
        ror     r8m_p+2
        ror     r8m_p+1
        ror     r8m_p
        dex
        bne     :-
@shd:   lda     r8m_p+3         ; u >= 0x7FFE: out
        ora     r8m_p+2
        bne     @far
        lda     r8m_p+1
        cmp     #$7F
        bcc     @ok
        bne     @far
        lda     r8m_p
        cmp     #$FE
        bcs     @far
@ok:    lda     ng              ; t = neg ? ~u : u
        beq     :+
        lda     r8m_p
        eor     #$FF
        sta     r8m_p
        lda     r8m_p+1
        eor     #$FF
        sta     r8m_p+1
:       clc                     ; t = ((t + 0x8001) >> 1) - 0x4000 (16 bits)
        lda     r8m_p
        adc     #$01
        sta     r8m_p
        lda     r8m_p+1
        adc     #$80
        lsr     a
        ror     r8m_p
        sec
        sbc     #$40
        sta     r8m_p+1
        ; t > lim or t < -lim: out
        lda     lim             ; lim - t >= 0 (signed)?
        sec
        sbc     r8m_p
        lda     lim+1
        sbc     r8m_p+1
        bvc     :+
        eor     #$80
:       bmi     @far
        clc                     ; t + lim >= 0?
        lda     r8m_p
        adc     lim
        lda     r8m_p+1
        adc     lim+1
        bvc     :+
        eor     #$80
:       bmi     @far
        clc
        rts
@far:   sec
        rts
