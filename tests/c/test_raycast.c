/* test_raycast.c - the ray caster (r8ray.h, R8_VIS_RAY): wall heights
 * against the exact figure, no fisheye, no corner skipped, the map's
 * edges and extremes, frames equal across formats and bands, memory
 * bounds, bad configurations; textured walls: u along each face (left
 * to right from outside, every side), texels against the untextured
 * frame's levels, tall walls, IDX8 and 1 bpp textures alike. */
#include "unity.h"
#include "r8ray.h"
#include "r8render.h"

#ifndef R8_NO_RAY

/* an 8 x 8 room, border level 16, a pillar (level 9) at (5, 5) and a
 * corner pair (level 12) at (2, 5) and (3, 4) that touch diagonally */
static const r8_u8 room_cells[64] R8_FLASH = {
    16, 16, 16, 16, 16, 16, 16, 16,
    16, 0, 0, 0, 0, 0, 0, 16,
    16, 0, 0, 0, 0, 0, 0, 16,
    16, 0, 0, 0, 0, 0, 0, 16,
    16, 0, 0, 12, 0, 0, 0, 16,
    16, 0, 12, 0, 0, 9, 0, 16,
    16, 0, 0, 0, 0, 0, 0, 16,
    16, 16, 16, 16, 16, 16, 16, 16
};
static r8_grid room;

/* a 255 x 1 corridor of 128-unit cells, open at both ends (the map's
 * edge is the wall): the longest distance a grid can have */
static const r8_u8 hall_cells[255] R8_FLASH = { 0 };
static r8_grid hall;

#define W 64
#define H 32
#define GUARD 0xA5
static r8_u8 work[8 + 8 * W + 64 + 8];   /* textured: 8 bytes a column */
static r8_u8 band1[8 + W * H + 8], band2[8 + W * H + 8];
static r8_scene scene;
static r8_camera cam;

void setUp(void)
{
    room.cells = room_cells;
    room.w = room.h = 8;
    room.shift = 6;
    room.sx = room.sz = 1;
    room.syaw = 0;
    hall.cells = hall_cells;
    hall.w = 255;
    hall.h = 1;
    hall.shift = 7;
    hall.sx = hall.sz = hall.syaw = 0;
    room.tex = hall.tex = 0;
    room.ntex = hall.ntex = 0;
    scene.objects = 0;
    scene.nobjects = 0;
    scene.grid = &room;
    cam.x = cam.y = cam.z = 0;
    cam.yaw = cam.pitch = cam.roll = cam.flags = 0;
    cam.m = 0;
    cam.focal = W;
    cam.znear = 16;
    cam.zfar = 4096;
}
void tearDown(void) {}

static r8_s16 absdiff(r8_s32 a, r8_s32 b)
{
    return (r8_s16)(a > b ? a - b : b - a);
}

/* A wall straight ahead: h = focal * 64 / depth, exactly (1/16 px). */
static void test_height_straight_ahead(void)
{
    r8_ray_hit hit;
    r8_s16 x;
    cam.x = 224;                    /* 3.5 cells */
    cam.z = 96;                     /* 1.5 cells: the border wall at z = 448 */
    cam.yaw = 0;
    cam.focal = W;
    for (x = 0; x < W; x++) {
        TEST_ASSERT_EQUAL_INT(0, r8_ray_cast(&room, &cam, W, x, &hit));
        if (hit.cz == 4 && hit.cx == 3) {          /* the corner block in front */
            /* its near face at z = 256: depth 160, h = 64 * 64 / 160 = 25.6 px */
            TEST_ASSERT_EQUAL_INT(1, hit.side);
            TEST_ASSERT_EQUAL_UINT(12, hit.cell);
            TEST_ASSERT_TRUE(absdiff(hit.h16, 410) <= 2);
        }
    }
    TEST_ASSERT_EQUAL_INT(0, r8_ray_cast(&room, &cam, W, W / 2, &hit));
    TEST_ASSERT_EQUAL_UINT(3, hit.cx);
    TEST_ASSERT_EQUAL_UINT(4, hit.cz);
}

