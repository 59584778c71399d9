/* raycast.c - the ray caster (see r8ray.h and docs/visibility.md,
 * "Ray caster").
 *
 * Per frame, one ray per screen column, all integer:
 *  - the ray's direction D = 2f F + (2x + 1 - W) R (F forward, R right,
 *    Q1.14; f the focal length, x the column), a 32-bit sum stepped by
 *    2R from column to column, then scaled to 13 bits.  Its component
 *    along F is the same 2f for every column, so the distance the DDA
 *    measures along one axis, divided by that axis' component, is the
 *    PERPENDICULAR depth: no fisheye, no cosine per column;
 *  - a DDA over the grid (Amanatides-Woo, in Bresenham form): the next x
 *    boundary comes first iff ax / |Dx| < az / |Dz|, i.e. ax |Dz| < az |Dx|,
 *    two 32-bit sums stepped by one cell's worth; every cell the ray
 *    crosses is visited (no corner skipped), no division in the loop;
 *  - the wall's screen height h = (1 << shift) |D_axis| 2^(sh - 15) / a
 *    (the focal length cancels), 1/a from a 129-entry reciprocal table
 *    (a normalised to 8 bits, rounded) and one 16x16 multiply.
 * Per band, each column's byte of each SSD1306 page is ceiling, wall
 * and floor masks (from a 9-entry table) over the dither column pattern
 * of the wall's and the floor's levels. */
#include <stddef.h>
#include "r8ray.h"
#include "r8fixed.h"
#include "r8flash.h"

#ifndef R8_NO_RAY

/* Textured walls: left out with R8_NO_TEXTURE, unless R8_RAY_TEXTURE
 * asks for them alone (the textured maze's firmware: no mesh texture
 * mapping, ports/fwdefs.sh). */
#if !defined(R8_NO_TEXTURE) || defined(R8_RAY_TEXTURE)
#define RAY_TEX 1
#else
#define RAY_TEX 0
#endif

#define FLOOR_LEVEL 2
#define WALL_MIN 3       /* distance shading stops here: above the floor */
#define EDGE_LEVEL 16    /* the map's edge */

/* round(2^21 / m), m = 128..256 */
static const r8_u16 recip[129] R8_FLASH = {
    16384, 16257, 16132, 16009, 15888, 15768, 15650, 15534, 15420, 15308,
    15197, 15087, 14980, 14873, 14769, 14665, 14564, 14463, 14364, 14266,
    14170, 14075, 13981, 13888, 13797, 13707, 13618, 13530, 13443, 13358,
    13273, 13190, 13107, 13026, 12945, 12866, 12788, 12710, 12633, 12558,
    12483, 12409, 12336, 12264, 12193, 12122, 12053, 11984, 11916, 11848,
    11782, 11716, 11651, 11586, 11523, 11460, 11398, 11336, 11275, 11215,
    11155, 11096, 11038, 10980, 10923, 10866, 10810, 10755, 10700, 10645,
    10592, 10538, 10486, 10434, 10382, 10331, 10280, 10230, 10180, 10131,
    10082, 10034, 9986, 9939, 9892, 9846, 9800, 9754, 9709, 9664,
    9620, 9576, 9533, 9489, 9447, 9404, 9362, 9321, 9279, 9239,
    9198, 9158, 9118, 9079, 9039, 9001, 8962, 8924, 8886, 8849,
    8812, 8775, 8738, 8702, 8666, 8630, 8595, 8560, 8525, 8490,
    8456, 8422, 8389, 8355, 8322, 8289, 8257, 8224, 8192
};

/* colpat[4 s + (x & 3)]: the 8 rows of a page of column x at dither
 * level s (bit r lit iff s > bayer[r & 3][x & 3], as r8_fb_dot) */
