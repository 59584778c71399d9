/* soak.c - r8soak: fault-injection soak of the C frame decoder on a real
 * emulator stream (make soak; tests/soak/soak.py is the Python twin).
 *
 *   r8soak STREAM DUMP [--faults N] [--seed S] [--quiet]
 *
 * STREAM is `rast8-emu --out` (or tests/soak/wire2.py's version-2 copy of
 * it), DUMP its `--dump` (the reference frames).
 * Each pass copies the stream with faults in it, at most one fault per
 * frame and fault frames at least 3 apart, decodes it with r8_dec and
 * checks:
 *   - every good frame equals the reference frame of that number;
 *   - frames lost: faults whose recovery windows overlap form a cluster;
 *     a cluster of k faults loses at most k * (P + 1) frames (P = the
 *     stream's full-frame period), a duplicated packet loses none, and
 *     every frame outside a cluster decodes;
 * Fault kinds: bit flip, byte drop (1-4), byte insert (1-4), burst
 * (2-16 random bytes), packet cut short, duplicated packet, two packets
 * swapped, whole frame lost, and the end of the stream cut off.  The
 * fault density changes from pass to pass (a fault every 3..64 frames).
 * Prints one summary line; exit 1 if any check failed. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "r8wire.h"

enum { F_FLIP, F_DROP, F_INSERT, F_BURST, F_CUT, F_DUP, F_SWAP, F_FRAME, F_KINDS };
static const char *kind_name[F_KINDS] = { "flip", "drop", "insert", "burst", "cut",
                                          "dup", "swap", "frame" };

static unsigned char *stream;
static long slen;
static long *pkt_start, *pkt_end; /* packet k: bytes [start, end), end = its 0x00 */
static long *pkt_frame;            /* index (0..) of the frame it belongs to */
static long npkt;
static long *frame_first_pkt;      /* first packet of frame i */
static long nframes;
static unsigned *frame_no;         /* frame number of frame i */
static unsigned char **ref;        /* reference pixels of frame i */
static unsigned fbytes;
static long period;                /* P: largest gap between full frames */
static int version;                /* the stream's protocol version */

static unsigned long long rng = 88172645463325252ULL;
static unsigned long rnd(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (unsigned long)(rng >> 11);
}
static long below(long n) { return (long)(rnd() % (unsigned long)n); }

static unsigned char *slurp(const char *path, long *n)
{
    FILE *f = fopen(path, "rb");
    unsigned char *b;
    if (!f) {
        fprintf(stderr, "r8soak: cannot read %s\n", path);
        exit(2);
    }
    fseek(f, 0, SEEK_END);
    *n = ftell(f);
    fseek(f, 0, SEEK_SET);
    b = malloc((size_t)*n + 1);
    if (!b || fread(b, 1, (size_t)*n, f) != (size_t)*n)
        exit(2);
    fclose(f);
    return b;
}

/* Split the stream into packets; number frames; find P. */
static void index_stream(void)
{
    long i, start = -1, k = 0, fi = -1, last_full = -1;
    unsigned char body[80];
    unsigned n;
    pkt_start = malloc(sizeof(long) * (size_t)slen);
    pkt_end = malloc(sizeof(long) * (size_t)slen);
    pkt_frame = malloc(sizeof(long) * (size_t)slen);
    frame_first_pkt = malloc(sizeof(long) * (size_t)slen + sizeof(long));
    period = 1;
    for (i = 0; i < slen; i++) {
        if (stream[i])
            continue;
        if (start >= 0 && i > start) {
            /* the kind is the first body byte (never 0: the first code > 1) */
            if (stream[start] > 1 && stream[start + 1] == R8_PKT_FRAME_START &&
                i - start <= 70 &&
                r8_cobs_decode(stream + start, (unsigned)(i - start), body, sizeof body, &n) == R8_OK) {
                fi++;
                frame_first_pkt[fi] = k;
                version = body[1];
                if (body[12] & R8_FLAG_FULL) {
                    if (last_full >= 0 && fi - last_full > period)
                        period = fi - last_full;
                    last_full = fi;
                }
            }
            pkt_start[k] = start;
            pkt_end[k] = i;
            pkt_frame[k] = fi;
            k++;
        }
        start = i + 1;
    }
    npkt = k;
    nframes = fi + 1;
    frame_first_pkt[nframes] = npkt;
    if (nframes - 1 - last_full > period)
        period = nframes - 1 - last_full;
}

