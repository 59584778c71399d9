/* walk_host.c - the host program of a keyed walk (see walk_host.h):
 * plat.h from emu/plat_host.c (the UART is a file, stdout or a pty).
 * With --pty, `rast8 view` on the printed device is the display and the
 * gamepad: its arrow keys and buttons arrive as INPUT packets after
 * every frame. */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <termios.h>
#include <unistd.h>

#include "walk_host.h"
#include "r8wire.h"
#include "plat.h"
#include "plat_host.h"

static const walk_app *app;

static void usage(FILE *f)
{
    fprintf(f,
"usage: %s [options]\n"
"%s"
"  --out FILE|-      the stream to FILE or stdout (default -)\n"
"  --pty             the stream on a new pty (its path on stdout); the reader's\n"
"                    bytes (REQUEST, INPUT) are read after every frame\n"
"  --baud N          pace the output as 8N1 at N baud (default: unpaced)\n"
"  --frames N        frames to send (default 64; 0 = forever)\n"
"  --keys FILE       key script, as rast8-emu --keys: line N is the key mask\n"
"                    (hex 0x.. or decimal, R8_KEY_* bits; '#' comments) sent as\n"
"                    an INPUT packet after frame N\n"
"  --rx FILE|-       also read display bytes from FILE or stdin\n"
"%s%s"
"  --print-ram       print the arena the configuration needs and exit\n"
"  -q                no summary on stderr\n"
"exit status: 0 ok, 2 bad option or key script, 3 configuration refused,\n"
"5 output failed\n", app->prog, app->about, app->log_help, app->opts_help);
}

static void die(int code, const char *what, const char *arg)
{
    fprintf(stderr, "%s: %s%s\n", app->prog, what, arg);
    exit(code);
}

struct host {
    FILE *keys, *log;
    int rx[2];                 /* pty master and --rx, or -1 */
    int bad;
};

static void feed_fd(int fd)
{
    unsigned char buf[256];
    struct pollfd p;
    ssize_t n, k;
    p.fd = fd;
    p.events = POLLIN;
    while (fd >= 0 && poll(&p, 1, 0) > 0 && (p.revents & POLLIN)) {
        if ((n = read(fd, buf, sizeof buf)) <= 0)
            break;
        for (k = 0; k < n; k++)
            app->rx(buf[k]);
    }
}

static int on_frame(void *ctx, r8_u16 no)
{
    struct host *h = ctx;
    app->frame(h->log, no);
    feed_fd(h->rx[0]);
    feed_fd(h->rx[1]);
    if (h->keys) {
        char line[128];
        while (fgets(line, sizeof line, h->keys)) {
            char *end, *p = line + strspn(line, " \t");
            unsigned long v;
            r8_u8 pk[R8_DEC_INPUT_BYTES];
            unsigned n, k;
            if (*p == '#' || *p == '\n' || *p == '\r' || !*p)
                continue;
            v = strtoul(p, &end, 0);
            if (end == p || v > 0xFFFFu || (*end && !strchr(" \t\r\n#", *end))) {
                fprintf(stderr, "%s: --keys: bad key mask '%.*s' (0..0xffff)\n", app->prog,
                        (int)strcspn(p, "\r\n"), p);
                h->bad = 1;
                return 1;
            }
            n = r8_dec_input(pk, (r8_u16)v);     /* as the display sends it */
            for (k = 0; k < n; k++)
                app->rx(pk[k]);
            break;
        }
    }
    return plat_host_failed();
}

static int open_pty(void)
{
    int m = posix_openpt(O_RDWR | O_NOCTTY), s;
    struct termios t;
    const char *name;
    struct pollfd p;
    if (m < 0 || grantpt(m) || unlockpt(m) || !(name = ptsname(m)))
        die(1, "cannot create a pty: ", strerror(errno));
    if ((s = open(name, O_RDWR | O_NOCTTY)) < 0 || tcgetattr(s, &t))
        die(1, "cannot set up the pty: ", strerror(errno));
    cfmakeraw(&t);
    tcsetattr(s, TCSANOW, &t);
    printf("%s\n", name);
    fflush(stdout);
    close(s);
    /* wait for the reader's first byte (rast8 view sends a REQUEST when
     * it has opened the port; earlier bytes would be flushed) */
    p.fd = m;
    p.events = POLLIN;
    while (poll(&p, 1, 100) >= 0 && !(p.revents & POLLIN))
        ;
    return m;
}

