/* test_bandz80.c - the Z80's r8k_band (ports/z80/band_z80.s, Z80_ASM's
 * "band", -DR8_ASM_BAND: r8_render_band of the cull firmware, render.c's
 * R8_BAND_Z80) against a C89 model of render.c's band loop
 * (r8_render_band_c's page-1 cull path): on random bands (widths, rows,
 * first rows above, inside and below the frame) and random face lists
 * (the faces going on from the band above and the band buckets, sorted
 * by id, links shared as in render.c), with r8_band_face (render.c's
 * draw_face) replaced here by a stub that logs its calls and answers
 * 0, 1 or 2 at random.  Compared: the calls (id, rows, band, state),
 * the band's clear (guard bytes around it kept), every link and
 * st->first.  The state is built from the offsets render.c asserts for
 * the kernel.  Elsewhere (no kernel) the model alone is checked: the
 * faces that go on are the merged lists' unfinished ones, in order. */
#include <string.h>
#include "unity.h"
#include "r8render.h"
#include "r8fb.h"

#if defined(__SDCC) && defined(R8_ASM_BAND)
#define BZ_KERN 1
void r8k_band(r8_render *r, r8_fb *fb);
#endif

void setUp(void) {}
void tearDown(void) {}

static r8_u32 seed = 777;
static r8_u16 rnd16(void)
{
    seed = seed * 1103515245ul + 12345ul;
    return (r8_u16)((seed >> 8) & 0xFFFFu);
}
static r8_s16 rndr(r8_s16 lo, r8_s16 hi) /* lo .. hi */
{
    return (r8_s16)(lo + (r8_s16)(rnd16() % (r8_u16)(hi - lo + 1)));
}

/* r8_state's fields the band loop reads (src/r8int.h; offsets on sdcc,
 * asserted in render.c under R8_BAND_Z80) */
#define ST_NBANDS 33
#define ST_NEXT 41
#define ST_HEADS 43
#define ST_FIRST 47
#define ST_SLOT 49
#define END 0xFFFFu
#define NF 40
#define NB 12
#define CALLS 64
#define GUARD 8
#define MAXB (128 * 2)

static r8_u16 next_k[NF], next_m[NF], heads[NB];
static r8_u8 ans[CALLS];
static unsigned ncall;
static r8_u16 log_g[CALLS];
static r8_s16 log_y0[CALLS], log_y1[CALLS];
static const void *log_st[CALLS], *log_fb[CALLS];
static r8_u8 band_k[MAXB + 2 * GUARD], band_m[MAXB + 2 * GUARD];

#ifdef BZ_KERN
static r8_u8 stb[64];
static void put16(r8_u8 *p, r8_u16 v)
{
    p[0] = (r8_u8)(v & 0xFFu);
    p[1] = (r8_u8)(v >> 8);
}
static r8_u16 get16(const r8_u8 *p)
{
    return (r8_u16)(p[0] | (r8_u16)p[1] << 8);
}
#endif

/* render.c's draw_face, as the kernel calls it: logged, answered from
 * ans[] (0: goes on below, 1: finished, 2: starts lower down) */
int r8_band_face(void *st, r8_u16 g, r8_s16 y0, r8_s16 y1, r8_fb *fb);
int r8_band_face(void *st, r8_u16 g, r8_s16 y0, r8_s16 y1, r8_fb *fb)
{
    if (ncall >= CALLS)
        return 1;
    log_g[ncall] = g;
    log_y0[ncall] = y0;
    log_y1[ncall] = y1;
    log_st[ncall] = st;
    log_fb[ncall] = fb;
    return ans[ncall++];
}

/* the model: r8_render_band's page-1 cull path (render.c) over next_m;
 * the calls it makes into the m_* logs; returns the new first */
static unsigned m_n;
static r8_u16 m_g[CALLS];
static r8_u16 model(r8_u16 first, const r8_fb *fb, r8_u16 nbands, r8_u8 *buf)
{
    r8_s16 y0 = fb->y0, y1 = (r8_s16)(fb->y0 + fb->rows);
    r8_u16 head = first, *link = &head, g, a = first, n = END, b;
    unsigned k;
    if (y1 > fb->height)
        y1 = fb->height;
    for (k = 0; k < R8_FB_PAGE1_BYTES(fb->width, fb->rows); k++)
        buf[k] = 0;
    b = (r8_u16)(y0 < 0 ? 0 : (r8_u16)y0 >> 3);
    if (b < nbands)
        n = heads[b];
    m_n = 0;
    while (a != END || n != END) {
        int d;
        if (n == END || (a != END && a < n)) {
            g = a;
            a = next_m[a];
        } else {
            g = n;
            n = next_m[n];
        }
        m_g[m_n] = g;
        d = m_n < CALLS ? ans[m_n] : 1;
        m_n++;
        /* (the kernel's y0, y1 are checked against these) */
        (void)y1;
        if (d != 1) {
            *link = g;
            link = &next_m[g];
        }
    }
    *link = END;
    return head;
}