/* Every column that sees the same flat wall gets the same height: the
 * distance is perpendicular (the seed's Euclidean distance bends it by
 * cos: 8% at this screen's edges). */
static void test_no_fisheye(void)
{
    r8_ray_hit hit;
    r8_s16 x, n = 0;
    cam.x = 96;                     /* cell (1, 1) looking +z: the column */
    cam.z = 96;                     /* x = 1..2 is open to the far wall */
    cam.yaw = 0;
    cam.focal = W;
    for (x = 0; x < W; x++) {
        r8_ray_cast(&room, &cam, W, x, &hit);
        if (hit.cz == 7 && hit.side == 1) {
            /* depth 448 - 96 = 352: h = 64 * 64 / 352 = 11.64 px = 186.2/16 */
            TEST_ASSERT_TRUE(absdiff(hit.h16, 186) <= 2);
            n++;
        }
    }
    TEST_ASSERT_TRUE(n >= 4);
}

/* Left and right mirror each other in a mirrored view. */
static void test_symmetry(void)
{
    r8_ray_hit a, b;
    r8_s16 x;
    cam.x = 256;                    /* the middle of the room, x = 4 cells */
    cam.z = 96;
    cam.yaw = 128;                  /* looking -z at the border wall */
    cam.focal = W;
    for (x = 0; x < W / 2; x++) {
        r8_ray_cast(&room, &cam, W, x, &a);
        r8_ray_cast(&room, &cam, W, (r8_s16)(W - 1 - x), &b);
        TEST_ASSERT_EQUAL_UINT(a.h16, b.h16);
        TEST_ASSERT_EQUAL_UINT(a.cz, b.cz);
    }
}

/* A ray between two blocks that touch at a corner does not slip through
 * (the seed's fixed step does): every direction from below-right of the
 * pair hits one of them or something nearer, never the pillar behind. */
static void test_no_corner_skip(void)
{
    r8_ray_hit hit;
    r8_u8 yaw;
    int hits = 0;
    /* from cell (2, 3) (x 128..191, z 192..255): the corner point is (192, 320) */
    cam.x = 160;
    cam.z = 256 + 16;   /* near the corner's row */
    cam.focal = W;
    for (yaw = 0; yaw < 64; yaw++) {
        cam.yaw = yaw;
        r8_ray_cast(&room, &cam, W, W / 2, &hit);
        TEST_ASSERT_TRUE(hit.cell != 0);
        if (hit.cell == 12)
            hits++;
        /* through the gap at (2,4)-(3,5) would mean cell (3, 5) or beyond */
        TEST_ASSERT_FALSE(hit.cx == 3 && hit.cz >= 5 && hit.cell != 16);
    }
    TEST_ASSERT_TRUE(hits > 0);
}

/* The extremes: against a wall (distance 0: the whole column), the far
 * end of a 255-cell corridor (32640 units: no overflow), off the map. */
