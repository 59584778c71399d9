/* z80sim.c - rast8's cycle-counting Z80 simulator and profiler (host tool,
 * C99).  Runs an sdcc Intel-hex image with the I/O conventions of
 * ports/z80/plat_z80.c and emu/sz80run.py (ucsim sz80), counting Zilog
 * datasheet T-states, and says where they go per function.
 *
 *   z80sim [options] FILE.ihx
 *     -o FILE      UART bytes to FILE (default: stdout), binary-safe
 *     -m FILE      marker log (default: stderr)
 *     -q           no MARK lines, only FRAME lines and the summary
 *     -l T         T-state limit (default 4e9); exit 124 when hit
 *     -P FILE      profile: T-states per function spent inside frames
 *                  (between markers 2 and 3), self and inclusive
 *     -F N         profile only frames N and later (default 0)
 *     -a           profile the whole run, not only frames (unit tests)
 *     -H FILE      per instruction inside the profiled frames:
 *                  "addr T executions function+offset" (hex address)
 *     -M FILE.map  the link map (default: FILE.ihx with .map); static
 *                  functions come from each module's .sym file, found in
 *                  the -s directories (default: the .ihx's directory and
 *                  ../obj next to it)
 *     -s DIR       one more directory to look for MODULE.sym in
 *     -u           ucsim sz80 0.6.4 timing (see below) instead of Zilog's
 *     -z FILE      code bytes per symbol (to the next symbol), largest
 *                  first, "run" if this run entered it, and the totals:
 *                  where the image's size goes
 *
 * Memory map and I/O (64 KB RAM, image loaded at its addresses, run from
 * 0x0000; crt0 sets SP):
 *   0x01FF  simif: 'w' then a byte appends the byte to the UART output;
 *           's' stops the run
 *   0x01FE  marker: every write logs  MARK id ticks=T delta=D
 *           and "FRAME n cycles=D" for a marker 3 after a marker 2; an id
 *           0xE0+c is plat_exit's exit marker (code c), with the stack
 *           peak at 0x01FC/0x01FD
 * At the end:
 *   END state=done|limit|halt|bad code=N ticks=T
 *   RAM stack_peak=N
 * These are the lines emu/sz80run.py writes, so the same scripts read
 * both.  Exit status: the firmware's exit code, 124 on the limit, 125 if
 * the program stopped without an exit code, 2 on usage errors.
 *
 * Timing: Zilog's T-states (Z80 CPU User Manual UM0080), no wait states.
 * ucsim sz80 0.6.4 counts a few instructions differently (measured with
 * sdasz80 snippets: inc/dec (hl) 7 instead of 11, CB rotates/res/set on
 * (hl) 8 instead of 15, bit n,(hl) 8 instead of 12, dec bc/de/hl 7
 * instead of 6, each repeated ldir/lddr step 20 instead of 21; the
 * (ix+d) forms agree); -u applies those, so the totals can be checked
 * against sz80 on the same image (emu/sz80run.py).
 */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <stdint.h>
#include <unistd.h>
#include <ctype.h>

#define SIF_ADDR 0x01FF
#define MARK_ADDR 0x01FE
#define STK_ADDR 0x01FC

/* ---- CPU state */
static uint8_t mem[65536];
static uint8_t A, F, B, C, D, E, H, L;
static uint8_t A2, F2, B2, C2, D2, E2, H2, L2;
static uint16_t IX, IY, SP, PC;
static uint8_t I_, R_, IFF;
static unsigned long long T;
static int ucsim_timing;

#define FS 0x80
#define FZ 0x40
#define FH 0x10
#define FP 0x04
#define FN 0x02
#define FC 0x01

static uint8_t szp[256]; /* S, Z and parity flags of a byte */

#define HL ((uint16_t)(H << 8 | L))
#define BC ((uint16_t)(B << 8 | C))
#define DE ((uint16_t)(D << 8 | E))
#define SETHL(v) do { uint16_t v_ = (uint16_t)(v); H = (uint8_t)(v_ >> 8); L = (uint8_t)v_; } while (0)
#define SETBC(v) do { uint16_t v_ = (uint16_t)(v); B = (uint8_t)(v_ >> 8); C = (uint8_t)v_; } while (0)
#define SETDE(v) do { uint16_t v_ = (uint16_t)(v); D = (uint8_t)(v_ >> 8); E = (uint8_t)v_; } while (0)

/* ---- I/O */
static FILE *uart_fp, *mark_fp;
static int quiet;
static int sif_w;          /* last simif byte was 'w' */
static int stopped;        /* 's' written */
static int exit_code = -1;
static unsigned stack_peak;
static unsigned long long last_mark;
static int in_frame;
static unsigned frame_no;
static unsigned prof_from;
static int profiling;      /* inside a profiled frame */
static int prof_all;       /* -a: the whole run */

static void wr(uint16_t a, uint8_t v);

static inline uint8_t rd(uint16_t a) { return mem[a]; }
static inline uint16_t rd16(uint16_t a) { return (uint16_t)(mem[a] | mem[(uint16_t)(a + 1)] << 8); }
static inline void wr16(uint16_t a, uint16_t v) { wr(a, (uint8_t)v); wr((uint16_t)(a + 1), (uint8_t)(v >> 8)); }

static void on_mark(uint8_t id)
{
    unsigned long long d = T - last_mark;
    last_mark = T;
    if (exit_code >= 0)
        return;
    if (id >= 0xE0 && id != 0xFF) {
        exit_code = id & 0x0F;
        stack_peak = (unsigned)(mem[STK_ADDR] | mem[STK_ADDR + 1] << 8);
        return;
    }
    if (!quiet)
        fprintf(mark_fp, "MARK %u ticks=%llu delta=%llu\n", id, T, d);
    if (id == 2) {
        in_frame = 1;
        profiling = prof_all || frame_no >= prof_from;
    } else if (id == 3 && in_frame) {
        fprintf(mark_fp, "FRAME %u cycles=%llu\n", frame_no, d);
        frame_no++;
        in_frame = 0;
        profiling = prof_all;
    }
}

