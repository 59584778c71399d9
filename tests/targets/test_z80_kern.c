/* test_z80_kern.c - the Z80 assembly kernels (ports/z80/NAME_z80.s) against
 * their C references, on thousands of random inputs, inside the
 * simulator (ucsim sz80: mk/targets.mk, step xkern-z80).  The kernels'
 * objects are linked in whatever Z80_ASM chose for the library.
 *
 *   r8k_trap (trap_z80.s): against the C89 reference of src/kern.c,
 *     compiled into this program under another name (kern.c's other
 *     kernels too, out of the library's way); every output byte compared:
 *     the whole band window, up to 4 pages of w columns at a random offset
 *     between guard bytes, and all of t, l and r.
 *   The wire kernels (wire_z80.s) are tests/c/test_wirek.c's (step
 *     xunit-z80, with -DR8_ASM_WIRE when Z80_ASM links them).
 *   r8k_fill (fill_z80.s): against memset (src/kern.c's reference) on
 *     random lengths 0..700 at random offsets, the bytes around kept.
 *   __mulint and __mul16 (mulint_z80.s, sdcc's int * int; linked here):
 *     against a C89 shift-and-add model, unsigned, signed and char.
 *   r8k_xform (xform_z80.s): against the reference on random matrices,
 *     offsets (the 32-bit extremes too) and vertices (model-sized, the
 *     16-bit extremes, and code bytes); out compared, m and t unchanged.
 *   r8k_edge (edge_z80.s): against the reference on random edges
 *     (tests/targets/test_avr_kern.c's classes), every path counted; the
 *     result and all of *it compared.
 *   r8k_project (project_z80.s): against the reference (r8_recip and
 *     r8_project_recip) on random points, focal lengths, guard bands and
 *     projections (tests/targets/test_avr_kern.c's cases), every path of
 *     the reference counted; out, *m, *e and the result compared.
 *   r8k_rotoff, r8_mat_apply_t14 and r8_mat_rotate (tframe_z80.s):
 *     against src/r8tfref.h's references (rot_offset, r8_mat_apply_t14,
 *     r8_mat_rotate), renamed, on random matrices (Q1.14 rows, full
 *     16-bit, zeros, the extremes), offsets d (world-sized, full 32-bit,
 *     high words 0, 1, -1, zeros) and vectors, both orders, every output
 *     and saturation side counted; r8_mat_rotate on every angle of each
 *     axis (the others random) and random triples, the words around m
 *     kept.
 *   r8k_trap's pattern cache: patterns from a pool of 6 in random order.
 *   r8k_cull (cull_z80.s): against the reference on random normals (zero
 *     components, +-16384 and other low bytes of 0, any Q1.14), vertices
 *     around the range's edges +-1023 and eyes (low words within +-16383,
 *     any high word); each answer -1, 0, 1 counted.
 *   r8_mul16 (the library's: assembly unless Z80_ASM leaves it out),
 *     r8z_mul16s (mulz_z80.s, what the kernels use) and __mullong (any
 *     r8_s32 product; mullong_z80.s is linked here): against a C89
 *     schoolbook model built from 8 x 8 bit products. */
#include <string.h>
#include "unity.h"
#include "r8kern.h"
#include "r8flash.h"

/* the C references, renamed */
void r8k_trap_ref(r8_trapfill *t, r8_interp *l, r8_interp *r, r8_u16 rows);
void r8k_xform_ref(const r8_mat3 *m, const r8_vec3l *t, const r8_s16 *v, r8_vec3l *out);
int r8k_project_ref(const r8_proj *p, const r8_vec3l *c, r8_s16 *out, r8_u16 *m, r8_s8 *e);
r8_s16 r8k_edge_ref(r8_interp *it, const r8_s16 *a, const r8_s16 *b);
void r8k_fill_ref(r8_u8 *p, r8_u8 v, unsigned n);
int r8k_cull_ref(const r8_s16 *n, const r8_s16 *v, const r8_vec3l *eye);
#define r8k_cull r8k_cull_ref
#define r8k_trap r8k_trap_ref
#define r8k_xform r8k_xform_ref
#define r8k_project r8k_project_ref
#define r8k_edge r8k_edge_ref
#define r8k_fill r8k_fill_ref
#undef R8_ASM_FILL
#undef R8_ASM_TRAP
#undef R8_ASM_XFORM
#undef R8_ASM_PROJECT
#undef R8_ASM_EDGE
#undef R8_ASM_CULL
#include "kern.c"
#undef r8k_cull
#undef r8k_trap
#undef r8k_xform
#undef r8k_project
#undef r8k_edge
#undef r8k_fill