static void test_extremes(void)
{
    r8_ray_hit hit;
    cam.focal = W;
    cam.x = 64;                     /* on the boundary of the border wall, */
    cam.z = 200;                    /* looking at it (-x) */
    cam.yaw = 192;
    r8_ray_cast(&room, &cam, W, W / 2, &hit);
    TEST_ASSERT_EQUAL_UINT(0xFFFFu, hit.h16);
    TEST_ASSERT_EQUAL_UINT(0, hit.cx);
    /* the corridor: from x = 64 looking +x, the edge at 32640 */
    cam.x = 64;
    cam.z = 64;
    cam.yaw = 64;
    cam.focal = 2047;
    r8_ray_cast(&hall, &cam, W, W / 2, &hit);
    TEST_ASSERT_EQUAL_UINT(16, hit.cell);
    TEST_ASSERT_EQUAL_UINT(0, hit.side);
    /* h = 2047 * 128 / 32576 = 8.04 px = 128.7/16 */
    TEST_ASSERT_TRUE(absdiff(hit.h16, 129) <= 2);
    /* looking back: the edge at 0, 64 units away: 2047 * 2 px = 65504/16 */
    cam.yaw = 192;
    r8_ray_cast(&hall, &cam, W, W / 2, &hit);
    TEST_ASSERT_TRUE(absdiff(hit.h16, 65504L) <= 16);
    cam.focal = 1;
    r8_ray_cast(&hall, &cam, W, 0, &hit);
    TEST_ASSERT_TRUE(hit.cell != 0);
    /* off the map: no wall */
    cam.focal = W;
    cam.x = -5;
    r8_ray_cast(&room, &cam, W, 3, &hit);
    TEST_ASSERT_EQUAL_UINT(0, hit.h16);
    TEST_ASSERT_EQUAL_UINT(0, hit.cell);
    cam.x = 600;
    r8_ray_cast(&room, &cam, W, 3, &hit);
    TEST_ASSERT_EQUAL_UINT(0, hit.h16);
    /* bad calls */
    TEST_ASSERT_EQUAL_INT(-1, r8_ray_cast(&room, &cam, W, W, &hit));
    TEST_ASSERT_EQUAL_INT(-1, r8_ray_cast(0, &cam, W, 0, &hit));
    cam.focal = 0;
    TEST_ASSERT_EQUAL_INT(-1, r8_ray_cast(&room, &cam, W, 0, &hit));
}

/* (the hooks r8ray.h gives r8_render_*; through those, with the
 * analyser and the names: tests/host/test_ray_render.c.  Here the ray
 * caster alone, small enough for the 6502 and Z80 maps.) */
static void cfg_for(r8_render_cfg *c, r8_u8 format, r8_s16 band)
{
    c->scene = &scene;
    c->method = R8_VIS_RAY;
    c->shading = R8_SHADE_LAMBERT;
    c->cull = R8_CULL_NORMAL;
    c->format = format;
    c->width = W;
    c->height = H;
    c->band = band;
    c->clip = 0;
    c->pool = 0;
}

/* Draw a frame in bands of `band` rows into out (whole frame, format f). */
static void draw(r8_u8 f, r8_s16 band, r8_u8 shading, r8_u8 *out)
{
    r8_render_cfg c;
    r8_render r;
    r8_fb fb;
    r8_s16 y;
    unsigned need, i, bytes = r8_fb_bytes(f, W, band);
    cfg_for(&c, f, band);
    c.shading = shading;
    need = r8_ray_ram(&c);
    TEST_ASSERT_TRUE(need > 0 && need + 16 <= sizeof work);
    for (i = 0; i < sizeof work; i++)
        work[i] = GUARD;
    TEST_ASSERT_EQUAL_INT(0, r8_ray_init(&r, &c, work + 8, need));
    r8_ray_frame(&r, &cam);
    for (y = 0; y < H; y = (r8_s16)(y + band)) {
        r8_u8 *p = out + 8 + r8_fb_bytes(f, W, y);
        if (f == R8_FMT_PAGE1)
            p = out + 8 + (unsigned)W * (unsigned)(y >> 3);
        TEST_ASSERT_EQUAL_INT(0, r8_fb_init(&fb, p, f, W, H, y, band));
        r8_ray_band(&r, &fb);
    }
    (void)bytes;
    for (i = 0; i < 8; i++)
        TEST_ASSERT_EQUAL_HEX8(GUARD, work[i]);
    for (i = 8 + need; i < sizeof work; i++)
        TEST_ASSERT_EQUAL_HEX8(GUARD, work[i]);
}

/* The SSD1306 page path equals the pixel path (row layout), pixel for
 * pixel, and bands of 8 rows equal one band of the whole frame. */
