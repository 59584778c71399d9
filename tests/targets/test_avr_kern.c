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
#include "r8int.h"                     /* (r8k_vertex's r8_state, r8_objx) */

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
r8_u8 r8k_fwalk_ref(r8_fwalk *w);
#define r8k_fwalk r8k_fwalk_ref
#define r8k_fwpaint r8k_fwpaint_ref        /* (the reference's stub) */
void r8k_fwpaint_ref(void);
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
#undef r8k_fwalk
#undef r8k_fwpaint

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

/* ---- r8k_trap's short calls (the renderer's: 1..3 rows, spans of 1..6
 * columns): every span width and column phase (xl & 3), each pattern
 * class (nibble F: set, 0: clear, others: dither; the high nibble
 * random), unclamped, clamped at 0 and at w, m one bit (page wraps
 * within the call) or any byte, every k ---- */
static void test_trap_short(void)
{
    unsigned rows, n, ph, cls, cm, k;
    unsigned long i = 0;
    for (rows = 1; rows <= 3; rows++)
        for (n = 1; n <= 6; n++)
            for (ph = 0; ph < 4; ph++)
                for (cls = 0; cls < 4; cls++)
                    for (cm = 0; cm < 3; cm++, i++) {
                        r8_trapfill ta, tr;
                        r8_interp la, lr_, ra, rr_;
                        r8_s16 w = (r8_s16)(24 + rndn(16));
                        unsigned off = rndn(256), len = GUARD + 2u * (unsigned)w + GUARD;
                        r8_u8 *wa = band_asm + off, *wr = band_ref + off, b = (r8_u8)rnd();
                        for (k = 0; k < len; k++) {
                            b = (r8_u8)(b + 151u);
                            wa[k] = b;
                        }
                        memcpy(wr, wa, len);
                        ta.page = wa + GUARD;
                        ta.m = (r8_u8)(rndn(4) ? 1u << rndn(8) : rnd());
                        ta.k = (r8_u8)rndn(4);
                        for (k = 0; k < 4; k++) {
                            r8_u8 hi = (r8_u8)(rnd() & 0xF0u), lo = (r8_u8)(1u + rndn(14));
                            if (cls == 0 || (cls == 3 && rndn(3) == 0))
                                lo = 0x0F;
                            else if (cls == 1 || (cls == 3 && rndn(2) == 0))
                                lo = 0x00;
                            ta.pat[k] = (r8_u8)(hi | lo);
                        }
                        ta.w = w;
                        rnd_interp(&la, w);
                        rnd_interp(&ra, w);
                        la.q = (r8_s16)rnds(-1, 1);
                        ra.q = (r8_s16)rnds(-1, 1);
                        if (cm == 0) {          /* [8 + ph, + n) */
                            la.val = (r8_s16)(8 + ph);
                            ra.val = (r8_s16)(la.val + n);
                        } else if (cm == 1) {   /* clamped to [0, n) */
                            la.val = (r8_s16)(-1 - (int)ph);
                            ra.val = (r8_s16)n;
                        } else {                /* clamped to [w - n, w) */
                            la.val = (r8_s16)(w - (r8_s16)n);
                            ra.val = (r8_s16)(w + 1 + (r8_s16)ph);
                        }
                        tr = ta;
                        tr.page = wr + GUARD;
                        lr_ = la;
                        rr_ = ra;
                        r8k_trap_ref(&tr, &lr_, &rr_, (r8_u16)rows);
                        r8k_trap(&ta, &la, &ra, (r8_u16)rows);
                        if (memcmp(wa - off, wr - off, off + len) != 0 || ta.page - wa != tr.page - wr ||
                            ta.m != tr.m || ta.k != tr.k || memcmp(&la, &lr_, sizeof la) != 0 ||
                            memcmp(&ra, &rr_, sizeof ra) != 0) {
                            print_case("r8k_trap short", i);
                            unity_fail_int(__LINE__, "r8k_trap differs from the reference", (long)n, (long)rows);
                        }
                    }
    unity_print("r8k_trap short: ");
    unity_print_long((long)i);
    unity_print(" cases\n");
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

/* model vertices whose x components (at fw_big + 0; z at + 1, y at + 2)
 * make depth sums past 16 bits and of -32768: 48 of them */
#define FW_BS(h) ((h) == 3 ? -16384 : (h) == 5 ? 16384 : (h) == 6 ? -32767 - 1 : (h) == 7 ? 24000 : (h) == 2)
#define FW_B1(i) (r8_s16)((i) % 3 ? KC_V1(i) : FW_BS(((i) * 11 + ((i) >> 3)) % 8))
static const r8_s16 fw_big[] R8_FLASH = {
    KC_64(FW_B1, 0), KC_64(FW_B1, 64), KC_16(FW_B1, 128), FW_B1(144), FW_B1(145)
};
/* the depth sums of verts[3 vi[k] ..] as r8k_zsum's and fwpaint.S's 16-bit
 * sums meet them: 0 plain, 1 a 16-bit overflow on the way and the exact
 * sums in [-32767, 32767], 2 the same out of it, 3 no overflow and a sum
 * of -32768 */
static unsigned zs_class(const r8_s16 *verts, const r8_u8 *vi, r8_u8 n)
{
    r8_u8 j, c, ov = 0, out = 0;
    for (c = 0; c < 3; c++) {
        r8_s32 t = 0, e = 0;
        for (j = 0; j < n; j++) {
            r8_s16 v = R8_RDS16(verts + 3u * vi[j] + c);
            e += v;
            t += v;
            if (t < -32768L || t > 32767L)
                ov = 1;
            if (t < -32768L)      /* t: the 16-bit sum, wrapped */
                t += 65536L;
            else if (t > 32767L)
                t -= 65536L;
        }
        out |= (r8_u8)(ov ? e < -32767L || e > 32767L : t == -32768L);
    }
    return ov ? (out ? 2u : 1u) : (out ? 3u : 0u);
}

/* ---- r8k_zsum (ports/avr/facez.S): the vertex table the program's own
 * code (arbitrary words: sums past 16 bits), fw_big + 0..2 or kc_verts
 * (small), n 1..4, indices 0..255 (code) or within the table, row
 * entries Q1.14; the result and *out compared (out left as it was on 0);
 * both results and every zs_class must be hit ---- */
static void test_zsum_random(void)
{
    unsigned long i, hit[6] = {0, 0, 0, 0, 0, 0};
    for (i = 0; i < 20000; i++) {
        unsigned src = rndn(6);
        int code = src < 2;
        const r8_s16 *verts = code ? (const r8_s16 *)(2u * rndn(((unsigned)_etext - 1600u) / 2u)) :
                              src < 4 ? fw_big + rndn(3) : kc_verts;
        unsigned nv = code ? 256u : src < 4 ? (unsigned)(sizeof fw_big / sizeof fw_big[0] / 3u) : (unsigned)(sizeof kc_verts / sizeof kc_verts[0] / 3u), k;
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
        hit[2 + zs_class(verts, vi, n)]++;
    }
    if (hit[0] < 300 || hit[1] < 3000)
        unity_fail_int(__LINE__, "r8k_zsum: a class too rare", (long)hit[0], (long)hit[1]);
    for (i = 2; i < 6; i++)
        if (hit[i] < 100)
            unity_fail_int(__LINE__, "r8k_zsum: a zs_class too rare", (long)i - 2, (long)hit[i]);
}

/* ---- r8k_fwalk (ports/avr/fwalk.S): walks over a flash table of faces
 * (n mostly 3 or 4, also 0, 2 and 5; indices 0..63), with and without
 * the cull (normals over kc_norms, model vertices over kc_verts, eye
 * random), over 64 screen vertices of 4 or 8 bytes: in the frame, far
 * out, at the 16-bit limits, x in [-32766, -32513] (ordinary), -32767
 * (to transform: r8_tf_vertex below, which writes new values, sometimes
 * -32768) and -32768 (the clipper's).  Every call of a walk to its end
 * is compared (return, f, top, bot), the vertices after it, and the
 * order of r8_tf_vertex's calls (their mv, g and o checked); with bsh >= 0 (faces put in band
 * buckets: 8- or 16-bit ids, slots or none) also the buckets, links,
 * slots and npoly; with bsh < 0, half the time painter's (pk: faces put
 * in depth buckets, ftop or none): the buckets, links, slots and ftop
 * too, keys 0, 63 and between each hit in 50 walks; half the painter's
 * walks over fw_big, whose x components make the depth sums of
 * fwpaint.S's every path (a 16-bit overflow on the way, the exact sums
 * then in range or not; -32768 without one), each walked over 100
 * times; each outcome must be hit ---- */
#define FW_NV 48
#define FW_NI(i, j) (((i) * 37 + (j) * 13 + ((i) >> 2) * 7 + 5) % FW_NV)
#define FW_N(i) ((i) % 16 == 6 ? 2 : (i) % 16 == 11 ? 5 : (i) % 16 == 15 ? 0 : 3 + ((i) * 5 % 3 != 0))
#define FW_F(i) {FW_N(i), 0, {FW_NI(i, 0), FW_NI(i, 1), FW_NI(i, 2), FW_NI(i, 3)}}
static const r8_face fw_faces[] R8_FLASH = {
    KC_64(FW_F, 0), KC_16(FW_F, 64), KC_16(FW_F, 80)
};
static r8_s16 fw_tf[FW_NV][2];        /* what r8_tf_vertex writes */
#define FW_NID 96                     /* face ids: fbase < 32, f < 64 */
/* the heads (64 keys) and ftop in band_ref, the vertices, links and
 * slots in band_asm (the test's statics fill the 1284P's SRAM: the
 * stack needs the room; the walk test uses neither band otherwise) */
static r8_s16 (*fw_sv)[FW_NV * 4];
static r8_u16 (*fw_next)[FW_NID];
static r8_u8 (*fw_slot)[FW_NID];
static r8_u16 (*fw_heads)[64];
static r8_u8 (*fw_ftop)[FW_NID];
static r8_fwpk fw_pk[2];               /* painter's keys (one per walk) */
static r8_s16 fw_row[3];
static unsigned long fw_keys[3];       /* painter's keys: 0, 1..62, 63 */
static unsigned long fw_cls[5];        /* faces walked over fw_big, by zs_class (4: n not 3, 4) */
static r8_u8 fw_log[2][FW_NV + 1], fw_nlog[2], fw_run;
static unsigned long fw_calls;
/* r8k_fwalk's st is vx_st here (with vsh 2 and Gouraud, so that fwalk.S's
 * call of r8k_vertex, vertex.S, hands it on to r8_tf_vertex below unchanged);
 * the walk is fw_cur; o is fw_o */
static const char fw_o[1];
static r8_fwalk *fw_cur;
static r8_state vx_st;                 /* (the r8k_vertex test's) */
static unsigned vx_mode;
static void vx_tf(r8_state *st, const r8_objx *o, const r8_s16 *mv, r8_u16 g);
void r8_tf_vertex(struct r8_state *st, const struct r8_objx *o, const r8_s16 *mv, r8_u16 g)
{
    r8_fwalk *w = fw_cur;
    r8_u8 i;
    if (vx_mode) {
        vx_tf(st, o, mv, g);          /* the r8k_vertex test */
        return;
    }
    i = (r8_u8)(g - w->vbase);
    if ((r8_u16)(g - w->vbase) < FW_NV && mv == w->verts + 3u * i && (const void *)o == (const void *)fw_o &&
        st == &vx_st) {
        r8_s16 *v = (r8_s16 *)w->base + ((unsigned)i << w->vsh);
        v[0] = fw_tf[i][0];
        v[1] = fw_tf[i][1];
    } else {
        i = 0xEE;                     /* (the logs then differ) */
    }
    if (fw_nlog[fw_run] < FW_NV + 1)
        fw_log[fw_run][fw_nlog[fw_run]++] = (r8_u8)(i + fw_run * (i == 0xEE));
    fw_calls++;
}
static r8_s16 fw_coord(unsigned c, int y)
{
    if (c == 0)
        return rndn(2) ? rnds(32700, 32767) : rnds(-32766, -32700);
    if (c == 1)
        return rnds(-32767, 32767);
    if (c == 2 && !y)
        return rnds(-32766, -32513);      /* high byte 0x80, not a mark */
    return y ? rnds(-400, 1400) : rnds(-600, 2600);
}
static void test_fwalk_random(void)
{
    unsigned long i, hit[4] = {0, 0, 0, 0};
    fw_heads = (r8_u16 (*)[64])(void *)band_ref;
    fw_ftop = (r8_u8 (*)[FW_NID])(void *)(band_ref + sizeof(r8_u16[2][64]));
    fw_sv = (r8_s16 (*)[FW_NV * 4])(void *)band_asm;
    fw_next = (r8_u16 (*)[FW_NID])(void *)(band_asm + sizeof(r8_s16[2][FW_NV * 4]));
    fw_slot = (r8_u8 (*)[FW_NID])(void *)(band_asm + sizeof(r8_s16[2][FW_NV * 4]) + sizeof(r8_u16[2][FW_NID]));
    for (i = 0; i < 1500; i++) {
        r8_fwalk w[2];
        r8_vec3l eye;
        r8_s32 *e = &eye.x;
        unsigned k, nf = 1 + rndn(64), off = rndn(sizeof fw_faces / sizeof fw_faces[0] - nf + 1);
        unsigned marks = rndn(3), nr = 0, c;
        r8_u16 npoly0;
        r8_u8 vsh = (r8_u8)(1 + rndn(2)), r[2];
        for (k = 0; k < FW_NV; k++) {
            r8_s16 *v = fw_sv[0] + (k << vsh);
            unsigned c = rndn(16);
            v[0] = fw_coord(rndn(8), 0);
            v[1] = fw_coord(rndn(8), 1);
            if (c < marks)
                v[0] = -32767;                /* to transform */
            else if (c == 3 && marks == 2)
                v[0] = -32767 - 1;            /* the clipper's */
            fw_tf[k][0] = rndn(24) ? fw_coord(rndn(8), 0) : -32767 - 1;
            fw_tf[k][1] = fw_coord(rndn(8), 1);
        }
        memcpy(fw_sv[1], fw_sv[0], sizeof fw_sv[0]);
        c = rndn(2);                  /* eye at its limits: sums past 2^30 */
        for (k = 0; k < 3; k++)
            e[k] = c ? rnds(-16383, 16383) : (rndn(2) ? 16383 : -16383);
        w[0].base = fw_sv[0];
        w[0].faces = fw_faces + off;
        w[0].normals = rndn(4) ? kc_norms + 3u * rndn(24) : 0;
        w[0].verts = kc_verts;
        w[0].eye = &eye;
        w[0].f = (r8_u16)nf;
        w[0].w = rndn(8) ? 128 : rnds(1, 200);
        w[0].h = rndn(8) ? 64 : rnds(1, 100);
        w[0].top = w[0].bot = 0x5A5A;
        w[0].vsh = vsh;
        w[0].o = fw_o;
        w[0].vbase = (r8_u16)rnd();
        /* the buckets: 16- or 8-bit ids, bands of 8 to 32 rows in at most
         * 64, with pool slots or none; or faces handed back */
        w[0].bsh = (r8_s8)(rndn(3) ? (int)(3 + rndn(3)) : -1);
        if (w[0].bsh >= 0)
            w[0].h = rndn(4) ? 64 : rnds(1, 64);
        w[0].fid8 = (r8_u8)rndn(2);
        w[0].fbase = (r8_u16)rndn(FW_NID - 64 + 1);
        w[0].npoly = npoly0 = (r8_u16)rnd();
        for (k = 0; k < 64; k++)
            fw_heads[0][k] = (r8_u16)rnd();
        for (k = 0; k < FW_NID; k++) {
            fw_next[0][k] = (r8_u16)rnd();
            fw_slot[0][k] = (r8_u8)rnd();
            fw_ftop[0][k] = (r8_u8)rnd();
        }
        memcpy(fw_heads[1], fw_heads[0], sizeof fw_heads[0]);
        memcpy(fw_next[1], fw_next[0], sizeof fw_next[0]);
        memcpy(fw_slot[1], fw_slot[0], sizeof fw_slot[0]);
        memcpy(fw_ftop[1], fw_ftop[0], sizeof fw_ftop[0]);
        /* painter's (bsh < 0, half the time): z sums within about
         * +-220000 (sums of up to 4 vertices, rows Q1.14) against zc
         * and zr that put them below, in and past the 64 keys; kmul
         * near 64 2^16 / zr (n 3) or a quarter of it (n 4), sometimes
         * any 32 bits (the product wraps) */
        w[0].pk = 0;
        w[0].paint = 0;
        if (w[0].bsh < 0 && rndn(2)) {
            for (k = 0; k < 2; k++) {
                r8_s32 zr = (r8_s32)(1 + rnd() % 400000UL);
                r8_u32 km = (r8_u32)(64UL * 65536UL / (r8_u32)zr);
                km = km / 2u + rnd() % (km + 1u);
                if (k)
                    km /= 4u;
                if (!rndn(8))
                    km = (rnd() << 8) ^ rnd();
                fw_pk[0].k[3 * k] = (r8_s32)(rnd() % 500000UL) - 250000L;
                fw_pk[0].k[3 * k + 1] = zr;
                fw_pk[0].k[3 * k + 2] = (r8_s32)km;
            }
            for (k = 0; k < 3; k++)
                fw_row[k] = rndn(4) ? rnds(-16384, 16384) : (rndn(2) ? 16384 : -16384);
            w[0].pk = &fw_pk[0];
            w[0].paint = r8k_fwpaint;
            if (rndn(2)) {            /* sums past 16 bits (no cull: its -1) */
                c = rndn(3);
                w[0].verts = fw_big + c;
                w[0].normals = 0;
                for (k = 0; k < nf; k++) {
                    const r8_face *fc = &fw_faces[off + k];
                    r8_u8 vi[4], j, n = R8_RDU8(&fc->n);
                    for (j = 0; j < 4; j++)
                        vi[j] = R8_RDU8(&fc->v[j]);
                    fw_cls[n < 3 || n > 4 ? 4 : zs_class(fw_big + c, vi, n)]++;
                }
            }
            fw_pk[0].row = fw_row;
            fw_pk[0].fbsh = (r8_s8)rndn(6);
        }
        fw_pk[0].ftop = rndn(2) ? fw_ftop[0] : 0;
        fw_pk[1] = fw_pk[0];
        fw_pk[1].ftop = fw_pk[0].ftop ? fw_ftop[1] : 0;
        if (w[0].pk)                  /* heads >= 0xA0 (ids are below 96) */
            for (k = 0; k < sizeof fw_heads[0]; k++)
                ((r8_u8 *)fw_heads[0])[k] = (r8_u8)(0xA0 + rndn(0x60));
        memcpy(fw_heads[1], fw_heads[0], sizeof fw_heads[0]);
        w[1] = w[0];
        w[0].heads = fw_heads[0];
        w[0].next = fw_next[0];
        w[0].slot = rndn(3) ? fw_slot[0] : 0;
        w[1].heads = fw_heads[1];
        w[1].next = fw_next[1];
        w[1].slot = w[0].slot ? fw_slot[1] : 0;
        if (w[0].pk)
            w[1].pk = &fw_pk[1];
        w[1].base = fw_sv[1];
        vx_st.vsh = 2;
        vx_st.attrs = R8_ATTR_S;     /* (Gouraud: r8k_vertex hands every call on) */
        w[0].st = &vx_st;
        w[1].st = &vx_st;
        fw_nlog[0] = fw_nlog[1] = 0;
        do {                          /* the two walks in step */
            fw_run = 0;
            fw_cur = &w[0];
            r[0] = r8k_fwalk_ref(&w[0]);
            fw_run = 1;
            fw_cur = &w[1];
            r[1] = r8k_fwalk(&w[1]);
            if (r[0] != r[1] || w[0].f != w[1].f || w[0].top != w[1].top || w[0].bot != w[1].bot ||
                w[0].npoly != w[1].npoly || memcmp(fw_heads[0], fw_heads[1], sizeof fw_heads[0]) ||
                memcmp(fw_next[0], fw_next[1], sizeof fw_next[0]) || memcmp(fw_slot[0], fw_slot[1], sizeof fw_slot[0]) ||
                memcmp(fw_ftop[0], fw_ftop[1], sizeof fw_ftop[0]) ||
                memcmp(fw_sv[0], fw_sv[1], sizeof fw_sv[0]) || fw_nlog[0] != fw_nlog[1] ||
                memcmp(fw_log[0], fw_log[1], fw_nlog[0])) {
                print_case("r8k_fwalk", i);
                unity_fail_int(__LINE__, "r8k_fwalk differs from the reference", (long)r[0], (long)r[1]);
                return;
            }
            if (r[0])
                hit[r[0] == 1 ? 0 : 1]++;
            if (!r[0])
                hit[0] += (r8_u16)(w[0].npoly - npoly0);   /* put in a bucket */
            nr++;
        } while (r[0] && nr <= nf);
        hit[3] += nf - (nr - 1u) - (r8_u16)(w[0].npoly - npoly0);   /* skipped inside */
        if (w[0].pk)
            for (k = 0; k < 64; k++)
                if (w[0].fid8 ? ((r8_u8 *)fw_heads[0])[k] < 0xA0 : fw_heads[0][k] < 0xA0A0u)
                    fw_keys[k == 0 ? 0 : k == 63 ? 2 : 1]++;
    }
    for (i = 0; i < 3; i++)
        if (fw_keys[i] < 50)
            unity_fail_int(__LINE__, "r8k_fwalk: a painter's key class too rare", 50, (long)fw_keys[i]);
    for (i = 0; i < 4; i++)
        if (fw_cls[i] < 100)
            unity_fail_int(__LINE__, "r8k_fwalk: a depth sum class too rare", 100, (long)fw_cls[i]);
    hit[2] = fw_calls;
    for (i = 0; i < 4; i++)
        if (hit[i] < 1000)
            unity_fail_int(__LINE__, "r8k_fwalk: an outcome too rare", 1000, (long)hit[i]);
}
static void test_estart_random(void);
static void test_scanband_random(void);

/* ---- r8k_vertex (ports/avr/vertex.S) against r8_tf_vertex for vsh 1
 * (the references r8k_xform_ref, the near test, r8k_project_ref, as
 * r8_tf_camera does them), on camera points chosen as the r8k_project
 * test chooses them (t is set so that the vertex lands there), model
 * vertices small (the kernel's rows), extreme and arbitrary (handed on),
 * znear around the point, and vsh 2 now and then: every entry of sv
 * around the vertex is compared; a call handed on to r8_tf_vertex (the
 * reference here: vx_tf) must carry st, o, mv and g unchanged.  Each
 * outcome must be hit: projected, behind the near plane and outside the
 * guard band by the kernel itself, and handed on ---- */
#ifndef VX_CASES
#define VX_CASES 8000
#endif
static r8_objx vx_o;
static r8_s16 vx_sv[2][16];
static const r8_s16 *vx_mv;
static r8_u16 vx_g;
static unsigned long vx_fall, vx_bad, vx_depth;
/* the depth call (transform.c's r8k_vdepth, which this replaces here):
 * a value made of its arguments */
r8_s16 r8k_vdepth(const struct r8_state *st, r8_u16 m, r8_s8 e)
{
    if (st != &vx_st)
        vx_bad++;
    vx_depth++;
    return (r8_s16)(m ^ ((r8_u16)(r8_u8)e << 9) ^ 0x5A3Cu);
}
static void vx_ref(r8_state *st, const r8_objx *o, const r8_s16 *mv, r8_u16 g)
{
    r8_vec3l c;
    r8_s16 *out = st->sv + ((unsigned)g << st->vsh);
    r8_u16 m;
    r8_s8 e;
    if (st->vsh != 1 && (st->attrs & R8_ATTR_S))
        return;                       /* Gouraud: only the call is checked */
    r8k_xform_ref(&o->m, &o->t, mv, &c);
    if (c.z < st->zn16) {
        out[0] = R8_VX_CLIP;
        return;
    }
    if (r8k_project_ref(&st->cam, &c, out, &m, &e))
        out[0] = R8_VX_CLIP;
    else if (st->vsh != 1)
        out[2] = r8k_vdepth(st, m, e);
}
static void vx_tf(r8_state *st, const r8_objx *o, const r8_s16 *mv, r8_u16 g)
{
    if (st != &vx_st || o != &vx_o || mv != vx_mv || g != vx_g)
        vx_bad++;
    vx_fall++;
    vx_ref(st, o, mv, g);
}
static void test_vertex_random(void)
{
    unsigned long i, hit[4] = {0, 0, 0, 0};
    for (i = 0; i < VX_CASES; i++) {
        r8_vec3l c, c0, t0;
        r8_mat3 m0;
        r8_s32 *pc = &c.x, *p0 = &c0.x, *pt = &vx_o.t.x;
        r8_s16 focal;
        unsigned k = rndn(16), fall0;
        if (k < 6)
            focal = 128;
        else if (k < 11)
            focal = (r8_s16)(1 + rndn(2047));
        else if (k < 13)
            focal = (r8_s16)(1025 + rndn(1023));
        else
            focal = (r8_s16)(1 + rndn(64));
        r8_proj_init(&vx_st.cam, 128, 64, focal, 16);
        k = rndn(16);
        if (k < 10)
            vx_st.cam.guard = 900;
        else if (k < 13)
            vx_st.cam.guard = (r8_s16)rndn(1024);
        else if (k < 15)
            vx_st.cam.guard = rnds(1018, 2047);
        else
            vx_st.cam.guard = rnds(-4, 3);
        if (rndn(8) == 0) {
            vx_st.cam.cx = (r8_s16)rnd();
            vx_st.cam.cy = (r8_s16)rnd();
        }
        if (rndn(16) == 0) {
            vx_st.cam.fn = (r8_s16)rnd();
            vx_st.cam.fsh = (r8_u8)rnd();
        }
        vx_st.vsh = (r8_u8)(rndn(4) ? 1 : 2);
        vx_st.attrs = (r8_u8)(rndn(4) ? rndn(2) : rnd());     /* D, S (Gouraud) */
        /* the camera point */
        c.z = rndn(4) ? 16 + (r8_s32)rndn(20000) : rnd_z();
        if (rndn(16) == 0) {
            c.z = (r8_s32)rndn(3) - 1;
            c.x = rndn(2) ? 0 : rnds(-2, 2);
            c.y = rndn(2) ? 0 : rnds(-2, 2);
        } else {
            unsigned n = rndn(4) ? 6 : 1;    /* mostly within 16 bits */
            do {
                c.x = rnd_coord(c.z, focal);
                c.y = rnd_coord(c.z, focal);
            } while (--n && (c.x != (r8_s16)c.x || c.y != (r8_s16)c.y));
        }
        k = rndn(8);
        if (k < 4)
            vx_st.zn16 = 16 + (r8_s32)rndn(400);
        else if (k < 6)
            vx_st.zn16 = c.z + rnds(-2, 2);
        else if (k < 7)
            vx_st.zn16 = rnd_z();
        else
            vx_st.zn16 = (r8_s32)rnd();
        /* the model vertex and the matrix; t puts the vertex at c */
        k = rndn(10);
        if (k < 8)
            vx_mv = vt_small + rndn(94);
        else if (k < 9)
            vx_mv = vt_ext + rndn(94);
        else
            vx_mv = KERN_CODE_PTR();
        for (k = 0; k < 9; k++)
            vx_o.m.m[k] = rndn(4) ? rnds(-16384, 16384) : rnd_m();
        memset(&vx_o.t, 0, sizeof vx_o.t);
        r8k_xform_ref(&vx_o.m, &vx_o.t, vx_mv, &c0);
        for (k = 0; k < 3; k++)
            pt[k] = (r8_s32)((r8_u32)pc[k] - (r8_u32)p0[k]);
        if (rndn(16) == 0)
            vx_o.t.z = rnd_t();
        m0 = vx_o.m;
        t0 = vx_o.t;
        vx_g = (r8_u16)rndn(4);
        for (k = 0; k < 16; k++)
            vx_sv[0][k] = vx_sv[1][k] = (r8_s16)rnd();
        vx_st.sv = vx_sv[0];
        vx_ref(&vx_st, &vx_o, vx_mv, vx_g);
        vx_st.sv = vx_sv[1];
        fall0 = (unsigned)vx_fall;
        vx_mode = 1;
        r8k_vertex(&vx_st, &vx_o, vx_mv, vx_g);
        vx_mode = 0;
        if (memcmp(vx_sv[0], vx_sv[1], sizeof vx_sv[0]) || vx_bad || vx_st.sv != vx_sv[1] ||
            memcmp(&m0, &vx_o.m, sizeof m0) || memcmp(&t0, &vx_o.t, sizeof t0) ||
            (vx_st.vsh != 1 && (vx_st.attrs & R8_ATTR_S) && fall0 == (unsigned)vx_fall)) {
            print_case("r8k_vertex", i);
            unity_print("x ");
            unity_print_long(c.x);
            unity_print(" y ");
            unity_print_long(c.y);
            unity_print(" z ");
            unity_print_long(c.z);
            unity_print(" zn16 ");
            unity_print_long(vx_st.zn16);
            unity_print("\n");
            TEST_ASSERT_EQUAL_INT16(vx_sv[0][vx_g << vx_st.vsh], vx_sv[1][vx_g << vx_st.vsh]);
            TEST_ASSERT_EQUAL_INT16(vx_sv[0][(vx_g << vx_st.vsh) + 1], vx_sv[1][(vx_g << vx_st.vsh) + 1]);
            TEST_ASSERT_EQUAL_INT16(vx_sv[0][(vx_g << vx_st.vsh) + 2], vx_sv[1][(vx_g << vx_st.vsh) + 2]);
            TEST_FAIL_MESSAGE("r8k_vertex: sv, its arguments or the call handed on differ");
        }
        if (fall0 != (unsigned)vx_fall)
            hit[3]++;
        else if (vx_sv[1][vx_g << vx_st.vsh] != R8_VX_CLIP)
            hit[0]++;
        else
            hit[(r8k_xform_ref(&vx_o.m, &vx_o.t, vx_mv, &c0), c0.z < vx_st.zn16) ? 1 : 2]++;
    }
    unity_print("r8k_vertex: projected, near, out, handed on: ");
    for (i = 0; i < 4; i++) {
        unity_print_long((long)hit[i]);
        unity_print(i < 3 ? " " : "\n");
    }
    unity_print("r8k_vertex: depth calls ");
    unity_print_long((long)vx_depth);
    unity_print("\n");
    if (vx_depth < VX_CASES / 40)
        unity_fail_int(__LINE__, "r8k_vertex: too few depth calls", VX_CASES / 40, (long)vx_depth);
    for (i = 0; i < 4; i++)
        if (hit[i] < VX_CASES / 40)
            unity_fail_int(__LINE__, "r8k_vertex: an outcome too rare", VX_CASES / 40, (long)hit[i]);
}

/* ---- r8k_depth (ports/avr/vertex.S) against its reference in
 * src/transform.c (compiled in here with that file's other functions
 * renamed out of the way): m mostly a reciprocal ([2^15, 2^16)), znm
 * normalised ([2^14, 2^15)), sh around 1..31, wf below 2^20 and gh near
 * 32767 2^16 / (2^20 - wf), as r8_tf_frame sets them; also any 16 and
 * 32 bits (p past 2^31: the arithmetic shift; products that wrap).
 * Each outcome must be hit: sh <= 0, sh > 31, w <= wf, w clamped to 2^20,
 * a depth ---- */
#define r8_tf_frame tfref_frame
#define r8_tf_depth tfref_depth
#define r8_tf_shade tfref_shade
#define r8_tf_camera tfref_camera
#define r8_tf_vertex tfref_vertex
#define r8_tf_vertices tfref_vertices
#define r8k_vertex tfref_kvertex
#define r8k_depth r8k_depth_ref
#include "transform.c"
#undef r8_tf_frame
#undef r8_tf_depth
#undef r8_tf_shade
#undef r8_tf_camera
#undef r8_tf_vertex
#undef r8_tf_vertices
#undef r8k_vertex
#undef r8k_depth
#ifndef DEPTH_CASES
#define DEPTH_CASES 12000
#endif
static void test_depth_random(void)
{
    unsigned long i, hit[5] = {0, 0, 0, 0, 0};
    for (i = 0; i < DEPTH_CASES; i++) {
        r8_u16 m = (r8_u16)(rndn(8) ? 32768u + rndn(32768u) : rnd());
        r8_u16 znm = (r8_u16)(rndn(8) ? 16384u + rndn(16384u) : rnd());
        r8_s16 sh = rndn(8) ? rnds(-2, 34) : (r8_s16)rnd();
        r8_u32 wf = rndn(4) ? (rnd() % (1UL << 20)) >> rndn(16) : rnd(), gh;
        r8_s16 ra, rr;
        r8_u32 w;
        if (rndn(4))
            gh = (r8_u32)(32767UL * 65536UL / ((1UL << 20) - (wf & 0xFFFFFUL)));
        else
            gh = rnd();
        if (rndn(4) == 0)             /* sh near where w meets wf */
            sh = (r8_s16)(10 + rndn(12));
        rr = r8k_depth_ref(m, znm, sh, wf, gh);
        ra = r8k_depth(m, znm, sh, wf, gh);
        if (ra != rr) {
            print_case("r8k_depth", i);
            unity_print("m ");
            unity_print_long((long)m);
            unity_print(" znm ");
            unity_print_long((long)znm);
            unity_print(" sh ");
            unity_print_long((long)sh);
            unity_print("\n");
            TEST_ASSERT_EQUAL_INT16(rr, ra);
        }
        if (sh <= 0)
            hit[0]++;
        else if (sh > 31)
            hit[1]++;
        else {
            w = (r8_u32)r8_asr32((r8_s32)((r8_u32)m * znm), (r8_u8)sh);
            if (w > (1UL << 20))
                hit[3]++;
            else if (w <= wf)
                hit[2]++;
            else
                hit[4]++;
        }
    }
    unity_print("r8k_depth: sh <= 0, sh > 31, w <= wf, clamped, a depth: ");
    for (i = 0; i < 5; i++) {
        unity_print_long((long)hit[i]);
        unity_print(i < 4 ? " " : "\n");
    }
    for (i = 0; i < 5; i++)
        if (hit[i] < DEPTH_CASES / 50)
            unity_fail_int(__LINE__, "r8k_depth: an outcome too rare", DEPTH_CASES / 50, (long)hit[i]);
}

/* ---- r8k_zrows (ports/avr/zfill.S) against its reference (src/zrows.c,
 * renamed r8k_zrows_ref): random triangles and quads scanned with depth
 * (r8_scan_begin; both runs from one copy of the scan, edges moved on
 * by the library's r8_scan_row_attrs) over random bands of w <= 64
 * columns and up to 16 rows starting at row y0 in band_ref / band_asm
 * (pages at GUARD, depths at zoff, every byte random), vertices around
 * the band, now and then left of 0 or spans 256+ wide (the rows the
 * kernel leaves: the test steps past them as r8_zfill does and calls
 * again), depths anywhere in 0..32767.  The return values, rows, all
 * the memory, the scans, t's z, page, m, k and r8_zcols (from a random
 * start: none or some columns) must end equal, and every depth the
 * reference changed lie in its r8_zcols' columns.  One in
 * eight scans carries shade too (the kernel's general attribute set-up,
 * r8_scan_attr_edge). ---- */
#define R8_ZROWS_REF 1
#define r8k_zrows r8k_zrows_ref
#define r8_interp_init_sub r8_interp_init_sub_ref
#define r8_attr_first r8_attr_first_ref
#define r8k_zband r8k_zband_ref
#define r8_scan_attrs r8_scan_attrs_ref
#define r8_zcols r8_zcols_ref
#include "zrows.c"
#undef r8_zcols
#undef r8_scan_attrs
#undef r8k_zband
#undef r8k_zrows
#undef r8_interp_init_sub
#undef r8_attr_first
int r8_attr_first(r8_interp *it, const r8_s16 *a, const r8_s16 *b, r8_s16 y, r8_u8 k);
int r8k_zrows(r8_zrows *t);
int r8k_zband(struct r8_act *a, const r8_fb *fb, r8_u16 *depth, r8_s16 ylimit);
extern r8_u8 r8_zcols[2];
void r8_interp_init_sub(r8_interp *it, r8_s16 base, r8_u16 s0, r8_s16 dv, r8_u16 n);

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

/* after the reference ran on band_ref, before the kernel runs on
 * band_asm (equal before): every depth of the band (rows of w at zoff)
 * the reference changed lies in the columns [xlo, xhi) (those a caller
 * clears next: r8_zcols) */
static int zcols_cover(unsigned zoff, unsigned rows, r8_u16 w, r8_u8 xlo, r8_u8 xhi)
{
    unsigned x, y;
    for (y = 0; y < rows; y++)
        for (x = 0; x < w; x++) {
            unsigned o = zoff + 2u * (y * w + x);
            if ((band_ref[o] != band_asm[o] || band_ref[o + 1] != band_asm[o + 1]) &&
                (x < xlo || x >= xhi))
                return 0;
        }
    return 1;
}

/* t's row state for row y of the band at y0 */
static void zrows_at(r8_zrows *t, r8_u8 *band, unsigned zoff, r8_u16 w, r8_s16 y0, r8_s16 y)
{
    r8_u16 by = (r8_u16)(y - y0);
    t->y = y;
    t->z = (r8_u16 *)(void *)(band + zoff) + by * w;
    t->page = band + GUARD + (by >> 3) * w;
    t->m = (r8_u8)(1u << (by & 7));
    t->k = (r8_u8)(y & 3);
}

static void zrows_bind(r8_zrows *t, r8_scan *s)
{
    t->lx = &s->c.l.x;
    t->rx = &s->c.r.x;
    t->ld = &s->ld;
    t->rd = &s->rd;
    t->s = s;
    t->lyend = &s->c.l.yend;
    t->ryend = &s->c.r.yend;
}

static r8_svert zverts[4];
static const r8_u16 zidx[4] = { 0, 1, 2, 3 };
/* (the scans inside the acts of test_zband_random: RAM is short) */
static r8_act zact_ref, zact_asm;
#define zscan_ref (zact_ref.s)
#define zscan_asm (zact_asm.s)

static void test_zrows_random(void)
{
    unsigned long i, stops = 0, drawn = 0, moves = 0, calls = 0;
    r8_u16 sum0;
    for (i = 0; i < 3000; i++) {
        r8_zrows ta, tr;
        r8_u16 w = (r8_u16)(1u + rndn(64)), rows = (r8_u16)(1u + rndn(16));
        r8_s16 y0 = (r8_s16)rndn(40), lim, y;
        unsigned j, zoff = (2u * GUARD + 3u * w + 1u) & ~1u;
        unsigned len = zoff + 2u * rows * w + GUARD, c = rndn(8), nv = 3u + rndn(2);
        int rr, ra;
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
        for (j = 0; j < nv; j++) {
            r8_svert *p = &zverts[j];
            if (c == 0)                 /* wide spans: 256+ and the limits */
                p->x = j & 1 ? rnds(250 * 16, 330 * 16) : rnds(0, 40 * 16);
            else if (c == 1)            /* starts left of 0 now and then */
                p->x = rnds(-6 * 16, (r8_s16)((w + 8) * 16));
            else
                p->x = rnds(-2 * 16, (r8_s16)((w + 40) * 16));
            p->y = rnds((r8_s16)(y0 * 16 - 40), (r8_s16)((y0 + rows) * 16 + 40));
            p->d = rndn(4) == 0 ? rnds(0, 32767) : rnds(16000, 16900);
            p->s = rnds(0, 4096);
        }
        if (nv == 4 && c != 0) {       /* a convex quad: a box's corners */
            r8_s16 xa = zverts[0].x, xb = zverts[1].x, ya = zverts[0].y, yb = zverts[1].y;
            zverts[0].x = xa; zverts[0].y = ya;
            zverts[1].x = xb; zverts[1].y = ya;
            zverts[2].x = xb; zverts[2].y = yb;
            zverts[3].x = xa; zverts[3].y = yb;
        }
        memset(&zscan_ref, 0, sizeof zscan_ref);
        if (!r8_scan_begin(&zscan_ref, zverts, zidx, (r8_u8)nv,
                           (r8_u8)(rndn(8) ? R8_ATTR_D : R8_ATTR_D | R8_ATTR_S), y0))
            continue;
        lim = zscan_ref.c.ybot < (r8_s16)(y0 + rows) ? zscan_ref.c.ybot : (r8_s16)(y0 + rows);
        y = zscan_ref.c.y;
        if (y < y0 || y >= lim)
            continue;
        memcpy(&zscan_asm, &zscan_ref, sizeof zscan_ref);
        zrows_bind(&tr, &zscan_ref);
        zrows_bind(&ta, &zscan_asm);
        tr.w = ta.w = w;
        tr.lim = ta.lim = lim;
        tr.pat = ta.pat = &r8_fb_dither_tab[4u * rndn(17)];   /* flash */
        r8_zcols_ref[0] = (r8_u8)(rndn(2) ? 255 : rndn(w + 1));   /* none, or some */
        r8_zcols_ref[1] = (r8_u8)(r8_zcols_ref[0] == 255 ? 0 : r8_zcols_ref[0] + rndn(w + 1 - r8_zcols_ref[0]));
        r8_zcols[0] = r8_zcols_ref[0];
        r8_zcols[1] = r8_zcols_ref[1];
        sum0 = zsum(band_ref, len);
        for (;;) {
            r8_s16 le = zscan_ref.c.l.yend, re = zscan_ref.c.r.yend;
            zrows_at(&tr, band_ref, zoff, w, y0, y);
            zrows_at(&ta, band_asm, zoff, w, y0, y);
            rr = r8k_zrows_ref(&tr);
            if (!zcols_cover(zoff, rows, w, r8_zcols_ref[0], r8_zcols_ref[1])) {
                print_case("r8k_zrows", i);
                unity_fail_int(__LINE__, "r8k_zrows: depth past r8_zcols", r8_zcols_ref[0], r8_zcols_ref[1]);
                return;
            }
            ra = r8k_zrows(&ta);
            calls++;
            moves += zscan_ref.c.l.yend != le || zscan_ref.c.r.yend != re;
            if (ra != rr || ta.y != tr.y || memcmp(band_ref, band_asm, len) != 0 ||
                memcmp(&zscan_ref, &zscan_asm, sizeof zscan_ref) != 0 ||
                (r8_u8 *)ta.z - band_asm != (r8_u8 *)tr.z - band_ref ||
                ta.page - band_asm != tr.page - band_ref || ta.m != tr.m || ta.k != tr.k ||
                r8_zcols[0] != r8_zcols_ref[0] || r8_zcols[1] != r8_zcols_ref[1]) {
                print_case("r8k_zrows", i);
                unity_fail_int(__LINE__, "r8k_zrows differs from the reference", (long)ra, (long)rr);
                return;
            }
            if (rr != 2)
                break;
            stops++;                    /* r8_zfill's row: stepped past */
            R8_INTERP_STEP(&zscan_ref.c.l.x);
            R8_INTERP_STEP(&zscan_ref.c.r.x);
            R8_INTERP_STEP(&zscan_ref.ld);
            R8_INTERP_STEP(&zscan_ref.rd);
            memcpy(&zscan_asm, &zscan_ref, sizeof zscan_ref);
            y = (r8_s16)(tr.y + 1);
            if (y >= lim)
                break;
        }
        drawn += zsum(band_ref, len) != sum0;   /* some depth or pixel written */
    }
    unity_print("r8k_zrows: ");
    unity_print_long((long)calls);
    unity_print(" calls, rows left to C ");
    unity_print_long((long)stops);
    unity_print(", edges moved on in ");
    unity_print_long((long)moves);
    unity_print(", memory written in ");
    unity_print_long((long)drawn);
    unity_print("\n");
    if (stops < 100 || drawn < 330 || moves < 500)
        unity_fail_int(__LINE__, "r8k_zrows: too few stops, moves or drawn bands", (long)stops, (long)drawn);
}

/* ---- r8k_zrows over tall bands: triangles over 260..300 rows of 1..4
 * columns, so that a run of rows without an edge move passes 255 (the
 * kernel's 8-bit row count: 255 rows, then on) and the edges' dens pass
 * 255 (the 16-bit steps); the same checks as test_zrows_random; its
 * summary line: calls, then the runs past 255 rows ---- */
static void test_zrows_tall(void)
{
    unsigned long i, calls = 0, tall = 0;
    for (i = 0; i < 40; i++) {
        r8_zrows ta, tr;
        r8_u16 w = (r8_u16)(1u + rndn(4)), rows = (r8_u16)(260u + rndn(41));
        r8_s16 y0 = (r8_s16)rndn(8), lim, y;
        unsigned j, zoff = (2u * GUARD + ((rows + 7u) >> 3) * w + 1u) & ~1u;
        unsigned len = zoff + 2u * rows * w + GUARD;
        int rr, ra;
        for (j = 0; j < len; j++)
            band_ref[j] = (r8_u8)rnd();
        memcpy(band_asm, band_ref, len);
        zverts[0].x = rnds(0, (r8_s16)(w * 16));
        zverts[0].y = rnds((r8_s16)(y0 * 16 - 20), (r8_s16)(y0 * 16 + 8));
        zverts[1].x = rnds(0, (r8_s16)(w * 8));
        zverts[1].y = rnds((r8_s16)((y0 + rows) * 16 - 8), (r8_s16)((y0 + rows) * 16 + 20));
        zverts[2].x = rnds((r8_s16)(w * 8), (r8_s16)(w * 16));
        zverts[2].y = rnds((r8_s16)((y0 + rows) * 16 - 8), (r8_s16)((y0 + rows) * 16 + 20));
        for (j = 0; j < 3; j++) {
            zverts[j].d = rnds(16000, 16900);
            zverts[j].s = 0;
        }
        memset(&zscan_ref, 0, sizeof zscan_ref);
        if (!r8_scan_begin(&zscan_ref, zverts, zidx, 3, R8_ATTR_D, y0))
            continue;
        lim = zscan_ref.c.ybot < (r8_s16)(y0 + rows) ? zscan_ref.c.ybot : (r8_s16)(y0 + rows);
        y = zscan_ref.c.y;
        if (y < y0 || y >= lim)
            continue;
        memcpy(&zscan_asm, &zscan_ref, sizeof zscan_ref);
        zrows_bind(&tr, &zscan_ref);
        zrows_bind(&ta, &zscan_asm);
        tr.w = ta.w = w;
        tr.lim = ta.lim = lim;
        tr.pat = ta.pat = &r8_fb_dither_tab[4u * rndn(17)];
        r8_zcols_ref[0] = r8_zcols[0] = 255;
        r8_zcols_ref[1] = r8_zcols[1] = 0;
        tall += zscan_ref.c.l.yend - y > 255 && zscan_ref.c.r.yend - y > 255 && lim - y > 255;
        for (;;) {
            zrows_at(&tr, band_ref, zoff, w, y0, y);
            zrows_at(&ta, band_asm, zoff, w, y0, y);
            rr = r8k_zrows_ref(&tr);
            ra = r8k_zrows(&ta);
            calls++;
            if (ra != rr || ta.y != tr.y || memcmp(band_ref, band_asm, len) != 0 ||
                memcmp(&zscan_ref, &zscan_asm, sizeof zscan_ref) != 0 ||
                (r8_u8 *)ta.z - band_asm != (r8_u8 *)tr.z - band_ref ||
                ta.page - band_asm != tr.page - band_ref || ta.m != tr.m || ta.k != tr.k ||
                r8_zcols[0] != r8_zcols_ref[0] || r8_zcols[1] != r8_zcols_ref[1]) {
                print_case("r8k_zrows", i);
                unity_fail_int(__LINE__, "r8k_zrows differs from the reference", (long)ra, (long)rr);
                return;
            }
            if (rr != 2)
                break;
            R8_INTERP_STEP(&zscan_ref.c.l.x);
            R8_INTERP_STEP(&zscan_ref.c.r.x);
            R8_INTERP_STEP(&zscan_ref.ld);
            R8_INTERP_STEP(&zscan_ref.rd);
            memcpy(&zscan_asm, &zscan_ref, sizeof zscan_ref);
            y = (r8_s16)(tr.y + 1);
            if (y >= lim)
                break;
        }
    }
    unity_print("r8k_zrows: ");        /* (the strings of the test above: */
    unity_print_long((long)calls);      /* RAM is short) */
    unity_print(", edges moved on in ");
    unity_print_long((long)tall);
    unity_print("\n");
    if (tall < 20)
        unity_fail_int(__LINE__, "r8k_zrows: too few stops, moves or drawn bands", 20, (long)tall);
}

/* ---- r8k_zband (zfill.S) against its reference (src/zrows.c, renamed
 * r8k_zband_ref, which calls r8k_zrows_ref): the scans of
 * test_zrows_random's kind in an r8_act of random level (0..20: past 16
 * too) over a band fb (rows at y0, w <= 64 columns, pages at GUARD,
 * depths at zoff) with random limits (the band's end, the face's, a
 * ylimit above both or between), from the scan's own first row y on.
 * r8k_zband builds the r8_zrows r8_zfill did (z, page, m, k from y -
 * fb->y0, the pattern from the level, the limit) and writes c.y; the
 * rows it leaves (its 2) are stepped past as r8_zfill's C does.  The
 * return values, all the memory, both acts and r8_zcols must end equal,
 * the depths changed inside r8_zcols' columns. ---- */
static void test_zband_random(void)
{
    unsigned long i, stops = 0, drawn = 0, calls = 0, cut = 0;
    for (i = 0; i < 2000; i++) {
        r8_fb fb_ref, fb_asm;
        r8_u16 w = (r8_u16)(1u + rndn(64)), rows = (r8_u16)(1u + rndn(16));
        r8_s16 y0 = (r8_s16)rndn(40), ylimit;
        unsigned j, zoff = (2u * GUARD + 3u * w + 1u) & ~1u;
        unsigned len = zoff + 2u * rows * w + GUARD, c = rndn(8), nv = 3u + rndn(2);
        int rr, ra;
        r8_u32 v = 0;
        r8_u16 sum0;
        for (j = 0; j < len; j++) {
            if (!(j & 3))
                v = rnd();
            band_ref[j] = (r8_u8)v;
            v >>= 8;
        }
        if (rndn(2))
            for (j = zoff; j < len; j += 2)
                band_ref[j + 1] = (r8_u8)(0x40 + (band_ref[j] & 1));
        memcpy(band_asm, band_ref, len);
        for (j = 0; j < nv; j++) {
            r8_svert *p = &zverts[j];
            if (c == 0)
                p->x = j & 1 ? rnds(250 * 16, 330 * 16) : rnds(0, 40 * 16);
            else if (c == 1)
                p->x = rnds(-6 * 16, (r8_s16)((w + 8) * 16));
            else
                p->x = rnds(-2 * 16, (r8_s16)((w + 40) * 16));
            p->y = rnds((r8_s16)(y0 * 16 - 40), (r8_s16)((y0 + rows) * 16 + 40));
            p->d = rndn(4) == 0 ? rnds(0, 32767) : rnds(16000, 16900);
            p->s = rnds(0, 4096);
        }
        memset(&zact_ref, 0, sizeof zact_ref);
        zact_ref.level = (r8_u8)rndn(21);
        zact_ref.used = (r8_u8)rnd();
        if (!r8_scan_begin(&zact_ref.s, zverts, zidx, (r8_u8)nv,
                           (r8_u8)(rndn(8) ? R8_ATTR_D : R8_ATTR_D | R8_ATTR_S), y0))
            continue;
        if (zact_ref.s.c.y < y0 || zact_ref.s.c.y >= (r8_s16)(y0 + rows))
            continue;
        memcpy(&zact_asm, &zact_ref, sizeof zact_ref);
        fb_ref.width = fb_asm.width = (r8_s16)w;
        fb_ref.height = fb_asm.height = 200;
        fb_ref.y0 = fb_asm.y0 = y0;
        fb_ref.rows = fb_asm.rows = (r8_s16)rows;
        fb_ref.format = fb_asm.format = R8_FMT_PAGE1;
        fb_ref.buf = band_ref + GUARD;
        fb_asm.buf = band_asm + GUARD;
        switch (rndn(3)) {
        case 0:
            ylimit = (r8_s16)(y0 + rows + (r8_s16)rndn(20));
            break;
        case 1:
            ylimit = (r8_s16)(zact_ref.s.c.y + 1 + (r8_s16)rndn(rows));
            break;
        default:
            ylimit = (r8_s16)(y0 + rows);
        }
        cut += ylimit < zact_ref.s.c.ybot && ylimit < (r8_s16)(y0 + rows);
        sum0 = zsum(band_ref, len);
        r8_zcols_ref[0] = (r8_u8)(rndn(2) ? 255 : rndn(w + 1));   /* none, or some */
        r8_zcols_ref[1] = (r8_u8)(r8_zcols_ref[0] == 255 ? 0 : r8_zcols_ref[0] + rndn(w + 1 - r8_zcols_ref[0]));
        r8_zcols[0] = r8_zcols_ref[0];
        r8_zcols[1] = r8_zcols_ref[1];
        for (;;) {
            rr = r8k_zband_ref(&zact_ref, &fb_ref, (r8_u16 *)(void *)(band_ref + zoff), ylimit);
            if (!zcols_cover(zoff, rows, w, r8_zcols_ref[0], r8_zcols_ref[1])) {
                print_case("r8k_zband", i);
                unity_fail_int(__LINE__, "r8k_zband: depth past r8_zcols", r8_zcols_ref[0], r8_zcols_ref[1]);
                return;
            }
            ra = r8k_zband(&zact_asm, &fb_asm, (r8_u16 *)(void *)(band_asm + zoff), ylimit);
            calls++;
            if (ra != rr || memcmp(band_ref, band_asm, len) != 0 ||
                memcmp(&zact_ref, &zact_asm, sizeof zact_ref) != 0 ||
                r8_zcols[0] != r8_zcols_ref[0] || r8_zcols[1] != r8_zcols_ref[1]) {
                print_case("r8k_zband", i);
                unity_fail_int(__LINE__, "r8k_zband differs from the reference", (long)ra, (long)rr);
                return;
            }
            if (rr != 2)
                break;
            stops++;                    /* r8_zfill's row: stepped past */
            R8_INTERP_STEP(&zact_ref.s.c.l.x);
            R8_INTERP_STEP(&zact_ref.s.c.r.x);
            R8_INTERP_STEP(&zact_ref.s.ld);
            R8_INTERP_STEP(&zact_ref.s.rd);
            zact_ref.s.c.y++;
            memcpy(&zact_asm, &zact_ref, sizeof zact_ref);
        }
        drawn += zsum(band_ref, len) != sum0;
    }
    unity_print("r8k_zband: ");
    unity_print_long((long)calls);
    unity_print(" calls, rows left to C ");
    unity_print_long((long)stops);
    unity_print(", cut by ylimit ");
    unity_print_long((long)cut);
    unity_print(", memory written in ");
    unity_print_long((long)drawn);
    unity_print("\n");
    if (stops < 50 || drawn < 200 || cut < 100)
        unity_fail_int(__LINE__, "r8k_zband: too few stops, cuts or drawn bands", (long)stops, (long)drawn);
}

/* ---- r8_scan_attrs (zfill.S) against its reference (src/zrows.c,
 * renamed r8_scan_attrs_ref): random triangles and quads begun by
 * r8_scanx_begin at a random row, attributes none, depth, depth and
 * shade or shade, the interpolators random before; edges tall (past
 * 256 subpixels) and depth steps wide (past 4095) now and then, so that
 * r8_attr_first says 0 and r8_scan_attr_edge sets them up.  The whole
 * scans must end equal. ---- */
#define sa_ref (zact_ref.s)              /* (RAM is short) */
#define sa_asm (zact_asm.s)

static void test_scan_attrs_random(void)
{
    unsigned long i, cases = 0, general = 0;
    static const r8_u8 attrs[4] = { 0, R8_ATTR_D, R8_ATTR_D | R8_ATTR_S, R8_ATTR_S };
    for (i = 0; i < 3000; i++) {
        unsigned j, nv = 3u + rndn(2), tall = rndn(4) == 0, wide = rndn(4) == 0;
        r8_s16 ys = (r8_s16)rndn(64);
        r8_u8 *p = (r8_u8 *)&sa_ref;
        for (j = 0; j < sizeof sa_ref; j++)
            p[j] = (r8_u8)rnd();
        for (j = 0; j < nv; j++) {
            r8_svert *v = &zverts[j];
            v->x = rnds(-200, 2200);
            v->y = tall ? rnds(0, 64 * 16) : rnds((r8_s16)(ys * 16 - 100), (r8_s16)(ys * 16 + 200));
            v->d = wide ? rnds(0, 32767) : rnds(16000, 18000);
            v->s = rnds(0, 4096);
            sa_ref.c.vp[j] = &v->x;
        }
        if (!r8_scanx_begin(&sa_ref.c, (r8_u8)nv, ys))
            continue;
        sa_ref.attrs = attrs[rndn(4)];
        memcpy(&sa_asm, &sa_ref, sizeof sa_ref);
        r8_scan_attrs_ref(&sa_ref);
        r8_scan_attrs(&sa_asm);
        cases++;
        general += tall || wide;
        if (memcmp(&sa_ref, &sa_asm, sizeof sa_ref) != 0) {
            print_case("r8_scan_attrs", i);
            unity_fail_int(__LINE__, "r8_scan_attrs differs from the reference", (long)sa_asm.ld.val,
                           (long)sa_ref.ld.val);
            return;
        }
    }
    unity_print("r8_scan_attrs: ");
    unity_print_long((long)cases);
    unity_print(" scans, tall or wide ");
    unity_print_long((long)general);
    unity_print("\n");
    if (cases < 1500 || general < 300)
        unity_fail_int(__LINE__, "r8_scan_attrs: too few cases", (long)cases, (long)general);
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
    RUN_TEST(test_trap_short);
    RUN_TEST(test_xform_random);
    RUN_TEST(test_edge_random);
    RUN_TEST(test_project_random);
    RUN_TEST(test_fill_random);
    RUN_TEST(test_cull_random);
    RUN_TEST(test_level_random);
    RUN_TEST(test_zsum_random);
    RUN_TEST(test_fwalk_random);
    RUN_TEST(test_vertex_random);
    RUN_TEST(test_depth_random);
    RUN_TEST(test_estart_random);
    RUN_TEST(test_scanband_random);
    RUN_TEST(test_zrows_random);
    RUN_TEST(test_zrows_tall);
    RUN_TEST(test_zband_random);
    RUN_TEST(test_scan_attrs_random);
    RUN_TEST(test_init_sub_random);
    RUN_TEST(test_attr_first_random);
    return UNITY_END();
}

/* ---- the scan kernels (src/scankern.c's and scanband.c's references,
 * renamed, calling the references of r8k_trap and r8k_edge) ---- */
#define r8k_trap r8k_trap_ref
#define r8k_edge r8k_edge_ref
#define r8k_estart r8k_estart_ref
#define r8k_scanfill r8k_scanfill_ref
#define r8k_scanband r8k_scanband_ref
#undef R8_ASM_ESTART
#undef R8_ASM_SCANFILL
#include "scankern.c"
#include "scanband.c"
#undef r8k_trap
#undef r8k_edge
#undef r8k_estart
#undef r8k_scanfill
#undef r8k_scanband
void r8k_estart(r8_scanx *s, r8_edge *e, r8_s16 y, r8_u8 from);
void r8k_scanband(r8_scanx *s, const r8_fb *fb, r8_s16 lim, r8_u8 level);

/* ---- r8k_estart (edge.S) against scankern.c's reference: random polygons
 * of 3..9 vertices (screen-sized, with shared rows, wide or far out,
 * near the 32760 row limit, non-convex and random), a random row y
 * above the polygon's last (the contract: y < ybot), a random start
 * position, either chain; the whole r8_scanx compared, the vertices
 * untouched. ---- */
#ifndef ESTART_CASES
#define ESTART_CASES 5000
#endif
static void test_estart_random(void)
{
    static r8_s16 vr[R8_SCAN_MAXV][2], va[R8_SCAN_MAXV][2];
    static r8_scanx sr, sa;
    unsigned long i, n_left = 0, n_walk = 0, n_empty = 0, n_wide = 0, n_step = 0, n_2048 = 0, n_a2048 = 0;
    for (i = 0; i < ESTART_CASES; i++) {
        unsigned n = 3 + rndn(R8_SCAN_MAXV - 2), k, c = rndn(16);
        r8_s16 ymax = R8_S16_MIN, ymin = 32767, y, ybot, ytop, cy = rnds(-3000, 3000);
        r8_u8 from = (r8_u8)rndn(n), *p, left = (r8_u8)rndn(2);
        r8_edge *er, *ea;
        for (k = 0; k < n; k++) {
            r8_s16 x, yy;
            if (c < 8) {                    /* screen-sized */
                x = rnds(-400, 2400);
                yy = rnds(-300, 1300);
            } else if (c < 11) {            /* rows shared: horizontal edges */
                x = rnds(-400, 2400);
                yy = (r8_s16)(16 * rnds(-2, 10) + rnds(-9, 9) * (rndn(3) == 0));
            } else if (c < 13) {            /* wide: tall, or x far out */
                x = rndn(2) ? rnds(-16400, 16400) : rnds(-400, 2400);
                yy = rnds(-1500, 3000);
            } else if (c < 14) {            /* near the row limit (half */
                x = rnds(-400, 2400);       /* of them past 32757) */
                yy = rndn(2) ? rnds(32600, 32767) : rnds(32758, 32767);
            } else {                        /* anything within +-3000 of cy */
                x = (r8_s16)rnd();
                yy = (r8_s16)(cy + rnds(-3000, 3000));
            }
            vr[k][0] = x;
            vr[k][1] = yy;
            if (yy > ymax)
                ymax = yy;
            if (yy < ymin)
                ymin = yy;
        }
        ybot = R8_ROW_OF(ymax);
        ytop = R8_ROW_OF(ymin);
        if (ytop >= ybot)
            continue;                       /* no row: never scanned */
        y = rnds((r8_s16)(ytop - 2), (r8_s16)(ybot - 1));
        if (rndn(2))
            y = rnds((r8_s16)(ybot - 3 > ytop ? ybot - 3 : ytop), (r8_s16)(ybot - 1));
        memcpy(va, vr, sizeof vr);
        p = (r8_u8 *)&sr;
        for (k = 0; k < sizeof sr; k++)
            p[k] = (r8_u8)rnd();
        sr.n = (r8_u8)n;
        for (k = 0; k < n; k++)
            sr.vp[k] = vr[k];
        memcpy(&sa, &sr, sizeof sr);
        for (k = 0; k < n; k++)
            sa.vp[k] = va[k];
        er = left ? &sr.l : &sr.r;
        ea = left ? &sa.l : &sa.r;
        r8k_estart_ref(&sr, er, y, from);
        r8k_estart(&sa, ea, y, from);
        for (k = 0; k < n; k++)             /* (pointers differ: compare through them) */
            sa.vp[k] = vr[k];
        if (memcmp(&sa, &sr, sizeof sr) != 0 || memcmp(va, vr, sizeof vr) != 0) {
            print_case("r8k_estart", i);
            unity_fail_int(__LINE__, "r8k_estart differs from the reference", (long)y, (long)from);
        }
        n_left += left;
        {
            r8_u8 to = er->vi, fr = (r8_u8)(left ? (to + 1u == n ? 0 : to + 1u) : (to == 0 ? n - 1u : to - 1u));
            const r8_s16 *a = vr[fr], *b = vr[to];
            if (fr != from)
                n_walk++;
            if (b[1] <= a[1])
                n_empty++;
            else {
                r8_interp it;
                r8_s16 y0 = r8k_edge_ref(&it, a, b);
                if (y0 == R8_EDGE_WIDE)
                    n_wide++;
                else if (y0 < y)
                    n_step++;
            }
            if (er->yend == 2048)
                n_2048++;
            if (b[1] > a[1] && R8_ROW_OF(a[1]) == 2048)
                n_a2048++;              /* (edge.S's first-row test: past 32767) */
        }
    }
    unity_print("r8k_estart: left ");
    unity_print_long((long)n_left);
    unity_print(", walked ");
    unity_print_long((long)n_walk);
    unity_print(", empty ");
    unity_print_long((long)n_empty);
    unity_print(", wide ");
    unity_print_long((long)n_wide);
    unity_print(", stepped ");
    unity_print_long((long)n_step);
    unity_print(", row 2048 ");
    unity_print_long((long)n_2048);
    unity_print(", from row 2048 ");
    unity_print_long((long)n_a2048);
    unity_print("\n");
    if (n_left < 500 || n_walk < 200 || n_empty < 20 || n_wide < 50 || n_step < 200 || n_2048 < 20
        || n_a2048 < 5)
        TEST_FAIL_MESSAGE("r8k_estart: a class of cases too rare to mean anything");
}

/* ---- r8k_scanband (trap.S, with r8k_scanfill) against the reference:
 * random polygons of 3..7 vertices over and around a page-1 band of 1..4
 * pages and 8..160 columns (at a random offset between guard bytes),
 * begun (r8_scanx_begin) at a random row of the band, filled from there
 * to a random limit at a random level (0..20); the band window, guards
 * included, and the whole r8_scanx compared.  Counted: trapezoids of
 * one row, of several, edge restarts, calls of more than one trapezoid,
 * spans with page groups (7+ rows, 16+ columns). ---- */
#ifndef SCANBAND_CASES
#define SCANBAND_CASES 1500
#endif
#define SB_WIN (GUARD + 255 + 4 * 160 + GUARD)
static r8_u8 sb_ref[SB_WIN], sb_asm[SB_WIN];
static void test_scanband_random(void)
{
    static r8_s16 v[7][2];
    static r8_scanx sr, sa;
    unsigned long i, n_run = 0, n_restart = 0, n_multi = 0, n_group = 0, n_level = 0;
    for (i = 0; i < SCANBAND_CASES; i++) {
        unsigned n = 3 + rndn(5), k, pages = 1 + rndn(4), len, off = rndn(256);
        r8_s16 w = (r8_s16)(8 + rndn(153)), y0 = rnds(-20, 60), rows = (r8_s16)(8 * pages);
        r8_s16 lim, ystart, ylimit;
        r8_u8 level = (r8_u8)rndn(21), b, l_vi, r_vi;
        r8_fb fr, fa;
        unsigned c = rndn(4);
        for (k = 0; k < n; k++) {
            if (c == 0) {                   /* around the band */
                v[k][0] = rnds(-40 * 16, (r8_s16)((w + 40) * 16));
                v[k][1] = rnds((r8_s16)((y0 - 12) * 16), (r8_s16)((y0 + rows + 12) * 16));
            } else if (c == 1) {            /* tall and wide: page groups */
                v[k][0] = rnds(-8 * 16, (r8_s16)((w + 8) * 16));
                v[k][1] = rnds((r8_s16)((y0 - 40) * 16), (r8_s16)((y0 + rows + 40) * 16));
            } else if (c == 2) {            /* small: many short trapezoids */
                v[k][0] = (r8_s16)(rnds(0, (r8_s16)(w * 16)) + rnds(-60, 60));
                v[k][1] = (r8_s16)(rnds((r8_s16)(y0 * 16), (r8_s16)((y0 + rows) * 16)) + rnds(-60, 60));
            } else {                        /* far out */
                v[k][0] = rnds(-3000, 3000);
                v[k][1] = rnds((r8_s16)((y0 - 200) * 16), (r8_s16)((y0 + rows + 200) * 16));
            }
        }
        if (c == 1 && n >= 4) {             /* a convex quad over the band */
            r8_s16 xl = rnds(-100, (r8_s16)(w * 4)), xr = rnds((r8_s16)(w * 8), (r8_s16)(w * 20));
            v[0][0] = xl; v[0][1] = (r8_s16)((y0 - 20) * 16 + rnds(0, 15));
            v[1][0] = xr; v[1][1] = (r8_s16)((y0 - 10) * 16 + rnds(0, 15));
            v[2][0] = (r8_s16)(xr + rnds(-40, 40)); v[2][1] = (r8_s16)((y0 + rows + 10) * 16);
            v[3][0] = (r8_s16)(xl + rnds(-40, 40)); v[3][1] = (r8_s16)((y0 + rows + 5) * 16);
            n = 4;
        }
        memset(&sr, 0, sizeof sr);
        for (k = 0; k < n; k++)
            sr.vp[k] = v[k];
        ystart = (r8_s16)(y0 + rndn((unsigned)rows));
        if (!r8_scanx_begin(&sr, (r8_u8)n, ystart))
            continue;
        ylimit = rndn(3) ? (r8_s16)(y0 + rows + 5) : (r8_s16)(sr.y + 1 + rndn(rows));
        lim = sr.ybot < ylimit ? sr.ybot : ylimit;
        if (lim > y0 + rows)
            lim = (r8_s16)(y0 + rows);
        if (sr.y < y0 || sr.y >= lim)
            continue;
        memcpy(&sa, &sr, sizeof sr);
        len = GUARD + off + pages * (unsigned)w + GUARD;
        b = (r8_u8)rnd();
        for (k = 0; k < len; k++) {
            b = (r8_u8)(b + 151u);
            sb_ref[k] = b;
        }
        memcpy(sb_asm, sb_ref, len);
        fr.buf = sb_ref + GUARD + off;
        fr.width = w;
        fr.height = 200;
        fr.y0 = y0;
        fr.rows = rows;
        fr.format = R8_FMT_PAGE1;
        fa = fr;
        fa.buf = sb_asm + GUARD + off;
        l_vi = sr.l.vi;
        r_vi = sr.r.vi;
        r8k_scanband_ref(&sr, &fr, lim, level);
        r8k_scanband(&sa, &fa, lim, level);
        if (memcmp(sb_asm, sb_ref, len) != 0 || memcmp(&sa, &sr, sizeof sr) != 0) {
            print_case("r8k_scanband", i);
            unity_fail_int(__LINE__, "r8k_scanband differs from the reference", (long)lim, (long)level);
        }
        n_run++;
        if (sr.l.vi != l_vi || sr.r.vi != r_vi)
            n_restart++;
        if (sr.l.vi != l_vi && sr.r.vi != r_vi)
            n_multi++;
        if (c == 1 && n == 4 && w >= 24)
            n_group++;
        if (level > 16)
            n_level++;
    }
    unity_print("r8k_scanband: ");
    unity_print_long((long)n_run);
    unity_print(" filled, restarts ");
    unity_print_long((long)n_restart);
    unity_print(", both edges ");
    unity_print_long((long)n_multi);
    unity_print(", quads over the band ");
    unity_print_long((long)n_group);
    unity_print(", level > 16 ");
    unity_print_long((long)n_level);
    unity_print("\n");
    if (n_run < 600 || n_restart < 100 || n_multi < 30 || n_group < 50 || n_level < 40)
        TEST_FAIL_MESSAGE("r8k_scanband: a class of cases too rare to mean anything");
}
