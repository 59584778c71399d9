/* r8config.h - what this build of the library carries.  Leave parts out
 * to save flash (docs/benchmarks.md lists what each costs): define the
 * switches here, or on the compiler's command line (-DR8_NO_SBUF ...).
 * A configuration that asks for a part left out is refused by
 * r8_render_init / r8_render_ram (they return -1 / 0).
 *
 *   R8_NO_PAINTER     painter's algorithm
 *   R8_NO_ZBUF        8- and 16-bit z-buffers
 *   R8_NO_BLOCK       4x4-block z-buffers (both)
 *   R8_NO_SBUF        S-buffer
 *   R8_NO_BSP         BSP order (R8_VIS_BSP; meshes link no trees)
 *   R8_NO_GOURAUD     Gouraud shading
 *   R8_NO_CLIP        the clipper: faces crossing the near plane or the
 *                     guard band are dropped (and counted) instead
 *   R8_NO_RT_NORMALS  meshes must carry their face normals (the scene
 *                     converter writes them); none are computed
 *   R8_SMALL_SCENE    8-bit face ids: at most 254 faces and clipped
 *                     polygons per scene, 1 byte per face less RAM
 *   R8_NO_POOL        no scan-state pool (cfg.pool is taken as 0: each
 *                     face's scan is set up again in every band it
 *                     crosses; the least RAM, slower on tall faces)
 *   R8_NO_LZ77        the LZ77 codec (RLE and raw stay)
 *   R8_NO_HUFF        the static Huffman codec (src/huff.c, 1 KB of tables)
 *   R8_NO_LZW         the LZW codec (src/lzw.c); without both, the wire
 *                     encoder has no per-band choice (R8_CODEC_BEST)
 *   R8_PAGE1_ONLY     the renderer draws the SSD1306 page layout only
 *   R8_NO_WIRE        wireframe (cfg.wire is then ignored), Wu's lines
 *                     and circles (r8_wu_line, r8_circle*)
 *   R8_NO_TEXTURE     texture mapping (R8_SHADE_TEXTURE)
 *   R8_NO_PORTAL      the portal renderer (R8_VIS_PORTAL, r8portal.h)
 *   R8_NO_RAY         the ray caster (R8_VIS_RAY, r8ray.h)
 */
#ifndef R8CONFIG_H
#define R8CONFIG_H

#ifdef R8_ARDUINO_PRESET
/* the Arduino library zip (make arduino): on an ATmega328P (32 KB of
 * flash, 2 KB of RAM: no room for a z-buffer band anyway) cull and
 * painter's with flat and Lambert shading into the SSD1306 page layout,
 * RLE on the wire, meshes with their normals (the scene converter's),
 * no clipper (keep the camera off the geometry), no wireframe, Wu's
 * lines or circles, no texture, BSP, portal or ray caster; edit here
 * for more */
#define R8_NO_ZBUF
#define R8_NO_BLOCK
#define R8_NO_SBUF
#define R8_NO_BSP
#define R8_NO_GOURAUD
#define R8_NO_TEXTURE
#define R8_NO_CLIP
#define R8_NO_LZ77
#define R8_NO_HUFF
#define R8_NO_LZW
#define R8_NO_RT_NORMALS
#define R8_PAGE1_ONLY
#define R8_NO_PORTAL
#define R8_NO_WIRE
#define R8_NO_RAY
#endif

#endif
