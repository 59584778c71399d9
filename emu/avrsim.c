/* avrsim.c - rast8's libsimavr runner (host tool, C99, GPL-3+ libsimavr).
 *
 *   avrsim [options] MCU ELF
 *     -f HZ        clock (default 16000000)
 *     -o FILE      UART bytes to FILE (default: stdout), binary-safe
 *     -p           UART bytes to a new pty; its name is printed on stderr
 *                  as "PTY /dev/pts/N"; the run starts after a line on
 *                  stdin (gate), and the pty stays open -k seconds after
 *     -k SEC       pty linger (default 2)
 *     -l CYCLES    cycle limit (default 4e9); exit 124 when hit
 *     -m FILE      marker log (default: stderr)
 *     -q           no marker lines, only the summary
 *     -P FILE      profile: cycles per function (ELF symbols) spent inside
 *                  frames (between markers 2 and 3), written to FILE;
 *                  libgcc's shared register saves (-mcall-prologues)
 *                  are charged to the function that jumped into them
 *     -F N         profile only frames N and later (default 0)
 *     -i FILE      bytes for the UART receiver (the display's side), one
 *                  at a time as the firmware reads them: the next byte
 *                  goes in when RXEN0 is set, RXC0 is clear and the last one went in
 *                  at least two byte times (400 cycles) before
 *     -H FILE      per instruction: "addr cycles executions" (hex address)
 *                  inside the profiled frames, for avr-objdump annotation
 *
 * Markers: every write to GPIOR0 (0x3E) logs
 *     MARK id cycle=C delta=D wait=W
 * D is the cycles since the previous marker, W the part of them spent in
 * the firmware's UART busy-wait (function plat_avr_txwait, found in the
 * ELF symbols), so D-W is compute.  A FRAME line follows every marker 3
 * (PLAT_MARK_FRAME_END) that has a marker 2 before it:
 *     FRAME n cycles=C compute=C-W
 * At the end:
 *     END state=done|crashed|limit code=N cycles=C
 *     RAM static=S stack_peak=P ramend=0x..
 * The stack peak comes from painting free RAM (end of .bss .. RAMEND)
 * with 0xA5 before reset and finding the lowest overwritten byte.
 * Exit status: the firmware's exit code (GPIOR1) when it stopped with
 * cli+sleep, 124 on the cycle limit, 125 on a crash, 2 on usage errors.
 */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <stdarg.h>
#include <unistd.h>
#include <fcntl.h>
#include <termios.h>
#include <pty.h>
#include "sim_avr.h"
#include "sim_elf.h"
#include "sim_io.h"
#include "avr_uart.h"

#define GPIOR0_ADDR 0x3E /* data-space address on m328p / m1284p / m2560 */
#define GPIOR1_ADDR 0x4A
#define RAMSTART 0x100
#define PAINT 0xA5

static FILE *uart_fp;
static int pty_fd = -1;
static FILE *mark_fp;
static int quiet;
static avr_cycle_count_t last_mark, wait_since_mark, prev_cycle;
static uint32_t wait_lo = 1, wait_hi = 0; /* [lo, hi) of plat_avr_txwait */
static int in_frame;
static unsigned frame_no;

/* profile: function start addresses (sorted) and cycles */
typedef struct { uint32_t addr; const char *name; unsigned long long cyc; int shared; } prof_fn;
static prof_fn *prof;
static int nprof;
static int prof_owner = -1;   /* the last function outside libgcc's shared saves */
static unsigned prof_from;
static unsigned long long *hist_cyc;   /* -H: per byte address */
static unsigned long *hist_n;

static int prof_cmp(const void *a, const void *b)
{
    const prof_fn *x = a, *y = b;
    return x->addr < y->addr ? -1 : x->addr > y->addr;
}

static int prof_cmp_cyc(const void *a, const void *b)
{
    const prof_fn *x = a, *y = b;
    return x->cyc < y->cyc ? 1 : x->cyc > y->cyc ? -1 : 0;
}

/* The linker's absolute symbols (memory region sizes, __stack) are not
 * code: an address range after one would be charged to it. */
