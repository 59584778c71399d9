/* fw_sizes.c - prints, on the target itself, the memory every scene x
 * method needs there (sizeof differs between host and targets):
 *   "S M BYTES\n" per combination, then "END\n"; with -DFW_SCENE=S only
 *   scene S (the build links only that scene's data).
 * BYTES is app_ram(cfg) for app_defaults + scene + method (FW_HAVE_APP),
 * else r8_render_ram(cfg) for the defaults.  The firmware builds size
 * their static arena from these lines. */
#if defined(FW_SCENE) && FW_SCENE == 10
#define R8_RAY_TEXTURE  /* the textured maze: the ray caster's textures only */
#endif
#if defined(FW_SCENE) && FW_SCENE != 7 && !defined(R8_NO_TEXTURE)
#define R8_NO_TEXTURE   /* as the firmware of that scene (ports/fwdefs.sh) */
#endif
#if defined(FW_SCENE) && FW_SCENE != 9
#define R8_NO_PORTAL   /* a mesh scene: as its table (ports/scene_strip.py) */
#endif
#include "plat.h"
#include "r8render.h"
#ifdef FW_HAVE_APP
#include "app.h"
static app_cfg acfg;
#include "fw_trim.c"   /* sizing renders nothing: no LZ77, no S-buffer */
#endif

static void put_u(unsigned v)
{
    char d[6];
    int n = 0;
    do {
        d[n++] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v);
    while (n)
        plat_putc((r8_u8)d[--n]);
}

#ifndef FW_HAVE_APP
#include "demo.h"
static r8_render_cfg cfg;
static r8_demo_run run;
#endif

int main(void)
{
    r8_u8 s, m;
    plat_init();
#ifdef FW_SCENE
    /* linked with one scene (ports/scene_strip.py): that scene only */
    for (s = FW_SCENE; s == FW_SCENE; s++)
#else
    for (s = 0; s < R8_DEMO_COUNT; s++)
#endif
        for (m = 0; m <= R8_VIS_RAY; m++) {
            const r8_demo *d = r8_demo_get(s);
            /* a world of sectors: the portal renderer (and painter's and
             * zbuf16 on its walls, for make bench); a grid (the maze): the
             * ray caster; else the mesh methods */
            if (!d)
                continue;
#ifndef R8_NO_PORTAL
            if (R8_RDPTR(&d->world)) {
                if (m != R8_VIS_PORTAL && m != R8_VIS_PAINTER && m != R8_VIS_Z16)
                    continue;
            } else
#endif
            if (s == R8_DEMO_MAZE || s == R8_DEMO_TMAZE) {
                if (m != R8_VIS_RAY)
                    continue;
            } else if (m >= R8_VIS_COUNT)
                continue;
            put_u(s);
            plat_putc(' ');
            put_u(m);
            plat_putc(' ');
#ifdef FW_HAVE_APP
            app_defaults(&acfg);
            acfg.render.clip = 0;   /* as fw_app.c */
#ifdef FW_POOL
            acfg.render.pool = FW_POOL;
#endif
#ifdef FW_SHADING
            acfg.render.shading = FW_SHADING;
#else
            if (s == 7 || s == 10)   /* the crate, tmaze: textured (fw_app.c) */
                acfg.render.shading = R8_SHADE_TEXTURE;
#endif
            acfg.scene = s;
#ifndef R8_NO_PORTAL
            if (R8_RDPTR(&d->world))
                acfg.render.clip = R8_PORTAL_CLIP;   /* as fw_app.c */
#endif
            acfg.render.method = m;
            put_u(app_ram(&acfg));
#else
            r8_render_defaults(&cfg);
            cfg.scene = &run.scene;
            r8_demo_setup(&run, r8_demo_get(s), cfg.width);
            cfg.method = m;
            put_u(r8_render_ram(&cfg) + R8_FB_PAGE1_BYTES(128, 8));
#endif
            plat_putc('\n');
        }
    plat_putc('E');
    plat_putc('N');
    plat_putc('D');
    plat_putc('\n');
    plat_exit(0);
    return 0;
}