static const r8_u8 colpat[17 * 4] R8_FLASH = {
    0x00, 0x00, 0x00, 0x00, 0x11, 0x00, 0x00, 0x00, 0x11, 0x00, 0x44, 0x00,
    0x11, 0x00, 0x55, 0x00, 0x55, 0x00, 0x55, 0x00, 0x55, 0x22, 0x55, 0x00,
    0x55, 0x22, 0x55, 0x88, 0x55, 0x22, 0x55, 0xAA, 0x55, 0xAA, 0x55, 0xAA,
    0x55, 0xBB, 0x55, 0xAA, 0x55, 0xBB, 0x55, 0xEE, 0x55, 0xBB, 0x55, 0xFF,
    0x55, 0xFF, 0x55, 0xFF, 0x77, 0xFF, 0x55, 0xFF, 0x77, 0xFF, 0xDD, 0xFF,
    0x77, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF
};

/* rows r..7 of a page: 0xFF << r */
static const r8_u8 from_row[9] R8_FLASH = {
    0xFF, 0xFE, 0xFC, 0xF8, 0xF0, 0xE0, 0xC0, 0x80, 0x00
};

typedef struct ray_state {
    const r8_grid *grid;
    r8_u8 *col;          /* per column: half height (pixels), level */
    r8_s16 width, height;
    r8_u8 shading, hb;   /* hb: full brightness from full = 1 << hb rows up */
    r8_u16 full;
    r8_u8 cap;           /* half heights stop here */
    r8_u8 tex;           /* textured: column records are tcol */
} ray_state;

#if RAY_TEX
/* A textured column: v is the wall's height fraction, 0.16 (65536 =
 * the texture's height), at the centre of screen row 0 (modulo 2^16:
 * only the wall's rows are read) and its step per row. */
typedef struct tcol {
    r8_u8 half, lv, tu, ti;  /* half height, level, texel column, texture */
    r8_u16 v0, vstep;
} tcol;
#define COL_BYTES(st) ((st)->tex ? (unsigned)sizeof(tcol) : 2u)
#else
#define COL_BYTES(st) 2u
#endif

/* One frame's rays: D of column 0 and its step, the scale, the camera. */
typedef struct ray_setup {
    r8_s32 dx, dz, stx, stz;
    r8_s16 px, pz;
    r8_u16 cell;         /* 1 << grid shift */
    r8_u8 sh;
    r8_s8 k;             /* h16 = |D_axis| 2^k / a */
} ray_setup;

int r8_grid_valid(const r8_grid *g)
{
    if (!g || !g->cells || g->w == 0 || g->h == 0 || g->shift < 2 || g->shift > 8)
        return 0;
    if (((r8_s32)g->w << g->shift) > 32767L || ((r8_s32)g->h << g->shift) > 32767L)
        return 0;
    return 1;
}

static void setup(const r8_grid *g, const r8_camera *cam, r8_s16 width, ray_setup *s)
{
    r8_s16 sn = r8_sin(cam->yaw), cs = r8_cos(cam->yaw);
    r8_s16 f2 = (r8_s16)(2 * cam->focal), u = (r8_s16)(1 - width);
    r8_s16 n = (r8_s16)(f2 + width);
    r8_u8 b = 0;
    /* forward F = (sin, cos), right R = (cos, -sin) in (x, z) */
    s->dx = r8_mul16(f2, sn) + r8_mul16(u, cs);
    s->dz = r8_mul16(f2, cs) - r8_mul16(u, sn);
    /* (no 2L * cs: SDCC 4.2 miscompiles long products of 16-bit values) */
    s->stx = (r8_s32)cs + cs;
    s->stz = -((r8_s32)sn + sn);
    while (n) {
        n >>= 1;
        b++;
    }
    /* |D| <= n 2^14 < 2^(b + 14): 13 bits after >> (b + 1) */
    s->sh = (r8_u8)(b + 1);
    s->k = (r8_s8)(g->shift + s->sh - 11);
    /* no run-time 1u << n: cc65 2.19 (DEVELOPERS.md) */
    s->cell = 1;
    for (b = 0; b < g->shift; b++)
        s->cell = (r8_u16)(s->cell + s->cell);
    s->px = cam->x;
    s->pz = cam->z;
}

