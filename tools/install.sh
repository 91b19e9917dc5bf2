#!/usr/bin/env bash
# Installs safelogic (builds it first with `cargo build --release --workspace`); X.Y.Z is
# the version of Cargo.toml ([workspace.package]):
#   $DESTDIR$PREFIX/lib/libsafelogic.so.X.Y.Z   shared library, SONAME libsafelogic.so.X
#   $DESTDIR$PREFIX/lib/libsafelogic.so.X       symlink (what programs load)
#   $DESTDIR$PREFIX/lib/libsafelogic.so         symlink (what `-lsafelogic` finds at link time)
#   $DESTDIR$PREFIX/lib/libsafelogic.a          static library (debug info and LLVM bitcode stripped)
#   $DESTDIR$PREFIX/include/safelogic.h
#   $DESTDIR$PREFIX/lib/pkgconfig/safelogic.pc  (Libs.private: what the static library needs)
#   $DESTDIR$PREFIX/bin/safelogic               the project tool (check, sim, export-c)
#   $DESTDIR$PREFIX/share/safelogic/plc_bindings/   the ST bindings (iec, codesys, twincat)
#
#   PREFIX=/usr/local tools/install.sh          (default PREFIX /usr/local)
#   tools/install.sh /opt/safelogic             (a positional PREFIX wins over the variable)
#   DESTDIR=/tmp/pkgroot PREFIX=/usr tools/install.sh   (staged install for packaging: the
#                                               files land under DESTDIR, safelogic.pc says /usr)
#   LIBDIR=lib/x86_64-linux-gnu tools/install.sh   (library directory relative to PREFIX)
#
# Then (see docs/c-integration.md):
#   cc app.c $(pkg-config --cflags --libs safelogic)                  shared; run after ldconfig,
#                                                                      or add -Wl,-rpath,<libdir>
#   cc -static app.c $(pkg-config --static --cflags --libs safelogic) static executable
set -euo pipefail
cd "$(dirname "$0")/.."
prefix=${1:-${PREFIX:-/usr/local}}
destdir=${DESTDIR:-}
libdir_rel=${LIBDIR:-lib}
case $prefix in
/*) ;;
*) echo "install.sh: PREFIX must be an absolute path (got '$prefix')" >&2; exit 2 ;;
esac
version=$(sed -n 's/^version = "\(.*\)"/\1/p' Cargo.toml | head -1)
major=${version%%.*}
soname=libsafelogic.so.$major
cargo build --release --quiet --workspace
so=target/release/libsafelogic.so
# The SONAME is set in build.rs; refuse to install a library whose SONAME disagrees.
if command -v readelf >/dev/null 2>&1; then
    got=$(readelf -d "$so" | sed -n 's/.*Library soname: \[\(.*\)\].*/\1/p')
    if [ "$got" != "$soname" ]; then
        echo "install.sh: $so has SONAME '$got', expected '$soname' (build.rs)" >&2
        exit 1
    fi
fi
lib=$destdir$prefix/$libdir_rel
inc=$destdir$prefix/include
bin=$destdir$prefix/bin
share=$destdir$prefix/share/safelogic
install -d "$lib/pkgconfig" "$inc" "$bin" "$share"
install -m 755 "$so" "$lib/libsafelogic.so.$version"
strip --strip-unneeded "$lib/libsafelogic.so.$version"
ln -sfn "libsafelogic.so.$version" "$lib/$soname"
ln -sfn "$soname" "$lib/libsafelogic.so"
install -m 644 target/release/libsafelogic.a "$lib/libsafelogic.a"
# Most of the archive is Rust's prebuilt std objects: their DWARF and the LLVM bitcode
# embedded for LTO (.llvmbc). A C linker needs neither (22 MB -> about 4 MB).
objcopy --strip-debug --remove-section=.llvmbc --remove-section=.llvmcmd "$lib/libsafelogic.a"
install -m 644 include/safelogic.h "$inc/safelogic.h"
install -m 755 target/release/safelogic "$bin/safelogic"
strip --strip-unneeded "$bin/safelogic"
# The generated bindings and their README; plc_bindings/tests are the repository's checks.
rm -rf "$share/plc_bindings"
install -d "$share/plc_bindings"
install -m 644 plc_bindings/README.md "$share/plc_bindings/README.md"
cp -R plc_bindings/iec plc_bindings/codesys plc_bindings/twincat "$share/plc_bindings/"
find "$share/plc_bindings" -type d -exec chmod 755 {} + -o -type f -exec chmod 644 {} +
cat > "$lib/pkgconfig/safelogic.pc" <<PC
prefix=$prefix
libdir=\${prefix}/$libdir_rel
includedir=\${prefix}/include

Name: safelogic
Description: TwinSAFE-style safety logic function blocks behind a C ABI (not a certified safety component)
Version: $version
Cflags: -I\${includedir}
Libs: -L\${libdir} -lsafelogic
Libs.private: -lpthread -ldl -lm -lrt -lutil
PC
echo "installed safelogic $version into $destdir$prefix (libdir $libdir_rel, SONAME $soname; pkg-config file: $lib/pkgconfig/safelogic.pc; tool: $bin/safelogic; ST bindings: $share/plc_bindings)"
