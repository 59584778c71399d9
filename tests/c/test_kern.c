/* test_kern.c - the kernels of r8kern.h: the library's (a port's
 * assembly where it defines R8_ASM_TRAP / R8_ASM_XFORM / R8_ASM_PROJECT,
 * ports/6502/ assembly) against the C89 references of src/kern.c, compiled in
 * here under other names, on random inputs; both against a plain model
 * of each contract too (so the test means something where the two are
 * the same C). */
#include "unity.h"
#include "r8kern.h"
#include "r8fb.h"

/* src/kern.c's C versions as ref_*, whatever this build links */
#undef R8_ASM_TRAP
#undef R8_ASM_XFORM
#undef R8_ASM_PROJECT
#undef R8_ASM_EDGE
#define r8k_edge ref_edge /* not tested here: out of the library's way */
#define r8k_trap ref_trap
#define r8k_xform ref_xform
#define r8k_project ref_project
#include "../../src/kern.c"
#undef r8k_trap
#undef r8k_xform
#undef r8k_project
#undef r8k_edge
void ref_trap(r8_trapfill *t, r8_interp *l, r8_interp *r, r8_u16 rows);
void ref_xform(const r8_mat3 *m, const r8_vec3l *t, const r8_s16 *v, r8_vec3l *out);
int ref_project(const r8_proj *p, const r8_vec3l *c, r8_s16 *out, r8_u16 *m, r8_s8 *e);

void setUp(void) {}
void tearDown(void) {}

static r8_u32 seed = 777;
static r8_u16 rnd16(void)
{
    seed = seed * 1103515245ul + 12345ul;
    return (r8_u16)((seed >> 8) & 0xFFFFu);
}
static r8_u16 rndn(r8_u16 n) /* 0 .. n-1 */
{
    return (r8_u16)(rnd16() % n);
}

/* ---- r8k_trap */
#define MAXW 300
#define PAGES 3
static r8_u8 buf_a[MAXW * PAGES + 8], buf_b[MAXW * PAGES + 8], buf_m[MAXW * PAGES + 8];

static void rnd_interp(r8_interp *it, r8_s16 w)
{
    it->val = (r8_s16)((r8_s16)rndn((r8_u16)(w + 80)) - 40);
    it->q = (r8_s16)((r8_s16)rndn(9) - 4);
    if (!rndn(8))
        it->q = (r8_s16)((r8_s16)rndn(200) - 100);
    it->den = (r8_u16)(1u + rndn(rndn(2) ? 30000u : 50u));
    it->err = rndn(it->den);
    it->r = rndn(it->den);
}

/* the contract, pixel by pixel */
static void model_trap(r8_u8 *buf, r8_s16 w, r8_u8 by, const r8_u8 *pat, r8_u8 k,
                       r8_interp *l, r8_interp *r, r8_u16 rows)
{
    r8_s16 x;
    while (rows--) {
        r8_u8 m = (r8_u8)(1u << (by & 7));
        r8_u8 *page = buf + (unsigned)(by >> 3) * (unsigned)w;
        for (x = l->val < 0 ? 0 : l->val; x < r->val && x < w; x++) {
            if ((pat[k] >> (3 - (x & 3))) & 1)
                page[x] = (r8_u8)(page[x] | m);
            else
                page[x] = (r8_u8)(page[x] & ~m);
        }
        R8_INTERP_STEP(l);
        R8_INTERP_STEP(r);
        k = (r8_u8)((k + 1) & 3);
        by++;
    }
}

