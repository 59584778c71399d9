/* test_avr_kern.c - the AVR assembly kernels (ports/avr/trap.S,
 * xform.S, edge.S, project.S) against their C references (src/kern.c,
 * compiled into this program under other names), on thousands of random
 * inputs, inside the simulator (ATmega1284P: mk/targets.mk, step
 * xkern-avr1284).
 *
 * Every case runs both versions on identical copies of the inputs and
 * compares every output byte: for r8k_trap the whole band window (up to
 * 4 pages of w columns, at a random offset, between guard bytes) and all
 * of t, l and r; for r8k_xform all of out (and m, t untouched).  v is
 * read from flash: windows over two tables below (small values for the
 * 16x8 path and its edges, extremes for the 16x16 one) and over the
 * program's own code (arbitrary words).  For r8k_edge the return value
 * and all of *it (left as it was on R8_EDGE_WIDE); for r8k_project the
 * return value, out[0..2] (left as they were on 1; out[2] always), *m,
 * *e, and c, p untouched.  For r8k_fill the window around p (guard
 * bytes included), over lengths 0..700 that hit every remainder mod 64.
 * Inputs come from classes aimed at each path
 * and limit of the reference; the test counts how often each was hit
 * and fails when one was too rare to mean anything. */
#include <string.h>
#include "unity.h"
#include "r8kern.h"
#include "r8flash.h"

/* the C references, renamed */
void r8k_trap_ref(r8_trapfill *t, r8_interp *l, r8_interp *r, r8_u16 rows);
void r8k_xform_ref(const r8_mat3 *m, const r8_vec3l *t, const r8_s16 *v, r8_vec3l *out);
r8_s16 r8k_edge_ref(r8_interp *it, const r8_s16 *a, const r8_s16 *b);
int r8k_project_ref(const r8_proj *p, const r8_vec3l *c, r8_s16 *out, r8_u16 *m, r8_s8 *e);
void r8k_fill_ref(r8_u8 *p, r8_u8 v, unsigned n);
#define r8k_trap r8k_trap_ref
#define r8k_fill r8k_fill_ref
#define r8k_xform r8k_xform_ref
#define r8k_edge r8k_edge_ref
#define r8k_project r8k_project_ref
#include "kern.c"
#undef r8k_trap
#undef r8k_xform
#undef r8k_edge
#undef r8k_project
#undef r8k_fill

#ifndef TRAP_CASES
#define TRAP_CASES 3000
#endif
#ifndef XFORM_CASES
#define XFORM_CASES 4000
#endif
#ifndef EDGE_CASES
#define EDGE_CASES 12000
#endif
#ifndef PROJ_CASES
#define PROJ_CASES 12000
#endif

static r8_u32 rng = 0x2545F491UL;
static r8_u32 rnd(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 17;
    rng ^= rng << 5;
    return rng;
}
static unsigned rndn(unsigned n) { return (unsigned)(rnd() % n); }
/* lo..hi (unsigned arithmetic: hi - lo may pass 32767) */
static r8_s16 rnds(r8_s16 lo, r8_s16 hi)
{
    return (r8_s16)((unsigned)lo + rndn((unsigned)hi - (unsigned)lo + 1u));
}

void setUp(void) {}
void tearDown(void) {}

static void print_case(const char *what, unsigned long i)
{
    unity_print(what);
    unity_print(" case ");
    unity_print_long((long)i);
    unity_print("\n");
}

/* ---- r8k_trap: tests/targets/kern_trap.h ---- */
#include "kern_trap.h"

/* ---- r8k_trap's page groups (trap.S: GMIN (7) or more rows of one
 * page byte, a one-bit m, |val| < 16384, -128 <= q <= 127, spans of 16+ columns get
 * one write per byte for the columns all rows cover): inputs aimed at
 * that path and at its limits (q = -128 / 127, val = +-16383 / 16384,
 * the interior just 16 columns or none, full and partial pages) ---- */
static r8_s16 rnd_edge_val(r8_s16 w)
{
    static const r8_s16 lim[6] = { -16385, -16384, -16383, 16382, 16383, 16384 };
    unsigned c = rndn(10);
    if (c < 6)
        return rnds(-20, (r8_s16)(w + 20));
    if (c < 8)
        return lim[rndn(6)];
    return rnds(-16400, 16400);
}

