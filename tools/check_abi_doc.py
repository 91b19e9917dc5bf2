#!/usr/bin/env python3
"""docs/abi.md against include/safelogic.h.

Every table row of docs/abi.md whose first cell names one or more `SL_*` constants and whose
next cell holds a number (decimal, -N or 0x...) is a claim: the constant has that value in the
header (a row "`SL_X1` ... `SL_X4` | 0x1 ... 0x8" claims the first and the last). Plain
`SL_NAME` (n) mentions in the text are checked the same way. Then completeness: every status
code (SL_OK, SL_E_*) and every option bit (SL_OPT_*) of the header must be listed in a table,
and every type tag (SL_TYPE_*). Prints "N passed, M failed"; exit 1 on any failure.
Standard library only.
"""
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
doc = (ROOT / "docs" / "abi.md").read_text(encoding="utf-8")
hdr = (ROOT / "include" / "safelogic.h").read_text(encoding="utf-8")


def cval(text):
    text = text.strip()
    # Unsigned constants carry U (4294967000U, (1U << 2)), Text IDs are hex (build.rs).
    m = re.fullmatch(r"\(?\s*(-?\s*(?:0x[0-9A-Fa-f]+|\d+))U?\s*\)?", text)
    if m:
        return int(m.group(1).replace(" ", ""), 0)
    m = re.fullmatch(r"\(\s*(\d+)U?\s*<<\s*(\d+)\s*\)", text)
    if m:
        return int(m.group(1)) << int(m.group(2))
    return None


defines = {}
for m in re.finditer(r"^#define\s+(SL_\w+)\s+(.+)$", hdr, re.M):
    v = cval(m.group(2))
    if v is not None:
        defines[m.group(1)] = v

passed = failed = 0
listed = set()


def claim(name, value, where):
    global passed, failed
    listed.add(name)
    if name not in defines:
        failed += 1
        print(f"FAIL: docs/abi.md ({where}) names {name}, which the header does not define")
    elif defines[name] != value:
        failed += 1
        print(f"FAIL: docs/abi.md ({where}) says {name} = {value}, the header says {defines[name]}")
    else:
        passed += 1


def num(tok):
    tok = tok.strip().strip("`")
    if re.fullmatch(r"-?\d+", tok):
        return int(tok)
    if re.fullmatch(r"0x[0-9A-Fa-f]+", tok):
        return int(tok, 16)
    return None


for line in doc.splitlines():
    if not line.startswith("|"):
        continue
    cells = [c.strip() for c in line.strip().strip("|").split("|")]
    if len(cells) < 2:
        continue
    names = re.findall(r"`(SL_[A-Z0-9_]+)`", cells[0])
    if not names or not re.fullmatch(r"`SL_[A-Z0-9_]+`(\s*(,|…|\.\.\.)\s*`SL_[A-Z0-9_]+`)*", cells[0]):
        continue
    values = [num(v) for v in re.split(r"\s*(?:,|…|\.\.\.)\s*", cells[1])]
    if any(v is None for v in values):
        continue
    if "…" in cells[0] or "..." in cells[0]:
        pairs = [(names[0], values[0]), (names[-1], values[-1])]
    else:
        if len(names) != len(values):
            failed += 1
            print(f"FAIL: row {line!r}: {len(names)} names, {len(values)} values")
            continue
        pairs = list(zip(names, values))
    for n, v in pairs:
        claim(n, v, "table")

for m in re.finditer(r"`(SL_[A-Z0-9_]+)`\s*(?:=\s*)?\((0x[0-9A-Fa-f]+|-?\d+)\)", doc):
    claim(m.group(1), int(m.group(2), 0), "text")
for m in re.finditer(r"`(SL_[A-Z0-9_]+)`\s*=\s*(0x[0-9A-Fa-f]+|-?\d+)\b", doc):
    claim(m.group(1), int(m.group(2), 0), "text")

required = [n for n in defines if n == "SL_OK" or n.startswith(("SL_E_", "SL_OPT_", "SL_TYPE_"))]
for n in required:
    if n in listed:
        passed += 1
    else:
        failed += 1
        print(f"FAIL: docs/abi.md does not list {n} (= {defines[n]}) of the header")

print(f"check_abi_doc: {len(listed)} constants of docs/abi.md checked against the header, "
      f"{len(required)} status codes / option bits / type tags required; {passed} passed, {failed} failed")
sys.exit(1 if failed else 0)
