#!/usr/bin/env bash
# tests/fuzz/run.sh SECONDS TARGET...  (TARGET = build/fuzz/fuzz_NAME)
# With FUZZ_RUNS=N in the environment each target runs N executions (and
# SECONDS is only a cap).  Prints per target "fuzz NAME: N executions,
# K crashes, T s".
# For each target: run every kept input in tests/fuzz/corpus/NAME once
# (regressions: earlier crashers and seeds), then fuzz for SECONDS with a
# scratch corpus in build/fuzz/work/NAME seeded from it.  A crash leaves
# its input in build/fuzz/crash-NAME-*: copy it into tests/fuzz/corpus/NAME
# once the bug is fixed.  Ends with "N passed, N failed" (one per target).
secs=$1; shift
pass=0; fail=0
for bin in "$@"; do
  name=$(basename "$bin"); name=${name#fuzz_}
  corpus=tests/fuzz/corpus/$name
  work=build/fuzz/work/$name
  mkdir -p "$work" "$corpus"
  if ! "$bin" -runs=0 "$corpus" > "build/fuzz/$name.regress.log" 2>&1; then
    echo "FAIL $name: a kept input fails (build/fuzz/$name.regress.log)"; tail -20 "build/fuzz/$name.regress.log"
    fail=$((fail + 1)); continue
  fi
  runs=()
  [ -n "${FUZZ_RUNS:-}" ] && runs=(-runs="$FUZZ_RUNS")
  rm -f build/fuzz/crash-"$name"-*
  t0=$(date +%s)
  "$bin" -max_total_time="$secs" "${runs[@]}" -seed=1 -print_final_stats=1 \
       -artifact_prefix="build/fuzz/crash-$name-" "$work" "$corpus" > "build/fuzz/$name.log" 2>&1
  rc=$?
  execs=$(grep -E '^stat::number_of_executed_units' "build/fuzz/$name.log" | tail -1 | awk '{print $2}')
  [ -z "$execs" ] && execs=$(grep -oE '^Done [0-9]+ runs' "build/fuzz/$name.log" | tail -1 | awk '{print $2}')
  crashes=$(ls build/fuzz/crash-"$name"-* 2>/dev/null | wc -l)
  echo "fuzz $name: ${execs:-0} executions, $crashes crashes, $(( $(date +%s) - t0 )) s"
  if [ "$rc" = 0 ] && [ "$crashes" = 0 ]; then
    pass=$((pass + 1))
  else
    echo "FAIL $name (build/fuzz/$name.log):"; grep -E 'ERROR|SUMMARY|Test unit written' "build/fuzz/$name.log" | head -5
    fail=$((fail + 1))
  fi
done
echo "$pass passed, $fail failed"
[ "$fail" = 0 ]
