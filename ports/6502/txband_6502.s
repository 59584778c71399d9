; txband_6502.s - r8_tx_band (include/r8wire.h) for the 6502 (ca65,
; issue 10): one band of a frame onto the wire without the C glue.
; Built into the 6502 library with -DR8_ASM_TXBAND (mk/targets.mk):
; src/wire.c then names its C89 version r8_tx_band_c, the reference,
; and this one takes the common case and hands every other to it:
;
;   in a frame, the band the encoder expects next (y0 = next_y), a whole
;   band (height - y0 >= band), the frame's width and format, codec RLE,
;   8 <= band bytes <= 255; and either the RLE payload smaller than the
;   band, with the COBS chain never broken (no block of 254 non-zero
;   bytes), or, when RLE does not pay, a band of fewer than 242 bytes
;   (the raw packet, n + 6 + 2 < 250 bytes, keeps its COBS chain).
;
; Nothing of tx changes before that is known (only the packet scratch
; is written), so the C version then does the whole band itself.  What
; is left is what src/wire.c's r8_tx_band, tx_band, tx_rle and tx_send
; do on those paths: the header, the RLE tokens (txrun and txlit of
; wire_6502.s: packet CRC, the band's CRC from 0, Fletcher sums, COBS
; links; tx_send all = 0) or the raw payload (its copy, the band's CRC
; and Fletcher sums in one pass, the packet CRC from the header's with
; one multiply, every 0x00 linked after: tx_send all = 1), the
; fingerprint, the frame CRC, the skip of an unchanged band in a delta
; frame, and one put of the framed packet.  A fixed-stream firmware
; (-DR8_TXBAND_ALL, mk/targets.mk FWK_6502) then never hands a band of
; its stream on but one out of order, and links src/wire.c's relay in
; place of the C band path.
; r8_tx_pkt (src/r8crc.h) is tx_send's all = 1 path, for such a
; firmware built with -DR8_ASM_TXPKT too: FRAME_START and FRAME_END.
; tests/c/test_txband.c compares the two on random frames in sim65,
; r8_tx_pkt with tx_send on random bodies, and the r8_tx / r8_fb
; offsets below with the C compiler's (r8_txband_offs, txoffs_6502.s).

        .export         _r8_tx_band, _r8_tx_pkt
        .import         _r8_tx_band_c, _r8_crc16_mul
        .import         txrun, txlit, THI, TLO
        .import         pushax, jmpvec
        .importzp       sp, ptr, optr, sptr, ch, cl, kk, cnt

; r8_tx (include/r8wire.h) and r8_fb (include/r8fb.h) on cc65
TX_FORMAT  = $00
TX_WIDTH   = $01
TX_HEIGHT  = $03
TX_BAND    = $05
TX_CODEC   = $07
TX_PUT     = $0E
TX_CTX     = $10
TX_PKT     = $12
TX_FP      = $16
TX_BANDB   = $1A
TX_XN      = $1C
TX_NEXTY   = $1E
TX_NEXTIDX = $20
TX_FRAME   = $22
TX_SENT    = $26
TX_FCRC    = $28
TX_HCRC    = $2A
TX_FULL    = $2C
TX_INFRAME = $2E
TX_BYTES   = $3C
TX_RAW     = $40
FB_BUF     = $00
FB_WIDTH   = $02
FB_Y0      = $06
FB_FORMAT  = $0A
; r8_tx_st (src/r8crc.h)
S_CRC   = 0
S_F1    = 2
S_F2    = 3
S_PKT   = 4
S_CODE  = 6
S_G     = 8

