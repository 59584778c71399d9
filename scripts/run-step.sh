#!/usr/bin/env bash
# run-step.sh NAME CMD...  runs one test step, logging to build/logs/NAME.log
# and its exit code to build/logs/NAME.rc; output is also shown.
name=$1; shift
mkdir -p build/logs
echo "== $name: $*"
"$@" > >(tee "build/logs/$name.log") 2>&1
rc=$?
wait
echo $rc > "build/logs/$name.rc"
exit $rc