static void test_trap(void)
{
    unsigned i, j, rows;
    for (i = 0; i < 400; i++) {
        r8_trapfill ta, tb;
        r8_interp la, ra, lb, rb, lm, rm;
        r8_s16 w = (r8_s16)(1 + rndn(i & 7 ? 140 : MAXW));
        r8_u8 by = (r8_u8)rndn(8), k = (r8_u8)rndn(4);
        for (j = 0; j < sizeof buf_a; j++)
            buf_a[j] = buf_b[j] = buf_m[j] = (r8_u8)rnd16();
        rnd_interp(&la, w);
        rnd_interp(&ra, w);
        if (rndn(2))
            ra.val = (r8_s16)(la.val + (r8_s16)rndn(60));
        lb = la;
        lm = la;
        rb = ra;
        rm = ra;
        ta.page = buf_a + 4;
        ta.m = (r8_u8)(1u << by);
        ta.k = k;
        for (j = 0; j < 4; j++)
            ta.pat[j] = (r8_u8)(rndn(3) ? rnd16() : (rndn(2) ? 0xFF : 0x00));
        ta.w = w;
        tb = ta;
        tb.page = buf_b + 4;
        rows = 1u + rndn((r8_u16)(8 * PAGES - by - 1)); /* stays in the buffer */
        ref_trap(&ta, &la, &ra, (r8_u16)rows);
        r8k_trap(&tb, &lb, &rb, (r8_u16)rows);
        model_trap(buf_m + 4, w, by, ta.pat, k, &lm, &rm, (r8_u16)rows);
        TEST_ASSERT_EQUAL_MEMORY(buf_a, buf_b, sizeof buf_a);
        TEST_ASSERT_EQUAL_MEMORY(buf_m, buf_b, sizeof buf_a);
        TEST_ASSERT_TRUE(tb.page == buf_b + (ta.page - buf_a));
        TEST_ASSERT_EQUAL_HEX8(ta.m, tb.m);
        TEST_ASSERT_EQUAL_UINT(ta.k, tb.k);
        TEST_ASSERT_EQUAL_INT(la.val, lb.val);
        TEST_ASSERT_EQUAL_UINT(la.err, lb.err);
        TEST_ASSERT_EQUAL_INT(ra.val, rb.val);
        TEST_ASSERT_EQUAL_UINT(ra.err, rb.err);
        TEST_ASSERT_EQUAL_INT(lm.val, lb.val);
        TEST_ASSERT_EQUAL_INT(rm.val, rb.val);
        TEST_ASSERT_EQUAL_HEX8((r8_u8)(1u << ((by + rows) & 7)), tb.m);
        TEST_ASSERT_TRUE(tb.page == buf_b + 4 + ((by + rows) >> 3) * (unsigned)w);
    }
}

/* ---- r8k_xform */
static r8_s32 mul32(r8_s16 a, r8_s16 b) /* the plain C product */
{
    r8_s32 p = a;
    p *= b;
    return p;
}

static r8_s16 rnd_coord(void)
{
    switch (rndn(4)) {
    case 0:
        return (r8_s16)rnd16();                    /* any */
    case 1:
        return (r8_s16)((r8_s16)rndn(256) - 128);  /* a byte */
    case 2:
        return (r8_s16)((r8_s16)rndn(3) - 1);      /* 0, +-1 */
    default:
        return (r8_s16)((r8_s16)rndn(4001) - 2000);
    }
}

static void test_xform(void)
{
    unsigned i, j;
    for (i = 0; i < 1500; i++) {
        r8_mat3 m;
        r8_vec3l t, oa, ob;
        r8_s16 v[3];
        r8_s32 s;
        for (j = 0; j < 9; j++) {
            m.m[j] = (r8_s16)((r8_s16)rndn(32769u) - 16384);
            if (!rndn(4))
                m.m[j] = (r8_s16)(rndn(3) ? 0 : (rndn(2) ? 16384 : -16384));
        }
        for (j = 0; j < 3; j++)
            v[j] = rnd_coord();
        t.x = (r8_s32)(r8_s16)rnd16() * 4096L + (r8_s32)rnd16();
        t.y = (r8_s32)(r8_s16)rnd16() * 16L;
        t.z = (r8_s32)(r8_s16)rnd16();
        ref_xform(&m, &t, v, &oa);
        r8k_xform(&m, &t, v, &ob);
        TEST_ASSERT_EQUAL_INT32(oa.x, ob.x);
        TEST_ASSERT_EQUAL_INT32(oa.y, ob.y);
        TEST_ASSERT_EQUAL_INT32(oa.z, ob.z);
        s = mul32(m.m[0], v[0]) + mul32(m.m[1], v[1]) + mul32(m.m[2], v[2]) + 512;
        TEST_ASSERT_EQUAL_INT32(R8_ASR32C(s, 10) + t.x, ob.x);
        s = mul32(m.m[6], v[0]) + mul32(m.m[7], v[1]) + mul32(m.m[8], v[2]) + 512;
        TEST_ASSERT_EQUAL_INT32(R8_ASR32C(s, 10) + t.z, ob.z);
    }
}

