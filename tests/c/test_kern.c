/* test_kern.c - the kernels of r8kern.h: the library's (a port's
 * assembly where it defines R8_ASM_TRAP / R8_ASM_XFORM / R8_ASM_PROJECT /
 * R8_ASM_EDGE,
 * ports/6502/ assembly) against the C89 references of src/kern.c, compiled in
 * here under other names, on random inputs; both against a plain model
 * of each contract too (so the test means something where the two are
 * the same C). */
#include "unity.h"
#include "r8kern.h"
#include "r8fb.h"
#include <string.h>

/* src/kern.c's C versions as ref_*, whatever this build links */
#undef R8_ASM_TRAP
#undef R8_ASM_XFORM
#undef R8_ASM_PROJECT
#undef R8_ASM_EDGE
#undef R8_ASM_FILL
#undef R8_ASM_CULL
#undef R8_ASM_LEVEL
#undef R8_ASM_ZSUM
#define r8k_zsum ref_zsum
int ref_zsum(const r8_s16 *verts, const r8_u8 *vi, r8_u8 n, const r8_s16 *row, r8_s32 *out);
#define r8k_cull ref_cull
#define r8k_level ref_level
#define r8k_trap ref_trap
#define r8k_xform ref_xform
#define r8k_project ref_project
#define r8k_edge ref_edge
#define r8k_fill ref_fill
#define r8k_fwalk ref_fwalk            /* (tested on AVR: test_avr_kern.c) */
#define r8k_fwpaint ref_fwpaint
void ref_fwpaint(void);
#define r8_tf_vertex ref_tf_vertex
void ref_tf_vertex(struct r8_state *st, const struct r8_objx *o, const r8_s16 *mv, r8_u16 g);
void ref_tf_vertex(struct r8_state *st, const struct r8_objx *o, const r8_s16 *mv, r8_u16 g)
{
    (void)st; (void)o; (void)mv; (void)g;
}
#include "../../src/kern.c"
#undef r8k_fwalk
#undef r8k_fwpaint
#undef r8_tf_vertex
#undef r8k_trap
#undef r8k_xform
#undef r8k_project
#undef r8k_edge
#undef r8k_fill
#undef r8k_cull
#undef r8k_level
#undef r8k_zsum
int ref_zsum(const r8_s16 *verts, const r8_u8 *vi, r8_u8 n, const r8_s16 *row, r8_s32 *out);
int ref_cull(const r8_s16 *n, const r8_s16 *v, const r8_vec3l *eye);
r8_u8 ref_level(const r8_s16 *n, const r8_vec3 *light, r8_s16 amb, r8_u8 colour);
void ref_fill(r8_u8 *p, r8_u8 v, unsigned n);
r8_s16 ref_edge(r8_interp *it, const r8_s16 *a, const r8_s16 *b);
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

/* The vertices r8k_xform reads: in R8_FLASH, as the contract says (on
 * AVR the kernel reads them with LPM).  A fixed mix of the classes
 * the random test draws: the extremes, any, a byte, 0 and +-1, +-2000. */
static const r8_s16 vt_kern[3 * 64] R8_FLASH = {
    -32767 - 1, 32767, -32767 - 1, 32767, -32767 - 1, -32767 - 1, 32767, 32767,
    32767, -1, 0, 1, 23447, 367, -5755, 1331,
    1373, 1, -111, -658, -1, -1, 1523, 53,
    -275, 1, 0, 27, -1, 1145, 97, -1819,
    -1881, -29, 1, -1, 1, -215, -1734, 1,
    -14, -1024, -28607, -767, -22158, 68, 1, -71,
    25106, -31, 0, -175, 12, -37, 2231, -761,
    -39, 117, 0, -1084, -27044, 0, -88, 0,
    387, 71, 758, 11, 466, -1743, 122, 1678,
    -1444, 217, 1, 6, 97, 21649, -32398, 193,
    -26140, -1, -73, 1413, -1430, 1530, 1172, -595,
    1, -267, 1, -7, 1, -7134, -1898, 6066,
    1486, 20, -26708, 4651, 116, 56, 1766, 51,
    -88, 90, -79, 0, -167, 8, -1, -5297,
    497, 1583, 1568, -93, 1265, -25527, 0, 0,
    1110, 16, 847, 1, 78, 0, 619, 0,
    0, 1495, 405, -1657, 1, 1730, 84, 7362,
    10179, -1, 499, 0, -5, 29, -25780, -91,
    -1215, 1747, 18675, 45, 39, -26197, 15199, -671,
    -48, 12504, -113, -1, -201, -1, 99, 497,
    959, 474, 53, 1368, 1, -410, -79, 626,
    -107, -31, 1992, 1, 1933, -25974, 31, -103,
    -77, -1, -1, 449, -1682, -1, -1334, 79,
    1854, -1, -38, -1373, 1970, 19215, -1960, 22629,
};