static void test_frame_formats_and_bands(void)
{
    r8_fb a, b;
    r8_s16 x, y;
    r8_u8 yaw, sh;
    unsigned i, lit = 0, n = r8_fb_bytes(R8_FMT_PAGE1, W, H);
    cam.x = 150;
    cam.z = 120;
    cam.focal = W;
    for (sh = 0; sh < 2; sh++)
        for (yaw = 0; yaw < 250; yaw = (r8_u8)(yaw + 50)) {
            cam.yaw = yaw;
            for (i = 0; i < sizeof band1; i++)
                band1[i] = band2[i] = GUARD;
            draw(R8_FMT_PAGE1, 8, sh, band1);
            draw(R8_FMT_PAGE1, H, sh, band2);
            for (i = 0; i < n + 16; i++)
                TEST_ASSERT_EQUAL_HEX8(band1[i], band2[i]);
            for (i = 0; i < 8; i++)
                TEST_ASSERT_EQUAL_HEX8(GUARD, band1[i]);
            for (i = 8 + n; i < sizeof band1; i++)
                TEST_ASSERT_EQUAL_HEX8(GUARD, band1[i]);
            draw(R8_FMT_ROW1, 8, sh, band2);
            r8_fb_init(&a, band1 + 8, R8_FMT_PAGE1, W, H, 0, H);
            r8_fb_init(&b, band2 + 8, R8_FMT_ROW1, W, H, 0, H);
            for (y = 0; y < H; y++)
                for (x = 0; x < W; x++) {
                    TEST_ASSERT_EQUAL_UINT(r8_fb_get(&b, x, y), r8_fb_get(&a, x, y));
                    lit += r8_fb_get(&a, x, y);
                }
            /* the top row is ceiling (black) unless a wall fills it */
        }
    TEST_ASSERT_TRUE(lit > 0);
}

/* The wall's rows: centred, as tall as r8_ray_cast says (flat shading,
 * level 16: solid white; floor: level 2; ceiling: black). */
static void test_column_rows(void)
{
    r8_fb a;
    r8_ray_hit hit;
    r8_s16 x, y, top, bot, half;
    r8_u8 k;
    /* the frame's columns (stepped from column to column) are the
     * columns r8_ray_cast computes alone, at any yaw */
    for (k = 0; k < 9; k++) {
    cam.x = (r8_s16)(96 + 20 * k);
    cam.z = 96;
    cam.yaw = (r8_u8)(k * 29);
    cam.focal = W;
    draw(R8_FMT_IDX8, H, R8_SHADE_FLAT, band1);
    r8_fb_init(&a, band1 + 8, R8_FMT_IDX8, W, H, 0, H);
    for (x = 0; x < W; x++) {
        r8_ray_cast(&room, &cam, W, x, &hit);
        half = (r8_s16)((hit.h16 + 16u) >> 5);
        if (half > H / 2)
            half = H / 2;
        top = (r8_s16)(H / 2 - half);
        bot = (r8_s16)(H / 2 + half);
        for (y = 0; y < H; y++) {
            r8_u8 want = 0;
            if (y >= bot)
                want = 2;
            else if (y >= top)
                want = (r8_u8)(hit.side ? hit.cell - (hit.cell >> 2) : hit.cell);
            TEST_ASSERT_EQUAL_UINT(want, r8_fb_get(&a, x, y));
        }
    }
    }
}

