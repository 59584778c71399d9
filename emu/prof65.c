/* prof65.c - a cycle-counting 6502 simulator that runs sim65 programs
 * (cc65 -t sim6502 .prg) and profiles them per function (host tool, C99).
 *
 *   prof65 [options] PROGRAM.prg [ARG...]
 *     -o FILE   the program's stdout (write(1, ...): the UART stream) to
 *               FILE, binary-safe (default: stdout)
 *     -m FILE   marker and summary lines to FILE (default: stderr)
 *     -x N      cycle limit (default 2e10); exit 124 when reached
 *     -L FILE   symbols: a VICE label file (ld65 -Ln; with cc65/ca65 -g
 *               it also names static functions) or an ld65 map (exports
 *               only).  Default: PROGRAM.lbl, else PROGRAM.map
 *     -P FILE   profile: cycles per function inside frames (between
 *               markers 2 and 3, like emu/avrsim -P), written to FILE
 *     -F N      profile frames N and later only (default 0)
 *     -H FILE   per instruction inside the profiled frames: "addr cycles
 *               executions" (hex address); with -D, the cycles of code
 *               without a source line (cc65's runtime library) go to
 *               the JSR that called it from code with one.
 *               emu/prof65_lines.py turns it into cycles per C line
 *     -D FILE   ld65's debug file (default: PROGRAM.dbg if it exists)
 *     -C FILE   code coverage of the whole run, per symbol: "size executed
 *               name" (bytes: its address range up to the next symbol,
 *               the opcode and operand bytes executed at least once),
 *               largest first, and a total line: what a build could trim
 *     -q        no MARK lines, only FRAME, END and RAM
 *     -h        this text
 *
 * The CPU is an NMOS 6502 with sim65 2.19's cycle counts: the data-sheet
 * timings, +1 for a read through abs,X / abs,Y / (zp),Y that crosses a
 * page, +1 for a taken branch and +1 more when its target is on another
 * page than the branch instruction.  sim65's paravirtual calls (a JSR or
 * JMP to $FFF4..$FFF9: open, close, read, write, args, exit) do the host
 * call and return at no extra cost, and the program's exit code is A at
 * exit.  "END ... cycles=C" equals sim65 -c's total for the same program.
 *
 * Markers: the platform layer's plat_mark(id) (ports/plat.h) is an empty
 * function on the 6502; every time the program enters it (the symbol
 * _plat_mark) the simulator logs
 *     MARK id cycle=C delta=D
 * with id = A (the argument, cc65 fastcall).  A FRAME line follows each
 * marker 3 that has a marker 2 before it:
 *     FRAME n cycles=C
 * At the end:
 *     END state=done|limit|crashed code=N cycles=C
 *     RAM stack_peak=N c=N hw=N      (when the program reports it on fd 2)
 *
 * The profile has one line per symbol, sorted by the third column:
 *     self      cycles with the PC inside the function
 *     +rt       C functions (names with a leading '_') also get the cycles
 *               of the runtime helpers they call (tosmulax, ladd, pushax,
 *               ...: symbols without '_'); a helper's own line keeps its
 *               self cycles
 *     incl      from entry (JSR) to return, callees included
 *     calls     JSRs to the function's first address
 * "JSR" frames are tracked by the stack pointer, so tail jumps (cc65's
 * "jmp incsp2") stay inside the caller's frame.
 * Exit status: the program's exit code; 124 on the cycle limit, 125 on
 * an illegal opcode, 2 on usage or file errors.
 */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <fcntl.h>
#include <sys/stat.h>

typedef unsigned long long u64;

static unsigned char M[0x10000];
static unsigned A, X, Y, S, P, PC;
static u64 cyc;

#define FC 0x01
#define FZ 0x02
#define FI 0x04
#define FD 0x08
#define FB 0x10
#define FV 0x40
#define FN 0x80
#define PV_BASE 0xFFF4
#define PV_N 6

/* ---- symbols */
typedef struct {
    unsigned addr;
    char *name;
    u64 self, cself, incl, calls;
    unsigned active; /* frames on the shadow stack (recursion) */
} sym;
static sym *syms;
static int nsyms;
static int *owner; /* address -> symbol index, -1 before the first */
static unsigned code_end = 0x10000; /* where CODE ends (the map's RODATA) */
static unsigned char *has_line; /* -D: addresses with a source line */

/* the map's segment list: CODE's end, for the last function's size */
static void read_code_end(const char *map)
{
    char line[256], name[64];
    unsigned start, end;
    FILE *f = fopen(map, "r");
    while (f && fgets(line, sizeof line, f))
        if (sscanf(line, "%63s %x %x", name, &start, &end) == 3 && !strcmp(name, "CODE"))
            code_end = end + 1;
    if (f)
        fclose(f);
}

static int sym_cmp(const void *a, const void *b)
{
    const sym *x = a, *y = b;
    if (x->addr != y->addr)
        return x->addr < y->addr ? -1 : 1;
    return strcmp(x->name, y->name);
}

static void add_sym(unsigned addr, const char *name)
{
    static int cap;
    if (name[0] == '_' && name[1] == '_')
        return; /* linker symbols: __MAIN_START__, ... */
    if (addr < 0x200 || addr >= 0x10000)
        return; /* zero page, hardware stack */
    if (name[0] == 'L' && strlen(name) == 5 && strspn(name + 1, "0123456789ABCDEF") == 4)
        return; /* cc65's local labels (L0012) inside a function */
    if (name[0] == '@')
        return; /* ca65's cheap local labels */
    if (nsyms == cap) {
        cap = cap ? 2 * cap : 1024;
        syms = realloc(syms, (size_t)cap * sizeof *syms);
        if (!syms) {
            fprintf(stderr, "prof65: out of memory\n");
            exit(2);
        }
    }
    memset(&syms[nsyms], 0, sizeof *syms);
    syms[nsyms].addr = addr;
    syms[nsyms].name = strdup(name);
    nsyms++;
}

