#!/usr/bin/env bash
# Instructions per steady call of every block in `cargo bench --bench blocks` (callgrind:
# repeatable, unlike times on a shared VM). Runs the bench's smoke mode under callgrind,
# collecting only inside the exported sl_*_cycle functions, and divides each function's
# inclusive count by the calls the smoke mode makes per row (200 warm-up + 20 x 1,000).
#   bash tools/callgrind_blocks.sh
set -euo pipefail
cd "$(dirname "$0")/.."
command -v valgrind >/dev/null || { echo "valgrind is needed (apt-get install valgrind)"; exit 1; }
bin=$(cargo bench --bench blocks --no-run 2>&1 | grep -o 'target/release/deps/blocks-[0-9a-f]*' | head -n 1)
[ -x "$bin" ] || { echo "bench binary not found"; exit 1; }
mkdir -p build/callgrind
out=build/callgrind/blocks.out
valgrind --tool=callgrind --callgrind-out-file="$out" --toggle-collect='sl_*_cycle' "$bin" >/dev/null 2>build/callgrind/blocks.log
calls=20200
printf '%-34s %12s\n' "function (steady inputs, see benches/blocks.rs)" "instr/call"
callgrind_annotate --inclusive=yes "$out" 2>/dev/null |
    awk -v calls="$calls" '/:sl_[a-z0-9_]*_cycle / {
        ir = $1; gsub(",", "", ir)
        fn = $0; sub(/.*:/, "", fn); sub(/ .*/, "", fn)
        printf "%-34s %12.0f\n", fn, ir / calls
    }' | sort
echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
