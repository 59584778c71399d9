/* two.c - the two-objects scene and its analysis (two.h). */
#include "two.h"

/* A cube 40 units across and an octahedron 80 units tip to tip; faces
 * clockwise seen from outside, outward normals in Q1.14 (flash). */
static const r8_s16 cube_v[24] R8_FLASH = {
    -20, -20, -20, 20, -20, -20, 20, 20, -20, -20, 20, -20,
    -20, -20, 20, 20, -20, 20, 20, 20, 20, -20, 20, 20
};
static const r8_face cube_f[6] R8_FLASH = {
    {4, 16, {0, 1, 2, 3}}, {4, 16, {5, 4, 7, 6}}, {4, 16, {1, 5, 6, 2}},
    {4, 16, {4, 0, 3, 7}}, {4, 16, {4, 5, 1, 0}}, {4, 16, {3, 2, 6, 7}}
};
static const r8_s16 cube_n[18] R8_FLASH = {
    0, 0, -16384, 0, 0, 16384, 16384, 0, 0, -16384, 0, 0, 0, -16384, 0, 0, 16384, 0
};
static const r8_mesh cube = {cube_v, cube_f, cube_n, 8, 6, 1, 35, 0 R8_MESH_TEX(0, 0)};

static const r8_s16 octa_v[18] R8_FLASH = {
    40, 0, 0, -40, 0, 0, 0, 40, 0, 0, -40, 0, 0, 0, 40, 0, 0, -40
};
static const r8_face octa_f[8] R8_FLASH = {
    {3, 11, {0, 4, 2, 0}}, {3, 11, {0, 2, 5, 0}}, {3, 11, {0, 3, 4, 0}}, {3, 11, {0, 5, 3, 0}},
    {3, 11, {1, 2, 4, 0}}, {3, 11, {1, 5, 2, 0}}, {3, 11, {1, 4, 3, 0}}, {3, 11, {1, 3, 5, 0}}
};
#define K 9459   /* 1/sqrt 3 in Q1.14 */
static const r8_s16 octa_n[24] R8_FLASH = {
    K, K, K, K, K, -K, K, -K, K, K, -K, -K, -K, K, K, -K, K, -K, -K, -K, K, -K, -K, -K
};
static const r8_mesh octa = {octa_v, octa_f, octa_n, 6, 8, 1, 40, 0 R8_MESH_TEX(0, 0)};

static r8_object obj[2];
r8_scene two_scene;
r8_camera two_cam;

void two_init(void)
{
    obj[0].mesh = &cube;
    r8_pose_identity(&obj[0].pose);
    obj[0].pose.x = -16;                   /* left, nearer */
    obj[0].pose.y = -4;
    obj[0].pose.z = 150;
    obj[1].mesh = &octa;
    r8_pose_identity(&obj[1].pose);
    obj[1].pose.x = 20;                    /* right, farther, partly behind it */
    obj[1].pose.y = 6;
    obj[1].pose.z = 250;
    two_scene.objects = obj;
    two_scene.nobjects = 2;
    two_scene.ambient = 3277;              /* 0.2 */
    two_scene.light.x = two_scene.light.y = two_scene.light.z = -9459;
    r8_camera_defaults(&two_cam, TWO_W);
    two_cam.focal = 100;
    two_cam.znear = 16;
    two_cam.zfar = 400;
    two_pose(0);
}

void two_pose(r8_u16 n)
{
    r8_u8 f = (r8_u8)n;
    obj[0].pose.ax = f;
    obj[0].pose.ay = (r8_u8)(2 * f);
    obj[1].pose.ay = (r8_u8)(2 * f);
    obj[1].pose.az = f;
}

int two_analyse(r8_render_cfg *cfg, const r8_bound *b, unsigned budget, r8_analysis *a)
{
    if (r8_analyse(cfg, &two_cam, b, budget, a))
        return -1;
    /* the depth range every allowed camera position needs: the depth
     * methods and painter's keys spread over it */
    two_cam.znear = (r8_s16)a->znear;
    two_cam.zfar = (r8_s16)a->zfar;
    return 0;
}

const char *two_why(r8_u8 why)
{
    switch (why) {
    case R8_WHY_CONVEX:
        return "one convex mesh: backface culling is exact";
    case R8_WHY_SORTABLE:
        return "convex objects apart in depth by more than a painter's bucket "
               "from every camera position allowed: painter's is exact";
    case R8_WHY_OVERLAP:
        return "the objects may come within a painter's bucket in depth (or overlap, "
               "or the camera may turn): a z-buffer";
    case R8_WHY_USER:
        return "given by the user";
    case R8_WHY_RAM:
        return "the exact method does not fit the RAM budget: the best that fits";
    default:
        return "?";
    }
}

r8_s32 two_gap(void)
{
    /* camera depth of each centre: the view axis is camera -> world
     * Ry(yaw) Rx(pitch) applied to +z */
    r8_s16 cp = r8_cos(two_cam.pitch);
    r8_s32 fx = r8_mulq(r8_sin(two_cam.yaw), cp, R8_Q14), fy = -r8_sin(two_cam.pitch);
    r8_s32 fz = r8_mulq(r8_cos(two_cam.yaw), cp, R8_Q14), z[2], g;
    r8_u8 i;
    for (i = 0; i < 2; i++) {
        r8_s32 dx = (r8_s32)obj[i].pose.x - two_cam.x, dy = (r8_s32)obj[i].pose.y - two_cam.y;
        r8_s32 dz = (r8_s32)obj[i].pose.z - two_cam.z;
        dx *= fx;      /* r8_s32 p = a; p *= b: the SDCC-safe product */
        dy *= fy;
        dz *= fz;
        z[i] = r8_asr32(dx + dy + dz + 8192, 14);
    }
    if (z[0] <= z[1])
        g = (z[1] - obj[1].mesh->radius) - (z[0] + obj[0].mesh->radius);
    else
        g = (z[0] - obj[0].mesh->radius) - (z[1] + obj[1].mesh->radius);
    return g;
}
