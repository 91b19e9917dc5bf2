#!/usr/bin/env bash
# Runs every test of the project (Rust and C) on a fresh Debian machine with the Rust
# toolchain. Installs what it needs (cmake via apt-get, Python packages into build/).
# Exits non-zero on the first failure.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)

step() { printf '\n==== %s ====\n' "$*"; }

step "prerequisites"
if [ "$(id -u)" = 0 ]; then sudo_cmd=""; else sudo_cmd="sudo"; fi
missing=""
command -v cmake >/dev/null 2>&1 && command -v ctest >/dev/null 2>&1 || missing="$missing cmake"
command -v cc >/dev/null 2>&1 || missing="$missing gcc"
command -v c++ >/dev/null 2>&1 || missing="$missing g++"
command -v python3 >/dev/null 2>&1 || missing="$missing python3"
command -v pkg-config >/dev/null 2>&1 || missing="$missing pkg-config"
python3 -c 'import venv, ensurepip' >/dev/null 2>&1 || missing="$missing python3-venv"
if [ -n "$missing" ]; then
    echo "installing:$missing"
    $sudo_cmd apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq $missing >/dev/null
fi
rustup component add rustfmt clippy >/dev/null 2>&1 || true
cmake --version | head -1
cargo --version

step "format and lints"
cargo fmt --all -- --check
cargo clippy --all-targets -- -D warnings

step "no_std build of the block layer"
cargo rustc --quiet --lib --release --no-default-features --crate-type rlib

step "release build (libsafelogic.a / .so) and header"
cargo build --release --quiet

step "Rust tests"
cargo test --release

step "C tests (ctest)"
cmake -S c_tests -B build/c_tests -DSAFELOGIC_ROOT="$root" >/dev/null
cmake --build build/c_tests -j2 >/dev/null
ctest --test-dir build/c_tests --output-on-failure

step "install step and pkg-config (ABI.md §1)"
rm -rf build/prefix
bash tools/install.sh "$root/build/prefix"
export PKG_CONFIG_PATH="$root/build/prefix/lib/pkgconfig"
# shellcheck disable=SC2046
cc -std=c11 -Wall -Wextra -Werror -pedantic examples/c/group_examples.c $(pkg-config --cflags --libs safelogic) \
    -Wl,-rpath,"$root/build/prefix/lib" -o build/prefix/group_examples
build/prefix/group_examples >/dev/null
echo "installed library, header and safelogic.pc: an example built with pkg-config runs"

step "PLC bindings (generated files fresh, blark, tree-sitter, offsets, CODESYS adapter)"
bash tools/plc_check.sh

step "all tests passed"
