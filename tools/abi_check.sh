#!/usr/bin/env bash
# The C ABI check: the library built from the current sources against the committed
# description of the release (abi/). Fails on any incompatible change.
#
#   tools/abi_check.sh              check (the test command runs this and --self-test)
#   tools/abi_check.sh --update     write abi/ from the current sources: at a release, in the
#                                   commit that sets the version and the CHANGELOG entry
#   tools/abi_check.sh --self-test  shows on a scratch copy of the sources that the check
#                                   fails on a moved struct field and on a changed signature
#
# Two parts (docs/release.md, "The ABI check"):
#   1. abidiff (libabigail) of target/abi/libsafelogic.so (the `abi` profile: the release
#      build with debug info, which abidw reads) against abi/libsafelogic.abi (abidw XML,
#      with the Rust module paths dropped from the names: see build_so).
#      It sees the exported functions, their parameter and return types, the structs they
#      reach (size, field offsets and types) and the SONAME. Added functions are compatible;
#      anything else abidiff reports fails.
#   2. abidiff does not see #define constants, nor structs no function reaches: abi/header.txt
#      lists every #define of include/safelogic.h and every offset and size its layout
#      asserts pin. A removed or changed line fails; added lines are compatible.
# The header's SL_VERSION_* macros are not compared (they change at every release); the
# major of Cargo.toml must still be the baseline's (an incompatible release writes abi/).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
mode=${1:-check}
out=${ABI_CHECK_OUT:-$root/build/abi}
mkdir -p "$out"

if ! command -v abidw >/dev/null 2>&1 || ! command -v abidiff >/dev/null 2>&1; then
    echo "installing: abigail-tools (abidw, abidiff)"
    if [ "$(id -u)" = 0 ]; then sudo_cmd=""; else sudo_cmd="sudo"; fi
    $sudo_cmd apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq abigail-tools >/dev/null
fi

version=$(sed -n 's/^version = "\(.*\)"/\1/p' Cargo.toml | head -1)
major=${version%%.*}

# The header's ABI facts, one per line: "define NAME VALUE" for each #define (but the
# include guard, the assert macro and the version macros) and "layout offsetof(T,f) N" /
# "layout sizeof(T) N" for each layout assert build.rs appends.
header_facts() {
    sed -n \
        -e '/^#define \(SAFELOGIC_H\|SL_STATIC_ASSERT\|SL_VERSION_[A-Z]*\)\b/d' \
        -e 's/^#define \([A-Za-z_][A-Za-z0-9_]*\) \(.*\)$/define \1 \2/p' \
        -e 's/^SL_STATIC_ASSERT(\(.*\) == \([0-9]*\), .*$/layout \1 \2/p' "$1" |
        sed 's/^\(layout offsetof([^,]*\), /\1,/' | LC_ALL=C sort
}

# Compares a header's facts with abi/header.txt: a removed or changed line fails.
compare_header() {
    header_facts "$1" >"$out/header.txt"
    grep -v '^#' abi/header.txt | LC_ALL=C comm -23 - "$out/header.txt" >"$out/header-lost.txt"
    if [ -s "$out/header-lost.txt" ]; then
        echo "$1: constants or layouts of safelogic $base_version removed or changed:"
        while read -r kind key value; do
            now=$(awk -v k="$kind" -v n="$key" '$1 == k && $2 == n { $1 = ""; $2 = ""; sub(/^  /, ""); print }' "$out/header.txt")
            echo "  $kind $key: $value -> ${now:-(removed)}"
        done <"$out/header-lost.txt"
        return 1
    fi
    echo "$1: every constant and layout of safelogic $base_version unchanged ($(grep -vc '^#' abi/header.txt) lines; $(($(wc -l <"$out/header.txt") - $(grep -vc '^#' abi/header.txt))) added)"
}