static int is_abs_symbol(const char *name)
{
    size_t n = strlen(name);
    return !strcmp(name, "__stack") ||
           (n > 9 && (!strcmp(name + n - 9, "_LENGTH__") || !strcmp(name + n - 9, "_ORIGIN__")));
}

static void prof_init(elf_firmware_t *fw)
{
    uint32_t i;
    prof = calloc(fw->symbolcount + 1, sizeof *prof);
    for (i = 0; i < fw->symbolcount; i++)
        if (fw->symbol[i]->addr < 0x800000u && fw->symbol[i]->symbol[0] != '.' &&
            !is_abs_symbol(fw->symbol[i]->symbol)) {
            prof[nprof].addr = fw->symbol[i]->addr;
            prof[nprof].name = fw->symbol[i]->symbol;
            prof[nprof].shared = !strcmp(prof[nprof].name, "__prologue_saves__") ||
                                 !strcmp(prof[nprof].name, "__epilogue_restores__");
            nprof++;
        }
    qsort(prof, nprof, sizeof *prof, prof_cmp);
}

static void prof_add(uint32_t pc, avr_cycle_count_t c)
{
    int lo = 0, hi = nprof - 1, k = -1;
    while (lo <= hi) {
        int mid = (lo + hi) / 2;
        if (prof[mid].addr <= pc) {
            k = mid;
            lo = mid + 1;
        } else {
            hi = mid - 1;
        }
    }
    if (k < 0)
        return;
    /* -mcall-prologues: a function jumps into libgcc's shared register
     * saves and restores; their cycles are the caller's (so bench.py's
     * render / wire split charges them to the right side) */
    if (prof[k].shared) {
        if (prof_owner >= 0)
            k = prof_owner;
    } else {
        prof_owner = k;
    }
    prof[k].cyc += c;
}

static void quiet_logger(struct avr_t *avr, const int level, const char *fmt, va_list ap)
{
    (void)avr;
    if (level <= LOG_WARNING && level != LOG_OUTPUT)
        vfprintf(stderr, fmt, ap);
}

static void uart_out(struct avr_irq_t *irq, uint32_t value, void *param)
{
    unsigned char c = (unsigned char)(value & 0xFF);
    (void)irq;
    (void)param;
    if (pty_fd >= 0) {
        while (write(pty_fd, &c, 1) != 1)
            usleep(1000);
    } else {
        putc(c, uart_fp);
    }
}

static void mark_write(struct avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param)
{
    avr_cycle_count_t d = avr->cycle - last_mark;
    (void)param;
    avr->data[addr] = v; /* io-write hooks must store the value */
    if (!quiet)
        fprintf(mark_fp, "MARK %u cycle=%llu delta=%llu wait=%llu\n", v,
                (unsigned long long)avr->cycle, (unsigned long long)d,
                (unsigned long long)wait_since_mark);
    if (v == 2) {
        in_frame = 1;
    } else if (v == 3 && in_frame) {
        fprintf(mark_fp, "FRAME %u cycles=%llu compute=%llu\n", frame_no++,
                (unsigned long long)d, (unsigned long long)(d - wait_since_mark));
        in_frame = 0;
    }
    last_mark = avr->cycle;
    wait_since_mark = 0;
}

static void no_sleep(struct avr_t *avr, avr_cycle_count_t howLong)
{
    (void)avr;
    (void)howLong;
}

static void find_txwait(elf_firmware_t *fw)
{
    uint32_t i, lo = 0, hi = 0xFFFFFFFFu;
    int found = 0;
    for (i = 0; i < fw->symbolcount; i++)
        if (!strcmp(fw->symbol[i]->symbol, "plat_avr_txwait")) {
            lo = fw->symbol[i]->addr;
            found = 1;
        }
    if (!found)
        return;
    for (i = 0; i < fw->symbolcount; i++) {
        uint32_t a = fw->symbol[i]->addr;
        if (a > lo && a < hi && a < 0x800000u)
            hi = a;
    }
    if (hi - lo > 64) /* the loop is a handful of words */
        hi = lo + 16;
    wait_lo = lo;
    wait_hi = hi;
}

