/* test_wirek.c - the wire encoder's kernels (src/r8crc.h): on AVR the
 * assembly of ports/avr/wire_avr.S (Z80: ports/z80/wire_z80.s, with
 * Z80_ASM's wire) against its C89 reference (the *_c functions),
 * elsewhere the C versions; on every target both against a
 * plain model of each kernel's contract, on random inputs. */
#include "unity.h"
#include "../../src/r8crc.h"

void setUp(void) {}
void tearDown(void) {}

static r8_u32 seed = 12345;
static r8_u8 rnd8(void)
{
    seed = seed * 1103515245ul + 12345ul;
    return (r8_u8)((seed >> 16) & 0xFFu);
}
static r8_u16 rnd16(void)
{
    r8_u16 v = rnd8();
    return (r8_u16)((v << 8) | rnd8());
}

#define N 300
static r8_u8 src[N + 2];
static r8_u8 pkt[400], out_a[400], out_b[400];

/* Random bytes with runs: kind 0 few zeros, 1 many zeros and runs. */
static void fill(r8_u8 *p, unsigned n, unsigned kind)
{
    unsigned i = 0, k, len;
    r8_u8 v;
    while (i < n) {
        len = 1u + rnd8() % (kind ? 40u : 4u);
        v = rnd8();
        if (kind && (v & 1u))
            v = 0;
        for (k = 0; k < len && i < n; k++, i++)
            p[i] = (rnd8() & 3u) ? v : rnd8();
    }
}

/* The band CRC from 0 and Fletcher sums of p[0..n), the model. */
static void model_sums(const r8_u8 *p, unsigned n, r8_u16 *g, r8_u8 *f1, r8_u8 *f2)
{
    while (n--) {
        *g = r8_crc16_update_c(*g, p, 1);
        *f1 = (r8_u8)(*f1 + *p++);
        *f2 = (r8_u8)(*f2 + *f1);
    }
}

static void test_crc_kernels(void)
{
    unsigned i, n;
    r8_u16 c, a, b, r, bit;
    for (i = 0; i < 400; i++) {
        fill(src, N, i & 1u);
        n = rnd8() + (i & 1u) * 40u;
        c = rnd16();
        TEST_ASSERT_EQUAL_HEX16(r8_crc16_update_c(c, src, n), r8_crc16_update(c, src, n));
        a = rnd16();
        b = rnd16();
        if (i < 16)
            a = (r8_u16)(1u << i);
        /* the model: shift and add, most significant bit first */
        r = 0;
        for (bit = 0x8000u; bit; bit >>= 1) {
            if (r & 0x8000u)
                r = (r8_u16)((unsigned)(r << 1) ^ 0x1021u);
            else
                r = (r8_u16)(r << 1);
            if (b & bit)
                r ^= a;
        }
        TEST_ASSERT_EQUAL_HEX16(r, r8_crc16_mul_c(a, b));
        TEST_ASSERT_EQUAL_HEX16(r, r8_crc16_mul(a, b));
    }
    TEST_ASSERT_EQUAL_HEX16(0x29B1, r8_crc16_update(0xFFFFu, (const r8_u8 *)"123456789", 9));
}

static void test_zeros(void)
{
    unsigned i, n, z, k;
    for (i = 0; i < 400; i++) {
        n = 1u + (rnd8() % 2u ? rnd8() : rnd16() % N);
        z = rnd16() % (n + 1u);
        for (k = 0; k < n; k++)
            src[k] = k < z ? 0 : (r8_u8)(rnd8() | (k == z));
        TEST_ASSERT_EQUAL_UINT(z, r8_tx_zeros_c(src, n));
        TEST_ASSERT_EQUAL_UINT(z, r8_tx_zeros(src, n));
    }
    TEST_ASSERT_EQUAL_UINT(0, r8_tx_zeros(src, 0));
}

static void st_init(r8_tx_st *s)
{
    s->crc = rnd16();
    s->f1 = rnd8();
    s->f2 = rnd8();
    s->g = (rnd8() & 3u) ? rnd16() : 0;
    s->pkt = pkt;
    s->code = pkt;
}

static void test_run(void)
{
    r8_tx_st a, b;
    unsigned i, k, c;
    r8_u8 v;
    r8_u16 g;
    r8_u8 f1, f2;
    for (i = 0; i < 500; i++) {
        v = (rnd8() & 1u) ? 0 : rnd8();
        k = 3u + rnd8() % 125u;
        for (c = 0; c < k + 2u; c++)
            src[c] = v;
        c = 3u + rnd8() % (k - 2u); /* the run ends at c (or k) */
        src[c] = (r8_u8)(v + 1u + rnd8() % 255u);
        st_init(&a);
        b = a;
        c = r8_tx_run_c(&a, out_a, src, (r8_u8)k);
        TEST_ASSERT_EQUAL_UINT(c, r8_tx_run(&b, out_b, src, (r8_u8)k));
        TEST_ASSERT_EQUAL_HEX16(a.crc, b.crc);
        TEST_ASSERT_EQUAL_HEX16(a.g, b.g);
        TEST_ASSERT_EQUAL_HEX8(a.f1, b.f1);
        TEST_ASSERT_EQUAL_HEX8(a.f2, b.f2);
        TEST_ASSERT_EQUAL_MEMORY(out_a, out_b, 2);
        /* the contract */
        TEST_ASSERT_TRUE(c >= 3u && c <= k);
        TEST_ASSERT_TRUE(c == k || src[c] != v);
        TEST_ASSERT_EQUAL_HEX8(c, out_b[0]);
        TEST_ASSERT_EQUAL_HEX8(v, out_b[1]);
        /* again, against the model */
        st_init(&a);
        b = a;
        g = a.g;
        f1 = a.f1;
        f2 = a.f2;
        r8_tx_run(&b, out_b, src, (r8_u8)k);
        model_sums(src, c, &g, &f1, &f2);
        TEST_ASSERT_EQUAL_HEX16(r8_crc16_update_c(a.crc, out_b, 2), b.crc);
        TEST_ASSERT_EQUAL_HEX16(g, b.g);
        TEST_ASSERT_EQUAL_HEX8(f1, b.f1);
        TEST_ASSERT_EQUAL_HEX8(f2, b.f2);
    }
}

