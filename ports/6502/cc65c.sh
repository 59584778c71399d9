#!/usr/bin/env bash
# cc65c.sh OBJ SRC CC65-FLAGS...  compiles one C file for the 6502 with
# cc65 + ca65, keeping the intermediate assembly next to OBJ (cl65 -c
# writes it next to the source, which collides in parallel builds and
# litters the source tree).
# Per-file flags (measured with bench/kern6502.py's cube / cull build):
#   wire.c  --codesize 200: the band walk's glue inlined (cc65 expands
#           the 32-bit adds and struct accesses instead of calling its
#           runtime): -11 k cycles a frame for +1.3 KB of image.
#           The other hot files gain nothing measurable from it.
obj=$1; src=$2; shift 2
extra=
case $(basename "$src") in
  wire.c) extra="--codesize 200" ;;
esac
cc65 "$@" $extra -o "${obj%.*}.s" "$src" && ca65 -g -t sim6502 -o "$obj" "${obj%.*}.s"
