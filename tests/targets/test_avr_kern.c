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
int r8k_cull_ref(const r8_s16 *n, const r8_s16 *v, const r8_vec3l *eye);
#define r8k_cull r8k_cull_ref
r8_u8 r8k_level_ref(const r8_s16 *n, const r8_vec3 *light, r8_s16 amb, r8_u8 colour);
#define r8k_level r8k_level_ref
int r8k_zsum_ref(const r8_s16 *verts, const r8_u8 *vi, r8_u8 n, const r8_s16 *row, r8_s32 *out);
#define r8k_zsum r8k_zsum_ref
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
#undef r8k_cull
#undef r8k_level
#undef r8k_zsum

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

/* ---- r8k_cull (ports/avr/facecull.S): v over a flash table of values
 * around the 16-bit range [-1023, 1023] (its edges included), n over one
 * of normal components in [-16384, 16384] (zeros included), eye random,
 * at its limits, or exactly 16 v (a zero dot product); every class of
 * result (-1, 0 with a zero sum, 0, 1) must be hit ---- */
#define KC_V1(i) (r8_s16)((((i) * 40503L + 12345L) % 2241L) - 1120L)
#define KC_N1(i) (r8_s16)((((i) * 25173L + 13849L) % 32769L) - 16384L)
#define KC_4(m, i) m(i), m(i + 1), m(i + 2), m(i + 3)
#define KC_16(m, i) KC_4(m, i), KC_4(m, i + 4), KC_4(m, i + 8), KC_4(m, i + 12)
#define KC_64(m, i) KC_16(m, i), KC_16(m, i + 16), KC_16(m, i + 32), KC_16(m, i + 48)
static const r8_s16 kc_verts[] R8_FLASH = {
    1023, -1023, 1023, 1024, -1024, 0, -1, 1, 1023, 1023, -1023, -1023,
    KC_64(KC_V1, 0), KC_64(KC_V1, 64), KC_64(KC_V1, 128), KC_64(KC_V1, 192)
};
static const r8_s16 kc_norms[] R8_FLASH = {
    16384, -16384, 16384, 0, 0, 0, -16384, 16384, -16384, 1, -1, 0,
    KC_64(KC_N1, 0), KC_64(KC_N1, 64), KC_64(KC_N1, 128), KC_64(KC_N1, 192)
};

static void test_cull_random(void)
{
    unsigned long i, hit[4] = {0, 0, 0, 0};
    unsigned nv = sizeof kc_verts / sizeof kc_verts[0] - 2u;
    unsigned nn = sizeof kc_norms / sizeof kc_norms[0] - 2u;
    for (i = 0; i < 20000; i++) {
        const r8_s16 *v = kc_verts + rndn(nv), *n = kc_norms + rndn(nn);
        r8_vec3l eye;
        r8_s32 *e = &eye.x;
        unsigned c = rndn(4), k;
        int ra, rr;
        for (k = 0; k < 3; k++) {
            r8_s16 vk = R8_RDS16(v + k);
            if (c == 0 && vk >= -1023 && vk <= 1023)
                e[k] = (r8_s32)vk * 16;                    /* eye = 16 v */
            else if (c == 1)
                e[k] = rndn(2) ? 16383 : -16383;
            else
                e[k] = rnds(-16383, 16383);
        }
        rr = r8k_cull_ref(n, v, &eye);
        ra = r8k_cull(n, v, &eye);
        if (ra != rr) {
            print_case("r8k_cull", i);
            unity_fail_int(__LINE__, "r8k_cull differs from the reference", (long)rr, (long)ra);
        }
        if (rr < 0)
            hit[0]++;
        else if (rr)
            hit[3]++;
        else if (c == 0)
            hit[1]++;
        else
            hit[2]++;
    }
    for (i = 0; i < 4; i++)
        if (hit[i] < 300)
            unity_fail_int(__LINE__, "r8k_cull: a class too rare", 300, (long)hit[i]);
}