static void test_bad_configs(void)
{
    r8_render_cfg c;
    r8_render r;
    unsigned need;
    cfg_for(&c, R8_FMT_PAGE1, 8);
    need = r8_ray_ram(&c);
    TEST_ASSERT_TRUE(need >= 2u * W && need <= 2u * W + 64u);
    TEST_ASSERT_EQUAL_INT(-2, r8_ray_init(&r, &c, work, need - 1u));
    c.shading = R8_SHADE_GOURAUD;
    TEST_ASSERT_EQUAL_UINT(0, r8_ray_ram(&c));
    TEST_ASSERT_EQUAL_INT(-1, r8_ray_init(&r, &c, work, sizeof work));
    cfg_for(&c, R8_FMT_PAGE1, 8);
    c.method = R8_VIS_CULL;                  /* not the ray caster */
    TEST_ASSERT_EQUAL_UINT(0, r8_ray_ram(&c));
    cfg_for(&c, R8_FMT_PAGE1, 12);          /* not a multiple of 8 */
    TEST_ASSERT_EQUAL_UINT(0, r8_ray_ram(&c));
    cfg_for(&c, R8_FMT_IDX8, 8);
    c.height = 512;
    TEST_ASSERT_EQUAL_UINT(0, r8_ray_ram(&c));
    scene.grid = 0;
    cfg_for(&c, R8_FMT_PAGE1, 8);
    TEST_ASSERT_EQUAL_UINT(0, r8_ray_ram(&c));
    room.shift = 9;
    scene.grid = &room;
    TEST_ASSERT_EQUAL_UINT(0, r8_ray_ram(&c));
    room.shift = 6;
    room.w = 0;
    TEST_ASSERT_EQUAL_UINT(0, r8_ray_ram(&c));
    TEST_ASSERT_EQUAL_INT(0, r8_grid_valid(&room));
    hall.w = 255;
    hall.shift = 8;                          /* 255 << 8 > 32767 */
    TEST_ASSERT_EQUAL_INT(0, r8_grid_valid(&hall));
}

/* Textures: 8 x 8, lit where (tu >= 4) != (tv >= 4) (quadrants), as
 * 1 bpp and as IDX8 (255 / 0): both must draw the same frame. */
static const r8_u8 quad1_d[8] R8_FLASH = {
    0x0F, 0x0F, 0x0F, 0x0F, 0xF0, 0xF0, 0xF0, 0xF0
};
static const r8_u8 quad8_d[64] R8_FLASH = {
    0, 0, 0, 0, 255, 255, 255, 255, 0, 0, 0, 0, 255, 255, 255, 255,
    0, 0, 0, 0, 255, 255, 255, 255, 0, 0, 0, 0, 255, 255, 255, 255,
    255, 255, 255, 255, 0, 0, 0, 0, 255, 255, 255, 255, 0, 0, 0, 0,
    255, 255, 255, 255, 0, 0, 0, 0, 255, 255, 255, 255, 0, 0, 0, 0
};
static r8_texture quad[2];

static void set_tex(r8_u8 fmt)
{
    quad[0].data = fmt == R8_TEX_1BPP ? quad1_d : quad8_d;
    quad[0].wlog = quad[0].hlog = 3;
    quad[0].format = fmt;
    quad[1] = quad[0];
    room.tex = quad;
    room.ntex = 2;
}

/* u: where on the face, left to right seen from outside.  Straight at
 * the corner block's near face (z = 256, x 192..255) from (224, 96):
 * column x sees x_hit = 224 + 160 (2x + 1 - W) / (2 f); u = 4 (x_hit -
 * 192).  From behind it (z = 400, looking -z) the same face's far side
 * (z = 320) reads the other way.  And every face of every frame: u does
 * not fall from one column to the next along one face. */
