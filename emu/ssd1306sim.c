/* ssd1306sim.c - libsimavr runner with simavr's own SSD1306 part
 * (libsimavrparts, parts/ssd1306_virt.h) wired to the AVR's SPI port,
 * for firmware that drives the display itself (examples/ssd1306).
 * Host tool, C99, GPL-3+ libsimavr.
 *
 *   ssd1306sim [options] MCU ELF
 *     -f HZ        clock (default 16000000)
 *     -o FILE      the display RAM after every frame: 1024 bytes (8 pages
 *                  of 128 columns, the SSD1306 page layout) per marker 3
 *     -g PREFIX    also every frame as a picture, PREFIX-NNNN.pgm
 *     -E FILE      the display RAM at the end of the run (1024 bytes), for
 *                  firmware without markers (an Arduino sketch)
 *     -l CYCLES    cycle limit (default 4e9); exit 124 when hit
 *     -m FILE      log (default stderr): FRAME lines, END, RAM, DISPLAY
 *
 * Wiring (4-wire SPI, as examples/ssd1306/ssd1306.c drives it):
 *     SCK PB5, MOSI PB3 (the SPI port) -> SCLK, SDIN
 *     PB2 -> CS (active low), PB1 -> D/C (high = data), PB0 -> RES (low)
 * Frames: the firmware writes PLAT_MARK_FRAME_END (3) to GPIOR0 after a
 * frame's last page has left the SPI port; the runner then copies the
 * part's display RAM.  Per frame (between markers 2 and 3):
 *     FRAME n cycles=C spi=S compute=C-S bytes=B
 * S is the time spent in the firmware's function ssd1306_spi_byte (found
 * in the ELF symbols): simavr 1.6 charges 100 us for every SPI byte
 * whatever the SPI clock (a real 328P at f/2 takes 16 cycles), so C is
 * mostly the simulator's SPI model and C-S is the rendering.  At the end:
 *     END state=done|crashed|limit code=N cycles=C frames=N
 *     RAM static=S stack_peak=P ramend=0x..
 *     DISPLAY on=0|1 inverted=0|1 contrast=0x.. mode=horizontal|vertical|page
 * simavr's part prints its own notes ("SSD1306: ...") on stdout.
 * Exit status: the firmware's exit code (GPIOR1) when it stopped with
 * cli+sleep, 124 on the cycle limit, 125 on a crash, 2 on usage errors.
 */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <stdarg.h>
#include <unistd.h>
#include "sim_avr.h"
#include "sim_elf.h"
#include "sim_io.h"
#include "avr_spi.h"
#include "ssd1306_virt.h"

#define GPIOR0_ADDR 0x3E /* data-space address on m328p / m1284p */
#define GPIOR1_ADDR 0x4A
#define RAMSTART 0x100
#define PAINT 0xA5

static ssd1306_t oled;
static FILE *out_fp, *log_fp;
static const char *end_file;
static const char *pgm_prefix;
static unsigned frames, spi_bytes;
static avr_cycle_count_t frame_start, spi_cycles;
static uint32_t spi_lo = 1, spi_hi = 0;   /* [lo, hi) of ssd1306_spi_byte */

static void quiet_logger(struct avr_t *avr, const int level, const char *fmt, va_list ap)
{
    (void)avr;
    if (level <= LOG_WARNING && level != LOG_OUTPUT)
        vfprintf(stderr, fmt, ap);
}

static void snapshot(void)
{
    int p;
    if (out_fp)
        for (p = 0; p < SSD1306_VIRT_PAGES; p++)
            fwrite(oled.vram[p], 1, SSD1306_VIRT_COLUMNS, out_fp);
    if (pgm_prefix) {
        char name[4096];
        FILE *f;
        int x, y;
        snprintf(name, sizeof name, "%s-%04u.pgm", pgm_prefix, frames);
        if (!(f = fopen(name, "wb"))) {
            perror(name);
            return;
        }
        fprintf(f, "P5\n%d %d\n255\n", SSD1306_VIRT_COLUMNS, SSD1306_VIRT_PAGES * 8);
        for (y = 0; y < SSD1306_VIRT_PAGES * 8; y++)
            for (x = 0; x < SSD1306_VIRT_COLUMNS; x++)
                fputc((oled.vram[y >> 3][x] >> (y & 7)) & 1 ? 255 : 0, f);
        fclose(f);
    }
}

static void mark_write(struct avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param)
{
    (void)param;
    avr->data[addr] = v; /* io-write hooks must store the value */
    if (v == 2) {
        frame_start = avr->cycle;
        spi_cycles = 0;
        spi_bytes = 0;
    } else if (v == 3) {
        avr_cycle_count_t c = avr->cycle - frame_start;
        fprintf(log_fp, "FRAME %u cycles=%llu spi=%llu compute=%llu bytes=%u\n", frames,
                (unsigned long long)c, (unsigned long long)spi_cycles,
                (unsigned long long)(c - spi_cycles), spi_bytes);
        snapshot();
        frames++;
    }
}

static void spi_out(struct avr_irq_t *irq, uint32_t value, void *param)
{
    (void)irq;
    (void)value;
    (void)param;
    spi_bytes++;
}