int walk_main(int argc, char **argv, const walk_app *a0)
{
    static r8_u8 mem[65536];
    struct host h;
    const char *out = "-";
    int i, fd = 1, pty = 0, quiet = 0, print_ram = 0, rc;
    long baud = 0;
    r8_u16 frames = 64;
    unsigned need;
    app = a0;
    memset(&h, 0, sizeof h);
    h.rx[0] = h.rx[1] = -1;
    for (i = 1; i < argc; i++) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : 0;
        int takes = !strcmp(a, "--out") || !strcmp(a, "--baud") || !strcmp(a, "--frames") ||
                    !strcmp(a, "--keys") || !strcmp(a, "--rx") || !strcmp(a, "--log");
        char *end;
        long n = 0;
        if (takes && !v)
            die(2, "missing value after ", a);
        if (!strcmp(a, "--baud") || !strcmp(a, "--frames")) {
            n = strtol(v, &end, 0);
            if (*end || end == v || n < 0 || n > (a[2] == 'f' ? 65535L : 100000000L))
                die(2, "bad number after ", a);
        }
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            usage(stdout);
            return 0;
        } else if (!strcmp(a, "--out")) {
            out = v;
        } else if (!strcmp(a, "--pty")) {
            pty = 1;
        } else if (!strcmp(a, "--baud")) {
            baud = n;
        } else if (!strcmp(a, "--frames")) {
            frames = (r8_u16)n;
        } else if (!strcmp(a, "--keys")) {
            if (!(h.keys = fopen(v, "r")))
                die(2, "cannot read the key script: ", strerror(errno));
        } else if (!strcmp(a, "--rx")) {
            if ((h.rx[1] = strcmp(v, "-") ? open(v, O_RDONLY) : 0) < 0)
                die(2, "cannot read --rx: ", strerror(errno));
        } else if (!strcmp(a, "--log")) {
            if (!(h.log = fopen(v, "w")))
                die(2, "cannot write the log: ", strerror(errno));
        } else if (!strcmp(a, "--print-ram")) {
            print_ram = 1;
        } else if (!strcmp(a, "-q")) {
            quiet = 1;
        } else if (!app->option || !app->option(a)) {
            die(2, "unknown option (see --help): ", a);
        }
        i += takes;
    }
    need = app->ram();
    if (print_ram) {
        printf("%u bytes\n", need);
        return need ? 0 : 3;
    }
    if (!need || need > sizeof mem)
        die(3, "the library refuses the configuration", "");
    if (pty && strcmp(out, "-"))
        die(2, "choose one of --out and --pty", "");
    if (pty) {
        fd = h.rx[0] = open_pty();
    } else if (strcmp(out, "-")) {
        if ((fd = open(out, O_WRONLY | O_CREAT | O_TRUNC, 0644)) < 0)
            die(1, "cannot write the output: ", strerror(errno));
    } else if (isatty(1)) {
        die(2, "refusing to write a binary stream to a terminal: use --out FILE, --pty "
            "or a pipe", "");
    }
    plat_init();
    plat_host_output(fd, baud);
    rc = app->run(frames, on_frame, &h, mem, need);    /* exactly ram() bytes */
    if (h.log)
        fclose(h.log);
    if (rc)
        die(3, "the library refuses the configuration", "");
    if (h.bad)
        return 2;
    if (plat_host_failed())
        die(5, "output failed (reader went away?)", "");
    if (!quiet) {
        fprintf(stderr, "%s: %lu frames, %lu bytes, arena %u bytes",
                app->prog, plat_host_marks(PLAT_MARK_FRAME_END), plat_host_bytes(), need);
        app->summary(stderr);
    }
    if (pty)
        sleep(1);   /* let the reader take the last bytes */
    return 0;
}
