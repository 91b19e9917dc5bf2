#!/usr/bin/env python3
"""Strict IEC 61131-3 syntax check of the generated IEC flavour (run by tools/plc_check.sh).

Uses the tree-sitter grammar `tree-sitter-iec61131-3-st` (PyPI; IEC 61131-3 ed. 3 Structured
Text, vendor dialects out of scope) with the `tree-sitter` Python binding - run it with the
interpreter of build/plc-venv.

    plc_strict.py FILE...            every FILE must parse without ERROR or MISSING nodes
    plc_strict.py --info FILE...     report, do not fail (used for the vendor-dialect files)

Besides the parse, the IEC file must not use the vendor constructs the IEC flavour exists to
avoid: ADR(), POINTER TO, TIME/LTIME inside a STRUCT, {attribute ...} pragmas, and every
END_STRUCT must be followed by ';'. Last line: "N passed, M failed".
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

import tree_sitter
import tree_sitter_iec61131_3_st as grammar


def problems(tree, src: bytes):
    out = []

    def walk(n):
        if n.is_error or n.is_missing:
            kind = f"MISSING {n.type}" if n.is_missing else "ERROR"
            row, col = n.start_point
            out.append(f"line {row + 1} col {col + 1}: {kind} near {src[n.start_byte:n.end_byte][:50]!r}")
        for c in n.children:
            walk(c)

    walk(tree.root_node)
    return out


def strip_comments_and_pragmas(text: str) -> str:
    text = re.sub(r"\(\*.*?\*\)", " ", text, flags=re.S)
    return re.sub(r"\{[^}]*\}", " ", text)


def main(argv) -> int:
    info = "--info" in argv
    files = [a for a in argv if a != "--info"]
    parser = tree_sitter.Parser(tree_sitter.Language(grammar.language()))
    passed = failed = 0
    for f in files:
        src = Path(f).read_bytes()
        tree = parser.parse(src)
        probs = problems(tree, src)
        top = [c.type for c in tree.root_node.children if c.type != "comment"]
        if info:
            print(f"info: {f}: {len(top)} top-level declarations, {len(probs)} strict-IEC syntax "
                  f"deviations (vendor dialect, not checked){': ' + probs[0] if probs else ''}")
            continue
        if probs:
            failed += 1
            for p in probs[:20]:
                print(f"FAIL {f}: {p}")
        else:
            passed += 1
        code = strip_comments_and_pragmas(src.decode("utf-8"))
        checks = [
            (r"\bADR\s*\(", "ADR() is not IEC 61131-3"),
            (r"\bPOINTER\s+TO\b", "POINTER TO is not IEC 61131-3 (use REF_TO)"),
            (r"\bEND_STRUCT\b(?!\s*;)", "END_STRUCT without ';'"),
        ]
        for pat, msg in checks:
            m = re.search(pat, code)
            if m:
                failed += 1
                print(f"FAIL {f}: {msg} (line {code[:m.start()].count(chr(10)) + 1})")
            else:
                passed += 1
        for body in re.findall(r"\bSTRUCT\b(.*?)\bEND_STRUCT\b", code, flags=re.S):
            if re.search(r":\s*(L?TIME)\b", body):
                failed += 1
                print(f"FAIL {f}: TIME/LTIME member inside a STRUCT")
            else:
                passed += 1
        if re.search(r"\{\s*attribute\b", src.decode("utf-8")):
            failed += 1
            print(f"FAIL {f}: vendor {{attribute ...}} pragma in the IEC file")
        else:
            passed += 1
        kinds = {}
        for t in top:
            kinds[t] = kinds.get(t, 0) + 1
        print(f"{f}: tree-sitter-iec61131-3-st: {len(probs)} ERROR/MISSING nodes; "
              + ", ".join(f"{v} {k}" for k, v in sorted(kinds.items())))
    print(f"plc_strict: {passed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
