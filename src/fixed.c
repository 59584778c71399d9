/* fixed.c - fixed-point helpers, trig table, vectors, matrices and the
 * perspective projection.  See r8fixed.h for the formats. */
#include "r8fixed.h"
#include "r8flash.h"

/* With R8_ASM_MUL16 a port links its own (ports/6502/mul16_6502.s,
 * ports/z80/mul16_z80.s); this is their reference (tests/c/test_mul.c). */
#ifndef R8_ASM_MUL16
r8_s32 r8_mul16(r8_s16 a, r8_s16 b)
{
    r8_s32 p = a; /* not (long)a * (long)b: SDCC 4.2 z80 gets that wrong */
    p *= b;
    return p;
}
#endif

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
    /* on the two 16-bit halves: no 32-bit compares on 8-bit CPUs */
    r8_u16 hi = (r8_u16)((r8_u32)v >> 16), lo = (r8_u16)((r8_u32)v & 0xFFFFu);
    if (hi == (r8_u16)((lo & 0x8000u) ? 0xFFFFu : 0u))
        return (r8_s16)v;                   /* -32768 .. 32767 */
    if (hi & 0x8000u)
        return (r8_s16)(-32767 - 1);
    return 32767;
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

/* r8_mat_rotate: src/r8tfref.h (the Z80's: ports/z80/tframe_z80.s) */
#ifndef R8_ASM_TFRAME
#define TFREF_ROTATE
#include "r8tfref.h"
#undef TFREF_ROTATE
#endif

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

/* r8_mat_apply_t14: src/r8tfref.h (the Z80's: ports/z80/tframe_z80.s) */
#ifndef R8_ASM_TFRAME
#define TFREF_T14
#include "r8tfref.h"
#undef TFREF_T14
#endif

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

