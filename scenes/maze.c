/* maze.c - the maze demo (R8_DEMO_MAZE): a 16 x 16 grid map for the ray
 * caster (r8ray.h, R8_VIS_RAY).  Written by hand, not by scene.py: it
 * has no meshes.  Cells are 64 world units; the walk starts in cell
 * (1, 1) looking down +z.  Wall levels: 16 the outer wall, 12, 9 and 6
 * inside, so corners and far walls read apart in 1 bpp. */
#include "demo.h"
#include "r8ray.h"

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

/* in RAM like a mesh struct (8 bytes); the cells in flash */
const r8_grid r8_grid_maze = { maze_cells, 16, 16, 6, 1, 1, 0 };

static const char maze_name[] R8_FLASH = "maze";
/* no objects; focal = width (53 degrees across), ambient and light unused */
const r8_demo r8_demo_maze R8_FLASH = {maze_name, 0, 0, 64, 4, 0, {0, 0, 0} R8_DEMO_WORLD(0, 0, 0)};