static void wr(uint16_t a, uint8_t v)
{
    mem[a] = v;
    if (a == SIF_ADDR) {
        if (sif_w) {
            putc(v, uart_fp);
            sif_w = 0;
        } else if (v == 'w')
            sif_w = 1;
        else if (v == 's')
            stopped = 1;
    } else if (a == MARK_ADDR)
        on_mark(v);
}

/* ---- profile */
typedef struct {
    uint16_t addr;
    char *name;
    unsigned long long self, incl, calls;
} fn_t;
static fn_t *fns;
static int nfns;
static uint16_t *fn_of; /* address -> index into fns (0 = "?") */
static uint8_t *covered; /* -z: instruction addresses run */
static unsigned long long *hist_t, *hist_n;
typedef struct { int fn, edge; uint16_t sp; unsigned long long t0; int counted; } frame_t;
static frame_t cstack[4096];
static int depth;
static uint16_t cur_pc; /* the instruction being run */
/* call edges caller -> callee (open hashing on the pair) */
typedef struct { int from, to; unsigned long long calls, incl; } edge_t;
#define NEDGE 8192
static edge_t edges[NEDGE];
static int nedges;

static int edge_of(int from, int to)
{
    unsigned h = ((unsigned)from * 2654435761u ^ (unsigned)to * 40503u) & (NEDGE - 1);
    while (edges[h].calls || edges[h].incl || edges[h].from || edges[h].to) {
        if (edges[h].from == from && edges[h].to == to)
            return (int)h;
        h = (h + 1) & (NEDGE - 1);
    }
    if (nedges >= NEDGE - 1)
        return -1;
    nedges++;
    edges[h].from = from;
    edges[h].to = to;
    return (int)h;
}

static int fn_cmp(const void *a, const void *b)
{
    const fn_t *x = a, *y = b;
    return x->addr < y->addr ? -1 : x->addr > y->addr;
}

static void add_fn(uint16_t addr, const char *name)
{
    static int cap;
    int i;
    if (!strncmp(name, "s__", 3) || !strncmp(name, "l__", 3) || name[0] == '.')
        return;
    for (i = 0; i < nfns; i++)
        if (fns[i].addr == addr && !strcmp(fns[i].name, name))
            return;
    if (nfns == cap) {
        cap = cap ? cap * 2 : 256;
        fns = realloc(fns, cap * sizeof *fns);
    }
    memset(&fns[nfns], 0, sizeof *fns);
    fns[nfns].addr = addr;
    fns[nfns].name = strdup(name);
    nfns++;
}

/* the globals of the link map: "     0000598F  _r8_fb_clear   fb" */
typedef struct { char name[128]; char mod[64]; uint16_t addr; } glob_t;
static glob_t *globs;
static int nglobs;

static int load_map(const char *path)
{
    FILE *f = fopen(path, "r");
    char line[512];
    int cap = 0;
    if (!f)
        return -1;
    while (fgets(line, sizeof line, f)) {
        unsigned long a;
        char name[128], mod[64];
        int n;
        mod[0] = 0;
        n = sscanf(line, " %lx %127s %63s", &a, name, mod);
        if (n < 2 || !isxdigit((unsigned char)line[5]) || strlen(line) < 20)
            continue;
        if (a > 0xFFFF)
            continue;
        if (nglobs == cap) {
            cap = cap ? cap * 2 : 256;
            globs = realloc(globs, cap * sizeof *globs);
        }
        strcpy(globs[nglobs].name, name);
        strcpy(globs[nglobs].mod, n == 3 ? mod : "");
        globs[nglobs].addr = (uint16_t)a;
        nglobs++;
    }
    fclose(f);
    return 0;
}

static const char *sym_dirs[16];
static int nsym_dirs;
static char main_sym[1024]; /* FILE.sym next to FILE.ihx: the main module's */

/* a module's .sym: every symbol of its _CODE area, placed by one of its
 * globals whose address the map gives */
static void load_sym(const char *mod)
{
    char path[1024], line[512];
    FILE *f = NULL;
    int i, code_area = -1, pass;
    long base = -1;
    for (i = 0; i < nsym_dirs && !f; i++) {
        snprintf(path, sizeof path, "%s/%s.sym", sym_dirs[i], mod);
        f = fopen(path, "r");
    }
    if (!f && main_sym[0]) /* (placed only if one of mod's globals is in it) */
        f = fopen(main_sym, "r");
    if (!f)
        return;
    /* the area table comes last: find _CODE's number first */
    while (fgets(line, sizeof line, f)) {
        int n;
        char area[64];
        if (sscanf(line, " %d %63s size", &n, area) == 2 && !strcmp(area, "_CODE") && strstr(line, "size"))
            code_area = n;
    }
    if (code_area < 0) {
        fclose(f);
        return;
    }
    for (pass = 0; pass < 2; pass++) {
        rewind(f);
        while (fgets(line, sizeof line, f)) {
            int n;
            char name[128], fl[8];
            unsigned long off;
            if (sscanf(line, " %d %127s %lx %7s", &n, name, &off, fl) != 4 || n != code_area ||
                strstr(line, "size"))
                continue;
            if (pass == 0 && base < 0) {
                for (i = 0; i < nglobs; i++)
                    if (!strcmp(globs[i].name, name) && !strcmp(globs[i].mod, mod)) {
                        base = (long)globs[i].addr - (long)off;
                        break;
                    }
            } else if (pass == 1 && base >= 0)
                add_fn((uint16_t)(base + (long)off), name);
        }
        if (base < 0)
            break;
    }
    fclose(f);
}

