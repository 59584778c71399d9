/* main.c - rast8-emu: runs the demo firmware (examples/spin/app.c) natively and
 * exposes its UART as a file, stdout, a pty or a TCP port.  See --help. */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <getopt.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>

#include "app.h"
#include "blob.h"
#include "plat.h"
#include "plat_host.h"

#define GUARD_BYTES 256
#define GUARD 0xA5

static const char *prog = "rast8-emu";

static void usage(FILE *f)
{
    int i;
    fprintf(f,
"usage: %s [options]\n"
"Runs the rast8 demo firmware natively and streams its frames (protocol v%d,\n"
"docs/protocol.md) out of a virtual UART.\n"
"\n"
"output (one of; default --out -):\n"
"  --out FILE|-      write the byte stream to FILE, or - for stdout\n"
"  --pty             create a pty, print its path on stdout, wait for a reader\n"
"  --tcp PORT        listen on 127.0.0.1:PORT (0 = any free port; the port is\n"
"                    printed on stdout) for one client, e.g. pyserial socket://\n"
"  --baud N          pace output in real time as 8N1 at N baud (10 bits/byte);\n"
"                    default: unpaced\n"
"  --gate MS         pty/tcp: once the reader is there, wait up to MS ms for its\n"
"                    first byte before streaming (default 2000; rast8 sends a\n"
"                    REQUEST on open): pyserial discards input that arrives\n"
"                    before it has finished opening the port\n"
"  --linger S        pty/tcp: after the last frame wait up to S seconds for the\n"
"                    reader to close (default 30) so no byte is lost\n"
"\n"
"input (display -> device: REQUEST and INPUT packets, docs/protocol.md):\n"
"                    with --pty/--tcp the reader's bytes are read after every\n"
"                    frame and fed to the firmware (app_rx)\n"
"  --rx FILE|-       also read display bytes from FILE or stdin (- ), the same way\n"
"  --keys FILE       key script: line N is the key mask (hex 0x.. or decimal,\n"
"                    R8_KEY_* bits; '#' comments) sent as an INPUT packet after\n"
"                    frame N, so the firmware sees it from frame N+1 on\n"
"  --key-log FILE    write 'FRAME KEYS' (hex) per frame: the key state the\n"
"                    firmware had while rendering that frame\n"
"\n"
"firmware config:\n"
"  --scene NAME|FILE scene: a .r8s, .obj or scene blob file, or (default cube):",
            prog, R8_WIRE_VERSION);
    for (i = 0; i < R8_DEMO_COUNT; i++)
        if (r8_demo_name((r8_u8)i))
            fprintf(f, " %s", r8_demo_name((r8_u8)i));
    fprintf(f, "\n  --method NAME     visibility method (default cull; ray for a grid\n"
            "                    scene such as maze, portal for rooms): auto");
    for (i = 0; i < R8_VIS_COUNT; i++)
        fprintf(f, " %s", r8_method_name((r8_u8)i));
    fprintf(f, " %s %s", r8_method_name(R8_VIS_RAY), r8_method_name(R8_VIS_PORTAL));
    fprintf(f, "\n"
"  --width W --height H   frame size (default 128x64)\n"
"  --format F        page1 (SSD1306 pages, default), row1, idx8\n"
"  --shading S       flat, lambert, gouraud, texture (default: the renderer's)\n"
"  --persp N         texture: perspective-correct every N pixels (default 0: affine)\n"
"  --bilinear        texture: bilinear filtering (8-bit textures)\n"
"  --wire            wireframe: the edges of the faces the method keeps (cull:\n"
"                    front faces; painter: far to near, hidden lines removed)\n"
"  --band H          band height in rows (default 8; multiple of 8 for page1)\n"
"  --frames N        frames to send (default 64; 0 = forever)\n"
"  --first N         number of the first frame (default 0)\n"
"  --codec C         rle (default), lz77, huff, lzw, raw, best (the smallest per band)\n"
"  --full-period N   full frame every N frames (default 32; 0 = first only)\n"
"  --no-dirty        send every band of every frame\n"
"  --ram BYTES       the target's RAM budget: fail if the config needs more,\n"
"                    and check the run stays inside it\n"
"\n"
"checks and info:\n"
"  --dump FILE       write every whole frame as rendered (the reference for\n"
"                    end-to-end tests): per frame 'R8FB' frame:2 width:2\n"
"                    height:2 format:1 0:1 then the raw framebuffer (big-endian)\n"
"  --print-ram       print the RAM the config needs and exit\n"
"  -q, --quiet       no summary on stderr\n"
"  -h, --help        this help\n"
"\n"
"exit status: 0 ok, 2 bad option, 3 RAM budget too small, 4 RAM overrun,\n"
"5 output failed (reader went away), 1 other errors\n");
}

