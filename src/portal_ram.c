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

/* Bytes of the portal's own arrays after the inner work. */
static unsigned own_bytes(const r8_render_cfg *cfg)
{
    return R8_PALIGN(sizeof(pvisit) * R8_PORTAL_VISITS) +
           R8_PALIGN(4u * R8_PORTAL_ROWS * (unsigned)cfg->height) +
           R8_PALIGN(sizeof(pdraw) * R8_PORTAL_DRAWS);
}

unsigned r8_portal_ram(const r8_render_cfg *cfg)
{
    r8_render_cfg ic;
    r8_scene sc;
    r8_object ob;
    unsigned n;
    if (!r8_portal_inner(cfg, &ic, &sc, &ob))
        return 0;
    n = r8_render_ram(&ic);
    if (!n)
        return 0;
    return R8_PALIGN(sizeof(pstate)) + PALIGN + own_bytes(cfg) + n;
}

#else
typedef int r8_portal_ram_unused;   /* ISO C: no empty translation unit */
#endif
