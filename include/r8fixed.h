/* r8fixed.h - fixed-point formats and integer helpers.
 *
 * Formats (see docs/fixed-point.md for the reasons):
 *   angles        r8_u8, 256 steps per turn
 *   sin/cos       Q1.14 in r8_s16 (16384 = 1.0): exact at 0, 90, 180 deg
 *   matrices      Q1.14 in r8_s16 (rotation entries lie in [-1, 1])
 *   unit normals,
 *   light vector  Q1.14 in r8_s16
 *   model coords  r8_s16 integer units
 *   camera coords r8_s32 with R8_CFRAC (4) fraction bits: 16 = one model
 *                 unit (rotation can grow |v| by sqrt 3)
 *   screen coords r8_s16 12.4: 4 subpixel bits (16 = one pixel); pixel
 *                 centres sit at 16*c + 8
 *   depth         r8_s16 0..32767, affine in 1/z (so linear in screen
 *                 space), larger = nearer; 8-bit depth is depth >> 7
 *   shade         r8_s16 8.8: level 0..16 (16 = white) with 8 fraction bits
 *
 * Every helper here is right with a 16-bit int and avoids the SDCC 4.2
 * widening-multiply bug (products are formed as r8_s32 p = a; p *= b).
 * Right shifts and divisions of negative numbers are implementation-
 * defined in C89, so the helpers do them on magnitudes.
 */
#ifndef R8FIXED_H
#define R8FIXED_H

#include "r8types.h"

#define R8_Q14 14
#define R8_ONE14 16384
#define R8_SUB 4           /* subpixel bits */
#define R8_SUBPX 16        /* subpixels per pixel */

typedef struct r8_vec3 { r8_s16 x, y, z; } r8_vec3;
typedef struct r8_vec3l { r8_s32 x, y, z; } r8_vec3l;
/* Row-major 3x3 rotation, Q1.14. */
typedef struct r8_mat3 { r8_s16 m[9]; } r8_mat3;

/* Full 32-bit product of two 16-bit values. */
r8_s32 r8_mul16(r8_s16 a, r8_s16 b);
/* The same in line where the compiler gets it right (SDCC 4.2 does not:
 * there it stays the function), or where a port's assembly does it
 * faster (R8_ASM_MUL16: ports/6502/mul16_6502.s). */
#if defined(__SDCC) || defined(R8_ASM_MUL16)
#define R8_MUL16(a, b) r8_mul16((r8_s16)(a), (r8_s16)(b))
#else
#define R8_MUL16(a, b) ((r8_s32)(r8_s16)(a) * (r8_s32)(r8_s16)(b))
#endif
/* floor(v / 2^n) for a constant n, portably and fast: the shift is done
 * on v + 2^31 as unsigned (a byte move for n >= 8), then the bias comes
 * off.  v + 2^31 must not pass 2^32: any r8_s32 v. */
#define R8_ASR32C(v, n) ((r8_s32)((r8_u32)((r8_u32)(v) + 0x80000000UL) >> (n)) - (r8_s32)(0x80000000UL >> (n)))
/* p >> 14 for 0 <= p < 2^30, as 16 bits: byte moves and two shifts. */
#define R8_SHR14U(p) ((r8_u16)((r8_u16)((r8_u32)(p) >> 16) << 2) | (r8_u16)((r8_u8)((r8_u32)(p) >> 8) >> 6))
/* u >> 4 and u << 4 for a 16-bit unsigned u.  avr-gcc -Os makes a
 * 4-step loop of these; its nibble swap makes them a few moves. */
#ifdef __AVR__
#define R8_SWAP4_(b) __builtin_avr_swap((r8_u8)(b))
#define R8_SHR4U(u) ((r8_u16)((r8_u16)(r8_u8)(R8_SWAP4_((u) >> 8) & 0x0Fu) << 8 | \
    (r8_u8)((R8_SWAP4_(u) & 0x0Fu) | (R8_SWAP4_((u) >> 8) & 0xF0u))))
#define R8_SHL4U(u) ((r8_u16)((r8_u16)(r8_u8)((R8_SWAP4_((u) >> 8) & 0xF0u) | \
    (R8_SWAP4_(u) & 0x0Fu)) << 8 | (r8_u8)(R8_SWAP4_(u) & 0xF0u)))
#else
#define R8_SHR4U(u) ((r8_u16)((r8_u16)(u) >> 4))
#define R8_SHL4U(u) ((r8_u16)((r8_u16)(u) << 4))
#endif
/* floor(v / 16) for |v| < 32768 - 16: the row or column of a 12.4 value. */
#define R8_FLOOR16(v) ((r8_s16)R8_SHR4U((r8_u16)((v) + 32768u)) - 2048)
/* (a * b) >> frac, rounded to nearest (ties away from zero), saturated
 * to r8_s16.  r8_mulq(a, b, 8) is the Q8.8 multiply, 14 the Q1.14 one. */
