#!/usr/bin/env python3
"""Layout check of the generated PLC bindings against the C header (run by tools/plc_check.sh).

Needs blark (PyPI) - run it with the interpreter of build/plc-venv.

    plc_layout.py --c-layout FILE [--bindings DIR]

FILE is the output of plc_bindings/tests/layout_dump.c (compiled against include/safelogic.h):
    S <struct> <sizeof>
    F <struct> <member> <offsetof> <sizeof member>

What it does, for every source of ST (each TwinCAT .TcDUT/.TcPOU/.TcGVL/.TcIO file, and the
TwinCAT, CODESYS and IEC plain .st files):
  1. parses the file with blark, unit by unit, long FB bodies in runs of whole statements
     (split_fb; a failure to parse is a failure);
  2. takes every STRUCT declaration (DUT) from the parse result and computes each member's
     offset and the DUT's SIZEOF under pack mode 8 and pack mode 4 (CODESYS/TwinCAT rules:
     a member is aligned to min(its alignment, pack), a STRUCT to min(largest member
     alignment, pack), SIZEOF is rounded up to that), and compares every member - name,
     order, offset, size - and the size with the C program's output (C struct FB_<NAME>
     <-> DUT ST_FB_<NAME>, any other C struct <-> DUT of the same name);
  3. checks that the DUTs of the TwinCAT and CODESYS sources carry {attribute 'pack_mode' := '8'};
  4. checks every function block FB_<NAME>: its VAR_INPUT/VAR_OUTPUT are exactly the C fields
     that are neither reserved (aReserved*) nor private (nested structs), plus tNow/nStatus
     and the STRING sReason, with the C field's size, inputs before outputs in C order; its
     body copies every input into stData, calls the cycle function with the address of
     stData, copies every output and reads sReason with the address of stData;
  5. checks that the self-test FB_SL_SELFTEST (and the IEC SL_SELFTEST_LAYOUT) tests SIZEOF and
     every member offset of every DUT with the C values.
Every failure names the source, the block/struct and the field. Last line: "N passed, M failed".
"""

from __future__ import annotations

import argparse
import hashlib
import multiprocessing
import os
import pickle
import re
import sys
import tempfile
import zlib
from dataclasses import dataclass
from pathlib import Path
from typing import Dict, List, Optional, Tuple

import blark
from blark import parse as bparse
from blark import transform as tf

ROOT = Path(__file__).resolve().parent.parent

SIZES = {
    "BOOL": 1, "BYTE": 1, "SINT": 1, "USINT": 1,
    "WORD": 2, "INT": 2, "UINT": 2,
    "DWORD": 4, "DINT": 4, "UDINT": 4, "REAL": 4, "TIME": 4,
    "LWORD": 8, "LINT": 8, "ULINT": 8, "LREAL": 8, "LTIME": 8,
}


class Result:
    def __init__(self) -> None:
        self.passed = 0
        self.failed = 0

    def ok(self, cond: bool, msg: str) -> bool:
        if cond:
            self.passed += 1
        else:
            self.failed += 1
            print("FAIL " + msg)
        return cond


R = Result()


# ---------------------------------------------------------------------------------------
# C side
# ---------------------------------------------------------------------------------------

@dataclass
class CMember:
    name: str
    offset: int
    size: int


def read_c_layout(path: Path) -> Tuple[Dict[str, int], Dict[str, List[CMember]]]:
    sizes: Dict[str, int] = {}
    members: Dict[str, List[CMember]] = {}
    for line in path.read_text().splitlines():
        parts = line.split()
        if not parts:
            continue
        if parts[0] == "S":
            sizes[parts[1]] = int(parts[2])
            members.setdefault(parts[1], [])
        elif parts[0] == "F":
            members.setdefault(parts[1], []).append(CMember(parts[2], int(parts[3]), int(parts[4])))
    if not sizes:
        raise SystemExit("plc_layout: empty C layout file")
    return sizes, members


