/* walk_loop.c - the loop of a keyed walk (examples/flythrough/fly.c,
 * examples/maze/maze.c include it after their own steering, camera and
 * scene): the arena (render work, one band, encoder scratch), then per
 * frame steer by the keys received so far, render, stream band by band
 * in the display protocol, and the display's bytes to the receive
 * parser.  The same C89 on the host and every target.  The includer
 * names its prefix, before it:
 *   #define WALK_FN(x) fly_##x    its names: fly_state, fly_cfg, fly_start,
 *                fly_steer, fly_camera (its walk); fly_ram, fly_run,
 *                fly_rx, fly_keys, fly_where are defined here
 *   #define WALK_UC(x) FLY_##x    FLY_WIDTH, FLY_HEIGHT, FLY_BAND (the
 *                screen and band, PAGE1 and RLE), FLY_OK, FLY_E_CFG,
 *                FLY_E_RAM (its codes)
 *   static int scene_config(r8_render_cfg *rc)   its scene into rc
 *                (after r8_render_defaults); 0: no scene
 * and gets the statics cam, ren, band, tx and st. */
static r8_camera cam;
static WALK_FN(state) st;
static r8_render ren;
static r8_fb band;
static r8_tx tx;

/* The stream's configuration beside the scene's; 0: no scene. */
static int config(r8_render_cfg *rc, r8_tx_cfg *t)
{
    int ok = scene_config(rc);
    t->format = rc->format;
    t->width = WALK_UC(WIDTH);
    t->height = WALK_UC(HEIGHT);
    t->band = WALK_UC(BAND);
    t->codec = R8_CODEC_RLE;
    t->full_period = 32;
    t->dirty = 1;
    t->palette = 0;
    t->npal = 0;
    return ok;
}

/* The arena: render work, then one band, then the encoder scratch. */
static unsigned plan(r8_render_cfg *rc, r8_tx_cfg *t, unsigned *work, unsigned *fb)
{
    unsigned s;
    if (!config(rc, t))
        return 0;
    *work = r8_render_ram(rc);
    *fb = r8_fb_bytes(t->format, t->width, t->band);
    s = r8_tx_scratch(t);
    if (!*work || !*fb || !s || *work > 0xFFFFu - *fb - s)
        return 0;
    return *work + *fb + s;
}

unsigned WALK_FN(ram)(void)
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

int WALK_FN(run)(const WALK_FN(cfg) *cfg, r8_u8 *mem, unsigned mem_size)
{
    r8_render_cfg rc;
    r8_tx_cfg t;
    unsigned work, fb, total = plan(&rc, &t, &work, &fb);
    r8_u16 i;
    r8_s16 y;
    if (!total)
        return WALK_UC(E_CFG);
    if (mem_size < total)
        return WALK_UC(E_RAM);
    if (r8_render_init(&ren, &rc, mem, work) ||
        r8_fb_init(&band, mem + work, t.format, t.width, t.height, 0, t.band) ||
        r8_tx_init(&tx, &t, mem + work + fb, total - work - fb, put, 0))
        return WALK_UC(E_CFG);
    WALK_FN(start)(&st);
    plat_mark(PLAT_MARK_START);
    r8_tx_sync(&tx);
    for (i = 0; !cfg->frames || i < cfg->frames; i++) {
        plat_mark(PLAT_MARK_FRAME_BEGIN);
        WALK_FN(steer)(&st, tx.keys);       /* the keys received so far */
        WALK_FN(camera)(&st, &cam);
        r8_render_frame(&ren, &cam);
        r8_tx_frame_begin(&tx, i);
        for (y = 0; y < WALK_UC(HEIGHT); y = (r8_s16)(y + WALK_UC(BAND))) {
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
    return WALK_UC(OK);
}

void WALK_FN(rx)(r8_u8 c)
{
    r8_tx_rx(&tx, c);
}

r8_u16 WALK_FN(keys)(void)
{
    return tx.keys;
}

const WALK_FN(state) *WALK_FN(where)(void)
{
    return &st;
}