static void prof_init(const char *map)
{
    int i, j;
    if (load_map(map) < 0) {
        fprintf(stderr, "z80sim: cannot read the map %s (function names: -M)\n", map);
        exit(2);
    }
    add_fn(0, "(reset)");
    for (i = 0; i < nglobs; i++) {
        add_fn(globs[i].addr, globs[i].name);
        if (globs[i].mod[0]) {
            for (j = 0; j < i; j++)
                if (!strcmp(globs[j].mod, globs[i].mod))
                    break;
            if (j == i)
                load_sym(globs[i].mod);
        }
    }
    qsort(fns, nfns, sizeof *fns, fn_cmp);
    fn_of = calloc(65536, sizeof *fn_of);
    for (i = 0, j = 0; i < 65536; i++) {
        while (j + 1 < nfns && fns[j + 1].addr <= i)
            j++;
        fn_of[i] = (uint16_t)j;
    }
}

/* ---- flags helpers */
static void init_tables(void)
{
    int i, b, p;
    for (i = 0; i < 256; i++) {
        for (p = 0, b = i; b; b >>= 1)
            p ^= b & 1;
        szp[i] = (uint8_t)((i & FS) | (i ? 0 : FZ) | (p ? 0 : FP));
    }
}

static inline void add8(uint8_t v, int cy)
{
    unsigned r = A + v + cy;
    F = (uint8_t)((szp[r & 0xFF] & (FS | FZ)) | ((A ^ v ^ r) & FH) |
                  (((A ^ ~v) & (A ^ r) & 0x80) ? FP : 0) | (r > 0xFF ? FC : 0));
    A = (uint8_t)r;
}

static inline uint8_t sub8f(uint8_t v, int cy)
{
    unsigned r = (unsigned)A - v - cy;
    F = (uint8_t)((szp[r & 0xFF] & (FS | FZ)) | ((A ^ v ^ r) & FH) |
                  (((A ^ v) & (A ^ r) & 0x80) ? FP : 0) | FN | ((r >> 8) & 1 ? FC : 0));
    return (uint8_t)r;
}

static inline void alu(int op, uint8_t v)
{
    switch (op) {
    case 0: add8(v, 0); break;
    case 1: add8(v, F & FC); break;
    case 2: A = sub8f(v, 0); break;
    case 3: A = sub8f(v, F & FC); break;
    case 4: A &= v; F = (uint8_t)(szp[A] | FH); break;
    case 5: A ^= v; F = szp[A]; break;
    case 6: A |= v; F = szp[A]; break;
    case 7: (void)sub8f(v, 0); break;
    }
}

static inline uint8_t inc8(uint8_t v)
{
    uint8_t r = (uint8_t)(v + 1);
    F = (uint8_t)((F & FC) | (szp[r] & (FS | FZ)) | ((r & 0x0F) == 0 ? FH : 0) | (r == 0x80 ? FP : 0));
    return r;
}

static inline uint8_t dec8(uint8_t v)
{
    uint8_t r = (uint8_t)(v - 1);
    F = (uint8_t)((F & FC) | (szp[r] & (FS | FZ)) | ((r & 0x0F) == 0x0F ? FH : 0) | (r == 0x7F ? FP : 0) | FN);
    return r;
}

static inline uint16_t add16(uint16_t a, uint16_t b)
{
    unsigned r = (unsigned)a + b;
    F = (uint8_t)((F & (FS | FZ | FP)) | (((a ^ b ^ r) >> 8) & FH) | (r > 0xFFFF ? FC : 0));
    return (uint16_t)r;
}

static inline uint16_t adc16(uint16_t a, uint16_t b)
{
    unsigned r = (unsigned)a + b + (F & FC);
    F = (uint8_t)(((r >> 8) & FS) | ((r & 0xFFFF) ? 0 : FZ) | (((a ^ b ^ r) >> 8) & FH) |
                  (((a ^ ~b) & (a ^ r) & 0x8000) ? FP : 0) | (r > 0xFFFF ? FC : 0));
    return (uint16_t)r;
}

static inline uint16_t sbc16(uint16_t a, uint16_t b)
{
    unsigned r = (unsigned)a - b - (F & FC);
    F = (uint8_t)(((r >> 8) & FS) | ((r & 0xFFFF) ? 0 : FZ) | (((a ^ b ^ r) >> 8) & FH) |
                  (((a ^ b) & (a ^ r) & 0x8000) ? FP : 0) | FN | ((r >> 16) & 1 ? FC : 0));
    return (uint16_t)r;
}

/* CB-prefix rotates and shifts: op 0..7 = rlc rrc rl rr sla sra sll srl */
static inline uint8_t rot(int op, uint8_t v)
{
    uint8_t r, c;
    switch (op) {
    case 0: c = v >> 7; r = (uint8_t)(v << 1 | c); break;
    case 1: c = v & 1; r = (uint8_t)(v >> 1 | c << 7); break;
    case 2: c = v >> 7; r = (uint8_t)(v << 1 | (F & FC)); break;
    case 3: c = v & 1; r = (uint8_t)(v >> 1 | (F & FC) << 7); break;
    case 4: c = v >> 7; r = (uint8_t)(v << 1); break;
    case 5: c = v & 1; r = (uint8_t)((v >> 1) | (v & 0x80)); break;
    case 6: c = v >> 7; r = (uint8_t)(v << 1 | 1); break;
    default: c = v & 1; r = (uint8_t)(v >> 1); break;
    }
    F = (uint8_t)(szp[r] | c);
    return r;
}

static inline uint8_t *reg8(int r)
{
    switch (r) {
    case 0: return &B;
    case 1: return &C;
    case 2: return &D;
    case 3: return &E;
    case 4: return &H;
    case 5: return &L;
    default: return &A; /* 7; 6 = (hl) is handled by the callers */
    }
}

static inline uint8_t fetch(void) { return mem[PC++]; }
static inline uint16_t fetch16(void) { uint16_t v = rd16(PC); PC = (uint16_t)(PC + 2); return v; }
static inline void push(uint16_t v) { SP = (uint16_t)(SP - 2); wr16(SP, v); }
static inline uint16_t pop(void) { uint16_t v = rd16(SP); SP = (uint16_t)(SP + 2); return v; }