r8_s32 r8z_mul16s(r8_s16 a, r8_s16 b); /* mulz_z80.s */

/* tframe_z80.s's references (src/r8tfref.h), renamed */
void r8_mat_apply_t14_ref(const r8_mat3 *m, const r8_vec3 *v, r8_vec3 *out);
void r8_mat_rotate_ref(r8_mat3 *m, r8_u8 ax, r8_u8 ay, r8_u8 az);
#define rot_offset r8k_rotoff_ref
#define r8_mat_apply_t14 r8_mat_apply_t14_ref
#define r8_mat_rotate r8_mat_rotate_ref
#define TFREF_ROT
#define TFREF_T14
#define TFREF_ROTATE
#include "r8tfref.h"
#undef TFREF_ROT
#undef TFREF_T14
#undef TFREF_ROTATE
#undef rot_offset
#undef r8_mat_apply_t14
#undef r8_mat_rotate

#ifndef TRAP_CASES
#define TRAP_CASES 3000
#endif
#ifndef EDGE_CASES
#define EDGE_CASES 4000
#endif
#ifndef PROJ_CASES
#define PROJ_CASES 4000
#endif
#ifndef XFORM_CASES
#define XFORM_CASES 2000
#endif
#ifndef TFRAME_CASES
#define TFRAME_CASES 3000
#endif
#ifndef MUL_CASES
#define MUL_CASES 3000
#endif

static r8_u32 rng = 0x2545F491UL;
static r8_u32 rnd(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 17;
    rng ^= rng << 5;
    return rng;
}
/* 0..n-1 (a 16-bit remainder: a 32-bit one is ~1000 times slower here) */
static unsigned rndn(unsigned n) { return (unsigned)((r8_u16)(rnd() >> 8) % n); }
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

/* ---- multiplies: the model, from 8 x 8 -> 16 bit products (16-bit
 * unsigned multiplies, no long multiply) ---- */

static r8_u32 model_mul(r8_u32 a, r8_u32 b)
{
    r8_u8 x[4], y[4], i, j;
    r8_u16 acc[5];
    r8_u32 r;
    for (i = 0; i < 4; i++) {
        x[i] = (r8_u8)(a >> (8 * i));
        y[i] = (r8_u8)(b >> (8 * i));
    }
    for (i = 0; i < 5; i++)
        acc[i] = 0;
    /* column sums of the partial products' bytes: < 2^16 for 4 columns */
    for (i = 0; i < 4; i++)
        for (j = 0; (r8_u8)(i + j) < 4; j++) {
            r8_u16 p = (r8_u16)((r8_u16)x[i] * (r8_u16)y[j]);
            acc[i + j] = (r8_u16)(acc[i + j] + (p & 0xFFu));
            acc[i + j + 1] = (r8_u16)(acc[i + j + 1] + (p >> 8));
        }
    r = 0;
    for (i = 0; i < 4; i++) { /* carry the columns */
        r |= (r8_u32)(acc[i] & 0xFFu) << (8 * i);
        acc[i + 1] = (r8_u16)(acc[i + 1] + (acc[i] >> 8));
    }
    return r;
}

static r8_s16 rnd_factor(void)
{
    static const r8_s16 ext[14] = {
        R8_S16_MIN, -32767, -16385, -256, -255, -129, -128, -1, 0, 1, 127, 255, 256, 32767
    };
    unsigned c = rndn(10);
    if (c < 3)
        return rnds(-255, 255);
    if (c < 8)
        return (r8_s16)rnd();
    return ext[rndn(14)];
}

static r8_s32 rnd_long(void)
{
    unsigned c = rndn(6);
    if (c < 2)
        return (r8_s32)rnd_factor();                 /* sign-extended 16 */
    if (c < 3)
        return (r8_s32)(r8_u16)rnd_factor();         /* zero-extended 16 */
    if (c < 4)
        return (r8_s32)((r8_u32)rnd_factor() << 16); /* low word 0 */
    return (r8_s32)rnd();
}

