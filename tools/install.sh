#!/usr/bin/env bash
# Installs safelogic into PREFIX (default /usr/local): the static and shared library, the
# header, and the pkg-config file safelogic.pc (ABI.md §1).
#   tools/install.sh [PREFIX]
# Then: cc app.c $(pkg-config --cflags --libs safelogic)            (shared)
#       cc app.c $(pkg-config --cflags --libs --static safelogic)   (static: add -l:libsafelogic.a)
set -euo pipefail
cd "$(dirname "$0")/.."
prefix=${1:-/usr/local}
version=$(sed -n 's/^version = "\(.*\)"/\1/p' Cargo.toml | head -1)
cargo build --release --quiet
install -d "$prefix/lib/pkgconfig" "$prefix/include"
install -m 644 target/release/libsafelogic.a "$prefix/lib/"
install -m 755 target/release/libsafelogic.so "$prefix/lib/"
install -m 644 include/safelogic.h "$prefix/include/"
cat > "$prefix/lib/pkgconfig/safelogic.pc" <<PC
prefix=$prefix
libdir=\${prefix}/lib
includedir=\${prefix}/include

Name: safelogic
Description: TwinSAFE-style safety logic function blocks behind a C ABI (not a certified safety component)
Version: $version
Cflags: -I\${includedir}
Libs: -L\${libdir} -lsafelogic
Libs.private: -lpthread -ldl -lm
PC
echo "installed safelogic $version into $prefix (pkg-config file: $prefix/lib/pkgconfig/safelogic.pc)"
