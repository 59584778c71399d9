; wire_6502.s - the wire encoder's kernels (src/r8crc.h) for the 6502 (ca65,
; issue 10): r8_crc16_update, r8_crc16_mul, r8_tx_zeros, r8_tx_run,
; r8_tx_lit (the last three's C entries are in wirec_6502.s, a module
; a firmware without wire.c's C band path leaves out; here txrun and
; txlit, which txband_6502.s calls).  Built into the 6502 library with
; -DR8_ASM_WIRE (mk/targets.mk); the C89 references are the *_c functions of
; src/crc16.c and src/wire.c, and tests/c/test_wirek.c compares the two
; in sim65 on random inputs.  ports/avr/wire_avr.S is the AVR version.
;
; The CRC-16/CCITT-FALSE byte step from a 512-byte table in RAM (R8PAGE,
; built before main by a constructor): T[i] = i * x^16 mod P as high and
; low bytes; x = hi ^ b, hi' = lo ^ THI[x], lo' = TLO[x] (27 cycles).
; r8_tx_st (layout fixed by src/r8crc.h): crc +0, f1 +2, f2 +3, pkt +4,
; code +6, g +8.

        .export         _r8_crc16_update, _r8_crc16_mul
        .export         txrun, txlit, THI, TLO      ; txband, wirec
        .exportzp       ptr, optr, sptr, ch, cl, kk, cnt, nlo, nhi
        .import         _r8_crc16_shift, pushax
        .importzp       sp
        .constructor    crc_init

S_CRC   = 0
S_F1    = 2
S_F2    = 3
S_CODE  = 6
S_G     = 8

        .zeropage
ptr:    .res    2               ; input bytes
optr:   .res    2               ; output bytes
sptr:   .res    2               ; the r8_tx_st
ch:     .res    1               ; a CRC being stepped (high, low)
cl:     .res    1
nlo:    .res    1               ; a byte count
nhi:    .res    1
f1:     .res    1
f2:     .res    1
cnt:    .res    1               ; a token's length
kk:     .res    1
vv:     .res    1
al:     .res    1               ; crc16_mul: a, b
ah:     .res    1
bl:     .res    1
bh:     .res    1
rl:     .res    1
code:   .res    2               ; tx_lit: the COBS chain's last code
stop:   .res    1
pbl:    .res    1               ; tx_lit: the packet CRC before the literals
pbh:    .res    1

        .segment "R8PAGE"
THI:    .res    256
TLO:    .res    256

        .code

; one CRC step of the byte in A on ch:cl (X changed)
.macro  CRCSTEP
        eor     ch
        tax
        lda     cl
        eor     THI,x
        sta     ch
        lda     TLO,x
        sta     cl
.endmacro

; pop N bytes of arguments off the C stack
.macro  POPN    n
        clc
        lda     sp
        adc     #n
        sta     sp
        bcc     :+
        inc     sp+1
:
.endmacro

; r8_u16 r8_crc16_update(r8_u16 crc, const r8_u8 *p, unsigned n)
;   n in A/X; p at (sp)+0, crc at (sp)+2.  35 cycles a byte.
_r8_crc16_update:
        sta     nlo
        stx     nhi
        ldy     #3
        lda     (sp),y
        sta     ch
        dey
        lda     (sp),y
        sta     cl
        dey
        lda     (sp),y
        sta     ptr+1
        dey
        lda     (sp),y
        sta     ptr
        POPN    4
        jsr     crcn
        lda     cl
        ldx     ch
        rts

; CRC of nhi:nlo bytes from ptr on ch:cl (ptr changed)
crcn:   ldy     #0
@pg:    lda     nhi
        beq     @part
@full:  lda     (ptr),y
        CRCSTEP
        iny
        bne     @full
        inc     ptr+1
        dec     nhi
        jmp     @pg
@part:  cpy     nlo
        beq     @done
@lp:    lda     (ptr),y
        CRCSTEP
        iny
        cpy     nlo
        bne     @lp
@done:  rts

