#!/usr/bin/env bash
# fwdefs.sh S-M-F SIZES  ->  the -D flags of one firmware build:
# scene S, method M, F frames, FW_RAM = the bytes sizes.txt (measured on
# the target by fw_sizes.c) gives for S and M (1 when unknown or 0: the
# firmware then reports APP_E_RAM/APP_E_CFG instead of rendering), and
# the link-time trims of ports/fw_trim.c that apply (-Isrc for r8int.h):
# the renderer built in with every method but M left out, no Gouraud
# (the demo is Lambert), no run-time normals (built-in meshes carry
# theirs), no clipper (the demo camera never sees a face cross the near
# plane or the guard band; the identity tests compare with the host's
# full build).
IFS=- read -r s m f <<< "$1"
ram=$(awk -v s="$s" -v m="$m" '$1==s && $2==m {print $3}' "$2")
case "$ram" in ''|0) ram=1 ;; esac
trim="-Isrc -DFW_TRIM_LZ77 -DFW_RENDER -DR8_NO_GOURAUD -DR8_NO_RT_NORMALS -DR8_NO_CLIP -DR8_PAGE1_ONLY"
[ "$m" != 1 ] && trim="$trim -DR8_NO_PAINTER"
[ "$m" != 2 ] && [ "$m" != 3 ] && trim="$trim -DR8_NO_ZBUF"
[ "$m" != 4 ] && [ "$m" != 5 ] && trim="$trim -DR8_NO_BLOCK"
[ "$m" != 6 ] && trim="$trim -DR8_NO_SBUF"
case "$s" in 4|5) nobj=2 ;; 6) nobj=4 ;; *) nobj=1 ;; esac   # objects per built-in scene
trim="$trim -DR8_DEMO_MAXOBJ=$nobj"
echo "-DFW_SCENE=$s -DFW_METHOD=$m -DFW_FRAMES=$f -DFW_RAM=$ram $trim"