static r8_s16 rnd_edge_q(void)
{
    static const r8_s16 lim[6] = { -129, -128, -127, 126, 127, 128 };
    unsigned c = rndn(10);
    if (c < 6)
        return rnds(-6, 6);
    if (c < 8)
        return lim[rndn(6)];
    return rnds(-130, 130);
}

static void test_trap_groups(void)
{
    unsigned long i, sets = 0, clears = 0, diths = 0, full = 0;
    for (i = 0; i < 2500; i++) {
        r8_trapfill ta, tr;
        r8_interp la, lr_, ra, rr_;
        r8_s16 w = (r8_s16)(rndn(4) == 0 ? 1 + rndn(600) : 16 + rndn(145));
        r8_u16 rows = (r8_u16)(rndn(4) == 0 ? 1u + rndn(30) : 5u + rndn(4));
        unsigned pages = (rows + 15u) / 8u + 1u, off = rndn(256), len, k, bit = rndn(8);
        r8_u8 *wa = band_asm + off, *wr = band_ref + off, b = (r8_u8)rnd();
        if (rndn(3) != 0)
            bit = rndn(2);              /* 7 or 8 rows of the page byte */
        len = GUARD + pages * (unsigned)w + GUARD;
        for (k = 0; k < len; k++) {
            b = (r8_u8)(b + 151u);
            wa[k] = b;
        }
        memcpy(wr, wa, len);
        ta.page = wa + GUARD;
        ta.m = (r8_u8)(1u << bit);
        ta.k = (r8_u8)rndn(4);
        k = rndn(4);
        for (bit = 0; bit < 4; bit++) {
            if (k == 0)
                ta.pat[bit] = 0xFF;
            else if (k == 1)
                ta.pat[bit] = 0x00;
            else
                ta.pat[bit] = (r8_u8)rnd();
        }
        sets += k == 0;
        clears += k == 1;
        diths += k > 1;
        full += ta.m == 1 && rows >= 8;
        ta.w = w;
        rnd_interp(&la, w);
        rnd_interp(&ra, w);
        la.val = rnd_edge_val(w);
        la.q = rnd_edge_q();
        ra.q = rnd_edge_q();
        if (rndn(4) == 0)
            ra.val = rnd_edge_val(w);
        else                            /* 10..40 columns right of l */
            ra.val = (r8_s16)(la.val + rnds(10, 40));
        k = rndn(8);                    /* edges with the same end on */
        if (k < 3) {                    /* every row of the group (or */
            la.q = (r8_s16)(rndn(2) ? 0 : -1);  /* all but one), one */
            la.r = (r8_u16)(la.q ? la.den - 1u - rndn(2) : rndn(2));
        }                               /* side or both */
        if (k == 0 || k == 3 || k == 4) {
            ra.q = (r8_s16)(rndn(2) ? 0 : -1);
            ra.r = (r8_u16)(ra.q ? ra.den - 1u - rndn(2) : rndn(2));
        }
        tr = ta;
        tr.page = wr + GUARD;
        lr_ = la;
        rr_ = ra;
        r8k_trap_ref(&tr, &lr_, &rr_, rows);
        r8k_trap(&ta, &la, &ra, rows);
        if (memcmp(wa - off, wr - off, off + len) != 0 || ta.page - wa != tr.page - wr ||
            ta.m != tr.m || ta.k != tr.k || memcmp(&la, &lr_, sizeof la) != 0 ||
            memcmp(&ra, &rr_, sizeof ra) != 0) {
            print_case("r8k_trap page groups", i);
            unity_fail_int(__LINE__, "r8k_trap differs from the reference", 0, 1);
        }
    }
    if (sets < 300 || clears < 300 || diths < 800 || full < 200)
        unity_fail_int(__LINE__, "r8k_trap page groups: a class too rare", 300, (long)full);
}

/* ---- r8k_xform inputs, r8k_edge, r8k_project: tests/targets/kern_cases.h ---- */
extern const char _etext[];   /* end of the program's code (avr-libc's linker script) */
#define KERN_CODE_PTR() ((const r8_s16 *)(rndn((unsigned)_etext - 6u)))
#include "kern_cases.h"