def dut_of(cname: str) -> str:
    return "ST_" + cname if is_block(cname) else cname


def is_block(cname: str) -> bool:
    """FB_<NAME> (TwinSAFE) or SF_<Name> (PLCopen Safety)."""
    return cname.startswith("FB_") or cname.startswith("SF_")


def is_sf(cname: str) -> bool:
    return cname.startswith("SF_")


def is_reserved(name: str) -> bool:
    return re.fullmatch(r"aReserved\d*", name) is not None


def library_fields(header: Path) -> set:
    """(struct, field) the library keeps for itself (documented "Private:" in the header, as
    SF_ModeSelector's tModesOff): in the DUT, not in the FB (plcgen.is_reserved)."""
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    import plcgen
    hdr = plcgen.parse_header(header.read_text(encoding="utf-8"))
    return {(st.name, f.name) for st in hdr.structs.values() for f in st.fields
            if plcgen.is_reserved(f) and not is_reserved(f.name)}


LIBRARY_FIELDS: set = set()  # filled in main from the header the bindings were made from


# ---------------------------------------------------------------------------------------
# ST side (blark)
# ---------------------------------------------------------------------------------------

@dataclass
class StMember:
    name: str
    type_name: str          # element type
    count: Optional[int]    # array length


def spec_type(init) -> Tuple[str, Optional[int]]:
    """(type name, array length or None) of a blark initialization object."""
    spec = getattr(init, "spec", None)
    if isinstance(spec, tf.ArraySpecification):
        if len(spec.subranges) != 1:
            raise ValueError(f"multi-dimensional array {init}")
        sr = spec.subranges[0]
        lo, hi = int(str(sr.start)), int(str(sr.stop))
        elem = spec.type
        tname = getattr(elem, "type_name", None) or str(elem)
        return str(tname).strip(), hi - lo + 1
    if spec is not None and hasattr(spec, "type"):
        return str(spec.type).strip(), None
    text = str(init).split(":=")[0].strip()
    return text, None


# The big single-file flavours (one file with every block, ~1 MB) take blark minutes as a whole,
# and their top-level units (TYPE, FUNCTION_BLOCK, FUNCTION, METHOD, INTERFACE, PROGRAM,
# VAR_GLOBAL) are independent: each unit is parsed on its own, on every CPU, and each parse
# result is cached under build/plc-check/blark-cache by the unit's text, so the synthetic pass
# (step 8) parses only what FB_SYNTH changed. A unit that does not parse is a failure, as a
# file that does not parse was.
UNIT_END = {
    "TYPE": "END_TYPE", "FUNCTION_BLOCK": "END_FUNCTION_BLOCK", "FUNCTION": "END_FUNCTION",
    "METHOD": "END_METHOD", "INTERFACE": "END_INTERFACE", "PROGRAM": "END_PROGRAM",
    "VAR_GLOBAL": "END_VAR",
}
UNIT_START = re.compile(r"^(FUNCTION_BLOCK|FUNCTION|TYPE|METHOD|INTERFACE|PROGRAM|VAR_GLOBAL)\b")
CACHE = ROOT / "build" / "plc-check" / "blark-cache"


def split_units(text: str) -> List[Tuple[int, str]]:
    """(first line, text) of each top-level unit, with the comments and pragmas before it;
    trailing text after the last unit is its own piece."""
    pieces: List[Tuple[int, str]] = []
    cur: List[str] = []
    first = 1
    end: Optional[str] = None
    for no, line in enumerate(text.splitlines(keepends=True), 1):
        if not cur:
            first = no
        cur.append(line)
        if end is None:
            m = UNIT_START.match(line)
            if m:
                end = UNIT_END[m.group(1)]
        elif re.match(rf"^{end}\b", line):
            pieces.append((first, "".join(cur)))
            cur, end = [], None
    if cur and "".join(cur).strip():
        pieces.append((first, "".join(cur)))
    return pieces


