#!/usr/bin/env bash
# Instructions per steady call of every block in `cargo bench --bench blocks` (callgrind:
# repeatable, unlike times on a shared VM): the bench runs its own smoke mode under callgrind
# (collecting only inside the exported sl_*_cycle functions) and divides each function's
# inclusive count by the calls of its row. `cargo bench --bench blocks` prints the same
# column beside the times. A second table covers every registered type, each configured and
# brought to its running state, which the bench asserts (benches/blocks/all_types.rs: a
# second callgrind child that makes only those steady calls).
#   bash tools/callgrind_blocks.sh
set -euo pipefail
cd "$(dirname "$0")/.."
command -v valgrind >/dev/null || { echo "valgrind is needed (apt-get install valgrind)"; exit 1; }
cargo bench --quiet --bench blocks -- --instructions
echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