build_so() {
    cargo build --quiet --profile abi -p safelogic --lib
    so=${CARGO_TARGET_DIR:-target}/abi/libsafelogic.so
    # the .so the check reads must carry the DWARF abidw describes the ABI from
    readelf -S "$so" | grep -F .debug_info >/dev/null || {
        echo "FAIL: $so has no .debug_info (profile.abi must keep debug info)"; exit 1
    }
    abidw --no-corpus-path --no-comp-dir-path --no-show-locs --type-id-style hash \
        --out-file "$out/libsafelogic.rust.abi" "$so"
    # abidw names each type and function with its Rust module path
    # (safelogic::blocks::boolean::estop::FB_ESTOP); the C ABI has no module paths and the
    # header names it FB_ESTOP. Without the paths, moving a type between Rust modules is no
    # change, and the report speaks C: drop the namespace elements (types refer to each other
    # by id, functions are matched by ELF symbol) and the path prefixes inside names.
    sed -e "/^ *<namespace-decl name='[^']*'>\$/d" -e '/^ *<\/namespace-decl>$/d' \
        -e ':a' -e "s/\(name='[^']*\)\b[A-Za-z_][A-Za-z0-9_]*::/\1/" -e 'ta' \
        "$out/libsafelogic.rust.abi" >"$out/libsafelogic.abi"
}

base_version=$(sed -n '1s/^# safelogic \([^:]*\):.*/\1/p' abi/header.txt 2>/dev/null || true)

case $mode in
--update)
    build_so
    mkdir -p abi
    cp "$out/libsafelogic.abi" abi/libsafelogic.abi
    { echo "# safelogic $version: C ABI facts of include/safelogic.h (tools/abi_check.sh --update)"
      header_facts include/safelogic.h; } >abi/header.txt
    echo "abi/ written for safelogic $version: $(grep -c '<elf-symbol ' abi/libsafelogic.abi) ELF symbols, $(grep -c . abi/header.txt) header lines"
    exit 0
    ;;
--self-test)
    # A scratch copy of what builds the library, with its own target directory (kept in
    # build/ between runs); each break runs this very script there and must fail on it.
    scratch=$out/self-test
    rm -rf "$scratch/src"
    mkdir -p "$scratch/src"
    cp -R Cargo.toml Cargo.lock build.rs build_support cbindgen.toml src include project benches abi "$scratch/src/"
    mkdir -p "$scratch/src/tools"
    cp tools/abi_check.sh "$scratch/src/tools/"
    run_break() { # name, file, sed expression, what the report must name (one or more)
        local name=$1 file=$2 expr=$3 rc=0 must
        shift 3
        cp "src/$file" "$scratch/src/src/$file"
        cp include/safelogic.h "$scratch/src/include/safelogic.h"
        sed -i "$expr" "$scratch/src/src/$file"
        if cmp -s "src/$file" "$scratch/src/src/$file"; then
            echo "FAIL: self-test '$name': the break did not apply to src/$file"; exit 1
        fi
        echo "--- self-test: $name (src/$file):"
        diff -U1 "src/$file" "$scratch/src/src/$file" | tail -n +3 || true
        # SAFELOGIC_WRITE_HEADER: the scratch build regenerates its include/safelogic.h, as a
        # change is committed (tests/header.rs fails a stale header)
        CARGO_TARGET_DIR=$scratch/target ABI_CHECK_OUT=$scratch/out SAFELOGIC_WRITE_HEADER=1 \
            bash "$scratch/src/tools/abi_check.sh" >"$scratch/$name.log" 2>&1 || rc=$?
        cat "$scratch/$name.log"
        if [ "$rc" = 0 ]; then
            echo "FAIL: self-test '$name': the ABI check passed a broken ABI"; exit 1
        fi
        for must in "$@"; do
            if ! grep -F -- "$must" "$scratch/$name.log" >/dev/null; then
                echo "FAIL: self-test '$name': the check failed, but its report does not say: $must"; exit 1
            fi
        done
        cp "src/$file" "$scratch/src/src/$file"
        echo "--- self-test: $name: the check fails (exit $rc) and says: $(printf '[%s] ' "$@")"
    }
    # FB_ESTOP's bEDM1 and bEDM2 trade places (offsets 1 and 2, in its declarations' data
    # file; the doc comments stay, so build.rs's own offset checks still agree and only a
    # comparison with the release sees it)
    run_break moved-field blocks/boolean/estop.abi.toml \
        's/^name = "bEDM1"$/name = "bEDM_X"/; s/^name = "bEDM2"$/name = "bEDM1"/; s/^name = "bEDM_X"$/name = "bEDM2"/' \
        "'function i32 sl_estop_cycle(FB_ESTOP*, u32)' has some indirect sub-type changes" \
        "'u8 bEDM1' offset changed from 8 to 16 (in bits)" \
        "layout offsetof(FB_ESTOP,bEDM1): 1 -> 2"
    # sl_ton2_restore_elapsed takes its time as uint16_t instead of uint32_t
    run_break changed-signature ffi/mod.rs \
        's/\(fn sl_ton2_restore_elapsed(fb: \*mut FB_TON2, nElapsedMs: \)u32\() -> i32 {\)/\1u16\2 let nElapsedMs = u32::from(nElapsedMs);/' \
        "'function i32 sl_ton2_restore_elapsed(FB_TON2*, u32)' has some indirect sub-type changes" \
        "type name changed from 'u32' to 'u16'"
    # The constants: abidiff does not see them, the header comparison does (no build needed)
    sed -e 's/^#define SL_E_INTERNAL (-7)$/#define SL_E_INTERNAL (-70)/' -e '/^#define SL_OPT_EDM1 /d' \
        include/safelogic.h >"$scratch/constants.h"
    grep -x '#define SL_E_INTERNAL (-70)' "$scratch/constants.h" >/dev/null
    echo "--- self-test: changed-constants (SL_E_INTERNAL -7 -> -70, SL_OPT_EDM1 removed):"
    rc=0
    out=$scratch compare_header "$scratch/constants.h" >"$scratch/constants.log" || rc=$?
    cat "$scratch/constants.log"
    [ "$rc" != 0 ] && grep -F "define SL_E_INTERNAL: (-7) -> (-70)" "$scratch/constants.log" >/dev/null &&
        grep -F "define SL_OPT_EDM1: " "$scratch/constants.log" | grep -F -- "-> (removed)" >/dev/null || {
        echo "FAIL: self-test 'changed-constants': the header comparison did not fail on them"; exit 1
    }
    echo "ABI check self-test: the moved field, the changed signature and the changed constants fail the check"
    exit 0
    ;;
