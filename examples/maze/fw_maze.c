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
 * byte from the display.  The simulators here have no receive path, so
 * a test firmware compiles the key script in (maze_keys.h, written by
 * keys2c.py): after frame N it feeds script line N's INPUT packet, byte
 * by byte, to maze_rx - the bytes a display sends, through the receive
 * parser (r8_tx_rx) a UART interrupt would call.  The host build reads
 * the same script at run time and builds the packets with the C
 * decoder's r8_dec_input, so both sides of the packet format meet. */
#include "plat.h"
#include "maze.h"
#ifdef MAZE_TRIM
#include "fw_trim.c"   /* FW_TRIM_LZ77: the LZ77 codec left out */
#include "render.c"
#include "scan.c"
#include "raycast.c"   /* with these switches: textures only if MAZE_TEXTURED */
#endif

#ifndef MAZE_FRAMES
#define MAZE_FRAMES 24
#endif

#ifdef MAZE_SIZE_ONLY
int main(void)
{
    char d[6];
    int n = 0;
    unsigned v = maze_ram();
    plat_init();
    do {
        d[n++] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v);
    while (n)
        plat_putc((r8_u8)d[--n]);
    plat_putc('\n');
    plat_exit(0);
    return 0;
}
#else

#ifndef MAZE_RAM
#define MAZE_RAM 1
#endif
static r8_u8 mem[MAZE_RAM];

#ifdef MAZE_KEYS
#include "maze_keys.h"  /* FLY_KEY_LINES, fly_key_bytes[], fly_key_end[] */

static int feed(void *ctx, r8_u16 frame)
{
    unsigned i, end;
    (void)ctx;
    if (frame >= FLY_KEY_LINES)
        return 0;
    i = frame ? R8_RDU16(&fly_key_end[frame - 1]) : 0;
    end = R8_RDU16(&fly_key_end[frame]);
    for (; i < end; i++) {
#ifdef MAZE_UART
        int c;
        while ((c = plat_getc()) < 0)
            ;                  /* the packet's next byte from the display */
        maze_rx((r8_u8)c);
#else
        maze_rx(R8_RDU8(&fly_key_bytes[i]));
#endif
    }
    return 0;
}
#endif

int main(void)
{
    maze_cfg cfg;
    plat_init();
    cfg.frames = MAZE_FRAMES;
    cfg.on_frame = 0;
    cfg.ctx = 0;
#ifdef MAZE_KEYS
    cfg.on_frame = feed;
#endif
    plat_exit(maze_run(&cfg, mem, sizeof mem));
    return 0;
}
#endif
