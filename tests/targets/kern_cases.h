/* kern_cases.h - the random cases the AVR and Z80 kernel tests share
 * (tests/targets/test_avr_kern.c, test_z80_kern.c): the r8k_xform
 * test, and the r8k_edge and r8k_project tests, each kernel against
 * its C reference (r8k_edge_ref, r8k_project_ref) on the same random
 * inputs.  The including file defines rnd(), rndn(), rnds(),
 * print_case(), XFORM_CASES, EDGE_CASES, PROJ_CASES and KERN_CODE_PTR()
 * (a random pointer into the program's code, for r8k_xform's inputs),
 * and includes <string.h>, unity.h, r8kern.h and r8flash.h first. */
#ifndef KERN_CASES_H
#define KERN_CASES_H

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
    unsigned j;
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
            v = KERN_CODE_PTR();   /* the program's own bytes */
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

/* ---- r8k_edge ---- */

static r8_s16 clamp16(r8_s32 v)
{
    if (v > 32767L)
        return 32767;
    if (v < -32768L)
        return R8_S16_MIN;
    return (r8_s16)v;
}

static void print_count(const char *what, unsigned long n)
{
    unity_print("  ");
    unity_print(what);
    unity_print(" ");
    unity_print_long((long)n);
    unity_print("\n");
}

/* classes of edges: a[1] < b[1] (the contract), otherwise anything */
static void rnd_edge(r8_s16 *a, r8_s16 *b)
{
    unsigned c = rndn(16);
    r8_s32 ay, dy, ax, dx;
    if (c < 11)
        ay = rnds(-300, 1300);
    else if (c < 13)
        ay = rnds(32744, 32766);           /* y0 = 2048 past 32760 */
    else if (c < 14)
        ay = rnds(R8_S16_MIN, -32700);
    else
        ay = (r8_s16)rnd();
    c = rndn(16);
    if (c < 3)
        dy = 1;
    else if (c < 7)
        dy = 1 + rndn(48);
    else if (c < 12)
        dy = 1 + rndn(1423);
    else if (c < 15)
        dy = 1414 + rndn(20);              /* the 1424 limit */
    else
        dy = 1 + (r8_s32)(rnd() & 0x7FFF);
    c = rndn(16);
    if (c < 9)
        ax = rnds(-400, 2400);
    else if (c < 12)
        ax = (c & 1 ? -16384 : 16383) + rnds(-3, 3);
    else if (c < 15)
        ax = rnds(-16384, 16383);
    else
        ax = (r8_s16)rnd();
    c = rndn(16);
    if (c < 2) {
        dx = 0;
    } else if (c < 8) {
        dx = rnds(-40, 40) + (r8_s32)rnds(-3, 3) * dy;
    } else if (c < 10) {
        /* |q| near 2048: short rows, x near the middle */
        dy = 1 + rndn(7);
        ax = rnds(-1500, 1500);
        dx = 2048L * dy + rnds((r8_s16)(-dy - 2), (r8_s16)(dy + 2));
        if (rndn(2))
            dx = -dx;
    } else if (c < 11) {
        /* ax - 8 + s0 q beyond 16 bits: s0 >= 12, q near +-2048, ax far
         * out on the same side */
        ay = (ay & ~15L) + 9 + rndn(4);
        dy = 1;
        ax = 9400 + rndn(4600);
        dx = 1950 + rndn(98);
        if (rndn(2)) {
            ax = -ax;
            dx = -dx;
        }
    } else if (c < 15) {
        dx = rnds(-16000, 16000);
    } else {
        dx = (r8_s16)rnd() - ax;
    }
    if (ay + dy > 32767L)
        dy = 32767L - ay;
    a[0] = (r8_s16)ax;
    a[1] = (r8_s16)ay;
    b[0] = clamp16(ax + dx);
    b[1] = (r8_s16)(ay + dy);
}

