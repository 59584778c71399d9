/* fixed.c - fixed-point helpers, trig table, vectors, matrices and the
 * perspective projection.  See r8fixed.h for the formats. */
#include "r8fixed.h"
#include "r8flash.h"

r8_s32 r8_mul16(r8_s16 a, r8_s16 b)
{
    r8_s32 p = a; /* not (long)a * (long)b: SDCC 4.2 z80 gets that wrong */
    p *= b;
    return p;
}

r8_s32 r8_asr14(r8_s32 v)
{
    /* floor(v / 2^14) from byte moves and short shifts: no 14-step
     * 32-bit shift loop on 8-bit CPUs */
    r8_s32 w = v >= 0 ? v : ~v;   /* ~v = -v - 1 >= 0 */
    w = ((w >> 16) << 2) | (r8_u8)((r8_u8)(w >> 8) >> 6);
    return v >= 0 ? w : ~w;
}

r8_s32 r8_asr32(r8_s32 v, r8_u8 n)
{
    /* floor for negatives without a signed shift (~v = -v - 1 >= 0);
     * whole bytes first, so a variable shift is at most 7 single steps
     * on 8-bit CPUs */
    r8_u32 u = v >= 0 ? (r8_u32)v : ~(r8_u32)v;
    if (n > 31)
        n = 31;
    if (n & 16)
        u >>= 16;
    if (n & 8)
        u >>= 8;
    u >>= (n & 7);
    return v >= 0 ? (r8_s32)u : (r8_s32)~u;
}

r8_s16 r8_sat16(r8_s32 v)
{
    if (v > 32767)
        return 32767;
    if (v < -32768L)
        return (r8_s16)(-32767 - 1);
    return (r8_s16)v;
}

r8_s16 r8_mulq(r8_s16 a, r8_s16 b, r8_u8 frac)
{
    r8_s32 p = r8_mul16(a, b);
    r8_s32 h = frac ? ((r8_s32)1 << (frac - 1)) : 0;
    if (p >= 0)
        p = (p + h) >> frac;
    else
        p = -((-p + h) >> frac); /* -p fits: |p| <= 2^30 */
    return r8_sat16(p);
}

r8_s32 r8_floordiv(r8_s32 n, r8_s32 d)
{
    if (n >= 0)
        return n / d;
    return -((-(n + 1)) / d) - 1;
}

r8_s32 r8_divround(r8_s32 n, r8_s32 d)
{
    r8_u32 un, ud, q, r;
    int neg = 0;
    if (n < 0) {
        un = (r8_u32)(-(n + 1)) + 1u;
        neg = 1;
    } else {
        un = (r8_u32)n;
    }
    if (d < 0) {
        ud = (r8_u32)(-(d + 1)) + 1u;
        neg = !neg;
    } else {
        ud = (r8_u32)d;
    }
    q = un / ud;
    r = un % ud;               /* one division routine gives both */
    if (r >= ud - r)
        q++;
    if (q > 0x7FFFFFFFUL)
        q = neg ? 0x80000000UL : 0x7FFFFFFFUL;
    return neg ? (r8_s32)(0u - q) : (r8_s32)q;
}

static r8_u32 uabs32(r8_s32 v)
{
    return v < 0 ? (r8_u32)(-(v + 1)) + 1u : (r8_u32)v;
}

r8_s32 r8_muldiv(r8_s32 a, r8_s32 b, r8_s32 c)
{
    /* 64-bit product in (hi, lo) from 16-bit halves, then a restoring
     * 64/32 division; slow, used only on the clipping path. */
    r8_u32 ua = uabs32(a), ub = uabs32(b), uc = uabs32(c);
    r8_u32 al = ua & 0xFFFFu, ah = ua >> 16, bl = ub & 0xFFFFu, bh = ub >> 16;
    r8_u32 lo, hi, mid1, mid2, t, q = 0, rem = 0;
    int neg = (a < 0) != (b < 0);
    int i;
    if (c < 0)
        neg = !neg;
    lo = al * bl;
    mid1 = al * bh;
    mid2 = ah * bl;
    hi = ah * bh;
    t = lo + (mid1 << 16);
    hi += (mid1 >> 16) + (t < lo);
    lo = t;
    t = lo + (mid2 << 16);
    hi += (mid2 >> 16) + (t < lo);
    lo = t;
    if (hi >= uc) /* quotient would not fit 32 bits */
        return neg ? (r8_s32)(-2147483647L - 1) : (r8_s32)2147483647L;
    rem = hi;
    for (i = 31; i >= 0; i--) {
        int carry = (rem & 0x80000000UL) != 0;
        rem = (rem << 1) | ((lo >> i) & 1u);
        q <<= 1;
        if (carry || rem >= uc) {
            rem -= uc;
            q |= 1u;
        }
    }
    if (q > 0x7FFFFFFFUL)
        return neg ? (r8_s32)(-2147483647L - 1) : (r8_s32)2147483647L;
    return neg ? -(r8_s32)q : (r8_s32)q;
}

