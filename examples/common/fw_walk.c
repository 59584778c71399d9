/* fw_walk.c - the main of a keyed walk's firmware on every target (AVR,
 * 6502, Z80), included by examples/flythrough/fw_fly.c and
 * examples/maze/fw_maze.c after their library trims: the application's
 * loop over a static arena, streaming through the port's plat.h.  The
 * including file names its application and maps its switches:
 *   WALK_FN(x)   its names, fly_##x: fly_cfg, fly_run, fly_ram, fly_rx
 *                (fly.h, maze.h)
 *   WALK_FRAMES  frames to stream (default 24)
 *   WALK_RAM     the arena: WALK_FN(ram)() measured on this target (the
 *                build runs the firmware with WALK_SIZE_ONLY first,
 *                mk/examples.mk)
 *   WALK_KEYS    include WALK_KEYS_H: a key script compiled in (below;
 *                written by examples/flythrough/keys2c.py: FLY_KEY_LINES,
 *                fly_key_bytes, fly_key_end)
 *   WALK_UART    with WALK_KEYS: the packets come over the UART instead
 *                (plat_getc; emu/avrsim -i feeds them), one after each
 *                frame, the firmware waiting for it (lockstep with the
 *                host's script)
 *   WALK_SIZE_ONLY  print WALK_FN(ram)() in decimal and stop
 *
 * Input: a real board's UART receive interrupt calls WALK_FN(rx)(c) for
 * every byte from the display.  The simulators here have no receive
 * path, so a test firmware compiles the key script in: after frame N it
 * feeds script line N's INPUT packet, byte by byte, to WALK_FN(rx) - the
 * bytes a display sends, through the receive parser (r8_tx_rx) a UART
 * interrupt would call.  The host build (examples/common/walk_host.c)
 * reads the same script at run time and builds the packets with the C
 * decoder's r8_dec_input, so both sides of the packet format meet. */
#ifndef WALK_FRAMES
#define WALK_FRAMES 24
#endif

#ifdef WALK_SIZE_ONLY
int main(void)
{
    char d[6];
    int n = 0;
    unsigned v = WALK_FN(ram)();
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

#ifndef WALK_RAM
#define WALK_RAM 1
#endif
static r8_u8 mem[WALK_RAM];

#ifdef WALK_KEYS
#include WALK_KEYS_H   /* FLY_KEY_LINES, fly_key_bytes[], fly_key_end[] */

static int feed(void *ctx, r8_u16 frame)
{
    unsigned i, end;
    (void)ctx;
    if (frame >= FLY_KEY_LINES)
        return 0;
    i = frame ? R8_RDU16(&fly_key_end[frame - 1]) : 0;
    end = R8_RDU16(&fly_key_end[frame]);
    for (; i < end; i++) {
#ifdef WALK_UART
        int c;
        while ((c = plat_getc()) < 0)
            ;                  /* the packet's next byte from the display */
        WALK_FN(rx)((r8_u8)c);
#else
        WALK_FN(rx)(R8_RDU8(&fly_key_bytes[i]));
#endif
    }
    return 0;
}
#endif

int main(void)
{
    WALK_FN(cfg) cfg;
    plat_init();
    cfg.frames = WALK_FRAMES;
    cfg.on_frame = 0;
    cfg.ctx = 0;
#ifdef WALK_KEYS
    cfg.on_frame = feed;
#endif
    plat_exit(WALK_FN(run)(&cfg, mem, sizeof mem));
    return 0;
}
#endif
