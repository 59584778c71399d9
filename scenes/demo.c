/* demo.c - the built-in scene list and the spin (see demo.h). */
#include "demo.h"
#include "r8ray.h"

extern const r8_demo r8_demo_cube, r8_demo_torus, r8_demo_teapot, r8_demo_terrain,
    r8_demo_wall, r8_demo_cross, r8_demo_separate, r8_demo_crate, r8_demo_maze,
    r8_demo_rooms, r8_demo_tmaze;

static const char *const names[R8_DEMO_COUNT] = {
    "cube", "torus", "teapot", "terrain", "wall", "cross", "separate", "crate", "maze", "rooms",
    "tmaze"
};

#ifdef R8_DEMO_ONLY
/* one scene linked: a firmware build (no table: RAM on AVR) */
#if R8_DEMO_ONLY == 0
#define R8_DEMO_THE_ r8_demo_cube
#elif R8_DEMO_ONLY == 1
#define R8_DEMO_THE_ r8_demo_torus
#elif R8_DEMO_ONLY == 2
#define R8_DEMO_THE_ r8_demo_teapot
#elif R8_DEMO_ONLY == 3
#define R8_DEMO_THE_ r8_demo_terrain
#elif R8_DEMO_ONLY == 4
#define R8_DEMO_THE_ r8_demo_wall
#elif R8_DEMO_ONLY == 5
#define R8_DEMO_THE_ r8_demo_cross
#elif R8_DEMO_ONLY == 7
#define R8_DEMO_THE_ r8_demo_crate
#elif R8_DEMO_ONLY == 8
#define R8_DEMO_THE_ r8_demo_maze
#elif R8_DEMO_ONLY == 9
#define R8_DEMO_THE_ r8_demo_rooms
#elif R8_DEMO_ONLY == 10
#define R8_DEMO_THE_ r8_demo_tmaze
#else
#define R8_DEMO_THE_ r8_demo_separate
#endif
const r8_demo *r8_demo_get(r8_u8 id)
{
    return id == R8_DEMO_ONLY ? &R8_DEMO_THE_ : 0;
}
#else
const r8_demo *r8_demo_get(r8_u8 id)
{
    static const r8_demo *const all[R8_DEMO_COUNT] = {
        &r8_demo_cube, &r8_demo_torus, &r8_demo_teapot, &r8_demo_terrain,
        &r8_demo_wall, &r8_demo_cross, &r8_demo_separate, &r8_demo_crate, &r8_demo_maze,
        &r8_demo_rooms, &r8_demo_tmaze
    };
    return id < R8_DEMO_COUNT ? all[id] : 0;
}
#endif

const char *r8_demo_name(r8_u8 id)
{
    return id < R8_DEMO_COUNT ? names[id] : 0;
}

static int streq(const char *a, const char *b)
{
    while (*a && *a == *b) {
        a++;
        b++;
    }
    return *a == *b;
}

int r8_demo_by_name(const char *name)
{
    int i;
    for (i = 0; i < R8_DEMO_COUNT; i++)
        if (names[i] && names[i][0] && streq(name, names[i]))
            return i;
    return -1;
}

/* The grid map of a grid scene (the generated r8_demo tables carry no
 * grid: the maze's are named here). */
#if !defined(R8_DEMO_ONLY) || R8_DEMO_ONLY == 8
extern const r8_grid r8_grid_maze;
#endif
#if !defined(R8_DEMO_ONLY) || R8_DEMO_ONLY == 10
extern const r8_grid r8_grid_tmaze;
#endif
#if !defined(R8_DEMO_ONLY) || R8_DEMO_ONLY == 8 || R8_DEMO_ONLY == 10
static const r8_grid *grid_of(const r8_demo *d)
{
#if !defined(R8_DEMO_ONLY) || R8_DEMO_ONLY == 8
    if (d == &r8_demo_maze)
        return &r8_grid_maze;
#endif
#if !defined(R8_DEMO_ONLY) || R8_DEMO_ONLY == 10
    if (d == &r8_demo_tmaze)
        return &r8_grid_tmaze;
#endif
    (void)d;
    return 0;
}
#endif