/* ---- r8k_fill: lengths 0..700 at random offsets in band_asm/band_ref
 * (kern_trap.h's windows), the bytes around them kept ---- */
static void test_fill_random(void)
{
    unsigned long i;
    unsigned rem[64];
    memset(rem, 0, sizeof rem);
    for (i = 0; i < 3000; i++) {
        unsigned c = rndn(4), n, off, j, len;
        r8_u8 b, v = (r8_u8)(rndn(3) == 0 ? 0 : rnd());
        if (c == 0)
            n = rndn(40);
        else if (c == 1)
            n = 16u * rndn(45) + rndn(2);
        else
            n = rndn(701);
        off = GUARD + rndn(256);
        len = off + n + GUARD;
        b = (r8_u8)rnd();
        for (j = 0; j < len; j++) {     /* an odd step: every value */
            b = (r8_u8)(b + 151u);
            band_ref[j] = b;
        }
        memcpy(band_asm, band_ref, len);
        r8k_fill_ref(band_ref + off, v, n);
        r8k_fill(band_asm + off, v, n);
        rem[n & 63]++;
        if (memcmp(band_asm, band_ref, len) != 0) {
            print_case("r8k_fill", i);
            unity_fail_int(__LINE__, "r8k_fill differs from the reference", (long)n, (long)off);
        }
    }
    for (i = 0; i < 64; i++)
        if (rem[i] < 10)
            unity_fail_int(__LINE__, "r8k_fill: a length remainder too rare", 10, (long)rem[i]);
}

/* ---- r8k_zrows (ports/avr/zfill.S) against its reference (src/zrows.c,
 * renamed r8k_zrows_ref): random bands of w <= 64 columns and up to 16
 * rows in band_ref / band_asm (pages at GUARD, depths at ZOFF, every
 * byte random, guards included), random edges (columns around the band,
 * now and then left of 0 or 256+ wide: the rows the kernel leaves),
 * depths anywhere in 0..32767.  All the memory, the return value, the
 * four interpolators and t's z, page, m, k must end equal. ---- */
#define R8_ZROWS_REF 1
#define r8k_zrows r8k_zrows_ref
#define r8_interp_init_sub r8_interp_init_sub_ref
#define r8_attr_first r8_attr_first_ref
#include "zrows.c"
#undef r8k_zrows
#undef r8_interp_init_sub
#undef r8_attr_first
int r8_attr_first(r8_interp *it, const r8_s16 *a, const r8_s16 *b, r8_s16 y, r8_u8 k);
r8_u16 r8k_zrows(r8_zrows *t, r8_u16 rows);
void r8_interp_init_sub(r8_interp *it, r8_s16 base, r8_u16 s0, r8_s16 dv, r8_u16 n);

static void rnd_zinterp(r8_interp *it, r8_s16 lo, r8_s16 hi, r8_s16 qmax, r8_u16 dmax)
{
    it->den = (r8_u16)(1u + rndn(dmax));
    it->val = rnds(lo, hi);
    it->q = rnds((r8_s16)-qmax, qmax);
    it->err = (r8_u16)rndn(it->den);
    it->r = (r8_u16)rndn(it->den);
}

static int interp_eq(const r8_interp *a, const r8_interp *b)
{
    return a->val == b->val && a->q == b->q && a->err == b->err && a->r == b->r &&
           a->den == b->den;
}

static r8_u16 zsum(const r8_u8 *p, unsigned n)
{
    r8_u16 h = 0;
    while (n--)
        h = (r8_u16)(((h << 1) | (h >> 15)) + *p++);
    return h;
}

