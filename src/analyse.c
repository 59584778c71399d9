/* analyse.c - model no more than a scene needs.  The analyser looks at a
 * scene's meshes and objects, and at where the camera can be, and picks
 * the cheapest visibility method that is exact for it:
 *   one convex mesh                      -> cull only (no depth memory)
 *   convex objects apart in depth, whose
 *   painter's buckets cannot interleave
 *   from any allowed camera position     -> painter's (depth buckets)
 *   non-convex meshes that all carry a
 *   BSP tree (one object, or objects
 *   apart in depth as for painter's)     -> BSP order (no depth memory)
 *   anything else (concave meshes,
 *   interpenetration, overlap in depth,
 *   a camera that may turn anywhere)     -> 16-bit z-buffer
 * then the largest band height (and scan-state pool) that fits the RAM
 * budget, and reports the depth range and coordinate width that set the
 * fixed-point scale.  Objects are taken at their current positions; they
 * may turn about them (their bounding spheres do not move). */
#include "r8int.h"

/* Camera-space z of world point p (world units) seen from a camera at q
 * with world -> camera rotation c (row 3 only). */
static r8_s32 cam_z(const r8_mat3 *c, const r8_object *ob, const r8_s16 *q)
{
    r8_s32 s = 0, d;
    r8_u8 k;
    for (k = 0; k < 3; k++) {
        d = (r8_s32)(&ob->pose.x)[k] - q[k];
        d *= c->m[6 + k];
        s += d;
    }
    return r8_asr32(s + 8192, 14);
}

static void cam_rot(const r8_camera *cam, r8_mat3 *c)
{
    if ((cam->flags & R8_CAM_MATRIX) && cam->m) {
        *c = *cam->m;
    } else {
        r8_mat3 ry, rx, rz, a, t;
        r8_mat_rotate(&ry, 0, cam->yaw, 0);
        r8_mat_rotate(&rx, cam->pitch, 0, 0);
        r8_mat_rotate(&rz, 0, 0, cam->roll);
        r8_mat_mul(&rx, &rz, &a);
        r8_mat_mul(&ry, &a, &t);
        r8_mat_transpose(&t, c);
    }
}

/* Corner k (0..7) of the camera box, or the camera itself. */
static void corner(const r8_camera *cam, const r8_bound *b, r8_u8 k, r8_s16 *q)
{
    if (!b || b->kind != R8_BOUND_BOX) {
        q[0] = cam->x;
        q[1] = cam->y;
        q[2] = cam->z;
        return;
    }
    q[0] = (k & 1) ? b->hi[0] : b->lo[0];
    q[1] = (k & 2) ? b->hi[1] : b->lo[1];
    q[2] = (k & 4) ? b->hi[2] : b->lo[2];
}

/* Painter's is exact when every object is convex and, for every camera
 * position allowed, each pair of objects keeps one order with the
 * nearer one's farthest point at least a whole bucket nearer than the
 * other's nearest point (gaps are linear in the camera position: the
 * box's corners bound them). */
static int sortable(const r8_scene *sc, const r8_camera *cam, const r8_bound *b,
                    const r8_mat3 *c, r8_s32 bucket, int convex)
{
    r8_u8 i, j, k, nk = (b && b->kind == R8_BOUND_BOX) ? 8 : 1;
    if (b && b->kind == R8_BOUND_ANY)
        return 0;
    for (i = 0; i < sc->nobjects && convex; i++)
        if (!sc->objects[i].mesh->convex)
            return 0;
    for (i = 0; i < sc->nobjects; i++)
        for (j = (r8_u8)(i + 1); j < sc->nobjects; j++) {
            const r8_object *a = &sc->objects[i], *o = &sc->objects[j];
            int order = 0;
            for (k = 0; k < nk; k++) {
                r8_s16 q[3];
                r8_s32 za, zb;
                int now;
                corner(cam, b, k, q);
                za = cam_z(c, a, q);
                zb = cam_z(c, o, q);
                if (za + a->mesh->radius + bucket <= zb - o->mesh->radius)
                    now = 1;            /* a in front of o */
                else if (zb + o->mesh->radius + bucket <= za - a->mesh->radius)
                    now = 2;
                else
                    return 0;
                if (order && now != order)
                    return 0;
                order = now;
            }
        }
    return 1;
}

#ifndef R8_NO_BSP
/* Every mesh carries a BSP tree (the converter's). */
static int has_trees(const r8_scene *sc)
{
    r8_u8 i;
    for (i = 0; i < sc->nobjects; i++)
        if (!sc->objects[i].mesh->bsp)
            return 0;
    return 1;
}
#endif

static unsigned need(r8_render_cfg *cfg)
{
    unsigned r = r8_render_ram(cfg);
    return r ? r + r8_fb_bytes(cfg->format, cfg->width, cfg->band) : 0;
}

/* Largest band that fits (whole frame first, then smaller multiples of
 * the method's row unit), each with the full pool, then with none.
 * Returns 0 if none. */
static r8_s16 fit_band(r8_render_cfg *cfg, unsigned budget)
{
    r8_s16 unit = 1, h;
    r8_u8 pool = cfg->pool, p;
    if (cfg->format == R8_FMT_PAGE1)
        unit = 8;
    else if (cfg->method == R8_VIS_BLOCK || cfg->method == R8_VIS_BLOCKMASK)
        unit = 4;
    for (p = 0; p < 2; p++) {
        cfg->pool = p ? 0 : pool;
        for (h = (r8_s16)(cfg->height - cfg->height % unit); h >= unit; h = (r8_s16)(h - unit)) {
            unsigned n;
            cfg->band = h;
            n = need(cfg);
            if (n && n <= budget)
                return h;
        }
    }
    cfg->pool = pool;
    return 0;
}

