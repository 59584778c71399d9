/* oled_cube.c - the SSD1306 example's application (oled_cube.h). */
#include "oled_cube.h"
#include "ssd1306_spi.h"

/* The mesh, in flash: 8 vertices 72 units apart, 6 faces clockwise seen
 * from outside (n, brightness 0..16, vertices), their outward normals
 * in Q1.14 (so no RAM is spent computing them). */
static const r8_s16 cube_v[24] R8_FLASH = {
    -36, -36, -36, 36, -36, -36, 36, 36, -36, -36, 36, -36,
    -36, -36, 36, 36, -36, 36, 36, 36, 36, -36, 36, 36
};
static const r8_face cube_f[6] R8_FLASH = {
    {4, 16, {0, 1, 2, 3}}, {4, 16, {5, 4, 7, 6}}, {4, 16, {1, 5, 6, 2}},
    {4, 16, {4, 0, 3, 7}}, {4, 16, {4, 5, 1, 0}}, {4, 16, {3, 2, 6, 7}}
};
static const r8_s16 cube_n[18] R8_FLASH = {
    0, 0, -16384, 0, 0, 16384, 16384, 0, 0, -16384, 0, 0, 0, -16384, 0, 0, 16384, 0
};
static const r8_mesh cube = {cube_v, cube_f, cube_n, 8, 6, 1, 63, 0 R8_MESH_TEX(0, 0)};

static r8_object obj;
static r8_scene scene;
static r8_camera cam;
static r8_render_cfg cfg;
static r8_render ren;
static r8_fb band;

static void setup(void)
{
    obj.mesh = &cube;
    r8_pose_identity(&obj.pose);
    obj.pose.z = 220;                      /* 220 units in front of the camera */
    scene.objects = &obj;
    scene.nobjects = 1;
    scene.ambient = 3277;                  /* 0.2 */
    scene.light.x = scene.light.y = scene.light.z = -9459;  /* from above left, in front */
    r8_camera_defaults(&cam, OLED_W);
    cam.focal = 100;                       /* pixels */
    cam.znear = 157;                       /* the cube's depth range */
    cam.zfar = 283;
    r8_render_defaults(&cfg);              /* cull (one convex mesh), Lambert, 128x64 pages */
    cfg.scene = &scene;
    cfg.band = 8;                          /* one band = one page */
    cfg.clip = 0;                          /* the cube never nears the camera */
}

unsigned oled_cube_ram(void)
{
    unsigned w;
    setup();
    w = r8_render_ram(&cfg);
    return w ? w + R8_FB_PAGE1_BYTES(OLED_W, 8) : 0;
}

int oled_cube_init(r8_u8 *arena, unsigned size)
{
    unsigned need = oled_cube_ram(), w = need - R8_FB_PAGE1_BYTES(OLED_W, 8);
    if (!need || size < need || r8_render_init(&ren, &cfg, arena, w) ||
        r8_fb_init(&band, arena + w, cfg.format, OLED_W, OLED_H, 0, 8))
        return -1;
    return 0;
}

void oled_cube_frame(r8_u16 n)
{
    r8_u8 f = (r8_u8)n, p;
    obj.pose.ax = (r8_u8)(2 * f);          /* the application turns the cube */
    obj.pose.ay = (r8_u8)(3 * f);
    obj.pose.az = f;
    r8_render_frame(&ren, &cam);
    for (p = 0; p < OLED_H / 8; p++) {
        r8_fb_set_band(&band, (r8_s16)(8 * p));
        r8_render_band(&ren, &band);       /* the page's 8 rows */
        ssd1306_page(p, band.buf, OLED_W);
    }
}
