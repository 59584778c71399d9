/*
 * rast8-usbcat - copy a USB device's bulk IN stream to stdout, a file or a pty.
 *
 * Some boards send the rast8 frame stream on a vendor-class USB bulk IN
 * endpoint instead of a CDC serial port, so there is no tty for serial
 * tools to open.  This tool reads the endpoint through libusb-1.0 and
 * copies the bytes unchanged (the stream is opaque here), so that
 *     rast8-usbcat usb:feed:beef | rast8 decode - -o out
 * or  rast8-usbcat --pty usb:feed:beef   (then open the printed path)
 * works like a serial link.  Host tool, not library code: gnu99, because
 * libusb.h is not C89.  See docs/usb.md.
 *
 * Exit codes (the Python usb: source uses the same numbers):
 *   0 ok (also when the reader closes the pipe/pty)  1 other USB error
 *   2 usage  3 no such device  4 permission denied
 *   5 interface busy  6 unplugged mid-stream  7 endpoint stalled
 *   8 timeout  9 cannot write the output
 * Bytes read before an error are always written out before the error is
 * reported.
 */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <poll.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>
#include <libusb.h>

enum {
    EX_OK = 0, EX_USB = 1, EX_USAGE = 2, EX_NODEV = 3, EX_ACCESS = 4,
    EX_BUSY = 5, EX_UNPLUGGED = 6, EX_STALL = 7, EX_TIMEOUT = 8, EX_OUTPUT = 9
};

#define URB_SIZE 4096          /* bytes per bulk IN request */
#define SLICE_MS 500           /* longest single wait, so Ctrl-C is seen */

static volatile sig_atomic_t stop_requested;
static const char *prog = "rast8-usbcat";
static int quiet;

struct opts {
    int vid, pid, ep;          /* ep: endpoint address, 0x81 by default */
    int bus, addr;             /* -1: any */
    int iface;                 /* -1: the interface owning ep */
    double timeout;            /* s; 0 = wait forever */
    double idle;               /* s; 0 = off */
    long long max_bytes;       /* 0 = no limit */
    const char *out;           /* NULL or "-" = stdout */
    int pty;
    double gate;               /* s to wait for a pty reader's first byte */
    double linger;             /* s to wait for a pty reader to drain */
    int list;
    char spec[64];
};

static void usage(FILE *f)
{
    fprintf(f,
"usage: rast8-usbcat [options] usb:VID:PID[:EP]\n"
"       rast8-usbcat --list\n"
"Copy the bulk IN stream of a USB device (vendor-class interface) to stdout,\n"
"a file or a pseudo-terminal, unchanged.  VID and PID are hex (feed:beef),\n"
"EP is the bulk IN endpoint address in hex (default 81).\n"
"\n"
"options:\n"
"  -o, --output FILE   write to FILE instead of stdout (- = stdout)\n"
"      --pty           create a pty, print its path on stdout and write the\n"
"                      stream to it (open the path with any serial tool);\n"
"                      streaming starts once a reader has opened it\n"
"      --list          list candidate devices: vendor-class interfaces with a\n"
"                      bulk IN endpoint, one usb: spec per line\n"
"  -t, --timeout SEC   fail (exit 8) when no data arrives for SEC seconds\n"
"                      (default 5; 0 = wait forever)\n"
"      --idle SEC      end cleanly (exit 0) once the device has sent data and\n"
"                      then nothing for SEC seconds (for captures)\n"
"  -n, --bytes N       stop after N bytes\n"
"      --bus N         pick the device on bus N (when several match)\n"
"      --addr N        pick the device with address N\n"
"  -i, --interface N   claim interface N (default: the one owning EP)\n"
"      --gate MS       with --pty: once the reader has opened the pty, wait\n"
"                      up to MS ms for its first byte before streaming\n"
"                      (default 2000; rast8 sends one as soon as its port is\n"
"                      open, pyserial discards input that arrives earlier)\n"
"      --linger SEC    with --pty: at the end wait up to SEC s (default 30)\n"
"                      for the reader to read everything (or to close the\n"
"                      pty) before closing it, so no byte is lost\n"
"  -q, --quiet         no summary line on stderr\n"
"  -h, --help          this help\n"
"\n"
"exit codes: 0 ok (also when the reader of the pipe or pty closes it),\n"
"  1 other USB error, 2 usage, 3 no such device,\n"
"  4 permission denied, 5 interface busy, 6 device unplugged mid-stream,\n"
"  7 endpoint stalled, 8 timeout, 9 cannot write the output.\n"
"Bytes received before an error are written out before it is reported.\n"
"Permission denied: install the udev rule from docs/usb.md.\n");
}