static inline int cond(int cc)
{
    switch (cc) {
    case 0: return !(F & FZ);
    case 1: return F & FZ;
    case 2: return !(F & FC);
    case 3: return F & FC;
    case 4: return !(F & FP);
    case 5: return F & FP;
    case 6: return !(F & FS);
    default: return F & FS;
    }
}

static inline uint16_t rp(int p) /* bc de hl sp */
{
    switch (p) {
    case 0: return BC;
    case 1: return DE;
    case 2: return HL;
    default: return SP;
    }
}

static inline void setrp(int p, uint16_t v)
{
    switch (p) {
    case 0: SETBC(v); break;
    case 1: SETDE(v); break;
    case 2: SETHL(v); break;
    default: SP = v; break;
    }
}

static void call_to(uint16_t target)
{
    push(PC);
    PC = target;
    if (fns && depth < (int)(sizeof cstack / sizeof cstack[0])) {
        int f = fn_of[target];
        cstack[depth].fn = f;
        cstack[depth].edge = profiling ? edge_of(fn_of[cur_pc], f) : -1;
        cstack[depth].sp = SP;
        cstack[depth].t0 = T;
        cstack[depth].counted = profiling;
        if (profiling) {
            fns[f].calls++;
            if (cstack[depth].edge >= 0)
                edges[cstack[depth].edge].calls++;
        }
        depth++;
    }
}

static int bad_op;
static char *edge_text;

/* one ED-prefixed instruction; returns its T-states */
static int exec_ed(void)
{
    uint8_t op = fetch();
    int x = op >> 6, y = (op >> 3) & 7, z = op & 7, p = y >> 1, q = y & 1;
    R_++;
    if (x == 1) {
        switch (z) {
        case 0: { /* in r,(c): no ports, reads 0xFF */
            uint8_t v = 0xFF;
            if (y != 6) *reg8(y) = v;
            F = (uint8_t)((F & FC) | szp[v]);
            return 12;
        }
        case 1: return 12; /* out (c),r: ignored */
        case 2: SETHL(q ? adc16(HL, rp(p)) : sbc16(HL, rp(p))); return 15;
        case 3: {
            uint16_t a = fetch16();
            if (q) setrp(p, rd16(a)); else wr16(a, rp(p));
            return 20;
        }
        case 4: { uint8_t v = A; A = 0; A = sub8f(v, 0); return 8; }
        case 5: PC = pop(); return 14;
        case 6: return 8;
        default:
            switch (y) {
            case 0: I_ = A; return 9;
            case 1: R_ = A; return 9;
            case 2: A = I_; F = (uint8_t)((F & FC) | (szp[A] & (FS | FZ)) | (IFF ? FP : 0)); return 9;
            case 3: A = R_; F = (uint8_t)((F & FC) | (szp[A] & (FS | FZ)) | (IFF ? FP : 0)); return 9;
            case 4: { /* rrd */
                uint8_t m = rd(HL);
                wr(HL, (uint8_t)((A << 4) | (m >> 4)));
                A = (uint8_t)((A & 0xF0) | (m & 0x0F));
                F = (uint8_t)((F & FC) | szp[A]);
                return 18;
            }
            case 5: { /* rld */
                uint8_t m = rd(HL);
                wr(HL, (uint8_t)((m << 4) | (A & 0x0F)));
                A = (uint8_t)((A & 0xF0) | (m >> 4));
                F = (uint8_t)((F & FC) | szp[A]);
                return 18;
            }
            default: return 8;
            }
        }
    }
    if (x == 2 && y >= 4 && z <= 1) {
        int dir = (y & 1) ? -1 : 1, rep = y >= 6;
        if (z == 0) { /* ldi ldd ldir lddr */
            wr(DE, rd(HL));
            SETHL(HL + dir);
            SETDE(DE + dir);
            SETBC(BC - 1);
            F = (uint8_t)((F & (FS | FZ | FC)) | (BC ? FP : 0));
            if (rep && BC) {
                PC = (uint16_t)(PC - 2);
                return ucsim_timing ? 20 : 21;
            }
            return 16;
        } else { /* cpi cpd cpir cpdr */
            uint8_t m = rd(HL), c = F & FC;
            uint8_t r = sub8f(m, 0);
            (void)r;
            SETHL(HL + dir);
            SETBC(BC - 1);
            F = (uint8_t)((F & (FS | FZ | FH)) | FN | c | (BC ? FP : 0));
            if (rep && BC && !(F & FZ)) {
                PC = (uint16_t)(PC - 2);
                return 21;
            }
            return 16;
        }
    }
    bad_op = 0xED00 | op;
    return 8;
}

/* (ix+d) / (iy+d) CB-prefixed: DD CB d op */
static int exec_xycb(uint16_t *xy)
{
    int8_t d = (int8_t)fetch();
    uint8_t op = fetch();
    uint16_t a = (uint16_t)(*xy + d);
    int x = op >> 6, y = (op >> 3) & 7, z = op & 7;
    uint8_t v = rd(a), r;
    if (x == 1) {
        F = (uint8_t)((F & FC) | FH | ((v >> y) & 1 ? 0 : (FZ | FP)) | (y == 7 && (v & 0x80) ? FS : 0));
        return 20;
    }
    if (x == 0)
        r = rot(y, v);
    else if (x == 2)
        r = (uint8_t)(v & ~(1 << y));
    else
        r = (uint8_t)(v | (1 << y));
    wr(a, r);
    if (z != 6)
        *reg8(z) = r;
    return 23;
}

