#!/usr/bin/env bash
# cc65c.sh OBJ SRC CC65-FLAGS...  compiles one C file for the 6502 with
# cc65 + ca65, keeping the intermediate assembly next to OBJ (cl65 -c
# writes it next to the source, which collides in parallel builds and
# litters the source tree).
obj=$1; src=$2; shift 2
cc65 "$@" -o "${obj%.*}.s" "$src" && ca65 -g -t sim6502 -o "$obj" "${obj%.*}.s"
