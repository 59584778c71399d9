/* r8codec.h - the band payload codecs: the seed's RLE and LZ77, and
 * (docs/protocol.md sections 3.4, 3.5) static Huffman and LZW.
 *
 * All functions work on caller buffers with explicit sizes and never
 * write past the size given.  They return R8_OK (0) or a negative
 * R8_E_* code; the number of bytes produced goes to *out_len.
 *
 * RLE (seed, "RLE Compression"): a count byte c;
 *   c & 0x80: (c & 0x7F) raw bytes follow (1..127);
 *   else:     the next byte repeats c times (1..127).
 *   Counts 0x00 and 0x80 are malformed.  The encoder codes runs of 3
 *   or more as repeats, merges shorter ones into raw runs and splits
 *   long runs at 127.  Worst case R8_RLE_BOUND(n) = n + ceil(n / 127).
 *
 * LZ77 (seed, "LZ77 Compression"): 16-bit signed big-endian words.
 *   w > 0:  w literal bytes follow (1..32767);
 *   w < 0:  copy from -w bytes back (1..32768), the next big-endian
 *           16-bit word is the length (1..65535); the copy may overlap
 *           its own output (length > distance repeats a pattern).
 *   w == 0 is malformed.  The window is the data already decoded in
 *   the same buffer (one band), capped at R8_LZ77_WINDOW bytes back;
 *   the encoder needs no memory beyond its input and output, the
 *   decoder none beyond its output.  Worst case R8_LZ77_BOUND(n).
 *
 * HUFF (docs/protocol.md 3.4): each byte's code from one static
 *   canonical Huffman table (src/huff_tab.h, 1..12 bits, tuned by
 *   tools/huff_tune.py on the built-in scenes' bands), MSB first; the
 *   last byte is padded with 1 bits (0..7).  No memory but the buffers;
 *   the tables are 1 KB of flash.  Worst case R8_HUFF_BOUND(n).
 *
 * LZW (docs/protocol.md 3.5): 9-bit codes, MSB first, padded with 0
 *   bits; 0..255 a byte, 256 + d dictionary entry d (d < R8_LZW_DICT =
 *   128, then the dictionary is frozen).  Entry d is phrase d followed
 *   by the first byte of phrase d + 1.  Encoder and decoder keep the
 *   dictionary as the phrases' lengths: R8_LZW_DICT bytes on the stack,
 *   the strings being in the band itself.  Worst case R8_LZW_BOUND(n).
 *
 * -DR8_NO_HUFF / -DR8_NO_LZW leave a codec out (the dispatch and the
 * wire encoder then answer R8_E_ARG for it).
 */
#ifndef R8CODEC_H
#define R8CODEC_H

#include "r8types.h"

#define R8_OK 0
#define R8_E_SPACE (-1)     /* output buffer too small */
#define R8_E_MALFORMED (-2) /* bad count/offset/length in the input */
#define R8_E_TRUNC (-3)     /* input ends inside a run or word */
#define R8_E_ARG (-4)       /* bad argument (size, format, ...) */

/* Codec ids (also the wire's codec byte). */
#define R8_CODEC_RAW 0
#define R8_CODEC_RLE 1
#define R8_CODEC_LZ77 2
#define R8_CODEC_HUFF 3
#define R8_CODEC_LZW 4
#define R8_CODEC_COUNT 5
/* Not a wire id: r8_tx_cfg.codec asking the encoder to send each band
 * with whichever built-in codec makes it smallest (docs/protocol.md 3.6). */
#define R8_CODEC_BEST 0x0F

#define R8_RLE_MAX 127
#define R8_RLE_BOUND(n) ((unsigned)(n) + ((unsigned)(n) + 126u) / 127u)

/* Search window of the LZ77 encoder (bytes back).  The format allows
 * 32768; a smaller window keeps the brute-force search fast on 8-bit
 * CPUs.  Override with -DR8_LZ77_WINDOW=N. */
#ifndef R8_LZ77_WINDOW
#define R8_LZ77_WINDOW 1024
#endif
#define R8_LZ77_MIN_MATCH 5
#define R8_LZ77_BOUND(n) ((unsigned)(n) + 2u * (((unsigned)(n) + 32766u) / 32767u))

#define R8_HUFF_MAXLEN 12
/* 12 bits a byte at worst: n + n/2, rounded up (no overflow for n < 43690) */
#define R8_HUFF_BOUND(n) ((unsigned)(n) + ((unsigned)(n) + 1u) / 2u)
#define R8_LZW_DICT 128
#define R8_LZW_BITS 9
#define R8_LZW_BOUND(n) ((unsigned)(n) + ((unsigned)(n) + 7u) / 8u)

/* Name <-> id ("raw", "rle", "lz77", "huff", "lzw"; by name also "best"
 * -> R8_CODEC_BEST); -1 / 0 when unknown. */
int r8_codec_by_name(const char *name);
const char *r8_codec_name(r8_u8 codec);

int r8_rle_encode(const r8_u8 *src, unsigned n, r8_u8 *dst, unsigned cap,
                  unsigned *out_len);
int r8_rle_decode(const r8_u8 *src, unsigned n, r8_u8 *dst, unsigned cap,
                  unsigned *out_len);

int r8_lz77_encode(const r8_u8 *src, unsigned n, r8_u8 *dst, unsigned cap,
                   unsigned *out_len);
int r8_lz77_decode(const r8_u8 *src, unsigned n, r8_u8 *dst, unsigned cap,
                   unsigned *out_len);

int r8_huff_encode(const r8_u8 *src, unsigned n, r8_u8 *dst, unsigned cap,
                   unsigned *out_len);
int r8_huff_decode(const r8_u8 *src, unsigned n, r8_u8 *dst, unsigned cap,
                   unsigned *out_len);

int r8_lzw_encode(const r8_u8 *src, unsigned n, r8_u8 *dst, unsigned cap,
                  unsigned *out_len);
int r8_lzw_decode(const r8_u8 *src, unsigned n, r8_u8 *dst, unsigned cap,
                  unsigned *out_len);

/* Dispatch on a codec id (R8_CODEC_RAW copies). */
int r8_codec_encode(r8_u8 codec, const r8_u8 *src, unsigned n, r8_u8 *dst,
                    unsigned cap, unsigned *out_len);
int r8_codec_decode(r8_u8 codec, const r8_u8 *src, unsigned n, r8_u8 *dst,
                    unsigned cap, unsigned *out_len);

#endif
