#!/usr/bin/env bash
# unit.sh TARGET BIN...  runs target builds of the C unit tests in their
# simulator (avr1284: emu/avrsim on an ATmega1284P; 6502: sim65; z80:
# ucsim sz80).  Each run prints its own "N passed, N failed" line; a run
# that crashes, times out or prints no result line adds "0 passed, 1
# failed".  Binaries that did not fit the target hold "SKIP: reason" and
# are listed and counted as skipped (not as passed); with UNIT_SKIP_FAILS
# set (every xtest-* and kernel step in mk/targets.mk) such a binary is a
# failure.
# AVR programs stop after 5 G cycles or 300 s (the kernel test, with
# every kernel, runs about 2.2 G cycles: ~25 s).
# ucsim runs the Z80 at ~50 M ticks/s; the whole Z80 set takes about 75 s
# (test_raster uses fewer random cases on 16-bit int); a run over XTEST_TIMEOUT seconds
# (default 300 from mk/targets.mk) is stopped and listed as skipped for time, never passed
# (a failure under UNIT_SKIP_FAILS, which every xtest step sets);
# `make xtest-z80 XTEST_TIMEOUT=900` runs everything to the end.
cd "$(dirname "$0")/../.."
tgt=$1; shift
# build the test programs here, so build errors land in this step's log
# (serialised with the other steps' builds)
mkdir -p build/x
env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL flock build/x/.lock \
  make -s --no-print-directory -j2 -k build/emu/avrsim "$@" 2>&1 | grep -v "^SKIP"
mkdir -p build/x
skipped=0; ran=0; bad=0
for bin in "$@"; do
  name=$(basename "${bin%.*}")
  if [ ! -e "$bin" ]; then
    echo "$tgt $name: not built"; echo "0 passed, 1 failed"; bad=$((bad+1)); continue
  fi
  if head -c 5 "$bin" | grep -q '^SKIP:'; then
    if [ -n "$UNIT_SKIP_FAILS" ]; then   # (a skip would hide the program's tests)
      echo "$tgt $name: did not fit: $(cut -c7- "$bin")"; echo "0 passed, 1 failed"; bad=$((bad+1)); continue
    fi
    echo "$tgt $name: SKIPPED: $(cut -c7- "$bin")"; skipped=$((skipped+1)); continue
  fi
  ran=$((ran+1))
  out=$(mktemp)
  case $tgt in
    avr*)  timeout 300 build/emu/avrsim -q -l 5000000000 -m /dev/null -o "$out" atmega1284p "$bin"; rc=$? ;;
    6502)  python3 emu/sim65run.py -t 120 -m /dev/null -o "$out" "$bin"; rc=$? ;;
    z80)   python3 emu/sz80run.py -G -t "${XTEST_TIMEOUT:-300}" -m /dev/null -o "$out" "$bin"; rc=$?
           if [ $rc = 124 ] && [ -n "$UNIT_SKIP_FAILS" ]; then
             echo "$tgt $name: stopped after the ${XTEST_TIMEOUT:-300} s time budget"; echo "0 passed, 1 failed"
             bad=$((bad+1)); rm -f "$out"; continue
           elif [ $rc = 124 ]; then
             echo "$tgt $name: SKIPPED: stopped after the ${XTEST_TIMEOUT:-300} s time budget (ucsim is slow; XTEST_TIMEOUT=900 runs it fully)"
             skipped=$((skipped+1)); ran=$((ran-1)); rm -f "$out"; continue
           fi ;;
  esac
  echo "== $tgt $name (exit $rc)"
  tr -d '\r' < "$out"
  if ! grep -Eq '^[0-9]+ passed, [0-9]+ failed' "$out"; then
    echo "$tgt $name: no result line (exit $rc)"; echo "0 passed, 1 failed"; bad=$((bad+1))
  elif [ "$tgt" != z80 ] && [ $rc -ne 0 ] && grep -Eq '^[0-9]+ passed, 0 failed' "$out"; then
    echo "$tgt $name: exit $rc despite 0 failed"; echo "0 passed, 1 failed"; bad=$((bad+1))
  elif ! grep -Eq '^[0-9]+ passed, 0 failed' "$out"; then
    bad=$((bad+1))
  fi
  rm -f "$out"
done
echo "$tgt: $ran test programs run, $skipped skipped (reasons above)"
[ $bad = 0 ]