static void test_tex_u(void)
{
    r8_ray_hit hit, prev;
    r8_s16 x, n = 0;
    r8_u8 k;
    cam.x = 224;
    cam.z = 96;
    cam.yaw = 0;
    cam.focal = W;
    for (x = 0; x < W; x++) {
        r8_s32 xh16 = 224L * 16 + (160L * 16 * (2 * x + 1 - W)) / (2 * W);   /* x_hit, 1/16 */
        r8_ray_cast(&room, &cam, W, x, &hit);
        if (hit.cx == 3 && hit.cz == 4 && hit.side == 1) {
            r8_s32 want = (xh16 - 192L * 16) * 4 / 16;
            TEST_ASSERT_TRUE(absdiff(hit.u, want) <= 1);
            n++;
        }
    }
    TEST_ASSERT_TRUE(n > 10);
    cam.z = 400;
    cam.yaw = 128;
    n = 0;
    for (x = 0; x < W; x++) {
        r8_s32 xh16 = 224L * 16 - (80L * 16 * (2 * x + 1 - W)) / (2 * W);
        r8_ray_cast(&room, &cam, W, x, &hit);
        if (hit.cx == 3 && hit.cz == 4 && hit.side == 1) {
            r8_s32 want = (256L * 16 - xh16) * 4 / 16;
            TEST_ASSERT_TRUE(absdiff(hit.u, want) <= 1);
            n++;
        }
    }
    TEST_ASSERT_TRUE(n > 5);
    for (k = 0; k < 64; k++) {
        cam.x = (r8_s16)(80 + (k & 7) * 40);
        cam.z = (r8_s16)(80 + (k >> 3) * 40);
        if (cam.x >= 448)
            cam.x = 440;
        if (cam.z >= 448)
            cam.z = 440;
        cam.yaw = (r8_u8)(k * 37);
        r8_ray_cast(&room, &cam, W, 0, &prev);
        for (x = 1; x < W; x++) {
            r8_ray_cast(&room, &cam, W, x, &hit);
            /* (a camera in a face's plane, a = 0: u is its own place) */
            if (hit.cell && hit.cx == prev.cx && hit.cz == prev.cz && hit.side == prev.side &&
                hit.h16 != 0xFFFFu)
                TEST_ASSERT_TRUE(hit.u >= prev.u);
            prev = hit;
        }
    }
}

/* A textured frame (IDX8 output: levels) is the untextured (Lambert)
 * frame where the texel is lit and black where it is not: the texel's
 * column from hit.u, its row from the row's place in the wall (above
 * the screen's middle: the texture's top half).  Walls up to touching
 * distance (taller than the screen: v starts inside the texture).  The
 * pages (1 bpp, 8-row bands) equal the pixel path, and a 1 bpp texture
 * draws what its IDX8 twin draws. */
static void test_tex_frame(void)
{
    static r8_u8 flat[8 + W * H + 8];
    r8_fb a, b;
    r8_ray_hit hit;
    r8_s16 x, y;
    r8_u8 k, fmt, seen_tall = 0;
    unsigned lit = 0, dark = 0, i, n = r8_fb_bytes(R8_FMT_PAGE1, W, H);
    for (k = 0; k < 12; k++) {
        cam.focal = W;
        cam.yaw = (r8_u8)(k * 21 + 3);
        cam.x = (r8_s16)(70 + k * 31);
        cam.z = (r8_s16)(66 + k * 13);
        if (k >= 9) {                       /* at the border wall: 1..3 units */
            cam.x = (r8_s16)(64 + k - 8);
            cam.z = 200;
            cam.yaw = (r8_u8)(190 + k);
        }
        room.tex = 0;
        draw(R8_FMT_IDX8, H, R8_SHADE_LAMBERT, flat);
        for (fmt = 0; fmt < 2; fmt++) {
            set_tex(fmt);
            draw(R8_FMT_IDX8, H, R8_SHADE_TEXTURE, band1);
            r8_fb_init(&a, band1 + 8, R8_FMT_IDX8, W, H, 0, H);
            r8_fb_init(&b, flat + 8, R8_FMT_IDX8, W, H, 0, H);
            for (x = 0; x < W; x++) {
                r8_s16 half, top;
                r8_ray_cast(&room, &cam, W, x, &hit);
                half = (r8_s16)((hit.h16 >> 5) + ((hit.h16 >> 4) & 1u));   /* no 16-bit overflow */
                if (half > H / 2) {
                    half = H / 2;
                    seen_tall = 1;
                }
                top = (r8_s16)(H / 2 - half);
                for (y = 0; y < H; y++) {
                    r8_u8 want = (r8_u8)r8_fb_get(&b, x, y);
                    if (y >= top && y < H / 2 + half) {
                        r8_u8 on = (r8_u8)((hit.u >= 128) != (y >= H / 2));
                        if (!on)
                            want = 0;
                        if (on)
                            lit++;
                        else
                            dark++;
                    }
                    TEST_ASSERT_EQUAL_UINT(want, r8_fb_get(&a, x, y));
                }
            }
            /* pages in bands of 8 = one band = the row layout */
            for (i = 0; i < sizeof band1; i++)
                band1[i] = band2[i] = GUARD;
            draw(R8_FMT_PAGE1, 8, R8_SHADE_TEXTURE, band1);
            draw(R8_FMT_PAGE1, H, R8_SHADE_TEXTURE, band2);
            for (i = 0; i < n + 16; i++)
                TEST_ASSERT_EQUAL_HEX8(band1[i], band2[i]);
            for (i = 8 + n; i < sizeof band1; i++)
                TEST_ASSERT_EQUAL_HEX8(GUARD, band1[i]);
            draw(R8_FMT_ROW1, 8, R8_SHADE_TEXTURE, band2);
            r8_fb_init(&a, band1 + 8, R8_FMT_PAGE1, W, H, 0, H);
            r8_fb_init(&b, band2 + 8, R8_FMT_ROW1, W, H, 0, H);
            for (y = 0; y < H; y++)
                for (x = 0; x < W; x++)
                    TEST_ASSERT_EQUAL_UINT(r8_fb_get(&b, x, y), r8_fb_get(&a, x, y));
        }
    }
    room.tex = 0;
    room.ntex = 0;
    TEST_ASSERT_TRUE(seen_tall);
    TEST_ASSERT_TRUE(lit > 1000 && dark > 1000);
}