check) ;;
*) echo "usage: tools/abi_check.sh [--update | --self-test]" >&2; exit 2 ;;
esac

[ -f abi/libsafelogic.abi ] && [ -n "$base_version" ] || {
    echo "FAIL: abi/libsafelogic.abi or abi/header.txt missing (tools/abi_check.sh --update)"; exit 1
}
if [ "${base_version%%.*}" != "$major" ]; then
    echo "FAIL: Cargo.toml says $version, abi/ describes $base_version: a new major writes its"
    echo "      baseline (tools/abi_check.sh --update) in the same commit"
    exit 1
fi
build_so
fail=0

# 1. the shared library: abidiff's exit status is a bit set (1 error, 2 usage, 4 ABI change,
# 8 incompatible change); with --no-added-syms additions do not count
rc=0
abidiff --fail-no-debug-info --no-added-syms abi/libsafelogic.abi "$out/libsafelogic.abi" \
    >"$out/abidiff.txt" 2>&1 || rc=$?
if [ $((rc & 3)) != 0 ]; then
    cat "$out/abidiff.txt"; echo "FAIL: abidiff could not compare (exit $rc)"; exit 1
elif [ "$rc" != 0 ]; then
    echo "abidiff abi/libsafelogic.abi (safelogic $base_version) against this build (exit $rc):"
    cat "$out/abidiff.txt"
    fail=1
else
    added=$(abidiff abi/libsafelogic.abi "$out/libsafelogic.abi" | grep -c "^  \[A\]" || true)
    echo "libsafelogic.so: compatible with safelogic $base_version ($(grep -c '<elf-symbol ' "$out/libsafelogic.abi") ELF symbols, $added added)"
fi

# 2. the header's constants and layouts
compare_header include/safelogic.h || fail=1

if [ "$fail" != 0 ]; then
    echo "FAIL: incompatible C ABI change against safelogic $base_version. If intended: raise the"
    echo "      major in Cargo.toml, run tools/abi_check.sh --update, add a CHANGELOG entry (docs/release.md)"
    exit 1
fi
echo "C ABI check passed: safelogic $version against the baseline of $base_version"
