/* portal_int.h - what portal.c and portal_ram.c share: the portal
 * renderer's state at the start of the caller's work memory. */
#ifndef R8PORTAL_INT_H
#define R8PORTAL_INT_H
#include "r8int.h"
#include "r8portal.h"

typedef struct pvisit {
    r8_s16 ytop, ybot;  /* rows [ytop, ybot) */
    r8_u16 row0;        /* their spans: rows[2 * (row0 + y - ytop)] */
    r8_u8 sector;
} pvisit;

typedef struct pdraw {
    r8_u16 g;           /* face id (mesh face, or nfaces + clipped polygon) */
    r8_u8 visit;
    r8_u8 level;
} pdraw;

typedef struct pstate {
    r8_render inner;    /* the ordinary renderer on the world object */
    r8_scene scene;
    r8_object obj;
    const r8_world *world;
    pvisit *visit;
    r8_s16 *rows;       /* x0, x1 per row of every visit */
    pdraw *draw;
    r8_u16 rows_cap, rows_used, ndraw, maxdraw;
    r8_u8 nvisit;
    r8_portal_stats stats;
} pstate;

#define PALIGN (sizeof(r8_s32) > sizeof(void *) ? sizeof(r8_s32) : sizeof(void *))

#define R8_PALIGN(n) ((unsigned)(((unsigned)(n) + (PALIGN - 1)) & ~(unsigned)(PALIGN - 1)))

/* The ordinary renderer's configuration for the world object (the
 * world mesh at the origin, cull-only order); 0 if cfg is not valid. */
int r8_portal_inner(const r8_render_cfg *cfg, r8_render_cfg *ic, r8_scene *sc,
                    r8_object *ob);

#endif
