#!/usr/bin/env bash
# skip.sh BIN TARGET  - called when a test binary failed to build; reads
# BIN.err.  If the reason is that the test does not fit the target
# (flash/RAM/address-space overflow), writes "SKIP: reason" into BIN so
# tests/targets/unit.sh reports it as skipped, and succeeds.  Any other
# error is printed and fails the build.
bin=$1; tgt=$2; err=$bin.err
# cc65 2.19 cannot evaluate ?: in integer constant expressions (e.g. an
# array sized by R8_WIRE_PKT_BYTES): a known compiler gap, reported as a
# skip with its reason, never as a pass.
if [ "$tgt" = 6502 ] && grep -q 'Constant integer expression expected' "$err"; then
  where=$(grep -m1 'Constant integer expression expected' "$err")
  echo "SKIP: cc65 cannot evaluate ?: in a constant expression: $where" > "$bin"
  echo "SKIP $(basename "$bin"): $where" >&2
  exit 0
fi
pat='region .* overflowed|will not fit in region|Memory area overflow|does not fit:'
if grep -Eq "$pat" "$err"; then
  reason=$(grep -Eo "$pat.*" "$err" | head -1)
  echo "SKIP: does not fit $tgt: $reason" > "$bin"
  echo "SKIP $(basename "$bin"): does not fit $tgt: $reason" >&2
  exit 0
fi
cat "$err" >&2
rm -f "$bin"
exit 1
