/* unity_target.c - tests/unity/unity.c built for a target: Unity's output
 * goes through plat_putc (the simulated UART). */
#include "plat.h"
#define UNITY_OUTPUT_CHAR(c) plat_putc((r8_u8)(c))
#ifdef __CC65__
/* cc65 2.19 rejects `u_name ? u_name : "?"` (const char * vs char *,
 * "Incompatible pointer types", unity.c line 49).  Dropping const in this
 * translation unit only is harmless: cc65 does not type-check across
 * units, and nothing here writes through the pointers. */
#define const
#endif
#include "unity.c"
