/* maze.c - the maze walk (see maze.h). */
#include "maze.h"
#include "r8ray.h"
#include "plat.h"

/* The grid (scenes/maze.c): a firmware (MAZE_TRIM) links one, chosen at
 * build time (MAZE_TEXTURED: the textured maze, R8_SHADE_TEXTURE); the
 * host links both and maze_textured() chooses. */
#if defined(MAZE_TRIM) && defined(MAZE_TEXTURED)
extern const r8_grid r8_grid_tmaze;
#define GRID (&r8_grid_tmaze)
#define SHADING R8_SHADE_TEXTURE
#elif defined(MAZE_TRIM)
extern const r8_grid r8_grid_maze;
#define GRID (&r8_grid_maze)
#else
extern const r8_grid r8_grid_maze, r8_grid_tmaze;
static const r8_grid *grid = &r8_grid_maze;
static r8_u8 shading = R8_SHADE_LAMBERT;
#define GRID grid
#define SHADING shading

void maze_textured(int on)
{
    grid = on ? &r8_grid_tmaze : &r8_grid_maze;
    shading = (r8_u8)(on ? R8_SHADE_TEXTURE : R8_SHADE_LAMBERT);
}
#endif

static r8_scene scene;

void maze_start(maze_state *s)
{
    const r8_grid *g = GRID;
    s->x = (r8_s16)((r8_s16)(2 * g->sx + 1) << (g->shift - 1));
    s->z = (r8_s16)((r8_s16)(2 * g->sz + 1) << (g->shift - 1));
    s->yaw = g->syaw;
}

/* Is the point (x, z) at least MAZE_RADIUS from every wall cell (and on
 * the map)?  The four corners of the walker's box. */
static int free_at(r8_s16 x, r8_s16 z)
{
    const r8_grid *g = GRID;
    r8_s16 dx, dz;
    for (dx = -MAZE_RADIUS; dx <= MAZE_RADIUS; dx += 2 * MAZE_RADIUS)
        for (dz = -MAZE_RADIUS; dz <= MAZE_RADIUS; dz += 2 * MAZE_RADIUS) {
            r8_s16 px = (r8_s16)(x + dx), pz = (r8_s16)(z + dz);
            r8_s16 cx, cz;
            if (px < 0 || pz < 0)
                return 0;
            cx = (r8_s16)(px >> g->shift);
            cz = (r8_s16)(pz >> g->shift);
            if (cx >= g->w || cz >= g->h ||
                R8_RDU8(&g->cells[(unsigned)cz * g->w + (unsigned)cx]))
                return 0;
        }
    return 1;
}

void maze_steer(maze_state *s, r8_u16 keys)
{
    r8_s16 step = 0, nx, nz;
    if (keys & R8_KEY_LEFT)
        s->yaw = (r8_u8)(s->yaw - MAZE_TURN);
    if (keys & R8_KEY_RIGHT)
        s->yaw = (r8_u8)(s->yaw + MAZE_TURN);
    if (keys & (R8_KEY_UP | R8_KEY_A))
        step = (r8_s16)(step + MAZE_STEP);
    if (keys & (R8_KEY_DOWN | R8_KEY_B))
        step = (r8_s16)(step - MAZE_STEP);
    if (!step)
        return;
    /* forward is (sin yaw, cos yaw); each axis on its own: slide on walls */
    nx = (r8_s16)(s->x + r8_mulq(r8_sin(s->yaw), step, R8_Q14));
    nz = (r8_s16)(s->z + r8_mulq(r8_cos(s->yaw), step, R8_Q14));
    if (free_at(nx, s->z))
        s->x = nx;
    if (free_at(s->x, nz))
        s->z = nz;
}

void maze_camera(const maze_state *s, r8_camera *c)
{
    r8_camera_defaults(c, MAZE_WIDTH);
    c->x = s->x;
    c->z = s->z;
    c->yaw = s->yaw;
}

/* the scene and the renderer's configuration (walk_loop.c: the rest) */
static int scene_config(r8_render_cfg *rc)
{
    scene.objects = 0;
    scene.nobjects = 0;
    scene.ambient = 0;
    scene.light.x = scene.light.y = scene.light.z = 0;
    scene.grid = GRID;
    r8_render_defaults(rc);
#ifdef SHADING
    rc->shading = SHADING;
#endif
    rc->scene = &scene;
    rc->method = R8_VIS_RAY;
    rc->width = MAZE_WIDTH;
    rc->height = MAZE_HEIGHT;
    rc->band = MAZE_BAND;
    return 1;
}

#define WALK_FN(x) maze_##x
#define WALK_UC(x) MAZE_##x
#include "walk_loop.c"   /* the arena, the frame loop, rx (examples/common) */