static void test_mul_random(void)
{
    unsigned long i;
    for (i = 0; i < MUL_CASES; i++) {
        r8_s16 a = rnd_factor(), b = rnd_factor();
        r8_s32 x = rnd_long(), y = rnd_long(), p;
        r8_u32 want = model_mul((r8_u32)(r8_s32)a, (r8_u32)(r8_s32)b);
        if ((r8_u32)r8_mul16(a, b) != want || (r8_u32)r8z_mul16s(a, b) != want) {
            print_case("r8_mul16", i);
            TEST_ASSERT_EQUAL_UINT32(want, (r8_u32)r8_mul16(a, b));
            TEST_ASSERT_EQUAL_UINT32(want, (r8_u32)r8z_mul16s(a, b));
        }
        p = x;
        p *= y; /* __mullong */
        if ((r8_u32)p != model_mul((r8_u32)x, (r8_u32)y)) {
            print_case("__mullong", i);
            TEST_ASSERT_EQUAL_UINT32(model_mul((r8_u32)x, (r8_u32)y), (r8_u32)p);
        }
    }
    /* the model itself, on known products */
    TEST_ASSERT_EQUAL_UINT32(0x3FFF0001UL, model_mul(0xFFFF8001UL, 0xFFFF8001UL));
    TEST_ASSERT_EQUAL_UINT32(0x00018789UL, model_mul(0x183UL, 0x103UL));
    TEST_ASSERT_EQUAL_UINT32(0xFFFFFFFFUL, model_mul(0xFFFFFFFFUL, 1UL));
    TEST_ASSERT_EQUAL_UINT32(0x40000000UL, (r8_u32)r8_mul16(R8_S16_MIN, R8_S16_MIN));
    TEST_ASSERT_EQUAL_UINT32(0xC0008000UL, (r8_u32)r8_mul16(R8_S16_MIN, 32767));
}

/* ---- __mulint / __mul16 (mulint_z80.s): every int product of this
 * file goes through them; the model only adds and shifts ---- */
static r8_u16 model_mulint(r8_u16 a, r8_u16 b)
{
    r8_u16 r = 0;
    r8_u8 i;
    for (i = 0; i < 16; i++) {
        r = (r8_u16)(r << 1);
        if (b & 0x8000u)
            r = (r8_u16)(r + a);
        b = (r8_u16)(b << 1);
    }
    return r;
}

static r8_u16 rnd_int(void)
{
    unsigned c = rndn(4);
    if (c == 0)
        return (r8_u16)rndn(256);
    if (c == 1)
        return (r8_u16)(0u - rndn(256));
    return (r8_u16)rnd();
}

static void test_mulint_random(void)
{
    unsigned long i;
    for (i = 0; i < MUL_CASES; i++) {
        r8_u16 a = rnd_int(), b = rnd_int(), want = model_mulint(a, b);
        r8_s16 sa = (r8_s16)a, sb = (r8_s16)b;
        signed char ca = (signed char)(a & 0xFFu), cb = (signed char)(b & 0xFFu);
        unsigned char ua = (unsigned char)(a & 0xFFu);
        if ((r8_u16)(a * b) != want || (r8_u16)(sa * sb) != want) {
            print_case("__mulint", i);
            TEST_ASSERT_EQUAL_UINT16(want, (r8_u16)(a * b));
            TEST_ASSERT_EQUAL_UINT16(want, (r8_u16)(sa * sb));
        }
        want = model_mulint((r8_u16)(r8_s16)ca, (r8_u16)(r8_s16)cb);
        if ((r8_u16)(ca * cb) != want) {
            print_case("__mulschar", i);
            TEST_ASSERT_EQUAL_UINT16(want, (r8_u16)(ca * cb));
        }
        want = model_mulint((r8_u16)ua, (r8_u16)(r8_s16)cb);
        if ((r8_u16)(ua * cb) != want) {
            print_case("__muluschar", i);
            TEST_ASSERT_EQUAL_UINT16(want, (r8_u16)(ua * cb));
        }
    }
    TEST_ASSERT_EQUAL_UINT16(0xFFFEu, model_mulint(0xFFFFu, 2u));
    TEST_ASSERT_EQUAL_UINT16(0x0001u, model_mulint(0xFFFFu, 0xFFFFu));
}

#if !defined(Z80K_PART) || Z80K_PART == 2
/* ---- r8k_xform inputs, r8k_edge, r8k_project: tests/targets/kern_cases.h ---- */
#define KERN_CODE_PTR() ((const r8_s16 *)(0x0200u + rndn(0x3000u)))   /* code bytes */
#include "kern_cases.h"

#endif

