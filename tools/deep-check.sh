#!/usr/bin/env bash
# Deep checks outside CI (nightly toolchain): Miri (Stacked and Tree Borrows) on the group
# and FFI tests, each fuzz target in fuzz/ for SECONDS_PER_TARGET, cargo-mutants on the
# given files; one summary at the end. Bounded: -j 1 everywhere (2-core machine).
#   bash tools/deep-check.sh [SECONDS_PER_TARGET] [FILES_FOR_MUTANTS...]
# Needs: rustup component add --toolchain nightly miri rust-src; cargo install cargo-fuzz
# cargo-mutants. MIRI_TESTS overrides the Miri test binaries (default below).
set -uo pipefail
cd "$(dirname "$0")/.."
secs=${1:-60}
shift || true
summary=()
note() { summary+=("$*"); printf '\n==== %s ====\n' "$*"; }

miri_tests=${MIRI_TESTS:-"group_soundness ffi"}
for mode in stacked tree; do
    flags="-Zmiri-disable-isolation"
    [ "$mode" = tree ] && flags="$flags -Zmiri-tree-borrows"
    for t in $miri_tests; do
        log=build/deep-check/miri-$mode-$t.log
        mkdir -p build/deep-check
        if MIRIFLAGS="$flags" cargo +nightly miri test -j 1 --test "$t" >"$log" 2>&1; then
            note "miri $mode $t: clean ($(grep -h 'test result' "$log" | tail -1))"
        else
            note "miri $mode $t: FAILED (see $log): $(grep -m1 -E 'Undefined Behavior|error' "$log")"
        fi
    done
done

for target in $(cd fuzz && cargo +nightly fuzz list); do
    log=build/deep-check/fuzz-$target.log
    (cd fuzz && CARGO_BUILD_JOBS=1 cargo +nightly fuzz run "$target" -- \
        -max_total_time="$secs" -rss_limit_mb=1024) >"$log" 2>&1
    rc=$?
    runs=$(grep -oE 'Done [0-9]+ runs' "$log" | tail -1)
    cov=$(grep -oE 'cov: [0-9]+ ft: [0-9]+' "$log" | tail -1)
    if [ $rc -eq 0 ]; then
        note "fuzz $target ${secs}s: ${runs:-?}, $cov, no finding"
    else
        note "fuzz $target: FINDING (see $log and fuzz/artifacts/$target)"
    fi
done

if [ $# -gt 0 ]; then
    args=()
    for f in "$@"; do args+=(--file "$f"); done
    log=build/deep-check/mutants.log
    cargo mutants -j 1 --timeout 300 "${args[@]}" >"$log" 2>&1
    note "mutants $*: $(grep -E '^[0-9]+ mutants tested' "$log" | tail -1)"
fi

printf '\n==== summary ====\n'
printf '%s\n' "${summary[@]}"
! printf '%s\n' "${summary[@]}" | grep -qE 'FAILED|FINDING'
