/* r8portal.h - the portal renderer (R8_VIS_PORTAL): an indoor world of
 * convex sectors joined by portal polygons, drawn with no depth memory.
 *
 * The world is one ordinary mesh (model space = world space) whose faces
 * are grouped by sector: each sector lists its walls, then its portals.
 * Every face faces INTO its sector (its front side is seen from inside).
 * A portal is a face of its sector too; the one leading back (B to A) is
 * a separate face of B with the opposite winding.  The walls alone can
 * be drawn as an ordinary mesh by the other methods (the converter emits
 * that mesh too), which is how the portal renderer is checked.
 *
 * Per frame (r8_render_frame with method R8_VIS_PORTAL): find the sector
 * holding the camera; draw its front-facing walls clipped to the whole
 * screen; every front-facing portal gives the sector behind it a screen
 * region (a span per row: the portal's pixels inside the region it was
 * seen through), whose faces are then drawn clipped to that region, and
 * so on.  Only the vertices of faces in the sectors seen are transformed.
 * Regions of one frame never overlap, so every pixel is written at most
 * once (walls only; the seed's "zero overdraw").  docs/visibility.md,
 * "Portal renderer", gives the details and where this differs from the
 * seed's pseudo-code.
 *
 * Movable objects: the scene's objects after the leading ones whose mesh
 * has the world mesh's vertex array (the world's walls, for the other
 * methods).  Each belongs, per frame, to the sector holding its pose's
 * origin (r8_portal_locate); one in a sector not visited is not
 * transformed at all.  The others are drawn in every visit of their
 * sector, clipped to its region: back faces culled, objects far to near,
 * the faces of a mesh that is not convex far to near.  Bands draw the
 * deepest visits first, each one's walls then its objects, so an object
 * covers what is seen through its sector's portals.  An object that
 * straddles a portal is cut to its own sector's region (docs/
 * visibility.md, "Movable objects", lists the limits).
 *
 * Memory: the caller's work (r8_render_ram) holds the usual vertex
 * arrays for the world mesh plus R8_PORTAL_VISITS sector visits, their
 * span rows (R8_PORTAL_ROWS frame heights in all) and R8_PORTAL_DRAWS
 * draws (walls and object faces), and with movable objects an ordinary
 * renderer's arrays for them; what does not fit is dropped and counted.
 */
#ifndef R8PORTAL_H
#define R8PORTAL_H

#include "r8render.h"

#ifndef R8_PORTAL_VISITS
#define R8_PORTAL_VISITS 16  /* sector visits per frame */
#endif
#ifndef R8_PORTAL_ROWS
#define R8_PORTAL_ROWS 6     /* span rows for all regions, in frame heights */
#endif
#ifndef R8_PORTAL_CLIP
#define R8_PORTAL_CLIP 24    /* clipped polygons per frame at least: cfg.clip
                                is raised to it (indoors, the floor and
                                ceiling round the camera need the clipper) */
#endif
#ifndef R8_PORTAL_DRAWS
#define R8_PORTAL_DRAWS 128  /* walls and object faces drawn per frame */
#endif

/* One sector: faces [wall0, wall0 + nwalls) of the world mesh are its
 * walls, [portal0, portal0 + nportals) its portals.  The mesh lists every
 * wall first (faces 0 .. nwalls-1: the walls-only mesh the other methods
 * draw), then every portal. */
typedef struct r8_sector {
    r8_u16 wall0, portal0;
    r8_u8 nwalls, nportals;
} r8_sector;

/* The world: a mesh and its sectors (arrays R8_FLASH, read through
 * R8_RD*; the struct itself is small and lives in RAM like r8_mesh). */
typedef struct r8_world {
    const r8_mesh *mesh;        /* walls, then portals; normals required */
    const r8_sector *sectors;   /* R8_FLASH */
    const r8_u8 *target;        /* R8_FLASH: for portal face f, the sector
                                   behind it is target[f - nwalls] */
    r8_u16 nwalls;
    r8_u8 nsectors;
} r8_world;

/* What the last frame did (r8_portal_stats). */
typedef struct r8_portal_stats {
    r8_u8 sector;       /* the camera's sector (255: the world is out of view) */
    r8_u8 visits;       /* sector visits (the camera's sector counts) */
    r8_u16 faces;       /* faces tested (in the sectors visited) */
    r8_u16 walls;       /* wall polygons set up to draw */
    r8_u16 portals;     /* portals passed through */
    r8_u16 dropped;     /* visits, rows or draws that did not fit */
    r8_u32 pixels;      /* pixels written so far in this frame's bands */
    /* movable objects (the scene's objects after the world's own walls) */
    r8_u8 objects;      /* objects set up: in a sector seen this frame */
    r8_u8 unseen;       /* objects in sectors not seen: not transformed */
    r8_u16 opolys;      /* object polygons set up to draw */
    r8_u16 overts;      /* object vertices transformed */
} r8_portal_stats;

/* The sector holding world point (x, y, z): the one it lies deepest
 * inside (largest smallest distance to a face plane), so a point on a
 * portal belongs to one of the two.  Coordinates within +-16383. */
r8_u8 r8_portal_locate(const r8_world *w, r8_s16 x, r8_s16 y, r8_s16 z);

/* The renderer's entry points (render.c calls them for R8_VIS_PORTAL). */
unsigned r8_portal_ram(const r8_render_cfg *cfg);
int r8_portal_init(r8_render *r, const r8_render_cfg *cfg, r8_u8 *work,
                   unsigned work_size);
void r8_portal_frame(r8_render *r, const r8_camera *cam);
void r8_portal_band(r8_render *r, r8_fb *band);
/* 0, or -1 if r is not a portal renderer. */
int r8_portal_stats_get(const r8_render *r, r8_portal_stats *s);

#endif