static int fail(int code, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static int fail(int code, const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "%s: ", prog);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    return code;
}

static int parse_hex(const char *s, size_t n, int max, int *out)
{
    char buf[16];
    char *end;
    long v;
    if (n == 0 || n >= sizeof buf) return -1;
    memcpy(buf, s, n);
    buf[n] = 0;
    errno = 0;
    v = strtol(buf, &end, 16);
    if (errno || *end || v < 0 || v > max) return -1;
    *out = (int)v;
    return 0;
}

/* usb:VID:PID[:EP] (the "usb:" prefix is optional) */
static int parse_spec(const char *spec, struct opts *o)
{
    const char *p = spec, *c1, *c2;
    if (strncmp(p, "usb:", 4) == 0) p += 4;
    c1 = strchr(p, ':');
    if (!c1) return -1;
    if (parse_hex(p, (size_t)(c1 - p), 0xFFFF, &o->vid)) return -1;
    c2 = strchr(c1 + 1, ':');
    if (parse_hex(c1 + 1, c2 ? (size_t)(c2 - c1 - 1) : strlen(c1 + 1), 0xFFFF, &o->pid)) return -1;
    if (c2) {
        if (parse_hex(c2 + 1, strlen(c2 + 1), 0xFF, &o->ep)) return -1;
        if (!(o->ep & 0x80))
            return -2;
    }
    snprintf(o->spec, sizeof o->spec, "usb:%04x:%04x:%02x", o->vid, o->pid, o->ep);
    return 0;
}

static int parse_num(const char *s, double *out)
{
    char *end;
    double v;
    errno = 0;
    v = strtod(s, &end);
    if (errno || end == s || *end || v < 0 || v > 1e6) return -1;
    *out = v;
    return 0;
}

static int parse_int(const char *s, long long max, long long *out)
{
    char *end;
    long long v;
    errno = 0;
    v = strtoll(s, &end, 0);
    if (errno || end == s || *end || v < 0 || v > max) return -1;
    *out = v;
    return 0;
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec / 1e9;
}

static void on_signal(int sig)
{
    (void)sig;
    stop_requested = 1;
}

/* write all of buf; 0 on success */
static int write_all(int fd, const unsigned char *buf, size_t n)
{
    while (n > 0) {
        ssize_t w = write(fd, buf, n);
        if (w < 0) {
            if (errno == EINTR) continue;
            return -1;
        }
        buf += w;
        n -= (size_t)w;
    }
    return 0;
}

static const char *udev_hint =
    "install the udev rule from docs/usb.md, e.g. in "
    "/etc/udev/rules.d/70-rast8.rules:\n"
    "  SUBSYSTEM==\"usb\", ATTR{idVendor}==\"%04x\", ATTR{idProduct}==\"%04x\", "
    "MODE=\"0660\", TAG+=\"uaccess\"\n"
    "then run 'sudo udevadm control --reload && sudo udevadm trigger' and "
    "re-plug the device (or run as root)";

/* Find the vendor-class (0xff) interface / altsetting owning a bulk IN
 * endpoint `ep`.  Returns 0 and fills iface/alt; -2 (and *iface, *alt =
 * the interface's class) when the endpoint is only on an interface of
 * another class, which is never opened (claiming it would detach e.g.
 * cdc_acm from the board's serial port); -1 if there is no such endpoint. */
