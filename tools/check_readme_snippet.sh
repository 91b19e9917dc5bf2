#!/usr/bin/env bash
# The C snippet of README.md ("Linking from C", the first ```c block) is a program part, not
# an illustration: extract it, compile it as C11 with -Wall -Wextra -Werror -pedantic and as
# C++17 with the same warnings, link each with tests/readme/snippet_main.c and
# target/release/libsafelogic.a, and run both.
set -euo pipefail
cd "$(dirname "$0")/.."
out=build/readme
mkdir -p "$out"
awk '/^## Linking from C/ { sec = 1 } sec && /^```c$/ { inb = 1; next } inb && /^```$/ { exit } inb { print }' \
    README.md >"$out/snippet.c"
lines=$(wc -l <"$out/snippet.c")
[ "$lines" -gt 5 ] || { echo "FAIL: no C snippet found in README.md under 'Linking from C'"; exit 1; }
lib=target/release/libsafelogic.a
warn=(-Wall -Wextra -Werror -pedantic)
gcc -std=c11 "${warn[@]}" -Iinclude -c "$out/snippet.c" -o "$out/snippet_c.o"
gcc -std=c11 "${warn[@]}" -c tests/readme/snippet_main.c -o "$out/main_c.o"
gcc "$out/snippet_c.o" "$out/main_c.o" "$lib" -lpthread -ldl -lm -o "$out/snippet_c"
g++ -std=c++17 "${warn[@]}" -Iinclude -x c++ -c "$out/snippet.c" -o "$out/snippet_cxx.o"
g++ -std=c++17 "${warn[@]}" -x c++ -c tests/readme/snippet_main.c -o "$out/main_cxx.o"
g++ "$out/snippet_cxx.o" "$out/main_cxx.o" "$lib" -lpthread -ldl -lm -o "$out/snippet_cxx"
"$out/snippet_c"
"$out/snippet_cxx"
echo "README C snippet ($lines lines): C11 and C++17 with -Wall -Wextra -Werror -pedantic, linked, run"