/* VICE labels ("al 00023A ._g") or an ld65 map's "Exports list by value" */
static int load_syms(const char *path)
{
    char line[512];
    int inmap = 0, i, j;
    FILE *f = fopen(path, "r");
    if (!f)
        return -1;
    while (fgets(line, sizeof line, f)) {
        unsigned a;
        char n1[256], n2[256], t1[8], t2[8];
        unsigned a2;
        if (sscanf(line, "al %x .%255s", &a, n1) == 2) {
            add_sym(a, n1);
            continue;
        }
        if (!strncmp(line, "Exports list by value", 21)) {
            inmap = 1;
            continue;
        }
        if (inmap && !strncmp(line, "Imports list", 12))
            break;
        if (inmap) {
            int k = sscanf(line, "%255s %x %7s %255s %x %7s", n1, &a, t1, n2, &a2, t2);
            if (k >= 3 && t1[0] == 'R' && t1[2] == 'A')
                add_sym(a, n1);
            if (k == 6 && t2[0] == 'R' && t2[2] == 'A')
                add_sym(a2, n2);
        }
    }
    fclose(f);
    qsort(syms, (size_t)nsyms, sizeof *syms, sym_cmp);
    /* one name per address (aliases: tosmula0 = tosumula0, ...) */
    for (i = j = 0; i < nsyms; i++) {
        if (j && syms[j - 1].addr == syms[i].addr) {
            free(syms[i].name);
            continue;
        }
        syms[j++] = syms[i];
    }
    nsyms = j;
    owner = malloc(0x10000 * sizeof *owner);
    for (i = 0, j = -1; i < 0x10000; i++) {
        while (j + 1 < nsyms && syms[j + 1].addr <= (unsigned)i)
            j++;
        owner[i] = j;
    }
    return 0;
}

/* ld65 --dbgfile: which addresses have a source line (C or assembly);
 * cc65's runtime library has none */
static int load_lines(const char *path)
{
    static unsigned segstart[64];
    static unsigned *spst, *spsz;
    static unsigned char *spseg;
    unsigned nspan = 0, id, a, b, c, k;
    char line[4096];
    FILE *f = fopen(path, "r");
    if (!f)
        return -1;
    spst = calloc(1 << 20, sizeof *spst);
    spsz = calloc(1 << 20, sizeof *spsz);
    spseg = calloc(1 << 20, 1);
    has_line = calloc(0x10000, 1);
    while (fgets(line, sizeof line, f)) {
        if (sscanf(line, "seg\tid=%u,name=%*[^,],start=0x%x", &id, &a) == 2 && id < 64)
            segstart[id] = a;
        else if (sscanf(line, "span\tid=%u,seg=%u,start=%u,size=%u", &id, &a, &b, &c) == 4 &&
                 id < (1u << 20)) {
            spseg[id] = (unsigned char)a;
            spst[id] = b;
            spsz[id] = c;
            if (id >= nspan)
                nspan = id + 1;
        }
    }
    rewind(f);
    while (fgets(line, sizeof line, f)) {
        char *p;
        if (strncmp(line, "line\t", 5) || !(p = strstr(line, "span=")))
            continue;
        p += 5;
        for (;;) {
            id = (unsigned)strtoul(p, &p, 10);
            if (id < nspan)
                for (k = 0; k < spsz[id]; k++)
                    has_line[(segstart[spseg[id] & 63] + spst[id] + k) & 0xFFFF] = 1;
            if (*p != '+')
                break;
            p++;
        }
    }
    fclose(f);
    free(spst);
    free(spsz);
    free(spseg);
    return 0;
}

static int find_sym(const char *name)
{
    int i;
    for (i = 0; i < nsyms; i++)
        if (!strcmp(syms[i].name, name))
            return i;
    return -1;
}

static int is_c(int s) { return s >= 0 && syms[s].name[0] == '_'; }

/* ---- coverage (-C): bytes executed, per symbol */
static unsigned char *covered;

static int cmp_size(const void *a, const void *b)
{
    const unsigned *x = a, *y = b;
    if (x[1] != y[1])
        return x[1] > y[1] ? -1 : 1;
    return x[0] < y[0] ? -1 : 1;
}

static void write_coverage(const char *path)
{
    FILE *f = fopen(path, "w");
    unsigned (*rows)[3] = calloc((size_t)nsyms + 1, sizeof *rows);
    unsigned tot = 0, tot_ex = 0;
    int i, n = 0;
    if (!f || !rows) {
        fprintf(stderr, "prof65: cannot write %s\n", path);
        exit(2);
    }
    for (i = 0; i < nsyms; i++) {
        unsigned a = syms[i].addr, e = i + 1 < nsyms ? syms[i + 1].addr : code_end, ex = 0, k;
        if (a >= code_end || a >= PV_BASE)
            continue;
        if (e > code_end)
            e = code_end;
        for (k = a; k < e; k++)
            ex += covered[k];
        rows[n][0] = (unsigned)i;
        rows[n][1] = e - a;
        rows[n][2] = ex;
        tot += e - a;
        tot_ex += ex;
        n++;
    }
    qsort(rows, (size_t)n, sizeof *rows, cmp_size);
    fprintf(f, "# prof65 coverage: code bytes per symbol (up to the next one), bytes executed\n");
    fprintf(f, "# %6s %8s  %s\n", "size", "executed", "symbol");
    for (i = 0; i < n; i++)
        fprintf(f, "%8u %8u  %s\n", rows[i][1], rows[i][2], syms[rows[i][0]].name);
    fprintf(f, "%8u %8u  (total; never executed: %u bytes)\n", tot, tot_ex, tot - tot_ex);
    fclose(f);
    free(rows);
}

