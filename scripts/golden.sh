#!/usr/bin/env bash
# golden.sh check|update - the demo cube at a few angles (and a few other
# configurations), rendered by build/r8dump, against tests/golden/*.raw.
# `check` never writes the golden files; only `update` (make golden) does.
cd "$(dirname "$0")/.."
mode=${1:-check}
cases=(
  "cube_f0_page1:--scene cube --frame 0"
  "cube_f16_page1:--scene cube --frame 16"
  "cube_f40_page1:--scene cube --frame 40"
  "cube_f40_row1_gouraud:--scene cube --frame 40 --format row1 --shading gouraud"
  "cube_f23_idx8_flat:--scene cube --frame 23 --format idx8 --shading flat"
  "torus_f9_zbuf16:--scene torus --frame 9 --method zbuf16"
)
mkdir -p build/golden
pass=0; fail=0
for c in "${cases[@]}"; do
  name=${c%%:*}; args=${c#*:}
  out=build/golden/$name.raw
  # shellcheck disable=SC2086
  if ! build/r8dump $args --raw "$out" >/dev/null; then
    echo "FAIL $name: r8dump failed"; fail=$((fail+1)); continue
  fi
  if [ "$mode" = update ]; then
    cp "$out" "tests/golden/$name.raw"; echo "updated tests/golden/$name.raw"; pass=$((pass+1))
  elif [ ! -f "tests/golden/$name.raw" ]; then
    echo "FAIL $name: no golden file (run make golden)"; fail=$((fail+1))
  elif cmp -s "$out" "tests/golden/$name.raw"; then
    pass=$((pass+1))
  else
    echo "FAIL $name: differs from tests/golden/$name.raw ($(cmp -l "$out" "tests/golden/$name.raw" | wc -l) bytes)"
    fail=$((fail+1))
  fi
done
echo "$pass passed, $fail failed"
[ $fail = 0 ]