; r8_u16 r8_crc16_mul(r8_u16 a, r8_u16 b): a * b modulo x^16 + x^12 +
; x^5 + 1, over the bits of b from the top.  b in A/X, a at (sp)+0.
; ~600 cycles.
_r8_crc16_mul:
        sta     bl
        stx     bh
        ldy     #1
        lda     (sp),y
        sta     ah
        dey
        lda     (sp),y
        sta     al
        POPN    2
        lda     #0
        sta     rl
        ldx     #8
        jsr     @half           ; the high byte of b
        ldy     bl
        sty     bh
        ldx     #8
        jsr     @half           ; the low byte
        tax                     ; result: rl (A), rh (X)
        lda     rl
        rts
; 8 bits of bh; r = rl (zp), A (high)
@half:
@bit:   asl     rl              ; r <<= 1, reduced by the polynomial
        rol     a
        bcc     :+
        eor     #$10
        tay
        lda     rl
        eor     #$21
        sta     rl
        tya
:       asl     bh              ; a bit of b: r ^= a
        bcc     :+
        eor     ah
        tay
        lda     rl
        eor     al
        sta     rl
        tya
:       dex
        bne     @bit
        rts

; ---- the RLE tokens

; r8_u8 r8_tx_run(r8_tx_st *s, r8_u8 *o, const r8_u8 *p, r8_u8 k)
;   k in A; p at (sp)+0, o +2, s +4.  The run at p (3 <= its length
; <= k), as [count, value] at o; feeds s->crc, s->g, s->f1, s->f2.
; (its C entry _r8_tx_run: wirec_6502.s)
; txrun: k in kk, p, o, s in ptr, optr, sptr (no stack)
txrun:  ldy     #0
        lda     (ptr),y
        sta     vv
        ldy     #3              ; c = 3; while c < k && p[c] == v: c++
@ext:   cpy     kk
        bcs     @len
        lda     (ptr),y
        cmp     vv
        bne     @len
        iny
        bne     @ext
@len:   sty     cnt
        tya                     ; o[0] = c, o[1] = v
        ldy     #0
        sta     (optr),y
        lda     vv
        iny
        sta     (optr),y
        ldy     #S_CRC+1        ; s->crc = crc(s->crc, o[0..1])
        lda     (sptr),y
        sta     ch
        dey
        lda     (sptr),y
        sta     cl
        lda     cnt
        CRCSTEP
        lda     vv
        CRCSTEP
        ldy     #S_CRC
        lda     cl
        sta     (sptr),y
        iny
        lda     ch
        sta     (sptr),y
        ldy     #S_F1
        lda     (sptr),y
        sta     f1
        iny
        lda     (sptr),y
        sta     f2
        lda     vv
        beq     @zero
        ldy     #S_G+1          ; g: c steps of v; Fletcher: c times v
        lda     (sptr),y
        sta     ch
        dey
        lda     (sptr),y
        sta     cl
        ldy     cnt
@vl:    lda     vv
        CRCSTEP
        lda     vv
        clc
        adc     f1
        sta     f1
        clc
        adc     f2
        sta     f2
        dey
        bne     @vl
        ldy     #S_G
        lda     cl
        sta     (sptr),y
        iny
        lda     ch
        sta     (sptr),y
        jmp     @f
@zero:  lda     #0              ; zeros: f2 += c * f1 (mod 256)
        ldx     #8
        ldy     cnt
        sty     kk
@mul:   asl     a
        asl     kk
        bcc     :+
        clc
        adc     f1
:       dex
        bne     @mul
        clc
        adc     f2
        sta     f2
        ldy     #S_G+1          ; g = r8_crc16_shift(g, c)
        lda     (sptr),y
        tax
        dey
        lda     (sptr),y
        jsr     pushax
        lda     cnt
        jsr     _r8_crc16_shift
        ldy     #S_G
        sta     (sptr),y
        iny
        txa
        sta     (sptr),y
@f:     ldy     #S_F1
        lda     f1
        sta     (sptr),y
        iny
        lda     f2
        sta     (sptr),y
        lda     cnt
        ldx     #0
        rts

; r8_u8 r8_tx_lit(r8_tx_st *s, r8_u8 *o, const r8_u8 *p, r8_u8 k, r8_u8 c)
;   c in A; k at (sp)+0, p +1, o +3, s +5.  L = the first i < k where
; p[i] = p[i+1] = p[i+2], else c; [0x80 | L, p[0..L)] at o; feeds
; s->crc, s->f1, s->f2; each 0x00 linked into the COBS chain (s->code)
; unless a block got longer than 254 (then bit 7 of the result, and
; the chain stops being linked); s->g = (g ^ Pb) * x^(8L) ^ Pa.
; (its C entry _r8_tx_lit: wirec_6502.s)
; txlit: c in cnt, k in kk, p, o, s in ptr, optr, sptr (no stack)
txlit:  ldx     kk              ; the first run of 3 among k positions
        beq     @len
        ldy     #0
