/* test_portal_obj.c - movable objects in the portal renderer's world
 * (R8_VIS_PORTAL): the built-in rooms walk with its three objects (a box
 * that goes through the door between rooms r00 and r10, a spinning gem
 * in r11, a box through the door between r01 and r02) against the
 * 16-bit z-buffer drawing the same walls and objects.  The walls are
 * drawn black and each object in a level of its own (flat shading, 8
 * bits a pixel), so a frame shows exactly which object is where.  Also:
 * objects in sectors not seen are not transformed (the portal stats);
 * an object that straddles a door; a mesh that is not convex (painter's
 * order inside it); band heights; memory; no write outside the band.
 * --measure prints the per-frame figures. */
#include <stdio.h>
#include <string.h>
#include "unity.h"
#include "r8render.h"
#include "r8portal.h"
#include "demo.h"

#define W 128
#define H 64
#define NPATH (48 * R8_PATH_STEPS)
#define NOBJ 3                  /* the rooms' movable objects: run.obj[1..3] */
#define GUARD 64

static const r8_u8 colour[NOBJ] = {16, 12, 6};
static r8_u8 work[32768 + 64];
static r8_u8 ref[W * H], img[W * H];
static r8_u8 bandmem[GUARD + W * H + GUARD];
static int measure;
static r8_demo_run run;
static r8_portal_stats last;
static r8_face blackf[400];
static r8_mesh bworld, bwalls;
static r8_world bw;

void setUp(void) {}
void tearDown(void) {}

/* The rooms with black walls and each object in its own level. */
static void cfg_for(r8_render_cfg *c, r8_u8 method, r8_s16 band)
{
    r8_u16 k;
    r8_u8 i;
    r8_render_defaults(c);
    TEST_ASSERT_EQUAL_INT(0, r8_demo_setup(&run, r8_demo_get(R8_DEMO_ROOMS), W));
    TEST_ASSERT_EQUAL_INT(1 + NOBJ, run.scene.nobjects);
    TEST_ASSERT_TRUE(run.scene.world->mesh->nfaces <= 400);
    bworld = *run.scene.world->mesh;
    bw = *run.scene.world;
    bwalls = *run.obj[0].mesh;
    for (k = 0; k < bworld.nfaces; k++) {
        blackf[k] = bworld.faces[k];
        blackf[k].colour = 0;
    }
    bworld.faces = bwalls.faces = blackf;
    bw.mesh = &bworld;
    run.scene.world = &bw;
    run.obj[0].mesh = &bwalls;
    for (i = 0; i < NOBJ; i++) {
        run.obj[1 + i].pose.flags |= R8_POSE_COLOUR;
        run.obj[1 + i].pose.colour = colour[i];
    }
    c->scene = &run.scene;
    c->method = method;
    c->format = R8_FMT_IDX8;
    c->shading = R8_SHADE_FLAT;
    c->band = band;
    c->clip = 24;
}

/* The current poses and camera into out (frame by frame: bands); 0 or
 * the init error.  The band lies between guard bytes that must not
 * change. */
static int draw(const r8_render_cfg *cfg, r8_u8 *out)
{
    r8_render r;
    r8_fb band;
    r8_s16 y;
    unsigned i;
    r8_u8 *bandbuf = bandmem + GUARD;
    int e = r8_render_init(&r, cfg, work, sizeof work);
    if (e)
        return e;
    memset(bandmem, 0x5A, sizeof bandmem);
    r8_render_frame(&r, &run.cam);
    r8_fb_init(&band, bandbuf, cfg->format, cfg->width, cfg->height, 0, cfg->band);
    for (y = 0; y < cfg->height; y = (r8_s16)(y + cfg->band)) {
        r8_fb_set_band(&band, y);
        r8_render_band(&r, &band);
        memcpy(out + (unsigned)y * W, bandbuf, (size_t)W * (size_t)cfg->band);
    }
    for (i = 0; i < GUARD; i++) {
        TEST_ASSERT_EQUAL_INT(0x5A, bandmem[i]);
        TEST_ASSERT_EQUAL_INT(0x5A, bandmem[GUARD + (unsigned)W * (unsigned)cfg->band + i]);
    }
    if (cfg->method == R8_VIS_PORTAL)
        TEST_ASSERT_EQUAL_INT(0, r8_portal_stats_get(&r, &last));
    return 0;
}

