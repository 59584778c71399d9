/* proj.c - the perspective projection: a reciprocal from a table in
 * flash with linear interpolation, then three 16x16 products per vertex
 * (no division). */
#include "r8fixed.h"
#include "r8flash.h"

/* R8_PROJ16: a build whose caller has proved every camera-space x and
 * y within 16 bits (ports/fw_trim.c FW_SPIN): no 32-bit fallback;
 * with the AVR kernel not even the C projection (below). */
#if defined(R8_PROJ16) && defined(R8_ASM_PROJECT) && defined(__AVR__)
#define R8_PROJ_KERNEL_ONLY
#endif

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

#ifndef R8_PROJ16
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

/* round(c * kk * 2^-sh) for a coordinate over 2047 units: c and the
 * shift are scaled down first; 1 if beyond `lim`. */
static int proj_wide(r8_s32 c, r8_s16 kk, int sh, r8_s16 lim, r8_s16 *q)
{
    rshift r2;
    r8_s32 v;
    while (c >= 32768L || c < -32768L) {
        c = R8_ASR32C(c, 1);
        sh--;
    }
    if (sh <= 0)
        return 1;           /* |q| >= 2^14: far outside any guard band */
    rshift_init(&r2, (r8_u8)sh);
    v = rshift_do(&r2, R8_MUL16(c, kk));
    if (v > lim || v < -lim)
        return 1;
    *q = (r8_s16)v;
    return 0;
}
#endif

#ifndef R8_PROJ_KERNEL_ONLY
/* round(p * 2^-(k+1)) = floor((floor(p / 2^k) + 1) / 2), the same as
 * floor((p + 2^k) / 2^(k+1)), for |result| < 2^14 (else 1: outside any
 * guard band).  Floor of a negative p through its complement
 * (floor(p / 2^k) = ~(~p >> k)), whole bytes first: no 32-bit
 * constants per shift count. */
static int proj_round(r8_s32 p, r8_u8 k, r8_s16 lim, r8_s16 *q)
{
    r8_u8 neg = (r8_u8)(p < 0);
    r8_u32 u = neg ? ~(r8_u32)p : (r8_u32)p;
    r8_s16 t;
    if (k & 16)
        u >>= 16;
    if (k & 8)
        u >>= 8;
    k &= 7;
    while (k--)
        u >>= 1;
    if (u >= 0x7FFEu)
        return 1;
    t = (r8_s16)u;
    if (neg)
        t = (r8_s16)~t;                     /* -0x7FFE < t < 0x7FFE */
    t = (r8_s16)((r8_s16)((r8_u16)((r8_u16)t + 0x8001u) >> 1) - 0x4000);
    if (t > lim || t < -lim)
        return 1;
    *q = t;
    return 0;
}
#endif

#ifdef R8_PROJ_KERNEL_ONLY
/* R8_PROJ16 with the AVR kernel (ports/avr/project.S): r8k_project
 * projects every point whose x and y fit 16 bits itself (under
 * r8_proj_init's guard band) and calls r8_project_recip only for the
 * others, which such a build has none of: r8_project through the
 * kernel, r8_project_recip only refusing. */
#include "r8kern.h"
int r8_project(const r8_proj *p, const r8_vec3l *v, r8_s16 *sx, r8_s16 *sy)
{
    r8_s16 out[2];
    r8_u16 m;
    r8_s8 e;
    if (r8k_project(p, v, out, &m, &e))
        return 1;
    *sx = out[0];
    *sy = out[1];
    return 0;
}

int r8_project_recip(const r8_proj *p, const r8_vec3l *v, r8_u16 m, r8_s8 e,
                     r8_s16 *sx, r8_s16 *sy)
{
    (void)p; (void)v; (void)m; (void)e; (void)sx; (void)sy;
    return 1;
}
#else
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
    r8_u16 kh;
    int sh = 31 + p->fsh - e;
    /* 16 * focal / z = kk * 2^-sh with kk in [2^14, 2^15) */
    kh = (r8_u16)(k >> 16);
    if (kh >= 0x4000u) {
        kk = (r8_s16)kh;
        sh -= 16;
    } else {
        kk = (r8_s16)((r8_u16)(kh << 1) | (r8_u16)((r8_u16)k >> 15));   /* k >> 15 */
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
    if ((r8_u32)(v->x + 32767) <= 65534UL && (r8_u32)(v->y + 32767) <= 65534UL && lim < 0x3FFF) {
        /* the usual case: 16-bit coordinates (and a guard band under
         * 1024 px, as r8_proj_init sets it) */
        if (proj_round(R8_MUL16(v->x, kk), (r8_u8)(sh - 1), lim, &qx) ||
            proj_round(R8_MUL16(v->y, kk), (r8_u8)(sh - 1), lim, &qy))
            return 1;
    } else {
#ifdef R8_PROJ16
        /* R8_PROJ16: a build whose caller has proved every camera-space
         * x and y within 16 bits (ports/fw_trim.c FW_SPIN checks the
         * scene's bound before the first frame), and guard under 1024
         * px (r8_proj_init's 900): never here.  No 32-bit fallback. */
        return 1;
#else
        if (proj_wide(v->x, kk, sh, lim, &qx) || proj_wide(v->y, kk, sh, lim, &qy))
            return 1;
#endif
    }
    *sx = (r8_s16)(p->cx + qx);
    *sy = (r8_s16)(p->cy + qy);
    return 0;
}
#endif