/* ---- shadow call stack (for +rt and incl) */
typedef struct {
    int fn, cown;
    unsigned rsite; /* -H: the JSR from code with line info that led here */
    unsigned s; /* S inside the callee */
    u64 t0;     /* profiled cycles at entry */
} frame;
static frame stk[4096];
static int depth;
static u64 pcyc; /* profiled cycles so far */
static int profiling; /* inside a profiled frame */

static void call_push(unsigned target, unsigned site)
{
    int fn = owner ? owner[target] : -1;
    frame *f;
    if (depth == (int)(sizeof stk / sizeof stk[0]))
        return;
    f = &stk[depth];
    f->fn = fn;
    f->s = S;
    f->t0 = pcyc;
    f->rsite = (!has_line || has_line[site] || !depth) ? site : stk[depth - 1].rsite;
    if (is_c(fn))
        f->cown = fn;
    else
        f->cown = depth ? stk[depth - 1].cown : fn;
    if (fn >= 0) {
        syms[fn].active++;
        if (syms[fn].addr == target && profiling)
            syms[fn].calls++;
    }
    depth++;
}

static void frame_end(frame *f)
{
    if (f->fn >= 0 && --syms[f->fn].active == 0)
        syms[f->fn].incl += pcyc - f->t0;
}

static void call_pop(void)
{
    while (depth && stk[depth - 1].s < S)
        frame_end(&stk[--depth]);
}

/* ---- memory and flags */
#define RD(a) M[(a) & 0xFFFF]
static unsigned rdw(unsigned a) { return RD(a) | RD(a + 1) << 8; }
static unsigned zpw(unsigned z) { return M[z & 0xFF] | M[(z + 1) & 0xFF] << 8; }
static void push(unsigned v) { M[0x100 | S] = (unsigned char)v; S = (S - 1) & 0xFF; }
static unsigned pop(void) { S = (S + 1) & 0xFF; return M[0x100 | S]; }
static void nz(unsigned v) { P = (P & ~(FN | FZ)) | (v & 0x80) | ((v & 0xFF) ? 0 : FZ); }

/* ---- paravirtual I/O (sim65 2.19 paravirt.c semantics) */
static FILE *outf;
static int exited = -1;
static char **pargv;
static int pargc;
static unsigned char sp_zp; /* the C stack pointer's zero-page address */
static char errbuf[256];
static int errlen;

static unsigned pop_param(unsigned incr)
{
    unsigned sp = zpw(sp_zp), v = rdw(sp);
    sp = (sp + incr) & 0xFFFF;
    M[sp_zp] = sp & 0xFF;
    M[(sp_zp + 1) & 0xFF] = sp >> 8;
    return v;
}

static void set_ax(unsigned v) { A = v & 0xFF; X = (v >> 8) & 0xFF; }

static FILE *markf;
static char ram_line[128];

/* plat_sim65.c's "STACK c=N hw=N" becomes sim65run.py's RAM line (after END) */
static void err_line(const char *l)
{
    unsigned c, hw;
    if (sscanf(l, "STACK c=%u hw=%u", &c, &hw) == 2)
        snprintf(ram_line, sizeof ram_line, "RAM stack_peak=%u c=%u hw=%u\n", c + hw, c, hw);
    else
        fputs(l, stderr);
}

static void pv_write_bytes(unsigned fd, const unsigned char *d, unsigned n)
{
    if (fd == 1) {
        fwrite(d, 1, n, outf);
    } else if (fd == 2) {
        /* keep the program's stderr lines (plat_sim65.c's STACK report) */
        unsigned i;
        for (i = 0; i < n; i++) {
            if (errlen < (int)sizeof errbuf - 1)
                errbuf[errlen++] = (char)d[i];
            if (d[i] == '\n') {
                errbuf[errlen] = 0;
                err_line(errbuf);
                errlen = 0;
            }
        }
    } else if (write((int)fd, d, n) < 0) {
        /* the program sees the count below */
    }
}

