#!/usr/bin/env python3
"""Compiles `safelogic export-st` of every example project (examples/projects/*.toml) in every
dialect with the real tools the repository uses:

- iec: matiec's iec2c with OpenPLC's options (-f -l -p -r -R -a), then gcc -c of the generated C
  (matiec's lib/C headers). tools/openplc_e2e.py builds three of them into OpenPLC and runs them.
- twincat, codesys: blark parses the file (a GVL and a PROGRAM, no parse error), and every call
  of the program is checked against the dialect's bindings (plc_bindings/twincat|codesys): the
  function or FB exists, every parameter it passes is one of its VAR_INPUTs, every type it
  declares is a DUT or FB there.

    build/plc-venv/bin/python tools/export_st_check.py --safelogic target/release/safelogic \
        --iec2c $MATIEC_DIR/iec2c --matiec-lib $MATIEC_DIR/lib --workdir build/export-st

Prints one line per check and "N passed, M failed" last; exit status 1 on any failure.
"""
from __future__ import annotations

import argparse
import re
import subprocess
import sys
from pathlib import Path

from blark import parse as bparse

ROOT = Path(__file__).resolve().parent.parent
BINDINGS = {
    "twincat": ROOT / "plc_bindings/twincat/safelogic_twincat.st",
    "codesys": ROOT / "plc_bindings/codesys/safelogic_codesys.st",
}
passed = failed = 0


def check(ok: bool, what: str) -> None:
    global passed, failed
    passed += ok
    failed += not ok
    print(f"{'ok  ' if ok else 'FAIL'}  {what}", flush=True)


def pous(path: Path) -> dict[str, set[str]]:
    """Every DUT/POU/GVL section of a bindings file: name -> its VAR_INPUT names."""
    out: dict[str, set[str]] = {}
    for sec in re.split(r"^\(\* ==== ", path.read_text(), flags=re.M)[1:]:
        head, _, body = sec.partition("\n")
        name = head.split()[1]
        ins: set[str] = set()
        for block in re.findall(r"^VAR_INPUT\n(.*?)^END_VAR", body, flags=re.M | re.S):
            ins |= {m.group(1) for m in re.finditer(r"^\s*(\w+)\s*:", block, flags=re.M)}
        out[name] = ins
    return out


def crossref(st: str, known: dict[str, set[str]], local_fbs: dict[str, str]) -> list[str]:
    """Calls and types of the exported program that the bindings do not have."""
    errs = []
    code = re.sub(r"\(\*.*?\*\)", "", st, flags=re.S)
    for m in re.finditer(r"\b(\w+)\s*:\s*(ST_FB_\w+|SL_\w+|FB_\w+)\s*;", code):
        if m.group(2) not in known:
            errs.append(f"type {m.group(2)} of {m.group(1)} is not in the bindings")
    for m in re.finditer(r"\b(\w+)\(([^()]*(?:\([^()]*\)[^()]*)*)\)", code):
        name, args = m.group(1), m.group(2)
        if name in ("ADR", "UDINT_TO_UINT", "BYTE_TO_UINT", "IF", "AND", "OR"):
            continue
        target = local_fbs.get(name, name)
        if target not in known:
            errs.append(f"call of {name}: {target} is not in the bindings")
            continue
        for p in re.findall(r"(\w+)\s*:=", args):
            if p not in known[target]:
                errs.append(f"call of {name} ({target}): {p} is not one of its VAR_INPUTs")
    return errs


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--safelogic", required=True)
    ap.add_argument("--iec2c", help="matiec's iec2c (without it the iec dialect is not compiled: a failure)")
    ap.add_argument("--matiec-lib")
    ap.add_argument("--workdir", required=True, type=Path)
    args = ap.parse_args()
    args.workdir.mkdir(parents=True, exist_ok=True)
    known = {d: pous(p) for d, p in BINDINGS.items()}
    projects = sorted(p for p in (ROOT / "examples/projects").glob("*.toml") if not p.name.endswith(".scenario.toml"))
    for proj in projects:
        crc = re.search(r"project CRC (0x[0-9A-F]{8})",
                        subprocess.run([args.safelogic, "check", str(proj)], capture_output=True, text=True, check=True).stdout).group(1)
        for d in ("iec", "twincat", "codesys"):
            tag = f"{proj.stem} ({d})"
            out = args.workdir / d / f"{proj.stem}.st"
            out.parent.mkdir(parents=True, exist_ok=True)
            texts = []
            for _ in range(2):
                subprocess.run([args.safelogic, "export-st", str(proj), "--dialect", d, "-o", str(out)], check=True)
                texts.append(out.read_text())
            check(texts[0] == texts[1] and f"(project CRC {crc})" in texts[0].splitlines()[0],
                  f"{tag}: deterministic, header names project CRC {crc}")
            if d == "iec":
                if not args.iec2c:
                    check(False, f"{tag}: no iec2c given")
                    continue
                gen = args.workdir / d / f"{proj.stem}.gen"
                gen.mkdir(exist_ok=True)
                r = subprocess.run([args.iec2c, "-f", "-l", "-p", "-r", "-R", "-a", "-I", args.matiec_lib, "-T", str(gen), str(out)],
                                   capture_output=True, text=True)
                ok = r.returncode == 0
                if ok:
                    for c in ("Config0.c", "Res0.c"):
                        g = subprocess.run(["gcc", "-std=gnu11", "-w", "-I", str(Path(args.matiec_lib) / "C"), "-I", str(gen),
                                            "-c", str(gen / c), "-o", str(gen / (c + ".o"))], capture_output=True, text=True)
                        if g.returncode:
                            ok = False
                            r = g
                check(ok, f"{tag}: iec2c -f -l -p -r -R -a and gcc -c of its C" + ("" if ok else f"\n{(r.stdout + r.stderr)[-3000:]}"))
            else:
                errs = [f"{res.identifier}: {res.exception}" for res in bparse.parse(str(out)) if res.exception is not None]
                kinds = [type(i).__name__ for res in bparse.parse(str(out)) if res.exception is None
                         for i in getattr(res.transform(), "items", [])]
                check(not errs and kinds == ["GlobalVariableDeclarations", "Program"],
                      f"{tag}: blark parses GVL_SafeLogicIO and PRG_SafeLogic {kinds} {errs[:1]}")
                st = texts[0]
                local = {m.group(1): m.group(2) for m in re.finditer(r"^\s*(\w+)\s*:\s*(FB_\w+)\s*;", st, flags=re.M)}
                bad = crossref(st, known[d], local)
                check(not bad, f"{tag}: every call, parameter and type is in plc_bindings/{d}" + (f": {bad[:3]}" if bad else ""))
    print(f"{passed} passed, {failed} failed")
    return 1 if failed or not passed else 0


if __name__ == "__main__":
    sys.exit(main())