/* ---- r8k_level (ports/avr/facelevel.S): n over kc_norms, the light's
 * components in [-16384, 16384] (or at its ends), ambient in [0, 16384]
 * and colour in [0, 255] (ends included); every class of the clamped
 * cosine (none, inside, clamped) must be hit ---- */
static void test_level_random(void)
{
    unsigned long i, hit[3] = {0, 0, 0};
    unsigned nn = sizeof kc_norms / sizeof kc_norms[0] - 2u;
    for (i = 0; i < 20000; i++) {
        const r8_s16 *n = kc_norms + rndn(nn);
        r8_vec3 l;
        r8_s16 amb, *lp = &l.x;
        r8_u8 colour, ra, rr;
        r8_s32 d;
        unsigned k;
        for (k = 0; k < 3; k++)
            lp[k] = rndn(8) ? rnds(-16384, 16384) : (rndn(2) ? 16384 : -16384);
        k = rndn(8);
        amb = k == 0 ? 0 : (k == 1 ? R8_ONE14 : rnds(0, R8_ONE14));
        k = rndn(8);
        colour = (r8_u8)(k == 0 ? 0 : (k == 1 ? 255 : (k < 5 ? rndn(17) : rndn(256))));
        rr = r8k_level_ref(n, &l, amb, colour);
        ra = r8k_level(n, &l, amb, colour);
        if (ra != rr) {
            print_case("r8k_level", i);
            unity_fail_int(__LINE__, "r8k_level differs from the reference", (long)rr, (long)ra);
        }
        d = (r8_s32)R8_RDS16(n) * l.x + (r8_s32)R8_RDS16(n + 1) * l.y + (r8_s32)R8_RDS16(n + 2) * l.z;
        hit[d <= 0 ? 0 : (d >= (r8_s32)R8_ONE14 * (R8_ONE14 + 1) ? 2 : 1)]++;
    }
    for (i = 0; i < 3; i++)
        if (hit[i] < 1000)
            unity_fail_int(__LINE__, "r8k_level: a class too rare", 1000, (long)hit[i]);
}

/* ---- r8k_zsum (ports/avr/facez.S): the vertex table the program's own
 * code (arbitrary words: sums past 16 bits) or kc_verts (small), n 1..4,
 * indices 0..255 (code) or within kc_verts, row entries Q1.14; the
 * result and *out compared (out left as it was on 0); both classes of
 * result must be hit ---- */
static void test_zsum_random(void)
{
    unsigned long i, hit[2] = {0, 0};
    for (i = 0; i < 20000; i++) {
        int code = rndn(3) == 0;
        const r8_s16 *verts = code ? (const r8_s16 *)(2u * rndn(((unsigned)_etext - 1600u) / 2u)) : kc_verts;
        unsigned nv = code ? 256u : (unsigned)(sizeof kc_verts / sizeof kc_verts[0] / 3u), k;
        r8_u8 vi[4], n = (r8_u8)(1 + rndn(4));
        r8_s16 row[3];
        r8_s32 oa = 0x5A5A5A5AL, orf = 0x5A5A5A5AL;
        int ra, rr;
        for (k = 0; k < 4; k++)
            vi[k] = (r8_u8)rndn(nv);
        for (k = 0; k < 3; k++)
            row[k] = rndn(4) ? rnds(-16384, 16384) : (rndn(2) ? 16384 : -16384);
        rr = r8k_zsum_ref(verts, vi, n, row, &orf);
        ra = r8k_zsum(verts, vi, n, row, &oa);
        if (ra != rr || oa != orf) {
            print_case("r8k_zsum", i);
            unity_fail_int(__LINE__, "r8k_zsum differs from the reference", (long)orf, (long)oa);
        }
        hit[rr ? 1 : 0]++;
    }
    if (hit[0] < 300 || hit[1] < 3000)
        unity_fail_int(__LINE__, "r8k_zsum: a class too rare", (long)hit[0], (long)hit[1]);
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
    RUN_TEST(test_cull_random);
    RUN_TEST(test_level_random);
    RUN_TEST(test_zsum_random);
    return UNITY_END();
}
