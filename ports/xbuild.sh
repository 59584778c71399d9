#!/usr/bin/env bash
# xbuild.sh TARGET OUT SRC [OBJ...] [-- CFLAGS...]
# Builds one program for a target from SRC (compiled with CFLAGS) + OBJ...
# + the target's plat object + its library archive (build/x/TARGET/):
#   avr328 / avr1284  avr-gcc, OUT.elf   (flags: $AVR_CFLAGS)
#   6502              cc65,    OUT.prg   (flags: $C65_CFLAGS)
#   z80               sdcc,    OUT.ihx   (flags: $Z80_CFLAGS; ports/z80/z80link.py)
# When the program does not fit the target (flash, static RAM, address
# space; or cc65's missing ?: in constant expressions) OUT becomes a
# one-line text file "SKIP: reason" and the script succeeds: runners and
# tests report it as skipped, with the reason.  Other errors fail.
# Also writes OUT.size: "flash=N ram_static=N" (bytes).
set -u
tgt=$1; out=$2; src=$3; shift 3
objs=()
while [ $# -gt 0 ] && [ "$1" != -- ]; do objs+=("$1"); shift; done
[ $# -gt 0 ] && shift
X=build/x/$tgt
base=${out%.*}
log=$out.log
rm -f "$out" "$out.size"
skip() { echo "SKIP: $*" > "$out"; echo "SKIP $(basename "$out"): $*" >&2; exit 0; }
fail() { cat "$log" >&2; exit 1; }
case $tgt in
  avr328|avr1284)
    if [ $tgt = avr328 ]; then mcu=atmega328p; ram=2048; flash=32768;
    else mcu=atmega1284p; ram=16384; flash=131072; fi
    avr-gcc -mmcu=$mcu $AVR_CFLAGS "$@" -c "$src" -o "$base.o" > "$log" 2>&1 || fail
    avr-gcc -mmcu=$mcu -mrelax -Wl,--gc-sections -Wl,-Map,"$base.map" -o "$out" "$base.o" "${objs[@]}" \
      $X/obj/plat_avr.o $X/librast8.a >> "$log" 2>&1 || {
        grep -Eq 'overflowed|will not fit|not within region' "$log" && skip "$(grep -Eo '(region|will not fit|section).*' "$log" | head -1) (statics exceed the $mcu's $ram B SRAM or $flash B flash)"; fail; }
    read -r text data bss < <(avr-size "$out" | awk 'NR==2 {print $1, $2, $3}')
    echo "flash=$((text + data)) ram_static=$((data + bss))" > "$out.size"
    [ $((text + data)) -le $flash ] || { mv "$out" "$out.toobig"; skip "flash $((text + data)) > $flash bytes ($mcu)"; }
    [ $((data + bss)) -lt $ram ] || { mv "$out" "$out.toobig"; skip "static RAM $((data + bss)) (.data $data + .bss $bss) >= $ram bytes ($mcu)"; }
    ;;
  6502)
    bash ports/6502/cc65c.sh "$base.o" "$src" $C65_CFLAGS "$@" > "$log" 2>&1 || {
      grep -q 'Constant integer expression expected' "$log" &&
        skip "cc65 cannot evaluate ?: in a constant expression: $(grep -m1 'Constant integer' "$log")"; fail; }
    # Function-level dead-code removal (ports/6502/gc65.py; C65_GC=0: off):
    # the program's and the library members' ca65 sources, only what
    # _main reaches, assembled in $base.gc/ and linked as objects.
    # A program that does not fit with the speed kernels is linked again
    # with ports/6502/ckern.s65: their C versions under their names.
    for try in 1 2; do
    link=("$base.o" "${objs[@]}" $X/obj/plat_sim65.o $X/rast8.lib)
    if [ "${C65_GC:-1}" != 0 ]; then
      progs=("$base.s")
      for o in "${objs[@]}" $X/obj/plat_sim65.o; do progs+=("${o%.*}.s"); done
      members=()
      for m in $(ar65 t $X/rast8.lib); do
        if [ -e "$X/obj/${m%.o}.s" ]; then members+=("$X/obj/${m%.o}.s"); else members+=("ports/6502/${m%.o}.s"); fi
      done
      rm -rf "$base.gc"
      gcs=$(python3 ports/6502/gc65.py "$base.gc" "${progs[@]}" -- "${members[@]}" 2>> "$log") || fail
      link=()
      for g in $gcs; do
        ca65 -g -t sim6502 -o "${g%.s}.o" "$g" >> "$log" 2>&1 || fail
        link+=("${g%.s}.o")
      done
    fi
    # C stack 1 KB instead of 2 (measured peaks are ~300 B): 1 KB more for code
    cl65 -t sim6502 -C ports/6502/rast8.cfg --ld-args -D,__STACKSIZE__=0x0200,-Ln,"$base.lbl",--dbgfile,"$base.dbg" -m "$base.map" -o "$out" "${link[@]}" \
      > "$log.ld" 2>&1 && { cat "$log.ld" >> "$log"; rm -f "$log.ld"; break; }
    cat "$log.ld" >> "$log"
    grep -q 'overflows memory area' "$log.ld" || fail
    [ $try = 2 ] && skip "$(grep -m1 -o 'Segment.*' "$log.ld") (sim6502: 63 KB for code+data, 512 B C stack; with the C kernels)"
    echo "xbuild.sh: $(grep -m1 -o 'Segment.*' "$log.ld"): again with ports/6502/ckern.s65" >> "$log"
    # (a unit with wire.c's relay r8_tx_band_c but no C band path tx_band,
    # R8_TXBAND_ALL, keeps the kernel r8_tx_band: ckern's last part out)
    if grep -q '^\.proc[[:space:]]_r8_tx_band_c:' "$base.s" && ! grep -q '^\.proc[[:space:]]_tx_band:' "$base.s"; then
      sed '/^; ---- r8_tx_band/,$d' ports/6502/ckern.s65 > "$base.ck.s"
    else
      cp ports/6502/ckern.s65 "$base.ck.s"
    fi
    ca65 -g -t sim6502 -o "$base.ck.o" "$base.ck.s" >> "$log" 2>&1 || fail
    objs+=("$base.ck.o")
    done
    # segment sizes from the map: CODE+RODATA+DATA (program), DATA+BSS (RAM)
    python3 - "$base.map" > "$out.size" <<'PY'
