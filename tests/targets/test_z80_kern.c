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
#include "kern.c"
#undef r8k_trap
#undef r8k_xform
#undef r8k_project
#undef r8k_edge
#undef r8k_fill

r8_s32 r8z_mul16s(r8_s16 a, r8_s16 b); /* mulz_z80.s */

#ifndef TRAP_CASES
#define TRAP_CASES 3000
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

/* ---- r8k_trap: tests/targets/kern_trap.h ---- */
#include "kern_trap.h"

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_mul_random);
    RUN_TEST(test_trap_random);
    RUN_TEST(test_trap_many_rows);
    return UNITY_END();
}