static void load_dump(const char *path)
{
    long n, i = 0, f = 0;
    unsigned char *d = slurp(path, &n);
    frame_no = malloc(sizeof(unsigned) * (size_t)(nframes + 1));
    ref = malloc(sizeof(unsigned char *) * (size_t)(nframes + 1));
    while (i + 12 <= n && f < nframes) {
        unsigned w = (unsigned)(d[i + 6] << 8 | d[i + 7]), h = (unsigned)(d[i + 8] << 8 | d[i + 9]);
        fbytes = r8_fb_bytes(d[i + 10], (r8_s16)w, (r8_s16)h);
        frame_no[f] = (unsigned)(d[i + 4] << 8 | d[i + 5]);
        ref[f] = d + i + 12;
        i += 12 + (long)fbytes;
        f++;
    }
    if (f != nframes) {
        fprintf(stderr, "r8soak: the dump has %ld frames, the stream %ld\n", f, nframes);
        exit(2);
    }
}

/* ---- one pass */
static unsigned char *out;
static long olen, ocap;
static void emit(const unsigned char *p, long n)
{
    if (olen + n > ocap) {
        ocap = (olen + n) * 2;
        out = realloc(out, (size_t)ocap);
    }
    memcpy(out + olen, p, (size_t)n);
    olen += n;
}
static void emit_rand(long n)
{
    while (n-- > 0) {
        unsigned char c = (unsigned char)rnd();
        emit(&c, 1);
    }
}

static unsigned long long faults, kinds[F_KINDS], checked, wrong, unexplained, over_bound,
    dup_lost, passes, truncs;
static long worst_single, worst_kind[F_KINDS];