static void paravirt(unsigned which)
{
    unsigned char buf[0x10000];
    switch (which) {
    case 0: { /* open(name, flags, ...) */
        char path[1024];
        unsigned mode = pop_param(Y - 4), flags = pop_param(2), name = pop_param(2), i;
        int of = 0, om = 0, r;
        if (Y - 4 < 2)
            mode = 3;
        for (i = 0; i < sizeof path - 1 && RD(name + i); i++)
            path[i] = (char)RD(name + i);
        path[i] = 0;
        of = (flags & 3) == 1 ? O_RDONLY : (flags & 3) == 2 ? O_WRONLY : O_RDWR;
        if (flags & 0x10) of |= O_CREAT;
        if (flags & 0x20) of |= O_TRUNC;
        if (flags & 0x40) of |= O_APPEND;
        if (flags & 0x80) of |= O_EXCL;
        if (mode & 1) om |= S_IRUSR;
        if (mode & 2) om |= S_IWUSR;
        r = open(path, of, om);
        set_ax((unsigned)r);
        break;
    }
    case 1: { /* close(fd) */
        unsigned fd = A | X << 8;
        set_ax(fd == 0xFFFF ? 0xFFFF : (unsigned)close((int)fd));
        break;
    }
    case 2: { /* read(fd, buf, count) */
        unsigned n = A | X << 8, b = pop_param(2), fd = pop_param(2), i;
        ssize_t r = read((int)fd, buf, n);
        for (i = 0; r > 0 && i < (unsigned)r; i++)
            M[(b + i) & 0xFFFF] = buf[i];
        set_ax((unsigned)r);
        break;
    }
    case 3: { /* write(fd, buf, count) */
        unsigned n = A | X << 8, b = pop_param(2), fd = pop_param(2), i;
        for (i = 0; i < n; i++)
            buf[i] = RD(b + i);
        pv_write_bytes(fd, buf, n);
        set_ax(n);
        break;
    }
    case 4: { /* args(&argv): argc in A/X */
        unsigned argv = A | X << 8, sp = zpw(sp_zp), args, i;
        int k;
        args = (sp - (unsigned)(pargc + 1) * 2) & 0xFFFF;
        M[argv] = args & 0xFF;
        M[(argv + 1) & 0xFFFF] = args >> 8;
        sp = args;
        for (k = 0; k < pargc; k++) {
            size_t len = strlen(pargv[k]);
            sp = (sp - (unsigned)len - 1) & 0xFFFF;
            for (i = 0; i <= len; i++)
                M[(sp + i) & 0xFFFF] = (unsigned char)pargv[k][i];
            M[args] = sp & 0xFF;
            M[(args + 1) & 0xFFFF] = sp >> 8;
            args = (args + 2) & 0xFFFF;
        }
        M[args] = sp_zp; /* sim65 writes SPAddr here: argv[argc] = NULL-ish */
        M[(args + 1) & 0xFFFF] = 0;
        M[sp_zp] = sp & 0xFF;
        M[(sp_zp + 1) & 0xFF] = sp >> 8;
        set_ax((unsigned)pargc);
        break;
    }
    default: /* exit(code) */
        exited = (int)A;
        return;
    }
    /* return as if by RTS */
    {
        unsigned lo = pop();
        PC = (lo | pop() << 8) + 1;
    }
}

/* ---- the CPU */
enum { IMP, ACC, IMM, ZP, ZPX, ZPY, ABS, ABX, ABY, IND, IZX, IZY, REL };
enum {
    ADC, AND, ASL, BCC, BCS, BEQ, BIT, BMI, BNE, BPL, BRK, BVC, BVS, CLC, CLD, CLI, CLV, CMP,
    CPX, CPY, DEC, DEX, DEY, EOR, INC, INX, INY, JMP, JSR, LDA, LDX, LDY, LSR, NOP, ORA, PHA,
    PHP, PLA, PLP, ROL, ROR, RTI, RTS, SBC, SEC, SED, SEI, STA, STX, STY, TAX, TAY, TSX, TXA,
    TXS, TYA, ILL
};
typedef struct { unsigned char op, mode, cyc; } opinfo;
static opinfo ops[256];
static const struct { unsigned char code, op, mode, cyc; } optab[] = {
    {0x69,ADC,IMM,2},{0x65,ADC,ZP,3},{0x75,ADC,ZPX,4},{0x6D,ADC,ABS,4},{0x7D,ADC,ABX,4},
    {0x79,ADC,ABY,4},{0x61,ADC,IZX,6},{0x71,ADC,IZY,5},
    {0x29,AND,IMM,2},{0x25,AND,ZP,3},{0x35,AND,ZPX,4},{0x2D,AND,ABS,4},{0x3D,AND,ABX,4},
    {0x39,AND,ABY,4},{0x21,AND,IZX,6},{0x31,AND,IZY,5},
    {0x0A,ASL,ACC,2},{0x06,ASL,ZP,5},{0x16,ASL,ZPX,6},{0x0E,ASL,ABS,6},{0x1E,ASL,ABX,7},
    {0x90,BCC,REL,2},{0xB0,BCS,REL,2},{0xF0,BEQ,REL,2},{0x30,BMI,REL,2},{0xD0,BNE,REL,2},
    {0x10,BPL,REL,2},{0x50,BVC,REL,2},{0x70,BVS,REL,2},
    {0x24,BIT,ZP,3},{0x2C,BIT,ABS,4},{0x00,BRK,IMP,7},
    {0x18,CLC,IMP,2},{0xD8,CLD,IMP,2},{0x58,CLI,IMP,2},{0xB8,CLV,IMP,2},
    {0xC9,CMP,IMM,2},{0xC5,CMP,ZP,3},{0xD5,CMP,ZPX,4},{0xCD,CMP,ABS,4},{0xDD,CMP,ABX,4},
    {0xD9,CMP,ABY,4},{0xC1,CMP,IZX,6},{0xD1,CMP,IZY,5},
    {0xE0,CPX,IMM,2},{0xE4,CPX,ZP,3},{0xEC,CPX,ABS,4},{0xC0,CPY,IMM,2},{0xC4,CPY,ZP,3},
    {0xCC,CPY,ABS,4},
    {0xC6,DEC,ZP,5},{0xD6,DEC,ZPX,6},{0xCE,DEC,ABS,6},{0xDE,DEC,ABX,7},
    {0xCA,DEX,IMP,2},{0x88,DEY,IMP,2},
    {0x49,EOR,IMM,2},{0x45,EOR,ZP,3},{0x55,EOR,ZPX,4},{0x4D,EOR,ABS,4},{0x5D,EOR,ABX,4},
    {0x59,EOR,ABY,4},{0x41,EOR,IZX,6},{0x51,EOR,IZY,5},
    {0xE6,INC,ZP,5},{0xF6,INC,ZPX,6},{0xEE,INC,ABS,6},{0xFE,INC,ABX,7},
    {0xE8,INX,IMP,2},{0xC8,INY,IMP,2},
    {0x4C,JMP,ABS,3},{0x6C,JMP,IND,5},{0x20,JSR,ABS,6},
    {0xA9,LDA,IMM,2},{0xA5,LDA,ZP,3},{0xB5,LDA,ZPX,4},{0xAD,LDA,ABS,4},{0xBD,LDA,ABX,4},
    {0xB9,LDA,ABY,4},{0xA1,LDA,IZX,6},{0xB1,LDA,IZY,5},
    {0xA2,LDX,IMM,2},{0xA6,LDX,ZP,3},{0xB6,LDX,ZPY,4},{0xAE,LDX,ABS,4},{0xBE,LDX,ABY,4},
    {0xA0,LDY,IMM,2},{0xA4,LDY,ZP,3},{0xB4,LDY,ZPX,4},{0xAC,LDY,ABS,4},{0xBC,LDY,ABX,4},
    {0x4A,LSR,ACC,2},{0x46,LSR,ZP,5},{0x56,LSR,ZPX,6},{0x4E,LSR,ABS,6},{0x5E,LSR,ABX,7},
    {0xEA,NOP,IMP,2},
    {0x09,ORA,IMM,2},{0x05,ORA,ZP,3},{0x15,ORA,ZPX,4},{0x0D,ORA,ABS,4},{0x1D,ORA,ABX,4},
    {0x19,ORA,ABY,4},{0x01,ORA,IZX,6},{0x11,ORA,IZY,5},
    {0x48,PHA,IMP,3},{0x08,PHP,IMP,3},{0x68,PLA,IMP,4},{0x28,PLP,IMP,4},
    {0x2A,ROL,ACC,2},{0x26,ROL,ZP,5},{0x36,ROL,ZPX,6},{0x2E,ROL,ABS,6},{0x3E,ROL,ABX,7},
    {0x6A,ROR,ACC,2},{0x66,ROR,ZP,5},{0x76,ROR,ZPX,6},{0x6E,ROR,ABS,6},{0x7E,ROR,ABX,7},
    {0x40,RTI,IMP,6},{0x60,RTS,IMP,6},
    {0xE9,SBC,IMM,2},{0xE5,SBC,ZP,3},{0xF5,SBC,ZPX,4},{0xED,SBC,ABS,4},{0xFD,SBC,ABX,4},
    {0xF9,SBC,ABY,4},{0xE1,SBC,IZX,6},{0xF1,SBC,IZY,5},
    {0x38,SEC,IMP,2},{0xF8,SED,IMP,2},{0x78,SEI,IMP,2},
    {0x85,STA,ZP,3},{0x95,STA,ZPX,4},{0x8D,STA,ABS,4},{0x9D,STA,ABX,5},{0x99,STA,ABY,5},
    {0x81,STA,IZX,6},{0x91,STA,IZY,6},
    {0x86,STX,ZP,3},{0x96,STX,ZPY,4},{0x8E,STX,ABS,4},
    {0x84,STY,ZP,3},{0x94,STY,ZPX,4},{0x8C,STY,ABS,4},
    {0xAA,TAX,IMP,2},{0xA8,TAY,IMP,2},{0xBA,TSX,IMP,2},{0x8A,TXA,IMP,2},{0x9A,TXS,IMP,2},
    {0x98,TYA,IMP,2},
};

