#!/usr/bin/env bash
# Shows that the state explorer (project/tests/explore.rs) catches a broken block: on a
# scratch copy of the sources, each patch of project/tests/explorer/mutants/ breaks one
# block; the copy is built, the explorer runs on that block alone and must report a
# violation, and the violation's trace must replay in that build's `safelogic sim` to the
# same state and outputs (the test asserts both with SAFELOGIC_EXPLORE_EXPECT_VIOLATION).
#   bash tools/explore_mutants.sh
# Minutes (a release build of the scratch copy per patch): run by tools/deep-check.sh
# (step explore), not by the test command.
set -euo pipefail
cd "$(dirname "$0")/.."
scratch=build/explore-mutants
mkdir -p "$scratch"
for patch in project/tests/explorer/mutants/*.patch; do
    name=$(basename "$patch" .patch)
    # The block the patch breaks: the first word of its name, in the registry's spelling.
    # The test that explores it: the group scenario for the group's patches.
    test=explore_boolean
    case "$name" in
        estop-*) block=ESTOP ;;
        sf-emergencystop-*) block=SF_EmergencyStop ;;
        twohand-*) block=TWOHAND ;;
        group-*) block=group test=explore_group ;;
        *) echo "FAIL: $name: no block known for this patch"; exit 1 ;;
    esac
    rm -rf "$scratch/src"
    mkdir -p "$scratch/src"
    cp -R Cargo.toml Cargo.lock build.rs build_support cbindgen.toml src include project benches abi plc_bindings examples "$scratch/src/"
    (cd "$scratch/src" && patch -p1 --quiet <"../../../$patch")
    if diff -rq src "$scratch/src/src" >/dev/null; then
        echo "FAIL: $name did not change src/"; exit 1
    fi
    echo "--- mutant $name (explorer on $block):"
    log=$scratch/$name.log
    if (cd "$scratch/src" && CARGO_TARGET_DIR=../target SAFELOGIC_EXPLORE_ONLY=$block \
        SAFELOGIC_EXPLORE_EXPECT_VIOLATION=1 cargo test --release -q -p safelogic-project \
        --test explore "$test" -- --nocapture) >"$log" 2>&1; then
        grep -E '^VIOLATION' "$log"
        grep -E 'expectations: .* passed, 0 failed' "$log" | sed 's/^/    replayed: /'
    else
        echo "FAIL: $name was not caught, or its trace did not replay (see $log)"; exit 1
    fi
done
echo "explorer self-test: every mutant caught and replayed in safelogic sim"