/* 16 times the screen height of a wall block at distance a along the
 * axis whose direction component is ad: ad 2^k / a */
static r8_u16 height16(r8_u16 a, r8_s16 ad, r8_s8 k)
{
    r8_u16 m = a, t = a;
    int e = 0, sft;
    r8_s32 p;
    if (a == 0)
        return 0xFFFFu;
    while (t >= 256u) {
        t >>= 1;
        e++;
    }
    if (e > 0) {
        m = (r8_u16)(((a >> (e - 1)) + 1u) >> 1);   /* rounded: 128..256 */
    } else {
        while (m < 128u) {
            m <<= 1;
            e--;
        }
    }
    p = r8_mul16(ad, (r8_s16)R8_RDU16(&recip[m - 128u]));
    sft = 21 + e - k;
    if (sft > 31)
        return 0;
    if (sft > 0) {
        p = ((p >> (sft - 1)) + 1) >> 1;
    } else {
        while (sft < 0) {
            if (p > 0x7FFFL)
                return 0xFFFFu;
            p <<= 1;
            sft++;
        }
    }
    if (p > 0xFFFFL)
        return 0xFFFFu;
    return (r8_u16)p;
}

/* The DDA for one ray of direction (dx, dz). */
#if RAY_TEX
#define CAST(g, s, dx, dz, hit, want_u) cast(g, s, dx, dz, hit, want_u)
static void cast(const r8_grid *g, const ray_setup *s, r8_s32 dx, r8_s32 dz, r8_ray_hit *hit,
                 r8_u8 want_u)
