/* portal_ram.c - the portal renderer's memory plan (r8portal.h): apart
 * from portal.c so a sizing build (R8_PLAN_ONLY: tests/targets/
 * fw_sizes.c) links it without the renderer. */
#include <stddef.h>
#include "r8int.h"
#include "r8portal.h"
#include "portal_int.h"

#ifndef R8_NO_PORTAL

/* The ordinary renderer's configuration for the world object. */
int r8_portal_inner(const r8_render_cfg *cfg, r8_render_cfg *ic, r8_scene *sc,
                     r8_object *ob)
{
    const r8_world *w;
    if (!cfg->scene || !cfg->scene->world)
        return 0;
    w = cfg->scene->world;
    if (!w->mesh || !w->mesh->normals || !w->sectors || w->nsectors == 0 ||
        w->nwalls > w->mesh->nfaces || cfg->shading == R8_SHADE_GOURAUD)
        return 0;
    ob->mesh = w->mesh;
    r8_pose_identity(&ob->pose);
    sc->objects = ob;
    sc->nobjects = 1;
    sc->ambient = cfg->scene->ambient;
    sc->light = cfg->scene->light;
    sc->world = 0;
    *ic = *cfg;
    ic->scene = sc;
    ic->method = R8_VIS_CULL;
    ic->cull = R8_CULL_NORMAL;
    ic->pool = 0;
    /* indoors, the floor and ceiling around the camera cross the near
     * plane and the guard band: 21 polygons at most on the rooms walk */
#ifndef R8_NO_CLIP
    if (ic->clip < R8_PORTAL_CLIP)
        ic->clip = R8_PORTAL_CLIP;
#endif
    return 1;
}

r8_u8 r8_portal_skip(const r8_render_cfg *cfg)
{
    const r8_scene *sc = cfg->scene;
    const r8_s16 *wv = sc->world->mesh->verts;
    r8_u8 k = 0;
    while (k < sc->nobjects && sc->objects[k].mesh && sc->objects[k].mesh->verts == wv)
        k++;
    return k;
}

int r8_portal_objcfg(const r8_render_cfg *cfg, r8_render_cfg *oc, r8_scene *sc)
{
    const r8_scene *as = cfg->scene;
    r8_u8 skip = r8_portal_skip(cfg);
    if (skip >= as->nobjects)
        return 0;
    *sc = *as;
    sc->objects = as->objects + skip;
    sc->nobjects = (r8_u8)(as->nobjects - skip);
    sc->world = 0;
    sc->grid = 0;
    *oc = *cfg;
    oc->scene = sc;
    oc->method = R8_VIS_CULL;
    oc->cull = R8_CULL_NORMAL;
    oc->pool = 0;
    return 1;
}

/* Scratch depth keys: the faces of the largest mesh that is not convex
 * (painter's order within it), at most R8_PORTAL_DRAWS. */
static unsigned okeys(const r8_scene *sc)
{
    unsigned n = 0;
    r8_u8 k;
    for (k = 0; k < sc->nobjects; k++) {
        const r8_mesh *me = sc->objects[k].mesh;
        if (!me->convex && me->nfaces > n)
            n = me->nfaces;
    }
    return n > R8_PORTAL_DRAWS ? R8_PORTAL_DRAWS : n;
}

/* Bytes of the portal's own arrays after the inner work. */
static unsigned own_bytes(const r8_render_cfg *cfg, const r8_scene *os)
{
    unsigned n = R8_PALIGN(sizeof(pvisit) * R8_PORTAL_VISITS) +
                 R8_PALIGN(4u * R8_PORTAL_ROWS * (unsigned)cfg->height) +
                 R8_PALIGN(sizeof(pdraw) * R8_PORTAL_DRAWS);
    if (os)
        n += R8_PALIGN(2u * os->nobjects) + R8_PALIGN(2u * okeys(os));
    return n;
}

unsigned r8_portal_ram(const r8_render_cfg *cfg)
{
    r8_render_cfg ic, oc;
    r8_scene sc, os;
    r8_object ob;
    unsigned n, m = 0;
    int objs;
    if (!r8_portal_inner(cfg, &ic, &sc, &ob))
        return 0;
    n = r8_render_ram(&ic);
    if (!n)
        return 0;
    objs = r8_portal_objcfg(cfg, &oc, &os);
    if (objs) {
        m = r8_render_ram(&oc);
        if (!m)
            return 0;
    }
    return R8_PALIGN(sizeof(pstate)) + PALIGN + own_bytes(cfg, objs ? &os : 0) +
           R8_PALIGN(n) + m;
}

unsigned r8_portal_own(const r8_render_cfg *cfg)
{
    r8_render_cfg oc;
    r8_scene os;
    return own_bytes(cfg, r8_portal_objcfg(cfg, &oc, &os) ? &os : 0);
}

unsigned r8_portal_okeys(const r8_scene *os)
{
    return okeys(os);
}

#else
typedef int r8_portal_ram_unused;   /* ISO C: no empty translation unit */
#endif