static void adc(unsigned v)
{
    unsigned c = P & FC, r;
    if (P & FD) { /* NMOS decimal mode, as sim65 */
        unsigned lo = (A & 0x0F) + (v & 0x0F) + c;
        int res;
        if (lo >= 0x0A)
            lo = ((lo + 0x06) & 0x0F) + 0x10;
        r = (A & 0xF0) + (v & 0xF0) + lo;
        res = (signed char)(A & 0xF0) + (signed char)(v & 0xF0) + (signed char)lo;
        P = (P & ~(FZ | FN | FC | FV)) | (((A + v + c) & 0xFF) ? 0 : FZ) | (r & 0x80);
        if (r >= 0xA0)
            r += 0x60;
        if (r & 0xFF00)
            P |= FC;
        if (res < -128 || res > 127)
            P |= FV;
        A = r & 0xFF;
        return;
    }
    r = A + v + c;
    P &= ~(FC | FV);
    if (r > 0xFF)
        P |= FC;
    if (!((A ^ v) & 0x80) && ((A ^ r) & 0x80))
        P |= FV;
    A = r & 0xFF;
    nz(A);
}

static void sbc(unsigned v)
{
    if (P & FD) { /* as sim65 */
        unsigned old = A, c = P & FC, lo, r;
        int res;
        lo = (old & 0x0F) - (v & 0x0F) + c - 1;
        if (lo & 0x80)
            lo = ((lo - 0x06) & 0x0F) - 0x10;
        r = (old & 0xF0) - (v & 0xF0) + lo;
        if (r & 0x80)
            r -= 0x60;
        res = (int)(r - v + !c);
        P &= ~(FZ | FN | FC | FV);
        P |= ((res & 0xFF) ? 0 : FZ) | (res & 0x80);
        if ((unsigned)res <= 0xFF)
            P |= FC;
        if ((old ^ v) & (old ^ (unsigned)res) & 0x80)
            P |= FV;
        A = r & 0xFF;
        return;
    }
    adc(v ^ 0xFF);
}

static void cmp(unsigned r, unsigned v)
{
    unsigned d = (r - v) & 0x1FF;
    nz(d & 0xFF);
    P = (P & ~FC) | (r >= v ? FC : 0);
}