#else
/* (without textures: no u, and no argument for it: the 6502 pays for each) */
#define CAST(g, s, dx, dz, hit, want_u) cast(g, s, dx, dz, hit)
static void cast(const r8_grid *g, const ray_setup *s, r8_s32 dx, r8_s32 dz, r8_ray_hit *hit)
#endif
{
    const r8_u8 *cells = g->cells;
    r8_u8 shift = g->shift, w = g->w, h = g->h;
    r8_u16 cell = s->cell, fmask = (r8_u16)(cell - 1u);
    r8_s16 adx, adz, cx, cz, sx, sz;
    r8_u16 ax, az, a = 0;
    r8_s32 ex, ez, ix, iz;
    unsigned idx, rowstep;
    r8_u8 side = 0, v = 0;
    hit->h16 = 0;
    hit->side = 0;
#if RAY_TEX
    hit->u = 0;
#endif
    hit->cell = 0;
    hit->cx = hit->cz = 0;
    if (s->px < 0 || s->pz < 0)
        return;
    cx = (r8_s16)(s->px >> shift);
    cz = (r8_s16)(s->pz >> shift);
    if (cx >= (r8_s16)w || cz >= (r8_s16)h)
        return;                       /* off the map: no walls */
    sx = 1;
    if (dx < 0) {
        dx = -dx;
        sx = -1;
    }
    sz = 1;
    rowstep = w;
    if (dz < 0) {
        dz = -dz;
        sz = -1;
    }
    adx = (r8_s16)(dx >> s->sh);
    adz = (r8_s16)(dz >> s->sh);
    /* world-unit distances to the first boundaries along each axis */
    ax = (r8_u16)((r8_u16)s->px & fmask);
    if (sx > 0)
        ax = (r8_u16)(cell - ax);
    az = (r8_u16)((r8_u16)s->pz & fmask);
    if (sz > 0)
        az = (r8_u16)(cell - az);
    /* x first iff ax / adx < az / adz: compare ax adz with az adx */
    ex = 0x7FFFFFFFL;
    ix = 0;
    if (adx) {
        ex = r8_mul16((r8_s16)ax, adz);
        ix = (r8_s32)adz << shift;
    }
    ez = 0x7FFFFFFFL;
    iz = 0;
    if (adz) {
        ez = r8_mul16((r8_s16)az, adx);
        iz = (r8_s32)adx << shift;
    }
    idx = (unsigned)cz * w + (unsigned)cx;
    for (;;) {
        if (ex < ez) {
            a = ax;
            ax = (r8_u16)(ax + cell);
            ex += ix;
            side = 0;
            cx = (r8_s16)(cx + sx);
            if ((r8_u16)cx >= w) {
                v = EDGE_LEVEL;
                break;
            }
            if (sx > 0)
                idx++;
            else
                idx--;
        } else {
            a = az;
            az = (r8_u16)(az + cell);
            ez += iz;
            side = 1;
            cz = (r8_s16)(cz + sz);
            if ((r8_u16)cz >= h) {
                v = EDGE_LEVEL;
                break;
            }
            if (sz > 0)
                idx += rowstep;
            else
                idx -= rowstep;
        }
        v = R8_RDU8(&cells[idx]);
        if (v)
            break;
    }
    hit->side = side;
    hit->cell = v;
    hit->cx = (r8_u8)cx;
    hit->cz = (r8_u8)cz;
    hit->h16 = height16(a, side ? adz : adx, s->k);
#if RAY_TEX
    if (want_u) {
        /* Where on the face: the DDA's own fraction.  Crossing an x
         * boundary at "time" exh = ex - ix (in units of 1 / (adx adz)),
         * the z distance left to the next z boundary is (ez - exh) / adx
         * world units, i.e. (ez - exh) / iz of a cell (likewise for z);
         * an axis the ray does not move along: its start distance over
         * the cell.  8 bits of it by shift and subtract, then mirrored
         * so the face reads left to right from outside. */
        r8_s32 num, den;
        r8_u8 q = 0, i, flip;
        if (side == 0) {
            num = ez - (ex - ix);
            den = iz;
            if (!adz) {
                num = az;
                den = cell;
            }
            flip = (r8_u8)((sx > 0) != (sz > 0));
        } else {
            num = ex - (ez - iz);
            den = ix;
            if (!adx) {
                num = ax;
                den = cell;
            }
            flip = (r8_u8)((sx > 0) == (sz > 0));
        }
        if (num >= den) {
            q = 255;
        } else {
            for (i = 0; i < 8; i++) {
                num += num;
                q = (r8_u8)(q + q);
                if (num >= den) {
                    num -= den;
                    q++;
                }
            }
        }
        hit->u = flip ? (r8_u8)(255u - q) : q;
    }
#endif
}

int r8_ray_cast(const r8_grid *g, const r8_camera *cam, r8_s16 width, r8_s16 x,
                r8_ray_hit *hit)
{
    ray_setup s;
    r8_s16 u;
    if (!r8_grid_valid(g) || !cam || cam->focal < 1 || cam->focal > 2047 ||
        width < 1 || width > 1024 || x < 0 || x >= width)
        return -1;
    setup(g, cam, width, &s);
    u = (r8_s16)(2 * x);
#if !RAY_TEX
    hit->u = 0;
#endif
    CAST(g, &s, s.dx + r8_mul16(u, r8_cos(cam->yaw)), s.dz - r8_mul16(u, r8_sin(cam->yaw)), hit, 1);
    return 0;
}

/* Does cfg draw textures (R8_SHADE_TEXTURE and a grid with them)?  1, 0,
 * or -1 for bad textures. */
static int textured(const r8_render_cfg *cfg)
{
#if RAY_TEX
    const r8_grid *g = cfg->scene->grid;
    r8_u8 i;
    if (cfg->shading != R8_SHADE_TEXTURE || !g->tex)
        return 0;
    if (g->ntex < 1 || g->ntex > 16)
        return -1;
    for (i = 0; i < g->ntex; i++) {
        const r8_texture *t = &g->tex[i];
        if (!t->data || t->wlog < 3 || t->wlog > 6 || t->hlog < 3 || t->hlog > 6 ||
            t->format > R8_TEX_IDX8)
            return -1;
    }
    return 1;
#else
    (void)cfg;
    return 0;
#endif
}