static void test_lit(void)
{
    r8_tx_st a, b, m;
    unsigned i, k, c, n, l, j, run;
    r8_u16 g;
    r8_u8 f1, f2, ra, rb;
    for (i = 0; i < 600; i++) {
        n = 1u + rnd8() % 140u; /* bytes left in the band */
        fill(src, n, i % 3u == 0);
        if (n >= 3u && src[1] == src[0] && src[2] == src[0])
            src[1] ^= 0x40; /* no run at p */
        c = n < 127u ? n : 127u;
        k = n >= 129u ? 127u : (n >= 2u ? n - 2u : 0u);
        if (k > c)
            k = c;
        if (i % 5u == 4u && c > 1u) { /* fewer literals allowed (room) */
            c = 1u + rnd8() % (c - 1u);
            if (k > c)
                k = c;
        }
        /* the COBS chain: its last code sometimes far back */
        for (j = 0; j < sizeof pkt; j++)
            pkt[j] = out_a[j] = out_b[j] = 0xEE;
        st_init(&a);
        if (rnd8() & 1u)
            a.code = pkt + 258; /* near */
        else /* far: a block may get too long for the chain */
            a.code = pkt + 8 + rnd8() % 16u;
        if (i % 7u == 3u)
            a.code = 0; /* the chain has stopped */
        b = a;
        m = a;
        ra = r8_tx_lit_c(&a, pkt + 262, src, (r8_u8)k, (r8_u8)c);
        for (j = 0; j < sizeof pkt; j++) {
            out_a[j] = pkt[j];
            pkt[j] = 0xEE;
        }
        rb = r8_tx_lit(&b, pkt + 262, src, (r8_u8)k, (r8_u8)c);
        TEST_ASSERT_EQUAL_HEX8(ra, rb);
        TEST_ASSERT_EQUAL_HEX16(a.crc, b.crc);
        TEST_ASSERT_EQUAL_HEX16(a.g, b.g);
        TEST_ASSERT_EQUAL_HEX8(a.f1, b.f1);
        TEST_ASSERT_EQUAL_HEX8(a.f2, b.f2);
        TEST_ASSERT_TRUE(a.code == b.code);
        TEST_ASSERT_EQUAL_MEMORY(out_a, pkt, sizeof pkt);
        /* the contract: L up to the first run of 3 among k positions */
        l = rb & 0x7Fu;
        for (run = c, j = 0; j < k; j++)
            if (src[j + 1] == src[j] && src[j + 2] == src[j]) {
                run = j;
                break;
            }
        TEST_ASSERT_EQUAL_UINT(run, l);
        TEST_ASSERT_EQUAL_HEX8(0x80u | l, pkt[262]);
        g = m.g;
        f1 = m.f1;
        f2 = m.f2;
        model_sums(src, l, &g, &f1, &f2);
        TEST_ASSERT_EQUAL_HEX16(g, b.g);
        TEST_ASSERT_EQUAL_HEX8(f1, b.f1);
        TEST_ASSERT_EQUAL_HEX8(f2, b.f2);
        /* the packet CRC over [count, literals], zeros as they were */
        for (j = 0; j < l; j++)
            out_b[j] = src[j];
        TEST_ASSERT_EQUAL_HEX16(r8_crc16_update_c(r8_crc16_update_c(m.crc, pkt + 262, 1), out_b, l),
                                b.crc);
        /* the literals; each 0x00 linked (the code before it points at
         * it) unless the chain stopped */
        for (j = 0; j < l; j++)
            if (src[j])
                TEST_ASSERT_EQUAL_HEX8(src[j], pkt[263 + j]);
        if (m.code && !(rb & 0x80u))
            for (j = 0; j < l; j++)
                if (!src[j]) {
                    TEST_ASSERT_EQUAL_UINT((unsigned)(pkt + 263 + j - m.code), *m.code);
                    m.code = pkt + 263 + j;
                }
        TEST_ASSERT_TRUE(m.code == b.code || (rb & 0x80u));
        TEST_ASSERT_EQUAL_HEX8(0xEE, pkt[263 + l]); /* nothing written past */
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_crc_kernels);
    RUN_TEST(test_zeros);
    RUN_TEST(test_run);
    RUN_TEST(test_lit);
    return UNITY_END();
}