static void test_edge_random(void)
{
    unsigned long i, n_wide = 0, n_wdy = 0, n_wx = 0, n_wq = 0, n_neg = 0, n_dx0 = 0,
        n_dy1 = 0, n_steep = 0, n_xlim = 0, n_ytop = 0, n_q0 = 0, n_long = 0, n_x17 = 0;
    for (i = 0; i < EDGE_CASES; i++) {
        static r8_s16 a[2], b[2];
        r8_interp ia, ir;
        r8_s16 ya, yr;
        r8_s32 dx, x17;
        rnd_edge(a, b);
        if (a[1] >= b[1]) {
            b[1] = (r8_s16)(a[1] + 1);     /* a[1] = 32767 cannot be an edge top */
            if (a[1] == 32767) {
                a[1] = 32766;
                b[1] = 32767;
            }
        }
        memset(&ia, (int)(i & 0xFF), sizeof ia);
        memset(&ir, (int)(i & 0xFF), sizeof ir);
        yr = r8k_edge_ref(&ir, a, b);
        ya = r8k_edge(&ia, a, b);
        if (ya != yr || memcmp(&ia, &ir, sizeof ia) != 0) {
            print_case("r8k_edge", i);
            unity_print("a ");
            unity_print_long(a[0]);
            unity_print(" ");
            unity_print_long(a[1]);
            unity_print(" b ");
            unity_print_long(b[0]);
            unity_print(" ");
            unity_print_long(b[1]);
            unity_print("\n");
            TEST_ASSERT_EQUAL_INT16(yr, ya);
            TEST_ASSERT_EQUAL_INT16(ir.val, ia.val);
            TEST_ASSERT_EQUAL_INT16(ir.q, ia.q);
            TEST_ASSERT_EQUAL_UINT16(ir.err, ia.err);
            TEST_ASSERT_EQUAL_UINT16(ir.r, ia.r);
            TEST_ASSERT_EQUAL_UINT16(ir.den, ia.den);
            TEST_FAIL_MESSAGE("r8k_edge differs from the reference");
        }
        dx = (r8_s32)b[0] - a[0];
        if (yr == R8_EDGE_WIDE) {
            n_wide++;
            if ((r8_u16)(b[1] - a[1]) >= 1424u)
                n_wdy++;
            else if (a[0] < -16384 || a[0] > 16383 || b[0] < -16384 || b[0] > 16383)
                n_wx++;
            else
                n_wq++;
            continue;
        }
        n_neg += dx < 0;
        n_dx0 += dx == 0;
        n_dy1 += ir.den == 1;
        n_steep += ir.q >= 1900 || ir.q <= -1900;
        n_q0 += ir.q == 0 || ir.q == -1;
        n_xlim += a[0] < -16380 || a[0] > 16379 || b[0] < -16380 || b[0] > 16379;
        n_ytop += a[1] > 32760;
        n_long += ir.den >= 1000;
        x17 = a[0] - 8 + (r8_s32)((8 - a[1]) & 15) * ir.q;
        n_x17 += x17 < -32768L || x17 > 32767L;
    }
    unity_print("r8k_edge: ");
    unity_print_long((long)i);
    unity_print(" cases\n");
    print_count("wide, dy >= 1424:", n_wdy);
    print_count("wide, x outside +-16384:", n_wx);
    print_count("wide, |q| >= 2048:", n_wq);
    print_count("dx < 0:", n_neg);
    print_count("dx = 0:", n_dx0);
    print_count("dy = 1:", n_dy1);
    print_count("|q| >= 1900:", n_steep);
    print_count("q = 0 or -1:", n_q0);
    print_count("x within 4 of +-16384:", n_xlim);
    print_count("a[1] > 32760 (y0 = 2048):", n_ytop);
    print_count("dy >= 1000:", n_long);
    print_count("ax - 8 + s0 q beyond 16 bits:", n_x17);
    TEST_ASSERT_GREATER_THAN(EDGE_CASES / 200, n_wdy);
    TEST_ASSERT_GREATER_THAN(EDGE_CASES / 200, n_wx);
    TEST_ASSERT_GREATER_THAN(EDGE_CASES / 200, n_wq);
    TEST_ASSERT_GREATER_THAN(EDGE_CASES / 10, n_neg);
    TEST_ASSERT_GREATER_THAN(EDGE_CASES / 100, n_dx0);
    TEST_ASSERT_GREATER_THAN(EDGE_CASES / 100, n_dy1);
    TEST_ASSERT_GREATER_THAN(EDGE_CASES / 200, n_steep);
    TEST_ASSERT_GREATER_THAN(EDGE_CASES / 100, n_q0);
    TEST_ASSERT_GREATER_THAN(EDGE_CASES / 200, n_xlim);
    TEST_ASSERT_GREATER_THAN(EDGE_CASES / 200, n_ytop);
    TEST_ASSERT_GREATER_THAN(EDGE_CASES / 100, n_long);
    TEST_ASSERT_GREATER_THAN(EDGE_CASES / 200, n_x17);
    TEST_ASSERT_LESS_THAN(EDGE_CASES / 2, n_wide);
}

/* ---- r8k_project ---- */

