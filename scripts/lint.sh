#!/usr/bin/env bash
# lint.sh - house rules a C89 compiler does not catch, for src/ and include/:
# no float/double, no long long, no <stdint.h>/<stdbool.h>, no malloc
# family, no // comments.  Prints each hit and "N passed, N failed".
cd "$(dirname "$0")/.."
files=$(ls src/*.c include/*.h 2>/dev/null)
pass=0; fail=0
check() { # name regex
  local hits
  # strip /* */ comments and string literals before matching
  hits=$(for f in $files; do
    python3 - "$f" "$2" <<'PY'
import re, sys
path, rx = sys.argv[1], sys.argv[2]
src = open(path).read()
# blank out comments and strings, keeping line numbers
def blank(m):
    return re.sub(r'[^\n]', ' ', m.group(0))
code = re.sub(r'/\*.*?\*/|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'', blank, src, flags=re.S)
for i, line in enumerate(code.split('\n'), 1):
    if re.search(rx, line):
        print(f"{path}:{i}: {src.split(chr(10))[i-1].strip()}")
PY
  done)
  if [ -n "$hits" ]; then echo "lint: $1:"; echo "$hits"; fail=$((fail+1)); else pass=$((pass+1)); fi
}
check "float/double" '\b(float|double)\b'
check "long long" 'long\s+long'
check "stdint.h/stdbool.h" '<(stdint|stdbool)\.h>'
check "malloc family" '\b(malloc|calloc|realloc|free)\s*\('
check "// comment" '//'
echo "$pass passed, $fail failed"
[ $fail = 0 ]
