/* fw_maze.c - the maze walk's main on every target (AVR, 6502, Z80):
 * maze.c's loop over a static arena, streaming through the port's plat.h.
 *   MAZE_FRAMES   frames to stream (default 24)
 *   MAZE_RAM      the arena: maze_ram() measured on this target (the build
 *                runs this file with MAZE_SIZE_ONLY first, mk/examples.mk)
 *   MAZE_KEYS    include maze_keys.h: a key script compiled in (below; written by
 *                examples/flythrough/keys2c.py, whose names it keeps:
 *                FLY_KEY_LINES, fly_key_bytes, fly_key_end)
 *   MAZE_UART     with MAZE_KEYS: the packets come over the UART instead
 *                (plat_getc; emu/avrsim -i feeds them), one after each
 *                frame, the firmware waiting for it (lockstep with the
 *                host's script)
 *   MAZE_SIZE_ONLY  print maze_ram() in decimal and stop
 *   MAZE_TEXTURED  the textured maze (scenes/maze.c tmaze; with
 *                -DR8_RAY_TEXTURE: the ray caster's textures, no mesh
 *                texture mapping)
 * Library parts the maze never uses are left out at compile time
 * (the R8_NO_* switches, given by mk/examples.mk): render.c and scan.c
 * are compiled in here with them, so the archive's full renderer is not
 * linked (the 6502 and Z80 images must stay under 64 KB).
 *
 * Input: a real board's UART receive interrupt calls maze_rx(c) for every
 * byte from the display; a test firmware has the key script compiled in
 * (maze_keys.h, written by keys2c.py; examples/common/fw_walk.c). */
#include "plat.h"
#include "maze.h"
#ifdef MAZE_TRIM
#include "fw_trim.c"   /* FW_TRIM_LZ77: the LZ77 codec left out */
#include "render.c"
#include "scan.c"
#include "raycast.c"   /* with these switches: textures only if MAZE_TEXTURED */
#endif

/* the walk's main (examples/common/fw_walk.c) for the maze */
#define WALK_FN(x) maze_##x
#define WALK_KEYS_H "maze_keys.h"
#ifdef MAZE_FRAMES
#define WALK_FRAMES MAZE_FRAMES
#endif
#ifdef MAZE_RAM
#define WALK_RAM MAZE_RAM
#endif
#ifdef MAZE_KEYS
#define WALK_KEYS
#endif
#ifdef MAZE_UART
#define WALK_UART
#endif
#ifdef MAZE_SIZE_ONLY
#define WALK_SIZE_ONLY
#endif
#include "fw_walk.c"
