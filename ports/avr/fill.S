/* fill.S - r8k_fill (include/r8kern.h) for AVR: the band and depth
 * clears of r8_render_band.
 *
 *   void r8k_fill(r8_u8 *p, r8_u8 v, unsigned n);    p[0..n-1] = v
 *
 * The same bytes as the C reference (memset, src/kern.c): passes of 64
 * unrolled stores, the first one entered at store 64 - (n mod 64) by an
 * ijmp when n is not a multiple of 64: 133 cycles per 64 bytes (2.08 a
 * byte; avr-libc's memset loop takes 6).
 */
    .section .text.r8k_fill,"ax",@progbits
    .global r8k_fill
    .type   r8k_fill, @function
r8k_fill:
    movw  r26, r24          /* X = p */
    mov   r18, r20          /* n mod 64 */
    andi  r18, 63
    clr   r25               /* r25:r24 = n >> 6 passes */
    lsl   r20
    rol   r21
    rol   r25
    lsl   r20
    rol   r21
    rol   r25
    mov   r24, r21
    tst   r18
    brne  2f
    sbiw  r24, 0
    brne  3f
    ret                     /* n = 0 */
2:  adiw  r24, 1            /* a first pass of n mod 64 stores */
    ldi   r30, pm_lo8(4f)
    ldi   r31, pm_hi8(4f)
    sub   r30, r18
    sbc   r31, r1
    ijmp
3:  .rept 64
    st    X+, r22
    .endr
4:  sbiw  r24, 1
    breq  5f
    rjmp  3b                /* (brne does not reach 64 words back) */
5:  ret
    .size r8k_fill, .-r8k_fill