# The self-test FB_SL_SELFTEST has a body of ~12,700 lines, and blark's Earley parser takes
# ~15 ms a line on this grammar (linear): as one unit it keeps one CPU busy for three minutes,
# and any header change (step 8's FB_SYNTH) makes it new. Its body is a list of top-level
# statements, so a long body is parsed in pieces: the declaration part with an empty body (a
# .TcPOU file: the file with an empty implementation, through blark's TcPOU loader), then runs
# of whole statements, each as plain ST in an FB of the same name with no declarations. The
# grammar's statement list is a repetition and every cut is at a line start outside any
# statement, so if every piece parses, the whole body does; a cut in the wrong place cannot hide
# an error, the pieces on both sides of it then fail to parse. Where a cut falls depends on the
# statements after it (a hash of their text) and on the distance to the previous cut, so a block
# added to the header (step 8) changes only the pieces around its checks. The runs are keyed by
# their text alone (RUN_PATH), so the TwinCAT XML, TwinCAT ST and CODESYS self-tests, whose
# bodies are the same text, are parsed once and the others come from the cache.
RUN_PATH = "statement-run.st"
SPLIT_BODY_LINES = 400
PIECE_MIN_LINES, PIECE_MAX_LINES, PIECE_CUT_ONE_IN = 100, 300, 8
NOT_A_STATEMENT_START = re.compile(r"(END_\w+|ELSIF|ELSE|UNTIL|THEN|DO|OF)\b")


def statement_runs(body: str) -> List[str]:
    """body cut before top-level statements (a letter in column 0 that does not continue or
    close a statement) into runs of PIECE_MIN_LINES..PIECE_MAX_LINES lines where possible."""
    lines = body.splitlines(keepends=True)
    starts = [i for i, line in enumerate(lines) if line[:1].isalpha() and not NOT_A_STATEMENT_START.match(line)]
    cuts = [0]
    # the hash covers the two statements after the cut: one alone may repeat verbatim
    # (nChecked := nChecked + 1;), which would make every one of them a cut or none
    for a, c in zip(starts, starts[2:] + [len(lines)] * 2):
        size = a - cuts[-1]
        if size >= PIECE_MAX_LINES or (
            size >= PIECE_MIN_LINES and zlib.crc32("".join(lines[a:c]).encode()) % PIECE_CUT_ONE_IN == 0
        ):
            cuts.append(a)
    cuts.append(len(lines))
    return ["".join(lines[x:y]) for x, y in zip(cuts, cuts[1:]) if x < y]


def split_fb(label: str, path: str, text: str) -> List[Tuple[str, str, str, str]]:
    """Parse jobs (label, path, text, role) of one FUNCTION_BLOCK unit (plain ST) or one .TcPOU
    file: [unit] when its body is short, else [declaration part] + [body runs] (see above)."""
    if path.endswith(".TcPOU"):
        whole = [(label, path, None, "unit")]
        impl = list(re.finditer(r"(<Implementation>\s*<ST><!\[CDATA\[)(.*?)(\]\]></ST>)", text, re.S))
        name = re.search(r'<POU Name="(\w+)"', text)
        if len(impl) != 1 or not name or impl[0].group(2).count("\n") <= SPLIT_BODY_LINES:
            return whole
        m = impl[0]
        head, tail = text[: m.start(2)], text[m.end(2):]
        jobs = [(f"{label} (declaration)", path, head + tail, "unit")]
        line = text[: m.start(2)].count("\n") + 1
        for run in statement_runs(m.group(2)):
            jobs.append((f"{label}:{line}", RUN_PATH, f"FUNCTION_BLOCK {name.group(1)}\n{run}END_FUNCTION_BLOCK\n", "body"))
            line += run.count("\n")
        return jobs
    whole = [(label, path, text, "unit")]
    lines = text.splitlines(keepends=True)
    first = next((i for i, line in enumerate(lines) if line.startswith("FUNCTION_BLOCK")), None)
    ends = [i for i, line in enumerate(lines) if re.match(r"END_FUNCTION_BLOCK\b", line)]
    if first is None or not ends:
        return whole
    decl_end = max([first + 1] + [i + 1 for i, line in enumerate(lines) if re.match(r"END_VAR\b", line)])
    end = ends[-1]
    if end - decl_end <= SPLIT_BODY_LINES:
        return whole
    name = lines[first].split()[1]
    jobs = [(f"{label} (declaration)", path, "".join(lines[:decl_end] + lines[end:]), "unit")]
    start = int(label.rsplit(":", 1)[1]) + decl_end
    for run in statement_runs("".join(lines[decl_end:end])):
        jobs.append((f"{path}:{start}", RUN_PATH, f"FUNCTION_BLOCK {name}\n{run}END_FUNCTION_BLOCK\n", "body"))
        start += run.count("\n")
    return jobs


