/* demo.h - the built-in demo scenes (one generated C file each in scenes/, from
 * host/rast8/scenes and scene.py by `make scenes`) and the spin that
 * animates them.  Application code, not library: a program links only
 * the scenes it names (a firmware build compiles demo.c with
 * -DR8_DEMO_ONLY=<id> so one scene's meshes are linked).
 *
 * The spin demo in a few lines:
 *     r8_demo_run run;
 *     r8_demo_setup(&run, r8_demo_get(R8_DEMO_CUBE), 128);
 *     cfg.scene = &run.scene;  ... r8_render_init ...
 *     per frame: r8_demo_pose(&run, frame); r8_render_frame(&r, &run.cam);
 */
#ifndef R8_DEMO_H
#define R8_DEMO_H

#include "r8render.h"
#include "r8portal.h"
#include "r8flash.h"

/* One object of a demo scene: a mesh, its place, its start angles and
 * its turn per frame (256 steps per turn). */
typedef struct r8_demo_obj {
    const r8_mesh *mesh;
    r8_s16 x, y, z;
    r8_u8 ax, ay, az;
    r8_s8 sx, sy, sz;
} r8_demo_obj;

/* r8_demo and its objects are R8_FLASH data (r8flash.h): on AVR read
 * them through R8_RD* only (r8_demo_setup does). */
typedef struct r8_demo {
    const char *name;
    const r8_demo_obj *objects;
    r8_u8 nobjects;
    r8_s16 focal_num;          /* focal length = width * focal_num / 64 px */
    r8_s16 znear;              /* near plane */
    r8_s16 ambient;            /* Q1.14 */
    r8_vec3 light;             /* unit vector towards the light, Q1.14 */
#ifndef R8_NO_PORTAL
    const r8_world *world;     /* sectors and portals (0: none) */
    const r8_s16 *path;        /* R8_FLASH: camera x, y, z, yaw per point */
    r8_u8 npath;               /* the camera walks the path, R8_PATH_STEPS
                                  frames from each point to the next */
    const r8_s16 *moves;       /* R8_FLASH: objects that move (0: none):
                                  per object its index, its point count n,
                                  then x, y, z per point; it goes round
                                  its points as the camera does */
    r8_u8 nmoves;              /* objects in moves */
#endif
} r8_demo;
/* (A grid scene, R8_DEMO_MAZE, has no objects: r8_demo_setup puts its
 * grid map, r8ray.h, in the run's scene.) */
#define R8_PATH_STEPS 16
/* The world fields of a scene's initialiser (generated scenes/\*.c): left
 * out with the portal renderer, so no other firmware's flash grows. */
#ifndef R8_NO_PORTAL
#define R8_DEMO_WORLD(w, p, n) , w, p, n, 0, 0
#define R8_DEMO_WORLDM(w, p, n, m, nm) , w, p, n, m, nm   /* with moving objects */
#else
#define R8_DEMO_WORLD(w, p, n)
#define R8_DEMO_WORLDM(w, p, n, m, nm)
#endif

/* The built-in scenes, in this order. */
#define R8_DEMO_CUBE 0        /* the rotating cube (one convex mesh) */
#define R8_DEMO_TORUS 1       /* 200-face torus */
#define R8_DEMO_TEAPOT 2      /* 232-face teapot */
#define R8_DEMO_TERRAIN 3     /* seed's fractal terrain */
#define R8_DEMO_WALL 4        /* seed's wall-and-pillar case */
#define R8_DEMO_CROSS 5       /* two interpenetrating objects */
#define R8_DEMO_SEPARATE 6    /* several separate objects */
#define R8_DEMO_CRATE 7       /* a textured crate (R8_SHADE_TEXTURE) */
#define R8_DEMO_MAZE 8        /* a grid maze for the ray caster (R8_VIS_RAY);
                                 the spin turns the camera in place */
#define R8_DEMO_ROOMS 9       /* nine rooms joined by doors: the portal
                                 renderer's world; the camera walks a path */
#define R8_DEMO_TMAZE 10       /* the maze with textured walls (R8_SHADE_TEXTURE) */
#define R8_DEMO_COUNT 11
#ifndef R8_DEMO_MAXOBJ
#define R8_DEMO_MAXOBJ 4      /* objects a run holds (a firmware of one
                                 scene may set its own count) */
#endif

/* Scene `id` (0 if out of range, or not linked in this build), its
 * name, and the id of a name (-1 if unknown). */
const r8_demo *r8_demo_get(r8_u8 id);
const char *r8_demo_name(r8_u8 id);
int r8_demo_by_name(const char *name);

/* A running demo: the application's scene, camera and objects (the
 * array last: a program may size it for its scene alone). */
typedef struct r8_demo_run {
    const r8_demo *demo;
    r8_scene scene;
    r8_camera cam;
    r8_object obj[R8_DEMO_MAXOBJ];
} r8_demo_run;

/* Objects at their start poses; the camera at the origin looking down
 * +z with the scene's focal length for a `width`-pixel screen, and its
 * near/far depth range fitted to the scene's extents.  -1 if d is 0 or
 * has too many objects. */
int r8_demo_setup(r8_demo_run *run, const r8_demo *d, r8_s16 width);
/* Poses of frame `frame`: angle = start + turn * (frame & 255); a grid
 * scene turns the camera instead, 2 steps a frame from the grid's
 * start yaw; a world's camera walks its path and its moving objects go
 * round theirs (R8_PATH_STEPS frames from point to point). */
void r8_demo_pose(r8_demo_run *run, r8_u16 frame);

#endif