#if !defined(Z80K_PART) || Z80K_PART == 1
/* ---- r8k_trap: tests/targets/kern_trap.h ---- */
/* trap_z80.s's group classes, derived from each case's inputs (the rows
 * walked as the kernel groups them, the DDAs stepped as the reference):
 * a group is g = min(rows to the page's end, rows left) >= 2 rows when
 * w <= 255 and m is one bit.  Per DDA of a group, dda's fast path (den <
 * 0x8000, q in [-256, 255], the first row's val in [0, w]) completes for
 * each g (tc_fast[g]) when the val after the g rows is in [0, w] too,
 * else falls back to ddas after its rows (tc_back); with both DDAs fast,
 * the group's bounds come from its first and last rows: max ga at the
 * first (tc_bnd[0]) or the last (tc_bnd[1]), min gb at the first
 * (tc_bnd[2]) or the last (tc_bnd[3]) */
static unsigned long tc_fast[9], tc_back, tc_bnd[4];

/* one DDA of a group: 1 if the fast path completes; *it steps g rows,
 * *last the last row's val */
static int tc_dda(r8_interp *it, r8_s16 w, unsigned g, r8_s16 *last)
{
    int fast = it->den < 0x8000u && it->q >= -256 && it->q <= 255 && it->val >= 0 && it->val <= w;
    unsigned i;
    for (i = 0; i < g; i++) {
        *last = it->val;
        R8_INTERP_STEP(it);
    }
    if (!fast)
        return 0;
    if (it->val >= 0 && it->val <= w) {
        tc_fast[g]++;
        return 1;
    }
    tc_back++;
    return 0;
}

static void trap_classes(const r8_trapfill *t, const r8_interp *l0, const r8_interp *r0, r8_u16 rows)
{
    r8_interp l, r;
    r8_u8 m = t->m;
    r8_s16 w = t->w;
    memcpy(&l, l0, sizeof l);
    memcpy(&r, r0, sizeof r);
    while (rows != 0) {
        unsigned s = 0, g;
        if (w <= 255 && m != 0 && (m & (m - 1u)) == 0) {
            while ((1u << s) != m)
                s++;
            g = 8u - s;
            if (rows < g)
                g = rows;
            if (g >= 2) {
                r8_s16 la = l.val, ra = r.val;
                r8_s16 lz = 0, rz = 0;
                int fl = tc_dda(&l, w, g, &lz), fr = tc_dda(&r, w, g, &rz);
                if (fl && fr) {
                    if (la > lz)
                        tc_bnd[0]++;
                    else if (lz > la)
                        tc_bnd[1]++;
                    if (ra < rz)
                        tc_bnd[2]++;
                    else if (rz < ra)
                        tc_bnd[3]++;
                }
                rows = (r8_u16)(rows - g);
                m = (r8_u8)(s + g < 8u ? 1u << (s + g) : 1u);
                continue;
            }
        }
        R8_INTERP_STEP(&l);
        R8_INTERP_STEP(&r);
        m = (r8_u8)(m << 1);
        if (m == 0)
            m = 1;
        rows--;
    }
}
#define TRAP_CLASSES(t, l, r, rows) trap_classes(t, l, r, rows)

/* test_trap_classes's extra cases: m one bit, both DDAs slow-moving
 * (q in [-3, 3], den <= 64) from a column in [0, w], so both often take
 * dda's fast path through a group and set its bounds */
static int tc_bias;
static void tc_bias_interp(r8_interp *it, r8_s16 w)
{
    it->den = (r8_u16)(1u + rndn(64));
    it->err = (r8_u16)(rndn(it->den));
    it->r = (r8_u16)(rndn(it->den));
    it->val = (r8_s16)rndn((unsigned)w + 1u);
    it->q = rnds(-3, 3);
}
static void trap_bias(r8_trapfill *t, r8_interp *l, r8_interp *r)
{
    if (!tc_bias)
        return;
    t->m = (r8_u8)(1u << rndn(8));
    tc_bias_interp(l, t->w);
    tc_bias_interp(r, t->w);
}
#define TRAP_BIAS(t, l, r) trap_bias(t, l, r)
#include "kern_trap.h"