def extract(job: Tuple[str, str, Optional[str], str]) -> dict:
    """Parses one file (path) or one unit (text given, parsed through a temp file with the
    path's suffix) and returns plain data: DUTs, FB interfaces and bodies, parse errors, and
    the job's role (a whole unit, or a run of a split body)."""
    label, path, text, role = job
    # The result depends only on the parsed text and the file's name and suffix.
    content = text if text is not None else Path(path).read_text(encoding="utf-8")
    key = hashlib.sha256(
        "\0".join((blark.__version__, Path(path).name, content)).encode()
    ).hexdigest()
    hit = CACHE / f"{key}.pickle"
    if hit.is_file():
        return dict(pickle.loads(hit.read_bytes()), role=role)
    target, tmp = path, None
    if text is not None:
        tmp = tempfile.NamedTemporaryFile("w", suffix=Path(path).suffix, delete=False, encoding="utf-8")
        tmp.write(text)
        tmp.close()
        target = tmp.name
    out: dict = {"errors": [], "duts": {}, "fbs": {}, "bodies": {}}
    try:
        for res in bparse.parse(str(target)):
            if res.exception is not None:
                out["errors"].append(f"blark could not parse {label} ({res.identifier}): {res.exception}")
                continue
            code = res.transform()
            for it in getattr(code, "items", []):
                if isinstance(it, tf.DataTypeDeclaration):
                    d = it.declaration
                    if isinstance(d, tf.StructureTypeDeclaration):
                        members = []
                        for el in d.declarations:
                            tname, count = spec_type(el.init)
                            for v in el.variables:
                                members.append(StMember(str(v.name), tname, count))
                        out["duts"][str(d.name)] = members
                elif isinstance(it, tf.FunctionBlock):
                    blocks: Dict[str, List[Tuple[str, str, Optional[int]]]] = {}
                    for decl in it.declarations:
                        hdr = str(getattr(decl, "block_header", type(decl).__name__)).split()[0]
                        lst = blocks.setdefault(hdr, [])
                        for item in getattr(decl, "items", []):
                            tname, count = spec_type(item.init)
                            for v in item.variables:
                                lst.append((str(getattr(v, "name", v)), tname, count))
                    out["fbs"][str(it.name)] = blocks
                    body = getattr(it, "body", None)
                    if body is not None:
                        out["bodies"][str(it.name)] = str(body)
                elif isinstance(it, tf.StatementList):
                    # TwinCAT XML: the implementation is a separate parse result named <POU>/implementation
                    out["bodies"][str(res.identifier).split("/")[0]] = str(it)
    finally:
        if tmp is not None:
            Path(tmp.name).unlink()
    if not out["errors"]:
        CACHE.mkdir(parents=True, exist_ok=True)
        (CACHE / f"{key}.pickle").write_bytes(pickle.dumps(out))
    return dict(out, role=role)


@dataclass
class Source:
    label: str
    files: List[Path]
    flavour: str               # twincat | codesys | iec
    duts: Dict[str, List[StMember]]
    fbs: Dict[str, Dict[str, List[Tuple[str, str, Optional[int]]]]]  # FB -> block -> [(name, type, count)]
    fb_bodies: Dict[str, str]
    texts: Dict[str, str]      # file text (for pragma checks)