static r8_s32 rnd_coord(r8_s32 z, r8_s16 focal)
{
    unsigned c = rndn(20);
    if (c < 10 && z > 0) {
        /* about u pixels off the axis: around the guard band */
        r8_s32 zf = z / focal;
        if (zf < 1000000L)
            return zf * (c & 1 ? rnds(-1100, 1100) : rnds(-80, 80)) + rnds(-40, 40);
    }
    if (c < 12)
        return 0;
    if (c < 15)
        return rnds(-3000, 3000);
    if (c < 17)
        return rndn(2) ? 32767L - (r8_s32)rndn(4) : -32767L + (r8_s32)rndn(4) - 1;
    if (c < 18)
        return (r8_s32)(rnd() & 0x3FFFFUL) - 0x20000L;
    return (r8_s32)rnd();
}

static r8_s32 rnd_z(void)
{
    unsigned c = rndn(24);
    if (c < 3)
        return 1 + (r8_s32)rndn(255);
    if (c < 15)
        return 256 + (r8_s32)rndn(65280u);
    if (c < 16)
        return 65534L + (r8_s32)rndn(4);    /* around 2^16 */
    if (c < 19)
        return 65536L + (r8_s32)(rnd() & 0xFFFFFUL);
    if (c < 21)
        return (r8_s32)(rnd() & 0x7FFFFFFFUL);
    if (c < 22)
        return 0x7FFFFFFFL - (r8_s32)rndn(4);
    if (c < 23)
        return (r8_s32)rndn(3);             /* 0, 1, 2 */
    return -(r8_s32)(rnd() & 0x7FFFFFFFUL); /* z <= 0 (the reference takes 1) */
}