int r8_demo_setup(r8_demo_run *run, const r8_demo *d, r8_s16 width)
{
    r8_s32 zn = 0x7FFFFFFFL, zf = 1;
    r8_u8 i, nobj;
    const r8_demo_obj *objs;
    r8_object *ob;
    if (!d)
        return -1;
    nobj = R8_RDU8(&d->nobjects);
    objs = (const r8_demo_obj *)R8_RDPTR(&d->objects);
    if (nobj > R8_DEMO_MAXOBJ)
        return -1;
    run->demo = d;
    ob = run->obj;
    for (i = nobj; i; i--, objs++, ob++) {
        const r8_mesh *me = (const r8_mesh *)R8_RDPTR(&objs->mesh);
        r8_s16 z = R8_RDS16(&objs->z);
        r8_s32 a = z, b = z;
        a -= me->radius;
        b += me->radius;
        ob->mesh = me;
        r8_pose_identity(&ob->pose);
        ob->pose.x = R8_RDS16(&objs->x);
        ob->pose.y = R8_RDS16(&objs->y);
        ob->pose.z = z;
        if (a < zn) zn = a;
        if (b > zf) zf = b;
    }
    run->scene.objects = run->obj;
    run->scene.nobjects = nobj;
    run->scene.ambient = R8_RDS16(&d->ambient);
    run->scene.light.x = R8_RDS16(&d->light.x);
    run->scene.light.y = R8_RDS16(&d->light.y);
    run->scene.light.z = R8_RDS16(&d->light.z);
#if !defined(R8_DEMO_ONLY) || R8_DEMO_ONLY == 8 || R8_DEMO_ONLY == 10
    run->scene.grid = grid_of(d);   /* (a mesh scene's firmware: 0, static) */
#endif
#ifndef R8_NO_PORTAL
    run->scene.world = (const r8_world *)R8_RDPTR(&d->world);
#endif   /* (else never read: the analyser and renderer ignore it) */
    r8_camera_defaults(&run->cam, width);
    run->cam.focal = (r8_s16)(r8_mul16(width, R8_RDS16(&d->focal_num)) >> 6);
#if !defined(R8_DEMO_ONLY) || R8_DEMO_ONLY == 8 || R8_DEMO_ONLY == 10
    if (run->scene.grid) {
        /* a walk's start: the middle of the start cell */
        const r8_grid *g = run->scene.grid;
        run->cam.x = (r8_s16)((r8_s16)(2 * g->sx + 1) << (g->shift - 1));
        run->cam.z = (r8_s16)((r8_s16)(2 * g->sz + 1) << (g->shift - 1));
        run->cam.yaw = g->syaw;
    }
#endif
    /* the depth range the objects can occupy: all the depth methods'
     * precision goes there (nothing lies nearer, so the near plane may
     * move up to it) */
#if !defined(R8_DEMO_ONLY) || R8_DEMO_ONLY == 8 || R8_DEMO_ONLY == 10
    if (!nobj)
        zn = R8_RDS16(&d->znear);   /* a grid scene: no objects */
#endif
    if (zn < R8_RDS16(&d->znear))
        zn = R8_RDS16(&d->znear);
    if (zf <= zn)
        zf = zn + 1;
#ifndef R8_NO_PORTAL
    if (run->scene.world) {
        /* the camera walks through the world: anything within its
         * diameter may be in view */
        zn = R8_RDS16(&d->znear);
        zf = 2L * run->scene.world->mesh->radius;
    }
#endif
    run->cam.znear = (r8_s16)zn;
    run->cam.zfar = (r8_s16)zf;
    r8_demo_pose(run, 0);
    return 0;
}

#ifndef R8_NO_PORTAL
/* x, y, z (out[0..2]) at step t of R8_PATH_STEPS from point a to b
 * (R8_FLASH) */
static void path_at(const r8_s16 *a, const r8_s16 *b, r8_s16 t, r8_s16 *out)
{
    r8_u8 k;
    for (k = 0; k < 3; k++)
        out[k] = (r8_s16)(R8_RDS16(a + k) +
                          R8_ASR32C(r8_mul16((r8_s16)(R8_RDS16(b + k) - R8_RDS16(a + k)), t), 4));
}
#endif

void r8_demo_pose(r8_demo_run *run, r8_u16 frame)
{
    const r8_demo *d = run->demo;
    const r8_demo_obj *o = (const r8_demo_obj *)R8_RDPTR(&d->objects);
    int f = (int)(frame & 0xFF);
#ifndef R8_NO_PORTAL
    r8_u8 i, n = run->scene.nobjects;   /* (a world's may be fewer) */
#else
    r8_u8 i, n = R8_RDU8(&d->nobjects);
#endif
#if !defined(R8_DEMO_ONLY) || R8_DEMO_ONLY == 8 || R8_DEMO_ONLY == 10
    if (run->scene.grid)
        run->cam.yaw = (r8_u8)(run->scene.grid->syaw + 2u * (r8_u8)f);
#endif
    for (i = 0; i < n; i++, o++) {
        r8_pose *p = &run->obj[i].pose;
        p->ax = (r8_u8)(R8_RDU8(&o->ax) + (r8_u8)(R8_RDS8(&o->sx) * f));
        p->ay = (r8_u8)(R8_RDU8(&o->ay) + (r8_u8)(R8_RDS8(&o->sy) * f));
        p->az = (r8_u8)(R8_RDU8(&o->az) + (r8_u8)(R8_RDS8(&o->sz) * f));
    }
#ifndef R8_NO_PORTAL
    n = R8_RDU8(&d->npath);
    if (n > 1) {
        /* the walk: point k to point k + 1 in R8_PATH_STEPS frames (the
         * last back to the first); yaw the short way round */
        const r8_s16 *pa = (const r8_s16 *)R8_RDPTR(&d->path);
        r8_u16 seg = (r8_u16)((frame / R8_PATH_STEPS) % n);
        r8_s16 t = (r8_s16)(frame % R8_PATH_STEPS), dy;
        const r8_s16 *a = pa + 4u * seg, *b = pa + 4u * (seg + 1u < n ? seg + 1u : 0u);
        r8_camera *c = &run->cam;
        path_at(a, b, t, &c->x);
        dy = (r8_s16)(((R8_RDS16(b + 3) - R8_RDS16(a + 3) + 128) & 255) - 128);
        c->yaw = (r8_u8)(R8_RDS16(a + 3) + R8_ASR32C(r8_mul16(dy, t), 4));
    }
    n = R8_RDU8(&d->nmoves);
    if (n) {
        /* moving objects: the same walk along their own points */
        const r8_s16 *m = (const r8_s16 *)R8_RDPTR(&d->moves);
        for (i = 0; i < n; i++) {
            r8_u8 oi = (r8_u8)R8_RDS16(m), np = (r8_u8)R8_RDS16(m + 1);
            r8_u16 seg = (r8_u16)((frame / R8_PATH_STEPS) % np);
            const r8_s16 *a = m + 2 + 3u * seg, *b = m + 2 + 3u * (seg + 1u < np ? seg + 1u : 0u);
            if (oi < run->scene.nobjects)
                path_at(a, b, (r8_s16)(frame % R8_PATH_STEPS), &run->obj[oi].pose.x);
            m += 2 + 3u * np;
        }
    }
#endif
}