def collect(source: Source, parts: List[dict]) -> None:
    for part in parts:
        for err in part["errors"]:
            R.ok(False, f"{source.label}: {err}")
        source.duts.update(part["duts"])
        if part["role"] == "body":
            # a run of a split body: more statements of an FB whose declarations came before
            for name, body in part["bodies"].items():
                source.fb_bodies[name] = "\n".join(filter(None, (source.fb_bodies.get(name), body)))
        else:
            source.fbs.update(part["fbs"])
            source.fb_bodies.update(part["bodies"])


def layout(duts: Dict[str, List[StMember]], name: str, pack: int, memo) -> Tuple[int, int, List[Tuple[str, int, int]]]:
    """(size, alignment, [(member, offset, size)]) of DUT name under a pack mode."""
    key = (name, pack)
    if key in memo:
        return memo[key]
    if name not in duts:
        raise KeyError(name)
    off = 0
    al = 1
    out = []
    for m in duts[name]:
        if m.type_name.upper() in SIZES:
            esize = SIZES[m.type_name.upper()]
            ealign = esize
        else:
            esize, ealign, _ = layout(duts, m.type_name, pack, memo)
        a = min(ealign, pack)
        off = (off + a - 1) // a * a
        size = esize * (m.count or 1)
        out.append((m.name, off, size))
        off += size
        al = max(al, a)
    al = min(al, pack)
    size = (off + al - 1) // al * al
    memo[key] = (size, al, out)
    return memo[key]


def check_duts(src: Source, csizes, cmembers) -> None:
    for cname in csizes:
        dname = dut_of(cname)
        if not R.ok(dname in src.duts, f"{src.label}: no DUT {dname} for C struct {cname}"):
            continue
        for pack in (8, 4):
            memo: dict = {}
            try:
                size, _, members = layout(src.duts, dname, pack, memo)
            except KeyError as e:
                R.ok(False, f"{src.label}: DUT {dname} uses unknown type {e}")
                break
            what = f"{src.label}: {'block ' if is_block(cname) else 'struct '}{cname} (DUT {dname}, pack mode {pack})"
            cm = cmembers[cname]
            R.ok(len(members) == len(cm),
                 f"{what}: {len(members)} members, C has {len(cm)}")
            for k, c in enumerate(cm):
                if k >= len(members):
                    R.ok(False, f"{what}: field {c.name} missing")
                    continue
                n, o, s = members[k]
                if not R.ok(n == c.name, f"{what}: member {k} is {n}, C field is {c.name}"):
                    continue
                R.ok(o == c.offset, f"{what}: field {c.name} at offset {o}, C offsetof = {c.offset}")
                R.ok(s == c.size, f"{what}: field {c.name} has size {s}, C sizeof = {c.size}")
            R.ok(size == csizes[cname], f"{what}: SIZEOF = {size}, C sizeof = {csizes[cname]}")
    extra = set(src.duts) - {dut_of(c) for c in csizes}
    # The group's storage DUTs of the IEC flavour (SL_MEMBER_STORAGE, SL_LINK_STORAGE) have no
    # C struct of their own: the C side sees them as arrays. SL_LINK_STORAGE must hold whole
    # SL_LINKs; SL_MEMBER_STORAGE 16 bytes (a 64-bit SL_MEMBER) per member, 8-byte aligned.
    for name in sorted(x for x in extra if x.endswith("_STORAGE")):
        memo = {}
        for pack in (8, 4):
            size, align, _ = layout(src.duts, name, pack, memo)
            if name == "SL_LINK_STORAGE" and "SL_LINK" in csizes:
                R.ok(size > 0 and size % csizes["SL_LINK"] == 0,
                     f"{src.label}: SL_LINK_STORAGE SIZEOF {size} is not a whole number of SL_LINK ({csizes['SL_LINK']})")
            elif name == "SL_MEMBER_STORAGE":
                R.ok(size > 0 and size % 16 == 0 and align == min(8, pack),
                     f"{src.label}: SL_MEMBER_STORAGE SIZEOF {size} / alignment {align}: not 16-byte slots, aligned to min(8, pack {pack})")
            else:
                R.ok(False, f"{src.label}: storage DUT {name} of unknown purpose")
        extra.discard(name)
    R.ok(not extra, f"{src.label}: DUTs without a C struct: {sorted(extra)}")