r8_u16 r8_isqrt32(r8_u32 v)
{
    r8_u32 r = 0, bit = 0x40000000UL;
    while (bit > v)
        bit >>= 2;
    while (bit) {
        if (v >= r + bit) {
            v -= r + bit;
            r = (r >> 1) + bit;
        } else {
            r >>= 1;
        }
        bit >>= 2;
    }
    return (r8_u16)r;
}

/* round(16384 * sin(i * 2 pi / 256)), i = 0..64 */
static const r8_s16 sin_q14[65] R8_FLASH = {
    0, 402, 804, 1205, 1606, 2006, 2404, 2801,
    3196, 3590, 3981, 4370, 4756, 5139, 5520, 5897,
    6270, 6639, 7005, 7366, 7723, 8076, 8423, 8765,
    9102, 9434, 9760, 10080, 10394, 10702, 11003, 11297,
    11585, 11866, 12140, 12406, 12665, 12916, 13160, 13395,
    13623, 13842, 14053, 14256, 14449, 14635, 14811, 14978,
    15137, 15286, 15426, 15557, 15679, 15791, 15893, 15986,
    16069, 16143, 16207, 16261, 16305, 16340, 16364, 16379,
    16384
};

r8_s16 r8_sin(r8_u8 a)
{
    r8_u8 q = (r8_u8)(a & 0x3F);
    switch (a >> 6) {
    case 0:
        return R8_RDS16(&sin_q14[q]);
    case 1:
        return R8_RDS16(&sin_q14[64 - q]);
    case 2:
        return (r8_s16)-R8_RDS16(&sin_q14[q]);
    default:
        return (r8_s16)-R8_RDS16(&sin_q14[64 - q]);
    }
}

r8_s16 r8_cos(r8_u8 a)
{
    return r8_sin((r8_u8)(a + 64));
}

r8_s32 r8_dot3(const r8_vec3 *a, const r8_vec3 *b)
{
    return r8_mul16(a->x, b->x) + r8_mul16(a->y, b->y) + r8_mul16(a->z, b->z);
}

void r8_cross3(const r8_vec3 *a, const r8_vec3 *b, r8_vec3l *c)
{
    c->x = r8_mul16(a->y, b->z) - r8_mul16(a->z, b->y);
    c->y = r8_mul16(a->z, b->x) - r8_mul16(a->x, b->z);
    c->z = r8_mul16(a->x, b->y) - r8_mul16(a->y, b->x);
}

void r8_normalize(const r8_vec3l *v, r8_vec3 *out)
{
    r8_u32 m = uabs32(v->x), len2;
    r8_s32 x = v->x, y = v->y, z = v->z;
    r8_u16 len;
    r8_u8 sh = 0;
    if (uabs32(v->y) > m)
        m = uabs32(v->y);
    if (uabs32(v->z) > m)
        m = uabs32(v->z);
    if (m == 0) {
        out->x = out->y = out->z = 0;
        return;
    }
    while ((m >> sh) >= 0x4000u)
        sh++;
    if (sh) {
        x = r8_divround(x, (r8_s32)1 << sh);
        y = r8_divround(y, (r8_s32)1 << sh);
        z = r8_divround(z, (r8_s32)1 << sh);
    }
    len2 = (r8_u32)(x * x) + (r8_u32)(y * y) + (r8_u32)(z * z);
    len = r8_isqrt32(len2);
    if (len == 0)
        len = 1;
    out->x = (r8_s16)r8_divround(x * R8_ONE14, len);
    out->y = (r8_s16)r8_divround(y * R8_ONE14, len);
    out->z = (r8_s16)r8_divround(z * R8_ONE14, len);
}

