/* maze.c - the maze demos (R8_DEMO_MAZE, R8_DEMO_TMAZE): a 16 x 16 grid
 * map for the ray caster (r8ray.h, R8_VIS_RAY).  Written by hand, not by
 * scene.py: it has no meshes.  Cells are 64 world units; the walk starts
 * in cell (1, 1) looking down +z.  Wall levels: 16 the outer wall, 12, 9
 * and 6 inside, so corners and far walls read apart in 1 bpp.
 *
 * The textured maze ("tmaze", drawn with R8_SHADE_TEXTURE) is the same
 * map with two textures, made by `rast8 scene texture` from
 * examples/maze/bricks.png (1 bpp, 32 x 32) and panel.png (IDX8,
 * 16 x 16): a wall of value v gets tex[(v - 1) % 2], so the 9s are
 * panels and the others bricks.  A firmware of one of the two
 * (R8_DEMO_ONLY) links only its own grid. */
#include "demo.h"
#include "r8ray.h"

#if !defined(R8_DEMO_ONLY) || R8_DEMO_ONLY == 8 || R8_DEMO_ONLY == 10
static const r8_u8 maze_cells[16 * 16] R8_FLASH = {
    16,16,16,16,16,16,16,16,16,16,16,16,16,16,16,16,
    16, 0, 0, 0,12, 0, 0, 0, 0, 0, 0, 0, 9, 0, 0,16,
    16, 0, 0, 0,12, 0, 9, 9, 9, 0, 0, 0, 9, 0, 0,16,
    16, 0, 0, 0, 0, 0, 0, 0, 9, 0, 6, 0, 0, 0, 0,16,
    16,12,12, 0,12,12, 0, 0, 9, 0, 6, 6, 6, 0, 0,16,
    16, 0, 0, 0, 0,12, 0, 0, 0, 0, 0, 0, 6, 0, 0,16,
    16, 0, 9, 9, 0,12, 0,12,12,12, 0, 0, 0, 0, 9,16,
    16, 0, 9, 0, 0, 0, 0,12, 0, 0, 0, 9, 9, 0, 9,16,
    16, 0, 9, 0, 6, 6, 0,12, 0, 6, 0, 0, 9, 0, 0,16,
    16, 0, 0, 0, 6, 0, 0, 0, 0, 6, 0, 0, 0, 0, 0,16,
    16, 6, 6, 0, 6, 0,12,12, 0, 6, 6, 6,12,12, 0,16,
    16, 0, 0, 0, 0, 0,12, 0, 0, 0, 0, 0, 0,12, 0,16,
    16, 0,12,12,12, 0,12, 0, 9, 9, 9, 0, 0,12, 0,16,
    16, 0, 0, 0,12, 0, 0, 0, 9, 0, 0, 0, 0, 0, 0,16,
    16, 0, 0, 0,12, 0, 0, 0, 9, 0, 0, 6, 0, 0, 0,16,
    16,16,16,16,16,16,16,16,16,16,16,16,16,16,16,16
};

#endif

#if !defined(R8_DEMO_ONLY) || R8_DEMO_ONLY == 8
/* in RAM like a mesh struct; the cells in flash */
const r8_grid r8_grid_maze = { maze_cells, 16, 16, 6, 1, 1, 0, 0, 0 };

static const char maze_name[] R8_FLASH = "maze";
/* no objects; focal = width (53 degrees across), ambient and light unused */
const r8_demo r8_demo_maze R8_FLASH = {maze_name, 0, 0, 64, 4, 0, {0, 0, 0} R8_DEMO_WORLD(0, 0, 0)};
#endif

#if !defined(R8_DEMO_ONLY) || R8_DEMO_ONLY == 10
/* rast8 scene texture --format 1bpp examples/maze/bricks.png */
static const r8_u8 maze_bricks_d[128] R8_FLASH = {
    127, 254, 254, 254, 255, 126, 255, 254, 255, 254, 127, 254, 191, 254, 255, 126,
    255, 190, 255, 254, 255, 254, 191, 254, 223, 254, 255, 190, 0, 0, 0, 0,
    254, 255, 222, 255, 238, 255, 254, 223, 254, 239, 254, 255, 254, 255, 238, 255,
    246, 255, 254, 239, 254, 247, 254, 255, 254, 255, 246, 255, 0, 0, 0, 0,
    255, 250, 255, 254, 255, 254, 251, 254, 253, 254, 255, 250, 255, 252, 255, 254,
    255, 254, 253, 254, 254, 254, 255, 252, 255, 254, 255, 254, 0, 0, 0, 0,
    254, 127, 254, 254, 254, 255, 126, 255, 190, 255, 254, 127, 254, 191, 254, 255,
    254, 255, 190, 255, 222, 255, 254, 191, 254, 223, 254, 255, 0, 0, 0, 0,
};
/* rast8 scene texture examples/maze/panel.png */
static const r8_u8 maze_panel_d[256] R8_FLASH = {
    255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255, 255,
    255, 162, 150, 156, 162, 150, 156, 162, 150, 156, 162, 150, 156, 162, 150, 40,
    255, 150, 156, 162, 150, 156, 162, 150, 156, 162, 150, 156, 162, 150, 156, 40,
    255, 156, 162, 150, 116, 162, 150, 156, 162, 150, 156, 162, 150, 156, 162, 40,
    255, 162, 150, 156, 122, 110, 156, 162, 150, 156, 162, 150, 156, 162, 150, 40,
    255, 150, 156, 162, 150, 116, 122, 150, 156, 162, 150, 156, 162, 150, 156, 40,
    255, 156, 162, 150, 156, 162, 110, 116, 162, 150, 156, 162, 150, 156, 162, 40,
    255, 162, 150, 156, 162, 150, 156, 122, 110, 156, 162, 150, 156, 162, 150, 40,
    255, 150, 156, 162, 150, 156, 162, 150, 116, 122, 150, 156, 162, 150, 156, 40,
    255, 156, 162, 150, 156, 162, 150, 156, 162, 110, 116, 162, 150, 156, 162, 40,
    255, 162, 150, 156, 162, 150, 156, 162, 150, 156, 122, 110, 156, 162, 150, 40,
    255, 150, 156, 162, 150, 156, 162, 150, 156, 162, 150, 116, 162, 150, 156, 40,
    255, 156, 162, 150, 156, 162, 150, 156, 162, 150, 156, 162, 150, 156, 162, 40,
    255, 162, 150, 156, 162, 150, 156, 162, 150, 156, 162, 150, 156, 162, 150, 40,
    255, 150, 156, 162, 150, 156, 162, 150, 156, 162, 150, 156, 162, 150, 156, 40,
    255, 40, 40, 40, 40, 40, 40, 40, 40, 40, 40, 40, 40, 40, 40, 40,
};
/* in RAM like r8_mesh.tex (tex[0] for the 9s, tex[1] for 6, 12 and 16) */
static const r8_texture tmaze_tex[2] = {
    {maze_panel_d, 4, 4, R8_TEX_IDX8}, {maze_bricks_d, 5, 5, R8_TEX_1BPP}
};
const r8_grid r8_grid_tmaze = { maze_cells, 16, 16, 6, 1, 1, 0, tmaze_tex, 2 };

static const char tmaze_name[] R8_FLASH = "tmaze";
const r8_demo r8_demo_tmaze R8_FLASH = {tmaze_name, 0, 0, 64, 4, 0, {0, 0, 0} R8_DEMO_WORLD(0, 0, 0)};
#endif