static void die(int code, const char *fmt, const char *arg)
{
    fprintf(stderr, "%s: ", prog);
    fprintf(stderr, fmt, arg);
    fprintf(stderr, "\n");
    exit(code);
}

static long num(const char *opt, const char *s, long lo, long hi)
{
    char *end;
    long v;
    errno = 0;
    v = strtol(s, &end, 0);
    if (errno || end == s || *end || v < lo || v > hi) {
        fprintf(stderr, "%s: %s: bad number '%s' (%ld..%ld)\n", prog, opt, s, lo, hi);
        exit(2);
    }
    return v;
}

/* ---- host hooks: dump whole frames, poll the display's requests */
struct host {
    FILE *dump;
    FILE *keys;          /* key script, or 0 */
    FILE *key_log;       /* per-frame key state, or 0 */
    int rx2_fd;          /* --rx FILE|-, or -1 */
    int bad_keys;        /* the key script had a bad line */
    unsigned char *frame;
    unsigned frame_bytes;
    int rx_fd;
    unsigned long requests;
    app_cfg *cfg;
};

static void on_band(void *ctx, const r8_fb *band)
{
    struct host *h = ctx;
    unsigned off, n, rows;
    if (!h->frame)
        return;
    rows = (unsigned)(band->height - band->y0);
    if (rows > (unsigned)band->rows)
        rows = (unsigned)band->rows;
    off = r8_fb_bytes(band->format, band->width, band->y0);
    if (band->y0 == 0)
        off = 0;
    n = r8_fb_bytes(band->format, band->width, (r8_s16)rows);
    memcpy(h->frame + off, band->buf, n);
}

static void put16(FILE *f, unsigned v)
{
    fputc((int)(v >> 8) & 0xFF, f);
    fputc((int)v & 0xFF, f);
}

/* Feed what the display sent (REQUEST, INPUT packets) to the firmware. */
static void feed_rx(int fd)
{
    unsigned char buf[256];
    struct pollfd p;
    ssize_t n, k;
    if (fd < 0)
        return;
    p.fd = fd;
    p.events = POLLIN;
    while (poll(&p, 1, 0) > 0 && (p.revents & POLLIN)) {
        n = read(fd, buf, sizeof buf);
        if (n <= 0)
            break;
        for (k = 0; k < n; k++)
            app_rx(buf[k]);
    }
}