def check_pack_pragma(src: Source) -> None:
    if src.flavour not in ("twincat", "codesys"):
        return
    alltext = "\n".join(src.texts.values())
    for dname in src.duts:
        pat = r"\{attribute\s+'pack_mode'\s*:=\s*'8'\}\s*TYPE\s+" + re.escape(dname) + r"\b"
        R.ok(re.search(pat, alltext) is not None,
             f"{src.label}: DUT {dname} lacks {{attribute 'pack_mode' := '8'}} right before TYPE")


def check_fbs(src: Source, csizes, cmembers) -> None:
    for cname in csizes:
        if not is_block(cname):
            continue
        fbname = cname  # the user-facing FB carries the C struct's name
        if not R.ok(fbname in src.fbs, f"{src.label}: block {cname}: no FUNCTION_BLOCK {fbname}"):
            continue
        blocks = src.fbs[fbname]
        ins = blocks.get("VAR_INPUT", [])
        outs = blocks.get("VAR_OUTPUT", [])
        public = [m for m in cmembers[cname] if not is_reserved(m.name) and (cname, m.name) not in LIBRARY_FIELDS
                  and not is_nested_struct(m, src, cname)]
        byname = {m.name: m for m in public}
        seen_in = [n for n, _, _ in ins if n != "tNow"]
        seen_out = [n for n, _, _ in outs if n not in ("nStatus", "sReason")]
        if is_sf(cname):
            # A PLCopen FB has exactly the PLCopen inputs: it reads its time into a VAR tNow.
            R.ok(not any(n == "tNow" for n, _, _ in ins), f"{src.label}: block {cname}: tNow is no VAR_INPUT")
            R.ok(any(n == "tNow" and t.upper() == "UDINT" for n, t, _ in blocks.get("VAR", [])),
                 f"{src.label}: block {cname}: VAR tNow : UDINT missing")
        else:
            R.ok(any(n == "tNow" and t.upper() == "UDINT" for n, t, _ in ins),
                 f"{src.label}: block {cname}: VAR_INPUT tNow : UDINT missing")
        R.ok(any(n == "nStatus" and t.upper() == "DINT" for n, t, _ in outs),
             f"{src.label}: block {cname}: VAR_OUTPUT nStatus : DINT missing")
        R.ok(any(n == "sReason" and t.upper().startswith("STRING") for n, t, _ in outs),
             f"{src.label}: block {cname}: VAR_OUTPUT sReason : STRING missing")
        R.ok(sorted(seen_in + seen_out) == sorted(byname),
             f"{src.label}: block {cname}: FB variables {sorted(set(seen_in + seen_out) ^ set(byname))} "
             f"differ from the public C fields")
        if seen_in and seen_out and all(n in byname for n in seen_in + seen_out):
            R.ok(max(byname[n].offset for n in seen_in) < min(byname[n].offset for n in seen_out),
                 f"{src.label}: block {cname}: an output field precedes an input field in C")
        for n, t, count in ins + outs:
            if n not in byname:
                continue
            esize = SIZES[t.upper()] if t.upper() in SIZES else layout(src.duts, t, 8, {})[0]
            size = esize * (count or 1)
            R.ok(size == byname[n].size,
                 f"{src.label}: block {cname} field {n}: FB type {t} has {size} bytes, C field {byname[n].size}")
        body = src.fb_bodies.get(fbname, "")
        if not R.ok(bool(body), f"{src.label}: block {cname}: no implementation found"):
            continue
        flat = re.sub(r"\s+", " ", body)
        R.ok(re.search(r"nStatus := \w+\(\s*pFb := (ADR|REF)\(stData\), tNow := tNow\)", flat) is not None,
             f"{src.label}: block {cname}: body does not call the cycle function with the address of stData and tNow")
        if is_sf(cname):
            R.ok(re.search(r"tNow := (SL_TIME_NOW_MS\(EN := TRUE\)|TIME_TO_UDINT\(TIME\(\)\));", flat) is not None,
                 f"{src.label}: block {cname}: body does not read the time before the call")
        # sReason: the reason text of this very instance, after a refusal or in ERROR
        R.ok(re.search(r"sReason := \w+\(\s*(nType := UDINT_TO_UINT\(\w+\.SL_TYPE_\w+\), pBlock := ADR|pFb := (ADR|REF))"
                       r"\(stData\)\)", flat) is not None,
             f"{src.label}: block {cname}: body does not read sReason from the address of stData")
        for n in seen_in:
            R.ok(re.search(rf"stData\.{n}(\[\d+\])? := (TIME_TO_UDINT\(|SL_TIME_TO_MS\(tIn := )?{n}\b", flat)
                 is not None,
                 f"{src.label}: block {cname} field {n}: input not copied into stData")
        for n in seen_out:
            R.ok(re.search(rf"\b{n}(\[\d+\])? := (UDINT_TO_TIME\()?stData\.{n}\b", flat) is not None,
                 f"{src.label}: block {cname} field {n}: output not copied from stData")


