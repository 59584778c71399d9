/* analyse.c - model no more than a scene needs.  The analyser looks at a
 * scene's meshes and objects and picks the cheapest visibility method
 * that is exact for it:
 *   one convex mesh                      -> cull only (no depth memory)
 *   convex objects apart in depth, whose
 *   painter's buckets cannot interleave  -> painter's (jeffsort)
 *   anything else (concave meshes,
 *   interpenetration, overlap in depth)  -> 16-bit z-buffer
 * then the largest band height that fits the RAM budget, and reports the
 * depth range and coordinate width that set the fixed-point scale. */
#include "r8int.h"

/* The same depth mapping as r8_render_init, for a z range. */
static void depth_consts(const r8_scene *sc, r8_s32 *zn, r8_s32 *zf, r8_s32 *c1, r8_s32 *c2)
{
    r8_u8 i;
    *zn = 0x7FFFFFFFL;
    *zf = 1;
    for (i = 0; i < sc->nobjects; i++) {
        const r8_object *ob = &sc->objects[i];
        r8_s32 a = (r8_s32)ob->z - ob->mesh->radius, b = (r8_s32)ob->z + ob->mesh->radius;
        if (a < *zn) *zn = a;
        if (b > *zf) *zf = b;
    }
    if (*zn < sc->znear)
        *zn = sc->znear;
    if (*zf <= *zn)
        *zf = *zn + 1;
    *c2 = r8_muldiv(32767L, *zn, *zf - *zn);
    *c1 = r8_muldiv(*c2, *zf, 1);
}

static r8_s32 bucket(r8_s32 c1, r8_s32 c2, r8_s32 z)
{
    r8_s32 d;
    if (z < 1)
        z = 1;
    d = c1 / z - c2;
    if (d < 0) d = 0;
    if (d > 32767) d = 32767;
    return d >> 9;
}

/* Painter's is exact when every object is convex and, taken in depth
 * order, each object's farthest point lands in a nearer bucket than the
 * next object's nearest point. */
static int sortable(const r8_scene *sc, r8_s32 c1, r8_s32 c2)
{
    r8_u8 i, j;
    for (i = 0; i < sc->nobjects; i++)
        if (!sc->objects[i].mesh->convex)
            return 0;
    for (i = 0; i < sc->nobjects; i++)
        for (j = 0; j < sc->nobjects; j++) {
            const r8_object *a = &sc->objects[i], *b = &sc->objects[j];
            r8_s32 afar, bnear;
            if (i == j || a->z > b->z)
                continue;                 /* a is the nearer one */
            afar = (r8_s32)a->z + a->mesh->radius;
            bnear = (r8_s32)b->z - b->mesh->radius;
            if (afar >= bnear || bucket(c1, c2, afar) <= bucket(c1, c2, bnear))
                return 0;
        }
    return 1;
}

static unsigned need(r8_render_cfg *cfg)
{
    unsigned r = r8_render_ram(cfg);
    return r ? r + r8_fb_bytes(cfg->format, cfg->width, cfg->band) : 0;
}

/* Largest band that fits: the whole frame, else the largest multiple of
 * the method's row unit.  Returns 0 if none. */
static r8_s16 fit_band(r8_render_cfg *cfg, unsigned budget)
{
    r8_s16 unit = 1, h;
    if (cfg->format == R8_FMT_PAGE1)
        unit = 8;
    else if (cfg->method == R8_VIS_BLOCK || cfg->method == R8_VIS_BLOCKMASK)
        unit = 4;
    for (h = (r8_s16)(cfg->height - cfg->height % unit); h >= unit; h = (r8_s16)(h - unit)) {
        unsigned n;
        cfg->band = h;
        n = need(cfg);
        if (n && n <= budget)
            return h;
    }
    return 0;
}

int r8_analyse(r8_render_cfg *cfg, unsigned budget, r8_analysis *a)
{
    static const r8_u8 fallback[] = {
        R8_VIS_Z16, R8_VIS_SBUF, R8_VIS_Z8, R8_VIS_BLOCKMASK, R8_VIS_BLOCK
    };
    const r8_scene *sc = r8_render_scene(cfg);
    r8_s32 zn, zf, c1, c2, m = 0;
    r8_s16 given = cfg->band;
    r8_u8 i, exact_method;
    if (!sc)
        return -1;
    depth_consts(sc, &zn, &zf, &c1, &c2);
    a->znear = zn;
    a->zfar = zf;
    for (i = 0; i < sc->nobjects; i++) {
        const r8_object *ob = &sc->objects[i];
        r8_s32 e = ob->mesh->radius;
        e += ob->x < 0 ? -(r8_s32)ob->x : ob->x;
        e += ob->y < 0 ? -(r8_s32)ob->y : ob->y;
        e += ob->z < 0 ? -(r8_s32)ob->z : ob->z;
        if (e > m)
            m = e;
    }
    a->coord_bits = 1;
    while (m > 0) {
        a->coord_bits++;
        m >>= 1;
    }
    if (sc->nobjects == 1 && sc->objects[0].mesh->convex) {
        exact_method = R8_VIS_CULL;
        a->why = R8_WHY_CONVEX;
    } else if (sortable(sc, c1, c2)) {
        exact_method = R8_VIS_PAINTER;
        a->why = R8_WHY_SORTABLE;
    } else {
        exact_method = R8_VIS_Z16;
        a->why = R8_WHY_OVERLAP;
    }
    if (cfg->method != R8_VIS_AUTO) {
        a->why = R8_WHY_USER;
    } else {
        cfg->method = exact_method;
    }
    /* band: keep a given one that fits, else the largest that fits */
    if (given > 0) {
        unsigned n;
        cfg->band = given;
        n = need(cfg);
        if (!n || n > budget)
            given = 0;
    }
    if (given <= 0 && !fit_band(cfg, budget)) {
        if (a->why == R8_WHY_USER)
            return -1;
        for (i = 0; i < sizeof fallback; i++) {
            cfg->method = fallback[i];
            if (fit_band(cfg, budget))
                break;
        }
        if (i == sizeof fallback)
            return -1;
        a->why = R8_WHY_RAM;
    }
    a->method = cfg->method;
    a->band = cfg->band;
    a->ram = need(cfg);
    a->exact = cfg->method == exact_method || cfg->method == R8_VIS_Z16 ||
               (exact_method == R8_VIS_CULL && cfg->method != R8_VIS_BLOCK) ||
               (exact_method == R8_VIS_PAINTER && cfg->method == R8_VIS_PAINTER);
    return 0;
}
