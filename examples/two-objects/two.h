/* two.h - two separate convex objects, a cube and an octahedron, each
 * turning in place, one behind the other and overlapping on screen.  The
 * analyser (r8_analyse) chooses the visibility method from the scene and
 * from what the application promises about its camera (an r8_bound):
 * while the objects stay apart in depth by more than one painter's
 * bucket from wherever the camera may be, painter's is exact and needs
 * no depth memory; otherwise it asks for a z-buffer.  C89, the same on
 * every target; the host program is two_host.c.
 */
#ifndef TWO_OBJECTS_H
#define TWO_OBJECTS_H

#include "r8render.h"

#define TWO_W 128
#define TWO_H 64

extern r8_scene two_scene;
extern r8_camera two_cam;

/* The scene and a camera at the origin looking down +z (focal 100 px). */
void two_init(void);
/* Frame n: the cube turns 1 and 2 steps a frame about x and y, the
 * octahedron 2 and 1 about y and z; their positions never change. */
void two_pose(r8_u16 n);
/* The analyser's choice for two_cam moving within b (0: fixed there):
 * method (unless cfg->method is given), band for `budget` bytes, and the
 * depth range, which it also sets as two_cam's znear/zfar.  0, or -1 if
 * nothing fits. */
int two_analyse(r8_render_cfg *cfg, const r8_bound *b, unsigned budget, r8_analysis *a);
/* The reason for a choice (R8_WHY_*), in words. */
const char *two_why(r8_u8 why);
/* The gap along the view axis between the nearer object's farthest point
 * and the farther one's nearest point (bounding spheres), world units,
 * seen from two_cam: what one painter's bucket must not exceed. */
r8_s32 two_gap(void);

#endif
