/* frame.c - a user program built against an installed rast8 with
 * nothing but `pkg-config --cflags --libs rast8` (tests/package/check.py):
 * the minimal API program (docs/api.md) - its own mesh (a cube, 72
 * units across), a camera, one pose, a frame - renders frame N of the
 * spinning cube (cull, 128x64 SSD1306 pages, one 64-row band) and writes
 * the 1024 framebuffer bytes to stdout: the same picture as
 * `r8dump --scene cube --frame N`.
 *   frame [N]      exit 0, or 1 with a message on stderr */
#include <stdio.h>
#include <stdlib.h>
#include "r8render.h"

/* the mesh: arrays the library reads through R8_RD* (R8_FLASH on AVR) */
static const r8_s16 cube_v[24] R8_FLASH = {
    -36, -36, -36, 36, -36, -36, 36, 36, -36, -36, 36, -36,
    -36, -36, 36, 36, -36, 36, 36, 36, 36, -36, 36, 36
};
static const r8_face cube_f[6] R8_FLASH = {   /* clockwise seen from outside */
    {4, 16, {0, 1, 2, 3}}, {4, 16, {5, 4, 7, 6}}, {4, 16, {1, 5, 6, 2}},
    {4, 16, {4, 0, 3, 7}}, {4, 16, {4, 5, 1, 0}}, {4, 16, {3, 2, 6, 7}}
};
/* no normals given: r8_render_init computes them into work memory */
static const r8_mesh cube = {cube_v, cube_f, 0, 8, 6, 1, 63, 0 R8_MESH_TEX(0, 0)};

static r8_u8 work[4096];
static r8_u8 buf[R8_FB_PAGE1_BYTES(128, 64)];

int main(int argc, char **argv)
{
    r8_object obj;
    r8_scene scene;
    r8_camera cam;
    r8_render_cfg cfg;
    r8_render r;
    r8_fb fb;
    unsigned need, n = (unsigned)(argc > 1 ? atoi(argv[1]) : 0) & 0xFFu;
    /* one object 220 units in front of the camera, turning */
    obj.mesh = &cube;
    r8_pose_identity(&obj.pose);
    obj.pose.z = 220;
    obj.pose.ax = (r8_u8)(2 * n);
    obj.pose.ay = (r8_u8)(3 * n);
    obj.pose.az = (r8_u8)n;
    scene.objects = &obj;
    scene.nobjects = 1;
    scene.ambient = 3277;                    /* 0.2 in Q1.14 */
    scene.light.x = scene.light.y = scene.light.z = -9459;   /* (-1,-1,-1)/sqrt 3 */
    r8_camera_defaults(&cam, 128);
    cam.focal = 100;
    cam.znear = 157;                         /* the cube's depth range */
    cam.zfar = 283;
    r8_render_defaults(&cfg);
    cfg.scene = &scene;
    cfg.band = 64;
    need = r8_render_ram(&cfg);
    if (need == 0 || need > sizeof work) {
        fprintf(stderr, "frame: work memory %u > %u\n", need, (unsigned)sizeof work);
        return 1;
    }
    if (r8_render_init(&r, &cfg, work, need) != 0
        || r8_fb_init(&fb, buf, cfg.format, cfg.width, cfg.height, 0, cfg.band) != 0) {
        fprintf(stderr, "frame: init failed\n");
        return 1;
    }
    r8_render_frame(&r, &cam);
    r8_render_band(&r, &fb);
    if (fwrite(buf, 1, sizeof buf, stdout) != sizeof buf)
        return 1;
    return 0;
}