/* ---- r8k_project */
static r8_s32 rnd_z(void)
{
    switch (rndn(6)) {
    case 0:
        return (r8_s32)(1 + rndn(300));
    case 1:
        return (r8_s32)rnd16() * (r8_s32)(1 + rndn(2000));
    case 2:
        return -(r8_s32)rndn(100);          /* behind: r8_recip takes it as 1 */
    case 3:
        return (r8_s32)(1u + rndn(0x7FFFu)) << rndn(16);
    default:
        return (r8_s32)(256 + rndn(20000));
    }
}

static r8_s32 rnd_xy(void)
{
    switch (rndn(5)) {
    case 0:
        return (r8_s32)(r8_s16)rnd16();
    case 1:
        return (r8_s32)(r8_s16)rnd16() * (r8_s32)(1 + rndn(300));   /* wide */
    case 2:
        return (r8_s32)((r8_s16)rndn(3) - 1) * 32768L + (r8_s32)rndn(3) - 1;
    default:
        return (r8_s32)((r8_s16)rndn(8001) - 4000);
    }
}

static void test_project(void)
{
    unsigned i;
    for (i = 0; i < 3000; i++) {
        r8_proj p;
        r8_vec3l c;
        r8_s16 oa[2], ob[2];
        r8_u16 ma, mb;
        r8_s8 ea, eb;
        int ra, rb;
        r8_proj_init(&p, (r8_s16)(16 + rndn(300)), (r8_s16)(16 + rndn(200)),
                     (r8_s16)(1 + rndn(i & 1 ? 200 : 2047)), 16);
        if (!rndn(10))
            p.guard = (r8_s16)rndn(2048);     /* some beyond 1024 px: the C path */
        c.x = rnd_xy();
        c.y = rnd_xy();
        c.z = rnd_z();
        oa[0] = oa[1] = ob[0] = ob[1] = 0x5A5A;
        ra = ref_project(&p, &c, oa, &ma, &ea);
        rb = r8k_project(&p, &c, ob, &mb, &eb);
        TEST_ASSERT_EQUAL_INT(ra, rb);
        TEST_ASSERT_EQUAL_UINT(ma, mb);
        TEST_ASSERT_EQUAL_INT(ea, eb);
        TEST_ASSERT_EQUAL_INT(oa[0], ob[0]);
        TEST_ASSERT_EQUAL_INT(oa[1], ob[1]);
        /* the contract: r8_recip's reciprocal, r8_project's result */
        TEST_ASSERT_EQUAL_UINT(r8_recip(c.z, &ea), mb);
        TEST_ASSERT_EQUAL_INT(ea, eb);
        TEST_ASSERT_EQUAL_INT(r8_project(&p, &c, &oa[0], &oa[1]), rb);
        if (!rb) {
            TEST_ASSERT_EQUAL_INT(oa[0], ob[0]);
            TEST_ASSERT_EQUAL_INT(oa[1], ob[1]);
        }
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_trap);
    RUN_TEST(test_xform);
    RUN_TEST(test_project);
    return UNITY_END();
}
