/* fw_fly.c - the flythrough's main on every target (AVR, 6502, Z80):
 * fly.c's loop over a static arena, streaming through the port's plat.h.
 *   FLY_FRAMES   frames to stream (default 24)
 *   FLY_RAM      the arena: fly_ram() measured on this target (the build
 *                runs this file with FLY_SIZE_ONLY first, mk/examples.mk)
 *   FLY_KEYS     include fly_keys.h: a key script compiled in (below)
 *   FLY_UART     with FLY_KEYS: the packets come over the UART instead
 *                (plat_getc; emu/avrsim -i feeds them), one after each
 *                frame, the firmware waiting for it (lockstep with the
 *                host's script)
 *   FLY_SIZE_ONLY  print fly_ram() in decimal and stop
 * Library parts the flythrough never uses are left out at compile time
 * (the R8_NO_* switches, given by mk/examples.mk): render.c and scan.c
 * are compiled in here with them, so the archive's full renderer is not
 * linked (the 6502 and Z80 images must stay under 64 KB).
 *
 * Input: a real board's UART receive interrupt calls fly_rx(c) for every
 * byte from the display; a test firmware has the key script compiled in
 * (fly_keys.h, written by keys2c.py; examples/common/fw_walk.c). */
#include "plat.h"
#include "fly.h"
#ifdef FLY_TRIM
#include "fw_trim.c"   /* FW_TRIM_LZ77: the LZ77 codec left out */
#include "render.c"
#include "scan.c"
#endif

/* the walk's main (examples/common/fw_walk.c) for the flythrough */
#define WALK_FN(x) fly_##x
#define WALK_KEYS_H "fly_keys.h"
#ifdef FLY_FRAMES
#define WALK_FRAMES FLY_FRAMES
#endif
#ifdef FLY_RAM
#define WALK_RAM FLY_RAM
#endif
#ifdef FLY_KEYS
#define WALK_KEYS
#endif
#ifdef FLY_UART
#define WALK_UART
#endif
#ifdef FLY_SIZE_ONLY
#define WALK_SIZE_ONLY
#endif
#include "fw_walk.c"