; (for txoffs_6502.s's table r8_txband_offs, test only)
        .export         TX_FORMAT, TX_WIDTH, TX_HEIGHT, TX_BAND, TX_CODEC, TX_PUT
        .export         TX_CTX, TX_PKT, TX_FP, TX_BANDB, TX_XN, TX_NEXTY, TX_NEXTIDX
        .export         TX_FRAME, TX_SENT, TX_FCRC, TX_HCRC, TX_FULL, TX_INFRAME
        .export         TX_BYTES, TX_RAW, FB_BUF, FB_WIDTH, FB_Y0, FB_FORMAT

        .zeropage
tx:     .res    2               ; the r8_tx
fbp:    .res    2               ; the r8_fb
bp:     .res    2               ; its buffer
lk:     .res    2               ; a code byte being linked
pk:     .res    2               ; tx->pkt
fpp:    .res    2               ; tx->fp + 4 * idx
y0:     .res    2
nn:     .res    1               ; band bytes
zz:     .res    1               ; its leading zeros
room:   .res    1               ; payload bytes still free
left:   .res    1               ; band bytes not encoded yet
full:   .res    1               ; a literal count that means "no room"
tmp:    .res    2

        .bss
st:     .res    10              ; the r8_tx_st of the packet

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

; int r8_tx_band(r8_tx *tx, const r8_fb *band): band in A/X, tx at (sp)
_r8_tx_band:
        sta     fbp
        stx     fbp+1
        ldy     #1
        lda     (sp),y
        sta     tx+1
        dey
        lda     (sp),y
        sta     tx
        ldy     #TX_INFRAME     ; the common case?
        lda     (tx),y
        beq     slow
        ldy     #TX_CODEC
        lda     (tx),y
        cmp     #1              ; R8_CODEC_RLE
        bne     slow
        ldy     #TX_BANDB+1
        lda     (tx),y
        bne     slow
        dey
        lda     (tx),y
        cmp     #8
        bcc     slow
        sta     nn
        ldy     #FB_Y0
        lda     (fbp),y
        sta     y0
        iny
        lda     (fbp),y
        sta     y0+1
        bmi     slow            ; y0 < 0
        ldy     #TX_NEXTY
        lda     (tx),y
        cmp     y0
        bne     slow
        iny
        lda     (tx),y
        cmp     y0+1
        bne     slow
        ldy     #FB_WIDTH
        lda     (fbp),y
        ldy     #TX_WIDTH
        cmp     (tx),y
        bne     slow
        ldy     #FB_WIDTH+1
        lda     (fbp),y
        ldy     #TX_WIDTH+1
        cmp     (tx),y
        bne     slow
        ldy     #FB_FORMAT
        lda     (fbp),y
        ldy     #TX_FORMAT
        cmp     (tx),y
        bne     slow
        sec                     ; height - y0 - band >= 0: a whole band
        ldy     #TX_HEIGHT
        lda     (tx),y
        sbc     y0
        sta     tmp
        iny
        lda     (tx),y
        sbc     y0+1
        sta     tmp+1
        sec
        lda     tmp
        ldy     #TX_BAND
        sbc     (tx),y
        lda     tmp+1
        iny
        sbc     (tx),y
        bpl     fast
slow:   lda     fbp             ; tx still on the C stack, band in A/X
        ldx     fbp+1
        jmp     _r8_tx_band_c

fast:   ldy     #FB_BUF
        lda     (fbp),y
        sta     bp
        iny
        lda     (fbp),y
        sta     bp+1
        ldy     #TX_PKT
        lda     (tx),y
        sta     pk
        iny
        lda     (tx),y
        sta     pk+1
        ldy     #TX_NEXTIDX     ; fpp = tx->fp + 4 idx
        lda     (tx),y
        sta     fpp
        iny
        lda     (tx),y
        asl     fpp
        rol     a
        asl     fpp
        rol     a
        sta     fpp+1
        ldy     #TX_FP
        lda     (tx),y
        clc
        adc     fpp
        sta     fpp
        iny
        lda     (tx),y
        adc     fpp+1
        sta     fpp+1
        lda     nn              ; zz: the leading zeros, 4 bytes a turn
        and     #$FC            ; up to nn & ~3, then one at a time
        sta     tmp
        ldy     #0
@z4:    lda     (bp),y
        bne     @zd
        iny
        lda     (bp),y
        bne     @zd
        iny
        lda     (bp),y
        bne     @zd
        iny
        lda     (bp),y
        bne     @zd
        iny
        cpy     tmp
        bne     @z4
@z:     cpy     nn
        beq     @zd
        lda     (bp),y
        bne     @zd
        iny
        bne     @z
@zd:    sty     zz
        cpy     nn
        bne     encode
        ldy     #3              ; a band of zeros: unchanged in a delta
        lda     #0              ; frame, only the frame CRC moves
@o:     ora     (fpp),y
        dey
        bpl     @o
        ldy     #TX_FULL
        ora     (tx),y
        bne     encode
        jsr     commit
        jsr     fcrcmul
        jmp     done

; ---- the packet, in the scratch only
encode: lda     #1              ; R8_CODEC_RLE
        jsr     hdr             ; the header; o = b + 6 = pkt + 7
        lda     cl              ; s.crc = crc(hcrc, b[3..5])
        sta     st+S_CRC
        lda     ch
        sta     st+S_CRC+1
        lda     pk              ; s.pkt = pkt
        sta     st+S_PKT
        lda     pk+1
        sta     st+S_PKT+1
        lda     #0
        sta     st+S_F1
        sta     st+S_F2
        sta     st+S_G
        sta     st+S_G+1
        lda     #6              ; the header's zeros (b[1..4]) linked,
        jsr     links0          ; s.code = pkt + the last
        txa
        clc
        adc     pk
        sta     st+S_CODE
        lda     pk+1
        adc     #0
        sta     st+S_CODE+1
        lda     #<st
        sta     sptr
        lda     #>st
        sta     sptr+1
        lda     bp
        sta     ptr
        lda     bp+1
        sta     ptr+1
        ldx     nn
        dex
        stx     room            ; cap = n - 1
        lda     nn
        sta     left

; the leading zeros: runs of up to 127 while 3 or more are left
@zl:    lda     zz
        cmp     #3
        bcc     tokens
        cmp     #127
        bcc     :+
        lda     #127
:       sta     cnt
        lda     room
        cmp     #2
        bcc     noroom
        sbc     #2
        sta     room
        ldy     #0
        lda     cnt
        sta     (optr),y
        tya
        iny
        sta     (optr),y
        lda     st+S_CRC        ; s.crc over [c, 0]
        sta     cl
        lda     st+S_CRC+1
        sta     ch
        lda     cnt
        CRCSTEP
        lda     #0
        CRCSTEP
        lda     cl
        sta     st+S_CRC
        lda     ch
        sta     st+S_CRC+1
        lda     #1              ; link o + 1
        jsr     linko
        bcs     broke
        jsr     adv2
        lda     zz
        sec
        sbc     cnt
        sta     zz
        lda     left
        sec
        sbc     cnt
        sta     left
        jsr     advp
        jmp     @zl

noroom: jmp     raw             ; RLE does not pay: the band goes raw
broke:  jmp     slow            ; the COBS chain broke: the C does it

; the tokens, as tx_rle: a run of 3 or more, else literals
tokens: lda     left
        bne     :+
        jmp     sent
:       cmp     #127
        bcc     :+
        lda     #127
:       sta     cnt             ; c = min(127, left)
        cmp     #3
        bcc     @lit
        ldy     #0
        lda     (ptr),y
        iny
        cmp     (ptr),y
        bne     @lit
        iny
        cmp     (ptr),y
        bne     @lit
        lda     room            ; a run
        cmp     #2
        bcc     noroom
        sbc     #2
        sta     room
        lda     cnt
        sta     kk
        jsr     txrun
        sta     cnt
        ldy     #1
        lda     (optr),y
        bne     :+
        lda     #1
        jsr     linko
        bcs     broke
:       jsr     adv2
        jmp     @next
@lit:   ldx     #127            ; k: where a run of 3 may start
        lda     left
        cmp     #129
        bcs     :+
        ldx     #0
        cmp     #2
        bcc     :+
        sbc     #2
        tax
:       stx     kk
        lda     #0
        sta     full
        lda     room            ; room <= c: at most room - 1 fit
        cmp     cnt
        beq     :+
        bcs     @fits
:       cmp     #2
        bcc     noroom
        sbc     #1
        sta     cnt
        sta     full
        cmp     kk
        bcs     @fits
        sta     kk
@fits:  jsr     txlit           ; (o + 1 in optr after it)
        tax
        bmi     broke2          ; the chain broke: the C does it
        cmp     full
        beq     noroom2         ; no room
        sta     cnt
        sec                     ; room -= c + 1
        lda     room
        sbc     cnt
        sec
        sbc     #1
        sta     room
        lda     cnt             ; o += c + 1
        clc
        adc     optr
        sta     optr
        bcc     @next
        inc     optr+1
@next:  lda     left
        sec
        sbc     cnt
        sta     left
        jsr     advp
        jmp     tokens

noroom2:
        jmp     raw
broke2: jmp     slow

; ---- the payload is in: o = end - 3; the CRC, links, the last code
sent:   ldy     #0              ; o[0], o[1] = the packet CRC
        lda     st+S_CRC+1
        sta     (optr),y
        bne     :+
        tya
        jsr     linko
        bcs     broke2
:       ldy     #1
        lda     st+S_CRC
        sta     (optr),y
        bne     :+
        tya
        jsr     linko
        bcs     broke2
:       lda     optr            ; end = o + 2
        clc
        adc     #2
        sta     optr
        bcc     :+
        inc     optr+1
:       lda     optr            ; end - code <= 255
        sec
        sbc     st+S_CODE
        tax
        lda     optr+1
        sbc     st+S_CODE+1
        bne     broke2
        lda     st+S_CODE
        sta     ptr
        lda     st+S_CODE+1
        sta     ptr+1
        txa
        ldy     #0
        sta     (ptr),y         ; *code = end - code
        tya
        sta     (optr),y        ; *end = 0

; ---- it goes: now tx changes (the packet ends at optr)
go:     jsr     commit
        lda     zz
        cmp     nn
        bne     @fp
        jsr     fcrcmul         ; zeros: fp = 0, fcrc = fcrc x^(8n)
        ldy     #3
        lda     #0
:       sta     (fpp),y
        dey
        bpl     :-
        jmp     @send
@fp:    lda     #0              ; the fingerprint g, f1, f2
        sta     tmp
        ldy     #0
        lda     st+S_G+1
        jsr     fpb
        lda     st+S_G
        jsr     fpb
        lda     st+S_F1
        jsr     fpb
        lda     st+S_F2
        jsr     fpb
        jsr     fcrcmul         ; fcrc = fcrc x^(8n) ^ g
        ldy     #TX_FCRC
        lda     (tx),y
        eor     st+S_G
        sta     (tx),y
        iny
        lda     (tx),y
        eor     st+S_G+1
        sta     (tx),y
        lda     tmp             ; changed, or a full frame?
        bne     @send
        ldy     #TX_FULL
        lda     (tx),y
        beq     done
@send:  ldy     #TX_SENT        ; tx->sent++ (before the put, which
        lda     (tx),y          ; does not read it: the put below is
        clc                     ; r8_tx_pkt's too)
        adc     #1
        sta     (tx),y
        iny
        lda     (tx),y
        adc     #0
        sta     (tx),y
        lda     optr            ; the packet: end + 1 - pkt bytes
        sec
        sbc     pk
        sta     tmp
        lda     optr+1
        sbc     pk+1
        sta     tmp+1
        inc     tmp
        bne     pput
        inc     tmp+1
; put(ctx, pkt, tmp), tx->bytes += tmp; pop tx, return 0
pput:   ldy     #TX_CTX+1       ; put(ctx, pkt, len)
        lda     (tx),y
        tax
        dey
        lda     (tx),y
        jsr     pushax
        lda     pk
        ldx     pk+1
        jsr     pushax
        ldy     #TX_PUT
        lda     (tx),y
        sta     jmpvec+1
        iny
        lda     (tx),y
        sta     jmpvec+2
        lda     tmp
        ldx     tmp+1
        jsr     jmpvec
        ldy     #TX_BYTES       ; tx->bytes += len
        lda     tmp
        ldx     tmp+1
        jsr     add32
done:   lda     #2              ; pop tx; R8_OK
        clc
        adc     sp
        sta     sp
        bcc     :+
        inc     sp+1
:       lda     #0
        tax
        rts

; void r8_tx_pkt(r8_tx *tx, unsigned n) (src/r8crc.h; src/wire.c
; R8_ASM_TXPKT): n in A (n + 4 < 255), tx at (sp).  tx_send's all = 1
; path, left with FRAME_START and FRAME_END (two a frame: small, not
; fast): the body pkt[1 .. n] gets its CRC-16 from R8_CRC16_INIT, high
; byte first, and the delimiter after it; every 0x00 of pkt[1 .. n + 3]
; is linked by links0 (no block can be over 254 bytes), the delimiter's
; the last code; one put of n + 4 bytes, counted in tx->bytes.
_r8_tx_pkt:
        sta     nn
        ldy     #1
        lda     (sp),y
        sta     tx+1
        dey
        lda     (sp),y
        sta     tx
        ldy     #TX_PKT
        lda     (tx),y
        sta     pk
        iny
        lda     (tx),y
        sta     pk+1
        lda     #$FF            ; R8_CRC16_INIT
        sta     cl
        sta     ch
        inc     nn              ; nn = n + 1, the body's end
        ldy     #1
@c:     cpy     nn
        beq     @e
        lda     (pk),y
        CRCSTEP
        iny
        bne     @c
@e:     lda     ch              ; pkt[n + 1], pkt[n + 2] = the CRC,
        sta     (pk),y          ; pkt[n + 3] = 0
        iny
        lda     cl
        sta     (pk),y
        iny
        lda     #0
        sta     (pk),y
        iny
        tya
        jsr     links0
        ldx     #0              ; n + 4 bytes
        stx     tmp+1
        lda     nn
        clc
        adc     #3
        sta     tmp
        jmp     pput

; ---- RLE does not pay: the raw packet (tx_band's from == b path), if
; short enough for its COBS chain to hold (n + 6 + 2 < 250), else the C
raw:    lda     nn
        cmp     #242
        bcc     :+
        jmp     slow
:
        lda     #0              ; R8_CODEC_RAW
        jsr     hdr             ; the header again (links wrote over its
        lda     cl              ; zeros); its CRC from hcrc saved
        pha
        lda     ch
        pha
        lda     #0              ; the payload: the band, its CRC from 0
        sta     cl              ; (g; leading zeros leave it 0) and its
        sta     ch              ; Fletcher sums (f1 tmp, f2 tmp+1)
        sta     tmp
        sta     tmp+1
        tay
@cp:    lda     (bp),y
        sta     (optr),y
        clc
        adc     tmp
        sta     tmp
        clc
        adc     tmp+1
        sta     tmp+1
        lda     (bp),y
        CRCSTEP
        iny
        cpy     nn
        bne     @cp
        lda     cl
        sta     st+S_G
        lda     ch
        sta     st+S_G+1
        lda     tmp
        sta     st+S_F1
        lda     tmp+1
        sta     st+S_F2
        pla                     ; the packet CRC: header's * x^(8n) ^ g
        tax
        pla
        jsr     mulxn
        eor     st+S_G
        sta     tmp
        txa
        eor     st+S_G+1
        ldy     nn              ; after the payload: CRC high, low, the
        sta     (optr),y        ; delimiter
        iny
        lda     tmp
        sta     (optr),y
        iny
        lda     #0
        sta     (optr),y
        tya                     ; end = o + n + 2
        clc
        adc     optr
        sta     optr
        bcc     :+
        inc     optr+1
:       tya                     ; every 0x00 of pkt[1 .. n + 9] linked,
        clc                     ; the delimiter's the last code
        adc     #8
        jsr     links0
        jmp     go

; ---- helpers
; the header at pkt + 1: BAND, frame, y0, codec A; cl:ch = the CRC of
; b[3..5] on from hcrc (b[0..2]'s); optr = b + 6 (the payload)
hdr:    ldy     #6
        sta     (pk),y          ; b[5] = the codec
        dey
        lda     y0
        sta     (pk),y
        dey
        lda     y0+1
        sta     (pk),y
        ldy     #TX_FRAME
        lda     (tx),y
        tax
        iny
        lda     (tx),y
        ldy     #2
        sta     (pk),y          ; b[1] = frame high
        txa
        iny
        sta     (pk),y          ; b[2] = frame low
        ldy     #1
        lda     #2              ; R8_PKT_BAND
        sta     (pk),y
        ldy     #TX_HCRC
        lda     (tx),y
        sta     cl
        iny
        lda     (tx),y
        sta     ch
        ldy     #4
@c:     lda     (pk),y
        CRCSTEP
        iny
        cpy     #7
        bne     @c
        lda     pk
        clc
        adc     #7
        sta     optr
        lda     pk+1
        adc     #0
        sta     optr+1
        rts

; link the 0x00 of pkt[1 .. A) into a chain from the code at pkt[0]
; (every one: the caller knows no block is over 254 bytes); X = the
; offset of the last code
links0: sta     left
        ldx     #0
        ldy     #1
@l:     lda     (pk),y
        bne     @n
        sty     tmp
        stx     tmp+1
        tya                     ; *code = q - code
        sec
        sbc     tmp+1
        ldy     tmp+1
        sta     (pk),y
        ldy     tmp             ; code = q
        ldx     tmp
@n:     iny
        cpy     left
        bne     @l
        rts

; link the 0x00 at optr + A into s's chain: carry set (and nothing
; done) when it is more than 254 bytes after the last code
linko:  clc
        adc     optr
        sta     tmp
        lda     optr+1
        adc     #0
        sta     tmp+1
        lda     tmp
        sec
        sbc     st+S_CODE
        tax
        lda     tmp+1
        sbc     st+S_CODE+1
        bne     @far
        cpx     #255
        bcs     @far
        ; *code = q - code
        lda     st+S_CODE
        sta     lk
        lda     st+S_CODE+1
        sta     lk+1
        txa
        ldy     #0
        sta     (lk),y
        lda     tmp
        sta     st+S_CODE
        lda     tmp+1
        sta     st+S_CODE+1
        clc
        rts
@far:   sec
        rts

; o += 2
adv2:   lda     optr
        clc
        adc     #2
        sta     optr
        bcc     :+
        inc     optr+1
:       rts

; p += cnt
advp:   lda     ptr
        clc
        adc     cnt
        sta     ptr
        bcc     :+
        inc     ptr+1
:       rts

; one fingerprint byte A at fpp[y]: tmp |= changed; y++
fpb:    tax
        eor     (fpp),y
        ora     tmp
        sta     tmp
        txa
        sta     (fpp),y
        iny
        rts

; next_y = y0 + band, next_idx++, raw_bytes += n
commit: ldy     #TX_BAND
        lda     (tx),y
        clc
        adc     y0
        ldy     #TX_NEXTY
        sta     (tx),y
        ldy     #TX_BAND+1
        lda     (tx),y
        adc     y0+1
        ldy     #TX_NEXTY+1
        sta     (tx),y
        ldy     #TX_NEXTIDX
        lda     (tx),y
        clc
        adc     #1
        sta     (tx),y
        iny
        lda     (tx),y
        adc     #0
        sta     (tx),y
        ldy     #TX_RAW
        lda     nn
        ldx     #0
; the 32-bit tx field at y += X:A
add32:  clc
        adc     (tx),y
        sta     (tx),y
        iny
        txa
        adc     (tx),y
        sta     (tx),y
        iny
        lda     (tx),y
        adc     #0
        sta     (tx),y
        iny
        lda     (tx),y
        adc     #0
        sta     (tx),y
        rts

; tx->fcrc = r8_crc16_mul(tx->fcrc, tx->xn)
fcrcmul:
        ldy     #TX_FCRC+1
        lda     (tx),y
        tax
        dey
        lda     (tx),y
        jsr     mulxn
        ldy     #TX_FCRC
        sta     (tx),y
        iny
        txa
        sta     (tx),y
        rts

; A/X = r8_crc16_mul(A/X, tx->xn): a CRC shifted over the band's n bytes
mulxn:  jsr     pushax
        ldy     #TX_XN+1
        lda     (tx),y
        tax
        dey
        lda     (tx),y
        jmp     _r8_crc16_mul