#ifndef TRAPB_CASES
#define TRAPB_CASES 500
#endif
static void test_trap_classes(void)
{
    unsigned g;
    unsigned long i;
    int bad;
    tc_bias = 1;
    for (i = 0; i < TRAPB_CASES; i++) {
        bad = trap_case((r8_s16)(1 + rndn(160)), (r8_u16)(2u + rndn(19)), 4, 0);
        if (bad) {
            print_case("r8k_trap biased", i);
            unity_fail_int(__LINE__, "r8k_trap differs from the reference (1 band, 2 page, 3 t, 4 l, 5 r)", 0, bad);
        }
    }
    tc_bias = 0;
    unity_print("r8k_trap dda fast g=2..8:");
    for (g = 2; g <= 8; g++) {
        unity_print(" ");
        unity_print_long((long)tc_fast[g]);
    }
    unity_print("; back to ddas ");
    unity_print_long((long)tc_back);
    unity_print("; bounds max ga first/last, min gb first/last:");
    for (g = 0; g < 4; g++) {
        unity_print(" ");
        unity_print_long((long)tc_bnd[g]);
    }
    unity_print("\n");
    for (g = 2; g <= 8; g++)
        if (tc_fast[g] < 50)
            unity_fail_int(__LINE__, "r8k_trap: dda's fast path too rare for a group size", (long)g,
                           (long)tc_fast[g]);
    if (tc_back < 100)
        unity_fail_int(__LINE__, "r8k_trap: dda's fast path falling back too rare", 100, (long)tc_back);
    for (g = 0; g < 4; g++)
        if (tc_bnd[g] < 50)
            unity_fail_int(__LINE__, "r8k_trap: a group bound class too rare", (long)g, (long)tc_bnd[g]);
}

/* ---- r8k_fill: lengths 0..700 at random offsets in band_asm/band_ref
 * (kern_trap.h's windows), the bytes around them kept ---- */
static void test_fill_random(void)
{
    unsigned long i;
    unsigned rem[16];
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
        rem[n & 15]++;
        if (memcmp(band_asm, band_ref, len) != 0) {
            print_case("r8k_fill", i);
            unity_fail_int(__LINE__, "r8k_fill differs from the reference", (long)n, (long)off);
        }
    }
    for (i = 0; i < 16; i++)
        if (rem[i] < 20)
            unity_fail_int(__LINE__, "r8k_fill: a length remainder too rare", 20, (long)rem[i]);
    /* the two-level count: 256 passes of 16 and more */
    memset(band_ref, 0x5A, 4200);
    r8k_fill(band_ref + 1, 0xC3, 4097);
    TEST_ASSERT_EQUAL_UINT8(0x5A, band_ref[0]);
    TEST_ASSERT_EQUAL_UINT8(0xC3, band_ref[1]);
    TEST_ASSERT_EQUAL_UINT8(0xC3, band_ref[4097]);
    TEST_ASSERT_EQUAL_UINT8(0x5A, band_ref[4098]);
}

#endif

#if !defined(Z80K_PART) || Z80K_PART == 2
/* ---- r8k_rotoff, r8_mat_apply_t14 (tframe_z80.s) ---- */
static r8_s16 rnd_elem(unsigned c)
{
    switch (c) {
    case 0:
        return rnds(-16384, 16384);             /* a rotation's range */
    case 1:
        return (r8_s16)rnd();
    case 2:
        return 0;
    case 3:
        return rndn(2) ? 32767 : (r8_s16)(-32767 - 1);
    default:
        return rnds(-300, 300);
    }
}

static r8_s32 rnd_d(void)
{
    r8_u32 u = rnd();
    switch (rndn(8)) {
    case 0:
        return 0;
    case 1:
        return (r8_s32)rnds(-32767, 32767);
    case 2:                                     /* |d| < 2^17, as r8_tf_frame's */
        return rndn(2) ? (r8_s32)(u & 0x1FFFFUL) : -(r8_s32)(u & 0x1FFFFUL);
    case 3:
        return (r8_s32)((u & 0xFFFFUL) | 0x10000UL);    /* high word 1 */
    case 4:
        return (r8_s32)((u & 0xFFFFUL) | 0xFFFF0000UL); /* high word -1 */
    case 5:
        return rndn(2) ? (r8_s32)0x7FFFFFFFL : (r8_s32)(-0x7FFFFFFFL - 1);
    default:
        return (r8_s32)u;
    }
}