static int find_endpoint(libusb_device *dev, int ep, int want_iface, int *iface, int *alt)
{
    int other = -1, other_class = 0;
    struct libusb_config_descriptor *cfg;
    int i, a, e, found = -1;
    if (libusb_get_active_config_descriptor(dev, &cfg) != 0 &&
        libusb_get_config_descriptor(dev, 0, &cfg) != 0)
        return -1;
    for (i = 0; i < cfg->bNumInterfaces && found < 0; i++) {
        const struct libusb_interface *it = &cfg->interface[i];
        for (a = 0; a < it->num_altsetting && found < 0; a++) {
            const struct libusb_interface_descriptor *d = &it->altsetting[a];
            if (want_iface >= 0 && d->bInterfaceNumber != want_iface) continue;
            for (e = 0; e < d->bNumEndpoints; e++) {
                const struct libusb_endpoint_descriptor *ed = &d->endpoint[e];
                if (ed->bEndpointAddress == ep &&
                    (ed->bmAttributes & 3) == LIBUSB_TRANSFER_TYPE_BULK &&
                    d->bInterfaceClass != LIBUSB_CLASS_VENDOR_SPEC && other < 0) {
                    other = d->bInterfaceNumber;
                    other_class = d->bInterfaceClass;
                } else if (ed->bEndpointAddress == ep &&
                    (ed->bmAttributes & 3) == LIBUSB_TRANSFER_TYPE_BULK) {
                    *iface = d->bInterfaceNumber;
                    *alt = d->bAlternateSetting;
                    found = 0;
                    break;
                }
            }
        }
    }
    libusb_free_config_descriptor(cfg);
    if (found < 0 && other >= 0) {
        *iface = other;
        *alt = other_class;
        return -2;
    }
    return found;
}

static int do_list(libusb_context *ctx)
{
    libusb_device **list;
    ssize_t n, i;
    int shown = 0;
    n = libusb_get_device_list(ctx, &list);
    if (n < 0)
        return fail(EX_USB, "cannot enumerate USB devices: %s", libusb_strerror((int)n));
    for (i = 0; i < n; i++) {
        struct libusb_device_descriptor dd;
        struct libusb_config_descriptor *cfg;
        int k, a, e;
        if (libusb_get_device_descriptor(list[i], &dd) != 0) continue;
        if (libusb_get_active_config_descriptor(list[i], &cfg) != 0 &&
            libusb_get_config_descriptor(list[i], 0, &cfg) != 0)
            continue;
        for (k = 0; k < cfg->bNumInterfaces; k++) {
            const struct libusb_interface *it = &cfg->interface[k];
            for (a = 0; a < it->num_altsetting; a++) {
                const struct libusb_interface_descriptor *d = &it->altsetting[a];
                if (d->bInterfaceClass != LIBUSB_CLASS_VENDOR_SPEC) continue;
                for (e = 0; e < d->bNumEndpoints; e++) {
                    const struct libusb_endpoint_descriptor *ed = &d->endpoint[e];
                    if ((ed->bmAttributes & 3) != LIBUSB_TRANSFER_TYPE_BULK ||
                        !(ed->bEndpointAddress & 0x80))
                        continue;
                    printf("usb:%04x:%04x:%02x  bus %03u addr %03u  interface %u alt %u"
                           "  max packet %u\n",
                           dd.idVendor, dd.idProduct, ed->bEndpointAddress,
                           libusb_get_bus_number(list[i]), libusb_get_device_address(list[i]),
                           d->bInterfaceNumber, d->bAlternateSetting, ed->wMaxPacketSize);
                    shown++;
                }
            }
        }
        libusb_free_config_descriptor(cfg);
    }
    libusb_free_device_list(list, 1);
    if (!shown)
        fprintf(stderr, "%s: no vendor-class interface with a bulk IN endpoint found "
                "(is the board plugged in? 'lsusb' lists all devices)\n", prog);
    fflush(stdout);
    return EX_OK;
}

