; txoffs_6502.s - r8_txband_offs: txband_6502.s's offsets of r8_tx and
; r8_fb, in the order tests/c/test_txband.c checks them against the C
; compiler's.  A module of its own: only that test refers to it, so gc65
; leaves it out of the firmware (it keeps a hand-written module whole
; once anything in it is needed, and txband_6502.s always is).  (ca65
; gives the offsets, all under 256, zero-page size: .importzp)

        .export         _r8_txband_offs
        .importzp       TX_FORMAT, TX_WIDTH, TX_HEIGHT, TX_BAND, TX_CODEC, TX_PUT
        .importzp       TX_CTX, TX_PKT, TX_FP, TX_BANDB, TX_XN, TX_NEXTY, TX_NEXTIDX
        .importzp       TX_FRAME, TX_SENT, TX_FCRC, TX_HCRC, TX_FULL, TX_INFRAME
        .importzp       TX_BYTES, TX_RAW, FB_BUF, FB_WIDTH, FB_Y0, FB_FORMAT

        .rodata
_r8_txband_offs:
        .byte   TX_FORMAT, TX_WIDTH, TX_HEIGHT, TX_BAND, TX_CODEC, TX_PUT, TX_CTX
        .byte   TX_PKT, TX_FP, TX_BANDB, TX_XN, TX_NEXTY, TX_NEXTIDX, TX_FRAME
        .byte   TX_SENT, TX_FCRC, TX_HCRC, TX_FULL, TX_INFRAME, TX_BYTES, TX_RAW
        .byte   FB_BUF, FB_WIDTH, FB_Y0, FB_FORMAT
