/* render.c - TEMPORARY STUB: draws a moving dithered box until the real
 * renderer lands.  Same API as the final one (r8render.h). */
#include "r8render.h"

void r8_render_defaults(r8_render_cfg *cfg)
{
    cfg->scene = R8_SCENE_CUBE;
    cfg->method = R8_VIS_CULL;
    cfg->shading = R8_SHADE_LAMBERT;
    cfg->cull = R8_CULL_NORMAL;
    cfg->format = R8_FMT_PAGE1;
    cfg->width = 128;
    cfg->height = 64;
    cfg->band = 8;
}

static const char *const scene_names[R8_SCENE_COUNT] = {
    "cube", "torus", "teapot", "terrain", "wall", "cross", "separate"
};
static const char *const method_names[R8_VIS_COUNT] = {
    "cull", "painter", "zbuf8", "zbuf16", "block", "blockmask", "sbuf"
};

static int streq(const char *a, const char *b)
{
    while (*a && *a == *b) {
        a++;
        b++;
    }
    return *a == *b;
}

const char *r8_scene_name(r8_u8 scene)
{
    return scene < R8_SCENE_COUNT ? scene_names[scene] : 0;
}

const char *r8_method_name(r8_u8 method)
{
    if (method == R8_VIS_AUTO)
        return "auto";
    return method < R8_VIS_COUNT ? method_names[method] : 0;
}

int r8_scene_by_name(const char *name)
{
    int i;
    for (i = 0; i < R8_SCENE_COUNT; i++)
        if (streq(name, scene_names[i]))
            return i;
    return -1;
}

int r8_method_by_name(const char *name)
{
    int i;
    if (streq(name, "auto"))
        return R8_VIS_AUTO;
    for (i = 0; i < R8_VIS_COUNT; i++)
        if (streq(name, method_names[i]))
            return i;
    return -1;
}

unsigned r8_render_ram(const r8_render_cfg *cfg)
{
    (void)cfg;
    return 16;
}

int r8_render_init(r8_render *r, const r8_render_cfg *cfg, r8_u8 *work,
                   unsigned work_size)
{
    if (work_size < r8_render_ram(cfg))
        return -2;
    r->cfg = *cfg;
    r->work = work;
    r->work_size = work_size;
    r->frame = 0;
    r->state = work;
    return 0;
}

void r8_render_frame(r8_render *r, r8_u16 frame)
{
    r->frame = frame;
}

void r8_render_band(r8_render *r, r8_fb *band)
{
    r8_s16 y, x0 = (r8_s16)(r->frame % 64u);
    r8_fb_clear(band, 0);
    for (y = 16; y < 48; y++)
        r8_fb_span_dither(band, y, x0, (r8_s16)(x0 + 40), (r8_u8)((y - 16) >> 1), 0);
}