/* round(a * b / 2^14) as r8_mat_mul rounds each entry */
static r8_s16 rmul(r8_s16 a, r8_s16 b)
{
    return r8_sat16(R8_ASR32C(R8_MUL16(a, b) + 8192, 14));
}

/* round((a * b + c * d) / 2^14), saturated */
static r8_s16 rmul2(r8_s16 a, r8_s16 b, r8_s16 c, r8_s16 d)
{
    return r8_sat16(R8_ASR32C(R8_MUL16(a, b) + R8_MUL16(c, d) + 8192, 14));
}

void r8_mat_rotate(r8_mat3 *m, r8_u8 ax, r8_u8 ay, r8_u8 az)
{
    /* Rx (Ry Rz) with the zero and one entries of each factor left out:
     * the same entries, rounded the same way, as two r8_mat_mul calls
     * on the three axis matrices, in 16 products instead of 54 */
    r8_s16 sa = r8_sin(ax), ca = r8_cos(ax), sb = r8_sin(ay), cb = r8_cos(ay);
    r8_s16 sc = r8_sin(az), cc = r8_cos(az);
    r8_s16 t0 = rmul(cb, cc), t1 = rmul(cb, (r8_s16)-sc);
    r8_s16 t6 = rmul((r8_s16)-sb, cc), t7 = rmul(sb, sc);
    /* Ry Rz = [t0 t1 sb; sc cc 0; t6 t7 cb] */
    m->m[0] = t0;
    m->m[1] = t1;
    m->m[2] = sb;
    m->m[3] = rmul2(ca, sc, (r8_s16)-sa, t6);
    m->m[4] = rmul2(ca, cc, (r8_s16)-sa, t7);
    m->m[5] = rmul((r8_s16)-sa, cb);
    m->m[6] = rmul2(sa, sc, ca, t6);
    m->m[7] = rmul2(sa, cc, ca, t7);
    m->m[8] = rmul(ca, cb);
}

void r8_mat_mul(const r8_mat3 *a, const r8_mat3 *b, r8_mat3 *c)
{
    r8_u8 i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            r8_s32 s = r8_mul16(a->m[i * 3], b->m[j]) +
                       r8_mul16(a->m[i * 3 + 1], b->m[3 + j]) +
                       r8_mul16(a->m[i * 3 + 2], b->m[6 + j]);
            c->m[i * 3 + j] = r8_sat16(r8_asr14(s + 8192));
        }
}

void r8_mat_apply(const r8_mat3 *m, const r8_vec3 *v, r8_vec3l *out)
{
    out->x = r8_asr14(r8_mul16(m->m[0], v->x) + r8_mul16(m->m[1], v->y) +
                      r8_mul16(m->m[2], v->z) + 8192);
    out->y = r8_asr14(r8_mul16(m->m[3], v->x) + r8_mul16(m->m[4], v->y) +
                      r8_mul16(m->m[5], v->z) + 8192);
    out->z = r8_asr14(r8_mul16(m->m[6], v->x) + r8_mul16(m->m[7], v->y) +
                      r8_mul16(m->m[8], v->z) + 8192);
}

void r8_mat_apply_t14(const r8_mat3 *m, const r8_vec3 *v, r8_vec3 *out)
{
    out->x = r8_sat16(r8_asr14(r8_mul16(m->m[0], v->x) + r8_mul16(m->m[3], v->y) +
                               r8_mul16(m->m[6], v->z) + 8192));
    out->y = r8_sat16(r8_asr14(r8_mul16(m->m[1], v->x) + r8_mul16(m->m[4], v->y) +
                               r8_mul16(m->m[7], v->z) + 8192));
    out->z = r8_sat16(r8_asr14(r8_mul16(m->m[2], v->x) + r8_mul16(m->m[5], v->y) +
                               r8_mul16(m->m[8], v->z) + 8192));
}