static int open_pty(void)
{
    int master, slave;
    char name[128];
    struct termios t;
    if (openpty(&master, &slave, name, NULL, NULL) < 0) {
        perror("openpty");
        return -1;
    }
    tcgetattr(slave, &t);
    cfmakeraw(&t);
    tcsetattr(slave, TCSANOW, &t);
    fprintf(stderr, "PTY %s\n", name);
    fflush(stderr);
    /* keep the slave open so early bytes are buffered, not dropped */
    return master;
}

int main(int argc, char **argv)
{
    elf_firmware_t fw;
    avr_t *avr;
    uint32_t flags = 0, freq = 16000000u;
    int state, opt, use_pty = 0, linger = 2, code;
    unsigned long long maxc = 4000000000ULL;
    const char *out = NULL, *marks = NULL, *proff = NULL, *histf = NULL, *inf = NULL;
    unsigned char *rx = NULL;
    long rx_n = 0, rx_at = 0;
    avr_cycle_count_t rx_last = 0;
    avr_irq_t *rx_irq;
    uint32_t a, static_end, low, sp_min_pc = 0;
    uint16_t sp_min = 0xFFFF;

    while ((opt = getopt(argc, argv, "f:o:pk:l:m:qP:F:H:i:")) != -1) {
        switch (opt) {
        case 'f': freq = strtoul(optarg, 0, 0); break;
        case 'o': out = optarg; break;
        case 'p': use_pty = 1; break;
        case 'k': linger = atoi(optarg); break;
        case 'l': maxc = strtoull(optarg, 0, 0); break;
        case 'm': marks = optarg; break;
        case 'q': quiet = 1; break;
        case 'P': proff = optarg; break;
        case 'F': prof_from = (unsigned)atoi(optarg); break;
        case 'H': histf = optarg; break;
        case 'i': inf = optarg; break;
        default: goto usage;
        }
    }
    if (argc - optind != 2) {
usage:
        fprintf(stderr, "usage: %s [-f HZ] [-o FILE | -p [-k SEC]] [-l CYCLES] [-m FILE] [-q] [-P FILE [-F N]] [-H FILE] [-i FILE] MCU ELF\n", argv[0]);
        return 2;
    }
    uart_fp = stdout;
    if (out && strcmp(out, "-") && !(uart_fp = fopen(out, "wb"))) {
        perror(out);
        return 2;
    }
    mark_fp = stderr;
    if (marks && !(mark_fp = fopen(marks, "w"))) {
        perror(marks);
        return 2;
    }
    avr_global_logger_set(quiet_logger); /* keep stdout binary-clean */
    memset(&fw, 0, sizeof fw);
    if (elf_read_firmware(argv[optind + 1], &fw)) {
        fprintf(stderr, "avrsim: cannot read %s\n", argv[optind + 1]);
        return 2;
    }
    if (!(avr = avr_make_mcu_by_name(argv[optind]))) {
        fprintf(stderr, "avrsim: unknown MCU %s\n", argv[optind]);
        return 2;
    }
    avr_init(avr);
    avr->frequency = freq;
    avr_load_firmware(avr, &fw);
    avr->sleep = no_sleep; /* don't throttle to wall clock */
    find_txwait(&fw);
    if (proff)
        prof_init(&fw);
    if (histf) {
        hist_cyc = calloc(avr->flashend + 1, sizeof *hist_cyc);
        hist_n = calloc(avr->flashend + 1, sizeof *hist_n);
    }

    /* paint free RAM: end of .data+.bss .. RAMEND */
    static_end = RAMSTART + fw.datasize + fw.bsssize;
    for (a = static_end; a <= avr->ramend; a++)
        avr->data[a] = PAINT;

    avr_ioctl(avr, AVR_IOCTL_UART_GET_FLAGS('0'), &flags);
    flags &= ~AVR_UART_FLAG_STDIO;
    avr_ioctl(avr, AVR_IOCTL_UART_SET_FLAGS('0'), &flags);
    avr_irq_register_notify(avr_io_getirq(avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUTPUT),
                            uart_out, NULL);
    avr_register_io_write(avr, GPIOR0_ADDR, mark_write, NULL);
    rx_irq = avr_io_getirq(avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_INPUT);
    if (inf) {
        FILE *f = fopen(inf, "rb");
        if (!f || !(rx = malloc(1 << 20))) {
            fprintf(stderr, "avrsim: cannot read %s\n", inf);
            return 2;
        }
        rx_n = (long)fread(rx, 1, 1 << 20, f);
        fclose(f);
    }

    if (use_pty) {
        char line[64];
        if ((pty_fd = open_pty()) < 0)
            return 2;
        if (!fgets(line, sizeof line, stdin)) /* gate: wait for the reader */
            line[0] = 0;
    }

    prev_cycle = avr->cycle;
    do {
        uint32_t pc = avr->pc;
        uint16_t sp = (uint16_t)(avr->data[0x5D] | avr->data[0x5E] << 8);
        if (sp < sp_min) {
            sp_min = sp;
            sp_min_pc = pc;
        }
        state = avr_run(avr);
        if (rx_at < rx_n && (avr->data[0xC1] & 0x10) && !(avr->data[0xC0] & 0x80)
            && avr->cycle - rx_last >= 400) {
            /* receiver on (UCSR0B.RXEN0), UCSR0A.RXC0 clear: the next byte */
            avr_raise_irq(rx_irq, rx[rx_at++]);
            rx_last = avr->cycle;
        }
        if (pc >= wait_lo && pc < wait_hi)
            wait_since_mark += avr->cycle - prev_cycle;
        else if (in_frame && frame_no >= prof_from) {
            if (prof)
                prof_add(pc, avr->cycle - prev_cycle);
            if (hist_cyc && pc <= avr->flashend) {
                hist_cyc[pc] += avr->cycle - prev_cycle;
                hist_n[pc]++;
            }
        }
        prev_cycle = avr->cycle;
    } while (state != cpu_Done && state != cpu_Crashed && avr->cycle < maxc);
    fflush(uart_fp);

    low = avr->ramend + 1;
    for (a = static_end; a <= avr->ramend; a++)
        if (avr->data[a] != PAINT) {
            low = a;
            break;
        }
    code = avr->data[GPIOR1_ADDR];
    fprintf(mark_fp, "END state=%s code=%d cycles=%llu\n",
            state == cpu_Done ? "done" : state == cpu_Crashed ? "crashed" : "limit",
            code, (unsigned long long)avr->cycle);
    fprintf(mark_fp, "RAM static=%u stack_peak=%u ramend=0x%x sp_min_pc=0x%x\n",
            (unsigned)(fw.datasize + fw.bsssize), (unsigned)(avr->ramend + 1 - low),
            (unsigned)avr->ramend, (unsigned)sp_min_pc);
    fflush(mark_fp);
    if (prof) {
        FILE *pf = fopen(proff, "w");
        unsigned long long tot = 0;
        int i;
        for (i = 0; i < nprof; i++)
            tot += prof[i].cyc;
        qsort(prof, nprof, sizeof *prof, prof_cmp_cyc);
        if (pf) {
            fprintf(pf, "# cycles inside frames %u..%u (UART wait excluded), per function\n",
                    prof_from, frame_no ? frame_no - 1 : 0);
            for (i = 0; i < nprof && prof[i].cyc; i++)
                fprintf(pf, "%12llu %5.1f%% %s\n", prof[i].cyc, tot ? 100.0 * prof[i].cyc / tot : 0.0,
                        prof[i].name);
            fclose(pf);
        }
    }
    if (hist_cyc) {
        FILE *hf = fopen(histf, "w");
        for (a = 0; hf && a <= avr->flashend; a++)
            if (hist_n[a])
                fprintf(hf, "%x %llu %lu\n", (unsigned)a, hist_cyc[a], hist_n[a]);
        if (hf)
            fclose(hf);
    }
    if (use_pty) {
        sleep((unsigned)linger);
        _exit(state == cpu_Done ? code : state == cpu_Crashed ? 125 : 124);
    }
    avr_terminate(avr);
    if (state == cpu_Done)
        return code;
    return state == cpu_Crashed ? 125 : 124;
}
