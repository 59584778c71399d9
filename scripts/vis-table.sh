#!/usr/bin/env bash
# vis-table.sh - RAM (renderer work memory + one band buffer, host build)
# and host instructions per frame (callgrind, difference between 17 and 1
# frames / 16) for every method on the cube, torus and terrain at 128x64
# PAGE1, band 8.  Writes a Markdown table to stdout.
cd "$(dirname "$0")/.."
make -s build/r8dump >/dev/null
ir() { # args... -> total Ir
  valgrind --tool=callgrind --callgrind-out-file=/dev/null build/r8dump "$@" 2>&1 \
    | awk '/Collected :/{print $4}'
}
echo "| scene | method | work bytes | band bytes | total RAM | host instr/frame |"
echo "|---|---|---:|---:|---:|---:|"
for s in cube torus terrain; do
  for m in cull painter zbuf8 zbuf16 block blockmask sbuf; do
    work=$(build/r8dump --scene $s --method $m --frame 0 | sed -n 's/work=//p')
    a=$(ir --scene $s --method $m --frame 0 --count 1)
    b=$(ir --scene $s --method $m --frame 0 --count 17)
    echo "| $s | $m | $work | 128 | $((work + 128)) | $(( (b - a) / 16 )) |"
  done
done