/* one instruction; returns its cycles, or -1 on an illegal opcode */
static int step(void)
{
    static const unsigned char len[] = {1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 2, 2, 2};
    unsigned op = M[PC], ea = 0, v, t;
    const opinfo *oi = &ops[op];
    int c = oi->cyc, pen = 0;
    switch (oi->mode) {
    case IMP: case ACC: break;
    case IMM: ea = (PC + 1) & 0xFFFF; break;
    case ZP: ea = RD(PC + 1); break;
    case ZPX: ea = (RD(PC + 1) + X) & 0xFF; break;
    case ZPY: ea = (RD(PC + 1) + Y) & 0xFF; break;
    case ABS: ea = rdw(PC + 1); break;
    case ABX: t = rdw(PC + 1); pen = (t & 0xFF) + X >= 0x100; ea = (t + X) & 0xFFFF; break;
    case ABY: t = rdw(PC + 1); pen = (t & 0xFF) + Y >= 0x100; ea = (t + Y) & 0xFFFF; break;
    case IND: t = rdw(PC + 1); ea = RD(t) | RD((t & 0xFF00) | ((t + 1) & 0xFF)) << 8; break;
    case IZX: ea = zpw(RD(PC + 1) + X); break;
    case IZY: t = zpw(RD(PC + 1)); pen = (t & 0xFF) + Y >= 0x100; ea = (t + Y) & 0xFFFF; break;
    case REL: ea = (PC + 2 + (unsigned)(signed char)RD(PC + 1)) & 0xFFFF; break;
    }
    PC = (PC + len[oi->mode]) & 0xFFFF;
#define BR(cond)                                                          \
    if (cond) {                                                           \
        c++;                                                              \
        if (((PC - 2) & 0xFF00) != (ea & 0xFF00))                         \
            c++;                                                          \
        PC = ea;                                                          \
    }
    switch (oi->op) {
    case ADC: adc(M[ea]); c += pen; break;
    case SBC: sbc(M[ea]); c += pen; break;
    case AND: A &= M[ea]; nz(A); c += pen; break;
    case ORA: A |= M[ea]; nz(A); c += pen; break;
    case EOR: A ^= M[ea]; nz(A); c += pen; break;
    case LDA: A = M[ea]; nz(A); c += pen; break;
    case LDX: X = M[ea]; nz(X); c += pen; break;
    case LDY: Y = M[ea]; nz(Y); c += pen; break;
    case CMP: cmp(A, M[ea]); c += pen; break;
    case CPX: cmp(X, M[ea]); break;
    case CPY: cmp(Y, M[ea]); break;
    case BIT: v = M[ea]; P = (P & ~(FN | FV | FZ)) | (v & (FN | FV)) | ((v & A) ? 0 : FZ); break;
    case STA: M[ea] = (unsigned char)A; break;
    case STX: M[ea] = (unsigned char)X; break;
    case STY: M[ea] = (unsigned char)Y; break;
    case ASL: case LSR: case ROL: case ROR:
        v = oi->mode == ACC ? A : M[ea];
        t = P & FC;
        if (oi->op == ASL || oi->op == ROL) {
            P = (P & ~FC) | (v >> 7);
            v = ((v << 1) | (oi->op == ROL ? t : 0)) & 0xFF;
        } else {
            P = (P & ~FC) | (v & 1);
            v = (v >> 1) | (oi->op == ROR && t ? 0x80 : 0);
        }
        nz(v);
        if (oi->mode == ACC)
            A = v;
        else
            M[ea] = (unsigned char)v;
        break;
    case INC: v = (M[ea] + 1) & 0xFF; M[ea] = (unsigned char)v; nz(v); break;
    case DEC: v = (M[ea] - 1) & 0xFF; M[ea] = (unsigned char)v; nz(v); break;
    case INX: X = (X + 1) & 0xFF; nz(X); break;
    case INY: Y = (Y + 1) & 0xFF; nz(Y); break;
    case DEX: X = (X - 1) & 0xFF; nz(X); break;
    case DEY: Y = (Y - 1) & 0xFF; nz(Y); break;
    case TAX: X = A; nz(X); break;
    case TAY: Y = A; nz(Y); break;
    case TXA: A = X; nz(A); break;
    case TYA: A = Y; nz(A); break;
    case TSX: X = S; nz(X); break;
    case TXS: S = X; break;
    case PHA: push(A); break;
    case PHP: push(P | 0x30); break;
    case PLA: A = pop(); nz(A); break;
    case PLP: P = pop() | 0x30; break;
    case CLC: P &= ~FC; break;
    case SEC: P |= FC; break;
    case CLD: P &= ~FD; break;
    case SED: P |= FD; break;
    case CLI: P &= ~FI; break;
    case SEI: P |= FI; break;
    case CLV: P &= ~FV; break;
    case NOP: break;
    case BCC: BR(!(P & FC)); break;
    case BCS: BR(P & FC); break;
    case BNE: BR(!(P & FZ)); break;
    case BEQ: BR(P & FZ); break;
    case BPL: BR(!(P & FN)); break;
    case BMI: BR(P & FN); break;
    case BVC: BR(!(P & FV)); break;
    case BVS: BR(P & FV); break;
    case JMP:
        PC = ea;
        if (PC >= PV_BASE && PC < PV_BASE + PV_N) {
            /* a tail jump to a hook returns to the caller's caller */
            paravirt(PC - PV_BASE);
            call_pop();
        }
        break;
    case JSR:
        t = (PC - 1) & 0xFFFF;
        push(t >> 8);
        push(t & 0xFF);
        PC = ea;
        if (PC >= PV_BASE && PC < PV_BASE + PV_N)
            paravirt(PC - PV_BASE);
        else
            call_push(ea, (t - 2) & 0xFFFF);
        break;
    case RTS:
        t = pop();
        PC = ((t | pop() << 8) + 1) & 0xFFFF;
        call_pop();
        break;
    case RTI:
        P = pop() | 0x30;
        t = pop();
        PC = t | pop() << 8;
        call_pop();
        break;
    case BRK:
        PC = (PC + 1) & 0xFFFF;
        push(PC >> 8);
        push(PC & 0xFF);
        push(P | 0x30);
        P |= FI;
        PC = rdw(0xFFFE);
        break;
    default:
        return -1;
    }
    return c;
}