@scan:  lda     (ptr),y         ; p[i]
        iny
        cmp     (ptr),y         ; p[i+1]
        bne     @nx
        iny
        cmp     (ptr),y         ; p[i+2]
        beq     @run
        dey
@nx:    dex
        bne     @scan
        beq     @len
@run:   dey                     ; a run starts at i
        dey
        sty     cnt
@len:   lda     cnt             ; *o = 0x80 | L; Pb = crc(s->crc, *o)
        ora     #$80
        ldy     #0
        sta     (optr),y
        pha
        ldy     #S_CRC+1
        lda     (sptr),y
        sta     ch
        dey
        lda     (sptr),y
        sta     cl
        pla
        CRCSTEP
        lda     cl
        sta     pbl
        lda     ch
        sta     pbh
        ldy     #S_F1
        lda     (sptr),y
        sta     f1
        iny
        lda     (sptr),y
        sta     f2
        ldy     #S_CODE
        lda     (sptr),y
        sta     code
        iny
        lda     (sptr),y
        sta     code+1
        lda     #0
        sta     stop
        inc     optr            ; the literals at o + 1
        bne     :+
        inc     optr+1
:       ldy     #0
        lda     cnt
        beq     @end
@lit:   lda     (ptr),y         ; copy, CRC, Fletcher, ~67 cycles a byte
        sta     (optr),y
        beq     @link
@lk:    sta     vv
        CRCSTEP
        lda     vv
        clc
        adc     f1
        sta     f1
        clc
        adc     f2
        sta     f2
        iny
        cpy     cnt
        bne     @lit
@end:   ldy     #S_CRC          ; write back crc, f1, f2, code
        lda     cl
        sta     (sptr),y
        iny
        lda     ch
        sta     (sptr),y
        iny
        lda     f1
        sta     (sptr),y
        iny
        lda     f2
        sta     (sptr),y
        ldy     #S_CODE
        lda     code
        sta     (sptr),y
        iny
        lda     code+1
        sta     (sptr),y
        ldy     #S_G+1          ; g = r8_crc16_shift(g ^ Pb, L) ^ Pa
        lda     (sptr),y
        eor     pbh
        tax
        dey
        lda     (sptr),y
        eor     pbl
        jsr     pushax
        lda     cnt
        jsr     _r8_crc16_shift
        eor     cl
        ldy     #S_G
        sta     (sptr),y
        txa
        eor     ch
        iny
        sta     (sptr),y
        lda     stop            ; L | stop << 7
        lsr     a
        ror     a
        ora     cnt
        ldx     #0
        rts
; a 0x00 at q = optr + y: link it unless the chain stopped or is off
@link:  ldx     stop
        bne     @lk0
        lda     code
        ora     code+1
        beq     @lk0            ; no chain (code = 0)
        tya                     ; q - code = optr + y - code
        clc
        adc     optr
        sta     vv
        lda     optr+1
        adc     #0
        tax                     ; q in vv (low), X (high)
        lda     vv
        sec
        sbc     code
        sta     kk              ; q - code, low
        txa
        sbc     code+1
        bne     @far            ; >= 256
        lda     kk
        cmp     #255
        bcs     @far            ; > 254
        tya                     ; *code = q - code
        pha
        ldy     #0
        lda     kk
        sta     (code),y
        pla
        tay
        lda     vv              ; code = q
        sta     code
        stx     code+1
        jmp     @lk0
@far:   lda     #1
        sta     stop
@lk0:   lda     #0
        jmp     @lk

; the CRC table: T[i] = the CRC step of byte i from 0
        .segment "ONCE"
crc_init:
        ldx     #0
@i:     stx     ch              ; r = i << 8
        lda     #0
        sta     cl
        ldy     #8
@b:     asl     cl
        rol     ch
        bcc     :+
        lda     cl
        eor     #$21
        sta     cl
        lda     ch
        eor     #$10
        sta     ch
:       dey
        bne     @b
        lda     ch
        sta     THI,x
        lda     cl
        sta     TLO,x
        inx
        bne     @i
        rts