static int render(const r8_render_cfg *cfg, r8_u16 frame, r8_u8 *out)
{
    r8_demo_pose(&run, frame);
    return draw(cfg, out);
}

/* Pixels of level v in a frame. */
static long count(const r8_u8 *a, r8_u8 v)
{
    long n = 0;
    unsigned i;
    for (i = 0; i < W * H; i++)
        n += a[i] == v;
    return n;
}

/* Pixels where a shows level v and b does not, and the other way. */
static long only_in(const r8_u8 *a, const r8_u8 *b, r8_u8 v)
{
    long n = 0;
    unsigned i;
    for (i = 0; i < W * H; i++)
        n += a[i] == v && b[i] != v;
    return n;
}

/* Object i's sector and whether a corner of it lies behind a face plane
 * of that sector (it straddles a door: its origin decides its sector). */
static r8_u8 sector_of(r8_u8 i, int *straddles)
{
    const r8_world *w = run.scene.world;
    const r8_pose *p = &run.obj[1 + i].pose;
    const r8_mesh *me = run.obj[1 + i].mesh;
    r8_u8 s = r8_portal_locate(w, p->x, p->y, p->z);
    const r8_sector *sec = &w->sectors[s];
    r8_mat3 m;
    r8_u16 k, part, f0, nf, c;
    r8_mat_rotate(&m, p->ax, p->ay, p->az);
    *straddles = 0;
    for (c = 0; c < me->nverts; c++) {
        const r8_s16 *mv = me->verts + 3u * c;
        long q[3];
        for (k = 0; k < 3; k++)
            q[k] = ((long)m.m[3 * k] * mv[0] + (long)m.m[3 * k + 1] * mv[1] +
                    (long)m.m[3 * k + 2] * mv[2]) / 16384L + (&p->x)[k];
        for (part = 0; part < 2; part++) {
            f0 = part ? sec->portal0 : sec->wall0;
            nf = part ? sec->nportals : sec->nwalls;
            for (k = f0; k < f0 + nf; k++) {
                const r8_s16 *v = w->mesh->verts + 3u * w->mesh->faces[k].v[0];
                const r8_s16 *n = w->mesh->normals + 3u * k;
                if (n[0] * (q[0] - v[0]) + n[1] * (q[1] - v[1]) + n[2] * (q[2] - v[2]) < 16384L)
                    *straddles = 1;
            }
        }
    }
    return s;
}

/* The whole walk: every object pixel is where zbuf16 puts it (walls are
 * black, so the frames are equal but for a straddling object: drawn
 * only in its own sector's region, so it may lose pixels, never gain
 * them); objects in sectors not seen are not transformed, and zbuf16
 * shows none of them; the moving box is seen in both its rooms. */
static void test_walk_objects_where_zbuf16_puts_them(void)
{
    r8_render_cfg zc, pc;
    r8_u16 f;
    long straddle_frames = 0, unseen_frames = 0, lost = 0;
    int shown[NOBJ][9];
    r8_u8 i;
    memset(shown, 0, sizeof shown);
    cfg_for(&zc, R8_VIS_Z16, 8);
    cfg_for(&pc, R8_VIS_PORTAL, 8);
    for (f = 0; f < NPATH; f++) {
        long d;
        int any_straddle = 0;
        TEST_ASSERT_EQUAL_INT(0, render(&zc, f, ref));
        TEST_ASSERT_EQUAL_INT(0, render(&pc, f, img));
        TEST_ASSERT_EQUAL_INT(0, last.dropped);
        TEST_ASSERT_EQUAL_INT(NOBJ, last.objects + last.unseen);
        if (last.objects == 0) {
            TEST_ASSERT_EQUAL_INT(0, last.overts);
            TEST_ASSERT_EQUAL_INT(0, last.opolys);
            unseen_frames++;
        }
        for (i = 0; i < NOBJ; i++) {
            int st;
            r8_u8 s = sector_of(i, &st);
            long zp = count(ref, colour[i]), pp = count(img, colour[i]);
            long miss = only_in(ref, img, colour[i]), extra = only_in(img, ref, colour[i]);
            if (measure && (miss || extra))
                printf("frame %u object %u sector %u%s: zbuf16 %ld px, portal %ld, missing %ld, extra %ld\n",
                       (unsigned)f, i, s, st ? " (straddles)" : "", zp, pp, miss, extra);
            if (st) {
                any_straddle = 1;
                TEST_ASSERT_EQUAL_INT(0, extra);
                lost += miss;
            } else {
                TEST_ASSERT_EQUAL_INT(0, miss);
                TEST_ASSERT_EQUAL_INT(0, extra);
            }
            if (zp)
                shown[i][s] = 1;
        }
        d = 0;
        {
            unsigned k;
            for (k = 0; k < W * H; k++)
                d += ref[k] != img[k];
        }
        if (!any_straddle)
            TEST_ASSERT_EQUAL_INT(0, d);
        else
            straddle_frames++;
    }
    if (measure)
        printf("walk: %u frames, %ld with an object straddling a door (%ld object pixels lost), "
               "%ld with every object unseen\n", (unsigned)NPATH, straddle_frames, lost, unseen_frames);
    TEST_ASSERT_TRUE(unseen_frames > 0);
    TEST_ASSERT_TRUE(straddle_frames > 0);
    /* the first box is seen in r00 and in r10 (sectors 0 and 1), the
     * second in r01 and r02 (3 and 6), the gem in r11 (4) */
    TEST_ASSERT_TRUE(shown[0][0] && shown[0][1]);
    TEST_ASSERT_TRUE(shown[2][3] && shown[2][6]);
    TEST_ASSERT_TRUE(shown[1][4]);
}

