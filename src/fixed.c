/* fixed.c - fixed-point helpers, trig table, vectors, matrices and the
 * perspective projection.  See r8fixed.h for the formats. */
#include "r8fixed.h"

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
    if (v >= 0)
        return v >> n;
    return ~((~v) >> n); /* floor for negatives, without a signed shift */
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
static const r8_s16 sin_q14[65] = {
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
        return sin_q14[q];
    case 1:
        return sin_q14[64 - q];
    case 2:
        return (r8_s16)-sin_q14[q];
    default:
        return (r8_s16)-sin_q14[64 - q];
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

void r8_mat_rotate(r8_mat3 *m, r8_u8 ax, r8_u8 ay, r8_u8 az)
{
    r8_mat3 rx, ry, rz, t;
    r8_s16 s, c;
    s = r8_sin(ax); c = r8_cos(ax);
    rx.m[0] = R8_ONE14; rx.m[1] = 0; rx.m[2] = 0;
    rx.m[3] = 0; rx.m[4] = c; rx.m[5] = (r8_s16)-s;
    rx.m[6] = 0; rx.m[7] = s; rx.m[8] = c;
    s = r8_sin(ay); c = r8_cos(ay);
    ry.m[0] = c; ry.m[1] = 0; ry.m[2] = s;
    ry.m[3] = 0; ry.m[4] = R8_ONE14; ry.m[5] = 0;
    ry.m[6] = (r8_s16)-s; ry.m[7] = 0; ry.m[8] = c;
    s = r8_sin(az); c = r8_cos(az);
    rz.m[0] = c; rz.m[1] = (r8_s16)-s; rz.m[2] = 0;
    rz.m[3] = s; rz.m[4] = c; rz.m[5] = 0;
    rz.m[6] = 0; rz.m[7] = 0; rz.m[8] = R8_ONE14;
    r8_mat_mul(&ry, &rz, &t);
    r8_mat_mul(&rx, &t, m);
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

void r8_camera_init(r8_camera *c, r8_s16 width, r8_s16 height, r8_s16 focal,
                    r8_s32 znear)
{
    c->cx = (r8_s16)(width * 8);  /* width/2 pixels in 12.4 */
    c->cy = (r8_s16)(height * 8);
    c->focal = focal;
    c->znear = znear;
    c->guard = 900;  /* |sx - cx| <= 900 px keeps 12.4 inside r8_s16 */
    c->xlimit = (r8_s32)2147483647L / r8_mul16(focal, R8_SUBPX);
}

/* focal * 16 * x / z, rounded; the fast path needs |x * f16| < 2^31. */
static r8_s16 proj1(const r8_camera *c, r8_s32 x, r8_s32 z)
{
    r8_s32 f16 = r8_mul16(c->focal, R8_SUBPX);
    if (x < c->xlimit && x > -c->xlimit)
        return r8_sat16(r8_divround(x * f16, z));
    return r8_sat16(r8_muldiv(x, f16, z));
}

void r8_project(const r8_camera *c, const r8_vec3l *v, r8_s16 *sx, r8_s16 *sy)
{
    *sx = r8_sat16((r8_s32)c->cx + proj1(c, v->x, v->z));
    *sy = r8_sat16((r8_s32)c->cy + proj1(c, v->y, v->z));
}