void r8_mat_apply16(const r8_mat3 *m, const r8_vec3 *v, r8_vec3l *out)
{
    /* Q1.14 * integer units, kept to 1/16 unit: (sum + 2^9) >> 10 */
    out->x = r8_asr32(r8_mul16(m->m[0], v->x) + r8_mul16(m->m[1], v->y) +
                      r8_mul16(m->m[2], v->z) + 512, 10);
    out->y = r8_asr32(r8_mul16(m->m[3], v->x) + r8_mul16(m->m[4], v->y) +
                      r8_mul16(m->m[5], v->z) + 512, 10);
    out->z = r8_asr32(r8_mul16(m->m[6], v->x) + r8_mul16(m->m[7], v->y) +
                      r8_mul16(m->m[8], v->z) + 512, 10);
}

void r8_mat_transpose(const r8_mat3 *a, r8_mat3 *c)
{
    r8_u8 i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++)
            c->m[i * 3 + j] = a->m[j * 3 + i];
}

/* round(2^31 / (32768 + 256 i)), i = 0..128 (the first clamped to 16 bits) */
static const r8_u16 rec_tab[129] R8_FLASH = {
    65535u, 65028u, 64528u, 64035u, 63550u, 63072u, 62602u, 62138u, 61681u, 61231u,
    60787u, 60350u, 59919u, 59494u, 59075u, 58662u, 58254u, 57852u, 57456u, 57065u,
    56680u, 56299u, 55924u, 55554u, 55188u, 54828u, 54471u, 54120u, 53773u, 53431u,
    53092u, 52759u, 52429u, 52103u, 51782u, 51464u, 51150u, 50840u, 50534u, 50231u,
    49932u, 49637u, 49345u, 49056u, 48771u, 48489u, 48210u, 47935u, 47663u, 47393u,
    47127u, 46864u, 46603u, 46346u, 46091u, 45839u, 45590u, 45344u, 45100u, 44859u,
    44620u, 44384u, 44151u, 43919u, 43691u, 43464u, 43240u, 43019u, 42799u, 42582u,
    42367u, 42154u, 41943u, 41734u, 41528u, 41323u, 41121u, 40920u, 40721u, 40525u,
    40330u, 40137u, 39946u, 39756u, 39569u, 39383u, 39199u, 39017u, 38836u, 38657u,
    38480u, 38304u, 38130u, 37958u, 37787u, 37617u, 37449u, 37283u, 37118u, 36954u,
    36792u, 36631u, 36472u, 36314u, 36158u, 36003u, 35849u, 35696u, 35545u, 35395u,
    35246u, 35099u, 34953u, 34808u, 34664u, 34521u, 34380u, 34239u, 34100u, 33962u,
    33825u, 33689u, 33554u, 33421u, 33288u, 33157u, 33026u, 32897u, 32768u
};

r8_u16 r8_recip(r8_s32 z, r8_s8 *e)
{
    r8_s8 s = 0;
    r8_u16 zn, t0, t1;
    r8_u8 i;
    /* normalise to [2^15, 2^16): whole bytes first */
    if (z >= 0x10000L) {
        r8_u32 u = (r8_u32)z;
        while (u >= 0x1000000UL) {
            u >>= 8;
            s = (r8_s8)(s - 8);
        }
        while (u >= 0x10000UL) {
            u >>= 1;
            s--;
        }
        zn = (r8_u16)u;
    } else {
        zn = (r8_u16)(z > 0 ? z : 1);
        if (zn < 0x80u) {
            zn = (r8_u16)(zn << 8);
            s = 8;
        }
        while (zn < 0x8000u) {
            zn = (r8_u16)(zn << 1);
            s++;
        }
    }
    i = (r8_u8)((zn >> 8) & 0x7Fu);
    t0 = R8_RDU16(&rec_tab[i]);
    t1 = R8_RDU16(&rec_tab[i + 1]);
    *e = s;
    /* linear interpolation on 7 fraction bits: (t0 - t1) < 512 */
    return (r8_u16)(t0 - (r8_u16)(((r8_u16)(t0 - t1) * (r8_u16)((zn & 0xFFu) >> 1) + 64u) >> 7));
}