#ifndef R8_NO_RAY
/* A grid map: the ray caster draws it (exact: one wall per column, the
 * nearest, by construction; its memory does not grow with the map). */
static int analyse_grid(r8_render_cfg *cfg, const r8_camera *cam, unsigned budget,
                        r8_analysis *a)
{
    r8_s16 given = cfg->band;
    unsigned n;
    a->why = R8_WHY_GRID;
    if (cfg->method == R8_VIS_AUTO)
        cfg->method = R8_VIS_RAY;
    else
        a->why = R8_WHY_USER;
    if (cfg->method != R8_VIS_RAY)
        return -1;             /* a grid scene has no meshes to draw */
    n = 0;
    if (given > 0)
        n = need(cfg);
    if ((!n || n > budget) && !fit_band(cfg, budget))
        return -1;
    a->method = cfg->method;
    a->band = cfg->band;
    a->pool = cfg->pool;
    a->ram = need(cfg);
    a->znear = cam->znear;
    a->zfar = cam->zfar;
    a->coord_bits = 16;
    a->exact = 1;
    return 0;
}
#endif

int r8_analyse(r8_render_cfg *cfg, const r8_camera *cam, const r8_bound *bound,
               unsigned budget, r8_analysis *a)
{
    static const r8_u8 fallback[] = {
        R8_VIS_Z16, R8_VIS_SBUF, R8_VIS_Z8, R8_VIS_BLOCKMASK, R8_VIS_BLOCK
    };
    const r8_scene *sc = cfg->scene;
    r8_mat3 c;
    r8_s32 zn = 0x7FFFFFFFL, zf = 1, m = 0, bucket;
    r8_s16 given = cfg->band;
    r8_u8 i, k, exact_method, nk = (bound && bound->kind == R8_BOUND_BOX) ? 8 : 1;
#ifndef R8_NO_RAY
    if (sc && cam && sc->grid)
        return analyse_grid(cfg, cam, budget, a);
#endif
    if (!sc || !cam || sc->nobjects == 0)
        return -1;
    cam_rot(cam, &c);
    for (i = 0; i < sc->nobjects; i++) {
        const r8_object *ob = &sc->objects[i];
        r8_s32 r = ob->mesh->radius;
        for (k = 0; k < nk; k++) {
            r8_s16 q[3];
            r8_s32 z, e = r;
            r8_u8 j;
            corner(cam, bound, k, q);
            for (j = 0; j < 3; j++) {
                r8_s32 d = (r8_s32)(&ob->pose.x)[j] - q[j];
                e += d < 0 ? -d : d;
            }
            if (bound && bound->kind == R8_BOUND_ANY)
                z = -e + r;              /* any direction: centre depth +-e */
            else
                z = cam_z(&c, ob, q);
            if (z - r < zn) zn = z - r;
            if (bound && bound->kind == R8_BOUND_ANY)
                z = e - r;
            if (z + r > zf) zf = z + r;
            if (e > m)
                m = e;
        }
    }
    if (zn < cam->znear)
        zn = cam->znear;
    if (zf <= zn)
        zf = zn + 1;
    a->znear = zn;
    a->zfar = zf;
    a->coord_bits = 1;
    while (m > 0) {
        a->coord_bits++;
        m >>= 1;
    }
    /* one painter's bucket in world units over that depth range */
    bucket = (zf - zn + R8_JEFF_BUCKETS - 1) / R8_JEFF_BUCKETS + 1;
    if (sc->nobjects == 1 && sc->objects[0].mesh->convex) {
        exact_method = R8_VIS_CULL;
        a->why = R8_WHY_CONVEX;
    } else if (sortable(sc, cam, bound, &c, bucket, 1)) {
        exact_method = R8_VIS_PAINTER;
        a->why = R8_WHY_SORTABLE;
#ifndef R8_NO_BSP
    } else if (has_trees(sc) &&
               (sc->nobjects == 1 || sortable(sc, cam, bound, &c, bucket, 0))) {
        /* a tree holds for any eye; objects apart in depth keep the far
         * end order r8_bsp_frame draws them in.  No depth memory, no
         * depth compare per pixel, the fast fill: cheaper than the
         * z-buffer whenever it is exact (docs/visibility.md) */
        exact_method = R8_VIS_BSP;
        a->why = R8_WHY_BSP;
#endif
    } else {
        exact_method = R8_VIS_Z16;
        a->why = R8_WHY_OVERLAP;
    }
#ifndef R8_NO_PORTAL
    if (sc->world) {
        exact_method = R8_VIS_PORTAL;   /* sectors and portals: no depth memory */
        a->why = R8_WHY_PORTALS;
    }
#endif
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
        if (!n || n > budget) {
            r8_u8 pool = cfg->pool;
            cfg->pool = 0;
            n = need(cfg);
            if (!n || n > budget) {
                cfg->pool = pool;
                given = 0;
            }
        }
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
    a->pool = cfg->pool;
    a->ram = need(cfg);
    a->exact = cfg->method == exact_method || cfg->method == R8_VIS_Z16 ||
               (exact_method == R8_VIS_CULL && cfg->method != R8_VIS_BLOCK) ||
               (exact_method == R8_VIS_PAINTER && cfg->method == R8_VIS_PAINTER)
#ifndef R8_NO_BSP
               || (cfg->method == R8_VIS_BSP && exact_method <= R8_VIS_PAINTER)
#endif
               ;
    return 0;
}