static int on_frame(void *ctx, r8_u16 no)
{
    struct host *h = ctx;
    if (h->dump) {
        fwrite("R8FB", 1, 4, h->dump);
        put16(h->dump, no);
        put16(h->dump, (unsigned)h->cfg->render.width);
        put16(h->dump, (unsigned)h->cfg->render.height);
        fputc(h->cfg->render.format, h->dump);
        fputc(0, h->dump);
        fwrite(h->frame, 1, h->frame_bytes, h->dump);
        fflush(h->dump);
    }
    if (h->key_log)
        fprintf(h->key_log, "%u %04x\n", (unsigned)no, (unsigned)app_keys());
    feed_rx(h->rx_fd);
    feed_rx(h->rx2_fd);
    if (h->keys) {
        /* the script's next line: an INPUT packet, as a display sends it */
        char line[128];
        while (fgets(line, sizeof line, h->keys)) {
            char *end, *s = line + strspn(line, " \t");
            unsigned long v;
            unsigned char pk[R8_DEC_INPUT_BYTES];
            unsigned n, k;
            if (*s == '#' || *s == '\n' || !*s)
                continue;
            v = strtoul(s, &end, 0);
            if (end == s || v > 0xFFFFu) {
                fprintf(stderr, "%s: --keys: bad key mask '%.*s' (0..0xffff)\n", prog,
                        (int)strcspn(s, "\n"), s);
                h->bad_keys = 1;
                return 1;
            }
            n = r8_dec_input(pk, (r8_u16)v);
            for (k = 0; k < n; k++)
                app_rx(pk[k]);
            break;
        }
    }
    return plat_host_failed();
}

/* ---- outputs */
static int open_pty(void)
{
    int m = posix_openpt(O_RDWR | O_NOCTTY);
    struct termios t;
    int s;
    const char *name;
    if (m < 0 || grantpt(m) || unlockpt(m) || !(name = ptsname(m)))
        die(1, "cannot create a pty: %s", strerror(errno));
    /* raw mode on the slave side, then let the reader open it */
    s = open(name, O_RDWR | O_NOCTTY);
    if (s < 0 || tcgetattr(s, &t))
        die(1, "cannot set up the pty: %s", strerror(errno));
    cfmakeraw(&t);
    tcsetattr(s, TCSANOW, &t);
    printf("%s\n", name);
    fflush(stdout);
    close(s);
    return m;
}

/* Wait until a reader has the pty slave open (the master stops
 * reporting POLLHUP). */
static void pty_wait_reader(int m)
{
    struct pollfd p;
    for (;;) {
        p.fd = m;
        p.events = POLLOUT;
        p.revents = 0;
        poll(&p, 1, 100);
        if (!(p.revents & POLLHUP))
            return;
        usleep(20000);
    }
}

/* After the run: wait until the reader closes (POLLHUP) or linger ends.
 * Closing the master earlier would drop bytes it has not read yet. */
static void pty_linger(int m, double secs)
{
    struct pollfd p;
    struct timespec a, b;
    char buf[64];
    clock_gettime(CLOCK_MONOTONIC, &a);
    for (;;) {
        p.fd = m;
        p.events = POLLIN;
        p.revents = 0;
        poll(&p, 1, 100);
        if (p.revents & POLLHUP)
            return;
        if (p.revents & POLLIN && read(m, buf, sizeof buf) <= 0)
            return;
        clock_gettime(CLOCK_MONOTONIC, &b);
        if ((double)(b.tv_sec - a.tv_sec) + (double)(b.tv_nsec - a.tv_nsec) / 1e9 > secs)
            return;
    }
}

/* Gate: wait up to secs for the reader's first byte (rast8 sends a
 * REQUEST when it opens the port).  pyserial flushes pending input when
 * it opens a port or socket, so bytes sent before that would be lost. */
static void wait_first_byte(int fd, double secs)
{
    struct pollfd p;
    char buf[64];
    p.fd = fd;
    p.events = POLLIN;
    p.revents = 0;
    if (poll(&p, 1, (int)(secs * 1000)) > 0 && (p.revents & POLLIN)) {
        usleep(20000); /* let the rest of the hello arrive */
        if (read(fd, buf, sizeof buf) < 0)
            return;
    }
}

