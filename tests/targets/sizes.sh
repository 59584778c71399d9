#!/usr/bin/env bash
# sizes.sh TARGET OUT SIZER...  runs each scene's sizer program
# (tests/targets/fw_sizes.c built with -DFW_SCENE=S) on the target and writes the
# "scene method bytes" lines to OUT.  A sizer that did not fit the target
# (a "SKIP: reason" file) gives "S M 0 # reason" for every method.
set -u
tgt=$1; out=$2; shift 2
tmp=$(mktemp); trap 'rm -f "$tmp" "$tmp.o"' EXIT
for prog in "$@"; do
  s=$(basename "$prog"); s=${s#sizes-}; s=${s%%.*}
  if head -c 5 "$prog" | grep -q '^SKIP:'; then
    reason=$(cut -c7- "$prog")
    for m in 0 1 2 3 4 5 6; do echo "$s $m 0 # $reason"; done >> "$tmp"
    continue
  fi
  case $tgt in
    avr*) build/emu/avrsim -q -m /dev/null -o "$tmp.o" atmega1284p "$prog" ;;
    6502) python3 emu/sim65run.py -m /dev/null -o "$tmp.o" "$prog" ;;
    z80)  python3 emu/sz80run.py -G -o "$tmp.o" "$prog" 2>/dev/null ;;
  esac
  grep -q '^END' "$tmp.o" || { echo "sizes.sh: $prog printed no END" >&2; cat "$tmp.o" >&2; exit 1; }
  grep -v '^END' "$tmp.o" >> "$tmp"
done
echo END >> "$tmp"
mv "$tmp" "$out"; trap - EXIT; rm -f "$tmp.o"
