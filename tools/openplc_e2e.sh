#!/usr/bin/env bash
# The OpenPLC v3 end-to-end test (tools/openplc_e2e.py): the KL6904 5.1, 5.2 and speed-monitor
# projects exported with `safelogic export-st`, built into the real OpenPLC runtime from
# ../shared/vendor/openplc (libsafelogic.a linked in), driven over Modbus TCP by pymodbus.
# Needs target/release/libsafelogic.a (cargo build --release). Installs pymodbus into
# build/openplc-venv; OpenPLC's tools are built once into build/openplc-cache (about a minute),
# each program in about 10 s. Runs in a private network namespace when it can (root and
# unshare), so no other OpenPLC runtime on this machine can answer its fixed control port.
# Arguments go to openplc_e2e.py (e.g. --only kl6904_5_1). Last line: "N passed, M failed".
# SAFELOGIC_SHARED_DIR overrides ../shared (for a checkout that does not sit next to it).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
openplc="${SAFELOGIC_SHARED_DIR:-$root/../shared}/vendor/openplc"
PYMODBUS_VERSION=3.11.3
if [ ! -x "$openplc/build_runtime.sh" ]; then
    echo "FAIL: $openplc/build_runtime.sh is missing (OpenPLC v3 runtime source next to the clone, in ../shared)"
    exit 1
fi
[ -f target/release/libsafelogic.a ] || { echo "FAIL: target/release/libsafelogic.a missing (cargo build --release)"; exit 1; }
cargo build --release --quiet -p safelogic-project
venv=build/openplc-venv
if ! "$venv/bin/python" -c "import pymodbus, sys; sys.exit(pymodbus.__version__ != '$PYMODBUS_VERSION')" 2>/dev/null; then
    python3 -m venv "$venv"
    "$venv/bin/python" -m pip install --quiet --disable-pip-version-check "pymodbus==$PYMODBUS_VERSION"
fi
args=(tools/openplc_e2e.py --safelogic target/release/safelogic --lib target/release/libsafelogic.a
      --openplc "$openplc" --workdir build/openplc-e2e --cache build/openplc-cache "$@")
if [ "$(id -u)" = 0 ] && unshare -n true 2>/dev/null; then
    OPENPLC_E2E_NETNS=1 exec unshare -n "$venv/bin/python" "${args[@]}"
fi
echo "note: no private network namespace (needs root and unshare); using the host's loopback"
exec "$venv/bin/python" "${args[@]}"
