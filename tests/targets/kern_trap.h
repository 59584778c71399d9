/* kern_trap.h - the random r8k_trap cases both port kernel tests run
 * (tests/targets/test_avr_kern.c, test_z80_kern.c): a kernel and its C
 * reference (r8k_trap_ref) fill copies of the same bytes from the same
 * random state; the windows must end equal, guard bytes included, and so
 * must the state left in t, l and r.  The including file defines rnd(),
 * rndn(), rnds() and print_case() and includes <string.h> and r8kern.h
 * first. */
#ifndef KERN_TRAP_H
#define KERN_TRAP_H

#define GUARD 16
#define MAXW 1024
#define WIN (GUARD + 255 + 4 * MAXW + GUARD)
static r8_u8 band_ref[WIN], band_asm[WIN];
static unsigned long n_rows;

static void rnd_interp(r8_interp *it, r8_s16 w)
{
    unsigned c = rndn(10);
    r8_u16 den;
    if (c < 4)
        den = (r8_u16)(1u + rndn(64));
    else if (c < 7)
        den = (r8_u16)(1u + rndn(4096));
    else if (c < 9)
        den = (r8_u16)(rnd() | 1u);
    else
        den = (r8_u16)(0x8000u | (r8_u16)rnd());    /* err + r can wrap */
    it->den = den;
    it->err = (r8_u16)((r8_u16)rnd() % den);
    it->r = (r8_u16)((r8_u16)rnd() % den);
    c = rndn(10);
    if (c < 5)
        it->val = rnds(-40, (r8_s16)(w + 40));
    else if (c < 8)
        it->val = rnds(-2100, 2100);
    else
        it->val = (r8_s16)rnd();
    c = rndn(10);
    if (c < 5)
        it->q = rnds(-8, 8);
    else if (c < 8)
        it->q = rnds(-2048, 2047);
    else
        it->q = (r8_s16)rnd();
}

/* one case: returns 0 if the two agree */
static int trap_case(r8_s16 w, r8_u16 rows, unsigned pages, int full)
{
    r8_trapfill ta, tr;
    r8_interp la, lr_, ra, rr_;
    unsigned off = rndn(256), len = GUARD + pages * (unsigned)w + GUARD, i, k;
    r8_u8 *wa = band_asm + off, *wr = band_ref + off, b = (r8_u8)rnd();
    {   /* cheap bytes (an odd step: every value), a new start per case */
        r8_u8 *q = wa, *e = wa + len;
        while (q != e) {
            b = (r8_u8)(b + 151u);
            *q++ = b;
        }
    }
    memcpy(wr, wa, len);
    ta.page = wa + GUARD;
    k = rndn(8);
    if (k < 6)
        ta.m = (r8_u8)(1u << rndn(8));
    else
        ta.m = (r8_u8)rnd();
    ta.k = (r8_u8)rndn(4);
    for (i = 0; i < 4; i++) {
        k = rndn(10);
        if (k < 3)
            ta.pat[i] = 0xFF;
        else if (k < 5)
            ta.pat[i] = 0x00;
        else if (k < 6)
            ta.pat[i] = (r8_u8)(rndn(2) ? 0x0F : 0xF0);
        else
            ta.pat[i] = (r8_u8)rnd();
    }
    ta.w = w;
    rnd_interp(&la, w);
    rnd_interp(&ra, w);
    if (rndn(3) == 0) {           /* often a real trapezoid: r right of l */
        ra.val = (r8_s16)(la.val + rnds(-4, (r8_s16)(w + 4)));
    }
#ifdef TRAP_BIAS
    TRAP_BIAS(&ta, &la, &ra);   /* the including test's biased inputs */
#endif
    tr = ta;
    tr.page = wr + GUARD;
    lr_ = la;
    rr_ = ra;
#ifdef TRAP_CLASSES
    TRAP_CLASSES(&ta, &la, &ra, rows);  /* the including test's counters */
#endif
    r8k_trap_ref(&tr, &lr_, &rr_, rows);
    r8k_trap(&ta, &la, &ra, rows);
    n_rows += rows;
    if (memcmp(wa - off, wr - off, full ? (unsigned)WIN : off + len) != 0)
        return 1;
    if ((unsigned)(ta.page - wa) != (unsigned)(tr.page - wr))
        return 2;
    if (ta.m != tr.m || ta.k != tr.k || memcmp(ta.pat, tr.pat, 4) != 0 || ta.w != tr.w)
        return 3;
    if (memcmp(&la, &lr_, sizeof la) != 0)
        return 4;
    if (memcmp(&ra, &rr_, sizeof ra) != 0)
        return 5;
    return 0;
}

static void test_trap_random(void)
{
    unsigned long i;
    int bad;
    for (i = 0; i < TRAP_CASES; i++) {
        unsigned c = rndn(10);
        r8_s16 w;
        if (c < 6)
            w = (r8_s16)(1 + rndn(160));
        else if (c < 8)
            w = (r8_s16)(1 + rndn(8));
        else
            w = (r8_s16)(1 + rndn(MAXW));
        c = rndn(8);                  /* rows 0..20, 1 (its own path) often */
        bad = trap_case(w, (r8_u16)(c < 2 ? 1u : rndn(21)), 4, (i & 63) == 0);
        if (bad) {
            print_case("r8k_trap", i);
            unity_fail_int(__LINE__, "r8k_trap differs from the reference (1 band, 2 page, 3 t, 4 l, 5 r)", 0, bad);
        }
    }
    unity_print("r8k_trap: ");
    unity_print_long((long)i);
    unity_print(" cases, ");
    unity_print_long((long)n_rows);
    unity_print(" rows\n");
}

/* long runs: the 256-row blocks, a narrow band of many pages */
static void test_trap_many_rows(void)
{
    unsigned long i;
    int bad;
    for (i = 0; i < 60; i++) {
        r8_s16 w = (r8_s16)(1 + rndn(12));
        r8_u16 rows = (r8_u16)(rndn(3) == 0 ? 256u + rndn(8) - 4u : 1u + rndn(600));
        bad = trap_case(w, rows, (rows + 15u) / 8u + 1u, 0);
        if (bad) {
            print_case("r8k_trap many rows", i);
            unity_fail_int(__LINE__, "r8k_trap differs from the reference", 0, bad);
        }
    }
}

#endif
