#!/usr/bin/env bash
# Check of the PLC bindings (plc_bindings/), for CI and for local use.
#
#   cargo build --release && tools/plc_check.sh
#
# Steps (each prints its own "N passed, M failed"; the last line sums them up):
#   1. generation drift: tools/plcgen.py --check regenerates from include/safelogic.h and the
#      registry's field table (examples/field_table.rs, checked against the header) in memory
#      and compares with every committed file under plc_bindings/ (also stale/missing files);
#   2. Python tools in a venv under build/plc-venv (created or reused): blark (PyPI) and the
#      strict IEC 61131-3 grammar tree-sitter-iec61131-3-st (PyPI) with the tree-sitter binding;
#   3. C truth: plc_bindings/tests/layout_dump.c compiled against include/safelogic.h prints
#      offsetof/sizeof of every member of every header struct;
#   4. tools/plc_layout.py: blark parses every generated ST/TcDUT/TcPOU/TcGVL/TcIO file,
#      computes every DUT member offset under pack mode 8 and 4, compares with step 3, checks
#      the FB interfaces/bodies and the PLC self-test constants;
#   5. tools/plc_strict.py: the IEC flavour through the strict tree-sitter grammar;
#   6. the CODESYS C adapter: built with gcc -Werror, its generated test run against
#      target/release/libsafelogic.a;
#   7. matiec: iec2c (built from ../shared/vendor/matiec, or $MATIEC_DIR) compiles the IEC file
#      unchanged with OpenPLC's options -f -l -p -r -R -a together with a test program;
#      tools/plc_matiec_run.py compiles the generated C, links it with the library and runs every
#      block through its ST FB, cycle by cycle against direct C calls (skipped, and said so,
#      when ../shared/vendor/matiec is missing);
#   8. genericity: tools/plc_synthetic.py adds a synthetic block FB_SYNTH (new field shapes) to a
#      copy of the header; the bindings generated from it go through steps 4-6 and the matiec
#      compile (with a C stub).
# Exit status: 0 only if every step passed.
#
# Environment: PYTHON (default python3, >= 3.8) for the venv and the stdlib-only tools;
# PLC_CHECK_OFFLINE=1 refuses to pip install (the venv must already exist).

set -u -o pipefail

ROOT=$(cd "$(dirname "$0")/.." && pwd)
cd "$ROOT" || exit 2

PY=${PYTHON:-python3}
VENV=build/plc-venv
WORK=build/plc-check
LIB=target/release/libsafelogic.a
BLARK_VERSION=0.8.3
TREE_SITTER_VERSION=0.26.1
GRAMMAR_VERSION=0.1.2

TOTAL_PASS=0
TOTAL_FAIL=0

note() { printf '\n== %s\n' "$*"; }

