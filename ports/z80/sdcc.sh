#!/usr/bin/env bash
# sdcc.sh ARGS...  runs sdcc, hides its "op8_cost" debug noise, keeps
# its exit status.
out=$(sdcc "$@" 2>&1); rc=$?
[ -n "$out" ] && printf '%s\n' "$out" | grep -v '^op8_cost' >&2
exit $rc
