;; txband_z80.s - r8_tx_band (include/r8wire.h) for the Z80 (sdcc 4.2,
;; sdas; issue 10): one band of a frame onto the wire without the C glue,
;; as ports/6502/txband_6502.s.  In the Z80 archive with Z80_ASM's
;; "txband" (with "wire": it calls wire_z80.s's kernels), which builds
;; the library with -DR8_ASM_TXBAND (mk/targets.mk): src/wire.c then
;; names its C89 version r8_tx_band_c, the reference, and this one takes
;; the common case and hands every other to it:
;;
;;   in a frame, the band the encoder expects next (y0 = next_y), a whole
;;   band (height - y0 >= band), the frame's width and format, codec RLE,
;;   8 <= band bytes <= 255; and the RLE payload smaller than the band,
;;   with the COBS chain never broken (no block of 254 non-zero bytes),
;;   or else (RLE does not pay) a packet of under 250 bytes, sent raw.
;;
;; Nothing of tx changes before that is known (only the packet scratch
;; is written), so the C version then does the whole band itself.  What
;; is left is what src/wire.c's r8_tx_band, tx_band, tx_rle and tx_send
;; do on that path: the header, the RLE tokens (r8_tx_run and r8_tx_lit
;; of wire_z80.s: packet CRC, the band's CRC from 0, Fletcher sums, COBS
;; links) or the raw bytes (tx_send's all = 1), the fingerprint, the
;; frame CRC, the skip of an unchanged band in a delta frame, and one put
;; of the framed packet.  So every band of the demo firmware's stream
;; (128 x 8 bands, 137-byte packets) that comes in order is taken here:
;; it builds src/wire.c with R8_TXBAND_ALL (FWK_z80, mk/targets.mk),
;; which leaves out the C band path (tx_band, tx_rle) and links a relay
;; r8_tx_band_c for a band out of order.
;; r8_tx_pkt (src/r8crc.h) is tx_send's all = 1 path, for such a
;; firmware built with -DR8_ASM_TXPKT too: FRAME_START and FRAME_END.
;; tests/c/test_txband.c compares the two on random frames in ucsim (and
;; counts the bands handed on), r8_tx_pkt with tx_send on random bodies,
;; and the r8_tx / r8_fb offsets below with the C compiler's
;; (r8_txband_offs).
;;
;; sdcc's __sdcccall(1): tx in HL, band in DE, the int result in DE; IX
;; (the caller's frame pointer) is kept: here it holds tx.  The callees
;; (wire_z80.s, the put function) keep IX and pop their stack arguments.
        .module txband_z80

        .globl  _r8_tx_band
        .globl  _r8_tx_pkt
        .globl  _r8_txband_offs
        .globl  _r8_tx_band_c
        .globl  _r8_tx_zeros
        .globl  _r8_tx_run
        .globl  _r8_tx_lit
        .globl  _r8_crc16_mul
        .globl  r8z_crctab

;; the CRC byte step of wire_z80.s: byte in A, crc in B:C, H = the
;; table's page (L changed)
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

;; r8_tx (include/r8wire.h) and r8_fb (include/r8fb.h) on sdcc
TX_FORMAT  = 0x00
TX_WIDTH   = 0x01
TX_HEIGHT  = 0x03
TX_BAND    = 0x05
TX_CODEC   = 0x07
TX_PUT     = 0x0E
TX_CTX     = 0x10
TX_PKT     = 0x12
TX_FP      = 0x16
TX_BANDB   = 0x1A
TX_XN      = 0x1C
TX_NEXTY   = 0x1E
TX_NEXTIDX = 0x20
TX_FRAME   = 0x22
TX_SENT    = 0x26
TX_FCRC    = 0x28
TX_HCRC    = 0x2A
TX_FULL    = 0x2C
TX_INFRAME = 0x2E
TX_BYTES   = 0x3C
TX_RAW     = 0x40
FB_BUF     = 0x00
FB_WIDTH   = 0x02
FB_Y0      = 0x06
FB_FORMAT  = 0x0A
;; r8_tx_st (src/r8crc.h)
S_CRC   = 0
S_F1    = 2
S_F2    = 3
S_PKT   = 4
S_CODE  = 6
S_G     = 8

        .area   _DATA
fbp:    .ds     2               ; the r8_fb
bp:     .ds     2               ; its buffer
fpp:    .ds     2               ; tx->fp + 4 * idx
y0:     .ds     2
pp:     .ds     2               ; the band byte being encoded
op:     .ds     2               ; the payload byte being written
len:    .ds     2               ; the framed packet's bytes
nn:     .ds     1               ; band bytes
zz:     .ds     1               ; its leading zeros
room:   .ds     1               ; payload bytes still free
left:   .ds     1               ; band bytes not encoded yet
full:   .ds     1               ; a literal count that means "no room"
cnt:    .ds     1               ; the token's bytes
st:     .ds     10              ; the r8_tx_st of the packet
hcrc:   .ds     2               ; the CRC after the RLE header (raw: Pb, g)
hcode:  .ds     2               ; the chain after the header's links
xtkey:  .ds     2               ; the xn xt is built for (0: none; xn != 0)
xt:     .ds     512             ; xt[i] = i * xn mod P, i = 0..255 (low, high)

        .area   _CODE
;; the offsets above, in the order tests/c/test_txband.c checks them
_r8_txband_offs:
        .db     TX_FORMAT, TX_WIDTH, TX_HEIGHT, TX_BAND, TX_CODEC, TX_PUT, TX_CTX
        .db     TX_PKT, TX_FP, TX_BANDB, TX_XN, TX_NEXTY, TX_NEXTIDX, TX_FRAME
        .db     TX_SENT, TX_FCRC, TX_HCRC, TX_FULL, TX_INFRAME, TX_BYTES, TX_RAW
        .db     FB_BUF, FB_WIDTH, FB_Y0, FB_FORMAT

;; int r8_tx_band(r8_tx *tx, const r8_fb *band)
_r8_tx_band:
        push    ix
        push    hl
        pop     ix              ; IX = tx
        ld      (fbp), de
        ld      a, TX_INFRAME (ix) ; the common case?
        or      a, a
        jp      z, slow
        ld      a, TX_CODEC (ix)
        dec     a               ; R8_CODEC_RLE
        jp      nz, slow
        ld      a, TX_BANDB+1 (ix)
        or      a, a
        jp      nz, slow
        ld      a, TX_BANDB (ix)
        cp      a, #8
        jp      c, slow
        ld      (nn), a
        ex      de, hl          ; HL = band
        ld      e, (hl)         ; FB_BUF
        inc     hl
        ld      d, (hl)
        ld      (bp), de
        inc     hl              ; FB_WIDTH
        ld      a, (hl)
        cp      a, TX_WIDTH (ix)
        jp      nz, slow
        inc     hl
        ld      a, (hl)
        cp      a, TX_WIDTH+1 (ix)
        jp      nz, slow
        inc     hl
        inc     hl
        inc     hl              ; FB_Y0
        ld      e, (hl)
        inc     hl
        ld      d, (hl)         ; DE = y0
        bit     7, d
        jp      nz, slow        ; y0 < 0
        ld      (y0), de
        ld      bc, #FB_FORMAT-FB_Y0-1
        add     hl, bc
        ld      a, (hl)
        cp      a, TX_FORMAT (ix)
        jp      nz, slow
        ld      a, TX_NEXTY (ix)
        cp      a, e
        jp      nz, slow
        ld      a, TX_NEXTY+1 (ix)
        cp      a, d
        jp      nz, slow
        ld      l, TX_HEIGHT (ix) ; height - y0 - band >= 0: a whole band
        ld      h, TX_HEIGHT+1 (ix)
        or      a, a
        sbc     hl, de
        ld      e, TX_BAND (ix)
        ld      d, TX_BAND+1 (ix)
        or      a, a
        sbc     hl, de
        jp      m, slow

        ld      e, TX_XN (ix)   ; xt for this xn (fcrcmul)
        ld      d, TX_XN+1 (ix)
        ld      hl, (xtkey)
        or      a, a
        sbc     hl, de
        call    nz, xtbuild
        ld      hl, #0
        ld      (st+S_F1), hl   ; f1 = f2 = 0
        ld      (st+S_G), hl    ; g = 0 (a band of zeros: fcrcmul takes it)
        ld      l, TX_NEXTIDX (ix) ; fpp = tx->fp + 4 idx
        ld      h, TX_NEXTIDX+1 (ix)
        add     hl, hl
        add     hl, hl
        ld      e, TX_FP (ix)
        ld      d, TX_FP+1 (ix)
        add     hl, de
        ld      (fpp), hl
        ld      hl, (bp)        ; zz: the leading zeros
        ld      a, (nn)
        ld      e, a
        ld      d, #0
        call    _r8_tx_zeros    ; -> DE
        ld      a, e
        ld      (zz), a
        ld      hl, #nn
        cp      a, (hl)
        jr      nz, encode
        ld      hl, (fpp)       ; a band of zeros: unchanged in a delta
        ld      a, (hl)         ; frame, only the frame CRC moves
        inc     hl
        or      a, (hl)
        inc     hl
        or      a, (hl)
        inc     hl
        or      a, (hl)
        or      a, TX_FULL (ix)
        jr      nz, encode
        call    commit
        call    fcrcmul
        jp      done

;; ---- the packet, in the scratch only
encode: ld      l, TX_PKT (ix)  ; s.pkt = s.code = pkt
        ld      h, TX_PKT+1 (ix)
        ld      (st+S_PKT), hl
        inc     hl              ; header b = pkt + 1: BAND, frame, y0, RLE
        ld      (hl), #2        ; R8_PKT_BAND
        inc     hl
        ld      a, TX_FRAME+1 (ix)
        ld      (hl), a
        inc     hl
        ld      a, TX_FRAME (ix)
        ld      (hl), a
        inc     hl
        ld      de, (y0)
        ld      (hl), d
        inc     hl
        ld      (hl), e
        inc     hl
        ld      (hl), #1        ; R8_CODEC_RLE
        inc     hl
        ld      (op), hl        ; o = b + 6
        ld      c, TX_HCRC (ix) ; s.crc = crc(hcrc, b[3..5])
        ld      b, TX_HCRC+1 (ix)
        ld      h, #>r8z_crctab
        ld      a, d
        CRCSTEP
        ld      a, e
        CRCSTEP
        ld      a, #1
        CRCSTEP
        ld      (st+S_CRC), bc
        ld      (hcrc), bc      ; (for the raw path)
        ld      hl, (st+S_PKT)  ; the header's zeros (b[1..4]) linked
        ld      d, h
        ld      e, l            ; DE = code
        inc     hl
        ld      b, #4
1$:     inc     hl
        ld      a, (hl)
        or      a, a
        jr      nz, 2$
        ld      a, l            ; *code = q - code (at most 5)
        sub     a, e
        ld      (de), a
        ld      d, h
        ld      e, l
2$:     djnz    1$
        ld      (st+S_CODE), de
        ld      (hcode), de     ; (for the raw path)
        ld      hl, (bp)
        ld      (pp), hl
        ld      a, (nn)
        ld      (left), a
        dec     a
        ld      (room), a       ; cap = n - 1

;; the leading zeros: runs of up to 127 while 3 or more are left
zl:     ld      a, (zz)
        cp      a, #3
        jr      c, tokens
        cp      a, #127
        jr      c, 1$
        ld      a, #127
1$:     ld      (cnt), a
        ld      a, (room)
        sub     a, #2
        jp      c, raw          ; no room: RLE does not pay
        ld      (room), a
        ld      hl, (op)        ; [c, 0]
        ld      a, (cnt)
        ld      (hl), a
        inc     hl
        ld      (hl), #0
        ld      bc, (st+S_CRC)  ; s.crc over them
        ld      h, #>r8z_crctab
        CRCSTEP
        xor     a, a
        CRCSTEP
        ld      (st+S_CRC), bc
        ld      a, #1           ; link o + 1
        call    linko
        jp      c, slow
        call    adv2
        ld      hl, #cnt
        ld      a, (zz)
        sub     a, (hl)
        ld      (zz), a
        ld      a, (left)
        sub     a, (hl)
        ld      (left), a
        call    advp
        jr      zl

;; the tokens, as tx_rle: a run of 3 or more, else literals
tokens: ld      a, (left)
        or      a, a
        jp      z, sent
        cp      a, #127
        jr      c, 1$
        ld      a, #127
1$:     ld      (cnt), a        ; c = min(127, left)
        cp      a, #3
        jr      c, lit
        ld      hl, (pp)
        ld      a, (hl)
        inc     hl
        cp      a, (hl)
        jr      nz, lit
        inc     hl
        cp      a, (hl)
        jr      nz, lit
        ld      a, (room)       ; a run
        sub     a, #2
        jp      c, raw
        ld      (room), a
        ld      a, (cnt)
        push    af
        inc     sp              ; k: one byte
        ld      hl, (pp)
        push    hl
        ld      de, (op)
        ld      hl, #st
        call    _r8_tx_run      ; (pops p, k) -> A
        ld      (cnt), a
        ld      hl, (op)
        inc     hl
        ld      a, (hl)
        or      a, a
        jr      nz, 2$
        inc     a               ; link o + 1
        call    linko
        jp      c, slow
2$:     call    adv2
        jr      next
lit:    ld      a, (left)       ; B = k: where a run of 3 may start
        ld      b, #127
        cp      a, #129
        jr      nc, 1$
        ld      b, #0
        cp      a, #2
        jr      c, 1$
        sub     a, #2
        ld      b, a
1$:     xor     a, a
        ld      (full), a
        ld      a, (cnt)
        ld      c, a            ; C = c
        ld      a, (room)       ; room <= c: at most room - 1 fit
        cp      a, c
        jr      z, 2$
        jr      nc, 3$
2$:     cp      a, #2
        jp      c, raw
        dec     a
        ld      c, a
        ld      (full), a
        cp      a, b            ; k = min(k, c)
        jr      nc, 3$
        ld      b, a
3$:     ld      h, c
        ld      l, b
        push    hl              ; k, c: one byte each
        ld      hl, (pp)
        push    hl
        ld      de, (op)
        ld      hl, #st
        call    _r8_tx_lit      ; (pops p, k, c) -> A
        bit     7, a
        jp      nz, slow        ; the chain broke: the C does it
        ld      hl, #full
        cp      a, (hl)
        jp      z, raw          ; no room
        ld      (cnt), a
        ld      c, a
        ld      a, (room)       ; room -= c + 1
        sub     a, c
        dec     a
        ld      (room), a
        ld      hl, (op)        ; o += c + 1
        ld      b, #0
        add     hl, bc
        inc     hl
        ld      (op), hl
next:   ld      hl, #cnt
        ld      a, (left)
        sub     a, (hl)
        ld      (left), a
        call    advp
        jp      tokens

;; ---- RLE does not pay: the band raw (tx_band's from == b, tx_send's
;; all = 1), when the packet (n + 6 + 2 bytes) is under 250 bytes, so no
;; 0x00 is more than 254 bytes after the code before it and the chain
;; cannot break (the C does a longer one).  The header stays, its links
;; too (hcode: the chain after them), b[5] = R8_CODEC_RAW is linked, and
;; its CRC is the RLE header's with the codec byte 1 -> 0: ^ T[1] =
;; 0x1021 (the table step is linear).  Then one loop copies the band,
;; CRCs it, sums it and links its zeros.  The band's CRC from 0 (its
;; leading zeros leave it 0, as the C's from src + z) comes from the
;; packet CRC: g = Pb x^(8n) ^ Pa (Pb, Pa: before and after the band),
;; fcrcmul's, with IX at hcrc - TX_FCRC.              ~125 T a byte
raw:    ld      a, (nn)
        cp      a, #250-6-2
        jp      nc, slow
        ld      hl, (hcode)
        ld      (st+S_CODE), hl
        ld      de, (st+S_PKT)
        ld      hl, #6
        add     hl, de
        ex      de, hl          ; DE = b + 5
        xor     a, a
        ld      (de), a         ; R8_CODEC_RAW
        call    rawz
        inc     de              ; main: DE = o, HL = band, B = the count
        ld      hl, (hcrc)      ; Pb
        ld      a, h
        xor     a, #0x10
        ld      b, a
        ld      a, l
        xor     a, #0x21
        ld      c, a
        ld      (hcrc), bc
        push    bc
        ld      hl, (bp)
        exx                     ; alternate: B:C = crc, E = f1, D = f2,
        pop     bc              ; H = the table's page
        ld      de, #0
        ld      h, #>r8z_crctab
        exx
        ld      a, (nn)
        ld      b, a
1$:     ld      a, (hl)
        ld      (de), a
        or      a, a
        call    z, rawz
        inc     hl
        inc     de
        exx
        ld      l, a
        add     a, e            ; f1 += v, f2 += f1
        ld      e, a
        add     a, d
        ld      d, a
        ld      a, l
        CRCSTEP
        exx
        djnz    1$
        ld      (op), de
        exx
        ld      (st+S_F1), de
        ld      (st+S_CRC), bc
        ld      (st+S_G), bc    ; Pa
        exx
        push    ix
        ld      ix, #hcrc-TX_FCRC
        call    fcrcmul         ; hcrc = Pb x^(8n) ^ Pa
        pop     ix
        ld      hl, (hcrc)
        ld      (st+S_G), hl

;; ---- the payload is in: o = end - 2; the CRC, links, the last code
sent:   ld      hl, (op)        ; o[0], o[1] = the packet CRC
        ld      a, (st+S_CRC+1)
        ld      (hl), a
        or      a, a
        jr      nz, 1$
        call    linko           ; (A = 0: o + 0)
        jp      c, slow
1$:     ld      hl, (op)
        inc     hl
        ld      a, (st+S_CRC)
        ld      (hl), a
        or      a, a
        jr      nz, 2$
        inc     a
        call    linko
        jp      c, slow
2$:     ld      hl, (op)        ; end = o + 2
        inc     hl
        inc     hl
        ld      (op), hl
        ld      de, (st+S_CODE) ; end - code <= 255
        or      a, a
        sbc     hl, de
        ld      a, h
        or      a, a
        jp      nz, slow
        ld      a, l
        ld      (de), a         ; *code = end - code
        ld      hl, (op)
        ld      (hl), #0        ; *end = 0

;; ---- it goes: now tx changes
        call    commit
        ld      a, (zz)
        ld      hl, #nn
        cp      a, (hl)
        jr      nz, 3$
        call    fcrcmul         ; zeros: fp = 0, fcrc = fcrc x^(8n)
        ld      hl, (fpp)
        xor     a, a
        ld      (hl), a
        inc     hl
        ld      (hl), a
        inc     hl
        ld      (hl), a
        inc     hl
        ld      (hl), a
        jr      send
3$:     ld      hl, (fpp)       ; the fingerprint g, f1, f2
        ld      c, #0           ; C: changed
        ld      a, (st+S_G+1)
        call    fpb
        ld      a, (st+S_G)
        call    fpb
        ld      a, (st+S_F1)
        call    fpb
        ld      a, (st+S_F2)
        call    fpb
        push    bc
        call    fcrcmul         ; fcrc = fcrc x^(8n) ^ g
        pop     bc
        ld      a, c            ; changed, or a full frame?
        or      a, TX_FULL (ix)
        jr      z, done
send:   ld      l, TX_SENT (ix) ; tx->sent++ (before the put, which
        ld      h, TX_SENT+1 (ix) ; does not read it: the put below is
        inc     hl              ; r8_tx_pkt's too)
        ld      TX_SENT (ix), l
        ld      TX_SENT+1 (ix), h
;; put(ctx, pkt, end + 1 - pkt), tx->bytes += that; pop IX, return 0
pput:   ld      hl, (op)        ; the packet: end + 1 - pkt bytes
        inc     hl
        ld      de, (st+S_PKT)
        or      a, a
        sbc     hl, de
        ld      (len), hl
        push    hl              ; put(ctx, pkt, len): len on the stack
        ld      l, TX_PUT (ix)
        ld      h, TX_PUT+1 (ix)
        push    hl
        pop     iy
        ld      l, TX_CTX (ix)
        ld      h, TX_CTX+1 (ix)
        call    calliy          ; (pops len)
        ld      de, (len)       ; tx->bytes += len
        ld      a, TX_BYTES (ix)
        add     a, e
        ld      TX_BYTES (ix), a
        ld      a, TX_BYTES+1 (ix)
        adc     a, d
        ld      TX_BYTES+1 (ix), a
        ld      a, TX_BYTES+2 (ix)
        adc     a, #0
        ld      TX_BYTES+2 (ix), a
        ld      a, TX_BYTES+3 (ix)
        adc     a, #0
        ld      TX_BYTES+3 (ix), a
done:   pop     ix
        ld      de, #0          ; R8_OK
        ret

slow:   push    ix              ; the C version does it all: tx HL, band DE
        pop     hl
        ld      de, (fbp)
        pop     ix
        jp      _r8_tx_band_c

calliy: jp      (iy)

;; void r8_tx_pkt(r8_tx *tx, unsigned n) (src/r8crc.h; src/wire.c
;; R8_ASM_TXPKT): tx in HL, n in E (n + 4 < 255).  tx_send's all = 1
;; path, left with FRAME_START and FRAME_END (two a frame: small, not
;; fast): the body pkt[1 .. n] gets its CRC-16 from R8_CRC16_INIT, high
;; byte first, and the delimiter after it; every 0x00 of pkt[1 .. n + 3]
;; is linked by rawz (no block can be over 254 bytes), the delimiter's
;; the last code; one put of n + 4 bytes (pput), counted in tx->bytes.
_r8_tx_pkt:
        push    ix
        push    hl
        pop     ix              ; IX = tx (pput's)
        ld      a, e
        ld      (nn), a
        ld      l, TX_PKT (ix)
        ld      h, TX_PKT+1 (ix)
        ld      (st+S_PKT), hl
        ld      (st+S_CODE), hl ; pkt[0]: the first code
        ex      de, hl          ; DE = pkt
        push    de
        ld      bc, #0xFFFF     ; R8_CRC16_INIT
        ld      h, #>r8z_crctab
        or      a, a
        jr      z, 2$
1$:     push    af              ; (A: the bytes left)
        inc     de
        ld      a, (de)
        CRCSTEP
        pop     af
        dec     a
        jr      nz, 1$
2$:     inc     de              ; pkt[n + 1], pkt[n + 2] = the CRC,
        ld      a, b            ; pkt[n + 3] = 0
        ld      (de), a
        inc     de
        ld      a, c
        ld      (de), a
        inc     de
        xor     a, a
        ld      (de), a
        ld      (op), de        ; end = pkt + n + 3
        pop     de              ; link the 0x00 of pkt[1 .. n + 3]
        ld      a, (nn)
        add     a, #3
        ld      b, a
3$:     inc     de
        ld      a, (de)
        or      a, a
        call    z, rawz
        djnz    3$
        jp      pput

;; ---- helpers
;; the raw loop's 0x00 at DE: *code = DE - code, code = DE (< 250 bytes
;; on: no test); A = 0 again
rawz:   push    hl
        ld      hl, (st+S_CODE)
        ld      a, e
        sub     a, l
        ld      (hl), a
        ld      (st+S_CODE), de
        pop     hl
        xor     a, a
        ret

;; link the 0x00 at o + A into s's chain: carry set (and nothing done)
;; when it is more than 254 bytes after the last code
linko:  ld      hl, (op)
        add     a, l
        ld      l, a
        jr      nc, 1$
        inc     h
1$:     push    hl              ; q
        ld      de, (st+S_CODE)
        or      a, a
        sbc     hl, de          ; q - code
        ld      a, h
        or      a, a
        jr      nz, 2$
        ld      a, l
        cp      a, #255
        jr      nc, 2$
        ld      (de), a         ; *code = q - code
        pop     hl
        ld      (st+S_CODE), hl ; code = q
        or      a, a
        ret
2$:     pop     hl
        scf
        ret

;; o += 2
adv2:   ld      hl, (op)
        inc     hl
        inc     hl
        ld      (op), hl
        ret

;; p += cnt
advp:   ld      hl, (pp)
        ld      a, (cnt)
        add     a, l
        ld      l, a
        jr      nc, 1$
        inc     h
1$:     ld      (pp), hl
        ret

;; one fingerprint byte A at (HL): C |= changed; HL++
fpb:    ld      b, a
        xor     a, (hl)
        or      a, c
        ld      c, a
        ld      (hl), b
        inc     hl
        ret

;; next_y = y0 + band, next_idx++, raw_bytes += n
commit: ld      hl, (y0)
        ld      e, TX_BAND (ix)
        ld      d, TX_BAND+1 (ix)
        add     hl, de
        ld      TX_NEXTY (ix), l
        ld      TX_NEXTY+1 (ix), h
        ld      l, TX_NEXTIDX (ix)
        ld      h, TX_NEXTIDX+1 (ix)
        inc     hl
        ld      TX_NEXTIDX (ix), l
        ld      TX_NEXTIDX+1 (ix), h
        ld      a, (nn)
        add     a, TX_RAW (ix)
        ld      TX_RAW (ix), a
        ld      a, #0
        adc     a, TX_RAW+1 (ix)
        ld      TX_RAW+1 (ix), a
        ld      a, #0
        adc     a, TX_RAW+2 (ix)
        ld      TX_RAW+2 (ix), a
        ld      a, #0
        adc     a, TX_RAW+3 (ix)
        ld      TX_RAW+3 (ix), a
        ret

;; tx->fcrc = r8_crc16_mul(tx->fcrc, tx->xn) ^ s.g, by the table xt of
;; the multiples of xn (built for tx->xn on the way in: at a stream's
;; first band, ~14 k T): with fcrc = fh x^8 + fl, fcrc xn = (fh xn) x^8
;; + fl xn, and the x^8 is the CRC table's zero-byte step.  ~230 T
;; against ~850 for r8_crc16_mul (8 bands a frame: ~5 k T).
fcrcmul:
        ld      l, TX_FCRC+1 (ix) ; xt[fh]
        ld      h, #0
        add     hl, hl
        ld      de, #xt
        add     hl, de
        ld      c, (hl)
        inc     hl
        ld      b, (hl)
        ld      h, #>r8z_crctab ; * x^8: (C ^ Th[B]) : Tl[B]
        ld      l, b
        ld      a, (hl)
        xor     a, c
        ld      b, a
        inc     h
        ld      c, (hl)
        ld      hl, (st+S_G)    ; ^ g
        ld      a, l
        xor     a, c
        ld      c, a
        ld      a, h
        xor     a, b
        ld      b, a
        ld      l, TX_FCRC (ix) ; ^ xt[fl]
        ld      h, #0
        add     hl, hl
        add     hl, de
        ld      a, (hl)
        xor     a, c
        ld      TX_FCRC (ix), a
        inc     hl
        ld      a, (hl)
        xor     a, b
        ld      TX_FCRC+1 (ix), a
        ret

;; xt[i] = i * xn mod P for xn = DE: xt[0] = 0, xt[1] = xn, then
;; xt[2k] = xt[k] * x and xt[2k + 1] = xt[2k] ^ xn for k = 1..127
xtbuild:
        ld      (xtkey), de
        ld      b, d
        ld      c, e            ; BC = xn
        ld      hl, #xt
        xor     a, a
        ld      (hl), a
        inc     hl
        ld      (hl), a
        inc     hl
        ld      (hl), c
        inc     hl
        ld      (hl), b
        inc     hl              ; HL = xt + 4: xt[2]
        ld      iy, #xt+2       ; IY = xt[k], k = 1
1$:     ld      e, 0 (iy)
        ld      d, 1 (iy)
        inc     iy
        inc     iy
        ex      de, hl          ; xt[k] * x mod P
        add     hl, hl
        jr      nc, 2$
        ld      a, h
        xor     a, #0x10
        ld      h, a
        ld      a, l
        xor     a, #0x21
        ld      l, a
2$:     ex      de, hl
        ld      (hl), e         ; xt[2k]
        inc     hl
        ld      (hl), d
        inc     hl
        ld      a, e            ; xt[2k + 1]
        xor     a, c
        ld      (hl), a
        inc     hl
        ld      a, d
        xor     a, b
        ld      (hl), a
        inc     hl
        ld      de, #xt+512
        or      a, a
        sbc     hl, de
        add     hl, de
        jr      nz, 1$
        ret