/* a list of the ids whose owner is `who`, sorted, linked through nx */
static r8_u16 make_list(const r8_u8 *owner, r8_u8 who, unsigned nf, r8_u16 *nx)
{
    r8_u16 h = END;
    unsigned f;
    for (f = nf; f-- > 0;)
        if (owner[f] == who) {
            nx[f] = h;
            h = (r8_u16)f;
        }
    return h;
}

static void test_band(void)
{
    static r8_u8 owner[NF];
    unsigned i, k, calls = 0, goes_on = 0;
    for (i = 0; i < 600; i++) {
        r8_fb fb;
        r8_u16 first, nbands = (r8_u16)rndr(1, NB), want, f;
        unsigned nf = (unsigned)rndr(0, NF), bytes;
#ifdef BZ_KERN
        r8_render r;
        r8_s16 y1;
#endif
        fb.width = rndr(1, 128);
        fb.rows = (r8_s16)((rnd16() & 1u) ? 8 : 16);
        fb.height = rndr(8, 96);
        fb.y0 = (r8_s16)(rndr(-2, 13) * 8);
        fb.format = R8_FMT_PAGE1;
        bytes = R8_FB_PAGE1_BYTES(fb.width, fb.rows);
        /* each face: from above (0), in band bucket 1 + b, or nowhere */
        for (f = 0; f < nf; f++)
            owner[f] = (r8_u8)(rnd16() % (nbands + 3u));
        for (f = 0; f < NF; f++)
            next_m[f] = (r8_u16)rnd16();
        first = make_list(owner, 0, nf, next_m);
        for (k = 0; k < NB; k++)
            heads[k] = k < nbands ? make_list(owner, (r8_u8)(1u + k), nf, next_m) : (r8_u16)rnd16();
        for (k = 0; k < CALLS; k++)
            ans[k] = (r8_u8)(rnd16() % 3u);
        memcpy(next_k, next_m, sizeof next_k);
        for (k = 0; k < sizeof band_m; k++)
            band_m[k] = band_k[k] = (r8_u8)(rnd16() & 0xFFu);
        fb.buf = band_m + GUARD;
        want = model(first, &fb, nbands, band_m + GUARD);
        /* the model: the merged lists' unfinished faces, in order */
        f = want;
        for (k = 0; k < m_n; k++)
            if (ans[k] != 1) {
                TEST_ASSERT_EQUAL_INT(m_g[k], f);
                f = next_m[f];
                goes_on++;
            }
        TEST_ASSERT_EQUAL_INT(END, f);
        for (k = 1; k < m_n; k++)
            TEST_ASSERT_TRUE(m_g[k - 1] < m_g[k]);
#ifdef BZ_KERN
        memset(stb, 0x5A, sizeof stb);
        put16(stb + ST_NBANDS, nbands);
        {
            r8_u16 *p = next_k;
            memcpy(stb + ST_NEXT, &p, sizeof p);
            p = heads;
            memcpy(stb + ST_HEADS, &p, sizeof p);
        }
        put16(stb + ST_FIRST, first);
        put16(stb + ST_SLOT, 0);   /* no pool: every face through r8_band_face */
        r.state = stb;
        fb.buf = band_k + GUARD;
        ncall = 0;
        r8k_band(&r, &fb);
        TEST_ASSERT_EQUAL_INT(m_n, ncall);
        y1 = (r8_s16)(fb.y0 + fb.rows);
        if (y1 > fb.height)
            y1 = fb.height;
        for (k = 0; k < ncall; k++) {
            TEST_ASSERT_EQUAL_INT(m_g[k], log_g[k]);
            TEST_ASSERT_EQUAL_INT(fb.y0, log_y0[k]);
            TEST_ASSERT_EQUAL_INT(y1, log_y1[k]);
            TEST_ASSERT_TRUE(log_st[k] == (const void *)stb);
            TEST_ASSERT_TRUE(log_fb[k] == (const void *)&fb);
        }
        TEST_ASSERT_EQUAL_INT(want, get16(stb + ST_FIRST));
        TEST_ASSERT_EQUAL_MEMORY(next_m, next_k, sizeof next_k);
        TEST_ASSERT_EQUAL_MEMORY(band_m, band_k, sizeof band_m);
        for (k = 0; k < bytes; k++)
            TEST_ASSERT_EQUAL_INT(0, band_k[GUARD + k]);
#else
        (void)bytes;
#endif
        calls += m_n;
    }
    TEST_ASSERT_TRUE(calls > 1000u);
    TEST_ASSERT_TRUE(goes_on > 500u);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_band);
    return UNITY_END();
}
