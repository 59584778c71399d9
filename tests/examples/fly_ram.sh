#!/usr/bin/env bash
# fly_ram.sh TARGET SIZER OUT - runs the flythrough's sizer
# (examples/flythrough/fw_fly.c -DFLY_SIZE_ONLY) in the target's simulator
# and writes the fly_ram() it prints to OUT: the arena the firmware build
# declares.  A sizer that did not fit the target ("SKIP: reason") is
# copied to OUT, and the firmware build copies it on.
set -u
tgt=$1; prog=$2; out=$3
if head -c 5 "$prog" | grep -q '^SKIP:'; then cp "$prog" "$out"; exit 0; fi
tmp=$(mktemp); trap 'rm -f "$tmp"' EXIT
case $tgt in
  avr328)  build/emu/avrsim -q -m /dev/null -o "$tmp" atmega328p "$prog" ;;
  avr1284) build/emu/avrsim -q -m /dev/null -o "$tmp" atmega1284p "$prog" ;;
  6502)    python3 emu/sim65run.py -m /dev/null -o "$tmp" "$prog" ;;
  z80)     python3 emu/sz80run.py -G -o "$tmp" "$prog" 2>/dev/null ;;
  *) echo "fly_ram.sh: unknown target $tgt" >&2; exit 2 ;;
esac
n=$(tr -d '\r' < "$tmp" | head -1)
case "$n" in
  ''|*[!0-9]*|0) echo "fly_ram.sh: $prog printed '$n', not the arena size" >&2; exit 1 ;;
esac
echo "$n" > "$out"