/* DD/FD-prefixed instruction on IX or IY; returns T-states */
static int exec_xy(uint16_t *xy)
{
    uint8_t op = fetch();
    R_++;
    switch (op) {
    case 0x09: case 0x19: case 0x29: case 0x39: {
        int p = (op >> 4) & 3;
        uint16_t v = p == 2 ? *xy : rp(p);
        *xy = add16(*xy, v);
        return 15;
    }
    case 0x21: *xy = fetch16(); return 14;
    case 0x22: wr16(fetch16(), *xy); return 20;
    case 0x2A: *xy = rd16(fetch16()); return 20;
    case 0x23: (*xy)++; return 10;
    case 0x2B: (*xy)--; return 10;
    case 0x24: *xy = (uint16_t)((inc8((uint8_t)(*xy >> 8)) << 8) | (*xy & 0xFF)); return 8;
    case 0x25: *xy = (uint16_t)((dec8((uint8_t)(*xy >> 8)) << 8) | (*xy & 0xFF)); return 8;
    case 0x26: *xy = (uint16_t)((fetch() << 8) | (*xy & 0xFF)); return 11;
    case 0x2C: *xy = (uint16_t)((*xy & 0xFF00) | inc8((uint8_t)*xy)); return 8;
    case 0x2D: *xy = (uint16_t)((*xy & 0xFF00) | dec8((uint8_t)*xy)); return 8;
    case 0x2E: *xy = (uint16_t)((*xy & 0xFF00) | fetch()); return 11;
    case 0x34: case 0x35: {
        uint16_t a = (uint16_t)(*xy + (int8_t)fetch());
        wr(a, op == 0x34 ? inc8(rd(a)) : dec8(rd(a)));
        return 23;
    }
    case 0x36: {
        uint16_t a = (uint16_t)(*xy + (int8_t)fetch());
        wr(a, fetch());
        return 19;
    }
    case 0xCB: return exec_xycb(xy);
    case 0xE1: *xy = pop(); return 14;
    case 0xE3: { uint16_t v = rd16(SP); wr16(SP, *xy); *xy = v; return 23; }
    case 0xE5: push(*xy); return 15;
    case 0xE9: PC = *xy; return 8;
    case 0xF9: SP = *xy; return 10;
    }
    if (op >= 0x40 && op < 0x80 && op != 0x76) {
        int y = (op >> 3) & 7, z = op & 7;
        if (z == 6) { /* ld r,(xy+d) */
            uint16_t a = (uint16_t)(*xy + (int8_t)fetch());
            *reg8(y) = rd(a);
            return 19;
        }
        if (y == 6) { /* ld (xy+d),r */
            uint16_t a = (uint16_t)(*xy + (int8_t)fetch());
            wr(a, *reg8(z));
            return 19;
        }
        { /* undocumented: h/l mean the halves of xy */
            uint8_t v;
            if (z == 4) v = (uint8_t)(*xy >> 8);
            else if (z == 5) v = (uint8_t)*xy;
            else v = *reg8(z);
            if (y == 4) *xy = (uint16_t)((v << 8) | (*xy & 0xFF));
            else if (y == 5) *xy = (uint16_t)((*xy & 0xFF00) | v);
            else *reg8(y) = v;
            return 8;
        }
    }
    if (op >= 0x80 && op < 0xC0) {
        int y = (op >> 3) & 7, z = op & 7;
        if (z == 6) {
            uint16_t a = (uint16_t)(*xy + (int8_t)fetch());
            alu(y, rd(a));
            return 19;
        }
        alu(y, z == 4 ? (uint8_t)(*xy >> 8) : z == 5 ? (uint8_t)*xy : *reg8(z));
        return 8;
    }
    /* any other opcode: the prefix is ignored (4 T); run it unprefixed */
    PC--;
    return -4;
}

static int exec_main(void);

static int exec_cb(void)
{
    uint8_t op = fetch();
    int x = op >> 6, y = (op >> 3) & 7, z = op & 7;
    uint8_t v = z == 6 ? rd(HL) : *reg8(z), r;
    R_++;
    if (x == 1) {
        F = (uint8_t)((F & FC) | FH | ((v >> y) & 1 ? 0 : (FZ | FP)) | (y == 7 && (v & 0x80) ? FS : 0));
        return z == 6 ? (ucsim_timing ? 8 : 12) : 8;
    }
    if (x == 0)
        r = rot(y, v);
    else if (x == 2)
        r = (uint8_t)(v & ~(1 << y));
    else
        r = (uint8_t)(v | (1 << y));
    if (z == 6) {
        wr(HL, r);
        return ucsim_timing ? 8 : 15;
    }
    *reg8(z) = r;
    return 8;
}