static int cfg_ok(const r8_render_cfg *cfg)
{
    const r8_scene *sc = cfg->scene;
    if (!sc || !r8_grid_valid(sc->grid) || cfg->method != R8_VIS_RAY)
        return 0;
#if RAY_TEX
    if (cfg->shading == R8_SHADE_TEXTURE) {
        if (textured(cfg) < 0)
            return 0;
    } else
#endif
    if (cfg->shading > R8_SHADE_LAMBERT)
        return 0;
    if (cfg->format > R8_FMT_IDX8)
        return 0;
    if (cfg->width < 8 || cfg->width > 1024 || cfg->height < 8 || cfg->height > 255)
        return 0;
    if (cfg->band < 1 || cfg->band > cfg->height)
        return 0;
    if (cfg->format == R8_FMT_PAGE1 && ((cfg->band & 7) || (cfg->height & 7)))
        return 0;
    return 1;
}

#define STATE_BYTES ((sizeof(ray_state) + 7u) & ~7u)

unsigned r8_ray_ram(const r8_render_cfg *cfg)
{
    if (!cfg_ok(cfg))
        return 0;
#if RAY_TEX
    if (textured(cfg))
        return (unsigned)(STATE_BYTES + 8u + sizeof(tcol) * (unsigned)cfg->width);
#endif
    return (unsigned)(STATE_BYTES + 8u + 2u * (unsigned)cfg->width);
}

int r8_ray_init(r8_render *r, const r8_render_cfg *cfg, r8_u8 *work, unsigned work_size)
{
    ray_state *st;
    r8_u8 *base;
    r8_s16 hh;
    if (!cfg_ok(cfg))
        return -1;
    if (work_size < r8_ray_ram(cfg))
        return -2;
    base = work + ((8u - ((unsigned)((size_t)(void *)work & 7u))) & 7u);
    st = (ray_state *)(void *)base;
    r->cfg = *cfg;
    r->work = work;
    r->work_size = work_size;
    r->state = st;
    st->grid = cfg->scene->grid;
    st->col = base + STATE_BYTES;
    st->width = cfg->width;
    st->height = cfg->height;
    st->shading = cfg->shading;
    st->hb = 0;
    st->full = 1;
    for (hh = cfg->height; hh > 1; hh >>= 1) {
        st->hb++;
        st->full = (r8_u16)(st->full + st->full);
    }
    st->cap = (r8_u8)(cfg->height >> 1);   /* top = height / 2 - half >= 0 */
    st->tex = (r8_u8)textured(cfg);
    {
        unsigned n = COL_BYTES(st) * (unsigned)cfg->width, i;
        for (i = 0; i < n; i++)
            st->col[i] = 0;
    }
    return 0;
}

#if RAY_TEX
/* v's step per screen row for a wall h16 / 16 pixels tall: 2^20 / h16
 * (0.16 of the wall), from the reciprocal table of the heights (h16 to
 * 8 bits, rounded) */
static r8_u16 vstep_of(r8_u16 h)
{
    r8_u16 m = h, t = h;
    r8_u32 p;
    int e = 0;
    if (h <= 16u)
        return 0xFFFFu;
    while (t >= 256u) {
        t >>= 1;
        e++;
    }
    if (e > 0) {
        m = (r8_u16)(((h >> (e - 1)) + 1u) >> 1);
    } else {
        while (m < 128u) {
            m <<= 1;
            e--;
        }
    }
    p = R8_RDU16(&recip[m - 128u]);     /* 2^21 / m; the result p 2^-(1 + e) */
    if (e >= 0) {
        p = ((p >> e) + 1u) >> 1;
    } else {
        for (; e < -1; e++)
            p <<= 1;
    }
    return p > 0xFFFFul ? 0xFFFFu : (r8_u16)p;
}
#endif

