/* fill.S - r8k_fill (include/r8kern.h) for AVR: the band and depth
 * clears of r8_render_band.
 *
 *   void r8k_fill(r8_u8 *p, r8_u8 v, unsigned n);    p[0..n-1] = v
 *
 * The same bytes as the C reference (memset, src/kern.c): n & 15 single
 * stores first, then blocks of 16 unrolled stores: 36 cycles per 16
 * bytes (2.25 a byte; avr-libc's memset loop takes 6).
 */
    .section .text.r8k_fill,"ax",@progbits
    .global r8k_fill
    .type   r8k_fill, @function
r8k_fill:
    movw  r26, r24          /* X = p */
    mov   r18, r20          /* n & 15 bytes one by one */
    andi  r18, 15
    breq  2f
1:  st    X+, r22
    dec   r18
    brne  1b
2:  lsr   r21               /* n >> 4 blocks of 16 */
    ror   r20
    lsr   r21
    ror   r20
    lsr   r21
    ror   r20
    lsr   r21
    ror   r20
    cp    r20, r1
    cpc   r21, r1
    breq  4f
3:  st    X+, r22
    st    X+, r22
    st    X+, r22
    st    X+, r22
    st    X+, r22
    st    X+, r22
    st    X+, r22
    st    X+, r22
    st    X+, r22
    st    X+, r22
    st    X+, r22
    st    X+, r22
    st    X+, r22
    st    X+, r22
    st    X+, r22
    st    X+, r22
    subi  r20, 1
    sbci  r21, 0
    brne  3b
4:  ret
    .size r8k_fill, .-r8k_fill
