#!/usr/bin/env bash
# size_run.sh TARGET SIZER OUT - runs an example's sizer (its firmware main
# built with -D..._SIZE_ONLY: it prints the arena it needs in decimal) in
# the target's simulator and writes the number to OUT: the static arena
# the firmware build declares, measured on the target itself (struct
# sizes differ from the host's).  A sizer that did not fit the target
# ("SKIP: reason") is copied to OUT, and the firmware build copies it on.
set -u
tgt=$1; prog=$2; out=$3
if head -c 5 "$prog" | grep -q '^SKIP:'; then cp "$prog" "$out"; exit 0; fi
tmp=$(mktemp); trap 'rm -f "$tmp"' EXIT
case $tgt in
  avr328)  build/emu/avrsim -q -m /dev/null -o "$tmp" atmega328p "$prog" ;;
  avr1284) build/emu/avrsim -q -m /dev/null -o "$tmp" atmega1284p "$prog" ;;
  6502)    python3 emu/sim65run.py -m /dev/null -o "$tmp" "$prog" ;;
  z80)     python3 emu/sz80run.py -G -o "$tmp" "$prog" 2>/dev/null ;;
  *) echo "size_run.sh: unknown target $tgt" >&2; exit 2 ;;
esac
n=$(tr -d '\r' < "$tmp" | head -1)
case "$n" in
  ''|*[!0-9]*|0) echo "size_run.sh: $prog printed '$n', not the arena size" >&2; exit 1 ;;
esac
echo "$n" > "$out"