# Run a step; add its "N passed, M failed" (last such line of its output) to the totals.
# A step that fails without printing counts is one failure.
step() {
    local name=$1
    shift
    local out rc counts p f
    out=$("$@" 2>&1)
    rc=$?
    printf '%s\n' "$out"
    counts=$(printf '%s\n' "$out" | grep -Eo '[0-9]+ passed, [0-9]+ failed' | tail -n 1)
    if [ -n "$counts" ]; then
        p=${counts%% passed*}
        f=${counts#*, }
        f=${f%% failed*}
    else
        p=0
        f=0
    fi
    if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
        f=1
    fi
    if [ "$rc" -eq 0 ] && [ "$f" -ne 0 ]; then
        rc=1
    fi
    TOTAL_PASS=$((TOTAL_PASS + p))
    TOTAL_FAIL=$((TOTAL_FAIL + f))
    if [ "$rc" -ne 0 ]; then
        echo "-- $name: FAILED (exit status $rc)"
    else
        echo "-- $name: ok"
    fi
    return 0
}

mkdir -p "$WORK"

note "1. generated files vs. a fresh generation from include/safelogic.h"
step "plcgen --check" "$PY" tools/plcgen.py --check

note "2. Python tools (venv $VENV)"
venv_ok() {
    [ -x "$VENV/bin/python" ] && "$VENV/bin/python" - "$BLARK_VERSION" "$TREE_SITTER_VERSION" "$GRAMMAR_VERSION" <<'EOF'
import sys
from importlib.metadata import version
want = dict(zip(("blark", "tree-sitter", "tree-sitter-iec61131-3-st"), sys.argv[1:]))
bad = {k: version(k) for k in want if version(k) != want[k]}
import blark, tree_sitter, tree_sitter_iec61131_3_st  # noqa: F401
sys.exit(1 if bad else 0)
EOF
}
setup_venv() {
    if venv_ok >/dev/null 2>&1; then
        echo "reusing $VENV"
    else
        if [ "${PLC_CHECK_OFFLINE:-0}" = 1 ]; then
            echo "FAIL: $VENV missing or incomplete and PLC_CHECK_OFFLINE=1"
            return 1
        fi
        [ -x "$VENV/bin/python" ] || "$PY" -m venv "$VENV" || return 1
        "$VENV/bin/python" -m pip install --quiet --disable-pip-version-check \
            "blark==$BLARK_VERSION" "tree-sitter==$TREE_SITTER_VERSION" \
            "tree-sitter-iec61131-3-st==$GRAMMAR_VERSION" || return 1
        venv_ok || { echo "FAIL: venv check after install"; return 1; }
    fi
    "$VENV/bin/python" - <<'EOF'
from importlib.metadata import version
for p in ("blark", "lark", "tree-sitter", "tree-sitter-iec61131-3-st"):
    print(f"  {p} {version(p)}")
print("1 passed, 0 failed")
EOF
}
step "venv" setup_venv

note "3. C layout of include/safelogic.h (offsetof/sizeof)"
c_layout() {
    gcc -std=c11 -Wall -Wextra -Werror -pedantic -Iinclude plc_bindings/tests/layout_dump.c \
        -o "$WORK/layout_dump" || return 1
    "$WORK/layout_dump" >"$WORK/c_layout.txt" || return 1
    echo "  $(grep -c '^S ' "$WORK/c_layout.txt") structs, $(grep -c '^F ' "$WORK/c_layout.txt") members"
    echo "1 passed, 0 failed"
}
step "C layout" c_layout

note "4. blark: parse every generated file, DUT offsets under pack mode 8 and 4 vs. C"
if [ -s "$WORK/c_layout.txt" ] && [ -x "$VENV/bin/python" ]; then
    step "plc_layout" "$VENV/bin/python" tools/plc_layout.py --c-layout "$WORK/c_layout.txt"
else
    echo "FAIL: prerequisites of step 4 missing"
    TOTAL_FAIL=$((TOTAL_FAIL + 1))
fi

note "5. strict IEC 61131-3 parse (tree-sitter-iec61131-3-st)"
if [ -x "$VENV/bin/python" ]; then
    step "plc_strict" "$VENV/bin/python" tools/plc_strict.py plc_bindings/iec/safelogic_iec.st
    "$VENV/bin/python" tools/plc_strict.py --info plc_bindings/twincat/safelogic_twincat.st \
        plc_bindings/codesys/safelogic_codesys.st | grep '^info:'
else
    echo "FAIL: no venv"
    TOTAL_FAIL=$((TOTAL_FAIL + 1))
fi

note "6. CODESYS C adapter (gcc -Werror) and its test against $LIB"
adapter() {
    if [ ! -f "$LIB" ]; then
        echo "FAIL: $LIB missing - run cargo build --release first"
        return 1
    fi
    local A=plc_bindings/codesys/adapter
    gcc -std=c11 -Wall -Wextra -Werror -pedantic -Iinclude -I"$A" -c "$A/sl_codesys_adapter.c" \
        -o "$WORK/sl_codesys_adapter.o" || return 1
    g++ -std=c++17 -Wall -Wextra -Werror -fsyntax-only -Iinclude -I"$A" -x c++ "$A/sl_codesys_adapter.h" || return 1
    gcc -std=c11 -Wall -Wextra -Werror -pedantic -Iinclude -I"$A" plc_bindings/tests/test_codesys_adapter.c \
        "$WORK/sl_codesys_adapter.o" "$LIB" -lpthread -ldl -lm -o "$WORK/test_codesys_adapter" || return 1
    "$WORK/test_codesys_adapter"
}
step "CODESYS adapter" adapter

note "6b. TwinCAT TcCOM method bodies: g++ syntax check against the header (TwinCAT types stubbed)"
tccom_syntax() {
    local CPP=plc_bindings/twincat/tccom/SafeLogicModule_methods.cpp
    "$PY" - "$CPP" "$WORK/tccom_shim.h" <<'EOF2' || return 1
import re, sys
src = open(sys.argv[1]).read()
decls = re.findall(r"^HRESULT CSafeLogicModule::(\w+)\((.*?)\)$", src, re.M)
if not decls:
    sys.exit("no method definitions found")
with open(sys.argv[2], "w") as fh:
    fh.write("#include <cstddef>\n#include <cstdint>\ntypedef void *PVOID;\ntypedef long HRESULT;\n"
             "#define S_OK 0L\n#define E_POINTER ((HRESULT)0x80004003L)\n"
             "class CSafeLogicModule {\npublic:\n")
    for name, params in decls:
        fh.write(f"    HRESULT {name}({params});\n")
    fh.write("};\n")
print(f"{len(decls)} methods")
EOF2
    g++ -std=c++17 -Wall -Wextra -Werror -fsyntax-only -Iinclude -include "$WORK/tccom_shim.h" -x c++ "$CPP" || return 1
    echo "1 passed, 0 failed"
}
step "TcCOM method bodies" tccom_syntax

note "7. IEC flavour under the real matiec compiler (iec2c from ../shared/vendor/matiec)"
# tools/test-all.sh builds iec2c and passes MATIEC_DIR; standalone, this builds it the same way.
MATIEC_SRC=${MATIEC_SRC:-$ROOT/../shared/vendor/matiec}
if [ -z "${MATIEC_DIR+set}" ] && [ -x "$MATIEC_SRC/build_iec2c.sh" ]; then
    MATIEC_DIR=$(bash "$MATIEC_SRC/build_iec2c.sh" "$ROOT/build/matiec" | tail -n 1)
fi
if [ -n "${MATIEC_DIR:-}" ] && [ -x "$MATIEC_DIR/iec2c" ]; then
    if [ -f "$LIB" ]; then
        step "matiec: compile, link, run every block against direct C calls" "$PY" tools/plc_matiec_run.py \
            --iec2c "$MATIEC_DIR/iec2c" --matiec-lib "$MATIEC_DIR/lib" --workdir "$WORK/matiec" --lib "$LIB"
    else
        echo "FAIL: $LIB missing - run cargo build --release first"
        TOTAL_FAIL=$((TOTAL_FAIL + 1))
    fi
else
    echo "SKIPPED: matiec stage - no iec2c: $MATIEC_SRC (matiec's source and build_iec2c.sh) is missing"
    MATIEC_DIR=""
fi

note "8. generator genericity: a synthetic block FB_SYNTH added to a copy of the header"
SYN=$WORK/synthetic
rm -rf "$SYN"
mkdir -p "$SYN"
synthetic_gen() {
    cargo run --release --quiet --example field_table >"$SYN/fields_real.json" || return 1
    "$PY" tools/plc_synthetic.py --header include/safelogic.h --out "$SYN" --fields "$SYN/fields_real.json" || return 1
    "$PY" tools/plcgen.py --header "$SYN/safelogic.h" --out "$SYN/plc_bindings" --fields "$SYN/fields.json" || return 1
    grep -q 'FUNCTION_BLOCK FB_SYNTH' "$SYN/plc_bindings/iec/safelogic_iec.st" || return 1
    gcc -std=c11 -Wall -Wextra -Werror -pedantic -I"$SYN" "$SYN/plc_bindings/tests/layout_dump.c" \
        -o "$SYN/layout_dump" || return 1
    "$SYN/layout_dump" >"$SYN/c_layout.txt" || return 1
    echo "1 passed, 0 failed"
}
synthetic_adapter() {
    local A=$SYN/plc_bindings/codesys/adapter
    gcc -std=c11 -Wall -Wextra -Werror -pedantic -I"$SYN" -I"$A" "$SYN/plc_bindings/tests/test_codesys_adapter.c" \
        "$A/sl_codesys_adapter.c" "$SYN/synth_stub.c" "$LIB" -lpthread -ldl -lm -o "$SYN/test_codesys_adapter" || return 1
    "$SYN/test_codesys_adapter"
}
step "synthetic: generate" synthetic_gen
if [ -s "$SYN/c_layout.txt" ] && [ -x "$VENV/bin/python" ] && [ -f "$LIB" ]; then
    step "synthetic: layout (blark: IEC, CODESYS, TwinCAT XML)" "$VENV/bin/python" tools/plc_layout.py \
        --c-layout "$SYN/c_layout.txt" --bindings "$SYN/plc_bindings" --sources iec,codesys,twincat-xml
    step "synthetic: strict IEC" "$VENV/bin/python" tools/plc_strict.py "$SYN/plc_bindings/iec/safelogic_iec.st"
    step "synthetic: CODESYS adapter" synthetic_adapter
    if [ -n "$MATIEC_DIR" ]; then
        step "synthetic: matiec compile" "$PY" tools/plc_matiec_run.py --compile-only --iec2c "$MATIEC_DIR/iec2c" \
            --matiec-lib "$MATIEC_DIR/lib" --workdir "$SYN/matiec" --header "$SYN/safelogic.h" \
            --st "$SYN/plc_bindings/iec/safelogic_iec.st"
    else
        echo "SKIPPED: synthetic matiec compile (no iec2c, see step 7)"
    fi
else
    echo "FAIL: prerequisites of step 8 missing"
    TOTAL_FAIL=$((TOTAL_FAIL + 1))
fi

echo
echo "plc_check: $TOTAL_PASS passed, $TOTAL_FAIL failed"
[ "$TOTAL_FAIL" -eq 0 ]