/* one instruction; returns its T-states */
static int exec_main(void)
{
    uint8_t op = fetch();
    int x = op >> 6, y = (op >> 3) & 7, z = op & 7, p = y >> 1, q = y & 1;
    R_++;
    if (x == 1) {
        if (op == 0x76) { /* halt */
            PC--;
            bad_op = -1;
            return 4;
        }
        if (z == 6) { *reg8(y) = rd(HL); return 7; }
        if (y == 6) { wr(HL, *reg8(z)); return 7; }
        *reg8(y) = *reg8(z);
        return 4;
    }
    if (x == 2) {
        if (z == 6) { alu(y, rd(HL)); return 7; }
        alu(y, *reg8(z));
        return 4;
    }
    if (x == 0) {
        switch (z) {
        case 0:
            switch (y) {
            case 0: return 4;
            case 1: { uint8_t t = A; A = A2; A2 = t; t = F; F = F2; F2 = t; return 4; }
            case 2: {
                int8_t d = (int8_t)fetch();
                if (--B) { PC = (uint16_t)(PC + d); return 13; }
                return 8;
            }
            case 3: { int8_t d = (int8_t)fetch(); PC = (uint16_t)(PC + d); return 12; }
            default: {
                int8_t d = (int8_t)fetch();
                if (cond(y - 4)) { PC = (uint16_t)(PC + d); return 12; }
                return 7;
            }
            }
        case 1:
            if (!q) { setrp(p, fetch16()); return 10; }
            SETHL(add16(HL, rp(p)));
            return 11;
        case 2:
            switch (y) {
            case 0: wr(BC, A); return 7;
            case 1: A = rd(BC); return 7;
            case 2: wr(DE, A); return 7;
            case 3: A = rd(DE); return 7;
            case 4: wr16(fetch16(), HL); return 16;
            case 5: SETHL(rd16(fetch16())); return 16;
            case 6: wr(fetch16(), A); return 13;
            default: A = rd(fetch16()); return 13;
            }
        case 3:
            setrp(p, (uint16_t)(rp(p) + (q ? -1 : 1)));
            return ucsim_timing && q && p != 3 ? 7 : 6;
        case 4:
            if (y == 6) { wr(HL, inc8(rd(HL))); return ucsim_timing ? 7 : 11; }
            *reg8(y) = inc8(*reg8(y));
            return 4;
        case 5:
            if (y == 6) { wr(HL, dec8(rd(HL))); return ucsim_timing ? 7 : 11; }
            *reg8(y) = dec8(*reg8(y));
            return 4;
        case 6:
            if (y == 6) { wr(HL, fetch()); return 10; }
            *reg8(y) = fetch();
            return 7;
        default:
            switch (y) {
            case 0: F = (uint8_t)((F & (FS | FZ | FP)) | (A >> 7)); A = (uint8_t)(A << 1 | A >> 7); return 4;
            case 1: F = (uint8_t)((F & (FS | FZ | FP)) | (A & 1)); A = (uint8_t)(A >> 1 | A << 7); return 4;
            case 2: { uint8_t c = A >> 7; A = (uint8_t)(A << 1 | (F & FC)); F = (uint8_t)((F & (FS | FZ | FP)) | c); return 4; }
            case 3: { uint8_t c = A & 1; A = (uint8_t)(A >> 1 | (F & FC) << 7); F = (uint8_t)((F & (FS | FZ | FP)) | c); return 4; }
            case 4: { /* daa */
                uint8_t cor = 0, c = F & FC, a = A;
                if ((F & FH) || (a & 0x0F) > 9) cor |= 0x06;
                if (c || a > 0x99) { cor |= 0x60; c = FC; }
                if (F & FN) {
                    A = (uint8_t)(a - cor);
                    F = (uint8_t)(szp[A] | FN | c | (((F & FH) && (a & 0x0F) < 6) ? FH : 0));
                } else {
                    A = (uint8_t)(a + cor);
                    F = (uint8_t)(szp[A] | c | ((a & 0x0F) > 9 ? FH : 0));
                }
                return 4;
            }
            case 5: A = (uint8_t)~A; F |= FH | FN; return 4;
            case 6: F = (uint8_t)((F & (FS | FZ | FP)) | FC); return 4;
            default: F = (uint8_t)(((F & (FS | FZ | FP | FC)) | ((F & FC) ? FH : 0)) ^ FC); return 4;
            }
        }
    }
    /* x == 3 */
    switch (z) {
    case 0:
        if (cond(y)) { PC = pop(); return 11; }
        return 5;
    case 1:
        if (!q) {
            uint16_t v = pop();
            if (p == 3) { A = (uint8_t)(v >> 8); F = (uint8_t)v; }
            else setrp(p, v);
            return 10;
        }
        switch (p) {
        case 0: PC = pop(); return 10;
        case 1: {
            uint8_t t;
            t = B; B = B2; B2 = t; t = C; C = C2; C2 = t;
            t = D; D = D2; D2 = t; t = E; E = E2; E2 = t;
            t = H; H = H2; H2 = t; t = L; L = L2; L2 = t;
            return 4;
        }
        case 2: PC = HL; return 4;
        default: SP = HL; return 6;
        }
    case 2: {
        uint16_t a = fetch16();
        if (cond(y)) PC = a;
        return 10;
    }
    case 3:
        switch (y) {
        case 0: PC = fetch16(); return 10;
        case 1: return exec_cb();
        case 2: (void)fetch(); return 11; /* out (n),a */
        case 3: (void)fetch(); A = 0xFF; return 11; /* in a,(n) */
        case 4: { uint16_t v = rd16(SP); wr16(SP, HL); SETHL(v); return 19; }
        case 5: { uint16_t t = HL; SETHL(DE); SETDE(t); return 4; }
        case 6: IFF = 0; return 4;
        default: IFF = 1; return 4;
        }
    case 4: {
        uint16_t a = fetch16();
        if (cond(y)) { call_to(a); return 17; }
        return 10;
    }
    case 5:
        if (!q) {
            push(p == 3 ? (uint16_t)(A << 8 | F) : rp(p));
            return 11;
        }
        switch (p) {
        case 0: { uint16_t a = fetch16(); call_to(a); return 17; }
        case 1: { int t = exec_xy(&IX); return t < 0 ? 4 + exec_main() : t; }
        case 2: return exec_ed();
        default: { int t = exec_xy(&IY); return t < 0 ? 4 + exec_main() : t; }
        }
    case 6:
        alu(y, fetch());
        return 7;
    default:
        call_to((uint16_t)(y * 8));
        return 11;
    }
}

/* ---- Intel hex */
static int load_ihx(const char *path)
{
    FILE *f = fopen(path, "r");
    char line[600];
    int n = 0;
    if (!f)
        return -1;
    while (fgets(line, sizeof line, f)) {
        unsigned cnt, addr, type, i, b;
        if (line[0] != ':')
            continue;
        if (sscanf(line + 1, "%2x%4x%2x", &cnt, &addr, &type) != 3) {
            fclose(f);
            return -2;
        }
        if (type == 1)
            break;
        if (type != 0)
            continue;
        if (strlen(line) < 9 + 2 * cnt) {
            fclose(f);
            return -2;
        }
        for (i = 0; i < cnt; i++) {
            if (sscanf(line + 9 + 2 * i, "%2x", &b) != 1) {
                fclose(f);
                return -2;
            }
            mem[(addr + i) & 0xFFFF] = (uint8_t)b;
        }
        n++;
    }
    fclose(f);
    return n ? 0 : -2;
}

