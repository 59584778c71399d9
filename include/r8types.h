/* r8types.h - the one place rast8 picks its integer types.
 *
 * Built on <limits.h> only (not the C99 fixed-width header): the library must compile with
 * gcc/clang on a 64-bit host (int 32, long 64), avr-gcc, cc65 and sdcc
 * (int 16, long 32, plain char unsigned on cc65 and sdcc).
 * Never do arithmetic on plain char; use r8_u8 / r8_s8.
 */
#ifndef R8TYPES_H
#define R8TYPES_H

#include <limits.h>

typedef unsigned char r8_u8;
typedef signed char r8_s8;

#if USHRT_MAX == 0xFFFF
typedef unsigned short r8_u16;
typedef short r8_s16;
#elif UINT_MAX == 0xFFFF
typedef unsigned int r8_u16;
typedef int r8_s16;
#else
#error "rast8: no 16-bit integer type"
#endif

#if UINT_MAX == 0xFFFFFFFFUL
typedef unsigned int r8_u32;   /* 64-bit hosts: long is 64 bits */
typedef int r8_s32;
#elif ULONG_MAX == 0xFFFFFFFFUL
typedef unsigned long r8_u32;  /* avr-gcc, cc65, sdcc, 32-bit hosts */
typedef long r8_s32;
#else
#error "rast8: no 32-bit integer type"
#endif

/* Compile-time check: the negative-array form works on gcc, clang,
 * avr-gcc, cc65 and sdcc (cc65 rejects ?: in constant expressions). */
#define R8_CASSERT(name, cond) typedef char r8_cassert_##name[1 - 2 * !(cond)]

R8_CASSERT(char_is_8_bits, CHAR_BIT == 8);
R8_CASSERT(u8_is_1_byte, sizeof(r8_u8) == 1);
R8_CASSERT(u16_is_2_bytes, sizeof(r8_u16) == 2);
R8_CASSERT(s16_is_2_bytes, sizeof(r8_s16) == 2);
R8_CASSERT(u32_is_4_bytes, sizeof(r8_u32) == 4);
R8_CASSERT(s32_is_4_bytes, sizeof(r8_s32) == 4);
R8_CASSERT(s16_is_signed, (r8_s16)-1 < 0);
R8_CASSERT(u32_is_unsigned, (r8_u32)-1 > 0);

#define R8_S16_MAX 32767
#define R8_S16_MIN (-32767 - 1)
#define R8_S32_MAX 2147483647L

#endif
