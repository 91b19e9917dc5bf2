#!/usr/bin/env bash
# The Debian packages on this machine: builds them (tools/deb.sh), installs them with
# dpkg -i, builds and runs a C program against the installed files with pkg-config
# (dynamically, no rpath: the loader finds /usr/lib/<multiarch>/libsafelogic.so.X) and
# one with -static, runs /usr/bin/safelogic, removes both packages with dpkg -r and checks
# that every file they listed is gone. Needs root (or sudo) for dpkg.
set -euo pipefail
trap 'echo "FAIL: tools/deb_check.sh line $LINENO: $BASH_COMMAND" >&2' ERR
cd "$(dirname "$0")/.."
root=$(pwd)
if [ "$(id -u)" = 0 ]; then sudo_cmd=""; else sudo_cmd="sudo"; fi
version=$(sed -n 's/^version = "\(.*\)"/\1/p' Cargo.toml | head -1)
major=${version%%.*}
arch=$(dpkg --print-architecture)
multiarch=$(dpkg-architecture -qDEB_HOST_MULTIARCH 2>/dev/null || gcc -print-multiarch)
libdir=/usr/lib/$multiarch
work=$root/build/deb-check
rm -rf "$work"
mkdir -p "$work"

# A safelogic installed in /usr by anything but these packages would be overwritten and
# then deleted by dpkg -r: refuse instead. A leftover of an interrupted run is removed.
for pkg in libsafelogic-dev libsafelogic; do
    if dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q 'install ok installed'; then
        echo "removing $pkg left installed by an earlier run"
        $sudo_cmd dpkg -r "$pkg" >/dev/null
    fi
done
for f in /usr/include/safelogic.h "$libdir/libsafelogic.so" "$libdir/libsafelogic.so.$major" \
    "$libdir/libsafelogic.a" "$libdir/pkgconfig/safelogic.pc" /usr/bin/safelogic /usr/share/safelogic; do
    if [ -e "$f" ] || [ -L "$f" ]; then
        echo "FAIL: $f exists and belongs to no safelogic package; not overwriting it" >&2
        exit 1
    fi
done

bash tools/deb.sh
rt=build/deb/libsafelogic_${version}_$arch.deb
dev=build/deb/libsafelogic-dev_${version}_$arch.deb
$sudo_cmd dpkg -i "$rt" "$dev" >"$work/dpkg-install.log"
# dpkg -r runs on any exit from here, so a failed check leaves nothing installed
remove() {
    $sudo_cmd dpkg -r libsafelogic-dev libsafelogic >"$work/dpkg-remove.log" 2>&1 || cat "$work/dpkg-remove.log"
}
trap remove EXIT
dpkg -L libsafelogic libsafelogic-dev | LC_ALL=C sort -u >"$work/files.txt"
for f in "$libdir/libsafelogic.so.$version" "$libdir/libsafelogic.so.$major" /usr/bin/safelogic \
    /usr/include/safelogic.h "$libdir/libsafelogic.so" "$libdir/libsafelogic.a" \
    "$libdir/pkgconfig/safelogic.pc" /usr/share/safelogic/plc_bindings/iec/safelogic_iec.st \
    /usr/share/safelogic/plc_bindings/codesys/safelogic_codesys.st; do
    grep -Fx "$f" "$work/files.txt" >/dev/null || { echo "FAIL: the packages do not install $f" >&2; exit 1; }
done
echo "installed: libsafelogic $version and libsafelogic-dev ($(wc -l <"$work/files.txt") paths by dpkg -L)"

# pkg-config as a Debian user has it: its default search path, no PKG_CONFIG_PATH
unset PKG_CONFIG_PATH PKG_CONFIG_LIBDIR
[ "$(pkg-config --modversion safelogic)" = "$version" ]
[ "$(pkg-config --variable=libdir safelogic)" = "$libdir" ]
# shellcheck disable=SC2046
cc -std=c11 -Wall -Wextra -Werror -pedantic examples/c/version_check.c \
    $(pkg-config --cflags --libs safelogic) -o "$work/version_check_dynamic"
# the loader resolves it to the packaged file (as /lib/<multiarch>/... on a merged-/usr system)
loaded=$(ldd "$work/version_check_dynamic" | awk -v n="libsafelogic.so.$major" '$1 == n { print $3 }')
[ -n "$loaded" ] && [ "$(readlink -f "$loaded")" = "$libdir/libsafelogic.so.$version" ]
"$work/version_check_dynamic"
# shellcheck disable=SC2046
cc -static -std=c11 -Wall -Wextra -Werror -pedantic examples/c/version_check.c \
    $(pkg-config --static --cflags --libs safelogic) -o "$work/version_check_static" 2>"$work/static-link.log" \
    || { cat "$work/static-link.log"; exit 1; }
if readelf -d "$work/version_check_static" 2>/dev/null | grep NEEDED >/dev/null; then
    echo "FAIL: the -static program needs shared libraries" >&2; exit 1
fi
"$work/version_check_static"
[ "$(/usr/bin/safelogic --version)" = "safelogic $version" ]
/usr/bin/safelogic check examples/projects/estop.toml >/dev/null
echo "a C program built with pkg-config runs against the packages dynamically and statically; /usr/bin/safelogic $version checks a project"

trap - EXIT
$sudo_cmd dpkg -r libsafelogic-dev libsafelogic >"$work/dpkg-remove.log"
for pkg in libsafelogic-dev libsafelogic; do
    if dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q 'install ok installed'; then
        echo "FAIL: $pkg still installed after dpkg -r" >&2; exit 1
    fi
done
# Every file and link the packages listed is gone; of their directories only those that
# existed before or hold other packages' files may stay (dpkg keeps shared directories).
left=""
while read -r f; do
    if [ -L "$f" ] || { [ -e "$f" ] && [ ! -d "$f" ]; }; then left="$left $f"; fi
done <"$work/files.txt"
[ -z "$left" ] || { echo "FAIL: left behind after dpkg -r:$left" >&2; exit 1; }
for d in /usr/share/safelogic /usr/share/doc/libsafelogic /usr/share/doc/libsafelogic-dev; do
    [ ! -e "$d" ] || { echo "FAIL: $d left behind after dpkg -r" >&2; exit 1; }
done
echo "removed: dpkg -r left none of the $(wc -l <"$work/files.txt") listed paths but shared directories"
