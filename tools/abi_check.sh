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
#      build with debug info, which abidw reads) against abi/libsafelogic.abi (abidw XML).
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

build_so() {
    cargo build --quiet --profile abi -p safelogic --lib
    so=${CARGO_TARGET_DIR:-target}/abi/libsafelogic.so
    # the .so the check reads must carry the DWARF abidw describes the ABI from
    readelf -S "$so" | grep -F .debug_info >/dev/null || {
        echo "FAIL: $so has no .debug_info (profile.abi must keep debug info)"; exit 1
    }
    abidw --no-corpus-path --no-comp-dir-path --no-show-locs --type-id-style hash \
        --out-file "$out/libsafelogic.abi" "$so"
}

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
    cp -R Cargo.toml Cargo.lock build.rs cbindgen.toml src include project benches abi "$scratch/src/"
    mkdir -p "$scratch/src/tools"
    cp tools/abi_check.sh "$scratch/src/tools/"
    run_break() { # name, file, sed expression, what the report must name
        local name=$1 file=$2 expr=$3 must=$4 rc=0
        cp "src/$file" "$scratch/src/src/$file"
        sed -i "$expr" "$scratch/src/src/$file"
        if cmp -s "src/$file" "$scratch/src/src/$file"; then
            echo "FAIL: self-test '$name': the break did not apply to src/$file"; exit 1
        fi
        echo "--- self-test: $name (src/$file):"
        diff -u "src/$file" "$scratch/src/src/$file" | sed -n '3,$p' | grep '^[-+]' || true
        CARGO_TARGET_DIR=$scratch/target ABI_CHECK_OUT=$scratch/out \
            bash "$scratch/src/tools/abi_check.sh" >"$scratch/$name.log" 2>&1 || rc=$?
        cat "$scratch/$name.log"
        if [ "$rc" = 0 ]; then
            echo "FAIL: self-test '$name': the ABI check passed a broken ABI"; exit 1
        fi
        if ! grep -F -- "$must" "$scratch/$name.log" >/dev/null; then
            echo "FAIL: self-test '$name': the check failed, but its report does not name '$must'"; exit 1
        fi
        cp "src/$file" "$scratch/src/src/$file"
        echo "--- self-test: $name: the check fails (exit $rc) and names '$must'"
    }
    # FB_ESTOP's bEDM1 and bEDM2 trade places (offsets 1 and 2; the doc comments stay, so
    # build.rs's own offset checks still agree and only a comparison with the release sees it)
    run_break moved-field blocks/boolean/estop.rs \
        's/pub bEDM1: SL_BOOL,/pub bEDM_X: SL_BOOL,/; s/pub bEDM2: SL_BOOL,/pub bEDM1: SL_BOOL,/; s/pub bEDM_X: SL_BOOL,/pub bEDM2: SL_BOOL,/' \
        "'bEDM1' offset changed from 8 to 16 (in bits)"
    # sl_ton2_restore_elapsed takes its time as uint16_t instead of uint32_t
    run_break changed-signature ffi/mod.rs \
        's/\(fn sl_ton2_restore_elapsed(fb: \*mut FB_TON2, nElapsedMs: \)u32\() -> i32 {\)/\1u16\2 let nElapsedMs = u32::from(nElapsedMs);/' \
        "sl_ton2_restore_elapsed"
    echo "ABI check self-test: both deliberate breaks fail the check"
    exit 0
    ;;
check) ;;
*) echo "usage: tools/abi_check.sh [--update | --self-test]" >&2; exit 2 ;;
esac

[ -f abi/libsafelogic.abi ] && [ -f abi/header.txt ] || {
    echo "FAIL: abi/libsafelogic.abi or abi/header.txt missing (tools/abi_check.sh --update)"; exit 1
}
base_version=$(sed -n '1s/^# safelogic \([^:]*\):.*/\1/p' abi/header.txt)
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
header_facts include/safelogic.h >"$out/header.txt"
grep -v '^#' abi/header.txt | LC_ALL=C comm -23 - "$out/header.txt" >"$out/header-lost.txt"
if [ -s "$out/header-lost.txt" ]; then
    echo "include/safelogic.h: constants or layouts of safelogic $base_version removed or changed:"
    while read -r kind key value; do
        now=$(awk -v k="$kind" -v n="$key" '$1 == k && $2 == n { $1 = ""; $2 = ""; sub(/^  /, ""); print }' "$out/header.txt")
        echo "  $kind $key: $value -> ${now:-(removed)}"
    done <"$out/header-lost.txt"
    fail=1
else
    echo "include/safelogic.h: every constant and layout of safelogic $base_version unchanged ($(grep -vc '^#' abi/header.txt) lines; $(($(wc -l <"$out/header.txt") - $(grep -vc '^#' abi/header.txt))) added)"
fi

if [ "$fail" != 0 ]; then
    echo "FAIL: incompatible C ABI change against safelogic $base_version. If intended: raise the"
    echo "      major in Cargo.toml, run tools/abi_check.sh --update, add a CHANGELOG entry (docs/release.md)"
    exit 1
fi
echo "C ABI check passed: safelogic $version against the baseline of $base_version"