r8_s16 r8_mulq(r8_s16 a, r8_s16 b, r8_u8 frac);
/* floor(v / 2^14), the Q1.14 shift, fast on 8-bit CPUs. */
r8_s32 r8_asr14(r8_s32 v);
/* floor(v / 2^n) for any sign (an arithmetic shift, portably). */
r8_s32 r8_asr32(r8_s32 v, r8_u8 n);
/* floor(n / d), d > 0, for any sign of n. */
r8_s32 r8_floordiv(r8_s32 n, r8_s32 d);
/* n / d rounded to nearest, ties away from zero; d != 0. */
r8_s32 r8_divround(r8_s32 n, r8_s32 d);
/* a * b / c, truncated toward zero, exact for any r8_s32 a, b and
 * nonzero c whose true result fits r8_s32 (saturates otherwise). */
r8_s32 r8_muldiv(r8_s32 a, r8_s32 b, r8_s32 c);
/* Clamp an r8_s32 to r8_s16. */
r8_s16 r8_sat16(r8_s32 v);
/* floor(sqrt(v)), v >= 0. */
r8_u16 r8_isqrt32(r8_u32 v);

/* Q1.14 sine and cosine of a 256-step angle. */
r8_s16 r8_sin(r8_u8 a);
r8_s16 r8_cos(r8_u8 a);

/* Dot products: 16-bit inputs, 32-bit result (no overflow for any
 * input when at most two terms reach 2^30; callers keep |x| < 2^15). */
r8_s32 r8_dot3(const r8_vec3 *a, const r8_vec3 *b);
/* c = a x b, exact: each component fits r8_s32 for any 16-bit input. */
void r8_cross3(const r8_vec3 *a, const r8_vec3 *b, r8_vec3l *c);
/* Scale v (any 32-bit vector) down by a power of two so every component
 * fits |x| < 2^14, then to unit length in Q1.14 (zero stays zero). */
void r8_normalize(const r8_vec3l *v, r8_vec3 *out);

/* Rotation about Z, then Y, then X (m = Rx * Ry * Rz), Q1.14: an object
 * spun about its own Y axis and then tilted by X. */
void r8_mat_rotate(r8_mat3 *m, r8_u8 ax, r8_u8 ay, r8_u8 az);
/* c = a * b (Q1.14). c may not alias a or b. */
void r8_mat_mul(const r8_mat3 *a, const r8_mat3 *b, r8_mat3 *c);
/* out = m * v (v integer units, out 32-bit, rounded). */
void r8_mat_apply(const r8_mat3 *m, const r8_vec3 *v, r8_vec3l *out);
/* out = m * v in camera units (v integer units, out << R8_CFRAC, rounded). */
void r8_mat_apply16(const r8_mat3 *m, const r8_vec3 *v, r8_vec3l *out);
/* out = transpose(m) * v for a Q1.14 v (the inverse rotation), Q1.14. */
void r8_mat_apply_t14(const r8_mat3 *m, const r8_vec3 *v, r8_vec3 *out);

/* Camera-space fraction bits: camera coordinates are model units * 16. */
#define R8_CFRAC 4
#define R8_CSCALE 16   /* 1 << R8_CFRAC: multiply signed values by it */

/* Perspective projection to 12.4 screen coordinates (the renderer's
 * internal view of a camera; the application's camera is r8_camera in
 * r8render.h). */
typedef struct r8_proj {
    r8_s16 cx, cy;   /* screen centre, 12.4 */
    r8_s16 focal;    /* focal length in pixels, 1..2047 */
    r8_s32 znear;    /* near plane, camera units (<< R8_CFRAC), > 0 */
    r8_s16 guard;    /* guard band half-width in pixels (|sx-cx| <= guard) */
    r8_s16 fn;       /* 16 * focal normalised to [2^14, 2^15) ... */
    r8_u8 fsh;       /* ... by this left shift */
} r8_proj;

void r8_proj_init(r8_proj *p, r8_s16 width, r8_s16 height, r8_s16 focal,
                  r8_s32 znear);
/* Project camera-space v (28.4, z >= znear) to 12.4 screen coordinates:
 * sx = cx + 16 * focal * x / z (rounded, relative error below 2^-14,
 * no division: a 129-entry reciprocal table in flash and three 16x16
 * products).  Returns 0, or 1 (sx, sy unset) when v lies outside the
 * guard band. */
int r8_project(const r8_proj *p, const r8_vec3l *v, r8_s16 *sx, r8_s16 *sy);
/* The same with the reciprocal of v->z already taken (r8_recip). */
int r8_project_recip(const r8_proj *p, const r8_vec3l *v, r8_u16 m, r8_s8 e,
                     r8_s16 *sx, r8_s16 *sy);
/* 2^31 / z to about 16 bits: returns m in [2^15, 2^16) and *e with
 * 1/z ~= m * 2^(*e - 31), for z >= 1. */
r8_u16 r8_recip(r8_s32 z, r8_s8 *e);
/* c = transpose(a). */
void r8_mat_transpose(const r8_mat3 *a, r8_mat3 *c);

#endif