/* An object in a sector the walk does not reach this frame is not
 * transformed and changes nothing; zbuf16 does not show it either. */
static void test_unseen_object_not_transformed(void)
{
    r8_render_cfg pc, zc;
    static r8_u8 without[W * H];
    r8_u8 s;
    cfg_for(&pc, R8_VIS_PORTAL, 8);
    r8_demo_pose(&run, 0);
    /* in r00, looking north (+z) at the door to r01 */
    run.cam.x = 3;
    run.cam.z = 5;
    run.cam.yaw = 0;
    /* the gem behind r00's north wall, in r11, in front of the camera */
    run.obj[2].pose.x = 180;
    run.obj[2].pose.z = 300;
    s = r8_portal_locate(run.scene.world, 180, 10, 300);
    TEST_ASSERT_EQUAL_INT(4, s);
    run.obj[1].pose.flags |= R8_POSE_HIDDEN;
    run.obj[3].pose.flags |= R8_POSE_HIDDEN;
    TEST_ASSERT_EQUAL_INT(0, draw(&pc, img));
    TEST_ASSERT_EQUAL_INT(0, last.sector);
    TEST_ASSERT_EQUAL_INT(0, last.objects);
    TEST_ASSERT_EQUAL_INT(1, last.unseen);
    TEST_ASSERT_EQUAL_INT(0, last.overts);
    TEST_ASSERT_EQUAL_INT(0, last.opolys);
    TEST_ASSERT_TRUE(last.visits >= 2);     /* r01 is seen through the door */
    run.obj[2].pose.flags |= R8_POSE_HIDDEN;
    TEST_ASSERT_EQUAL_INT(0, draw(&pc, without));
    TEST_ASSERT_EQUAL_INT(0, last.unseen);
    TEST_ASSERT_EQUAL_INT(0, memcmp(img, without, sizeof img));
    run.obj[2].pose.flags &= (r8_u8)~R8_POSE_HIDDEN;
    zc = pc;
    zc.method = R8_VIS_Z16;
    TEST_ASSERT_EQUAL_INT(0, draw(&zc, ref));
    TEST_ASSERT_EQUAL_INT(0, count(ref, colour[1]));
    /* moved into r01, which is seen: transformed and drawn */
    run.obj[2].pose.x = 20;
    run.obj[2].pose.z = 300;
    TEST_ASSERT_EQUAL_INT(0, draw(&pc, img));
    TEST_ASSERT_EQUAL_INT(1, last.objects);
    TEST_ASSERT_EQUAL_INT(0, last.unseen);
    TEST_ASSERT_TRUE(last.overts >= 3 && last.overts <= 6);
    TEST_ASSERT_TRUE(last.opolys >= 1 && last.opolys <= 8);
    TEST_ASSERT_TRUE(count(img, colour[1]) > 0);
    TEST_ASSERT_EQUAL_INT(0, draw(&zc, ref));
    TEST_ASSERT_EQUAL_INT(0, memcmp(img, ref, sizeof img));
}

