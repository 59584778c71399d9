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
static r8_camera cam;
static maze_state st;
static r8_render ren;
static r8_fb band;
static r8_tx tx;

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

static void config(r8_render_cfg *rc, r8_tx_cfg *t)
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
    t->format = rc->format;
    t->width = MAZE_WIDTH;
    t->height = MAZE_HEIGHT;
    t->band = MAZE_BAND;
    t->codec = R8_CODEC_RLE;
    t->full_period = 32;
    t->dirty = 1;
    t->palette = 0;
    t->npal = 0;
}

static unsigned plan(r8_render_cfg *rc, r8_tx_cfg *t, unsigned *work, unsigned *fb)
{
    unsigned s;
    config(rc, t);
    *work = r8_render_ram(rc);
    *fb = r8_fb_bytes(t->format, t->width, t->band);
    s = r8_tx_scratch(t);
    if (!*work || !*fb || !s || *work > 0xFFFFu - *fb - s)
        return 0;
    return *work + *fb + s;
}

unsigned maze_ram(void)
{
    r8_render_cfg rc;
    r8_tx_cfg t;
    unsigned w, b;
    return plan(&rc, &t, &w, &b);
}

static void put(void *ctx, const r8_u8 *p, unsigned n)
{
    (void)ctx;
    plat_write(p, n);
}

int maze_run(const maze_cfg *cfg, r8_u8 *mem, unsigned mem_size)
{
    r8_render_cfg rc;
    r8_tx_cfg t;
    unsigned work, fb, total = plan(&rc, &t, &work, &fb);
    r8_u16 i;
    r8_s16 y;
    if (!total)
        return MAZE_E_CFG;
    if (mem_size < total)
        return MAZE_E_RAM;
    if (r8_render_init(&ren, &rc, mem, work) ||
        r8_fb_init(&band, mem + work, t.format, t.width, t.height, 0, t.band) ||
        r8_tx_init(&tx, &t, mem + work + fb, total - work - fb, put, 0))
        return MAZE_E_CFG;
    maze_start(&st);
    plat_mark(PLAT_MARK_START);
    r8_tx_sync(&tx);
    for (i = 0; !cfg->frames || i < cfg->frames; i++) {
        plat_mark(PLAT_MARK_FRAME_BEGIN);
        maze_steer(&st, tx.keys);        /* the keys received so far */
        maze_camera(&st, &cam);
        r8_render_frame(&ren, &cam);
        r8_tx_frame_begin(&tx, i);
        for (y = 0; y < MAZE_HEIGHT; y = (r8_s16)(y + MAZE_BAND)) {
            r8_fb_set_band(&band, y);
            r8_render_band(&ren, &band);
            r8_tx_band(&tx, &band);
        }
        r8_tx_frame_end(&tx);
        plat_mark(PLAT_MARK_FRAME_END);
        if (cfg->on_frame && cfg->on_frame(cfg->ctx, i))
            break;
    }
    plat_mark(PLAT_MARK_DONE);
    return MAZE_OK;
}

void maze_rx(r8_u8 c)
{
    r8_tx_rx(&tx, c);
}

r8_u16 maze_keys(void)
{
    return tx.keys;
}

const maze_state *maze_where(void)
{
    return &st;
}