static void test_tframe_random(void)
{
    unsigned long i;
    unsigned j, sat_hi = 0, sat_lo = 0, tr_n = 0;
    r8_mat3 m, m0;                      /* (function scope: sdcc, DEVELOPERS.md) */
    r8_s32 d[3], d0[3];
    r8_vec3l oa, or_;
    r8_vec3 v, v0, ta, tr;
    for (i = 0; i < TFRAME_CASES; i++) {
        unsigned c = rndn(5);
        int t = (int)rndn(2);
        for (j = 0; j < 9; j++)
            m.m[j] = rnd_elem(rndn(4) == 0 ? rndn(5) : c);
        for (j = 0; j < 3; j++)
            d[j] = rnd_d();
        v.x = rnd_elem(rndn(5));
        v.y = rnd_elem(rndn(5));
        v.z = rnd_elem(rndn(5));
        m0 = m;
        v0 = v;
        memcpy(d0, d, sizeof d);
        memset(&oa, 0x5A, sizeof oa);
        memset(&or_, 0xA5, sizeof or_);
        r8k_rotoff_ref(&m, d, &or_, t);
        r8k_rotoff(&m, d, &oa, t);
        tr_n += (unsigned)t;
        if (memcmp(&oa, &or_, sizeof oa) != 0 || memcmp(&m, &m0, sizeof m) != 0 ||
            memcmp(d, d0, sizeof d) != 0) {
            print_case("r8k_rotoff", i);
            TEST_ASSERT_EQUAL_INT32(or_.x, oa.x);
            TEST_ASSERT_EQUAL_INT32(or_.y, oa.y);
            TEST_ASSERT_EQUAL_INT32(or_.z, oa.z);
            TEST_FAIL_MESSAGE("r8k_rotoff changed m or d");
        }
        memset(&ta, 0x5A, sizeof ta);
        memset(&tr, 0xA5, sizeof tr);
        r8_mat_apply_t14_ref(&m, &v, &tr);
        r8_mat_apply_t14(&m, &v, &ta);
        if (memcmp(&ta, &tr, sizeof ta) != 0 || memcmp(&m, &m0, sizeof m) != 0 ||
            memcmp(&v, &v0, sizeof v) != 0) {
            print_case("r8_mat_apply_t14", i);
            TEST_ASSERT_EQUAL_INT16(tr.x, ta.x);
            TEST_ASSERT_EQUAL_INT16(tr.y, ta.y);
            TEST_ASSERT_EQUAL_INT16(tr.z, ta.z);
            TEST_FAIL_MESSAGE("r8_mat_apply_t14 changed m or v");
        }
        sat_hi += (tr.x == 32767) + (tr.y == 32767) + (tr.z == 32767);
        sat_lo += (tr.x == -32767 - 1) + (tr.y == -32767 - 1) + (tr.z == -32767 - 1);
    }
    unity_print("tframe: ");
    unity_print_long((long)i);
    unity_print(" cases, transposed ");
    unity_print_long((long)tr_n);
    unity_print(", saturated ");
    unity_print_long((long)sat_hi);
    unity_print(" / ");
    unity_print_long((long)sat_lo);
    unity_print("\n");
    if (sat_hi < 20 || sat_lo < 20 || tr_n < TFRAME_CASES / 3)
        TEST_FAIL_MESSAGE("tframe: a case class too rare");
}

static void test_rotate(void)
{
    unsigned long i;
    unsigned j;
    r8_mat3 w[3], r;                     /* w[1] the kernel's, between guards */
    r8_u8 a[3];                          /* (function scope: sdcc, DEVELOPERS.md) */
    for (i = 0; i < 1024; i++) {
        for (j = 0; j < 3; j++)
            a[j] = (r8_u8)rnd();
        if (i < 768)
            a[i >> 8] = (r8_u8)i;         /* every angle of each axis */
        memset(w, 0xA5, sizeof w);
        memset(&r, 0x5A, sizeof r);
        r8_mat_rotate_ref(&r, a[0], a[1], a[2]);
        r8_mat_rotate(&w[1], a[0], a[1], a[2]);
        if (memcmp(&w[1], &r, sizeof r) != 0) {
            print_case("r8_mat_rotate", i);
            for (j = 0; j < 3; j++) {
                unity_print_long((long)a[j]);
                unity_print(" ");
            }
            for (j = 0; j < 9; j++) {
                unity_print_long((long)r.m[j]);
                unity_print("/");
                unity_print_long((long)w[1].m[j]);
                unity_print(" ");
            }
            unity_print("\n");
            for (j = 0; j < 9; j++)
                TEST_ASSERT_EQUAL_INT16(r.m[j], w[1].m[j]);
        }
        for (j = 0; j < 9; j++)
            if (w[0].m[j] != (r8_s16)0xA5A5u || w[2].m[j] != (r8_s16)0xA5A5u) {
                print_case("r8_mat_rotate", i);
                TEST_FAIL_MESSAGE("r8_mat_rotate wrote outside m");
            }
    }
    /* the identity and a quarter turn about y, exactly */
    r8_mat_rotate(&r, 0, 0, 0);
    TEST_ASSERT_EQUAL_INT16(16384, r.m[0]);
    TEST_ASSERT_EQUAL_INT16(0, r.m[1]);
    TEST_ASSERT_EQUAL_INT16(16384, r.m[4]);
    TEST_ASSERT_EQUAL_INT16(16384, r.m[8]);
    r8_mat_rotate(&r, 0, 64, 0);
    TEST_ASSERT_EQUAL_INT16(0, r.m[0]);
    TEST_ASSERT_EQUAL_INT16(16384, r.m[2]);
    TEST_ASSERT_EQUAL_INT16(-16384, r.m[6]);
}

