/* r8kern.h - the hot inner loops, as kernels a port may replace with
 * assembly (ports/<cpu>/).  Each has a C89 reference in src/kern.c; a
 * build that links a port's version defines the kernel's R8_ASM_*
 * macro, and the port's simulator test shows the two equal on random
 * inputs (DEVELOPERS.md: assembly is the exception).
 *
 *   r8k_trap    fill the rows of a trapezoid between two column DDAs
 *               into an SSD1306 page band (R8_ASM_TRAP)
 *   r8k_xform   a model vertex (flash) into camera space (R8_ASM_XFORM)
 *   r8k_project a camera-space point to screen coordinates (R8_ASM_PROJECT)
 *   r8k_edge    an edge's column DDA for its first row (R8_ASM_EDGE)
 *   r8k_fill    n bytes set to one value: the band and depth clears
 *               (R8_ASM_FILL)
 *   r8k_cull    the 16-bit backface test of a face (R8_ASM_CULL)
 *   r8k_level   a face's Lambert dither level (R8_ASM_LEVEL)
 *   r8k_zsum    a face's painter's depth sum (R8_ASM_ZSUM)
 *   r8k_fwalk   an object's faces: cull, screen box, rows (R8_ASM_FWALK)
 *   r8k_vertex  a model vertex to its screen vertex (R8_ASM_VERTEX)
 *   r8k_depth   a vertex's depth from its reciprocal (R8_ASM_DEPTH)
 */
#ifndef R8KERN_H
#define R8KERN_H

#include "r8types.h"
#include "r8raster.h"
#include "r8fixed.h"
#include "r8scene.h"

/* Where a trapezoid fill writes: the current row's page in the band
 * (its column 0), the row's bit in the page byte, the row's dither
 * phase k (the pattern is pat[k], k = row & 3 as the caller counts),
 * and the frame width (spans are clamped to [0, w); the page stride). */
typedef struct r8_trapfill {
    r8_u8 *page;
    r8_u8 m;
    r8_u8 k;
    r8_u8 pat[4];
    r8_s16 w;
} r8_trapfill;

/* Fill `rows` rows: on each, columns [l->val, r->val) clamped to
 * [0, w), pattern pat[k] under bit m (0xFF sets, 0 clears, others mix
 * per column: bit 3 - (x & 3) of the pattern's low nibble, repeated
 * every 4 columns, as r8_fb_page_run; the dither rows carry the same
 * nibble in both halves); then both DDAs step (R8_INTERP_STEP), m moves
 * to the next row (and page), k to the next phase.  The state in t, l
 * and r is left for the next row. */
void r8k_trap(r8_trapfill *t, r8_interp *l, r8_interp *r, r8_u16 rows);

/* out = m * v + t in camera units: each row's three Q1.14 x s16 products
 * summed exactly (32 bits), plus 512, shifted right 10 with floor, plus
 * t.  v points at three r8_s16 in R8_FLASH (a mesh vertex). */
void r8k_xform(const r8_mat3 *m, const r8_vec3l *t, const r8_s16 *v, r8_vec3l *out);

/* out = m * d (transpose: m's transpose * d), each row's three Q1.14 x
 * r8_s32 products summed in 32 bits (wrapping), plus 512, shifted right
 * 10 with floor: r8_tf_frame's object offsets.  The Z80's kernel
 * (ports/z80/tframe_z80.s, R8_ASM_TFRAME); reference rot_offset in
 * src/r8tfref.h. */
void r8k_rotoff(const r8_mat3 *m, const r8_s32 *d, r8_vec3l *out, int transpose);

/* c (camera space, z >= 1) to 12.4 screen coordinates out[0], out[1]
 * through p, exactly as r8_project (r8fixed.h); *m, *e get the
 * reciprocal of c->z as r8_recip gives it (the depth is taken from it).
 * Returns 1, out[] unset, when c lies outside the guard band. */
int r8k_project(const r8_proj *p, const r8_vec3l *c, r8_s16 *out, r8_u16 *m, r8_s8 *e);

/* The column DDA of the edge from a to b (12.4 screen points x, y with
 * b[1] > a[1]) on its first row y0 = R8_ROW_OF(a[1]): it->val the
 * column of the first pixel centre at or right of the edge on row y0
 * (top-left rule: ceil((a[0] - 8 + (16 y0 + 8 - a[1]) (b[0] - a[0]) /
 * (b[1] - a[1])) / 16)), and it->q, r, den, err such that R8_INTERP_STEP
 * moves it exactly to the next row (den = b[1] - a[1]).  Returns y0; or
 * R8_EDGE_WIDE, *it unset, for an edge this 16-bit set-up does not take
 * (dy >= 1424 subpixels, a slope of 2048 columns per row or more, or an
 * x beyond +-1024 px): the caller then sets it up in 32 bits (scan.c). */