import re, sys
sz = {}
seg = False
for line in open(sys.argv[1]):
    if line.startswith("Segment list:"):
        seg = True
    elif seg:
        m = re.match(r"(\w+)\s+([0-9A-F]{6})\s+([0-9A-F]{6})\s+([0-9A-F]{6})", line)
        if m:
            sz[m.group(1)] = int(m.group(4), 16)
        elif line.strip() == "" and sz:
            break
# R8PAGE: page-aligned RAM (bss) for the 6502 kernels' tables (ports/6502/rast8.cfg)
prog = sum(v for k, v in sz.items() if k not in ("BSS", "ZEROPAGE", "EXEHDR", "R8PAGE"))
ram = sz.get("DATA", 0) + sz.get("BSS", 0) + sz.get("R8PAGE", 0)
print("flash=%d ram_static=%d" % (prog, ram))
PY
    ;;
  z80)
    bash ports/z80/sdcc.sh $Z80_CFLAGS "$@" -c -o "$base.rel" "$src" > "$log" 2>&1 || fail
    link=("$base.rel" "${objs[@]}" $X/obj/plat_z80.rel $X/rast8.lib)
    # Function-level dead-code removal (ports/z80/gcz80.py; Z80_GC=0: off):
    # the sdasz80 sources sdcc -c left beside the program's objects and the
    # library's members (ports/z80/*.s for the kernels), only what _main
    # reaches, assembled in $base.gc/ and linked as objects (crt0 and
    # z80.lib as before).  A program object without its .asm links whole.
    progs=()
    for o in "$base.rel" "${objs[@]}" $X/obj/plat_z80.rel; do
      [ -e "${o%.*}.asm" ] && progs+=("${o%.*}.asm")
    done
    if [ "${Z80_GC:-1}" != 0 ] && [ ${#progs[@]} = $((${#objs[@]} + 2)) ]; then
      members=()
      for m in $(sdar t $X/rast8.lib); do
        if [ -e "$X/obj/${m%.rel}.asm" ]; then members+=("$X/obj/${m%.rel}.asm"); else members+=("ports/z80/${m%.rel}.s"); fi
      done
      rm -rf "$base.gc"
      gcs=$(python3 ports/z80/gcz80.py "$base.gc" "${progs[@]}" -- "${members[@]}" 2>> "$log") || fail
      link=()
      for g in $gcs; do
        # as sdcc -c assembles its output (.sym: emu/z80sim's static
        # functions) and mk/targets.mk the kernels
        case $g in
          *.asm) sdasz80 -plosgffw "${g%.*}.rel" "$g" >> "$log" 2>&1 || fail ;;
          *) sdasz80 -o "${g%.*}.rel" "$g" >> "$log" 2>&1 || fail ;;
        esac
        link+=("${g%.*}.rel")
      done
    fi
    python3 ports/z80/z80link.py "$out" "${link[@]}" >> "$log" 2>&1 || {
      [ $? = 3 ] && skip "$(grep -m1 'does not fit' "$log" | sed 's/^does not fit: //') (64 KB Z80 map)"; fail; }
    grep -o 'code=[0-9]* data=[0-9]*' "$log" | tail -1 | sed 's/code=\([0-9]*\) data=\([0-9]*\)/flash=\1 ram_static=\2/' > "$out.size"
    ;;
  *) echo "xbuild.sh: unknown target $tgt" >&2; exit 2 ;;
esac
exit 0