/* ---- r8k_cull (cull_z80.s) ---- */
#ifndef CULL_CASES
#define CULL_CASES 4000
#endif
static r8_s16 rnd_normal(void)
{
    switch (rndn(5)) {
    case 0: return 0;
    case 1: return (r8_s16)(rndn(2) ? 16384 : -16384);
    case 2: return (r8_s16)((r8_s16)rnds(-64, 64) * 256);
    default: return rnds(-16384, 16384);
    }
}
static r8_s16 rnd_vert(void)
{
    switch (rndn(4)) {
    case 0: return rnds(-1030, -1016);
    case 1: return rnds(1016, 1030);
    case 2: return rnds(-4, 4);
    default: return (r8_s16)(rndn(16) ? rnds(-1023, 1023) : (r8_s16)rnd());
    }
}
static void test_cull_random(void)
{
    unsigned long i;
    unsigned j, seen[3];
    r8_s16 n[3], v[3];
    r8_vec3l eye;
    int want, got;
    seen[0] = seen[1] = seen[2] = 0;
    for (i = 0; i < CULL_CASES; i++) {
        for (j = 0; j < 3; j++) {
            n[j] = rnd_normal();
            v[j] = rnd_vert();
        }
        eye.x = (r8_s32)((r8_u32)rnd() << 16) + (r8_s32)rnds(-16383, 16383);
        eye.y = (r8_s32)((r8_u32)rnd() << 16) + (r8_s32)rnds(-16383, 16383);
        eye.z = (r8_s32)((r8_u32)rnd() << 16) + (r8_s32)rnds(-16383, 16383);
        if (i & 1) {      /* (the sign of the low words is what the test reads) */
            eye.x = (r8_s16)eye.x;
            eye.y = (r8_s16)eye.y;
            eye.z = (r8_s16)eye.z;
        }
        want = r8k_cull_ref(n, v, &eye);
        got = r8k_cull(n, v, &eye);
        if (want != got) {
            print_case("r8k_cull", i);
            for (j = 0; j < 3; j++) {
                unity_print_long((long)n[j]);
                unity_print(" ");
                unity_print_long((long)v[j]);
                unity_print(" ");
            }
            unity_print_long((long)(r8_s16)eye.x);
            unity_print(" ");
            unity_print_long((long)(r8_s16)eye.y);
            unity_print(" ");
            unity_print_long((long)(r8_s16)eye.z);
            unity_print("\n");
            TEST_ASSERT_EQUAL_INT(want, got);
        }
        seen[want + 1]++;
    }
    unity_print("cull: -1/0/1 ");
    unity_print_long((long)seen[0]);
    unity_print(" / ");
    unity_print_long((long)seen[1]);
    unity_print(" / ");
    unity_print_long((long)seen[2]);
    unity_print("\n");
    if (seen[0] < CULL_CASES / 10 || seen[1] < CULL_CASES / 10 || seen[2] < CULL_CASES / 10)
        TEST_FAIL_MESSAGE("cull: an answer too rare");
}

#endif

#if !defined(Z80K_PART) || Z80K_PART == 1
/* ---- r8k_trap's pattern cache (trap_z80.s: 4 slots, rebuilt in turn):
 * the patterns of a pool of 6 come back in random order, so every slot
 * is hit, missed and rebuilt; as trap_case, on rows of a page (groups).
 * The pool's patterns share prefixes (one base, bytes 0, 1, 2, 3 or 2
 * and 3 changed), so a lookup meets slots that differ first at each
 * byte: counted on a miss (every slot is compared then) from a model of
 * the slots (the last 4 patterns missed: rebuilt in turn), set first by
 * 4 calls with patterns the other tests never give */
