#!/usr/bin/env bash
# strict.sh - gcc and clang compile every library file with
# -std=c89 -pedantic -Wall -Wextra -Werror.
cd "$(dirname "$0")/.."
pass=0; fail=0
for cc in gcc clang; do
  for f in src/*.c; do
    if $cc -std=c89 -pedantic -Wall -Wextra -Werror -Iinclude -c "$f" -o /dev/null; then
      pass=$((pass+1)); else echo "FAIL: $cc $f"; fail=$((fail+1)); fi
  done
done
echo "$pass passed, $fail failed"
[ $fail = 0 ]