static void test_tex_configs(void)
{
    r8_render_cfg c;
    unsigned plain, tex;
    cfg_for(&c, R8_FMT_PAGE1, 8);
    plain = r8_ray_ram(&c);
    c.shading = R8_SHADE_TEXTURE;
    TEST_ASSERT_EQUAL_UINT(plain, r8_ray_ram(&c));   /* no textures: as Lambert */
    set_tex(R8_TEX_1BPP);
    tex = r8_ray_ram(&c);
    TEST_ASSERT_TRUE(tex >= plain + 6u * W && tex <= plain + 6u * W + 16u);
    c.shading = R8_SHADE_LAMBERT;                    /* textures unused */
    TEST_ASSERT_EQUAL_UINT(plain, r8_ray_ram(&c));
    c.shading = R8_SHADE_TEXTURE;
    room.ntex = 0;
    TEST_ASSERT_EQUAL_UINT(0, r8_ray_ram(&c));
    room.ntex = 17;
    TEST_ASSERT_EQUAL_UINT(0, r8_ray_ram(&c));
    room.ntex = 2;
    quad[1].wlog = 7;
    TEST_ASSERT_EQUAL_UINT(0, r8_ray_ram(&c));
    quad[1].wlog = 3;
    quad[1].format = 2;
    TEST_ASSERT_EQUAL_UINT(0, r8_ray_ram(&c));
    quad[1].format = R8_TEX_1BPP;
    quad[0].data = 0;
    TEST_ASSERT_EQUAL_UINT(0, r8_ray_ram(&c));
    room.tex = 0;
    room.ntex = 0;
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_height_straight_ahead);
    RUN_TEST(test_no_fisheye);
    RUN_TEST(test_symmetry);
    RUN_TEST(test_no_corner_skip);
    RUN_TEST(test_extremes);
    RUN_TEST(test_frame_formats_and_bands);
    RUN_TEST(test_column_rows);
    RUN_TEST(test_bad_configs);
    RUN_TEST(test_tex_u);
    RUN_TEST(test_tex_frame);
    RUN_TEST(test_tex_configs);
    return UNITY_END();
}

#else
int main(void)
{
    UNITY_BEGIN();
    return UNITY_END();
}
#endif