/* pty: master fd and slave path.  The slave is opened once to make it raw
 * (no echo, no CR/LF translation; the setting stays with the pty), then
 * closed, so that the master polls POLLHUP whenever no reader has it open. */
static int open_pty(int *master, char *path, size_t pathlen)
{
    struct termios t;
    const char *name;
    int s, m = posix_openpt(O_RDWR | O_NOCTTY);
    if (m < 0 || grantpt(m) || unlockpt(m) || !(name = ptsname(m))) return -1;
    snprintf(path, pathlen, "%s", name);
    s = open(path, O_RDWR | O_NOCTTY);
    if (s < 0) return -1;
    if (tcgetattr(s, &t) == 0) {
        cfmakeraw(&t);
        tcsetattr(s, TCSANOW, &t);
    }
    close(s);
    *master = m;
    return 0;
}

static int pty_reader_present(int master)
{
    struct pollfd p;
    p.fd = master;
    p.events = POLLIN;
    p.revents = 0;
    poll(&p, 1, 0);
    return !(p.revents & POLLHUP);
}

/* Read and drop what the reader sent (rast8 sends requests; we are
 * read-only towards the board).  Returns 1 if something was read. */
static int pty_discard_input(int master, int wait_ms)
{
    unsigned char junk[256];
    struct pollfd p;
    p.fd = master;
    p.events = POLLIN;
    p.revents = 0;
    if (poll(&p, 1, wait_ms) > 0 && (p.revents & POLLIN) && !(p.revents & POLLHUP))
        return read(master, junk, sizeof junk) > 0;
    return 0;
}

/* Wait for a reader to open the pty, then up to gate s for its first byte.
 * Returns 0, or -1 if interrupted. */
static int pty_wait_reader(int master, double gate)
{
    double end;
    while (!pty_reader_present(master)) {
        if (stop_requested) return -1;
        usleep(20000);
    }
    end = now_s() + gate;
    while (now_s() < end) {
        if (stop_requested) return -1;
        if (pty_discard_input(master, 20)) break;
        if (!pty_reader_present(master)) break;
    }
    return 0;
}

/* Write all of buf to the (non-blocking) master, waiting while the
 * reader is slow; fails with EPIPE if the reader closes the pty. */
static int pty_write_all(int master, const unsigned char *buf, size_t n)
{
    while (n > 0) {
        ssize_t w = write(master, buf, n);
        if (w > 0) {
            buf += w;
            n -= (size_t)w;
            continue;
        }
        if (w < 0 && errno != EAGAIN && errno != EINTR) return -1;
        if (!pty_reader_present(master)) {
            errno = EPIPE;
            return -1;
        }
        pty_discard_input(master, 0);
        {
            struct pollfd p;
            p.fd = master;
            p.events = POLLOUT;
            p.revents = 0;
            poll(&p, 1, 50);
        }
    }
    return 0;
}

/* At the end: wait until the reader has read everything (FIONREAD on a
 * slave fd, where the kernel supports it) or has closed the pty, at most
 * linger s.  Closing the master drops what the reader has not read. */
static void pty_drain(int master, const char *path, double linger)
{
    double end = now_s() + linger;
    int zeros = 0, n = 0;
    int s = open(path, O_RDONLY | O_NOCTTY | O_NONBLOCK);
    if (s >= 0 && ioctl(s, FIONREAD, &n) != 0) {
        close(s);                   /* no FIONREAD: wait for the reader to close */
        s = -1;
    }
    while (now_s() < end && !stop_requested) {
        if (s >= 0) {
            if (ioctl(s, FIONREAD, &n) == 0 && n == 0) {
                if (++zeros >= 4) break;    /* empty for 200 ms: all read */
            } else {
                zeros = 0;
            }
        } else if (!pty_reader_present(master)) {
            break;
        }
        pty_discard_input(master, 50);
    }
    if (s >= 0) close(s);
}