#ifndef TRAPC_CASES
#define TRAPC_CASES 1500
#endif
static void test_trap_cache(void)
{
    static r8_u8 pool[6][4], slot[4][4];
    static const r8_u8 chg[6][4] = {
        { 0, 0, 0, 0 }, { 1, 0, 0, 0 }, { 0, 1, 0, 0 }, { 0, 0, 1, 0 }, { 0, 0, 0, 1 }, { 0, 0, 1, 1 } };
    unsigned long i, miss[4];
    unsigned j, nslot = 0;
    r8_trapfill ta, tr;
    r8_interp la, lr_, ra, rr_;
    r8_s16 w;
    for (j = 0; j < 4; j++) {
        r8_u8 base = (r8_u8)rnd(), x = (r8_u8)(1u + rndn(255));
        for (i = 0; i < 6; i++)
            pool[i][j] = (r8_u8)(chg[i][j] ? base ^ x : base);  /* all different */
    }
    memset(miss, 0, sizeof miss);
    memset(&ta, 0, sizeof ta);
    ta.page = band_asm;
    ta.w = 8;
    rnd_interp(&la, 8);
    ra = la;
    for (j = 0; j < 4; j++) {    /* rows 0: the lookup only */
        slot[j][0] = 0x96;
        slot[j][1] = 0x69;
        slot[j][2] = 0x35;
        slot[j][3] = (r8_u8)(0xA7 + j);
        memcpy(ta.pat, slot[j], 4);
        r8k_trap(&ta, &la, &ra, 0);
    }
    for (i = 0; i < TRAPC_CASES; i++) {
        unsigned off = rndn(64), len;
        r8_u16 rows = (r8_u16)(1u + rndn(20));
        w = (r8_s16)(1 + rndn(160));
        len = GUARD + 4u * (unsigned)w + GUARD;
        for (j = 0; j < len; j++)
            band_asm[off + j] = band_ref[off + j] = (r8_u8)(j * 151u + i);
        ta.page = band_asm + off + GUARD;
        ta.m = (r8_u8)(1u << rndn(8));
        ta.k = (r8_u8)rndn(4);
        memcpy(ta.pat, pool[rndn(6)], 4);
        for (j = 0; j < 4 && memcmp(slot[j], ta.pat, 4) != 0; j++)
            ;
        if (j == 4) {   /* a miss: each slot differs first at a byte */
            for (j = 0; j < 4; j++) {
                unsigned b = 0;
                while (slot[j][b] == ta.pat[b])
                    b++;
                miss[b]++;
            }
            memcpy(slot[nslot], ta.pat, 4);
            nslot = (nslot + 1u) & 3u;
        }
        ta.w = w;
        rnd_interp(&la, w);
        rnd_interp(&ra, w);
        la.val = rnds(-4, (r8_s16)(w + 4));
        ra.val = (r8_s16)(la.val + rnds(-2, (r8_s16)(w + 4)));
        la.q = rnds(-2, 2);
        ra.q = rnds(-2, 2);
        tr = ta;
        tr.page = band_ref + off + GUARD;
        lr_ = la;
        rr_ = ra;
        r8k_trap_ref(&tr, &lr_, &rr_, rows);
        r8k_trap(&ta, &la, &ra, rows);
        if (memcmp(band_asm + off, band_ref + off, len) != 0 || ta.m != tr.m || ta.k != tr.k ||
            (unsigned)(ta.page - band_asm) != (unsigned)(tr.page - band_ref) ||
            memcmp(&la, &lr_, sizeof la) != 0 || memcmp(&ra, &rr_, sizeof ra) != 0) {
            print_case("r8k_trap cache", i);
            TEST_FAIL_MESSAGE("r8k_trap differs from the reference (pattern cache)");
        }
    }
    unity_print("r8k_trap cache: slots differing first at bytes 0..3 on a miss:");
    for (j = 0; j < 4; j++) {
        unity_print(" ");
        unity_print_long((long)miss[j]);
    }
    unity_print("\n");
    for (j = 0; j < 4; j++)
        if (miss[j] < 100)
            unity_fail_int(__LINE__, "r8k_trap cache: a mismatch byte too rare", (long)j, (long)miss[j]);
}

#endif

int main(void)
{
    UNITY_BEGIN();
    /* Z80K_PART 1 or 2 (mk/targets.mk): one half of the cases each, so
     * each program leaves ucsim's 64 KB room for its stack (gcz80 drops
     * the other half's tests, references and buffers); without it, all */
#if !defined(Z80K_PART) || Z80K_PART == 1
    RUN_TEST(test_mul_random);
    RUN_TEST(test_mulint_random);
    RUN_TEST(test_trap_random);
    RUN_TEST(test_trap_many_rows);
    RUN_TEST(test_trap_classes);
    RUN_TEST(test_fill_random);
    RUN_TEST(test_trap_cache);
#endif
#if !defined(Z80K_PART) || Z80K_PART == 2
    RUN_TEST(test_xform_random);
    RUN_TEST(test_tframe_random);
    RUN_TEST(test_rotate);
    RUN_TEST(test_project_random);
    RUN_TEST(test_edge_random);
    RUN_TEST(test_cull_random);
#endif
    return UNITY_END();
}
