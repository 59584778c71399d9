/* r8ray.h - the ray caster (visibility method R8_VIS_RAY, "ray"): a
 * grid map in flash seen from the camera, one ray per screen column
 * (the seed's "Ray Casting Algorithm", done right: docs/visibility.md,
 * "Ray caster").
 *
 * It is a world renderer: a scene with a grid (r8_scene.grid) and
 * cfg.method = R8_VIS_RAY goes through the ordinary entry points
 * (r8_render_ram/init/frame/band call the functions below), so the
 * demo, the emulator, the firmwares and the wire work unchanged.
 *
 * The world: cell (i, j) of the grid covers x in [i << shift, (i+1) << shift)
 * and z in [j << shift, (j+1) << shift), world units; a non-zero cell is
 * a wall block as tall as it is wide, the eye at its mid-height.  The
 * camera's x, z and yaw are used; y, pitch and roll are ignored (a
 * ray caster's walls stand upright), as are znear and zfar.  Rays that
 * leave the map end on its edge as on a wall of level 16.
 *
 * Shading: R8_SHADE_FLAT draws a wall cell at its own level (1..16),
 * walls across z (hit from the z side) at 3/4 of it; R8_SHADE_LAMBERT
 * (the default) also dims it with distance.  R8_SHADE_TEXTURE with a
 * grid that has textures (r8_grid.tex) draws each wall's texture, its
 * texels (0..255) times the distance-shaded level; a grid without
 * textures is then drawn as with Lambert.  Ceiling black, floor
 * level 2, all through the 4x4 ordered dither of r8fb.h.  Gouraud is
 * rejected.  Every format is drawn; R8_FMT_PAGE1 (SSD1306 pages) a
 * column byte at a time.
 *
 * Textures: u from the exact hit position along the wall face (the
 * DDA's own fraction, r8_ray_hit.u), mirrored so a face reads left to
 * right seen from outside, whichever side; v stepped down the column,
 * one step per column from the reciprocal table of the heights, the
 * start offset from the exact (unclipped) wall top, so walls taller
 * than the screen show their middle.  No division per pixel or row.
 *
 * Memory: r8_ray_ram(cfg) = a small state + 2 bytes per screen column
 * (half height and level of each column's wall; 8 bytes textured: also
 * texture, texel column, v at row 0 and v step), made by r8_ray_frame
 * and drawn band by band by r8_ray_band.  Height at most 255 rows (rows
 * are bytes in the band loop).
 *
 * Leave it out of a build with -DR8_NO_RAY. */
#ifndef R8RAY_H
#define R8RAY_H

#include "r8types.h"
#include "r8render.h"

/* A grid map: the struct is small and lives in RAM (like r8_mesh), its
 * cells in flash. */
typedef struct r8_grid {
    const r8_u8 *cells;    /* R8_FLASH: w * h bytes, row z = 0 first; 0 =
                              empty, 1..16 = a wall of that level */
    r8_u8 w, h;            /* cells across x and z (1..255) */
    r8_u8 shift;           /* a cell is 1 << shift world units (2..8);
                              w << shift and h << shift at most 32767 */
    r8_u8 sx, sz, syaw;    /* where a walk starts: cell (sx, sz), looking
                              at yaw syaw (for applications and demos) */
    const r8_texture *tex; /* 0: untextured; else ntex textures (in RAM,
                              like r8_mesh.tex; their data R8_FLASH): a
                              wall of cell value v gets tex[(v - 1) % ntex]
                              (R8_SHADE_TEXTURE only) */
    r8_u8 ntex;            /* 1..16 with tex */
} r8_grid;

/* One ray's result. */
typedef struct r8_ray_hit {
    r8_u16 h16;            /* wall height on screen, 1/16 pixels (0xFFFF: at
                              least that; 0: no wall, camera off the map) */
    r8_u8 cx, cz;          /* the cell hit */
    r8_u8 side;            /* 0: crossed an x boundary, 1: a z boundary */
    r8_u8 cell;            /* its value (16 on the map's edge) */
    r8_u8 u;               /* where on the face, 0..255 = left to right
                              seen from outside (256 x the fraction,
                              floored; the texture's u) */
} r8_ray_hit;

/* Cast the ray of screen column x (0..width-1) of a width-pixel screen
 * with focal length cam->focal: exactly what r8_ray_frame computes for
 * that column.  0, or -1 for a bad grid or camera. */
int r8_ray_cast(const r8_grid *g, const r8_camera *cam, r8_s16 width, r8_s16 x,
                r8_ray_hit *hit);

/* The hooks behind r8_render_*: the same contracts. */
unsigned r8_ray_ram(const r8_render_cfg *cfg);
int r8_ray_init(r8_render *r, const r8_render_cfg *cfg, r8_u8 *work, unsigned work_size);
void r8_ray_frame(r8_render *r, const r8_camera *cam);
void r8_ray_band(r8_render *r, r8_fb *fb);
/* Is this grid usable (sizes in range)?  1 or 0. */
int r8_grid_valid(const r8_grid *g);

#endif