int main(int argc, char **argv)
{
    unsigned long long want = 10000000ULL;
    int quiet = 0, a;
    long *fault_kind, *fault_lo, *fault_hi, *fault_at, *fault_pkt, *frame_out_end, *frame_idx;
    unsigned char *good, *pkt, *fb, pal[768];
    if (argc < 3) {
        fprintf(stderr, "usage: r8soak STREAM DUMP [--faults N] [--seed S] [--quiet]\n");
        return 2;
    }
    for (a = 3; a < argc; a++) {
        if (!strcmp(argv[a], "--faults") && a + 1 < argc)
            want = strtoull(argv[++a], 0, 0);
        else if (!strcmp(argv[a], "--seed") && a + 1 < argc)
            rng ^= strtoull(argv[++a], 0, 0) * 0x9E3779B97F4A7C15ULL;
        else if (!strcmp(argv[a], "--quiet"))
            quiet = 1;
        else {
            fprintf(stderr, "r8soak: unknown option '%s'\n", argv[a]);
            return 2;
        }
    }
    stream = slurp(argv[1], &slen);
    index_stream();
    load_dump(argv[2]);
    fault_kind = malloc(sizeof(long) * (size_t)nframes);
    fault_lo = malloc(sizeof(long) * (size_t)nframes);
    fault_hi = malloc(sizeof(long) * (size_t)nframes);
    fault_at = malloc(sizeof(long) * (size_t)nframes);
    fault_pkt = malloc(sizeof(long) * (size_t)nframes);
    frame_out_end = malloc(sizeof(long) * (size_t)nframes);
    frame_idx = malloc(sizeof(long) * 65536);
    for (a = 0; a < 65536; a++)
        frame_idx[a] = -1;
    for (a = 0; a < nframes; a++) {
        if (frame_idx[frame_no[a]] >= 0) {
            fprintf(stderr, "r8soak: frame number %u occurs twice: use a stream of < 65536 frames\n", frame_no[a]);
            return 2;
        }
        frame_idx[frame_no[a]] = a;
    }
    good = malloc((size_t)nframes);
    pkt = malloc(R8_DEC_PKT_BYTES(fbytes));
    fb = malloc(fbytes);
    ocap = slen * 2;
    out = malloc((size_t)ocap);

    while (faults < want) {
        long spacing = 3 + below(62), f, nf = 0, k, i, end_frame = nframes;
        r8_dec d;
        memset(good, 0, (size_t)nframes);
        /* choose the fault frames: >= 3 apart, at most one fault each,
         * and the packet of the frame it hits */
        for (f = 1 + below(spacing); f < nframes - 1; f += 3 + below(2 * spacing - 3)) {
            long first = frame_first_pkt[f], count = frame_first_pkt[f + 1] - first;
            fault_kind[nf] = below(F_KINDS);
            fault_at[nf] = f;
            fault_pkt[nf] = first + below(count);
            fault_lo[nf] = fault_hi[nf] = f;
            nf++;
        }
        /* build the damaged stream packet by packet */
        olen = 0;
        emit(stream, pkt_start[0]); /* the leading sync */
        i = 0;
        for (k = 0; k < npkt; k++) {
            long s = pkt_start[k], e = pkt_end[k], fr = pkt_frame[k], plen = e + 1 - s;
            while (i < nf && fault_at[i] < fr)
                i++;
            if (i < nf && fault_at[i] == fr && fault_kind[i] == F_FRAME) {
                /* every packet of the frame is gone */
            } else if (i < nf && k == fault_pkt[i]) {
                long p = s + below(plen), n;
                switch (fault_kind[i]) {
                case F_FLIP: {
                    unsigned char c = (unsigned char)(stream[p] ^ (1u << below(8)));
                    emit(stream + s, p - s);
                    emit(&c, 1);
                    emit(stream + p + 1, e - p);
                    break;
                }
                case F_DROP:
                    n = 1 + below(4);
                    if (p + n > e + 1)
                        n = e + 1 - p;
                    emit(stream + s, p - s);
                    emit(stream + p + n, e + 1 - p - n);
                    break;
                case F_INSERT:
                    emit(stream + s, p - s);
                    emit_rand(1 + below(4));
                    emit(stream + p, e + 1 - p);
                    break;
                case F_BURST: /* 2..16 random bytes over the packet (and its 0x00) */
                    n = 2 + below(15);
                    if (p + n > e + 1)
                        p = e + 1 - n < s ? s : e + 1 - n;
                    if (p + n > e + 1)
                        n = e + 1 - p;
                    emit(stream + s, p - s);
                    emit_rand(n);
                    emit(stream + p + n, e + 1 - p - n);
                    break;
                case F_CUT: /* the packet ends early */
                    emit(stream + s, p - s);
                    emit(stream + e, 1);
                    break;
                case F_DUP:
                    emit(stream + s, plen);
                    emit(stream + s, plen);
                    break;
                case F_SWAP:
                    if (k + 1 < npkt) {
                        emit(stream + pkt_start[k + 1], pkt_end[k + 1] + 1 - pkt_start[k + 1]);
                        emit(stream + s, plen);
                        k++;
                    } else {
                        emit(stream + s, plen);
                    }
                    break;
                }
                /* a fault on the last packet (delimiter, swap) reaches the next frame */
                if (k + 1 < npkt && pkt_frame[k + 1] != fr)
                    fault_hi[i] = fr + 1;
            } else {
                emit(stream + s, plen);
            }
            frame_out_end[fr] = olen;
        }
        faults += (unsigned long long)nf;
        for (i = 0; i < nf; i++)
            kinds[fault_kind[i]]++;
        /* every fourth pass the end of the stream is cut off too: frames
         * not wholly before the cut are not expected */
        if ((passes & 3) == 3) {
            long cut = olen - 1 - below(olen / 10 + 1);
            olen = cut;
            while (end_frame > 0 && frame_out_end[end_frame - 1] > cut)
                end_frame--;
            faults++;
            truncs++;
        }
        passes++;
        /* decode */
        r8_dec_init(&d, pkt, R8_DEC_PKT_BYTES(fbytes), fb, fbytes, pal, sizeof pal);
        for (k = 0; k < olen; k++) {
            long fi;
            if (r8_dec_feed(&d, out[k]) != R8_DEC_FRAME)
                continue;
            fi = frame_idx[d.frame];
            if (fi < 0 || memcmp(fb, ref[fi], fbytes)) {
                /* keep the evidence: the damaged stream of this pass */
                char name[64];
                FILE *w;
                wrong++;
                sprintf(name, "build/soak/wrong-%llu.bin", wrong);
                if ((w = fopen(name, "wb")) != 0) {
                    fwrite(out, 1, (size_t)olen, w);
                    fclose(w);
                }
                fprintf(stderr, "r8soak: WRONG frame %u accepted at byte %ld of pass %llu "
                        "(stream kept in %s)\n", (unsigned)d.frame, k, passes, name);
                continue;
            }
            checked++;
            good[fi] = 1;
        }
        r8_dec_end(&d);
        /* frames lost: faults whose recovery windows overlap form a cluster */
        {
            long c0 = 0, lo, hi, lost, fr, kk, ndup;
            for (i = 0; i <= nf; i++) {
                if (i < nf && i > c0 && fault_lo[i] <= fault_hi[i - 1] + period + 1)
                    continue; /* still the same cluster */
                if (i > c0) {
                    lo = fault_lo[c0];
                    hi = fault_hi[i - 1] + period + 1;
                    if (hi > end_frame - 1)
                        hi = end_frame - 1;
                    lost = ndup = 0;
                    for (fr = lo; fr <= hi; fr++)
                        lost += !good[fr];
                    kk = i - c0;
                    for (fr = c0; fr < i; fr++)
                        ndup += fault_kind[fr] == F_DUP;
                    if (lost > kk * (period + 1))
                        over_bound++;
                    if (ndup == kk && lost)
                        dup_lost++;
                    if (kk == 1) {
                        if (lost > worst_single)
                            worst_single = lost;
                        if (lost > worst_kind[fault_kind[c0]])
                            worst_kind[fault_kind[c0]] = lost;
                    }
                }
                c0 = i;
            }
            /* outside every fault's window each frame decodes */
            for (fr = 0, i = 0; fr < end_frame; fr++) {
                while (i < nf && fault_hi[i] + period + 1 < fr)
                    i++;
                if (i < nf && fr >= fault_lo[i])
                    continue;
                if (!good[fr])
                    unexplained++;
            }
        }
        if (!quiet && passes % 200 == 0)
            fprintf(stderr, "r8soak: %llu faults...\n", faults);
    }
    printf("soak C decoder (protocol v%d): %llu faults (", version, faults);
    for (a = 0; a < F_KINDS; a++)
        printf("%s%s %llu", a ? ", " : "", kind_name[a], kinds[a]);
    printf(", truncation %llu), %llu frames checked, %llu wrong frames accepted, "
           "worst frames lost per fault %ld (bound P+1 = %ld; flip %ld drop %ld insert %ld "
           "burst %ld cut %ld dup %ld swap %ld frame %ld), %llu over the bound, "
           "%llu duplicates that cost a frame, %llu frames lost outside a fault window\n",
           truncs, checked, wrong, worst_single, period + 1, worst_kind[0],
           worst_kind[1], worst_kind[2], worst_kind[3], worst_kind[4], worst_kind[5],
           worst_kind[6], worst_kind[7], over_bound, dup_lost, unexplained);
    return wrong || over_bound || dup_lost || unexplained || worst_single > period + 1;
}