/* ---- markers and frames */
static int quiet;
static u64 last_mark, frame_start;
static int in_frame;
static unsigned frame_no, prof_from;

static void mark(unsigned id)
{
    if (!quiet)
        fprintf(markf, "MARK %u cycle=%llu delta=%llu\n", id, cyc, cyc - last_mark);
    last_mark = cyc;
    if (id == 2) {
        in_frame = 1;
        frame_start = cyc;
    } else if (id == 3 && in_frame) {
        in_frame = 0;
        fprintf(markf, "FRAME %u cycles=%llu\n", frame_no, cyc - frame_start);
        frame_no++;
    }
}

static int cmp_cself(const void *a, const void *b)
{
    const sym *x = a, *y = b;
    u64 kx = x->cself > x->self ? x->cself : x->self;
    u64 ky = y->cself > y->self ? y->cself : y->self;
    if (kx != ky)
        return kx > ky ? -1 : 1;
    return x->addr < y->addr ? -1 : 1;
}

static void usage(FILE *f)
{
    fprintf(f, "usage: prof65 [-o OUT] [-m MARKS] [-x CYCLES] [-L LABELS] [-P PROFILE [-F N]]\n"
               "              [-H HIST [-D DBG]] [-C COVERAGE] [-q] PROGRAM.prg [ARG...]\n"
               "runs a cc65 sim6502 program like sim65 (same cycle total), logs plat_mark\n"
               "markers and frame cycles, and profiles cycles per function in frames.\n");
}

