#!/usr/bin/env bash
# Builds the Debian packages from a staged install (tools/install.sh with DESTDIR) with
# dpkg-deb, for the machine's architecture:
#   build/deb/libsafelogic_X.Y.Z_ARCH.deb      /usr/lib/<multiarch>/libsafelogic.so.X.Y.Z and
#                                              its SONAME link libsafelogic.so.X, /usr/bin/safelogic
#   build/deb/libsafelogic-dev_X.Y.Z_ARCH.deb  /usr/include/safelogic.h, the link libsafelogic.so,
#                                              libsafelogic.a, pkgconfig/safelogic.pc,
#                                              /usr/share/safelogic/plc_bindings/
# Every file the install step stages goes into exactly one package (checked). The runtime
# package's dependencies come from dpkg-shlibdeps; it declares its shared library (shlibs)
# and activates the ldconfig trigger. tools/deb_check.sh installs, uses and removes them.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
umask 022
version=$(sed -n 's/^version = "\(.*\)"/\1/p' Cargo.toml | head -1)
major=${version%%.*}
arch=$(dpkg --print-architecture)
multiarch=$(dpkg-architecture -qDEB_HOST_MULTIARCH 2>/dev/null || gcc -print-multiarch)
maintainer=${DEB_MAINTAINER:-safelogic maintainers <safelogic@localhost>}
out=$root/build/deb
rm -rf "$out"
mkdir -p "$out"
stage=$out/stage
DESTDIR=$stage PREFIX=/usr LIBDIR=lib/$multiarch bash tools/install.sh >/dev/null

rt=$out/libsafelogic
dev=$out/libsafelogic-dev
libdir=usr/lib/$multiarch
# Moves staged paths (relative to /) into a package tree.
take() {
    local pkg=$1 p
    shift
    for p in "$@"; do
        [ -e "$stage/$p" ] || [ -L "$stage/$p" ] || { echo "deb.sh: $p was not installed" >&2; exit 1; }
        mkdir -p "$pkg/$(dirname "$p")"
        mv "$stage/$p" "$pkg/$p"
    done
}
take "$rt" "$libdir/libsafelogic.so.$version" "$libdir/libsafelogic.so.$major" usr/bin/safelogic
take "$dev" "$libdir/libsafelogic.so" "$libdir/libsafelogic.a" "$libdir/pkgconfig/safelogic.pc" \
    usr/include/safelogic.h usr/share/safelogic
left=$(find "$stage" ! -type d)
[ -z "$left" ] || { echo "deb.sh: staged files in no package:"; echo "$left"; exit 1; } >&2

for pkg in "$rt" "$dev"; do
    doc=$pkg/usr/share/doc/$(basename "$pkg")
    mkdir -p "$doc"
    gzip -9n <CHANGELOG.md >"$doc/changelog.gz"
    cat >"$doc/copyright" <<EOF
Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/
Upstream-Name: safelogic

Files: *
Copyright: the safelogic authors
License: MIT or Apache-2.0
 On Debian systems the Apache License 2.0 is in /usr/share/common-licenses/Apache-2.0.
EOF
done

# Runtime dependencies of the ELF files, as Debian's packaging computes them.
mkdir -p "$out/shlibdeps/debian"
printf 'Source: safelogic\n\nPackage: libsafelogic\nArchitecture: any\n' >"$out/shlibdeps/debian/control"
depends=$(cd "$out/shlibdeps" &&
    dpkg-shlibdeps -O -e"$rt/$libdir/libsafelogic.so.$version" -e"$rt/usr/bin/safelogic" 2>/dev/null |
    sed -n 's/^shlibs:Depends=//p')
[ -n "$depends" ] || { echo "deb.sh: dpkg-shlibdeps found no dependencies" >&2; exit 1; }

control() { # package tree, fields after Version
    local pkg=$1
    shift
    mkdir -p "$pkg/DEBIAN"
    {
        printf 'Package: %s\nVersion: %s\nArchitecture: %s\nMaintainer: %s\n' \
            "$(basename "$pkg")" "$version" "$arch" "$maintainer"
        printf 'Installed-Size: %s\n' "$(du -sk --exclude=DEBIAN "$pkg" | cut -f1)"
        printf '%s\n' "$@"
    } >"$pkg/DEBIAN/control"
    (cd "$pkg" && find usr -type f -exec md5sum {} + | LC_ALL=C sort -k2) >"$pkg/DEBIAN/md5sums"
}
control "$rt" "Section: libs" "Priority: optional" "Depends: $depends" \
    "Description: TwinSAFE-style safety logic function blocks (C library and tool)" \
    " The shared library libsafelogic.so.$major (C ABI $major.x: SONAME libsafelogic.so.$major) with" \
    " the TwinSAFE Logic function blocks behind a C ABI, and the safelogic tool (check, simulate" \
    " and export project files). Not a certified safety component."
printf 'libsafelogic %s libsafelogic (>= %s)\n' "$major" "$version" >"$rt/DEBIAN/shlibs"
printf 'activate-noawait ldconfig\n' >"$rt/DEBIAN/triggers"
control "$dev" "Section: libdevel" "Priority: optional" "Depends: libsafelogic (= $version)" \
    "Description: TwinSAFE-style safety logic function blocks (development files)" \
    " The C header safelogic.h, the static library, the link-time libsafelogic.so, the" \
    " pkg-config file safelogic.pc and the IEC 61131-3 structured-text bindings (matiec," \
    " CODESYS, TwinCAT) under /usr/share/safelogic/plc_bindings."

for pkg in "$rt" "$dev"; do
    deb=$out/$(basename "$pkg")_${version}_$arch.deb
    dpkg-deb --root-owner-group --build "$pkg" "$deb" >/dev/null
    echo "built $(basename "$deb") ($(du -k "$deb" | cut -f1) KiB, $(dpkg-deb -c "$deb" | grep -vc '/$') files and links)"
done
