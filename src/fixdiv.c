/* fixdiv.c - 32-bit divisions and what needs them: floor and rounded
 * division, the exact a * b / c, integer square root, normalising a
 * vector.  Init-time and clipping paths only (a firmware that clips
 * nothing and brings its normals links none of this). */
#include "r8fixed.h"

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