int main(int argc, char **argv)
{
    struct opts o;
    libusb_context *ctx = NULL;
    libusb_device **list = NULL, *dev = NULL;
    libusb_device_handle *h = NULL;
    ssize_t n, i;
    int matches = 0, iface = -1, alt = 0, r, rc = EX_OK, outfd = 1;
    int claimed = 0, detached = 0, reader_gone = 0;
    long long total = 0;
    const char *spec = NULL;
    char ptypath[PATH_MAX];
    static unsigned char buf[URB_SIZE];
    double last_data, t0;
    struct sigaction sa;

    memset(&o, 0, sizeof o);
    o.ep = 0x81; o.bus = -1; o.addr = -1; o.iface = -1; o.timeout = 5.0; o.linger = 30.0; o.gate = 2.0;

    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *val = (i + 1 < argc) ? argv[i + 1] : NULL;
        long long ll;
#define NEED_VAL() do { if (!val) { fprintf(stderr, "%s: %s needs a value\n", prog, a); usage(stderr); return EX_USAGE; } i++; } while (0)
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) { usage(stdout); return EX_OK; }
        else if (!strcmp(a, "--list")) o.list = 1;
        else if (!strcmp(a, "--pty")) o.pty = 1;
        else if (!strcmp(a, "-q") || !strcmp(a, "--quiet")) quiet = 1;
        else if (!strcmp(a, "-o") || !strcmp(a, "--output")) { NEED_VAL(); o.out = val; }
        else if (!strcmp(a, "-t") || !strcmp(a, "--timeout")) {
            NEED_VAL();
            if (parse_num(val, &o.timeout)) return fail(EX_USAGE, "bad --timeout '%s' (seconds, >= 0)", val);
        } else if (!strcmp(a, "--idle")) {
            NEED_VAL();
            if (parse_num(val, &o.idle)) return fail(EX_USAGE, "bad --idle '%s' (seconds, >= 0)", val);
        } else if (!strcmp(a, "--gate")) {
            NEED_VAL();
            if (parse_num(val, &o.gate)) return fail(EX_USAGE, "bad --gate '%s' (milliseconds, >= 0)", val);
            o.gate /= 1000.0;
        } else if (!strcmp(a, "--linger")) {
            NEED_VAL();
            if (parse_num(val, &o.linger)) return fail(EX_USAGE, "bad --linger '%s' (seconds, >= 0)", val);
        } else if (!strcmp(a, "-n") || !strcmp(a, "--bytes")) {
            NEED_VAL();
            if (parse_int(val, (long long)1 << 50, &ll) || ll == 0) return fail(EX_USAGE, "bad --bytes '%s' (a count > 0)", val);
            o.max_bytes = ll;
        } else if (!strcmp(a, "--bus")) {
            NEED_VAL();
            if (parse_int(val, 255, &ll)) return fail(EX_USAGE, "bad --bus '%s'", val);
            o.bus = (int)ll;
        } else if (!strcmp(a, "--addr")) {
            NEED_VAL();
            if (parse_int(val, 255, &ll)) return fail(EX_USAGE, "bad --addr '%s'", val);
            o.addr = (int)ll;
        } else if (!strcmp(a, "-i") || !strcmp(a, "--interface")) {
            NEED_VAL();
            if (parse_int(val, 255, &ll)) return fail(EX_USAGE, "bad --interface '%s'", val);
            o.iface = (int)ll;
        } else if (a[0] == '-' && a[1]) {
            fprintf(stderr, "%s: unknown option '%s'\n", prog, a);
            usage(stderr);
            return EX_USAGE;
        } else if (!spec) spec = a;
        else return fail(EX_USAGE, "more than one device given ('%s', '%s'); see --help", spec, a);
