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
# dpkg-shlibdeps, dpkg-architecture: the Debian packages (tools/deb.sh)
command -v dpkg-shlibdeps >/dev/null 2>&1 || missing="$missing dpkg-dev"
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
cargo clippy --workspace --all-targets -- -D warnings
RUSTDOCFLAGS="-D warnings" cargo doc --quiet --no-deps -p safelogic --lib

step "no_std build of the block layer"
cargo rustc --quiet --lib --release --no-default-features --crate-type rlib

step "release build (libsafelogic.a / .so) and header"
cargo build --release --quiet

step "Rust tests"
cargo test --release

step "projects: safelogic tool (check, sim, VCD/SVG, export-c), manual samples, committed diagrams"
command -v rsvg-convert >/dev/null 2>&1 || {
    echo "installing: librsvg2-bin (rsvg-convert renders the timing diagrams)"
    $sudo_cmd apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq librsvg2-bin >/dev/null
}
# SAFELOGIC_REQUIRE_RSVG: the diagram test fails (not skips) without rsvg-convert; it also
# fails when a committed docs/diagrams/*.svg is stale, and compiles export-c output against
# target/release/libsafelogic.a (built above)
SAFELOGIC_REQUIRE_RSVG=1 cargo test --release -p safelogic-project
mkdir -p build
cargo run --release --quiet -p safelogic-project >build/safelogic_default.txt
grep -q "expectations: .* passed, 0 failed" build/safelogic_default.txt
for f in examples/projects/*.toml; do
    case "$f" in *.scenario.toml) continue ;; esac
    cargo run --release --quiet -p safelogic-project -- check "$f" >/dev/null
done
echo "safelogic: every example project checks, the default run passes; diagrams fresh and rendered"

step "README: its first steps run verbatim, its C (C11, C++17, -Werror) and Rust programs; docs: no history; docs/abi.md against the header"
bash tools/check_readme_snippet.sh
# README at most 200 lines, no issue numbers, sessions or experiment dates in any page; the
# self-test first shows that each rule fails on a tree that breaks it
bash tools/check_docs.sh --selftest
bash tools/check_docs.sh
python3 tools/check_abi_doc.py

step "C tests (ctest)"
cmake -S c_tests -B build/c_tests -DSAFELOGIC_ROOT="$root" >/dev/null
cmake --build build/c_tests -j2 >/dev/null
ctest --test-dir build/c_tests --output-on-failure
# the C examples print the Rust demo's scenarios in the same table: byte-identical output
cargo run --release --quiet --example demo >build/demo_rust.txt
build/c_tests/kl6904_examples >build/demo_c.txt
diff -u build/demo_rust.txt build/demo_c.txt
echo "examples/c/kl6904_examples.c prints exactly what cargo run --example demo prints ($(wc -l <build/demo_c.txt) lines)"
cargo run --release --quiet --example speed_monitor >build/speed_rust.txt
build/c_tests/speed_monitor >build/speed_c.txt
diff -u build/speed_rust.txt build/speed_c.txt
echo "examples/c/speed_monitor.c prints exactly what cargo run --example speed_monitor prints ($(wc -l <build/speed_c.txt) lines)"
cargo run --release --quiet --example press >build/press_rust.txt
build/c_tests/press >build/press_c.txt
diff -u build/press_rust.txt build/press_c.txt
echo "examples/c/press.c prints exactly what cargo run --example press prints ($(wc -l <build/press_c.txt) lines)"

step "install step, SONAME and pkg-config: one program linked dynamically, one statically"
rm -rf build/prefix build/stage
bash tools/install.sh "$root/build/prefix"
lib=build/prefix/lib
# one version source: Cargo.toml's version names the files, the SONAME (major), the .pc,
# the header's macros, sl_version() and the tool
version=$(sed -n 's/^version = "\(.*\)"/\1/p' Cargo.toml | head -1)
major=${version%%.*}
grep -x "#define SL_VERSION_MAJOR $major" include/safelogic.h >/dev/null
grep -x "#define SL_VERSION_MINOR $(echo "$version" | cut -d. -f2)" include/safelogic.h >/dev/null
grep -x "#define SL_VERSION_PATCH $(echo "$version" | cut -d. -f3)" include/safelogic.h >/dev/null
grep -x "Version: $version" "$lib/pkgconfig/safelogic.pc" >/dev/null
[ "$(build/prefix/bin/safelogic --version)" = "safelogic $version" ]
# versioned names: the real file, the SONAME link, the link-time link
[ -f "$lib/libsafelogic.so.$version" ] && [ ! -L "$lib/libsafelogic.so.$version" ]
[ "$(readlink "$lib/libsafelogic.so.$major")" = "libsafelogic.so.$version" ]
[ "$(readlink "$lib/libsafelogic.so")" = "libsafelogic.so.$major" ]
# (grep reads to the end, never -q: a producer cut off by an early exit dies of SIGPIPE and
# fails the pipeline under pipefail - seen with ldd on a loaded machine)
readelf -d "$lib/libsafelogic.so.$version" | grep "Library soname: \[libsafelogic.so.$major\]" >/dev/null
# DESTDIR + PREFIX (staged install for packaging): files under DESTDIR, the .pc names PREFIX
DESTDIR="$root/build/stage" PREFIX=/usr bash tools/install.sh >/dev/null
[ -L "build/stage/usr/lib/libsafelogic.so.$major" ] && [ -f build/stage/usr/include/safelogic.h ]
[ -x build/stage/usr/bin/safelogic ] && [ -f build/stage/usr/share/safelogic/plc_bindings/iec/safelogic_iec.st ]
grep -qx 'prefix=/usr' build/stage/usr/lib/pkgconfig/safelogic.pc
export PKG_CONFIG_PATH="$root/build/prefix/lib/pkgconfig"
# Dynamic, as README and docs/c-integration.md say: pkg-config, plus an rpath to pkg-config's libdir (or install
# into a system directory and run ldconfig).
# shellcheck disable=SC2046
cc -std=c11 -Wall -Wextra -Werror -pedantic examples/c/group_examples.c $(pkg-config --cflags --libs safelogic) \
    -Wl,-rpath,"$(pkg-config --variable=libdir safelogic)" -o build/prefix/group_examples_dynamic
readelf -d build/prefix/group_examples_dynamic | grep "NEEDED.*\[libsafelogic.so.$major\]" >/dev/null
ldd build/prefix/group_examples_dynamic | grep "libsafelogic.so.$major => $root/build/prefix/lib/libsafelogic.so.$major" >/dev/null
build/prefix/group_examples_dynamic >/dev/null
# Static, as docs/c-integration.md says: pkg-config --static (Libs.private) with -static
# shellcheck disable=SC2046
cc -static -std=c11 -Wall -Wextra -Werror -pedantic examples/c/group_examples.c \
    $(pkg-config --static --cflags --libs safelogic) -o build/prefix/group_examples_static 2>build/prefix/static-link.log \
    || { cat build/prefix/static-link.log; exit 1; }
if readelf -d build/prefix/group_examples_static 2>/dev/null | grep NEEDED >/dev/null; then
    echo "static program needs shared libraries:"; readelf -d build/prefix/group_examples_static; exit 1
fi
build/prefix/group_examples_static >/dev/null
echo "installed: libsafelogic.so.$version (SONAME libsafelogic.so.$major) with links, static library $(du -k "$lib/libsafelogic.a" | cut -f1) KiB, header, safelogic.pc, tool, ST bindings (also under DESTDIR)"
echo "a program linked with pkg-config runs dynamically (NEEDED libsafelogic.so.$major) and statically (no NEEDED)"

step "C ABI against the release baseline abi/ (abidiff, header constants and layouts), and the check's self-test"
bash tools/abi_check.sh
# the check is shown to fail, every run: a moved field and a changed signature (scratch copy)
bash tools/abi_check.sh --self-test

step "Debian packages: build, dpkg -i, a C program via pkg-config (dynamic and -static), dpkg -r"
bash tools/deb_check.sh

step "matiec (iec2c, the IEC 61131-3 compiler of OpenPLC/Beremiz) from ../shared/vendor/matiec"
matiec_src="$root/../shared/vendor/matiec"
if [ -x "$matiec_src/build_iec2c.sh" ]; then
    # offline, about 45 s on 2 cores the first time; cached in build/matiec afterwards
    MATIEC_DIR=$(bash "$matiec_src/build_iec2c.sh" "$root/build/matiec" | tail -n 1)
    [ -x "$MATIEC_DIR/iec2c" ] || { echo "build_iec2c.sh did not produce $MATIEC_DIR/iec2c"; exit 1; }
    export MATIEC_DIR
    "$MATIEC_DIR/iec2c" -v 2>&1 | head -n 1 || true
else
    echo "SKIPPED: $matiec_src (matiec's source and build_iec2c.sh) is missing on this machine;"
    echo "         the IEC bindings are then not compiled with matiec (plc_check step 7 says so too)"
    export MATIEC_DIR=""
fi

step "PLC bindings (generated files fresh, blark, tree-sitter, offsets, CODESYS adapter, matiec run)"
bash tools/plc_check.sh

step "export-st: every example project in every dialect (iec2c + gcc; blark + the bindings' interfaces)"
if [ -z "$MATIEC_DIR" ]; then
    echo "FAIL: export-st's IEC output needs iec2c (../shared/vendor/matiec, see the matiec step)"; exit 1
fi
cargo build --release --quiet -p safelogic-project
build/plc-venv/bin/python tools/export_st_check.py --safelogic target/release/safelogic \
    --iec2c "$MATIEC_DIR/iec2c" --matiec-lib "$MATIEC_DIR/lib" --workdir build/export-st

step "OpenPLC v3: KL6904 5.1/5.2 and the speed monitor exported, built into the runtime, played over Modbus TCP"
# OpenPLC from ../shared/vendor/openplc (tools once into build/openplc-cache), pymodbus in build/openplc-venv
bash tools/openplc_e2e.sh
# the 1,000-block program of docs/performance.md built and brought to RUN (all 1,000 outputs on), briefly
bash tools/openplc_scan_cost.sh --seconds 2

step "peer benchmark: plain-ST E-stop (matiec, gcc -O2) vs the library in one process (brief; figures not asserted)"
# the scenario check (plain ST, direct C call and ST wrapper agree cycle by cycle) is asserted;
# the full run is `cargo bench --bench peer`
if [ -n "$MATIEC_DIR" ]; then
    python3 tools/peer_bench.py --iec2c "$MATIEC_DIR/iec2c" --matiec-lib "$MATIEC_DIR/lib" \
        --workdir build/peer-bench --batches 20
else
    echo "SKIPPED: no iec2c (see the matiec step)"
fi

step "all tests passed"