/* The address range of the firmware's ssd1306_spi_byte, if it has one. */
static void find_spi(elf_firmware_t *fw)
{
    uint32_t i, hi = 0xFFFFFFFFu;
    int found = 0;
    for (i = 0; i < fw->symbolcount; i++)
        if (!strcmp(fw->symbol[i]->symbol, "ssd1306_spi_byte")) {
            spi_lo = fw->symbol[i]->addr;
            found = 1;
        }
    if (!found)
        return;
    for (i = 0; i < fw->symbolcount; i++) {
        uint32_t a = fw->symbol[i]->addr;
        if (a > spi_lo && a < hi && a < 0x800000u)
            hi = a;
    }
    spi_hi = hi - spi_lo > 64 ? spi_lo + 16 : hi;
}

static void no_sleep(struct avr_t *avr, avr_cycle_count_t howLong)
{
    (void)avr;
    (void)howLong;
}

int main(int argc, char **argv)
{
    static const char *const modes[] = {"horizontal", "vertical", "page"};
    elf_firmware_t fw;
    avr_t *avr;
    ssd1306_wiring_t wiring;
    uint32_t freq = 16000000u, a, static_end, low;
    int state, opt, code;
    unsigned long long maxc = 4000000000ULL;
    const char *out = NULL, *logf = NULL;

    while ((opt = getopt(argc, argv, "f:o:g:E:l:m:h")) != -1) {
        switch (opt) {
        case 'f': freq = strtoul(optarg, 0, 0); break;
        case 'o': out = optarg; break;
        case 'g': pgm_prefix = optarg; break;
        case 'E': end_file = optarg; break;
        case 'l': maxc = strtoull(optarg, 0, 0); break;
        case 'm': logf = optarg; break;
        default: goto usage;
        }
    }
    if (argc - optind != 2) {
usage:
        fprintf(stderr, "usage: %s [-f HZ] [-o FRAMES] [-g PGM-PREFIX] [-E END] [-l CYCLES] [-m LOG] MCU ELF\n"
                "SSD1306 on SPI: CS PB2, D/C PB1, RES PB0; display RAM after every marker 3\n",
                argv[0]);
        return 2;
    }
    log_fp = stderr;
    if (logf && !(log_fp = fopen(logf, "w"))) {
        perror(logf);
        return 2;
    }
    if (out && !(out_fp = fopen(out, "wb"))) {
        perror(out);
        return 2;
    }
    avr_global_logger_set(quiet_logger);
    memset(&fw, 0, sizeof fw);
    if (elf_read_firmware(argv[optind + 1], &fw)) {
        fprintf(stderr, "ssd1306sim: cannot read %s\n", argv[optind + 1]);
        return 2;
    }
    if (!(avr = avr_make_mcu_by_name(argv[optind]))) {
        fprintf(stderr, "ssd1306sim: unknown MCU %s\n", argv[optind]);
        return 2;
    }
    avr_init(avr);
    avr->frequency = freq;
    avr_load_firmware(avr, &fw);
    avr->sleep = no_sleep;

    ssd1306_init(avr, &oled, SSD1306_VIRT_COLUMNS, SSD1306_VIRT_PAGES * 8);
    wiring.chip_select.port = 'B';
    wiring.chip_select.pin = 2;
    wiring.data_instruction.port = 'B';
    wiring.data_instruction.pin = 1;
    wiring.reset.port = 'B';
    wiring.reset.pin = 0;
    ssd1306_connect(&oled, &wiring);
    avr_register_io_write(avr, GPIOR0_ADDR, mark_write, NULL);
    avr_irq_register_notify(avr_io_getirq(avr, AVR_IOCTL_SPI_GETIRQ(0), SPI_IRQ_OUTPUT), spi_out, NULL);
    find_spi(&fw);

    static_end = RAMSTART + fw.datasize + fw.bsssize;
    for (a = static_end; a <= avr->ramend; a++)
        avr->data[a] = PAINT;
    do {
        uint32_t pc = avr->pc;
        avr_cycle_count_t before = avr->cycle;
        state = avr_run(avr);
        if (pc >= spi_lo && pc < spi_hi)
            spi_cycles += avr->cycle - before;
    } while (state != cpu_Done && state != cpu_Crashed && avr->cycle < maxc);
    if (out_fp)
        fclose(out_fp);
    if (end_file) {
        FILE *f = fopen(end_file, "wb");
        if (!f || fwrite(oled.vram, 1, sizeof oled.vram, f) != sizeof oled.vram)
            perror(end_file);
        if (f)
            fclose(f);
    }

    low = avr->ramend + 1;
    for (a = static_end; a <= avr->ramend; a++)
        if (avr->data[a] != PAINT) {
            low = a;
            break;
        }
    code = avr->data[GPIOR1_ADDR];
    fprintf(log_fp, "END state=%s code=%d cycles=%llu frames=%u\n",
            state == cpu_Done ? "done" : state == cpu_Crashed ? "crashed" : "limit",
            code, (unsigned long long)avr->cycle, frames);
    fprintf(log_fp, "RAM static=%u stack_peak=%u ramend=0x%x\n",
            (unsigned)(fw.datasize + fw.bsssize), (unsigned)(avr->ramend + 1 - low),
            (unsigned)avr->ramend);
    fprintf(log_fp, "DISPLAY on=%d inverted=%d contrast=0x%02x mode=%s\n",
            ssd1306_get_flag(&oled, SSD1306_FLAG_DISPLAY_ON),
            ssd1306_get_flag(&oled, SSD1306_FLAG_DISPLAY_INVERTED), oled.contrast_register,
            oled.addr_mode <= SSD1306_ADDR_MODE_PAGE ? modes[oled.addr_mode] : "?");
    fflush(log_fp);
    avr_terminate(avr);
    if (state == cpu_Done)
        return code;
    return state == cpu_Crashed ? 125 : 124;
}
