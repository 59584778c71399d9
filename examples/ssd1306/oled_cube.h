/* oled_cube.h - the SSD1306 example's application: a shaded, spinning
 * cube (its mesh in flash) drawn band by band straight onto the display,
 * one 8-row band = one SSD1306 page, through ssd1306_page().  No serial
 * viewer, no frame buffer: RAM is the renderer's work memory and one
 * 128-byte page, both in the caller's arena.
 *
 *     static r8_u8 arena[OLED_RAM];       at least oled_cube_ram() bytes
 *     ssd1306_init();
 *     if (oled_cube_init(arena, sizeof arena)) ...too small
 *     for (n = 0;; n++) oled_cube_frame(n);
 *
 * Frame n is the picture of `r8dump --scene cube --frame n` (the same
 * mesh, light, camera and turn per frame), which the tests compare with
 * the display RAM of simavr's SSD1306.
 */
#ifndef OLED_CUBE_H
#define OLED_CUBE_H

#include "r8render.h"

#define OLED_W 128
#define OLED_H 64

/* Arena bytes: the renderer's work memory plus one page (128 bytes);
 * 0 if the library refuses the configuration. */
unsigned oled_cube_ram(void);
/* 0, or -1 if the arena is smaller than oled_cube_ram() (or refused). */
int oled_cube_init(r8_u8 *arena, unsigned size);
/* Pose of frame n (the cube turns 2, 3 and 1 steps a frame about x, y
 * and z), render, and send the 8 pages to the display. */
void oled_cube_frame(r8_u16 n);

#endif
