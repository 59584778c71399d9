#!/usr/bin/env bash
# fwdefs.sh S-M-F SIZES  ->  the -D flags of one firmware build:
# scene S, method M, F frames, FW_RAM = the bytes sizes.txt (measured on
# the target by fw_sizes.c) gives for S and M (1 when unknown or 0: the
# firmware then reports APP_E_RAM/APP_E_CFG instead of rendering), and
# the link-time trims of ports/fw_trim.c that apply (-Isrc for r8int.h).
IFS=- read -r s m f <<< "$1"
ram=$(awk -v s="$s" -v m="$m" '$1==s && $2==m {print $3}' "$2")
case "$ram" in ''|0) ram=1 ;; esac
trim="-Isrc -DFW_TRIM_LZ77"
[ "$m" != 6 ] && trim="$trim -DFW_TRIM_SBUF"
echo "-DFW_SCENE=$s -DFW_METHOD=$m -DFW_FRAMES=$f -DFW_RAM=$ram $trim"
