#!/usr/bin/env bash
# The README's first steps are program parts, not illustrations. This script
#  1. "C or C++ runtime": checks that the ```c block is examples/c/first_estop.c byte for byte,
#     compiles that program as C11 and as C++17 with -Wall -Wextra -Werror -pedantic, links
#     each with target/release/libsafelogic.a and runs both (exit 0: K1 switched on after the
#     restart and off in the very cycle S1 was pressed), then runs the section's ```sh block
#     verbatim (install into build/prefix, pkg-config with an rpath, the program run);
#  2. "Safety engineer": runs the ```sh block verbatim (check, sim with SVG and VCD, export-c);
#  3. "Rust": checks that the ```rust block is examples/first_estop.rs and runs the ```sh block;
#  4. docs/c-integration.md, "A task": compiles its ```c block as C11 and C++17 with the same
#     warnings, links each with tests/readme/snippet_main.c (which plays the machine) and runs
#     both.
# The PLC section's step (`cargo build --release && bash tools/plc_check.sh`) is the test
# command's own PLC step. Needs target/release (cargo build --release).
set -euo pipefail
cd "$(dirname "$0")/.."
out=build/readme
mkdir -p "$out"
lib=target/release/libsafelogic.a
warn=(-Wall -Wextra -Werror -pedantic)

# block FILE SECTION LANG: the first ```LANG block under the "## SECTION…" heading of FILE
block() {
    awk -v sec="## $2" -v lang="$3" '
        index($0, "## ") == 1 { in_sec = (index($0, sec) == 1) }
        in_sec && !inb && $0 == "```" lang { inb = 1; next }
        inb && $0 == "```" { exit }
        inb { print }' "$1"
}
# same FILE SECTION LANG EXPECTED: the block is the file EXPECTED, byte for byte
same() {
    block "$1" "$2" "$3" >"$out/block.txt"
    if ! diff -u "$4" "$out/block.txt"; then
        echo "FAIL: the \`\`\`$3 block under '## $2' of $1 differs from $4 (above: - file, + page)"
        exit 1
    fi
}
# run_sh SECTION: the section's ```sh block of README.md, verbatim, in a fresh shell
run_sh() {
    block README.md "$1" sh >"$out/step.sh"
    [ -s "$out/step.sh" ] || { echo "FAIL: no \`\`\`sh block under '## $1' of README.md"; exit 1; }
    echo "-- README '## $1', verbatim:"
    sed 's/^/   $ /' "$out/step.sh"
    bash -euo pipefail "$out/step.sh" >"$out/step.log" 2>&1 || { cat "$out/step.log"; echo "FAIL: README '## $1'"; exit 1; }
}
# build_run SOURCE NAME [DRIVER]: C11 and C++17 builds with -Werror, linked and run
build_run() {
    local src=$1 name=$2 driver=${3:-}
    gcc -std=c11 "${warn[@]}" -Iinclude -c "$src" -o "$out/${name}_c.o"
    g++ -std=c++17 "${warn[@]}" -Iinclude -x c++ -c "$src" -o "$out/${name}_cxx.o"
    local objs_c=("$out/${name}_c.o") objs_cxx=("$out/${name}_cxx.o")
    if [ -n "$driver" ]; then
        gcc -std=c11 "${warn[@]}" -c "$driver" -o "$out/${name}_main_c.o"
        g++ -std=c++17 "${warn[@]}" -x c++ -c "$driver" -o "$out/${name}_main_cxx.o"
        objs_c+=("$out/${name}_main_c.o")
        objs_cxx+=("$out/${name}_main_cxx.o")
    fi
    gcc "${objs_c[@]}" "$lib" -lpthread -ldl -lm -o "$out/${name}_c"
    g++ "${objs_cxx[@]}" "$lib" -lpthread -ldl -lm -o "$out/${name}_cxx"
    "$out/${name}_c" >"$out/${name}_c.txt"
    "$out/${name}_cxx" >"$out/${name}_cxx.txt"
    diff -u "$out/${name}_c.txt" "$out/${name}_cxx.txt"
}

# 1. C or C++ runtime
same README.md "C or C++ runtime" c examples/c/first_estop.c
build_run examples/c/first_estop.c first_estop
grep -q "100 ms  S1 released K1 on  RUN" "$out/first_estop_c.txt"
grep -q "200 ms  S1 pressed  K1 off SAFE" "$out/first_estop_c.txt"
run_sh "C or C++ runtime"
# the step's last lines are the program's output (install.sh and cargo print before it)
tail -n "$(wc -l <"$out/first_estop_c.txt")" "$out/step.log" | diff -u "$out/first_estop_c.txt" -
echo "README C program ($(wc -l <examples/c/first_estop.c) lines) = examples/c/first_estop.c: C11 and C++17 with -Werror, linked, run; its install + pkg-config step run verbatim"

# 2. Safety engineer
run_sh "Safety engineer"
grep -q "expectations: .* passed, 0 failed" "$out/step.log"
echo "README project step run verbatim: check, sim (all expectations passed), export-c"

# 3. Rust
same README.md "Rust" rust examples/first_estop.rs
run_sh "Rust"
grep -q "RUN " "$out/step.log"
echo "README Rust program = examples/first_estop.rs; cargo run --example first_estop run verbatim"

# 4. docs/c-integration.md, "A task"
block docs/c-integration.md "A task" c >"$out/snippet.c"
lines=$(wc -l <"$out/snippet.c")
[ "$lines" -gt 5 ] || { echo "FAIL: no C snippet under '## A task' of docs/c-integration.md"; exit 1; }
build_run "$out/snippet.c" snippet tests/readme/snippet_main.c
echo "docs/c-integration.md task snippet ($lines lines): C11 and C++17 with -Werror, linked with tests/readme/snippet_main.c, run"
