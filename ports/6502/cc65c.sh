#!/usr/bin/env bash
# cc65c.sh OBJ SRC CC65-FLAGS...  compiles one C file for the 6502 with
# cc65 + ca65, keeping the intermediate assembly next to OBJ (cl65 -c
# writes it next to the source, which collides in parallel builds and
# litters the source tree).
#
# A unit whose configuration is fixed at compile time (-DFW_RENDER: the
# demo firmware, examples/spin/fw_app.c's R8_CFG_* / R8_TXCFG_*, folds
# src/render.c's and src/wire.c's checks of that configuration to
# constants) draws cc65's "Unreachable code" warning at each folded
# check, and that warning has no name for -W to switch off.  Such a unit
# is compiled with warnings as warnings, and this script fails on any
# warning but that one (and the const-comparison the flags already
# ignore): every other warning is still an error.
obj=$1; src=$2; shift 2
s=${obj%.*}.s
fixed=0
for a in "$@"; do [ "$a" = -DFW_RENDER ] && fixed=1; done
if [ $fixed = 0 ]; then
  cc65 "$@" -o "$s" "$src" && ca65 -g -t sim6502 -o "$obj" "$s"
  exit
fi
args=()
for a in "$@"; do
  case "$a" in
    +error) unset 'args[${#args[@]}-1]' ;;   # -W +error alone: both go
    +error,*) args+=("${a#+error,}") ;;      # -W +error,...: the rest kept
    *,+error) args+=("${a%,+error}") ;;
    *) args+=("$a") ;;
  esac
done
log=$(mktemp)
trap 'rm -f "$log"' EXIT
cc65 "${args[@]}" -o "$s" "$src" 2> "$log"
rc=$?
bad=$(grep -v ': Warning: Unreachable code$' "$log")
[ -n "$bad" ] && { cat "$log" >&2; rm -f "$s"; exit 1; }
[ $rc = 0 ] || { cat "$log" >&2; exit $rc; }
ca65 -g -t sim6502 -o "$obj" "$s"