#undef NEED_VAL
    }

    if (!o.list) {
        if (!spec) {
            fprintf(stderr, "%s: no device given\n", prog);
            usage(stderr);
            return EX_USAGE;
        }
        r = parse_spec(spec, &o);
        if (r == -2)
            return fail(EX_USAGE, "endpoint in '%s' is an OUT endpoint; give a bulk IN "
                        "address (bit 7 set, e.g. 81)", spec);
        if (r)
            return fail(EX_USAGE, "bad device '%s': expected usb:VID:PID[:EP] with hex "
                        "numbers, e.g. usb:feed:beef or usb:feed:beef:81", spec);
        if (o.pty && o.out)
            return fail(EX_USAGE, "--pty and -o are exclusive");
    }

    r = libusb_init(&ctx);
    if (r != 0)
        return fail(EX_USB, "cannot initialise libusb: %s", libusb_strerror(r));

    if (o.list) {
        rc = do_list(ctx);
        libusb_exit(ctx);
        return rc;
    }

    /* select the device */
    n = libusb_get_device_list(ctx, &list);
    if (n < 0) {
        rc = fail(EX_USB, "cannot enumerate USB devices: %s", libusb_strerror((int)n));
        goto out;
    }
    for (i = 0; i < n; i++) {
        struct libusb_device_descriptor dd;
        if (libusb_get_device_descriptor(list[i], &dd) != 0) continue;
        if (dd.idVendor != o.vid || dd.idProduct != o.pid) continue;
        if (o.bus >= 0 && libusb_get_bus_number(list[i]) != o.bus) continue;
        if (o.addr >= 0 && libusb_get_device_address(list[i]) != o.addr) continue;
        /* "first" = the lowest bus number, then the lowest address */
        if (!dev || libusb_get_bus_number(list[i]) < libusb_get_bus_number(dev) ||
            (libusb_get_bus_number(list[i]) == libusb_get_bus_number(dev) &&
             libusb_get_device_address(list[i]) < libusb_get_device_address(dev)))
            dev = list[i];
        matches++;
    }
    if (!dev) {
        rc = fail(EX_NODEV, "no such device: no USB device %04x:%04x%s is connected. "
                  "Plug the board in (check the cable carries data), check VID:PID with "
                  "'rast8-usbcat --list' or 'lsusb'", o.vid, o.pid,
                  (o.bus >= 0 || o.addr >= 0) ? " at the given --bus/--addr" : "");
        goto out;
    }
    if (matches > 1 && !quiet)
        fprintf(stderr, "%s: %d devices match %04x:%04x; using bus %u addr %u "
                "(choose with --bus/--addr)\n", prog, matches, o.vid, o.pid,
                libusb_get_bus_number(dev), libusb_get_device_address(dev));
    r = find_endpoint(dev, o.ep, o.iface, &iface, &alt);
    if (r == -2) {
        rc = fail(EX_NODEV, "not a vendor-class interface: endpoint 0x%02x of %04x:%04x is on "
                  "interface %d of class 0x%02x%s, which rast8 does not open (it would take "
                  "the interface from its kernel driver, e.g. the board's serial port). Use "
                  "the vendor-class endpoint that 'rast8-usbcat --list' shows, or read the "
                  "serial port", o.ep, o.vid, o.pid, iface, alt,
                  alt == 0x0a ? " (CDC data)" : alt == 0x02 ? " (CDC control)" : "");
        goto out;
    }
    if (r != 0) {
        if (o.iface >= 0)
            rc = fail(EX_NODEV, "no such endpoint: interface %d of %04x:%04x has no bulk "
                      "IN endpoint 0x%02x; 'rast8-usbcat --list' shows the endpoints",
                      o.iface, o.vid, o.pid, o.ep);
        else
            rc = fail(EX_NODEV, "no such endpoint: %04x:%04x has no bulk IN endpoint "
                      "0x%02x; 'rast8-usbcat --list' shows the endpoints", o.vid, o.pid, o.ep);
        goto out;
    }

    r = libusb_open(dev, &h);
    if (r == LIBUSB_ERROR_ACCESS) {
        fprintf(stderr, "%s: permission denied opening %04x:%04x (bus %03u addr %03u): ",
                prog, o.vid, o.pid, libusb_get_bus_number(dev), libusb_get_device_address(dev));
        fprintf(stderr, udev_hint, o.vid, o.pid);
        fputc('\n', stderr);
        rc = EX_ACCESS;
        goto out;
    }
    if (r == LIBUSB_ERROR_NO_DEVICE) {
        rc = fail(EX_NODEV, "no such device: %04x:%04x went away while opening it; "
                  "re-plug it and retry", o.vid, o.pid);
        goto out;
    }
    if (r != 0) {
        rc = fail(EX_USB, "cannot open %04x:%04x: %s", o.vid, o.pid, libusb_strerror(r));
        goto out;
    }
    /* detach a kernel driver bound to the interface (re-attached at exit) */
    r = libusb_kernel_driver_active(h, iface);
    if (r == 1) {
        r = libusb_detach_kernel_driver(h, iface);
        if (r == 0) detached = 1;
        else if (r != LIBUSB_ERROR_NOT_FOUND && !quiet)
            fprintf(stderr, "%s: cannot detach the kernel driver of interface %d: %s\n",
                    prog, iface, libusb_strerror(r));
    }
    r = libusb_claim_interface(h, iface);
    if (r == LIBUSB_ERROR_BUSY) {
        rc = fail(EX_BUSY, "interface busy: interface %d of %04x:%04x is claimed by another "
                  "program (another rast8-usbcat or rast8 viewer?) or by a kernel driver "
                  "that could not be detached. Close that program and retry", iface,
                  o.vid, o.pid);
        goto out;
    }
    if (r == LIBUSB_ERROR_ACCESS) {
        fprintf(stderr, "%s: permission denied claiming interface %d of %04x:%04x "
                "(detaching its kernel driver needs root): ", prog, iface, o.vid, o.pid);
        fprintf(stderr, udev_hint, o.vid, o.pid);
        fputc('\n', stderr);
        rc = EX_ACCESS;
        goto out;
    }
    if (r == LIBUSB_ERROR_NO_DEVICE) {
        rc = fail(EX_UNPLUGGED, "device unplugged: %04x:%04x disappeared before streaming "
                  "began; re-plug it and retry", o.vid, o.pid);
        goto out;
    }
    if (r != 0) {
        rc = fail(EX_USB, "cannot claim interface %d of %04x:%04x: %s", iface, o.vid, o.pid,
                  libusb_strerror(r));
        goto out;
    }
    claimed = 1;
    if (alt != 0) {
        r = libusb_set_interface_alt_setting(h, iface, alt);
        if (r != 0) {
            rc = fail(EX_USB, "cannot select alternate setting %d of interface %d: %s",
                      alt, iface, libusb_strerror(r));
            goto out;
        }
    }
    /* a halt left over from an earlier run would stall the first read */
    libusb_clear_halt(h, (unsigned char)o.ep);

    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    signal(SIGPIPE, SIG_IGN);

    /* output */
    if (o.pty) {
        if (open_pty(&outfd, ptypath, sizeof ptypath) != 0) {
            rc = fail(EX_OUTPUT, "cannot create a pty: %s", strerror(errno));
            goto out;
        }
        printf("%s\n", ptypath);
        fflush(stdout);
        if (pty_wait_reader(outfd, o.gate) != 0) goto out;
        fcntl(outfd, F_SETFL, fcntl(outfd, F_GETFL) | O_NONBLOCK);
    } else if (o.out && strcmp(o.out, "-") != 0) {
        outfd = open(o.out, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (outfd < 0) {
            rc = fail(EX_OUTPUT, "cannot write '%s': %s", o.out, strerror(errno));
            goto out;
        }
    }

    t0 = last_data = now_s();
    for (;;) {
        int got = 0, want = URB_SIZE;
        double limit, left;
        unsigned int slice;
        if (stop_requested) break;
        if (o.max_bytes && total >= o.max_bytes) break;
        limit = (total > 0 && o.idle > 0) ? o.idle : o.timeout;
        left = limit > 0 ? limit - (now_s() - last_data) : SLICE_MS / 1000.0;
        /* always ask the device once more before giving up, so a slow
         * host (not a quiet device) never ends the stream early */
        slice = left > 0 ? (unsigned int)(left * 1000.0 + 0.5) : 1;
        if (slice > SLICE_MS) slice = SLICE_MS;
        if (slice == 0) slice = 1;
        if (o.pty) {
            pty_discard_input(outfd, 0);
            if (!pty_reader_present(outfd)) {
                reader_gone = 1;
                break;
            }
        }
        r = libusb_bulk_transfer(h, (unsigned char)o.ep, buf, want, &got, slice);
        if (got > 0) {
            long long keep = got;
            if (o.max_bytes && total + keep > o.max_bytes) keep = o.max_bytes - total;
            if ((o.pty ? pty_write_all(outfd, buf, (size_t)keep)
                       : write_all(outfd, buf, (size_t)keep)) != 0) {
                if (errno == EPIPE)     /* the reader is done: a normal end */
                    reader_gone = 1;
                else
                    rc = fail(EX_OUTPUT, "cannot write the output: %s", strerror(errno));
                break;
            }
            total += keep;
            last_data = now_s();
        }
        if (r == 0 || r == LIBUSB_ERROR_TIMEOUT || r == LIBUSB_ERROR_INTERRUPTED) {
            if (got == 0 && limit > 0 && now_s() - last_data >= limit) {
                if (total > 0 && o.idle > 0) break;           /* clean end */
                rc = fail(EX_TIMEOUT, "timeout: no data from %s for %.1f s%s. Check that "
                          "the firmware is streaming, or wait longer with --timeout SEC "
                          "(0 = forever)%s", o.spec, limit,
                          total ? " (after the data so far)" : "",
                          total ? "; --idle SEC ends a capture cleanly" : "");
                break;
            }
            continue;
        }
        if (r == LIBUSB_ERROR_NO_DEVICE) {
            rc = fail(EX_UNPLUGGED, "device unplugged: %s disappeared mid-stream after %lld "
                      "bytes (all written out). Check the cable and power, re-plug and "
                      "run again", o.spec, total);
        } else if (r == LIBUSB_ERROR_PIPE) {
            rc = fail(EX_STALL, "endpoint stalled: the device halted endpoint 0x%02x after "
                      "%lld bytes (all written out). The firmware reported an error; reset "
                      "the board and run again (the halt is cleared on start)", o.ep, total);
        } else if (r == LIBUSB_ERROR_OVERFLOW) {
            rc = fail(EX_USB, "USB overflow on endpoint 0x%02x after %lld bytes: the device "
                      "sent more than was asked for", o.ep, total);
        } else if (r == LIBUSB_ERROR_IO) {
            rc = fail(EX_USB, "USB bus error on %s after %lld bytes (all written out): the "
                      "transfer failed on the wire (EPROTO/EILSEQ/ETIME: bad signal, noise or "
                      "power). Try another cable, a port on the computer itself rather than a "
                      "hub, or a powered hub, then run again", o.spec, total);
        } else {
            rc = fail(EX_USB, "USB read error on %s after %lld bytes: %s", o.spec, total,
                      libusb_strerror(r));
        }
        break;
    }
    if (o.pty && outfd > 2 && rc != EX_OUTPUT && !reader_gone)
        pty_drain(outfd, ptypath, o.linger);
    if (!quiet)
        fprintf(stderr, "%s: %lld bytes from %s in %.2f s%s\n", prog, total, o.spec,
                now_s() - t0, stop_requested ? " (interrupted)" :
                reader_gone ? " (the reader closed the output)" : "");

out:
    if (outfd > 2) close(outfd);
    if (claimed) libusb_release_interface(h, iface);
    if (detached) libusb_attach_kernel_driver(h, iface);
    if (h) libusb_close(h);
    if (list) libusb_free_device_list(list, 1);
    libusb_exit(ctx);
    return rc;
}