static void test_zrows_random(void)
{
    unsigned long i, stops = 0, drawn = 0;
    r8_u16 sum0;
    for (i = 0; i < 1500; i++) {
        r8_zrows ta, tr;
        r8_interp ia[4], ir[4];
        r8_u16 w = (r8_u16)(1u + rndn(64)), rows = (r8_u16)(1u + rndn(16)), ra, rr;
        unsigned j, zoff = (2u * GUARD + 3u * w + 1u) & ~1u;
        unsigned len = zoff + 2u * rows * w + GUARD, c = rndn(8);
        r8_u32 v = 0;
        for (j = 0; j < len; j++) {
            if (!(j & 3))
                v = rnd();
            band_ref[j] = (r8_u8)v;
            v >>= 8;
        }
        if (rndn(2))                   /* depths near each other: both ways */
            for (j = zoff; j < len; j += 2)
                band_ref[j + 1] = (r8_u8)(0x40 + (band_ref[j] & 1));
        memcpy(band_asm, band_ref, len);
        if (c == 0) {                   /* wide spans: 256+ and the limits */
            rnd_zinterp(&ir[0], 0, 40, 3, 50);
            rnd_zinterp(&ir[1], 250, 330, 3, 50);
        } else if (c == 1) {            /* starts left of 0 now and then */
            rnd_zinterp(&ir[0], -6, 10, 2, 20);
            rnd_zinterp(&ir[1], -2, (r8_s16)(w + 8), 2, 20);
        } else {
            rnd_zinterp(&ir[0], -2, (r8_s16)(w + 2), 3, 400);
            rnd_zinterp(&ir[1], -2, (r8_s16)(w + 40), 3, 400);
        }
        if (rndn(4) == 0) {             /* extreme depth steps */
            rnd_zinterp(&ir[2], 0, 32767, 32767, 32767);
            rnd_zinterp(&ir[3], 0, 32767, 32767, 32767);
        } else {
            rnd_zinterp(&ir[2], 16000, 16900, 60, 300);
            rnd_zinterp(&ir[3], 16000, 16900, 60, 300);
        }
        memcpy(ia, ir, sizeof ia);
        tr.w = w;
        tr.m = (r8_u8)(1u << rndn(8));
        tr.k = (r8_u8)rndn(4);
        for (j = 0; j < 4; j++)
            tr.pat[j] = (r8_u8)rnd();
        ta = tr;
        tr.lx = &ir[0]; tr.rx = &ir[1]; tr.ld = &ir[2]; tr.rd = &ir[3];
        ta.lx = &ia[0]; ta.rx = &ia[1]; ta.ld = &ia[2]; ta.rd = &ia[3];
        tr.page = band_ref + GUARD;
        ta.page = band_asm + GUARD;
        tr.z = (r8_u16 *)(void *)(band_ref + zoff);
        ta.z = (r8_u16 *)(void *)(band_asm + zoff);
        sum0 = zsum(band_ref, len);
        rr = r8k_zrows_ref(&tr, rows);
        ra = r8k_zrows(&ta, rows);
        stops += rr != 0;
        drawn += zsum(band_ref, len) != sum0;   /* some depth or pixel written */
        if (ra != rr || memcmp(band_ref, band_asm, len) != 0 || !interp_eq(&ia[0], &ir[0]) ||
            !interp_eq(&ia[1], &ir[1]) || !interp_eq(&ia[2], &ir[2]) ||
            !interp_eq(&ia[3], &ir[3]) ||
            (r8_u8 *)ta.z - band_asm != (r8_u8 *)tr.z - band_ref ||
            ta.page - band_asm != tr.page - band_ref || ta.m != tr.m || ta.k != tr.k) {
            print_case("r8k_zrows", i);
            unity_fail_int(__LINE__, "r8k_zrows differs from the reference", (long)ra, (long)rr);
        }
    }
    unity_print("r8k_zrows: rows left to C in ");
    unity_print_long((long)stops);
    unity_print(" calls, memory written in ");
    unity_print_long((long)drawn);
    unity_print("\n");
    if (stops < 150 || drawn < 500)
        unity_fail_int(__LINE__, "r8k_zrows: too few stops or drawn rows", (long)stops, (long)drawn);
}

/* ---- r8_interp_init_sub (zfill.S) against its reference (src/zrows.c):
 * every s0 (0..15) and the limits of n (1, 2, 255, 256), dv (0, +-1,
 * +-4095) and base (-32768, 32767: val saturates), then random inputs
 * in the whole domain (8000); all five fields equal ---- */
static void check_init_sub(r8_s16 base, r8_u16 s0, r8_s16 dv, r8_u16 n, unsigned long i)
{
    r8_interp a, b;
    memset(&a, 0x5A, sizeof a);
    memset(&b, 0xA5, sizeof b);
    r8_interp_init_sub_ref(&b, base, s0, dv, n);
    r8_interp_init_sub(&a, base, s0, dv, n);
    if (!interp_eq(&a, &b)) {
        print_case("r8_interp_init_sub", i);
        unity_fail_int(__LINE__, "r8_interp_init_sub differs from the reference", (long)a.val, (long)b.val);
    }
}

