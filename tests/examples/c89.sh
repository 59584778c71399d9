#!/usr/bin/env bash
# c89.sh - the examples' portable application files (the code a firmware
# runs: examples/flythrough/fly.c, examples/maze/maze.c, examples/ssd1306/oled_cube.c,
# examples/two-objects/two.c) through the library's C89 gate on gcc and
# clang, and through avr-gcc, cc65 and sdcc.  Prints "N passed, N failed".
cd "$(dirname "$0")/../.."
STRICT="-std=c89 -pedantic -Wall -Wextra -Werror"
INC="-Iinclude -Iscenes -Iports -Iexamples/common -Iexamples/flythrough -Iexamples/maze -Iexamples/ssd1306 -Iexamples/two-objects"
t=$(mktemp -d); trap 'rm -rf "$t"' EXIT
p=0; f=0
ok() { if "$@" > "$t/log" 2>&1; then p=$((p+1)); else f=$((f+1)); echo "FAIL: $*"; cat "$t/log"; fi; }
for src in examples/flythrough/fly.c examples/maze/maze.c examples/ssd1306/oled_cube.c examples/two-objects/two.c; do
  for cc in gcc clang; do ok $cc $STRICT $INC -c "$src" -o "$t/a.o"; done
  ok avr-gcc $STRICT -mmcu=atmega328p -Os $INC -c "$src" -o "$t/a.o"
  ok cc65 -t sim6502 --standard c89 -W +error,-const-comparison -Or -Cl $INC "$src" -o "$t/a.s"
  ok sdcc -mz80 --std-c89 --Werror $INC -c "$src" -o "$t/a.rel"
done
echo "$p passed, $f failed"
[ $f = 0 ]