void r8_ray_frame(r8_render *r, const r8_camera *cam)
{
    ray_state *st = (ray_state *)r->state;
    ray_setup s;
    r8_ray_hit hit;
    r8_s32 dx, dz;
    r8_s16 x;
    r8_u8 *c = st->col;
#if RAY_TEX
    const r8_grid *g = st->grid;
    r8_s16 cy2 = (r8_s16)(2 * (st->height >> 1) - 1);
#endif
    setup(st->grid, cam, st->width, &s);
    dx = s.dx;
    dz = s.dz;
    for (x = 0; x < st->width; x++) {
        r8_u16 half;
        r8_u8 lv;
        CAST(st->grid, &s, dx, dz, &hit, st->tex);
        dx += s.stx;
        dz += s.stz;
        half = (r8_u16)((hit.h16 >> 5) + ((hit.h16 >> 4) & 1u));   /* h / 2, rounded */
        if (half > st->cap)
            half = st->cap;
        lv = hit.cell > 16 ? 16 : hit.cell;
        if (hit.side)
            lv = (r8_u8)(lv - (lv >> 2));
        if (st->shading != R8_SHADE_FLAT && half) {   /* Lambert, texture */
            r8_u16 hp = (r8_u16)(hit.h16 >> 4);
            if (hp > st->full)
                hp = st->full;
            lv = (r8_u8)(((r8_u16)lv * hp) >> st->hb);
            if (lv < WALL_MIN)
                lv = WALL_MIN;
        }
#if RAY_TEX
        if (st->tex) {
            tcol *tc = (tcol *)(void *)c;
            const r8_texture *t;
            r8_s32 p;
            tc->half = (r8_u8)half;
            tc->lv = lv;
            tc->ti = (r8_u8)(hit.cell ? (r8_u8)(hit.cell - 1u) % g->ntex : 0);
            t = &g->tex[tc->ti];
            tc->tu = (r8_u8)(hit.u >> (8 - t->wlog));
            tc->vstep = vstep_of(hit.h16);
            /* v at the centre of row 0: the wall's middle (v = 1/2) is at
             * the screen's (the eye's height), row 0's centre cy - 1/2
             * rows above it; so only the step's error counts, times the
             * rows from the middle (at most cy), and a wall taller than
             * the screen starts inside its texture */
            p = cy2;
            p *= (r8_s32)tc->vstep;
            tc->v0 = (r8_u16)(0x8000u - (r8_u16)(p >> 1));
            c += sizeof(tcol);
            continue;
        }
#endif
        c[0] = (r8_u8)half;
        c[1] = lv;
        c += 2;
    }
}

#if RAY_TEX
/* The level of the texel of column c at v: the texel (0..255) times the
 * column's level, as texture.c */
static r8_u8 texel_level(const r8_texture *t, const tcol *c, r8_u8 tv)
{
    r8_u16 tl;
    if (t->format == R8_TEX_IDX8) {
        tl = R8_RDU8(t->data + ((r8_u16)tv << t->wlog) + c->tu);
        return (r8_u8)(((tl + (tl >> 7)) * c->lv + 128u) >> 8);
    }
    if (R8_RDU8(t->data + ((r8_u16)tv << (t->wlog - 3)) + (c->tu >> 3)) & (0x80u >> (c->tu & 7u)))
        return c->lv;
    return 0;
}

/* The texel row of v (0.16 of the wall) in a texture 2^(8 - s8) rows
 * tall: v's high byte >> s8 (an 8-bit shift); on the wall's last row
 * (last), v rounded past the bottom (wrapped below 1/2) is the bottom
 * row, hm.  Below 2^(8 - s8) whatever v: no read outside the texture. */
