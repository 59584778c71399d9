#!/usr/bin/env bash
# fwdefs.sh S-M-F[-SH[-W[-O]]] SIZES [TARGET]  ->  the -D flags of one firmware
# build: scene S, method M, F frames, W = 1 the wireframe (cfg.wire;
# else R8_NO_WIRE leaves wireframe, Wu and circles out), FW_RAM = the bytes sizes.txt (measured on
# the target by fw_sizes.c) gives for S and M (1 when unknown or 0: the
# firmware then reports APP_E_RAM/APP_E_CFG instead of rendering), and
# the link-time trims of ports/fw_trim.c that apply (-Isrc for r8int.h):
# the renderer built in with every method but M left out, no Gouraud
# (the demo is Lambert), no run-time normals (built-in meshes carry
# theirs), no clipper (the demo camera never sees a face cross the near
# plane or the guard band; the identity tests compare with the host's
# full build); in a mesh scene's firmware no camera rotation and no
# 32-bit projection (FW_SPIN: the firmware proves both unneeded).  On the 2 KB ATmega328P (TARGET avr328): no scan-state
# pool (R8_NO_POOL: its code left out too) and 8-bit face ids
# (R8_SMALL_SCENE), the least RAM; fw_sizes.c
# measures the same (XSIZES_avr328 in mk/targets.mk).
SMALL328="-DFW_POOL=0 -DR8_NO_POOL -DR8_SMALL_SCENE"
[ "$1" = --small328 ] && { echo "$SMALL328"; exit 0; }
IFS=- read -r s m f sh w o <<< "$1"
sizes=$2
[ "${sh:-1}" = 2 ] && sizes=${2%.txt}-sh2.txt
ram=$(awk -v s="$s" -v m="$m" '$1==s && $2==m {print $3}' "$sizes")
case "$ram" in ''|0) ram=1 ;; esac
trim="-Isrc -DFW_TRIM_LZ77 -DR8_NO_LZ77 -DFW_RENDER -DR8_NO_RT_NORMALS -DR8_NO_CLIP -DR8_PAGE1_ONLY -DR8_NO_HUFF -DR8_NO_LZW"
# SH: shading (R8_SHADE_*: 0 flat, 1 Lambert, 2 Gouraud; default Lambert,
# the demo's; make bench builds the others: fw-S-M-F-SH; Gouraud's
# arena from sizes-sh2.txt beside SIZES)
case "${sh:-1}" in
  2) trim="$trim -DFW_SHADING=2" ;;
  0) trim="$trim -DFW_SHADING=0 -DR8_NO_GOURAUD" ;;
  *) trim="$trim -DR8_NO_GOURAUD" ;;
esac
[ "$m" != 1 ] && [ "$m" != 7 ] && trim="$trim -DR8_NO_PAINTER"   # BSP draws with painter's path
[ "$m" != 7 ] && trim="$trim -DR8_NO_BSP"
[ "$m" != 2 ] && [ "$m" != 3 ] && trim="$trim -DR8_NO_ZBUF"
[ "$m" != 4 ] && [ "$m" != 5 ] && trim="$trim -DR8_NO_BLOCK"
[ "$m" != 6 ] && trim="$trim -DR8_NO_SBUF"
if [ "${w:-0}" = 1 ]; then trim="$trim -DFW_WIRE=1"; else trim="$trim -DR8_NO_WIRE"; fi
# the crate (R8_DEMO_CRATE) is drawn textured (fw_app.c); no other
# firmware carries texture mapping
[ "$s" != 7 ] && trim="$trim -DR8_NO_TEXTURE"
[ "$s" = 10 ] && trim="$trim -DR8_RAY_TEXTURE"   # the textured maze: the ray caster's textures only
[ "$m" != 17 ] && trim="$trim -DR8_NO_RAY"   # the ray caster: the maze's firmware only
# the portal renderer (16): left out of every other firmware; its own
# firmware keeps the clipper (the floor and ceiling round the camera)
# (the rooms, scene 9, a world: every method of it keeps both)
[ "$m" != 16 ] && [ "$s" != 9 ] && trim="$trim -DR8_NO_PORTAL"
[ "$s" = 9 ] && trim="${trim/ -DR8_NO_CLIP/}"
# a mesh scene (objects that only turn, the camera stays put; not the
# walks 8, 10): no camera rotation, no 32-bit projection, the firmware
# checking both (FW_SPIN, fw_trim.c)
case "$trim" in *R8_NO_PORTAL*) [ "$m" != 17 ] && [ "$s" != 8 ] && [ "$s" != 10 ] && trim="$trim -DFW_SPIN" ;; esac
# scenes whose meshes have at most 8 faces (cube, wall, separate, crate):
# the face-walk kernel (r8k_fwalk) buys the cube ~200 cycles a frame for
# ~1 KB of flash, so these keep r8_bucket_object's C loop (R8_NO_FWALK)
case "$s" in 0|4|6|7) trim="$trim -DR8_NO_FWALK" ;; esac
# a mesh scene: its objects, vertices and faces as constants (the demo
# firmware's plan, src/render.c R8_CFG_NVERTS; cfg_valid checks them)
case "$trim" in *R8_NO_PORTAL*) trim="$trim $(python3 ports/scene_strip.py "$s" --counts)" ;; esac
case "$s" in 4|5) nobj=2 ;; 6|9) nobj=4 ;; *) nobj=1 ;; esac   # objects per built-in scene
trim="$trim -DR8_DEMO_MAXOBJ=$nobj"
# O = 0: a world's walls alone, without its movable objects (make bench-portal)
[ "${o:-1}" = 0 ] && trim="$trim -DFW_WALLS_ALONE"
# (the 2 KB part without FW_SPIN: proj.c built into the firmware unit is
# inlined into the vertex transform, 22 B more stack on the deepest call
# chain; the 328P torus painter's would keep 57 B free, not 64)
[ "${3:-}" = avr328 ] && trim="${trim/ -DFW_SPIN/} $SMALL328"
# the 328P's block methods (whose frames go to the block buffer, not the
# face walk's fast path) and the terrain's painter's (the largest mesh
# tables) leave the face walk and its vertex kernel out: ~2 KB of flash
# they need to fit the 32 KB part (cross / block 604 B over, terrain /
# painter's 62 B)
[ "${3:-}" = avr328 ] && { [ "$m" = 4 ] || [ "$m" = 5 ] || [ "$s-$m" = 3-1 ]; } && case "$trim" in
  *R8_NO_FWALK*) ;; *) trim="$trim -DR8_NO_FWALK" ;; esac
echo "-DFW_SCENE=$s -DFW_METHOD=$m -DFW_FRAMES=$f -DFW_RAM=$ram $trim"