/* A box straddling the door between r00 and r10 (x = 128, the door
 * spans z -48..48): seen from the room that holds its origin it is
 * whole; seen from the other room it is drawn inside the door only, so
 * a part on the camera's side of the door that is seen beside the door
 * (the box at the door's edge, z 34..54) is lost (the documented
 * limit).  Never a pixel where zbuf16 has none. */
static void test_straddling_object(void)
{
    r8_render_cfg pc, zc;
    static const struct { r8_s16 ox, oz, cx; r8_u8 yaw; int whole; } cases[6] = {
        {124, 0, 3, 64, 1},      /* origin in r00, camera in r00 looking east */
        {132, 0, 227, 192, 1},   /* origin in r10, camera in r10 looking west */
        {132, 0, 3, 64, 1},      /* origin in r10, camera in r00: all of it
                                    is seen inside the door */
        {124, 0, 227, 192, 1},   /* and the other way */
        {132, 44, 3, 64, 0},     /* at the door's edge: cut to the door */
        {124, 44, 227, 192, 0},
    };
    r8_u8 k;
    for (k = 0; k < 6; k++) {
        long zp, pp;
        int st;
        cfg_for(&pc, R8_VIS_PORTAL, 8);
        r8_demo_pose(&run, 0);
        run.obj[2].pose.flags |= R8_POSE_HIDDEN;
        run.obj[3].pose.flags |= R8_POSE_HIDDEN;
        run.obj[1].pose.x = cases[k].ox;
        run.obj[1].pose.z = cases[k].oz;
        run.obj[1].pose.ay = 0;
        run.cam.x = cases[k].cx;
        run.cam.z = 5;
        run.cam.yaw = cases[k].yaw;
        TEST_ASSERT_EQUAL_INT(cases[k].ox < 128 ? 0 : 1, sector_of(0, &st));
        TEST_ASSERT_TRUE(st);
        zc = pc;
        zc.method = R8_VIS_Z16;
        TEST_ASSERT_EQUAL_INT(0, draw(&zc, ref));
        TEST_ASSERT_EQUAL_INT(0, draw(&pc, img));
        TEST_ASSERT_EQUAL_INT(1, last.objects);
        zp = count(ref, colour[0]);
        pp = count(img, colour[0]);
        if (measure)
            printf("straddle case %u: zbuf16 %ld px, portal %ld\n", k, zp, pp);
        TEST_ASSERT_TRUE(zp > 50);
        TEST_ASSERT_EQUAL_INT(0, only_in(img, ref, colour[0]));
        if (cases[k].whole)
            TEST_ASSERT_EQUAL_INT(0, memcmp(img, ref, sizeof img));
        else
            TEST_ASSERT_TRUE(pp < zp);
    }
}

/* A mesh that is not convex: two boxes one behind the other (one mesh),
 * the far one partly hidden; painter's order inside the mesh draws it as
 * zbuf16 does. */
static r8_s16 twov[16 * 3];
static r8_face twof[12];
static r8_s16 twon[12 * 3];
static r8_mesh two;