#define TEXROW(v, s8, hm, last) ((r8_u8)((last) && !((v) & 0x8000u) ? (hm) : \
                                         (r8_u8)((v) >> 8) >> (s8)))

static void band_tex(ray_state *st, r8_fb *fb, r8_s16 y0, r8_s16 y1)
{
    const r8_texture *tex = st->grid->tex;
    r8_s16 x, y, w = st->width, cy = (r8_s16)(st->height >> 1);
    const tcol *c = (const tcol *)(const void *)st->col;
    if (fb->format == R8_FMT_PAGE1) {
        /* as the flat band below, the wall's part of each byte texel by
         * texel: a 1 bpp texture gives the mask of its lit texels over
         * the column's dither pattern, an IDX8 one a level per pixel */
        r8_u8 *row = fb->buf, cy8 = (r8_u8)cy;
        for (y = y0; y < y1; y = (r8_s16)(y + 8), row += w) {
            r8_u8 *p = row, yt = (r8_u8)y, yb = (r8_u8)(y + 8), ph = 0;
            c = (const tcol *)(const void *)st->col;
            for (x = 0; x < w; x++, c++, p++, ph = (r8_u8)((ph + 1u) & 3u)) {
                r8_u8 top = (r8_u8)(cy8 - c->half), bot = (r8_u8)(cy8 + c->half);
                r8_u8 ra, rb, bit, last, s8, hm, out = 0, fm = 0;
                const r8_texture *t;
                r8_u16 v, vs;
                if (bot <= yt) {
                    *p = R8_RDU8(&colpat[(FLOOR_LEVEL << 2) | ph]);
                    continue;
                }
                if (top >= yb) {
                    *p = 0;                   /* ceiling */
                    continue;
                }
                ra = top > yt ? (r8_u8)(top - yt) : 0;
                rb = 8;
                if (bot < yb) {
                    rb = (r8_u8)(bot - yt);
                    fm = R8_RDU8(&from_row[rb]);
                }
                t = &tex[c->ti];
                s8 = (r8_u8)(8 - t->hlog);
                hm = (r8_u8)(0xFFu >> s8);
                vs = c->vstep;
                v = (r8_u16)(c->v0 + (r8_u16)((r8_u16)(yt + ra) * vs));
                if (top >= yt && (v & 0x8000u))
                    v = 0;            /* the top row: v rounded below 0 */
                last = (r8_u8)(bot <= yb ? rb - 1u : 8u);
                bit = (r8_u8)(R8_RDU8(&from_row[ra]) & (r8_u8)~R8_RDU8(&from_row[ra + 1u]));
                if (t->format == R8_TEX_IDX8) {
                    for (; ra < rb; ra++, bit = (r8_u8)(bit << 1), v = (r8_u16)(v + vs)) {
                        r8_u8 tv = TEXROW(v, s8, hm, ra == last);
                        out = (r8_u8)(out | (R8_RDU8(&colpat[((unsigned)texel_level(t, c, tv) << 2) | ph]) & bit));
                    }
                } else {
                    const r8_u8 *d = t->data + (c->tu >> 3);
                    r8_u8 rs = (r8_u8)(t->wlog - 3), tb = (r8_u8)(0x80u >> (c->tu & 7u));
                    for (; ra < rb; ra++, bit = (r8_u8)(bit << 1), v = (r8_u16)(v + vs)) {
                        r8_u8 tv = TEXROW(v, s8, hm, ra == last);
                        if (R8_RDU8(d + ((unsigned)tv << rs)) & tb)
                            out = (r8_u8)(out | bit);
                    }
                    out = (r8_u8)(out & R8_RDU8(&colpat[((unsigned)c->lv << 2) | ph]));
                }
                if (fm)
                    out = (r8_u8)(out | (R8_RDU8(&colpat[(FLOOR_LEVEL << 2) | ph]) & fm));
                *p = out;
            }
        }
        return;
    }
    for (x = 0; x < w; x++, c++) {
        r8_s16 t = (r8_s16)(cy - c->half), b = (r8_s16)(cy + c->half);
        r8_u16 v = (r8_u16)(c->v0 + (r8_u16)((r8_u16)y0 * c->vstep));
        for (y = y0; y < y1; y++, v = (r8_u16)(v + c->vstep)) {
            r8_u8 sh = 0;
            if (y >= b) {
                sh = FLOOR_LEVEL;
            } else if (y >= t) {
                const r8_texture *tx = &tex[c->ti];
                r8_u16 vv = v;        /* the end rows: v rounded out of the texture */
                if (y == t && (vv & 0x8000u))
                    vv = 0;
                sh = texel_level(tx, c, TEXROW(vv, (r8_u8)(8 - tx->hlog), (r8_u8)(0xFFu >> (8 - tx->hlog)), y == b - 1));
            }
            r8_fb_dot(fb, x, y, sh, 0);
        }
    }
}
#endif

