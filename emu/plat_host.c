/* plat_host.c - the emulator's platform layer: the UART is a file
 * descriptor (file, stdout, pty master or TCP socket), optionally paced
 * to a baud rate; markers are counted. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "plat.h"
#include "plat_host.h"

static int out_fd = 1;
static long out_baud;
static unsigned long out_bytes;
static int out_failed;
static unsigned long marks[8];
static struct timespec t0;

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)(t.tv_sec - t0.tv_sec) + (double)(t.tv_nsec - t0.tv_nsec) / 1e9;
}

void plat_host_output(int fd, long baud)
{
    out_fd = fd;
    out_baud = baud;
    out_bytes = 0;
    out_failed = 0;
    clock_gettime(CLOCK_MONOTONIC, &t0);
}

unsigned long plat_host_bytes(void) { return out_bytes; }
int plat_host_failed(void) { return out_failed; }
unsigned long plat_host_marks(int id) { return id >= 0 && id < 8 ? marks[id] : 0; }
double plat_host_elapsed(void) { return now(); }

void plat_init(void)
{
    clock_gettime(CLOCK_MONOTONIC, &t0);
}

/* Sleep until the line would have sent out_bytes bytes. */
static void pace(void)
{
    double due, d;
    struct timespec ts;
    if (out_baud <= 0)
        return;
    due = (double)out_bytes * 10.0 / (double)out_baud;
    d = due - now();
    if (d <= 0)
        return;
    ts.tv_sec = (time_t)d;
    ts.tv_nsec = (long)((d - (double)ts.tv_sec) * 1e9);
    while (nanosleep(&ts, &ts) && errno == EINTR)
        ;
}

static void write_all(const unsigned char *p, unsigned n)
{
    ssize_t w;
    while (n && !out_failed) {
        w = write(out_fd, p, n);
        if (w < 0) {
            if (errno == EINTR || errno == EAGAIN)
                continue;
            out_failed = 1;
            return;
        }
        p += w;
        n -= (unsigned)w;
    }
}

void plat_write(const r8_u8 *p, unsigned n)
{
    /* paced output goes in small slices so the timing follows the line */
    unsigned slice = out_baud > 0 ? (unsigned)(out_baud / 10 / 100 + 1) : n;
    while (n && !out_failed) {
        unsigned k = n < slice ? n : slice;
        write_all(p, k);
        out_bytes += k;
        p += k;
        n -= k;
        pace();
    }
}

void plat_putc(r8_u8 c)
{
    plat_write(&c, 1);
}

int plat_getc(void)
{
    return -1;   /* the emulator feeds app_rx itself (emu/main.c: --rx, --keys) */
}

void plat_mark(r8_u8 id)
{
    marks[id & 7]++;
}

void plat_exit(int code)
{
    fflush(stdout);
    exit(code);
}
