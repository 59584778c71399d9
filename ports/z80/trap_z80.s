;; trap_z80.s - r8k_trap for the Z80 (sdcc 4.2, sdas; issue 10).
;;
;; void r8k_trap(r8_trapfill *t, r8_interp *l, r8_interp *r, r8_u16 rows)
;; fills `rows` rows of a trapezoid into a PAGE1 band: on each row the
;; columns [l->val, r->val) clamped to [0, w), pattern pat[k] under the
;; row's bit m; then both column DDAs step, m moves to the next row (and
;; page), k to the next phase (include/r8kern.h has the contract; the C89
;; reference is src/kern.c, left out with -DR8_ASM_TRAP).
;;
;; sdcc's __sdcccall(1): t in HL, l in DE, r and rows on the stack (this
;; function pops them: it returns void).  IX is kept.
;;
;; Rows come in groups: when w <= 255 and m is one bit, the rows up to
;; the page's end (g = 2..8, at most `rows`) are done together.  Both
;; DDAs step g rows in registers on the caller's l and r (dda: each row's
;; columns clamped to [0, w] into ga, gb; ~195 T a row and edge); the
;; columns all g rows cover, [max ga, min gb), get one read-modify-write
;; a byte under the group's bits (dspan: the four phases' column values
;; in registers, ~31 T a byte for up to 8 pixels; the values come from
;; q16, the patterns transposed, cached while t->pat stays the same);
;; each row's columns left and right of those one by one (ragf, ~56 T a
;; pixel).  Other rows (m of several bits or 0, w > 255, the last row
;; of a page alone) go one at a time as before: *l, *r copied into
;; static memory, a dither span (0xFF and 0x00 are the nibbles 1111 and
;; 0000) in the same dspan loop, the DDAs stepped with the carry of the
;; err compare (ccf; adc), and copied back.
;; Round 10 (k-z80g): the pattern cache has 4 slots (the cube's faces
;; each keep theirs: newpat 9,738 -> 1,082 T a frame) and the group rows'
;; left and right parts skip the per-row min/max when the rows share
;; columns (gfast): r8k_trap 96,203 -> 84,186 T a frame (cube / cull
;; frames 2-3, emu/z80sim -P -F 2, Zilog T); +133 B code, +96 B in the
;; image (the slots' zero initialiser), +97 B RAM.
;; Round 7 (k-z80c): cube / cull frames 2-3 (emu/z80sim -P -F 2, Zilog
;; T) r8k_trap 266,571 -> ~196,000 T; the frames 591,075 + 741,200 ->
;; 546,273 + 714,315 (ucsim: see docs/benchmarks.md); the image +566 B.
;; Round 6 (k-z80b): 282,771 -> 266,571 T in r8k_trap.
;;
;; The cube / cull firmware (bench/kernz80.py, emu/z80sim, frames 1-3):
;; Z80_ASM="mul16 mullong" 1,612,609 T a frame, with trap 1,336,504
;; (-17%); the image 255 bytes smaller.  tests/targets/test_z80_kern.c
;; (step xkern-z80) compares it with the reference on random inputs.
        .module trap_z80

;; the undocumented halves of IX and IY (sdas has no names for them;
;; ucsim and emu/z80sim run them)
        .macro  LD_IXH_A
        .db     0xDD, 0x67
        .endm
        .macro  LD_IXL_A
        .db     0xDD, 0x6F
        .endm
        .macro  OR_IXH
        .db     0xDD, 0xB4
        .endm
        .macro  OR_IXL
        .db     0xDD, 0xB5
        .endm
        .macro  LD_A_IYH
        .db     0xFD, 0x7C
        .endm
        .macro  LD_IYH_A
        .db     0xFD, 0x67
        .endm
        .macro  LD_A_IYL
        .db     0xFD, 0x7D
        .endm
        .macro  OR_IYL
        .db     0xFD, 0xB5
        .endm
        .macro  LD_IYL_A
        .db     0xFD, 0x6F
        .endm
        .macro  DEC_IYL
        .db     0xFD, 0x2D
        .endm
        .globl  _r8k_trap

NSLOT   = 4                     ; the pattern cache's slots (a power of 2)

        .area   _DATA
ts:                             ; a copy of *t (r8_trapfill: 10 bytes)
ts_page: .ds    2
ts_m:   .ds     1
ts_k:   .ds     1
ts_pat: .ds     4
ts_w:   .ds     2
tl:     .ds     10              ; *l: val +0, q +2, err +4, r +6, den +8
tr:     .ds     10              ; *r
ts_rows: .ds    2
ts_pt:  .ds     2               ; t, l, r themselves
ts_pl:  .ds     2
ts_pr:  .ds     2
ts_ph:  .ds     1               ; a dither span's first phase
ts_nm:  .ds     1               ; its ~mask
ga:     .ds     8               ; a group's rows: clamp(l.val, 0, w)
gb:     .ds     8               ; clamp(r.val, 0, w) (ga + 8)
gg:     .ds     1               ; the group's rows (2..8)
gA:     .ds     1               ; max ga, or 255: no common columns
gB:     .ds     1               ; min gb, or 255
gC:     .ds     1               ; the rows to the page's end
gM:     .ds     1               ; m after the group (0: the next page)
gslow:  .ds     1               ; nonzero: a DDA of the group went slow
pr12:   .ds     2               ; this call's slot's r12 and q16
pq16:   .ds     2
        ;; the pattern cache, rebuilt when t->pat differs from its
        ;; patterns (all zero at start: consistent).  The patterns (4),
        ;; r12 (12): pat[0..3]'s
        ;; low nibbles, each twice in its byte (bit 7: phase 0), three
        ;; times over; q16 (16): q16[4 j + ph] the column byte of phase ph
        ;; for rows from phase j: bit i = bit 3 - ph of pat[(j + i) & 3]
        ;; NSLOT such slots of 32 bytes, rebuilt in turn (cvic: the next
        ;; one's offset): the cube's three faces keep theirs
cvic:   .ds     1
        .area   _INITIALIZED
cache:  .ds     32 * NSLOT
        .area   _INITIALIZER
        .rept   2 * NSLOT
        .db     0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0
        .endm

        .area   _CODE

p2:     .db     1, 2, 4, 8, 16, 32, 64, 128, 0  ; 1 << i (0: past bit 7)

_r8k_trap:
        ld      (ts_pt), hl
        ld      (ts_pl), de
        ld      de, #ts
        ldi                     ; (10 bytes: ldir's 21 T a byte less
        ldi                     ; its loop)
        ldi
        ldi
        ldi
        ldi
        ldi
        ldi
        ldi
        ldi
        pop     bc              ; the return address
        pop     hl              ; r
        pop     de              ; rows
        push    bc
        ld      (ts_pr), hl
        ld      (ts_rows), de
        push    ix
        ld      de, (ts_pat)    ; the pattern cache: a slot of these
        ld      bc, (ts_pat + 2) ; patterns? (E, D, C, B: pat[0..3])
        ld      hl, #cache      ; (HL walks the slots: a mismatch at
2$:     ld      a, (hl)         ; byte i moves it 32 - i on)
        cp      a, e
        jr      nz, 31$
        inc     hl
        ld      a, (hl)
        cp      a, d
        jr      nz, 32$
        inc     hl
        ld      a, (hl)
        cp      a, c
        jr      nz, 33$
        inc     hl
        ld      a, (hl)
        cp      a, b
        jr      z, 4$           ; found: HL = the slot + 3
        ld      a, #29
        jr      35$
33$:    ld      a, #30
        jr      35$
32$:    ld      a, #31
        jr      35$
31$:    ld      a, #32
35$:    add     a, l
        ld      l, a
        adc     a, h
        sub     a, l
        ld      h, a
        ld      a, l            ; past the last slot? (no slot's low
        cp      a, #<(cache + 32 * NSLOT) ; byte is the end's: 32 i
        jr      nz, 2$          ; < 256)
        ld      a, (cvic)       ; none: rebuild the slot cvic (the
        and     a, #(NSLOT - 1) * 32 ; slots in turn)
        ld      l, a
        add     a, #32
        ld      (cvic), a
        ld      h, #0
        ld      de, #cache + 4
        add     hl, de
        ld      (pr12), hl
        ld      de, #12
        add     hl, de
        ld      (pq16), hl
        jp      newpat
4$:     inc     hl              ; found: its r12 and q16
        ld      (pr12), hl
        ld      de, #12
        add     hl, de
        ld      (pq16), hl
        jp      next

newpat: ld      hl, (pr12)      ; the slot: patterns, r12, q16
        ld      de, #-4
        add     hl, de
        ex      de, hl
        ld      hl, #ts_pat
        ld      bc, #4
        ldir
        ld      hl, #ts_pat     ; r12 (DE)
        ld      b, #4
1$:     ld      a, (hl)
        and     a, #0x0F
        ld      c, a
        add     a, a
        add     a, a
        add     a, a
        add     a, a
        or      a, c
        ld      (de), a
        inc     hl
        inc     de
        djnz    1$
        ld      hl, (pr12)
        ld      c, #8
        ldir
        ld      ix, (pr12)      ; q16[0..3]: bit i = bit 3 - ph of
        ld      b, #8           ; pat[i & 3] (r12[7] down to r12[0])
3$:     ld      c, 7 (ix)
        dec     ix
        rr      c
        rl      l               ; phase 3
        rr      c
        rl      h               ; phase 2
        rr      c
        rl      e               ; phase 1
        rr      c
        rl      d               ; phase 0
        djnz    3$
        ld      iy, (pq16)      ; q16[4 j + ph]: q16[ph] rotated right j
        ld      b, #4
4$:     ld      0 (iy), d
        ld      1 (iy), e
        ld      2 (iy), h
        ld      3 (iy), l
        rrc     d
        rrc     e
        rrc     h
        rrc     l
        inc     iy
        inc     iy
        inc     iy
        inc     iy
        djnz    4$
        jp      next

row:    ; ---- the span: xl = max(l.val, 0), xr = min(r.val, w)
        ld      de, (tl)
        bit     7, d
        jr      z, 1$
        ld      de, #0
1$:     ld      hl, (tr)
        bit     7, h
        jp      nz, step        ; xr < 0 <= xl: empty
        ld      bc, (ts_w)
        or      a, a
        sbc     hl, bc
        jr      c, 2$
        ld      h, b            ; xr >= w: w
        ld      l, c
        jr      3$
2$:     add     hl, bc
3$:     or      a, a            ; both >= 0 here
        sbc     hl, de          ; n = xr - xl
        jp      c, step
        jp      z, step
        ld      b, h
        ld      c, l            ; BC = n
        ld      hl, (ts_page)
        add     hl, de          ; HL = page + xl
        push    de              ; xl (its phase)
        ex      de, hl          ; DE = the first byte
        ld      a, (ts_k)
        ld      hl, #ts_pat
        add     a, l
        ld      l, a
        adc     a, h
        sub     a, l
        ld      h, a
        ld      a, (hl)         ; pat[k]
        ex      de, hl          ; HL = the first byte
        pop     de              ; E: xl's low byte
        jp      fdith           ; (0xFF and 0x00 too: their nibbles)

        ;; ---- step both DDAs, then m, page and k.  err += r; when the
        ;; 16-bit sum is >= den: err -= den and val += q + 1, else val +=
        ;; q.  After `sbc hl, de` a borrow (no step) is undone by `add hl,
        ;; de`, which then always carries (err + r - den wrapped below 0):
        ;; so the carry is 1 exactly when val gets q alone, and `ccf; adc`
        ;; adds q plus the step.
step:   ld      hl, (tl + 4)    ; l: err += r
        ld      de, (tl + 6)
        add     hl, de
        ld      de, (tl + 8)
        or      a, a
        sbc     hl, de          ; >= den (the 16-bit sum, as the C)?
        jr      nc, 1$
        add     hl, de          ; below: back, carry set
1$:     ld      (tl + 4), hl
        ld      hl, (tl)
        ld      de, (tl + 2)
        ccf
        adc     hl, de
        ld      (tl), hl
        ld      hl, (tr + 4)    ; r: the same
        ld      de, (tr + 6)
        add     hl, de
        ld      de, (tr + 8)
        or      a, a
        sbc     hl, de
        jr      nc, 3$
        add     hl, de
3$:     ld      (tr + 4), hl
        ld      hl, (tr)
        ld      de, (tr + 2)
        ccf
        adc     hl, de
        ld      (tr), hl
4$:     ld      a, (ts_k)
        inc     a
        and     a, #3
        ld      (ts_k), a
        ld      a, (ts_m)
        add     a, a
        jr      nz, 5$
        ld      hl, (ts_page)   ; past the page's last row: the next page
        ld      de, (ts_w)
        add     hl, de
        ld      (ts_page), hl
        inc     a
5$:     ld      (ts_m), a
        ld      hl, (ts_pl)     ; l->val, l->err
        ld      de, (tl)
        ld      (hl), e
        inc     hl
        ld      (hl), d
        inc     hl
        inc     hl
        inc     hl
        ld      de, (tl + 4)
        ld      (hl), e
        inc     hl
        ld      (hl), d
        ld      hl, (ts_pr)     ; r->val, r->err
        ld      de, (tr)
        ld      (hl), e
        inc     hl
        ld      (hl), d
        inc     hl
        inc     hl
        inc     hl
        ld      de, (tr + 4)
        ld      (hl), e
        inc     hl
        ld      (hl), d
next:   ld      hl, (ts_rows)
        ld      a, h
        or      a, l
        jr      z, done
        ld      a, (ts_w + 1)   ; a group of rows needs w <= 255 and m
        or      a, a            ; one bit
        jr      nz, single
        ld      a, (ts_m)
        or      a, a
        jr      z, single
        ld      b, a
        dec     a
        and     a, b
        jr      nz, single
        ld      a, b            ; C = the rows to the page's end: 8 -
        ld      c, #8           ; log2 m (m one bit), by halves
        cp      a, #0x10
        jr      c, 1$
        rrca
        rrca
        rrca
        rrca
        ld      c, #4
1$:     cp      a, #4
        jr      c, 3$
        rrca
        rrca
        dec     c
        dec     c
3$:     cp      a, #2
        jr      c, 4$
        dec     c
4$:     ld      a, c
        ld      (gC), a
        ld      a, h            ; g = min(C, rows)
        or      a, a
        jr      nz, 2$
        ld      a, l
        cp      a, c
        jr      nc, 2$
        ld      c, a
2$:     ld      a, c
        cp      a, #2
        jr      c, single
        ld      e, c
        ld      d, #0
        or      a, a
        sbc     hl, de
        ld      (ts_rows), hl
        jp      grp
single: dec     hl              ; one row: *l, *r copied in and out
        ld      (ts_rows), hl
        ld      hl, (ts_pl)
        ld      de, #tl
        ld      bc, #10
        ldir
        ld      hl, (ts_pr)
        ld      de, #tr
        ld      c, #10
        ldir
        jp      row

done:   pop     ix
        ld      de, (ts_pt)     ; t->page, t->m, t->k
        ld      hl, #ts
        ldi
        ldi
        ldi
        ldi
        ret

        ;; ---- a dither: column x gets m where bit 3 - (x & 3) of the
        ;; pattern's low nibble is set, ~m elsewhere.  A = pat, BC = n,
        ;; HL = the first byte, E = xl's low byte.  The four column values
        ;; go to E, IXH, IXL, D (phases 0..3).  With ph = xl & 3, the span
        ;; passes phase 3 G = (ph + n) / 4 times: the unchecked loop g0..g3
        ;; is entered at phase ph and runs G times (B, then IYL passes of
        ;; 256), then the T = (ph + n) & 3 columns left (IYH) go through
        ;; d0.., which counts each column in B; a span that never reaches
        ;; phase 3 (G = 0, n < 4) goes there too, entered at ph.
fdith:  ld      d, a            ; D = pat
        ld      a, e
        and     a, #3
        ld      (ts_ph), a
        push    bc              ; n
        ld      a, (ts_m)
        ld      c, a            ; C = m
        cpl
        ld      (ts_nm), a
        ld      b, d            ; the nibble's bits from bit 0 (phase 3)
        srl     b
        sbc     a, a
        and     a, c
        ld      d, a            ; phase 3
        srl     b
        sbc     a, a
        and     a, c
        LD_IXL_A                ; phase 2
        srl     b
        sbc     a, a
        and     a, c
        LD_IXH_A                ; phase 1
        srl     b
        sbc     a, a
        and     a, c
        ld      e, a            ; phase 0
        pop     bc
        call    dspan
        jp      step

;; dspan: columns [x, x + n) of one page byte row: HL = the first byte,
;; BC = n >= 1, (ts_ph) = x & 3, (ts_nm) = ~mask, the four column values
;; (phases 0..3) in E, IXH, IXL, D.  Each byte = (byte & ~mask) | value.
;; With ph = (ts_ph), the span passes phase 3 G = (ph + n) / 4 times: the
;; unchecked loop g0..g3 is entered at phase ph and runs G times (B,
;; then IYL passes of 256), then the T = (ph + n) & 3 columns left (IYH)
;; go through d0.., which counts each column in B; a span that never
;; reaches phase 3 (G = 0, n < 4) goes there too, entered at ph.
;; Clobbers A, BC, HL, IY.
dspan:  push    hl              ; the first byte
        ld      a, (ts_ph)
        ld      l, a
        ld      h, #0
        add     hl, bc          ; ph + n
        ld      a, l
        and     a, #3
        LD_IYH_A                ; T
        srl     h
        rr      l
        srl     h
        rr      l               ; HL = G
        ld      a, h
        or      a, l
        jr      nz, 1$
        ld      a, c            ; G = 0: the count is n; carry set
        scf
        jr      2$
1$:     ld      a, l            ; B = G's low byte (0 = 256), IYL the
        or      a, a            ; passes of djnz
        ld      a, h
        jr      z, 3$
        inc     a
3$:     LD_IYL_A
        ld      a, l
        or      a, a            ; carry clear
2$:     pop     hl
        ld      b, a
        ld      a, (ts_nm)
        ld      c, a            ; C = ~mask
        ld      a, (ts_ph)
        jr      c, dsh
        or      a, a            ; G >= 1: enter the loop at ph
        jr      z, g0
        dec     a
        jr      z, g1
        dec     a
        jr      z, g2
        jr      g3
g0:     ld      a, (hl)
        and     a, c
        or      a, e
        ld      (hl), a
        inc     hl
g1:     ld      a, (hl)
        and     a, c
        OR_IXH
        ld      (hl), a
        inc     hl
g2:     ld      a, (hl)
        and     a, c
        OR_IXL
        ld      (hl), a
        inc     hl
g3:     ld      a, (hl)
        and     a, c
        or      a, d
        ld      (hl), a
        inc     hl
        djnz    g0
        DEC_IYL
        jr      nz, g0
        LD_A_IYH                ; T columns left, from phase 0
        or      a, a
        ret     z
        ld      b, a
        jr      d0
dsh:    or      a, a            ; G = 0: n columns from ph (ph + n <= 3)
        jr      z, d0
        dec     a
        jr      z, d1
        jr      d2
d0:     ld      a, (hl)         ; (never past phase 2 here)
        and     a, c
        or      a, e
        ld      (hl), a
        inc     hl
        dec     b
        ret     z
d1:     ld      a, (hl)
        and     a, c
        OR_IXH
        ld      (hl), a
        inc     hl
        dec     b
        ret     z
d2:     ld      a, (hl)
        and     a, c
        OR_IXL
        ld      (hl), a
        ret

        ;; ---- a group: g = (gg) rows (2..8) in one page, m one bit, w
        ;; <= 255 (ts_rows already less g).  Both DDAs give each row's
        ;; clamped columns (ga, gb); the columns every row covers, [gA,
        ;; gB), are filled once a byte under the group's bits; each row's
        ;; columns left and right of them one by one.  Then k, m and the
        ;; page move on g rows.
grp:    ld      (gg), a
        ld      b, a
        xor     a, a
        ld      (gslow), a
        ld      a, b            ; IX = ga - 8 + g (dda's rows at
        add     a, #<(ga - 8)   ; 8 - g .. 7)
        ld      l, a
        adc     a, #>(ga - 8)
        sub     a, l
        ld      h, a
        push    hl
        pop     ix
        ld      iy, (ts_pl)
        call    dda             ; (B, IX kept)
        ld      de, #8          ; gb = ga + 8
        add     ix, de
        ld      iy, (ts_pr)
        call    dda
        ld      a, (gC)         ; m after the group: p2[s + g], s =
        ld      b, a            ; 8 - gC (m = 1 << s; 0 past the
        ld      a, (gg)         ; page's last row)
        add     a, #8
        sub     a, b
        ld      e, a
        ld      d, #0
        ld      hl, #p2
        add     hl, de
        ld      a, (hl)
        ld      (gM), a
        ld      a, (gslow)      ; both DDAs monotone and unwrapped
        or      a, a            ; (dda's fast path): their clamped
        jr      nz, 8$          ; columns too, so the max of ga and
        ld      a, (gg)         ; the min of gb are at the first or
        dec     a               ; the last row
        ld      e, a
        ld      d, #0
        ld      hl, #ga
        ld      a, (hl)
        add     hl, de
        cp      a, (hl)
        jr      nc, 9$
        ld      a, (hl)
9$:     ld      (gA), a
        ld      hl, #gb
        ld      a, (hl)
        add     hl, de
        cp      a, (hl)
        jr      c, 10$
        ld      a, (hl)
10$:    ld      (gB), a
        jr      11$
8$:     ld      a, (gg)         ; gA = max ga
        ld      b, a
        ld      hl, #ga
        xor     a, a
1$:     cp      a, (hl)
        jr      nc, 2$
        ld      a, (hl)
2$:     inc     hl
        djnz    1$
        ld      (gA), a
        ld      a, (gg)         ; gB = min gb
        ld      b, a
        ld      hl, #gb
        ld      a, #255
3$:     cp      a, (hl)
        jr      c, 4$
        ld      a, (hl)
4$:     inc     hl
        djnz    3$
        ld      (gB), a
11$:    ld      hl, #gA
        cp      a, (hl)         ; gB - gA
        jr      c, 5$
        jr      nz, 6$
5$:     ld      a, #255         ; no column common to all rows
        ld      (gA), a
        ld      (gB), a
        jp      grag
6$:     ;; the column values: q16[4 j + ph] & G, G the group's bits
        ;; (m << g) - m, j = (k - s) & 3 = (k + gC) & 3 for m = 1 << s
        ;; (E, IXH, IXL, D: phases 0..3, as dspan takes them)
        ld      a, (ts_m)
        ld      c, a
        ld      a, (gM)
        sub     a, c
        ld      c, a            ; C = G
        cpl
        ld      (ts_nm), a
        ld      a, (gC)
        ld      hl, #ts_k
        add     a, (hl)
        and     a, #3
        add     a, a
        add     a, a
        ld      hl, (pq16)
        add     a, l
        ld      l, a
        adc     a, h
        sub     a, l
        ld      h, a
        ld      a, (hl)
        and     a, c
        ld      e, a
        inc     hl
        ld      a, (hl)
        and     a, c
        LD_IXH_A
        inc     hl
        ld      a, (hl)
        and     a, c
        LD_IXL_A
        inc     hl
        ld      a, (hl)
        and     a, c
        ld      d, a
        ld      a, (gA)
        ld      c, a
        and     a, #3
        ld      (ts_ph), a
        ld      b, #0
        ld      hl, (ts_page)
        add     hl, bc          ; HL = page + gA
        ld      a, (gB)
        sub     a, c
        ld      c, a            ; BC = gB - gA >= 1
        call    dspan
grag:   ;; each row: [ga, min(gb, gA)) and [max(ga, gB), gb); IY = its
        ;; r12 entry, C' its bit, B' the rows left
        ld      a, (ts_k)
        ld      hl, (pr12)
        add     a, l
        ld      l, a
        adc     a, h
        sub     a, l
        ld      h, a
        push    hl
        pop     iy
        ld      a, (ts_m)
        ld      c, a
        ld      a, (gg)
        ld      b, a
        exx                     ; to C' and B'
        ld      a, (gA)
        cp      a, #255
        jr      nz, gfast
        ld      ix, #ga
1$:     ld      a, (gA)         ; left: [ga, min(gb, gA))
        ld      b, 8 (ix)
        cp      a, b
        jr      c, 2$
        ld      a, b
2$:     sub     a, 0 (ix)
        jr      z, 3$
        jr      c, 3$
        ex      af, af'         ; n
        ld      a, 0 (ix)
        call    ragf
3$:     ld      a, (gB)         ; right: [max(ga, gB), gb)
        cp      a, 0 (ix)
        jr      nc, 4$
        ld      a, 0 (ix)
4$:     ld      e, a
        ld      a, 8 (ix)
        sub     a, e
        jr      z, 5$
        jr      c, 5$
        ex      af, af'         ; n
        ld      a, e
        call    ragf
5$:     inc     ix
        inc     iy
        exx
        sla     c
        dec     b
        exx
        jr      nz, 1$
gend:   ld      a, (gg)         ; k, m and the page: g rows on
        ld      b, a
        ld      a, (ts_k)
        add     a, b
        and     a, #3
        ld      (ts_k), a
        ld      a, (gM)
        or      a, a
        jr      nz, 7$
        ld      hl, (ts_page)   ; the page's last row done: the next page
        ld      de, (ts_w)
        add     hl, de
        ld      (ts_page), hl
        inc     a
7$:     ld      (ts_m), a
        jp      next

;; gfast: grag when the rows have columns in common (gA < gB): then
;; min(gb, gA) = gA and max(ga, gB) = gB, so each row's left part is
;; [ga, gA) and its right part [gB, gb).  A = gA here; IY, C', B' as
;; grag sets them.
gfast:  ld      b, a            ; B = gA
        ld      a, (gB)
        ld      c, a            ; C = gB
        ld      hl, #ga
        ld      de, #gb
1$:     ld      a, b            ; left: gA - ga columns from ga
        sub     a, (hl)
        jr      nz, 5$
2$:     ld      a, (de)         ; right: gb - gB columns from gB
        sub     a, c
        jr      nz, 6$
3$:     inc     hl
        inc     de
        inc     iy
        exx
        sla     c
        dec     b
        exx
        jr      nz, 1$
        jp      gend
5$:     ex      af, af'         ; n
        ld      a, (hl)         ; x = ga
        call    ragf
        jr      2$
6$:     ex      af, af'         ; n
        ld      a, c            ; x = gB
        call    ragf
        jr      3$

;; ragf: columns [x, x + n) of one row, one by one: A = x, A' = n >= 1,
;; C' = the row's bit, (IY) = its pattern nibble twice (bit 7: phase 0).
;; Each byte = (byte & ~bit) | (bit if bit 3 - (x & 3) of the nibble).
;; Works in the alternate set (HL', DE'; B', C' kept) and keeps the main
;; one, so gfast's loop keeps its registers across it (round 11: was
;; push / pop of three pairs a call).  Clobbers AF, AF', HL', DE'.
ragf:   exx
        ld      e, a
        ld      hl, (ts_page)
        add     a, l
        ld      l, a
        adc     a, h
        sub     a, l
        ld      h, a            ; HL' = page + x
        ld      a, e
        ld      e, 0 (iy)
        and     a, #3
        jr      z, 2$
1$:     rlc     e               ; bit 7: phase x & 3
        dec     a
        jr      nz, 1$
2$:     ex      af, af'
        ld      d, a            ; D' = n
3$:     rlc     e
        sbc     a, a
        xor     a, (hl)
        and     a, c
        xor     a, (hl)
        ld      (hl), a
        inc     hl
        dec     d
        jr      nz, 3$
        exx
        ret

;; dda: B = g (1..8) rows of the column DDA at IY (val +0, q +2, err +4,
;; r +6, den +8): row i's clamp(val, 0, w) to (IX + 8 - g + i), then the
;; step (as `step`); *IY left after the g rows.  Uses the alternate
;; registers for err, r, den; B, IX kept.
;; Fast path (round 11): with den < 0x8000 (so err + r < 2 den never
;; wraps 16 bits; err, r < den as R8_INTERP_STEP keeps them), q in
;; [-256, 255] and the first row's val in [0, w], the rows go unclamped
;; with err biased by -den (err - den + r carries exactly when err + r >=
;; den; then - den borrows: the carry is the step either way, and `adc`
;; adds it to val), unrolled (c0..c7, 12 bytes a row: entered at row 8 -
;; g through the stack).  val does not wrap and the DDA is monotone, so
;; when val after the g rows is in [0, w] too, every row's was and none
;; needed the clamp.  Else the slow loop (ddas, gslow set) redoes the
;; rows from *IY (not written until the end).  65 T a row without the
;; step, 75 with it (was ~146).
dda:    ld      a, #8           ; the entry: c0 + 12 (8 - g)
        sub     a, b
        add     a, a
        add     a, a
        ld      e, a
        add     a, a
        add     a, e
        add     a, #<c0
        ld      l, a
        adc     a, #>c0
        sub     a, l
        ld      h, a
        push    hl
        ld      a, (ts_w)
        ld      c, a            ; C = w (<= 255)
        ld      d, 3 (iy)       ; q in [-256, 255] (no val wraps 16
        ld      a, d            ; bits on g <= 8 rows)
        inc     a
        cp      a, #2
        jr      nc, ddax
        ld      l, 0 (iy)
        ld      h, 1 (iy)       ; HL = val
        ld      a, h            ; the first row in [0, w]?
        or      a, a
        jr      nz, ddax
        ld      a, c
        cp      a, l
        jr      c, ddax
        ld      e, 2 (iy)       ; DE = q
        ld      a, 9 (iy)
        exx
        ld      b, a
        add     a, a            ; den >= 0x8000: err + r may wrap
        jr      c, ddaxx
        ld      c, 8 (iy)
        ld      l, 4 (iy)
        ld      h, 5 (iy)       ; HL' = err - den (carry clear here)
        sbc     hl, bc
        dec     bc              ; BC' = den - 1 (sbc with the carry)
        ld      e, 6 (iy)
        ld      d, 7 (iy)       ; DE' = r
        exx
        ret                     ; to row 8 - g
ddaxx:  exx
ddax:   pop     hl
        jr      ddas
c0:     ld      0 (ix), l      ; row 0
        exx
        add     hl, de          ; err - den + r: carry when err + r >= den
        jr      nc, 10$
        sbc     hl, bc          ; - den (the carry: + 1), carry set again
10$:    exx
        adc     hl, de          ; val += q + the step
         ld      1 (ix), l      ; row 1
        exx
        add     hl, de          ; err - den + r: carry when err + r >= den
        jr      nc, 11$
        sbc     hl, bc          ; - den (the carry: + 1), carry set again
11$:    exx
        adc     hl, de          ; val += q + the step
         ld      2 (ix), l      ; row 2
        exx
        add     hl, de          ; err - den + r: carry when err + r >= den
        jr      nc, 12$
        sbc     hl, bc          ; - den (the carry: + 1), carry set again
12$:    exx
        adc     hl, de          ; val += q + the step
         ld      3 (ix), l      ; row 3
        exx
        add     hl, de          ; err - den + r: carry when err + r >= den
        jr      nc, 13$
        sbc     hl, bc          ; - den (the carry: + 1), carry set again
13$:    exx
        adc     hl, de          ; val += q + the step
         ld      4 (ix), l      ; row 4
        exx
        add     hl, de          ; err - den + r: carry when err + r >= den
        jr      nc, 14$
        sbc     hl, bc          ; - den (the carry: + 1), carry set again
14$:    exx
        adc     hl, de          ; val += q + the step
         ld      5 (ix), l      ; row 5
        exx
        add     hl, de          ; err - den + r: carry when err + r >= den
        jr      nc, 15$
        sbc     hl, bc          ; - den (the carry: + 1), carry set again
15$:    exx
        adc     hl, de          ; val += q + the step
         ld      6 (ix), l      ; row 6
        exx
        add     hl, de          ; err - den + r: carry when err + r >= den
        jr      nc, 16$
        sbc     hl, bc          ; - den (the carry: + 1), carry set again
16$:    exx
        adc     hl, de          ; val += q + the step
         ld      7 (ix), l      ; row 7
        exx
        add     hl, de          ; err - den + r: carry when err + r >= den
        jr      nc, 17$
        sbc     hl, bc          ; - den (the carry: + 1), carry set again
17$:    exx
        adc     hl, de          ; val += q + the step
        ld      a, h            ; val after the rows in [0, w]?
        or      a, a
        jr      nz, ddas
        ld      a, c
        cp      a, l
        jr      c, ddas
        ld      0 (iy), l
        ld      1 (iy), h
        exx
        inc     bc              ; err = biased + den
        add     hl, bc
        ld      4 (iy), l
        ld      5 (iy), h
        exx
        ret
ddas:   ld      a, #1           ; the slow loop from the start
        ld      (gslow), a
        ld      l, 0 (iy)
        ld      h, 1 (iy)       ; HL = val
        push    ix
        ld      a, #8           ; IX = the first row's byte
        sub     a, b
        ld      e, a
        ld      d, #0
        add     ix, de
        push    bc
        ld      e, 2 (iy)
        ld      d, 3 (iy)       ; DE = q
        exx
        ld      l, 4 (iy)
        ld      h, 5 (iy)       ; HL' = err
        ld      e, 6 (iy)
        ld      d, 7 (iy)       ; DE' = r
        ld      c, 8 (iy)
        ld      b, 9 (iy)       ; BC' = den
        exx
1$:     ld      a, h
        or      a, a
        jr      nz, 3$
        ld      a, l
        cp      a, c
        jr      c, 4$
2$:     ld      a, c            ; >= w: w
        jr      4$
3$:     bit     7, h
        jr      z, 2$
        xor     a, a            ; < 0: 0
4$:     ld      0 (ix), a
        inc     ix
        add     hl, de          ; val += q
        exx
        add     hl, de          ; err += r (16 bits)
        or      a, a
        sbc     hl, bc          ; >= den?
        jr      nc, 5$
        add     hl, bc
        exx
        djnz    1$
        jr      6$
5$:     exx
        inc     hl              ; val + 1
        djnz    1$
6$:     ld      0 (iy), l
        ld      1 (iy), h
        exx
        ld      4 (iy), l
        ld      5 (iy), h
        exx
        pop     bc
        pop     ix
        ret
