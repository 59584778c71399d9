/* test_avr_kern.c - the AVR assembly kernels (ports/avr/trap.S,
 * ports/avr/xform.S) against their C references (src/kern.c, compiled
 * into this program under other names), on thousands of random inputs,
 * inside the simulator (ATmega1284P: mk/targets.mk, step xkern-avr1284).
 *
 * Every case runs both versions on identical copies of the inputs and
 * compares every output byte: for r8k_trap the whole band window (up to
 * 4 pages of w columns, at a random offset, between guard bytes) and all
 * of t, l and r; for r8k_xform all of out (and m, t untouched).  v is
 * read from flash: windows over two tables below (small values for the
 * 16x8 path and its edges, extremes for the 16x16 one) and over the
 * program's own code (arbitrary words). */
#include <string.h>
#include "unity.h"
#include "r8kern.h"
#include "r8flash.h"

/* the C references, renamed */
void r8k_trap_ref(r8_trapfill *t, r8_interp *l, r8_interp *r, r8_u16 rows);
void r8k_xform_ref(const r8_mat3 *m, const r8_vec3l *t, const r8_s16 *v, r8_vec3l *out);
#define r8k_trap r8k_trap_ref
#define r8k_xform r8k_xform_ref
#include "kern.c"
#undef r8k_trap
#undef r8k_xform

#ifndef TRAP_CASES
#define TRAP_CASES 3000
#endif
#ifndef XFORM_CASES
#define XFORM_CASES 4000
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

/* ---- r8k_trap ---- */

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
    for (i = 0; i < len; i++) {
        b = (r8_u8)(b * 37u + 89u);   /* cheap bytes, a new start per case */
        wa[i] = wr[i] = b;
    }
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
    tr = ta;
    tr.page = wr + GUARD;
    lr_ = la;
    rr_ = ra;
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

/* ---- r8k_xform ---- */

static const r8_s16 vt_ext[96] R8_FLASH = {
    128, -32767, 0, 2, 128, R8_S16_MIN, -256, 1, 32767, 2, 32767, -129,
    255, 32766, -16383, -32767, 126, 2, -127, -32766, -255, 16384, -2, -32767,
    0, -16384, 129, -2, -1, 0, -128, 32767, 256, -129, 1, -16383,
    256, -128, 256, -2, -16384, 1, 16385, -255, 1, 129, -1, -32767,
    128, R8_S16_MIN, -255, -16384, -256, -128, 127, -2, 16385, -255, -127, 256,
    127, 1, 0, 2, -32766, 255, 128, -127, 126, -16383, 32767, -255,
    0, -255, -32767, -32767, 2, -128, 32767, 129, 256, -32766, 127, -32766,
    -16384, -1, 128, -2, 129, -16384, -16385, 16385, 16385, -16385, 1, R8_S16_MIN
};
static const r8_s16 vt_small[96] R8_FLASH = {
    -128, 127, -128, -128, 127, 127, -31, 50, 93, 84, 100, -3,
    12, -55, -37, -67, 8, 105, 26, -44, -39, -38, 117, 49,
    39, 94, -14, -126, -106, 41, 35, -4, -88, 6, 101, 79,
    -47, 71, 125, -5, 11, 119, 127, -96, -43, 122, 108, 77,
    -59, 87, 50, 70, 122, -44, 97, -78, 84, -110, -127, 96,
    -95, -103, 51, -81, -51, -73, 104, 120, -57, 106, 95, 100,
    47, 4, 106, 88, 40, -50, -7, 37, -112, -28, 117, -116,
    -69, 23, 94, -2, 20, -83, -105, -74, 18, -45, 116, -56
};
extern const char _etext[];   /* end of the program's code (avr-libc's linker script) */

static r8_s16 rnd_m(void)
{
    static const r8_s16 ext[12] = {
        R8_S16_MIN, -32767, -16385, -16384, -16383, -1, 0, 1, 16383, 16384, 16385, 32767
    };
    unsigned c = rndn(10);
    if (c < 4)
        return rnds(-16384, 16384);
    if (c < 7)
        return (r8_s16)rnd();
    return ext[rndn(12)];
}

static r8_s32 rnd_t(void)
{
    unsigned c = rndn(8);
    if (c < 3)
        return (r8_s32)rnds(-4096, 4096);
    if (c < 6)
        return (r8_s32)rnd();
    if (c < 7)
        return (r8_s32)0x7FFFFFFFL;
    return (r8_s32)(-0x7FFFFFFFL - 1);
}

static void test_xform_random(void)
{
    unsigned long i;
    unsigned j, code = (unsigned)_etext;
    unsigned long n_small = 0;
    for (i = 0; i < XFORM_CASES; i++) {
        r8_mat3 m, m0;
        r8_vec3l t, t0, oa, or_;
        const r8_s16 *v;
        unsigned c = rndn(10);
        for (j = 0; j < 9; j++)
            m.m[j] = rnd_m();
        t.x = rnd_t();
        t.y = rnd_t();
        t.z = rnd_t();
        if (c < 5)
            v = vt_small + rndn(94);
        else if (c < 8)
            v = vt_ext + rndn(94);
        else
            v = (const r8_s16 *)(rndn(code - 6u));
        if (R8_RDS16(v) >= -128 && R8_RDS16(v) < 128 && R8_RDS16(v + 1) >= -128 &&
            R8_RDS16(v + 1) < 128 && R8_RDS16(v + 2) >= -128 && R8_RDS16(v + 2) < 128)
            n_small++;
        m0 = m;
        t0 = t;
        memset(&oa, 0x5A, sizeof oa);
        memset(&or_, 0xA5, sizeof or_);
        r8k_xform_ref(&m, &t, v, &or_);
        r8k_xform(&m, &t, v, &oa);
        if (memcmp(&oa, &or_, sizeof oa) != 0 || memcmp(&m, &m0, sizeof m) != 0 ||
            memcmp(&t, &t0, sizeof t) != 0) {
            print_case("r8k_xform", i);
            TEST_ASSERT_EQUAL_INT32(or_.x, oa.x);
            TEST_ASSERT_EQUAL_INT32(or_.y, oa.y);
            TEST_ASSERT_EQUAL_INT32(or_.z, oa.z);
            TEST_FAIL_MESSAGE("r8k_xform changed m or t");
        }
    }
    unity_print("r8k_xform: ");
    unity_print_long((long)i);
    unity_print(" cases, ");
    unity_print_long((long)n_small);
    unity_print(" with every component in -128..127\n");
    TEST_ASSERT_GREATER_THAN(XFORM_CASES / 4, n_small);
    TEST_ASSERT_LESS_THAN(XFORM_CASES - XFORM_CASES / 4, n_small);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_trap_random);
    RUN_TEST(test_trap_many_rows);
    RUN_TEST(test_xform_random);
    return UNITY_END();
}
