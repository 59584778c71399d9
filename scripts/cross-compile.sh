#!/usr/bin/env bash
# cross-compile.sh - avr-gcc, cc65 and sdcc (z80) compile every library file.
cd "$(dirname "$0")/.."
pass=0; fail=0
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
for f in src/*.c; do
  b=$(basename "$f" .c)
  if avr-gcc -std=c89 -pedantic -Wall -Wextra -Werror -mmcu=atmega328p -Os -Iinclude -c "$f" -o "$tmp/$b.o"; then
    pass=$((pass+1)); else echo "FAIL: avr-gcc $f"; fail=$((fail+1)); fi
  if cc65 -t sim6502 --standard c89 -W +error,-const-comparison -Oirs -Iinclude "$f" -o "$tmp/$b.s" >/dev/null; then
    pass=$((pass+1)); else echo "FAIL: cc65 $f"; fail=$((fail+1)); fi
  if sdcc -mz80 --std-c89 --Werror -Iinclude -c "$f" -o "$tmp/$b.rel" >/dev/null; then
    pass=$((pass+1)); else echo "FAIL: sdcc $f"; fail=$((fail+1)); fi
done
echo "$pass passed, $fail failed"
[ $fail = 0 ]