static void test_init_sub_random(void)
{
    static const r8_u16 ns[] = { 1, 2, 3, 16, 255, 256 };
    static const r8_s16 dvs[] = { 0, 1, -1, 4095, -4095, 2048, -2048 };
    static const r8_s16 bases[] = { -32767 - 1, 32767, 0, 12345 };
    unsigned long i = 0;
    unsigned s0, a, b, c;
    for (s0 = 0; s0 < 16; s0++)
        for (a = 0; a < 6; a++)
            for (b = 0; b < 7; b++)
                for (c = 0; c < 4; c++)
                    check_init_sub(bases[c], (r8_u16)s0, dvs[b], ns[a], i++);
    for (i = 0; i < 8000; i++)
        check_init_sub((r8_s16)rnd(), (r8_u16)rndn(16), rnds(-4095, 4095),
                       (r8_u16)(1u + rndn(256)), i);
}

/* ---- r8_attr_first (zfill.S) against its reference (src/zrows.c):
 * edges placed around each of its limits (y 0 / 2047 / 2048 / < 0, s0
 * -1 / 0 / 15 / 16, n 1 / 256 / 257, by <= ay, dv +-4095 / +-4096 and
 * 16-bit overflow) and random, 8000; the return value and all of it (left as
 * it was on 0) equal; both outcomes counted ---- */
static void test_attr_first_random(void)
{
    unsigned long i, taken = 0;
    for (i = 0; i < 8000; i++) {
        r8_s16 a[4], b[4], y;
        r8_interp ia, ir;
        r8_u8 k = (r8_u8)(2 + rndn(2));
        int ra, rr;
        unsigned c = rndn(8);
        y = c == 0 ? rnds(-3, 3) : c == 1 ? rnds(2044, 2050) : c == 2 ? (r8_s16)rnd() : rnds(0, 200);
        a[0] = (r8_s16)rnd();
        b[0] = (r8_s16)rnd();
        a[1] = (r8_s16)((r8_u16)y * 16u + 8u - (r8_u16)rnds(-2, 17));      /* s0 around 0..15 */
        if (rndn(8) == 0)
            a[1] = (r8_s16)rnd();
        c = rndn(8);
        b[1] = (r8_s16)(a[1] + (c == 0 ? rnds(-300, 0) : c == 1 ? rnds(254, 258) : rnds(1, 300)));
        if (rndn(8) == 0)
            b[1] = (r8_s16)rnd();
        a[2] = rnds(0, 32767);
        a[3] = rnds(0, 4096);
        c = rndn(8);
        b[k] = (r8_s16)(a[k] + (c == 0 ? rnds(4094, 4097) : c == 1 ? rnds(-4097, -4094) : rnds(-5000, 5000)));
        if (rndn(8) == 0)
            b[k] = (r8_s16)rnd();
        b[5 - k] = (r8_s16)rnd();
        a[5 - k] = (r8_s16)rnd();
        memset(&ia, 0x5A, sizeof ia);
        memset(&ir, 0x5A, sizeof ir);
        rr = r8_attr_first_ref(&ir, a, b, y, k);
        ra = r8_attr_first(&ia, a, b, y, k);
        taken += rr != 0;
        if (ra != rr || memcmp(&ia, &ir, sizeof ia) != 0) {
            print_case("r8_attr_first", i);
            unity_fail_int(__LINE__, "r8_attr_first differs from the reference", (long)ra, (long)rr);
        }
    }
    if (taken < 1000 || taken > 7000)
        unity_fail_int(__LINE__, "r8_attr_first: one outcome too rare", 3000, (long)taken);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_trap_random);
    RUN_TEST(test_trap_many_rows);
    RUN_TEST(test_trap_groups);
    RUN_TEST(test_xform_random);
    RUN_TEST(test_edge_random);
    RUN_TEST(test_project_random);
    RUN_TEST(test_fill_random);
    RUN_TEST(test_zrows_random);
    RUN_TEST(test_init_sub_random);
    RUN_TEST(test_attr_first_random);
    return UNITY_END();
}