r8_s16 r8k_edge(r8_interp *it, const r8_s16 *a, const r8_s16 *b);
#define R8_EDGE_WIDE (-32767 - 1)

/* p[0..n-1] = v (memset; on AVR an unrolled store loop). */
void r8k_fill(r8_u8 *p, r8_u8 v, unsigned n);

/* R8_SDCC_FACE_KERN: r8k_cull, r8k_level and r8k_zsum are left unused
 * by the renderer under SDCC (the Z80 keeps the code they replace, as
 * at 38ee31d): SDCC 4.2 was seen to miscompile the C reference of
 * r8k_zsum inside the library (tests/c/test_kern.c), so those tests are
 * left out there too. */
/* r8_cull_front's 16-bit test (src/cull.c): -1 when a component of v
 * (three r8_s16 in R8_FLASH, the face's first vertex) lies outside
 * [-1023, 1023]; else 1 if n . (eye - 16 v) > 0, 0 if not, exactly (n
 * three Q1.14 r8_s16 in R8_FLASH, the unit face normal; eye's components
 * within +-16383, of which the low 16 bits are read). */
int r8k_cull(const r8_s16 *n, const r8_s16 *v, const r8_vec3l *eye);

/* The dither level of a face of normal n (three Q1.14 r8_s16 in
 * R8_FLASH) under `light` (components within +-16384) for brightness
 * colour and ambient amb in [0, 16384]: (r8_u8)((r8_tf_shade(n, light,
 * colour) + 128) >> 8) (src/cull.c) bit for bit, as (q colour + 8224) >>
 * 14, q = amb + (16384 - amb) i >> 14, i = n . light >> 14 (<= 16384). */
r8_u8 r8k_level(const r8_s16 *n, const r8_vec3 *light, r8_s16 amb, r8_u8 colour);

/* The model vertices verts[3 vi[k] ..] (R8_FLASH; vi in RAM, n >= 1)
 * summed per component: 0 when a sum lies outside [-32767, 32767];
 * else 1 and *out = floor((row . sums + 512) / 1024), exactly (row three
 * Q1.14 r8_s16: the camera-space z row of the object's matrix). */
int r8k_zsum(const r8_s16 *verts, const r8_u8 *vi, r8_u8 n, const r8_s16 *row, r8_s32 *out);

/* r8k_fwalk's painter's keys (r8_bucket_object; render.c's depth_key
 * with the object's constants taken once). */
typedef struct r8_fwpk {
    r8_s32 k[6];            /* for n = 3, then 4: zc = n (t.z - zn16),
                               zr = n (zf16 - zn16), kmul (r8_u32) */
    const r8_s16 *row;      /* r8k_zsum's row (RAM) */
    r8_u8 *ftop;            /* first band per face id, or 0 */
    r8_s8 fbsh;             /* its log2 band rows (>= 0 when ftop is set) */
} r8_fwpk;

/* r8k_fwalk's walk over one object's faces (r8_bucket_object). */
typedef struct r8_fwalk {
    const r8_s16 *base;     /* the object's screen vertices: vertex i at
                               base + (i << vsh); x, y in 12.4, or x
                               -32767 (R8_VX_TODO), -32768 (R8_VX_CLIP) */
    const r8_face *faces;   /* the mesh's faces (R8_FLASH) */
    const r8_s16 *normals;  /* the face normals for r8k_cull (R8_FLASH), or
                               0: no cull */
    const r8_s16 *verts;    /* the model vertices (R8_FLASH) */
    const r8_vec3l *eye;    /* r8k_cull's eye */
    r8_u16 f;               /* faces f - 1 down to 0 are left; the face
                               returned */
    r8_s16 w, h;            /* the frame */
    r8_s16 top, bot;        /* the rows of the face returned with 1 */
    r8_u8 vsh;              /* 1 or 2 */
    void *st;               /* r8_tf_vertex's state and object */
    const void *o;
    void *heads, *next;     /* the band buckets and links (r8_fid: r8_u8
                               with fid8, else r8_u16) */
    r8_u8 *slot;            /* pool slots per face id, or 0 */
    r8_u16 npoly;           /* faces put in a bucket */
    r8_u16 fbase;           /* the object's first face id */
    r8_s8 bsh;              /* log2 band rows; < 0: faces handed back */
    r8_u8 fid8;
    r8_u16 vbase;           /* the object's first vertex (r8_tf_vertex) */
    struct r8_fwpk *pk;     /* painter's (bsh < 0): 0, or the faces are
                               put in their depth buckets */
    void (*paint)(void);    /* AVR: r8k_fwpaint with pk, else 0 */
} r8_fwalk;