def is_nested_struct(m: CMember, src: Source, cname: str) -> bool:
    """A struct member that is not an interface field (the private state); an array of
    structs (a value table, LOADSENSING's aRow) is an interface field."""
    dname = dut_of(cname)
    for sm in src.duts.get(dname, []):
        if sm.name == m.name:
            return sm.type_name.upper() not in SIZES and sm.count is None
    return False


def check_selftest(src: Source, csizes, cmembers) -> None:
    text = "\n".join(src.texts.values())
    found: Dict[Tuple[str, Optional[str]], int] = {}
    if src.flavour == "iec":
        # matiec's C names are upper case (ST_SF_EmergencyStop -> ST_SF_EMERGENCYSTOP)
        vars_ = dict((v, t.upper()) for t, v in re.findall(r"^\s*(\w+) (sl_plc_\w+);$", text, re.M))
        for v, val in re.findall(r"sizeof\((\w+)\) != (\d+)", text):
            found[(vars_.get(v, "?"), None)] = int(val)
        for v, f, val in re.findall(r"\(char \*\)&(\w+)\.(\w+) - \(char \*\)&\1 != (\d+)", text):
            found[(vars_.get(v, "?"), f.upper())] = int(val)
        norm = str.upper
    else:
        decl = src.fbs.get("FB_SL_SELFTEST", {}).get("VAR", [])
        vars_ = {n: t for n, t, _ in decl}
        for v, val in re.findall(r"SIZEOF\((\w+)\) <> (\d+)", text):
            found[(vars_.get(v, "?"), None)] = int(val)
        for v, f, val in re.findall(r"ADR\((\w+)\.(\w+)\) - ADR\(\1\) <> (\d+)", text):
            found[(vars_.get(v, "?"), f)] = int(val)
        norm = str
    for cname, size in csizes.items():
        d = dut_of(cname)
        R.ok(found.get((norm(d), None)) == size,
             f"{src.label}: self-test: SIZEOF of {d} (C struct {cname}) checked against {found.get((norm(d), None))}, C sizeof = {size}")
        for m in cmembers[cname]:
            got = found.get((norm(d), norm(m.name)))
            R.ok(got == m.offset,
                 f"{src.label}: self-test: {'block' if is_block(cname) else 'struct'} {cname} field {m.name}: "
                 f"checked against {got}, C offsetof = {m.offset}")


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--c-layout", type=Path, required=True)
    ap.add_argument("--bindings", type=Path, default=ROOT / "plc_bindings")
    ap.add_argument("--sources", default="twincat-xml,twincat-st,codesys,iec",
                    help="comma list of: twincat-xml, twincat-st, codesys, iec (default: all)")
    args = ap.parse_args()
    # The header the bindings were generated from: the repository's, or the synthetic one
    # beside the synthetic bindings (tools/plc_synthetic.py).
    header = next(h for h in (args.bindings.parent / "include/safelogic.h", args.bindings.parent / "safelogic.h")
                  if h.exists())
    LIBRARY_FIELDS.update(library_fields(header))
    wanted = set(args.sources.split(","))
    csizes, cmembers = read_c_layout(args.c_layout)
    b = args.bindings

    tc_xml = sorted(p for ext in ("TcDUT", "TcPOU", "TcGVL", "TcIO") for p in (b / "twincat").rglob(f"*.{ext}"))
    sources = [
        ("twincat-xml", Source("twincat XML (.TcDUT/.TcPOU/.TcGVL/.TcIO)", tc_xml, "twincat", {}, {}, {}, {})),
        ("twincat-st", Source("twincat/safelogic_twincat.st", [b / "twincat/safelogic_twincat.st"], "twincat", {}, {}, {}, {})),
        ("codesys", Source("codesys/safelogic_codesys.st", [b / "codesys/safelogic_codesys.st"], "codesys", {}, {}, {}, {})),
        ("iec", Source("iec/safelogic_iec.st", [b / "iec/safelogic_iec.st"], "iec", {}, {}, {}, {})),
    ]
    unknown = wanted - {k for k, _ in sources}
    if unknown:
        raise SystemExit(f"plc_layout: unknown --sources {sorted(unknown)}")
    sources = [src for k, src in sources if k in wanted]
    R.ok(bool(tc_xml) or "twincat-xml" not in wanted, "no TwinCAT XML files found")
    nfiles = 0
    with multiprocessing.Pool(os.cpu_count() or 1) as pool:
        for src in sources:
            jobs: List[Tuple[str, str, Optional[str], str]] = []
            for path in src.files:
                if not R.ok(path.is_file(), f"{src.label}: {path} missing"):
                    continue
                text = path.read_text(encoding="utf-8")
                src.texts[str(path)] = text
                nfiles += 1
                if path.suffix == ".TcPOU":
                    jobs.extend(split_fb(str(path), str(path), text))
                    continue
                if path.suffix != ".st":
                    jobs.append((str(path), str(path), None, "unit"))
                    continue
                if src.flavour == "iec":
                    # blark 0.8.3's grammar has POINTER TO/REFERENCE TO but not the IEC ed. 3
                    # REF_TO/REF(); both occur only in function parameters and call arguments
                    # (never inside a DUT). Parse a copy with that one-to-one token
                    # substitution; the strict tree-sitter check reads the file unmodified.
                    text = re.sub(r"\bREF_TO\b", "POINTER TO", text)
                    text = re.sub(r"\bREF\(", "ADR(", text)
                for line, unit in split_units(text):
                    jobs.extend(split_fb(f"{path}:{line}", str(path), unit))
            collect(src, pool.map(extract, jobs, chunksize=4))
            check_duts(src, csizes, cmembers)
            check_pack_pragma(src)
            check_fbs(src, csizes, cmembers)
            check_selftest(src, csizes, cmembers)
            nfb = sum(1 for c in csizes if is_block(c))
            print(f"{src.label}: {len(src.files)} file(s) parsed by blark ({len(jobs)} parse units), "
                  f"{len(src.duts)} DUTs, {nfb} block FBs checked against {len(csizes)} C structs "
                  f"(pack 8 and 4)")
    print(f"plc_layout: {nfiles} files; {R.passed} passed, {R.failed} failed")
    return 1 if R.failed else 0


if __name__ == "__main__":
    sys.exit(main())
