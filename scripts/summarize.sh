#!/usr/bin/env bash
# Adds up the closing lines of every test log in $1:
#   C tests:  "N passed, N failed"      pytest: "... N passed ... N failed ..."
# Prints one line per log, then the total as "N passed, N failed".
# Exit 1 if anything failed or no test ran at all.
dir=${1:-build/logs}
tp=0; tf=0
for f in "$dir"/*.log; do
  [ -e "$f" ] || continue
  name=$(basename "$f" .log)
  p=0; fl=0; seen=0
  while IFS= read -r line; do
    if [[ $line =~ ^([0-9]+)\ passed,\ ([0-9]+)\ failed ]]; then
      p=$((p + BASH_REMATCH[1])); fl=$((fl + BASH_REMATCH[2])); seen=1
    elif [[ $line =~ ^(=+\ )?[0-9]+\ (passed|failed|errors?).*\ in\ [0-9.]+s ]]; then
      [[ $line =~ ([0-9]+)\ passed ]] && p=$((p + BASH_REMATCH[1]))
      [[ $line =~ ([0-9]+)\ failed ]] && fl=$((fl + BASH_REMATCH[1]))
      [[ $line =~ ([0-9]+)\ errors? ]] && fl=$((fl + BASH_REMATCH[1]))
      seen=1
    fi
  done < "$f"
  if [ -e "$dir/$name.rc" ] && [ "$(cat "$dir/$name.rc")" != 0 ] && [ "$fl" = 0 ]; then
    fl=1
  fi
  if [ $seen = 0 ] && [ "$fl" = 0 ]; then fl=1; echo "  $name: no result line (see $f)"; fi
  printf '  %-28s %5d passed, %d failed\n' "$name" "$p" "$fl"
  tp=$((tp + p)); tf=$((tf + fl))
done
echo "$tp passed, $tf failed"
[ "$tf" = 0 ] && [ "$tp" -gt 0 ]