int main(int argc, char **argv)
{
    const char *outp = NULL, *markp = NULL, *labp = NULL, *profp = NULL, *histp = NULL;
    const char *covp = NULL, *dbgp = NULL;
    u64 limit = 20000000000ULL;
    u64 *hist_c = NULL, *hist_n = NULL;
    unsigned char hdr[12];
    unsigned load, reset, a;
    int o, i, ill = 0, markfn = -1, ch, state;
    unsigned mark_addr = 0x10000;
    FILE *f;
    char lab[4096];

    while ((o = getopt(argc, argv, "+o:m:x:L:P:F:H:C:D:qh")) != -1) {
        switch (o) {
        case 'o': outp = optarg; break;
        case 'm': markp = optarg; break;
        case 'x': limit = strtoull(optarg, NULL, 0); break;
        case 'L': labp = optarg; break;
        case 'P': profp = optarg; break;
        case 'F': prof_from = (unsigned)atoi(optarg); break;
        case 'H': histp = optarg; break;
        case 'C': covp = optarg; break;
        case 'D': dbgp = optarg; break;
        case 'q': quiet = 1; break;
        case 'h': usage(stdout); return 0;
        default: usage(stderr); return 2;
        }
    }
    if (optind >= argc) {
        usage(stderr);
        return 2;
    }
    pargv = argv + optind;
    pargc = argc - optind;

    for (i = 0; i < 256; i++)
        ops[i].op = ILL, ops[i].mode = IMP, ops[i].cyc = 2;
    for (i = 0; i < (int)(sizeof optab / sizeof optab[0]); i++) {
        ops[optab[i].code].op = optab[i].op;
        ops[optab[i].code].mode = optab[i].mode;
        ops[optab[i].code].cyc = optab[i].cyc;
    }

    /* the program: "sim65", version 2, CPU, sp address, load, reset */
    f = fopen(argv[optind], "rb");
    if (!f || fread(hdr, 1, 12, f) != 12 || memcmp(hdr, "sim65", 5) || hdr[5] != 2) {
        fprintf(stderr, "prof65: %s: not a sim65 version 2 program\n", argv[optind]);
        return 2;
    }
    if (hdr[6] != 0) {
        fprintf(stderr, "prof65: %s: CPU type %u (only the 6502 is simulated)\n", argv[optind], hdr[6]);
        return 2;
    }
    sp_zp = hdr[7];
    load = hdr[8] | hdr[9] << 8;
    reset = hdr[10] | hdr[11] << 8;
    for (a = load; (ch = fgetc(f)) != EOF; a++) {
        if (a >= PV_BASE) {
            fprintf(stderr, "prof65: %s: too large for $%04X-$%04X\n", argv[optind], load, PV_BASE);
            return 2;
        }
        M[a] = (unsigned char)ch;
    }
    fclose(f);

    /* symbols */
    if (!labp) {
        size_t n = strlen(argv[optind]);
        const char *dot = strrchr(argv[optind], '.');
        size_t stem = dot && !strchr(dot, '/') ? (size_t)(dot - argv[optind]) : n;
        if (stem > sizeof lab - 8) stem = sizeof lab - 8;
        memcpy(lab, argv[optind], stem);
        strcpy(lab + stem, ".lbl");
        strcpy(lab + stem, ".map");
        read_code_end(lab);
        strcpy(lab + stem, ".lbl");
        if (access(lab, R_OK)) strcpy(lab + stem, ".map");
        if (!access(lab, R_OK)) labp = lab;
    }
    if (labp && strlen(labp) > 4 && !strcmp(labp + strlen(labp) - 4, ".map"))
        read_code_end(labp);
    if (labp && load_syms(labp)) {
        fprintf(stderr, "prof65: cannot read symbols from %s\n", labp);
        return 2;
    }
    if (!labp && (profp || covp)) {
        fprintf(stderr, "prof65: -P and -C need symbols (-L, or a .lbl / .map next to the program)\n");
        return 2;
    }
    if (nsyms && (markfn = find_sym("_plat_mark")) >= 0)
        mark_addr = syms[markfn].addr;

    outf = outp ? fopen(outp, "wb") : stdout;
    markf = markp ? fopen(markp, "w") : stderr;
    if (!outf || !markf) {
        fprintf(stderr, "prof65: cannot open %s\n", !outf ? outp : markp);
        return 2;
    }
    if (covp)
        covered = calloc(0x10000, 1);
    if (histp) {
        char dbg[4096];
        if (!dbgp) {
            const char *dot = strrchr(argv[optind], '.');
            size_t stem = dot && !strchr(dot, '/') ? (size_t)(dot - argv[optind]) : strlen(argv[optind]);
            if (stem < sizeof dbg - 8) {
                memcpy(dbg, argv[optind], stem);
                strcpy(dbg + stem, ".dbg");
                if (!access(dbg, R_OK))
                    dbgp = dbg;
            }
        }
        if (dbgp && load_lines(dbgp)) {
            fprintf(stderr, "prof65: cannot read %s\n", dbgp);
            return 2;
        }
    }
    if (histp) {
        hist_c = calloc(0x10000, sizeof *hist_c);
        hist_n = calloc(0x10000, sizeof *hist_n);
    }

    M[0xFFFC] = reset & 0xFF;
    M[0xFFFD] = reset >> 8;
    PC = reset;
    P = 0x30;
    S = 0xFF;
    state = 0;
    while (exited < 0) {
        unsigned pc0 = PC;
        int c;
        if (PC == mark_addr)
            mark(A);
        profiling = in_frame && frame_no >= prof_from;
        if (covered) {
            static const unsigned char len[] = {1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 2, 2, 2};
            unsigned k;
            for (k = 0; k < len[ops[M[PC]].mode]; k++)
                covered[(PC + k) & 0xFFFF] = 1;
        }
        c = step();
        if (c < 0) {
            fprintf(stderr, "prof65: illegal opcode $%02X at $%04X\n", M[pc0], pc0);
            ill = 1;
            break;
        }
        if (exited >= 0)
            break; /* sim65 exits inside the JSR/JMP: its cycles are not counted */
        cyc += (u64)c;
        if (profiling) {
            pcyc += (u64)c;
            if (owner) {
                int s = owner[pc0];
                if (s >= 0) {
                    syms[s].self += (u64)c;
                    if (is_c(s))
                        syms[s].cself += (u64)c;
                    else if (depth && stk[depth - 1].cown >= 0)
                        syms[stk[depth - 1].cown].cself += (u64)c;
                }
            }
            if (hist_c) {
                unsigned at = pc0;
                if (has_line && !has_line[pc0] && depth)
                    at = stk[depth - 1].rsite; /* a runtime helper: its caller */
                hist_c[at] += (u64)c;
                if (at == pc0)
                    hist_n[pc0]++;
            }
        }
        if (cyc >= limit) {
            state = 1;
            break;
        }
    }
    fflush(outf);
    fprintf(markf, "END state=%s code=%d cycles=%llu\n",
            ill ? "crashed" : state ? "limit" : "done", exited < 0 ? -1 : exited, cyc);
    if (errlen) {
        errbuf[errlen] = 0;
        err_line(errbuf);
    }
    fputs(ram_line, markf);

    if (covered && nsyms)
        write_coverage(covp); /* (before the profile sorts the symbols) */
    if (profp && nsyms) {
        FILE *pf = fopen(profp, "w");
        u64 tot = pcyc;
        while (depth)
            frame_end(&stk[--depth]);
        qsort(syms, (size_t)nsyms, sizeof *syms, cmp_cself);
        if (!pf) {
            fprintf(stderr, "prof65: cannot write %s\n", profp);
            return 2;
        }
        fprintf(pf, "# prof65 %s: cycles inside frames %u..%u (markers 2..3), total %llu\n",
                argv[optind], prof_from, frame_no ? frame_no - 1 : 0, tot);
        fprintf(pf, "# self: PC in the function; +rt: C functions with the runtime helpers they call;\n"
                    "# incl: entry to return, callees included; calls: JSRs to its first address\n");
        fprintf(pf, "#%11s %6s %12s %6s %12s %9s  %s\n", "self", "%", "+rt", "%", "incl", "calls", "function");
        for (i = 0; i < nsyms; i++) {
            sym *s = &syms[i];
            if (!s->self && !s->cself && !s->incl)
                continue;
            fprintf(pf, "%12llu %5.1f%% %12llu %5.1f%% %12llu %9llu  %s\n", s->self,
                    tot ? 100.0 * (double)s->self / (double)tot : 0.0,
                    is_c(i) ? s->cself : s->self,
                    tot ? 100.0 * (double)(is_c(i) ? s->cself : s->self) / (double)tot : 0.0,
                    s->incl, s->calls, s->name);
        }
        fclose(pf);
    }
    if (hist_c) {
        FILE *hf = fopen(histp, "w");
        for (a = 0; hf && a < 0x10000; a++)
            if (hist_n[a] || hist_c[a])
                fprintf(hf, "%04x %llu %llu\n", a, hist_c[a], hist_n[a]);
        if (hf)
            fclose(hf);
    }
    if (ill)
        return 125;
    if (state)
        return 124;
    return exited;
}
