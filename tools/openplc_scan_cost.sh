#!/usr/bin/env bash
# Scan cost inside OpenPLC v3 (tools/openplc_scan_cost.py): a 1,000-block program exported from a
# generated project beside the same logic in plain ST, both built into the runtime from
# ../shared/vendor/openplc and measured by it. Run tools/openplc_e2e.sh first (pymodbus venv,
# OpenPLC tool cache). Arguments go to the Python tool (--seconds, --blocks). The figures are
# docs/performance.md's; the test command runs it with --seconds 2 (built, brought to RUN).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
openplc="${SAFELOGIC_SHARED_DIR:-$root/../shared}/vendor/openplc"
venv=build/openplc-venv
[ -x "$venv/bin/python" ] || { echo "FAIL: $venv missing (run tools/openplc_e2e.sh first)"; exit 1; }
args=(tools/openplc_scan_cost.py --safelogic target/release/safelogic --lib target/release/libsafelogic.a
      --openplc "$openplc" --workdir build/openplc-scan --cache build/openplc-cache "$@")
if [ "$(id -u)" = 0 ] && unshare -n true 2>/dev/null; then
    OPENPLC_E2E_NETNS=1 exec unshare -n "$venv/bin/python" "${args[@]}"
fi
exec "$venv/bin/python" "${args[@]}"
