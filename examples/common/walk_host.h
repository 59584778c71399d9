/* walk_host.h - the host program of a walk steered by the display's keys
 * (examples/flythrough, examples/maze): options, the stream to a file,
 * stdout or a pty, the key script and the display's bytes fed to the
 * application after every frame, the exit codes.  The application gives
 * its loop and its texts; the firmware side is the application's own. */
#ifndef WALK_HOST_H
#define WALK_HOST_H

#include <stdio.h>
#include "r8types.h"

typedef struct walk_app {
    const char *prog;        /* program name (messages) */
    const char *about;       /* --help: the lines between "usage:" and the options */
    const char *log_help;    /* --help: the --log option's lines */
    const char *opts_help;   /* --help: the application's own options ("" none) */
    unsigned (*ram)(void);   /* the arena it needs (after the options) */
    /* its loop: `frames` frames (0 = forever) in mem[n], on_frame(ctx,
     * frame) after each (non-zero: stop); 0 or an error */
    int (*run)(r8_u16 frames, int (*on_frame)(void *ctx, r8_u16 frame), void *ctx,
               r8_u8 *mem, unsigned n);
    void (*rx)(r8_u8 c);     /* a byte from the display */
    void (*frame)(FILE *log, r8_u16 frame);   /* after each frame (log: 0 without --log) */
    int (*option)(const char *arg);           /* its own flags: 1 taken, 0 unknown */
    void (*summary)(FILE *f);                 /* the summary line's end, with its newline */
} walk_app;

/* The program: parse argv, run, report; the exit status (0 ok, 2 bad
 * option or key script, 3 configuration refused, 5 output failed). */
int walk_main(int argc, char **argv, const walk_app *app);

#endif