static void test_xform(void)
{
    unsigned i, j;
    for (i = 0; i < 1500; i++) {
        r8_mat3 m;
        r8_vec3l t, oa, ob;
        const r8_s16 *v = &vt_kern[3 * rndn(64)];
        r8_s16 x, y, z;                      /* v as read from flash */
        r8_s32 s;
        for (j = 0; j < 9; j++) {
            m.m[j] = (r8_s16)((r8_s16)rndn(32769u) - 16384);
            if (!rndn(4))
                m.m[j] = (r8_s16)(rndn(3) ? 0 : (rndn(2) ? 16384 : -16384));
        }
        x = R8_RDS16(&v[0]);
        y = R8_RDS16(&v[1]);
        z = R8_RDS16(&v[2]);
        t.x = (r8_s32)(r8_s16)rnd16() * 4096L + (r8_s32)rnd16();
        t.y = (r8_s32)(r8_s16)rnd16() * 16L;
        t.z = (r8_s32)(r8_s16)rnd16();
        ref_xform(&m, &t, v, &oa);
        r8k_xform(&m, &t, v, &ob);
        TEST_ASSERT_EQUAL_INT32(oa.x, ob.x);
        TEST_ASSERT_EQUAL_INT32(oa.y, ob.y);
        TEST_ASSERT_EQUAL_INT32(oa.z, ob.z);
        s = mul32(m.m[0], x) + mul32(m.m[1], y) + mul32(m.m[2], z) + 512;
        TEST_ASSERT_EQUAL_INT32(R8_ASR32C(s, 10) + t.x, ob.x);
        s = mul32(m.m[6], x) + mul32(m.m[7], y) + mul32(m.m[8], z) + 512;
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

/* ---- r8k_edge: classes of edges as tests/targets/test_avr_kern.c
 * draws them (a[1] < b[1], the contract); the return value and all of
 * *it (left as it was on R8_EDGE_WIDE) */
#define EDGE_CASES 4000
static r8_u32 erng = 0x2545F491UL;
static r8_u32 ernd(void)
{
    erng ^= erng << 13;
    erng ^= erng >> 17;
    erng ^= erng << 5;
    return erng;
}
static unsigned erndn(unsigned n) { return (unsigned)(ernd() % n); }
static r8_s16 ernds(r8_s16 lo, r8_s16 hi)   /* lo..hi */
{
    return (r8_s16)((unsigned)lo + erndn((unsigned)hi - (unsigned)lo + 1u));
}
static r8_s16 eclamp16(r8_s32 v)
{
    if (v > 32767L)
        return 32767;
    if (v < -32768L)
        return (r8_s16)(-32767 - 1);
    return (r8_s16)v;
}

static void rnd_edge(r8_s16 *a, r8_s16 *b)
{
    unsigned c = erndn(16);
    r8_s32 ay, dy, ax, dx;
    if (c < 11)
        ay = ernds(-300, 1300);
    else if (c < 13)
        ay = ernds(32744, 32766);           /* y0 = 2048 past 32760 */
    else if (c < 14)
        ay = ernds((r8_s16)(-32767 - 1), -32700);
    else
        ay = (r8_s16)ernd();
    c = erndn(16);
    if (c < 3)
        dy = 1;
    else if (c < 7)
        dy = 1 + erndn(48);
    else if (c < 12)
        dy = 1 + erndn(1423);
    else if (c < 15)
        dy = 1414 + erndn(20);              /* the 1424 limit */
    else
        dy = 1 + (r8_s32)(ernd() & 0x7FFF);
    c = erndn(16);
    if (c < 9)
        ax = ernds(-400, 2400);
    else if (c < 12)
        ax = (c & 1 ? -16384 : 16383) + ernds(-3, 3);
    else if (c < 15)
        ax = ernds(-16384, 16383);
    else
        ax = (r8_s16)ernd();
    c = erndn(16);
    if (c < 2) {
        dx = 0;
    } else if (c < 8) {
        dx = ernds(-40, 40) + (r8_s32)ernds(-3, 3) * dy;
    } else if (c < 10) {
        /* |q| near 2048: short rows */
        dy = 1 + erndn(7);
        ax = ernds(-1500, 1500);
        dx = 2048L * dy + ernds((r8_s16)(-dy - 2), (r8_s16)(dy + 2));
        if (erndn(2))
            dx = -dx;
    } else if (c < 11) {
        /* s0 >= 12, q near +-2048, ax far out on the same side */
        ay = (ay & ~15L) + 9 + erndn(4);
        dy = 1;
        ax = 9400 + erndn(4600);
        dx = 1950 + erndn(98);
        if (erndn(2)) {
            ax = -ax;
            dx = -dx;
        }
    } else if (c < 15) {
        dx = ernds(-16000, 16000);
    } else {
        dx = (r8_s16)ernd() - ax;
    }
    if (ay + dy > 32767L)
        dy = 32767L - ay;
    a[0] = (r8_s16)ax;
    a[1] = (r8_s16)ay;
    b[0] = eclamp16(ax + dx);
    b[1] = (r8_s16)(ay + dy);
    if (a[1] >= b[1]) {
        b[1] = (r8_s16)(a[1] + 1);
        if (a[1] == 32767) {
            a[1] = 32766;
            b[1] = 32767;
        }
    }
}

static void test_edge(void)
{
    static r8_s16 a[2], b[2];
    static r8_interp ia, ir;
    unsigned i, n_wdy = 0, n_wx = 0, n_wq = 0, n_neg = 0, n_dx0 = 0, n_dy1 = 0,
        n_steep = 0, n_ytop = 0, n_q0 = 0;
    for (i = 0; i < EDGE_CASES; i++) {
        r8_s16 ya, yr;
        rnd_edge(a, b);
        memset(&ia, (int)(i & 0xFF), sizeof ia);
        memset(&ir, (int)(i & 0xFF), sizeof ir);
        yr = ref_edge(&ir, a, b);
        ya = r8k_edge(&ia, a, b);
        TEST_ASSERT_EQUAL_INT16(yr, ya);
        TEST_ASSERT_EQUAL_INT16(ir.val, ia.val);
        TEST_ASSERT_EQUAL_INT16(ir.q, ia.q);
        TEST_ASSERT_EQUAL_UINT16(ir.err, ia.err);
        TEST_ASSERT_EQUAL_UINT16(ir.r, ia.r);
        TEST_ASSERT_EQUAL_UINT16(ir.den, ia.den);
        if (yr == R8_EDGE_WIDE) {
            if ((r8_u16)(b[1] - a[1]) >= 1424u)
                n_wdy++;
            else if (a[0] < -16384 || a[0] > 16383 || b[0] < -16384 || b[0] > 16383)
                n_wx++;
            else
                n_wq++;
            continue;
        }
        /* the contract: the first row's column and the step */
        TEST_ASSERT_EQUAL_UINT16((r8_u16)((r8_u16)b[1] - (r8_u16)a[1]), ir.den);
        TEST_ASSERT(ir.err < ir.den && ir.r < ir.den);
        n_neg += b[0] < a[0];
        n_dx0 += b[0] == a[0];
        n_dy1 += ir.den == 1;
        n_steep += ir.q >= 1900 || ir.q <= -1900;
        n_q0 += ir.q == 0 || ir.q == -1;
        n_ytop += a[1] > 32760;
    }
    TEST_ASSERT_GREATER_THAN(EDGE_CASES / 200, n_wdy);
    TEST_ASSERT_GREATER_THAN(EDGE_CASES / 200, n_wx);
    TEST_ASSERT_GREATER_THAN(EDGE_CASES / 200, n_wq);
    TEST_ASSERT_GREATER_THAN(EDGE_CASES / 10, n_neg);
    TEST_ASSERT_GREATER_THAN(EDGE_CASES / 100, n_dx0);
    TEST_ASSERT_GREATER_THAN(EDGE_CASES / 100, n_dy1);
    TEST_ASSERT_GREATER_THAN(EDGE_CASES / 200, n_steep);
    TEST_ASSERT_GREATER_THAN(EDGE_CASES / 100, n_q0);
    TEST_ASSERT_GREATER_THAN(EDGE_CASES / 200, n_ytop);
}

/* r8k_fill: the library's (fill.S on AVR) against the reference and a
 * plain loop, lengths 0..300 at random offsets, the bytes around kept */
static void test_fill(void)
{
    static r8_u8 a[340], b[340], c[340];
    unsigned i, j;
    for (i = 0; i < 400; i++) {
        unsigned n = rndn(i < 40 ? 40 : 301), off = 8u + rndn(24);
        r8_u8 v = (r8_u8)rnd16();
        for (j = 0; j < sizeof a; j++)
            a[j] = b[j] = c[j] = (r8_u8)(j * 151u + i);
        r8k_fill(a + off, v, n);
        ref_fill(b + off, v, n);
        for (j = 0; j < n; j++)
            c[off + j] = v;
        TEST_ASSERT_EQUAL_MEMORY(c, a, sizeof a);
        TEST_ASSERT_EQUAL_MEMORY(c, b, sizeof b);
    }
}

/* ---- r8k_cull and r8k_level: the library's and the reference against
 * plain 32-bit models (r8_cull_front's 16-bit test; r8_face_level's
 * (r8_tf_shade(n, light, colour) + 128) >> 8, step by step).  n and v
 * from flash tables: v around the 16-bit range [-1023, 1023] (its ends
 * included), n in [-16384, 16384] (after the edge cases, 64 values of
 * ((40503 i + 12345) mod 2241) - 1120 and ((25173 i + 13849) mod 32769)
 * - 16384). */
static const r8_s16 kv_tab[] R8_FLASH = {
    1023, -1023, 1023, 1024, -1024, 0, -1, 1, 1023, 1023, -1023, -1023,
    20, 185, 350, 515, 680, 845, 1010, -1066, -901, -736,
    -571, -406, -241, -76, 89, 254, 419, 584, 749, 914,
    1079, -997, -832, -667, -502, -337, -172, -7, 158, 323,
    488, 653, 818, 983, -1093, -928, -763, -598, -433, -268,
    -103, 62, 227, 392, 557, 722, 887, 1052, -1024, -859,
    -694, -529, -364, -199, -34, 131, 296, 461, 626, 791,
    956, -1120, -955, -790
};
static const r8_s16 kn_tab[] R8_FLASH = {
    16384, -16384, 16384, 0, 0, 0, -16384, 16384, -16384, 1, -1, 0,
    -2535, -10131, 15042, 7446, -150, -7746, -15342, 9831, 2235, -5361,
    -12957, 12216, 4620, -2976, -10572, 14601, 7005, -591, -8187, -15783,
    9390, 1794, -5802, -13398, 11775, 4179, -3417, -11013, 14160, 6564,
    -1032, -8628, -16224, 8949, 1353, -6243, -13839, 11334, 3738, -3858,
    -11454, 13719, 6123, -1473, -9069, 16104, 8508, 912, -6684, -14280,
    10893, 3297, -4299, -11895, 13278, 5682, -1914, -9510, 15663, 8067,
    471, -7125, -14721, 10452
};

static int cull_model(const r8_s16 *n, const r8_s16 *v, const r8_vec3l *eye)
{
    const r8_s32 *e = &eye->x;
    r8_s32 dot = 0;
    unsigned k;
    for (k = 0; k < 3; k++) {
        r8_s16 x = R8_RDS16(v + k);
        if (x < -1023 || x > 1023)
            return -1;
    }
    for (k = 0; k < 3; k++)
        dot += mul32(R8_RDS16(n + k), (r8_s16)(e[k] - 16L * R8_RDS16(v + k)));
    return dot > 0;
}

static r8_u8 level_model(const r8_s16 *n, const r8_vec3 *l, r8_s16 amb, r8_u8 colour)
{
    r8_s32 d = mul32(R8_RDS16(n), l->x) + mul32(R8_RDS16(n + 1), l->y) + mul32(R8_RDS16(n + 2), l->z);
    r8_s16 i = 0;
    r8_u32 p;
    if (d > 0) {
        i = (r8_s16)R8_SHR14U(d);
        if (i > R8_ONE14)
            i = R8_ONE14;
    }
    p = (r8_u32)mul32((r8_s16)(R8_ONE14 - amb), i);
    p = (r8_u16)(amb + R8_SHR14U(p));
    p *= (r8_u16)((r8_u16)colour << 8);
    return (r8_u8)(((r8_s16)R8_SHR14U(p + 8192u) + 128) >> 8);
}

static void test_cull(void)
{
    unsigned i, k, nv = sizeof kv_tab / sizeof kv_tab[0] - 2u, nn = sizeof kn_tab / sizeof kn_tab[0] - 2u;
    unsigned hit[3] = {0, 0, 0};
    for (i = 0; i < 3000; i++) {
        const r8_s16 *v = kv_tab + rndn(nv), *n = kn_tab + rndn(nn);
        r8_vec3l eye;
        r8_s32 *e = &eye.x;
        unsigned c = rndn(4);
        int m;
        for (k = 0; k < 3; k++) {
            r8_s16 x = R8_RDS16(v + k);
            if (c == 0 && x >= -1023 && x <= 1023)
                e[k] = 16L * x;                     /* a zero dot product */
            else if (c == 1)
                e[k] = rndn(2) ? 16383 : -16383;
            else
                e[k] = (r8_s32)rndn(32767u) - 16383;
        }
        m = cull_model(n, v, &eye);
        TEST_ASSERT_EQUAL_INT(m, ref_cull(n, v, &eye));
        TEST_ASSERT_EQUAL_INT(m, r8k_cull(n, v, &eye));
        hit[m + 1]++;
    }
    TEST_ASSERT_GREATER_THAN(100, (int)hit[0]);     /* -1 */
    TEST_ASSERT_GREATER_THAN(100, (int)hit[1]);     /* 0 */
    TEST_ASSERT_GREATER_THAN(100, (int)hit[2]);     /* 1 */
}

static void test_level(void)
{
    unsigned i, k, nn = sizeof kn_tab / sizeof kn_tab[0] - 2u;
    for (i = 0; i < 3000; i++) {
        const r8_s16 *n = kn_tab + rndn(nn);
        r8_vec3 l;
        r8_s16 amb, *lp = &l.x;
        r8_u8 colour, m;
        for (k = 0; k < 3; k++)
            lp[k] = rndn(8) ? (r8_s16)((r8_s16)rndn(32769u) - 16384) : (rndn(2) ? 16384 : -16384);
        k = rndn(8);
        amb = (r8_s16)(k == 0 ? 0 : (k == 1 ? R8_ONE14 : rndn(16385u)));
        k = rndn(8);
        colour = (r8_u8)(k == 0 ? 0 : (k == 1 ? 255 : (k < 5 ? rndn(17) : rndn(256))));
        m = level_model(n, &l, amb, colour);
        TEST_ASSERT_EQUAL_UINT8(m, ref_level(n, &l, amb, colour));
        TEST_ASSERT_EQUAL_UINT8(m, r8k_level(n, &l, amb, colour));
    }
}

/* ---- r8k_zsum: over vt_kern's 64 vertices (extremes: sums past 16
 * bits) and kv_tab's 25 (small), n 1..4, row entries Q1.14; against a
 * plain model (exact sums, the 16-bit test, the product row, floor) */
static int zsum_model(const r8_s16 *verts, const r8_u8 *vi, r8_u8 n, const r8_s16 *row, r8_s32 *out)
{
    r8_s32 sum[3], dot = 0;
    unsigned k, j;
    for (j = 0; j < 3; j++) {
        sum[j] = 0;
        for (k = 0; k < n; k++)
            sum[j] += R8_RDS16(verts + 3u * vi[k] + j);
        if (sum[j] > 32767 || sum[j] < -32767)
            return 0;
    }
    for (j = 0; j < 3; j++)
        dot += mul32(row[j], (r8_s16)sum[j]);
    *out = R8_ASR32C(dot + 512, 10);
    return 1;
}

static void test_zsum(void)
{
    unsigned i, k, hit[2] = {0, 0};
    for (i = 0; i < 3000; i++) {
        int big = rndn(3) == 0;
        const r8_s16 *verts = big ? vt_kern : kv_tab;
        unsigned nv = big ? 64u : (unsigned)(sizeof kv_tab / sizeof kv_tab[0] / 3u);
        r8_u8 vi[4], n = (r8_u8)(1 + rndn(4));
        r8_s16 row[3];
        r8_s32 om = 0x5A5A5A5AL, orf = 0x5A5A5A5AL, ok = 0x5A5A5A5AL;
        int m;
        for (k = 0; k < 4; k++)
            vi[k] = (r8_u8)rndn((r8_u16)nv);
        for (k = 0; k < 3; k++)
            row[k] = rndn(4) ? (r8_s16)((r8_s16)rndn(32769u) - 16384) : (rndn(2) ? 16384 : -16384);
        m = zsum_model(verts, vi, n, row, &om);
        TEST_ASSERT_EQUAL_INT(m, ref_zsum(verts, vi, n, row, &orf));
        TEST_ASSERT_EQUAL_INT(m, r8k_zsum(verts, vi, n, row, &ok));
        TEST_ASSERT_EQUAL_INT32(om, orf);
        TEST_ASSERT_EQUAL_INT32(om, ok);
        hit[m]++;
    }
    TEST_ASSERT_TRUE(hit[0] > 100 && hit[1] > 1000);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_trap);
    RUN_TEST(test_xform);
    RUN_TEST(test_project);
    RUN_TEST(test_edge);
    RUN_TEST(test_fill);
#ifndef __SDCC   /* (R8_SDCC_FACE_KERN in r8kern.h: the Z80 renderer does not use them) */
    RUN_TEST(test_cull);
    RUN_TEST(test_level);
    RUN_TEST(test_zsum);
#endif
    return UNITY_END();
}