void r8_ray_band(r8_render *r, r8_fb *fb)
{
    ray_state *st = (ray_state *)r->state;
    r8_s16 y0 = fb->y0, y1 = (r8_s16)(fb->y0 + fb->rows), cy = (r8_s16)(st->height >> 1);
    r8_s16 x, y, w = st->width;
    const r8_u8 *c;
    if (y1 > fb->height)
        y1 = fb->height;
#if RAY_TEX
    if (st->tex) {
        band_tex(st, fb, y0, y1);
        return;
    }
#endif
    if (fb->format == R8_FMT_PAGE1) {
        /* rows are bytes here (height <= 255): each column's page byte is
         * ceiling, wall or floor whole (the common case), or masks of two
         * of them from the 9-entry table */
        r8_u8 *row = fb->buf, cy8 = (r8_u8)cy;
        for (y = y0; y < y1; y = (r8_s16)(y + 8), row += w) {
            r8_u8 *p = row, yt = (r8_u8)y, yb = (r8_u8)(y + 8), ph = 0;
            c = st->col;
            for (x = 0; x < w; x++, c += 2, p++, ph = (r8_u8)((ph + 1u) & 3u)) {
                r8_u8 top = (r8_u8)(cy8 - c[0]), bot = (r8_u8)(cy8 + c[0]), wm, fm;
                if (bot <= yt) {
                    *p = R8_RDU8(&colpat[(FLOOR_LEVEL << 2) | ph]);
                    continue;
                }
                if (top >= yb) {
                    *p = 0;                   /* ceiling */
                    continue;
                }
                if (top <= yt && bot >= yb) {
                    *p = R8_RDU8(&colpat[((unsigned)c[1] << 2) | ph]);
                    continue;
                }
                fm = 0;
                if (bot < yb)
                    fm = R8_RDU8(&from_row[(r8_u8)(bot - yt)]);
                wm = (r8_u8)~fm;
                if (top > yt)
                    wm = (r8_u8)(wm & R8_RDU8(&from_row[(r8_u8)(top - yt)]));
                *p = (r8_u8)((R8_RDU8(&colpat[((unsigned)c[1] << 2) | ph]) & wm) |
                             (R8_RDU8(&colpat[(FLOOR_LEVEL << 2) | ph]) & fm));
            }
        }
        return;
    }
    /* other formats: a pixel at a time */
    c = st->col;
    for (x = 0; x < w; x++, c += 2) {
        r8_s16 t = (r8_s16)(cy - c[0]), b = (r8_s16)(cy + c[0]);
        for (y = y0; y < y1; y++) {
            r8_u8 s = 0;
            if (y >= b)
                s = FLOOR_LEVEL;
            else if (y >= t)
                s = c[1];
            r8_fb_dot(fb, x, y, s, 0);
        }
    }
}

#else
typedef int r8_ray_left_out;   /* ISO C: a translation unit is not empty */
#endif