/* The next face of w (f - 1 down to 0; w->f = that face) that is to be
 * drawn: n = faces[f].n in [3, R8_MAX_FACE_VERTS]; with normals,
 * r8k_cull(normals + 3 f, verts + 3 v[0], eye) 1 (0: the face is
 * skipped); its vertices transformed (r8_tf_vertex(st, o, verts + 3 i,
 * vbase + i) for each whose x is -32767, in order); the rows [top, bot) = [R8_FLOOR16(ymin + 7),
 * R8_FLOOR16(ymax + 7)) of its vertices' box (16-bit wrapping sums) hold
 * a pixel centre of the frame (top < bot, bot > 0, top < h,
 * R8_FLOOR16(xmax + 7) > 0, R8_FLOOR16(xmin + 7) < w; else the face is
 * skipped).  With bsh >= 0 such a face is put in its band's bucket, as
 * r8_bucket_object does (id = fbase + f; next[id] = heads[key], heads[key]
 * = id, key = top >> bsh or 0 for top < 0; slot[id] = 0xFF; npoly + 1),
 * and the walk goes on; with bsh < 0 w->top, w->bot are set and, with pk,
 * when r8k_zsum(verts, vi, n, pk->row, &zs) gives 1 for the face's
 * vertex indices vi, it is put in its depth bucket (key =
 * 63 - min(63, k) for z = zs + zc in [0, zr), k = (r8_u16)(z kmul >> 16),
 * >> 2 more for n = 4; key 0 for z >= zr, z < 0 taken as 0; the constants
 * pk->k[0..2] for n = 3, k[3..5] for n = 4, arithmetic wrapping; then
 * ftop[id] = min(255, top >> fbsh, 0 for top < 0) when ftop is set, and
 * the links, slot and npoly as above) and the walk goes on; else it
 * returns 1 (painter's: the caller buckets it).  Returns 2 (R8_FW_OTHER) for
 * a face the caller takes itself (n out of range, r8k_cull -1, a vertex
 * whose x is -32768: at once, later vertices left as they are), 0 when no
 * face is left. */
r8_u8 r8k_fwalk(r8_fwalk *w);
#define R8_FW_OTHER 2
/* AVR: r8k_fwalk's painter's part (ports/avr/fwpaint.S, its own object:
 * builds without painter's leave it and r8k_zsum out); not to be called */
void r8k_fwpaint(void);
/* r8k_fwalk's call to transform a vertex (src/transform.c; r8int.h) */
struct r8_state;
struct r8_objx;
void r8_tf_vertex(struct r8_state *st, const struct r8_objx *o, const r8_s16 *mv, r8_u16 g);
/* r8k_fwalk's vertex call on AVR (fwalk.S): r8_tf_vertex(st, o, mv, g)
 * exactly; the kernel (ports/avr/vertex.S, R8_ASM_VERTEX) does the
 * vertices without Gouraud (vsh 1, or vsh 2 with the depth through
 * r8k_vdepth) with small model coordinates in one piece, and hands
 * every other case to r8_tf_vertex.  Reference: src/transform.c. */
void r8k_vertex(struct r8_state *st, const struct r8_objx *o, const r8_s16 *mv, r8_u16 g);
/* r8_tf_depth's arithmetic (src/transform.c): with p = m znm (32 bits),
 * w = 2^20 for sh <= 0, 0 for sh > 31, else min(2^20, (r8_u32)
 * r8_asr32(p, sh)); 0 when w <= wf, else ((w - wf) gh + 2^15) >> 16
 * (modulo 2^32).  AVR: vertex.S (R8_ASM_DEPTH); reference in
 * src/transform.c. */
r8_s16 r8k_depth(r8_u16 m, r8_u16 znm, r8_s16 sh, r8_u32 wf, r8_u32 gh);
/* AVR (vertex.S): out[2] of a vsh-2 vertex from its reciprocal m, e
 * (r8_tf_depth when st->attrs has R8_ATTR_D, else 0; src/transform.c) */
r8_s16 r8k_vdepth(const struct r8_state *st, r8_u16 m, r8_s8 e);

#endif