static int cmp_self(const void *a, const void *b)
{
    const fn_t *x = a, *y = b;
    return x->self < y->self ? 1 : x->self > y->self ? -1 : 0;
}

static int cmp_incl(const void *a, const void *b)
{
    const fn_t *x = a, *y = b;
    return x->incl < y->incl ? 1 : x->incl > y->incl ? -1 : 0;
}

static void usage(const char *me)
{
    fprintf(stderr,
            "usage: %s [-o OUT] [-m MARKS] [-q] [-l T] [-P PROF [-F N | -a]] [-H HIST]\n"
            "       [-M FILE.map] [-s DIR]... [-u] FILE.ihx\n"
            "Runs an sdcc Z80 image (I/O as in ports/z80/plat_z80.c), counting\n"
            "T-states; -P writes T-states per function inside frames N.. (self,\n"
            "then inclusive with call counts).  See the header of emu/z80sim.c.\n", me);
}

int main(int argc, char **argv)
{
    const char *out = NULL, *marks = NULL, *proff = NULL, *histf = NULL, *mapf = NULL, *sizef = NULL;
    unsigned long long limit = 4000000000ULL;
    char mapbuf[1024], dir0[1024], dir1[1024], dir2[1040];
    const char *state;
    int c, i, rc;
    while ((c = getopt(argc, argv, "o:m:ql:P:F:H:M:s:uz:ah")) != -1) {
        switch (c) {
        case 'o': out = optarg; break;
        case 'm': marks = optarg; break;
        case 'q': quiet = 1; break;
        case 'l': limit = strtoull(optarg, 0, 0); break;
        case 'P': proff = optarg; break;
        case 'F': prof_from = (unsigned)atoi(optarg); break;
        case 'H': histf = optarg; break;
        case 'M': mapf = optarg; break;
        case 's':
            if (nsym_dirs < 14)
                sym_dirs[nsym_dirs++] = optarg;
            break;
        case 'u': ucsim_timing = 1; break;
        case 'z': sizef = optarg; break;
        case 'a': prof_all = 1; break;
        case 'h': usage(argv[0]); return 0;
        default: usage(argv[0]); return 2;
        }
    }
    if (optind != argc - 1) {
        usage(argv[0]);
        return 2;
    }
    rc = load_ihx(argv[optind]);
    if (rc == -1) {
        fprintf(stderr, "z80sim: cannot open %s\n", argv[optind]);
        return 2;
    }
    if (rc < 0) {
        fprintf(stderr, "z80sim: %s is not an Intel hex image\n", argv[optind]);
        return 2;
    }
    uart_fp = out ? fopen(out, "wb") : stdout;
    mark_fp = marks ? fopen(marks, "w") : stderr;
    if (!uart_fp || !mark_fp) {
        fprintf(stderr, "z80sim: cannot write %s\n", !uart_fp ? out : marks);
        return 2;
    }
    init_tables();
    if (proff || histf || sizef) {
        const char *ihx = argv[optind], *slash = strrchr(ihx, '/');
        size_t dl = slash ? (size_t)(slash - ihx) : 1;
        snprintf(dir1, sizeof dir1, "%.*s", (int)dl, slash ? ihx : ".");
        snprintf(dir2, sizeof dir2, "%s/../obj", dir1);
        {   /* FILE.gc/: the modules ports/z80/gcz80.py cut, linked in place of those */
            size_t n = strlen(ihx);
            const char *name = slash ? slash + 1 : ihx;
            size_t m = strlen(name);
            FILE *g;
            snprintf(dir0, sizeof dir0, "%.*s.gc", (int)(n > 4 ? n - 4 : n), ihx);
            snprintf(main_sym, sizeof main_sym, "%.*s.gc/%.*s.sym", (int)(n > 4 ? n - 4 : n), ihx,
                     (int)(m > 4 ? m - 4 : m), name);
            g = fopen(main_sym, "r");
            if (g) {
                fclose(g);
                sym_dirs[nsym_dirs++] = dir0;
            } else {
                n = strlen(ihx);
                snprintf(main_sym, sizeof main_sym, "%.*s.sym", (int)(n > 4 ? n - 4 : n), ihx);
            }
        }
        sym_dirs[nsym_dirs++] = dir1;
        sym_dirs[nsym_dirs++] = dir2;
        if (!mapf) {
            size_t n = strlen(ihx);
            snprintf(mapbuf, sizeof mapbuf, "%.*s.map", (int)(n > 4 ? n - 4 : n), ihx);
            mapf = mapbuf;
        }
        prof_init(mapf);
        if (sizef)
            covered = calloc(65536, 1);
        if (histf) {
            hist_t = calloc(65536, sizeof *hist_t);
            hist_n = calloc(65536, sizeof *hist_n);
        }
    }

    profiling = prof_all;
    while (!stopped && T < limit && !bad_op) {
        uint16_t pc = cur_pc = PC;
        int t = exec_main();
        T += (unsigned)t;
        if (covered)
            covered[pc] = 1;
        if (profiling && fns) {
            fns[fn_of[pc]].self += (unsigned)t;
            if (hist_t) {
                hist_t[pc] += (unsigned)t;
                hist_n[pc]++;
            }
        }
        /* calls whose return address was popped (ret, or pop + jp) */
        while (depth && SP > cstack[depth - 1].sp) {
            depth--;
            if (cstack[depth].counted) {
                fns[cstack[depth].fn].incl += T - cstack[depth].t0;
                if (cstack[depth].edge >= 0)
                    edges[cstack[depth].edge].incl += T - cstack[depth].t0;
            }
        }
    }
    fflush(uart_fp);
    if (bad_op > 0)
        fprintf(stderr, "z80sim: unknown instruction 0x%04X at 0x%04X\n", bad_op, PC);
    state = stopped ? "done" : bad_op == -1 ? "halt" : bad_op ? "bad" : "limit";
    if (exit_code >= 0)
        fprintf(mark_fp, "END state=%s code=%d ticks=%llu\n", state, exit_code, T);
    else
        fprintf(mark_fp, "END state=%s code=None ticks=%llu\n", state, T);
    if (exit_code >= 0)
        fprintf(mark_fp, "RAM stack_peak=%u\n", stack_peak);
    fflush(mark_fp);

    if (sizef) {
        /* code bytes per symbol: to the next symbol or the end of the
         * code (the first byte no .ihx record set, from the end) */
        FILE *zf = fopen(sizef, "w");
        unsigned end = 0, tot = 0;
        int *idx = malloc(sizeof(int) * (size_t)nfns), j, k;
        unsigned *sz = malloc(sizeof(unsigned) * (size_t)nfns);
        char *ran = calloc((size_t)nfns, 1);
        for (i = 0; i < 65536; i++)
            if (covered[i])
                ran[fn_of[i]] = 1;
        if (!zf) {
            fprintf(stderr, "z80sim: cannot write %s\n", sizef);
            return 2;
        }
        for (i = 0; i < nglobs; i++)
            if (!strcmp(globs[i].name, "s__DATA"))
                end = globs[i].addr;
        for (i = 0; i < nfns; i++) {
            unsigned next = i + 1 < nfns ? fns[i + 1].addr : end;
            if (end && next > end)
                next = end;
            sz[i] = fns[i].addr < next && fns[i].addr >= 0x200 ? next - fns[i].addr : 0;
            tot += sz[i];
            idx[i] = i;
        }
        for (j = 1; j < nfns; j++)
            for (k = j; k > 0 && sz[idx[k]] > sz[idx[k - 1]]; k--) {
                int t2 = idx[k];
                idx[k] = idx[k - 1];
                idx[k - 1] = t2;
            }
        {
            unsigned rb = 0;
            for (i = 0; i < nfns; i++)
                if (ran[i])
                    rb += sz[i];
            fprintf(zf, "# code bytes per symbol from 0x0200 to _DATA (0x%04X): %u in all, %u in"
                    " symbols this run entered (\"run\")\n", end, tot, rb);
        }
        for (j = 0; j < nfns && sz[idx[j]]; j++)
            fprintf(zf, "%6u %04x %-4s %s\n", sz[idx[j]], fns[idx[j]].addr, ran[idx[j]] ? "run" : "-", fns[idx[j]].name);
        fclose(zf);
        free(idx);
        free(sz);
        free(ran);
    }

    if (proff) {
        FILE *pf = fopen(proff, "w");
        unsigned long long tot = 0;
        unsigned nfr = frame_no > prof_from ? frame_no - prof_from : 0;
        for (i = 0; i < nfns; i++)
            tot += fns[i].self;
        if (!pf) {
            fprintf(stderr, "z80sim: cannot write %s\n", proff);
            return 2;
        }
        {
            /* call edges (indices into the address-sorted fns): by callee's incl */
            static int order[NEDGE];
            int ne = 0, j, k;
            char (*nm)[2][64] = calloc(NEDGE, sizeof *nm);
            for (j = 0; j < NEDGE; j++)
                if (edges[j].calls) {
                    snprintf(nm[j][0], 64, "%s", fns[edges[j].from].name);
                    snprintf(nm[j][1], 64, "%s", fns[edges[j].to].name);
                    order[ne++] = j;
                }
            for (j = 1; j < ne; j++) /* insertion sort, descending incl */
                for (k = j; k > 0 && edges[order[k]].incl > edges[order[k - 1]].incl; k--) {
                    int t2 = order[k];
                    order[k] = order[k - 1];
                    order[k - 1] = t2;
                }
            edge_text = malloc((size_t)ne * 180 + 1);
            edge_text[0] = 0;
            for (j = 0, k = 0; j < ne; j++)
                k += snprintf(edge_text + k, 180, "# %12llu %8llu %s -> %s\n", edges[order[j]].incl,
                              edges[order[j]].calls, nm[order[j]][0], nm[order[j]][1]);
            free(nm);
        }
        qsort(fns, nfns, sizeof *fns, cmp_self);
        fprintf(pf, "# T-states inside frames %u..%u (%u frames, %llu T, %s timing), per function (self)\n",
                prof_from, frame_no ? frame_no - 1 : 0, nfr, tot, ucsim_timing ? "ucsim" : "Zilog");
        for (i = 0; i < nfns && fns[i].self; i++)
            fprintf(pf, "%12llu %5.1f%% %s\n", fns[i].self, tot ? 100.0 * fns[i].self / tot : 0.0, fns[i].name);
        qsort(fns, nfns, sizeof *fns, cmp_incl);
        fprintf(pf, "# inclusive (callees counted in), per call: incl %% calls T/call name\n");
        for (i = 0; i < nfns && fns[i].incl; i++)
            fprintf(pf, "# %12llu %5.1f%% %8llu %10llu %s\n", fns[i].incl, tot ? 100.0 * fns[i].incl / tot : 0.0,
                    fns[i].calls, fns[i].calls ? fns[i].incl / fns[i].calls : 0, fns[i].name);
        fprintf(pf, "# call edges: incl calls caller -> callee\n%s", edge_text);
        fclose(pf);
    }
    if (histf) {
        FILE *hf = fopen(histf, "w");
        int a;
        if (!hf) {
            fprintf(stderr, "z80sim: cannot write %s\n", histf);
            return 2;
        }
        qsort(fns, nfns, sizeof *fns, fn_cmp);
        for (a = 0; a < 65536; a++)
            if (hist_n[a])
                fprintf(hf, "%04x %llu %llu %s+0x%x\n", a, hist_t[a], hist_n[a], fns[fn_of[a]].name,
                        a - fns[fn_of[a]].addr);
        fclose(hf);
    }
    if (stopped && exit_code >= 0)
        return exit_code;
    if (!stopped && !bad_op)
        return 124;
    return 125;
}
