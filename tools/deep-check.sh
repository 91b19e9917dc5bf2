#!/usr/bin/env bash
# Deep checks outside CI (nightly toolchain): Miri (Stacked and Tree Borrows) on the group
# and FFI tests, each fuzz target in fuzz/ for SECONDS_PER_TARGET, cargo-mutants on the
# given files; one summary at the end. Bounded: -j 1 everywhere (2-core machine).
#   bash tools/deep-check.sh [SECONDS_PER_TARGET] [FILES_FOR_MUTANTS...]
# Needs: rustup component add --toolchain nightly miri rust-src; cargo install cargo-fuzz
# cargo-mutants. Environment:
#   MIRI_TESTS     the Miri test binaries (default below: the group and FFI suites, and the
#                  block suites that go through the C functions' slice building; property
#                  tests run a hundredth of their cases under Miri, tests/common depth_cases)
#   DEEP_STEPS     which steps run (default "miri fuzz mutants peer explore")
#   PEER_ST        a copy of the PLCopen peer ST for the step peer (default: download it)
#   MUTANTS_ARGS   more cargo-mutants options, e.g. "--in-diff build/my.diff" (only the
#                  mutants on the lines of that diff; the files may then be omitted)
#   MUTANTS_TESTS  test targets each mutant is built and tested with (besides the lib's unit
#                  tests; default below: the suites that exercise src/base, ESTOP/MON and the
#                  group, without the minute-long conformance/props runs)
# Missed mutants that match a line of tools/mutants-equivalent.txt (regex over the mutant's
# name without its line:column; each documented in docs/testing.md) are reported apart;
# any other missed mutant fails the check.
# Example, the mutants of one branch's changes only:
#   git diff main... > build/my.diff
#   DEEP_STEPS=mutants MUTANTS_ARGS="--in-diff build/my.diff" bash tools/deep-check.sh
set -uo pipefail
cd "$(dirname "$0")/.."
secs=${1:-60}
shift || true
summary=()
note() { summary+=("$*"); printf '\n==== %s ====\n' "$*"; }

steps=${DEEP_STEPS:-"miri fuzz mutants peer explore"}
step() { [[ " $steps " == *" $1 "* ]]; }

miri_tests=${MIRI_TESTS:-"ffi group_soundness links group fsoe_group analog_group group_schedule edm muting opmode rs sr ton ton2 twohand xor"}
step miri && for mode in stacked tree; do
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

step fuzz && for target in $(cd fuzz && cargo +nightly fuzz list); do
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

# The differential run of the SF_ blocks against the PLCopen peer ST (docs/plcopen-peer-diff.md):
# needs build/matiec (tools/test-all.sh builds it) and the peer file: PEER_ST=path, or the network.
if step peer; then
    log=build/deep-peer.log
    src=(--fetch)
    [ -n "${PEER_ST:-}" ] && src=(--peer "$PEER_ST")
    cargo build --release --lib -q &&
        python3 tools/plcopen_peer_diff.py --iec2c build/matiec/iec2c --matiec-lib build/matiec/lib \
            --workdir build/peer-diff "${src[@]}" >"$log" 2>&1
    if grep -q '^1 passed, 0 failed' "$log"; then
        note "peer diff: $(grep -E 'calls compared' "$log" | sed 's/ (DiagCode.*//'), every disagreement classified"
    else
        note "peer diff FAILED (see $log)"
    fi
fi

mutants_tests=${MUTANTS_TESTS:-"estop mon envelope fb_envelope edm fast_path group group_soundness links group_schedule analog_group fsoe_group connshutdown ffi"}
if step mutants && { [ $# -gt 0 ] || [ -n "${MUTANTS_ARGS:-}" ]; }; then
    args=(--cargo-arg=--lib)
    for t in $mutants_tests; do args+=("--cargo-arg=--test=$t"); done
    for f in "$@"; do args+=(--file "$f"); done
    # shellcheck disable=SC2206 # word splitting of the option string is intended
    args+=(${MUTANTS_ARGS:-})
    log=build/deep-check/mutants.log
    out=build/deep-check/mutants
    mkdir -p "$out"
    CARGO_PROFILE_DEV_DEBUG=0 nice -n 10 cargo mutants -j 1 --minimum-test-timeout 30 \
        --test-package safelogic -o "$out" "${args[@]}" >"$log" 2>&1
    missed=$out/mutants.out/missed.txt
    unexplained=$(sed -E 's/^([^:]+):[0-9]+:[0-9]+:/\1:/' "$missed" 2>/dev/null |
        grep -v -E -f <(grep -v -E '^(#|$)' tools/mutants-equivalent.txt) || true)
    equivalent=$(( $(wc -l <"$missed" 2>/dev/null || echo 0) - $(printf '%s' "$unexplained" | grep -c . || true) ))
    summary_line=$(grep -E '^[0-9]+ mutants tested' "$log" | tail -1)
    if [ -n "$unexplained" ]; then
        note "mutants ${*:-} ${MUTANTS_ARGS:-}: $summary_line; FAILED: missed and not a listed equivalent:"
        printf '%s\n' "$unexplained" | sed 's/^/    /'
        summary+=("$(printf '%s\n' "$unexplained" | sed 's/^/    /')")
    else
        note "mutants ${*:-} ${MUTANTS_ARGS:-}: $summary_line ($equivalent missed, all listed equivalents)"
    fi
fi

# The state explorer (docs/testing.md "State exploration"): every option of the Boolean,
# PLCopen and CONNECTION SHUTDOWN blocks (MUTING included), the analog and press/motion
# blocks over their boundary values, and the explorer's self-test (three broken blocks
# caught, each trace replayed in safelogic sim).
if step explore; then
    log=build/deep-check/explore.log
    mkdir -p build/deep-check
    if cargo test --release -q -p safelogic-project --test explore -- --ignored --nocapture >"$log" 2>&1; then
        note "explore: every option and the analog/motion blocks: no violation, every state reached"
    else
        note "explore FAILED (see $log): $(grep -m1 -E 'VIOLATION|never reached|panicked' "$log")"
    fi
    if bash tools/explore_mutants.sh >build/deep-check/explore-mutants.log 2>&1; then
        note "explore self-test: $(grep -c '^--- mutant' build/deep-check/explore-mutants.log) broken blocks caught and replayed"
    else
        note "explore self-test FAILED (see build/deep-check/explore-mutants.log)"
    fi
fi

printf '\n==== summary ====\n'
printf '%s\n' "${summary[@]}"
! printf '%s\n' "${summary[@]}" | grep -qE 'FAILED|FINDING'