static void test_not_convex_mesh(void)
{
    static const r8_s8 cv[8][3] = {
        {-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
        {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
    static const r8_u8 cf[6][4] = {
        {0, 1, 2, 3}, {5, 4, 7, 6}, {1, 5, 6, 2}, {4, 0, 3, 7}, {4, 5, 1, 0}, {3, 2, 6, 7}};
    r8_render_cfg pc, zc;
    r8_u8 b, k, j;
    for (b = 0; b < 2; b++) {
        for (k = 0; k < 8; k++) {
            twov[3 * (8 * b + k)] = (r8_s16)(cv[k][0] * 8 + (b ? 6 : -6));
            twov[3 * (8 * b + k) + 1] = (r8_s16)(cv[k][1] * 8);
            twov[3 * (8 * b + k) + 2] = (r8_s16)(cv[k][2] * 8 + (b ? -20 : 20));
        }
        for (k = 0; k < 6; k++) {
            twof[6 * b + k].n = 4;
            twof[6 * b + k].colour = (r8_u8)(b ? 16 : 8);
            for (j = 0; j < 4; j++)
                twof[6 * b + k].v[j] = (r8_u8)(cf[k][j] + 8 * b);
        }
    }
    memset(&two, 0, sizeof two);
    two.verts = twov;
    two.faces = twof;
    two.nverts = 16;
    two.nfaces = 12;
    two.convex = 0;
    two.radius = 40;
    r8_mesh_normals(&two, twon);
    two.normals = twon;
    cfg_for(&pc, R8_VIS_PORTAL, 8);
    r8_demo_pose(&run, 0);
    run.obj[2].pose.flags |= R8_POSE_HIDDEN;
    run.obj[3].pose.flags |= R8_POSE_HIDDEN;
    run.obj[1].mesh = &two;
    run.obj[1].pose.flags &= (r8_u8)~R8_POSE_COLOUR;
    run.obj[1].pose.x = 70;
    run.obj[1].pose.y = 10;
    run.obj[1].pose.z = 0;
    run.cam.x = 3;
    run.cam.z = 5;
    for (k = 0; k < 8; k++) {
        long near_px;
        run.cam.yaw = (r8_u8)(56 + 2 * k);
        run.obj[1].pose.ay = (r8_u8)(32 * k);
        zc = pc;
        zc.method = R8_VIS_Z16;
        TEST_ASSERT_EQUAL_INT(0, draw(&zc, ref));
        TEST_ASSERT_EQUAL_INT(0, draw(&pc, img));
        TEST_ASSERT_EQUAL_INT(1, last.objects);
        near_px = count(ref, 16) + count(ref, 8);
        TEST_ASSERT_TRUE(near_px > 100);
        TEST_ASSERT_EQUAL_INT(0, memcmp(img, ref, sizeof img));
    }
}

/* Band heights change nothing (8, 16, 64 rows; every 8th frame). */
static void test_bands_agree(void)
{
    static r8_u8 full[W * H];
    r8_render_cfg c;
    r8_u16 f;
    for (f = 0; f < NPATH; f = (r8_u16)(f + 8)) {
        cfg_for(&c, R8_VIS_PORTAL, 64);
        TEST_ASSERT_EQUAL_INT(0, render(&c, f, full));
        cfg_for(&c, R8_VIS_PORTAL, 8);
        TEST_ASSERT_EQUAL_INT(0, render(&c, f, img));
        TEST_ASSERT_EQUAL_INT(0, memcmp(full, img, sizeof img));
        cfg_for(&c, R8_VIS_PORTAL, 16);
        TEST_ASSERT_EQUAL_INT(0, render(&c, f, img));
        TEST_ASSERT_EQUAL_INT(0, memcmp(full, img, sizeof img));
    }
}

/* The objects' memory is counted: more than the walls alone, guard
 * bytes past r8_render_ram never change, one byte less is refused. */
static void test_memory(void)
{
    r8_render_cfg c;
    r8_render r;
    unsigned need, walls, i;
    r8_u16 f;
    cfg_for(&c, R8_VIS_PORTAL, 8);
    need = r8_render_ram(&c);
    run.scene.nobjects = 1;
    walls = r8_render_ram(&c);
    run.scene.nobjects = 1 + NOBJ;
    if (measure)
        printf("work: %u bytes with the objects, %u without\n", need, walls);
    TEST_ASSERT_TRUE(walls > 0 && need > walls && need + 64 <= sizeof work);
    for (f = 0; f < NPATH; f = (r8_u16)(f + 24)) {
        r8_fb band;
        r8_s16 y;
        memset(work, 0xA5, sizeof work);
        TEST_ASSERT_EQUAL_INT(0, r8_render_init(&r, &c, work, need));
        r8_demo_pose(&run, f);
        r8_render_frame(&r, &run.cam);
        r8_fb_init(&band, bandmem + GUARD, c.format, W, H, 0, c.band);
        for (y = 0; y < H; y = (r8_s16)(y + c.band)) {
            r8_fb_set_band(&band, y);
            r8_render_band(&r, &band);
        }
        for (i = need; i < need + 64; i++)
            TEST_ASSERT_EQUAL_INT(0xA5, work[i]);
    }
    TEST_ASSERT_EQUAL_INT(-2, r8_render_init(&r, &c, work, need - 1));
}

int main(int argc, char **argv)
{
    measure = argc > 1 && strcmp(argv[1], "--measure") == 0;
    UNITY_BEGIN();
    RUN_TEST(test_walk_objects_where_zbuf16_puts_them);
    RUN_TEST(test_unseen_object_not_transformed);
    RUN_TEST(test_straddling_object);
    RUN_TEST(test_not_convex_mesh);
    RUN_TEST(test_bands_agree);
    RUN_TEST(test_memory);
    return UNITY_END();
}