void r8_proj_init(r8_proj *p, r8_s16 width, r8_s16 height, r8_s16 focal,
                  r8_s32 znear)
{
    r8_s16 f = (r8_s16)(focal * R8_SUBPX);
    p->cx = (r8_s16)(width * 8);  /* width/2 pixels in 12.4 */
    p->cy = (r8_s16)(height * 8);
    p->focal = focal;
    p->znear = znear;
    p->guard = 900;  /* |sx - cx| <= 900 px keeps 12.4 inside r8_s16 */
    p->fsh = 0;
    while (f < 0x4000) {
        f = (r8_s16)(f << 1);
        p->fsh++;
    }
    p->fn = f;
}

/* What the rounding shift by sh needs: 2^(sh-1) + 2^31 (added) and
 * 2^31 >> sh (taken off after the shift), sh = 1..31. */
typedef struct rshift {
    r8_u32 add, bias;
    r8_u8 sh;
} rshift;

static void rshift_init(rshift *r, r8_u8 sh)
{
    r8_u32 b = 0x80000000UL, h = 1;   /* 2^31 >> sh, 2^(sh-1): bytes first */
    r8_u8 n = (r8_u8)(sh - 1);
    if (sh & 16)
        b >>= 16;
    if (sh & 8)
        b >>= 8;
    b >>= (sh & 7);
    if (n & 16)
        h <<= 16;
    if (n & 8)
        h <<= 8;
    h <<= (n & 7);
    r->sh = sh;
    r->bias = b;
    r->add = h + 0x80000000UL;
}

/* floor((v + 2^(sh-1)) / 2^sh): whole bytes first */
static r8_s32 rshift_do(const rshift *r, r8_s32 v)
{
    r8_u32 u = (r8_u32)v + r->add;
    r8_u8 n = r->sh;
    if (n & 16)
        u >>= 16;
    if (n & 8)
        u >>= 8;
    u >>= (n & 7);
    return (r8_s32)(u - r->bias);
}

/* round(c * kk * 2^-sh) for one coordinate c; 1 if beyond `lim`. */
static int proj1(r8_s32 c, r8_s16 kk, const rshift *rs, r8_s16 lim, r8_s16 *q)
{
    r8_s32 v;
    if ((r8_u32)(c + 32767) > 65534UL) {
        /* a coordinate over 2047 units: scale it (and the shift) down */
        int sh = rs->sh;
        rshift r2;
        while (c >= 32768L || c < -32768L) {
            c = R8_ASR32C(c, 1);
            sh--;
        }
        if (sh <= 0)
            return 1;           /* |q| >= 2^14: far outside any guard band */
        rshift_init(&r2, (r8_u8)sh);
        v = rshift_do(&r2, R8_MUL16(c, kk));
    } else {
        v = rshift_do(rs, R8_MUL16(c, kk));
    }
    if (v > lim || v < -lim)
        return 1;
    *q = (r8_s16)v;
    return 0;
}

int r8_project(const r8_proj *p, const r8_vec3l *v, r8_s16 *sx, r8_s16 *sy)
{
    r8_s8 e;
    r8_u16 m = r8_recip(v->z, &e);
    return r8_project_recip(p, v, m, e, sx, sy);
}

int r8_project_recip(const r8_proj *p, const r8_vec3l *v, r8_u16 m, r8_s8 e,
                     r8_s16 *sx, r8_s16 *sy)
{
    r8_u32 k = (r8_u32)m * (r8_u16)p->fn;   /* [2^29, 2^31) */
    r8_s16 kk, qx, qy, lim = (r8_s16)(p->guard * R8_SUBPX);
    int sh = 31 + p->fsh - e;
    rshift rs;
    /* 16 * focal / z = kk * 2^-sh with kk in [2^14, 2^15) */
    if (k >= 0x40000000UL) {
        kk = (r8_s16)(k >> 16);
        sh -= 16;
    } else {
        kk = (r8_s16)(k >> 15);
        sh -= 15;
    }
    if (sh <= 0) {
        /* z below 1/4 of the focal length's scale: only the axis itself
         * projects inside the guard band */
        if (v->x || v->y)
            return 1;
        *sx = p->cx;
        *sy = p->cy;
        return 0;
    }
    if (sh > 31)
        sh = 31;
    rshift_init(&rs, (r8_u8)sh);
    if (proj1(v->x, kk, &rs, lim, &qx) || proj1(v->y, kk, &rs, lim, &qy))
        return 1;
    *sx = (r8_s16)(p->cx + qx);
    *sy = (r8_s16)(p->cy + qy);
    return 0;
}