static void test_project_random(void)
{
    unsigned long i, n_ok = 0, n_out = 0, n_wide = 0, n_shz = 0, n_shz0 = 0, n_sh31 = 0,
        n_zbig = 0, n_zle0 = 0, n_lim = 0, n_x32 = 0, n_m32768 = 0, n_limhi = 0, n_limneg = 0,
        n_anyfn = 0;
    static r8_proj p;
    for (i = 0; i < PROJ_CASES; i++) {
        static r8_vec3l c, c0;
        static r8_proj p0;
        r8_s16 oa[3], or_[3], focal;
        r8_u16 ma, mr;
        r8_s8 ea, er;
        int ra, rr, sh, big;
        r8_s16 lim;
        unsigned k = rndn(16);
        if (k < 4)
            focal = 128;
        else if (k < 9)
            focal = (r8_s16)(1 + rndn(2047));
        else if (k < 12)
            focal = (r8_s16)(1025 + rndn(1023));   /* fsh 0: sh <= 0 possible */
        else
            focal = (r8_s16)(1 + rndn(64));        /* large fsh: sh > 31 */
        r8_proj_init(&p, 128, 64, focal, 16);
        k = rndn(16);
        if (k < 8)
            p.guard = 900;
        else if (k < 10)
            p.guard = (r8_s16)rndn(1024);
        else if (k < 12)
            p.guard = rnds(1018, 1029);             /* lim across 0x3FFF */
        else if (k < 14)
            p.guard = rnds(1024, 2047);             /* the C path */
        else if (k < 15)
            p.guard = rnds(-40, -1);
        else
            p.guard = (r8_s16)rndn(4);
        if (rndn(8) == 0) {
            p.cx = (r8_s16)rnd();
            p.cy = (r8_s16)rnd();
        }
        if (rndn(16) == 0) {
            /* not from r8_proj_init: any fn (kk of either sign), fsh */
            p.fn = (r8_s16)rnd();
            p.fsh = (r8_u8)rnd();
            n_anyfn++;
        }
        c.z = rnd_z();
        if (rndn(16) == 0) {
            /* the axis itself near z = 1 (sh <= 0 with focal > 1024) */
            c.z = (r8_s32)rndn(3) - 1;
            c.x = rndn(2) ? 0 : rnds(-2, 2);
            c.y = rndn(2) ? 0 : rnds(-2, 2);
        } else {
            c.x = rnd_coord(c.z, focal);
            c.y = rnd_coord(c.z, focal);
        }
        c0 = c;
        p0 = p;
        oa[0] = or_[0] = (r8_s16)rnd();
        oa[1] = or_[1] = (r8_s16)rnd();
        oa[2] = or_[2] = (r8_s16)rnd();
        ma = mr = (r8_u16)rnd();
        ea = er = (r8_s8)rnd();
        rr = r8k_project_ref(&p, &c, or_, &mr, &er);
        ra = r8k_project(&p, &c, oa, &ma, &ea);
        if (ra != rr || memcmp(oa, or_, sizeof oa) != 0 || ma != mr || ea != er ||
            memcmp(&c, &c0, sizeof c) != 0 || memcmp(&p, &p0, sizeof p) != 0) {
            print_case("r8k_project", i);
            unity_print("x ");
            unity_print_long(c.x);
            unity_print(" y ");
            unity_print_long(c.y);
            unity_print(" z ");
            unity_print_long(c.z);
            unity_print(" focal ");
            unity_print_long(p.focal);
            unity_print(" guard ");
            unity_print_long(p.guard);
            unity_print("\n");
            TEST_ASSERT_EQUAL_UINT16(mr, ma);
            TEST_ASSERT_EQUAL_INT8(er, ea);
            TEST_ASSERT_EQUAL_INT(rr, ra);
            TEST_ASSERT_EQUAL_INT16(or_[0], oa[0]);
            TEST_ASSERT_EQUAL_INT16(or_[1], oa[1]);
            TEST_ASSERT_EQUAL_INT16(or_[2], oa[2]);
            TEST_FAIL_MESSAGE("r8k_project changed c or p");
        }
        /* which path the reference took */
        sh = 31 + p.fsh - er;
        sh -= (r8_u16)(((r8_u32)mr * (r8_u16)p.fn) >> 16) >= 0x4000u ? 16 : 15;
        lim = (r8_s16)(p.guard * 16);
        big = c.x < -32767L || c.x > 32767L || c.y < -32767L || c.y > 32767L;
        n_ok += rr == 0;
        n_out += rr != 0;
        n_zbig += c.z >= 0x10000L;
        n_zle0 += c.z <= 0;
        if (sh <= 0) {
            n_shz++;
            n_shz0 += rr == 0;
            continue;
        }
        n_sh31 += sh > 31;
        if (big || lim >= 0x3FFF) {
            /* the reference's proj_wide: the kernel's own code when x and
             * y fit 16 bits, else r8_project_recip */
            n_wide++;
            n_x32 += c.x < -32768L || c.x > 32767L || c.y < -32768L || c.y > 32767L;
            n_m32768 += c.x == -32768L || c.y == -32768L;
            n_limhi += !big && lim >= 0x3FFF;
        } else {
            n_lim += lim > 16300;
            n_limneg += lim < 0;
        }
    }
    unity_print("r8k_project: ");
    unity_print_long((long)i);
    unity_print(" cases\n");
    print_count("inside (0):", n_ok);
    print_count("outside (1):", n_out);
    print_count("z >= 2^16:", n_zbig);
    print_count("z <= 0:", n_zle0);
    print_count("sh <= 0:", n_shz);
    print_count("sh <= 0, on the axis (0):", n_shz0);
    print_count("sh > 31:", n_sh31);
    print_count("reference's proj_wide (lim >= 0x3FFF or |x|, |y| > 32767):", n_wide);
    print_count("  x or y beyond 16 bits (kernel's C call):", n_x32);
    print_count("  x or y = -32768:", n_m32768);
    print_count("  x, y in 16 bits, lim >= 0x3FFF:", n_limhi);
    print_count("proj_round, lim in 16301..16382:", n_lim);
    print_count("proj_round, lim < 0:", n_limneg);
    print_count("random fn, fsh:", n_anyfn);
    TEST_ASSERT_GREATER_THAN(PROJ_CASES / 5, n_ok);
    TEST_ASSERT_GREATER_THAN(PROJ_CASES / 5, n_out);
    TEST_ASSERT_GREATER_THAN(PROJ_CASES / 20, n_zbig);
    TEST_ASSERT_GREATER_THAN(PROJ_CASES / 100, n_zle0);
    TEST_ASSERT_GREATER_THAN(PROJ_CASES / 500, n_shz);
    TEST_ASSERT_GREATER_THAN(PROJ_CASES / 2000, n_shz0);
    TEST_ASSERT_GREATER_THAN(PROJ_CASES / 100, n_sh31);
    TEST_ASSERT_GREATER_THAN(PROJ_CASES / 20, n_x32);
    TEST_ASSERT_GREATER_THAN(PROJ_CASES / 500, n_m32768);
    TEST_ASSERT_GREATER_THAN(PROJ_CASES / 50, n_limhi);
    TEST_ASSERT_GREATER_THAN(PROJ_CASES / 200, n_lim);
    TEST_ASSERT_GREATER_THAN(PROJ_CASES / 200, n_limneg);
}

#endif
