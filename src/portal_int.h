/* portal_int.h - what portal.c and portal_ram.c share: the portal
 * renderer's state at the start of the caller's work memory. */
#ifndef R8PORTAL_INT_H
#define R8PORTAL_INT_H
#include "r8int.h"
#include "r8portal.h"

typedef struct pvisit {
    r8_s16 ytop, ybot;  /* rows [ytop, ybot) */
    r8_u16 row0;        /* their spans: rows[2 * (row0 + y - ytop)] */
    r8_u16 w0, nw;      /* its draws: walls [w0, w0 + nw), then the */
    r8_u16 o0, no;      /*   objects' faces [o0, o0 + no), far to near */
    r8_u8 sector;
} pvisit;

typedef struct pdraw {
    r8_u16 g;           /* face id (mesh face, or nfaces + clipped polygon) */
    r8_u8 visit;        /* | PD_OBJ: a face of the objects' renderer */
    r8_u8 level;
} pdraw;
#define PD_OBJ 0x80

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
    /* movable objects (the scene's objects from `skip` on: the ones
     * before are the world's own walls for the other methods) */
    r8_render oinner;   /* the ordinary renderer on them (nmov > 0) */
    r8_scene oscene;
    r8_u8 skip, nmov;
    r8_u8 *osec;        /* per object: its sector this frame, 255 none */
    r8_u8 *oorder;      /* the objects set up, far to near */
    r8_s16 *okey;       /* scratch: depth keys of one object's draws */
} pstate;

#define PALIGN (sizeof(r8_s32) > sizeof(void *) ? sizeof(r8_s32) : sizeof(void *))

#define R8_PALIGN(n) ((unsigned)(((unsigned)(n) + (PALIGN - 1)) & ~(unsigned)(PALIGN - 1)))

/* The ordinary renderer's configuration for the world object (the
 * world mesh at the origin, cull-only order); 0 if cfg is not valid. */
int r8_portal_inner(const r8_render_cfg *cfg, r8_render_cfg *ic, r8_scene *sc,
                    r8_object *ob);
/* The leading scene objects that are the world's walls (a mesh with the
 * world mesh's vertex array), and the renderer configuration for the
 * others (0 if there are none). */
r8_u8 r8_portal_skip(const r8_render_cfg *cfg);
int r8_portal_objcfg(const r8_render_cfg *cfg, r8_render_cfg *oc, r8_scene *sc);
/* Bytes of the portal's own arrays; scratch keys for the objects' scene. */
unsigned r8_portal_own(const r8_render_cfg *cfg);
unsigned r8_portal_okeys(const r8_scene *os);

#endif