static int open_tcp(long port)
{
    int s = socket(AF_INET, SOCK_STREAM, 0), c, one = 1;
    struct sockaddr_in a;
    socklen_t len = sizeof a;
    if (s < 0)
        die(1, "socket: %s", strerror(errno));
    setsockopt(s, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    memset(&a, 0, sizeof a);
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    a.sin_port = htons((unsigned short)port);
    if (bind(s, (struct sockaddr *)&a, sizeof a) || listen(s, 1))
        die(1, "cannot listen on the port: %s", strerror(errno));
    getsockname(s, (struct sockaddr *)&a, &len);
    printf("%u\n", (unsigned)ntohs(a.sin_port));
    fflush(stdout);
    c = accept(s, 0, 0);
    if (c < 0)
        die(1, "accept: %s", strerror(errno));
    close(s);
    return c;
}

static void tcp_linger(int c, double secs)
{
    struct pollfd p;
    char buf[64];
    int ms = (int)(secs * 1000);
    shutdown(c, SHUT_WR);
    p.fd = c;
    p.events = POLLIN;
    while (ms > 0 && poll(&p, 1, 100) >= 0) {
        if (p.revents & (POLLIN | POLLHUP)) {
            if (read(c, buf, sizeof buf) <= 0)
                return;
        }
        ms -= 100;
    }
}

/* --method auto: the analyser picks the cheapest exact method for the
 * scene and, unless --band is given, the largest band that fits the RAM
 * budget (--ram, else 16 KB) after the encoder's own buffers. */
static void analyse(app_cfg *cfg, int band_given, long ram, int quiet)
{
    static const char *const why[] = {
        "", "one convex mesh: backface culling is exact",
        "convex objects apart in depth: painter's is exact",
        "concave or interpenetrating geometry: z-buffer",
        "given by the user", "the exact method does not fit the RAM budget",
        "a grid map: the ray caster draws it",
        "sectors joined by portals: the portal renderer draws each pixel once, no depth memory",
        "non-convex meshes with BSP trees, apart in depth: BSP order is exact"
    };
    long budget = ram >= 0 ? ram : 16384;
    long extra;
    r8_analysis a;
    app_layout lay;
    /* leave room for the encoder: shrink the renderer's share until the
     * whole app fits (the encoder's buffers grow with the band) */
    for (extra = 0; ; extra += 32) {
        r8_render_cfg rc = cfg->render;
        r8_demo_run *run = app_demo(cfg);
        rc.method = R8_VIS_AUTO;
        if (!band_given)
            rc.band = 0;
        if (run)
            rc.scene = &run->scene;
        if (budget - extra <= 0 || !run ||
            r8_analyse(&rc, &run->cam, 0, (unsigned)(budget - extra), &a)) {
            fprintf(stderr, "%s: --method auto: nothing fits %ld bytes of RAM for scene %s\n",
                    prog, budget, (cfg->demo ? cfg->demo->name : r8_demo_name(cfg->scene)));
            exit(3);
        }
        rc.scene = 0;
        cfg->render = rc;
        if (app_plan(cfg, &lay) || (long)lay.total <= budget)
            break;                      /* (a bad layout is reported by the caller) */
    }
    if (!quiet)
        fprintf(stderr, "%s: analyser: scene %s -> method %s (%s), band %d rows, "
                "renderer+band %u bytes; depth range z %ld..%ld, camera coordinates "
                "need %d bits\n", prog, (cfg->demo ? cfg->demo->name : r8_demo_name(cfg->scene)),
                r8_method_name(a.method), why[(size_t)a.why < sizeof why / sizeof why[0] ? a.why : 0], a.band, a.ram,
                (long)a.znear, (long)a.zfar, a.coord_bits);
}

static int fmt_by_name(const char *s)
{
    if (!strcmp(s, "page1")) return R8_FMT_PAGE1;
    if (!strcmp(s, "row1")) return R8_FMT_ROW1;
    if (!strcmp(s, "idx8")) return R8_FMT_IDX8;
    return -1;
}

int main(int argc, char **argv)
{
    enum { O_OUT = 256, O_PTY, O_TCP, O_BAUD, O_RAM, O_SCENE, O_METHOD, O_BAND,
           O_FRAMES, O_FIRST, O_W, O_H, O_FMT, O_CODEC, O_PERIOD, O_NODIRTY,
           O_DUMP, O_LINGER, O_PRINTRAM, O_GATE, O_RX, O_KEYS, O_KEYLOG, O_SHADING, O_WIRE, O_PERSP, O_BILINEAR };
    static const struct option opts[] = {
        { "out", 1, 0, O_OUT }, { "pty", 0, 0, O_PTY }, { "tcp", 1, 0, O_TCP },
        { "baud", 1, 0, O_BAUD }, { "ram", 1, 0, O_RAM }, { "scene", 1, 0, O_SCENE },
        { "method", 1, 0, O_METHOD }, { "band", 1, 0, O_BAND },
        { "frames", 1, 0, O_FRAMES }, { "first", 1, 0, O_FIRST },
        { "width", 1, 0, O_W }, { "height", 1, 0, O_H }, { "format", 1, 0, O_FMT },
        { "codec", 1, 0, O_CODEC }, { "full-period", 1, 0, O_PERIOD },
        { "no-dirty", 0, 0, O_NODIRTY }, { "dump", 1, 0, O_DUMP },
        { "linger", 1, 0, O_LINGER }, { "rx", 1, 0, O_RX }, { "keys", 1, 0, O_KEYS },
        { "key-log", 1, 0, O_KEYLOG }, { "shading", 1, 0, O_SHADING }, { "wire", 0, 0, O_WIRE }, { "persp", 1, 0, O_PERSP }, { "bilinear", 0, 0, O_BILINEAR }, { "gate", 1, 0, O_GATE }, { "print-ram", 0, 0, O_PRINTRAM },
        { "quiet", 0, 0, 'q' }, { "help", 0, 0, 'h' }, { 0, 0, 0, 0 }
    };
    app_cfg cfg;
    app_layout lay;
    struct host host;
    const char *out = "-", *dump = 0, *rx = 0, *keys = 0, *key_log = 0;
    int use_pty = 0, quiet = 0, print_ram = 0, c, v, fd = 1, rc, band_given = 0, method_given = 0;
    long tcp = -1, baud = 0, ram = -1;
    double linger = 30, gate = 2;
    unsigned char *arena;
    unsigned need, size, k;

    app_defaults(&cfg);
    memset(&host, 0, sizeof host);
    host.rx_fd = -1;
    host.rx2_fd = -1;
    while ((c = getopt_long(argc, argv, "qh", opts, 0)) != -1) {
        switch (c) {
        case O_OUT: out = optarg; break;
        case O_PTY: use_pty = 1; break;
        case O_TCP: tcp = num("--tcp", optarg, 0, 65535); break;
        case O_BAUD: baud = num("--baud", optarg, 0, 100000000L); break;
        case O_RAM: ram = num("--ram", optarg, 1, 1L << 30); break;
        case O_SCENE:
            if ((v = r8_demo_by_name(optarg)) >= 0) {
                cfg.scene = (r8_u8)v;
            } else {
                char err[200];
                if (r8_scene_open(optarg, &cfg.demo, err, sizeof err))
                    die(2, "--scene: %s (a scene name: see --help)", err);
            }
            break;
        case O_METHOD:
            if ((v = r8_method_by_name(optarg)) < 0)
                die(2, "--method: unknown method '%s' (see --help)", optarg);
            cfg.render.method = (r8_u8)v;
            method_given = 1;
            break;
        case O_BAND: cfg.render.band = (r8_s16)num("--band", optarg, 1, R8_WIRE_MAX_DIM); band_given = 1; break;
        case O_FRAMES: cfg.frames = (r8_u16)num("--frames", optarg, 0, 65535); break;
        case O_FIRST: cfg.first_frame = (r8_u16)num("--first", optarg, 0, 65535); break;
        case O_W: cfg.render.width = (r8_s16)num("--width", optarg, 1, R8_WIRE_MAX_DIM); break;
        case O_H: cfg.render.height = (r8_s16)num("--height", optarg, 1, R8_WIRE_MAX_DIM); break;
        case O_FMT:
            if ((v = fmt_by_name(optarg)) < 0)
                die(2, "--format: unknown format '%s' (page1, row1, idx8)", optarg);
            cfg.render.format = (r8_u8)v;
            break;
        case O_CODEC:
            if ((v = r8_codec_by_name(optarg)) < 0)
                die(2, "--codec: unknown codec '%s' (rle, lz77, raw)", optarg);
            cfg.codec = (r8_u8)v;
            break;
        case O_PERIOD: cfg.full_period = (r8_u16)num("--full-period", optarg, 0, 65535); break;
        case O_NODIRTY: cfg.dirty = 0; break;
        case O_WIRE: cfg.render.wire = 1; break;
        case O_DUMP: dump = optarg; break;
        case O_RX: rx = optarg; break;
        case O_SHADING:
            if (!strcmp(optarg, "flat")) cfg.render.shading = R8_SHADE_FLAT;
            else if (!strcmp(optarg, "lambert")) cfg.render.shading = R8_SHADE_LAMBERT;
            else if (!strcmp(optarg, "gouraud")) cfg.render.shading = R8_SHADE_GOURAUD;
            else if (!strcmp(optarg, "texture")) cfg.render.shading = R8_SHADE_TEXTURE;
            else die(2, "--shading: unknown shading '%s' (flat, lambert, gouraud, texture)", optarg);
            break;
        case O_PERSP:
            cfg.render.persp = (r8_u8)num("--persp", optarg, 0, 64);
            if (cfg.render.persp == 1)
                die(2, "--persp: %s: 0 (affine) or 2..64", optarg);
            break;
        case O_BILINEAR: cfg.render.texfilter = R8_TEXF_BILINEAR; break;
        case O_KEYS: keys = optarg; break;
        case O_KEYLOG: key_log = optarg; break;
        case O_LINGER: linger = (double)num("--linger", optarg, 0, 86400); break;
        case O_GATE: gate = (double)num("--gate", optarg, 0, 86400) / 1000.0; break;
        case O_PRINTRAM: print_ram = 1; break;
        case 'q': quiet = 1; break;
        case 'h': usage(stdout); return 0;
        default:
            fprintf(stderr, "%s: see --help\n", prog);
            return 2;
        }
    }
    if (optind < argc)
        die(2, "unexpected argument '%s' (see --help)", argv[optind]);
    if ((use_pty != 0) + (tcp >= 0) + (strcmp(out, "-") != 0) > 1)
        die(2, "%s", "choose one of --out, --pty, --tcp");

    if (!method_given && app_demo(&cfg) && app_demo(&cfg)->scene.grid)
        cfg.render.method = R8_VIS_RAY;   /* a grid scene: the ray caster */
    if (cfg.render.method == R8_VIS_AUTO)
        analyse(&cfg, band_given, ram, quiet);

    if (app_demo(&cfg))
        cfg.render.scene = &app_demo(&cfg)->scene;
    if (!r8_render_ram(&cfg.render)) {
        fprintf(stderr, "%s: invalid configuration: the renderer does not accept "
                "scene %s, method %s, %dx%d, format %d, band %d\n", prog,
                (cfg.demo ? cfg.demo->name : r8_demo_name(cfg.scene)), r8_method_name(cfg.render.method),
                cfg.render.width, cfg.render.height, cfg.render.format, cfg.render.band);
        return 2;
    }
    if (!use_pty && tcp < 0 && !strcmp(out, "-") && !print_ram && isatty(1))
        die(2, "%s", "refusing to write a binary stream to a terminal: use --out FILE, "
            "--pty, --tcp PORT, or a pipe (see --help)");
    if (app_plan(&cfg, &lay)) {
        fprintf(stderr, "%s: invalid configuration: %dx%d format %d band %d "
                "(band must be 1..height, a multiple of 8 for page1, and a "
                "band at most %u bytes)\n", prog, cfg.render.width,
                cfg.render.height, cfg.render.format, cfg.render.band,
                R8_WIRE_MAX_BAND);
        return 2;
    }
    need = lay.total;
    if (print_ram) {
        printf("%u bytes: render work %u + band %u + encoder %u\n", need,
               lay.work_size, lay.band_size, lay.scratch_size);
        return 0;
    }
    if (ram >= 0 && (unsigned long)ram < need) {
        fprintf(stderr, "%s: RAM budget exceeded: this config needs %u bytes "
                "(render work %u + band %u + encoder %u) but --ram is %ld\n",
                prog, need, lay.work_size, lay.band_size, lay.scratch_size, ram);
        return 3;
    }
    size = ram >= 0 ? (unsigned)ram : need;
    arena = malloc((size_t)size + GUARD_BYTES);
    if (!arena)
        die(1, "%s", "out of memory");
    memset(arena, 0xCD, size);
    memset(arena + size, GUARD, GUARD_BYTES);

    if (dump) {
        host.dump = fopen(dump, "wb");
        if (!host.dump)
            die(1, "cannot write the dump file: %s", strerror(errno));
        host.frame_bytes = r8_fb_bytes(cfg.render.format, cfg.render.width, cfg.render.height);
        host.frame = calloc(1, host.frame_bytes);
    }
    if (rx) {
        host.rx2_fd = strcmp(rx, "-") ? open(rx, O_RDONLY) : 0;
        if (host.rx2_fd < 0)
            die(1, "cannot read --rx: %s", strerror(errno));
    }
    if (keys && !(host.keys = fopen(keys, "r")))
        die(1, "cannot read the key script: %s", strerror(errno));
    if (key_log && !(host.key_log = fopen(key_log, "w")))
        die(1, "cannot write the key log: %s", strerror(errno));
    host.cfg = &cfg;
    cfg.on_band = on_band;
    cfg.on_frame = on_frame;
    cfg.ctx = &host;

    signal(SIGPIPE, SIG_IGN);
    if (use_pty) {
        fd = open_pty();
        pty_wait_reader(fd);
        wait_first_byte(fd, gate);
        host.rx_fd = fd;
    } else if (tcp >= 0) {
        fd = open_tcp(tcp);
        wait_first_byte(fd, gate);
        host.rx_fd = fd;
    } else if (strcmp(out, "-")) {
        fd = open(out, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd < 0)
            die(1, "cannot write the output file: %s", strerror(errno));
    }

    plat_init();
    plat_host_output(fd, baud);
    rc = app_run(&cfg, arena, size);
    if (rc == APP_E_RAM)
        die(3, "%s", "RAM budget too small");
    if (rc)
        die(2, "%s", "invalid configuration");
    for (k = 0; k < GUARD_BYTES; k++)
        if (arena[size + k] != GUARD) {
            fprintf(stderr, "%s: RAM overrun: a write past the %u-byte arena\n", prog, size);
            return 4;
        }
    if (use_pty)
        pty_linger(fd, linger);
    else if (tcp >= 0)
        tcp_linger(fd, linger);
    if (fd != 1)
        close(fd);
    if (host.dump)
        fclose(host.dump);
    if (host.key_log)
        fclose(host.key_log);
    if (host.bad_keys)
        return 2;
    if (plat_host_failed()) {
        fprintf(stderr, "%s: output failed after %lu bytes (reader went away?)\n",
                prog, plat_host_bytes());
        return 5;
    }
    if (!quiet) {
        unsigned long frames = plat_host_marks(PLAT_MARK_FRAME_END);
        fprintf(stderr, "%s: %lu frames, %lu bytes (%.1f B/frame), %s, RAM %u of %u bytes, %.2f s\n",
                prog, frames, plat_host_bytes(),
                frames ? (double)plat_host_bytes() / (double)frames : 0.0,
                r8_codec_name(cfg.codec), need, size, plat_host_elapsed());
    }
    free(arena);
    free(host.frame);
    return 0;
}
