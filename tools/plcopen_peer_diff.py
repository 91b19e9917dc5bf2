#!/usr/bin/env python3
"""Differential run of our PLCopen SF_ blocks against the open-source peer ST (research
plcopen_safety.md §6 #1), both compiled and run in one process, over random input sequences.

    python3 tools/plcopen_peer_diff.py --iec2c build/matiec/iec2c --matiec-lib build/matiec/lib \\
        --workdir build/peer-diff [--peer FILE | --fetch] [--sequences N] [--steps N] [--seed S]

The peer: LeonOss/CycleBoundedModelCheckingTest, Benchmark/sac18_cyclebmc/programs/st/plcopen.st
at commit PEER_COMMIT (v1.0 semantics, no licence: it is read at run time, never stored in this
repository). `--fetch` downloads exactly that file and checks its SHA-256; `--peer` takes a copy.

1. The peer's function blocks that we implement are cut out of the file and adapted for matiec
   by ADAPTATIONS only (mechanical, no logic changed): SAFEBOOL -> BOOL, the peer's TONX -> the
   standard TON, CASE on the WORD DiagCode -> CASE WORD_TO_UINT(DiagCode), hexadecimal CASE
   labels -> decimal (IEC 61131-3 case labels are signed integers), BOOL sums -> BOOL_TO_UINT.
2. A matiec PROGRAM calls one peer instance per block; the driver (C, same process) writes the
   peer FB's inputs into matiec's instance, sets matiec's clock (__CURRENT_TIME, what TON
   reads), runs the cycle, and calls our sl_sf_<name>_cycle with the same inputs and time and
   the v1.0 DiagCode profile (the peer's numbering).
3. Every sequence starts with both blocks idle (Activate FALSE) and random constant times; per
   cycle each input flips with a small probability, time advances by a random step. After
   every call DiagCode, Ready, Error and the safety output are compared. The first
   disagreement of a sequence is recorded (afterwards the two states have diverged) and
   classified by CLASSES; an unclassified disagreement fails the run. It also fails when one
   of our v1.0 DiagCodes was never reached (the run must reach what it compares).
Prints the table of docs/plcopen-peer-diff.md's form and "N passed, M failed".
"""
from __future__ import annotations

import argparse
import hashlib
import re
import sys
import urllib.request
from collections import Counter, defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tools"))
import plcgen  # noqa: E402
from plc_matiec_run import add_matiec_args, build_matiec, run  # noqa: E402

PEER_REPO = "LeonOss/CycleBoundedModelCheckingTest"
PEER_COMMIT = "e1cfea70aa78ba394384653835b905e5134bad29"
PEER_PATH = "Benchmark/sac18_cyclebmc/programs/st/plcopen.st"
PEER_SHA256 = "ccc583f2818e33e726dd25104da019a64cff45b72f217017e0dbda01c583703a"
PEER_URL = f"https://raw.githubusercontent.com/{PEER_REPO}/{PEER_COMMIT}/{PEER_PATH}"

# Our block -> the peer's FB of the same function (v1.0 names) and input renames (ours: peer's).
PEER_FB = {
    "SF_EmergencyStop": ("SF_EmergencyStop", {}),
    "SF_ESPE": ("SF_ESPE", {}),
    "SF_Equivalent": ("SF_Equivalent", {}),
    "SF_Antivalent": ("SF_Antivalent", {}),
    "SF_Guard": ("SF_GuardMonitoring", {}),
    "SF_SafetyRequest": ("SF_SafetyRequest", {}),
    "SF_EnableSwitch": ("SF_EnableSwitch", {}),
    "SF_TwoHandControlTypeII": ("SF_TwoHandControlTypeII", {}),
    "SF_TwoHandControlTypeIII": ("SF_TwoHandControlTypeIII", {}),
    "SF_ModeSelector": ("SF_ModeSelector", {}),
}

# Constant times a sequence picks from (ms): T#0 (research §8.13), short, long.
TIMES = (0, 20, 50, 200)
# Time steps between two calls (ms).
# 600 ms: longer than SF_TwoHandControlTypeIII's fixed 500 ms synchronism time.
STEPS = (1, 4, 10, 30, 120, 600)
# BOOL inputs that are constants of our block (latched at activation): set per sequence, never
# flipped (a change while activated is our library fault C3FD, not a PLCopen state).
CONST_BOOLS = ("AutoSetMode",)

# The classification of a disagreement: (id, block regex, predicate on the record, text).
# A record: block, prev (the code both had before the call), peer, ours (the codes after it),
# ins (input name -> 0/1 or ms), outs (the outputs that differ), in_state (ms since our state
# was entered). The ids are the rows of docs/plcopen-peer-diff.md.
# The waiting states with a monitored time: block -> (the time input, v1.0 waiting state ->
# the v1.0 error it ends in when the time has elapsed).
TIMED_WAITS = {
    "SF_Equivalent": ("DiscrepancyTime", {0x8004: 0xC001, 0x8014: 0xC002, 0x8005: 0xC003}),
    "SF_Antivalent": ("DiscrepancyTime", {0x8004: 0xC001, 0x8014: 0xC002, 0x8005: 0xC003}),
    "SF_Guard": ("DiscrepancyTime", {0x8004: 0xC011, 0x8014: 0xC012}),
    "SF_SafetyRequest": ("MonitoringTime", {0x8003: 0xC003}),
}

CLASSES = [
    ("D1", r"SF_(Equivalent|Antivalent|Guard|SafetyRequest)$",
     lambda r: r["ours"] == TIMED_WAITS[r["block"]][1].get(r["prev"])
     and r["in_state"] >= r["ins"][TIMED_WAITS[r["block"]][0]] and r["peer"] < 0xC000,
     "peer bug (§6: timers): the peer calls its monitoring TONX only on the transition into the "
     "waiting state (and with IN FALSE elsewhere), never while waiting, so its Q never rises and "
     "the timeout error is never reached (the peer stays, or takes the next guard); ours: the "
     "error once the monitored time has elapsed since the entry, before every other guard "
     "(PP1, QG, QR)"),
    ("D2", r"SF_Antivalent$",
     lambda r: r["prev"] == 0x8000 and r["ins"]["S_ChannelNC"] == 0 and r["ins"]["S_ChannelNO"] == 1
     and r["peer"] == 0x8005 and r["ours"] == 0x8001,
     "peer bug (§6: Antivalent unreachable guard): in 8000 the peer tests 'NOT NC OR NO' before "
     "'NOT NC AND NO', so both channels inactive go to 8005 (and then C003); ours: 8001 (PP1)"),
    ("D3", r"SF_SafetyRequest$",
     lambda r: r["prev"] == 0x8001 and r["peer"] == 0x8001 and r["ours"] == 0xC001 and r["ins"]["Reset"] == 1,
     "peer gap (§6: 'SafetyRequest lacks static-reset check in init'): a Reset held in INIT "
     "leaves the peer waiting in 8001; ours: the static-reset error C001 (v2.01 C001), as in every "
     "other wait for a Reset edge (QR2)"),
    ("D4", r"SF_EnableSwitch$",
     lambda r: r["prev"] == 0xC040 and r["ins"]["Reset"] == 1 and r["ins"]["S_AutoReset"] == 0
     and (r["peer"], r["ours"]) in ((0xC002, 0x8007), (0xC040, 0xC002)),
     "peer bug (§4.9: C040's static-reset guard written 'Reset AND R_TRIG.Q'): a Reset edge in C040 "
     "gives the peer C002 (ours: 8007, the reset), a held Reset leaves it in C040 (ours: C002) (QN5)"),
    ("D5", r"SF_TwoHandControlTypeIII$",
     lambda r: r["prev"] in (0x8005, 0x8006)
     and ((0xC004 <= r["peer"] <= 0xC006 and r["in_state"] <= 500)
          or (r["peer"] == r["prev"] and r["ours"] == 0x8004)),
     "peer bug (§4.7: the 500 ms TON is never called with IN FALSE): after its first expiry its Q "
     "stays TRUE, so in a later 8005/8006 the peer takes its timer branch at once: C004-C006 within "
     "500 ms of the first button, or no transition at all with both buttons released (its nested "
     "IF has no released case); ours: the time from each entry, an error only after more than "
     "500 ms, both released -> 8004 (QH3)"),
    ("D6", r"SF_ModeSelector$",
     lambda r: r["prev"] in (0xC001, 0xC002) and r["ours"] == r["prev"] and r["ins"]["Reset"] == 1
     and r["peer"] in (0x8005, r["prev"] + 2),
     "v1.0 vs v2.01 (QM1): the peer (v1.0) leaves C001/C002 on a Reset edge, or goes to the "
     "static-reset error C003/C004, while the fault is still present or in the call in which it "
     "disappears; ours (one machine, v2.01) stays in C010/C020 while the fault is present and "
     "enters C410/C420 (shown as C001/C002 in v1.0) in that call, taking Reset from the next"),
    ("D7", r"SF_ModeSelector$",
     lambda r: r["prev"] == 0x8005 and r["peer"] == 0x8005 and r["ours"] == 0xC002
     and sum(r["ins"][f"S_Mode{i}"] for i in range(8)) == 0,
     "peer bug (§4.8: ModeMonitorTime trigger inverted, timer called only on edges): all S_ModeX "
     "FALSE for longer than ModeMonitorTime since the last one fell is C002 for us, not for the "
     "peer (QM4)"),
    ("D8", r"SF_ModeSelector$",
     lambda r: r["prev"] == 0x8004 and r["peer"] == 0x8000 and r["ours"] == 0x8005
     and r["ins"]["S_Unlock"] == 1,
     "reading (QM3): on S_Unlock with S_ModeX other than the locked selection the peer goes to 8000 "
     "and selects the new mode without S_SetMode; ours: 8005 (MODE_CHANGED), a new S_SetMode edge "
     "needed"),
]



def peer_text(args) -> str:
    if args.peer:
        data = Path(args.peer).read_bytes()
    else:
        try:
            with urllib.request.urlopen(PEER_URL, timeout=60) as r:
                data = r.read()
        except OSError as e:
            sys.exit(f"FAIL: cannot download {PEER_URL} ({e}); get the file and pass --peer FILE")
    digest = hashlib.sha256(data).hexdigest()
    if digest != PEER_SHA256:
        sys.exit(f"FAIL: the peer file's SHA-256 is {digest}, expected {PEER_SHA256} ({PEER_URL})")
    return data.decode("utf-8")


def adapt(fb_text: str) -> str:
    """The ADAPTATIONS of the module doc: spelling for matiec, no change of logic."""
    t = re.sub(r"\bSAFEBOOL\b", "BOOL", fb_text)
    t = re.sub(r"\bTONX\b", "TON", t)
    t = t.replace("CASE DiagCode OF", "CASE WORD_TO_UINT(DiagCode) OF")
    t = re.sub(r"(?m)^(\s*)16#([0-9A-Fa-f]+)(\s*[,:])",
               lambda m: m.group(1) + str(int(m.group(2), 16)) + m.group(3), t)
    t = re.sub(r"\bS_Mode(\d)(?=\s*\+)", r"BOOL_TO_UINT(S_Mode\1)", t)
    t = re.sub(r"(\+\s*)S_Mode(\d)\b", r"\1BOOL_TO_UINT(S_Mode\2)", t)
    return t


def peer_fbs(text: str) -> dict:
    return {m.group(1): m.group(0) for m in
            re.finditer(r"FUNCTION_BLOCK\s+(\w+)\b.*?END_FUNCTION_BLOCK", text, re.S)}


def var_section(fb_text: str, kind: str) -> list:
    """(name, type) of a VAR_INPUT / VAR_OUTPUT section."""
    m = re.search(rf"\b{kind}\b(.*?)\bEND_VAR", fb_text, re.S)
    out = []
    for line in (m.group(1) if m else "").splitlines():
        d = re.match(r"\s*(\w+)\s*:\s*(\w+)", re.sub(r"\(\*.*?\*\)", "", line))
        if d:
            out.append((d.group(1), d.group(2).upper()))
    return out


class Pair:
    """One of our blocks with its peer FB: which inputs, times and outputs are shared."""

    def __init__(self, b: plcgen.Block, peer_name: str, renames: dict, fb_text: str):
        self.b, self.peer = b, peer_name
        self.var = f"p{b.name}"
        pins = dict(var_section(fb_text, "VAR_INPUT"))
        pouts = dict(var_section(fb_text, "VAR_OUTPUT"))
        ours_in = {f.name: f for f in b.inputs}
        self.bools, self.times = [], []
        for name, typ in pins.items():
            mine = {v: k for k, v in renames.items()}.get(name, name)
            if mine not in ours_in:
                continue
            (self.times if typ == "TIME" else self.bools).append((mine, name))
        self.outs = [(f.name, f.name) for f in b.outputs if f.name in pouts and f.name != "DiagCode"]
        self.output = [o for o, _ in self.outs if o.startswith("S_")]


def program(pairs) -> str:
    out = ["", "PROGRAM prog0", "VAR"]
    out += [f"    {p.var} : {p.peer};" for p in pairs]
    out += ["END_VAR"] + [f"{p.var}();" for p in pairs] + ["END_PROGRAM", "",
            "CONFIGURATION Config0", "  RESOURCE Res0 ON PLC",
            "    TASK task0(INTERVAL := T#10ms, PRIORITY := 0);",
            "    PROGRAM instance0 WITH task0 : prog0;", "  END_RESOURCE", "END_CONFIGURATION", ""]
    return "\n".join(out)


def probe_c(pairs) -> str:
    """Reads and writes the peer instances (compiled with matiec's headers and POUS.h)."""
    out = ["/* generated by tools/plcopen_peer_diff.py */", '#include "iec_std_lib.h"', '#include "POUS.h"',
           "extern PROG0 RES0__INSTANCE0;", ""]
    for p in pairs:
        inst = f"RES0__INSTANCE0.{p.var.upper()}"
        out.append(f"void peer_{p.b.lower}_set(const unsigned char *b, const unsigned *t)")
        out.append("{")
        for i, (_, peer) in enumerate(p.bools):
            out.append(f"    {inst}.{peer.upper()}.value = b[{i}];")
        for i, (_, peer) in enumerate(p.times):
            out.append(f"    {inst}.{peer.upper()}.value.tv_sec = t[{i}] / 1000u;")
            out.append(f"    {inst}.{peer.upper()}.value.tv_nsec = (long)(t[{i}] % 1000u) * 1000000L;")
        out.append("}")
        out.append(f"void peer_{p.b.lower}_get(unsigned char *o, unsigned short *diag)")
        out.append("{")
        for i, (_, peer) in enumerate(p.outs):
            out.append(f"    o[{i}] = {inst}.{peer.upper()}.value;")
        out.append(f"    *diag = {inst}.DIAGCODE.value;")
        out.append("}")
    return "\n".join(out) + "\n"


def driver_c(pairs, sequences: int, steps: int, seed: int) -> str:
    out = ["/* generated by tools/plcopen_peer_diff.py */", "#include <stdio.h>", "#include <string.h>",
           '#include "safelogic.h"', "",
           "void config_init__(void);", "void config_run__(unsigned long tick);",
           "typedef struct { long int tv_sec; long int tv_nsec; } IEC_TIMESPEC_;",
           "IEC_TIMESPEC_ __CURRENT_TIME;", "unsigned char __DEBUG;", "",
           f"static unsigned long long rng = {seed}ull;",
           "static unsigned rnd(unsigned n) { rng ^= rng << 13; rng ^= rng >> 7; rng ^= rng << 17; "
           "return (unsigned)((rng >> 11) % n); }",
           f"static const unsigned TIMES[] = {{{', '.join(map(str, TIMES))}}};",
           f"static const unsigned STEPS[] = {{{', '.join(map(str, STEPS))}}};",
           "static unsigned now_ms = 1000;", "static unsigned long tick;",
           "static long compared;", ""]
    for p in pairs:
        nb, nt, no = len(p.bools), max(len(p.times), 1), max(len(p.outs), 1)
        lo = p.b.lower
        out += [f"void peer_{lo}_set(const unsigned char *b, const unsigned *t);",
                f"void peer_{lo}_get(unsigned char *o, unsigned short *diag);",
                f"static {p.b.struct.name} o_{lo};",
                f"static unsigned char in_{lo}[{nb}];", f"static unsigned t_{lo}[{nt}];",
                f"static int live_{lo}; static unsigned hold_{lo}; static unsigned entered_{lo};",
                f"static unsigned tr_{lo}[128]; static int ntr_{lo};",
                f"static unsigned reached_{lo}[65536 / 32];", ""]
        out.append(f"static void step_{lo}(int seq, int k, int fresh)")
        out.append("{")
        out.append("    int i;")
        out.append("    if (fresh) {")
        out.append(f"        memset(in_{lo}, 0, sizeof in_{lo});")
        for i, (mine, _) in enumerate(p.bools):
            if mine in CONST_BOOLS:
                out.append(f"        in_{lo}[{i}] = (unsigned char)rnd(2);")
        for i in range(len(p.times)):
            out.append(f"        t_{lo}[{i}] = TIMES[rnd({len(TIMES)})];")
        out.append(f"        live_{lo} = 1;")
        out.append(f"    }} else if (!live_{lo} && hold_{lo} == 0) {{")
        out.append(f"        in_{lo}[0] = 0; /* after a disagreement and the calls held: one idle call, then compare again */")
        out.append(f"        live_{lo} = 1;")
        out.append("    } else {")
        out.append(f"        if (!live_{lo}) hold_{lo}--; /* diverged: our block goes on (its states are counted), not compared */")
        keep = "".join(f" && i != {i}" for i, (mine, _) in enumerate(p.bools) if mine in CONST_BOOLS)
        out.append(f"        for (i = 0; i < {nb}; i++) {{")
        out.append(f"            if (i == 0) {{ if (rnd(100) < (in_{lo}[0] ? 2u : 40u)) in_{lo}[0] ^= 1; }}")
        out.append(f"            else if (rnd(100) < 15u{keep}) in_{lo}[i] ^= 1;")
        out.append("        }")
        out.append("    }")
        out.append(f"    peer_{lo}_set(in_{lo}, t_{lo});")
        # our struct: the same inputs, the v1.0 profile, the same times
        for i, (mine, _) in enumerate(p.bools):
            out.append(f"    o_{lo}.{mine} = in_{lo}[{i}];")
        for i, (mine, _) in enumerate(p.times):
            out.append(f"    o_{lo}.{mine} = t_{lo}[{i}];")
        out.append(f"    o_{lo}.nDiagProfile = 1;")
        out.append(f"    {p.b.cycle.name}(&o_{lo}, now_ms);")
        out.append("    (void)seq; (void)k; /* the peer runs in config_run__, after every step_ */")
        out.append("}")
        out.append(f"static void check_{lo}(int seq, int k, unsigned short prev, unsigned prev_entered)")
        out.append("{")
        out.append(f"    unsigned char po[{no}]; unsigned short pd; int differ = 0; int i;")
        out.append(f"    peer_{lo}_get(po, &pd);")
        out.append(f"    reached_{lo}[o_{lo}.DiagCode >> 5] |= 1u << (o_{lo}.DiagCode & 31);")
        out.append(f"    if (o_{lo}.DiagCode != prev) entered_{lo} = now_ms;")
        out.append(f"    if (!live_{lo}) return;")
        out.append("    compared++;")
        out.append(f"    if (pd == o_{lo}.DiagCode) {{ unsigned t = ((unsigned)prev << 16) | pd; int j; "
                   f"for (j = 0; j < ntr_{lo} && tr_{lo}[j] != t; j++) {{}} "
                   f"if (j == ntr_{lo} && j < 128) tr_{lo}[ntr_{lo}++] = t; }}")
        out.append(f"    if (pd != o_{lo}.DiagCode) differ = 1;")
        for i, (mine, _) in enumerate(p.outs):
            out.append(f"    if (po[{i}] != o_{lo}.{mine}) differ = 1;")
        out.append("    if (!differ) return;")
        out.append(f"    live_{lo} = 0;")
        out.append(f"    hold_{lo} = rnd(8);")
        out.append(f'    printf("DIFF {p.b.name} seq=%d cycle=%d prev=%04X peer=%04X ours=%04X in_state=%u", '
                   f"seq, k, prev, pd, o_{lo}.DiagCode, now_ms - prev_entered);")
        for i, (mine, _) in enumerate(p.bools):
            out.append(f'    printf(" {mine}=%u", in_{lo}[{i}]);')
        for i, (mine, _) in enumerate(p.times):
            out.append(f'    printf(" {mine}=%u", t_{lo}[{i}]);')
        for i, (mine, _) in enumerate(p.outs):
            out.append(f'    if (po[{i}] != o_{lo}.{mine}) printf(" out:{mine}=%u/%u", po[{i}], o_{lo}.{mine});')
        out.append('    printf("\\n");')
        out.append("    (void)i;")
        out.append("}")
        out.append("")
    out += ["int main(void)", "{", "    int s, k;", "    config_init__();",
            f"    for (s = 0; s < {sequences}; s++) {{", f"        for (k = 0; k < {steps}; k++) {{"]
    for p in pairs:
        out.append(f"            unsigned short prev_{p.b.lower} = o_{p.b.lower}.DiagCode; unsigned ent_{p.b.lower} = entered_{p.b.lower};")
    out += ["            if (k > 0) now_ms += STEPS[rnd(sizeof STEPS / sizeof STEPS[0])];",
            "            __CURRENT_TIME.tv_sec = now_ms / 1000u;",
            "            __CURRENT_TIME.tv_nsec = (long)(now_ms % 1000u) * 1000000L;"]
    for p in pairs:
        out.append(f"            step_{p.b.lower}(s, k, k == 0);")
    out.append("            config_run__(tick++);")
    for p in pairs:
        out.append(f"            check_{p.b.lower}(s, k, prev_{p.b.lower}, ent_{p.b.lower});")
    out += ["        }", "    }"]
    for p in pairs:
        out.append(f'    printf("TRANSITIONS {p.b.name} %d\\n", ntr_{p.b.lower});')
    for p in pairs:
        out.append(f"    {{ unsigned c; printf(\"REACHED {p.b.name}\"); for (c = 0; c < 65536u; c++) "
                   f"if (reached_{p.b.lower}[c >> 5] & (1u << (c & 31))) printf(\" %04X\", c); printf(\"\\n\"); }}")
    out += ['    printf("COMPARED %ld\\n", compared);', "    return 0;", "}", ""]
    return "\n".join(out)



def parse_record(line: str) -> dict:
    parts = line.split()
    r = {"block": parts[1], "ins": {}, "outs": []}
    for p in parts[2:]:
        k, v = p.split("=", 1)
        if k.startswith("out:"):
            r["outs"].append(k[4:])
        elif k in ("seq", "cycle", "in_state"):
            r[k] = int(v)
        elif k in ("prev", "peer", "ours"):
            r[k] = int(v, 16)
        else:
            r["ins"][k] = int(v)
    return r


def classify(r: dict):
    for cid, pat, pred, _ in CLASSES:
        if re.match(pat, r["block"]) and pred(r):
            return cid
    return None


def main() -> int:
    ap = argparse.ArgumentParser()
    add_matiec_args(ap)
    ap.add_argument("--header", type=Path, default=ROOT / "include/safelogic.h")
    src = ap.add_mutually_exclusive_group(required=True)
    src.add_argument("--peer", help="a copy of the peer's plcopen.st (checked against PEER_SHA256)")
    src.add_argument("--fetch", action="store_true", help=f"download it from {PEER_URL}")
    ap.add_argument("--sequences", type=int, default=20000)
    ap.add_argument("--steps", type=int, default=40)
    ap.add_argument("--seed", type=lambda s: int(s, 0), default=0x5AFE_D1FF)
    ap.add_argument("--show", type=int, default=3, help="example records printed per class")
    ap.add_argument("--selftest", action="store_true",
                    help="break the peer's SF_EmergencyStop on purpose (S_AutoReset ignored in 8005): the run "
                         "must then report unclassified disagreements for it, and passes only if it does")
    args = ap.parse_args()

    hdr = plcgen.parse_header(args.header.read_text(encoding="utf-8"))
    fbs = peer_fbs(peer_text(args))
    pairs = [Pair(b, PEER_FB[b.struct.name][0], PEER_FB[b.struct.name][1], fbs[PEER_FB[b.struct.name][0]])
             for b in hdr.blocks if b.struct.name in PEER_FB]
    w = args.workdir
    gen = w / "gen"
    gen.mkdir(parents=True, exist_ok=True)
    for p in gen.iterdir():
        p.unlink()
    if args.selftest:
        broken = fbs["SF_EmergencyStop"].replace("R_TRIGatReset.Q OR S_AutoReset", "R_TRIGatReset.Q")
        assert broken != fbs["SF_EmergencyStop"], "selftest: the peer text changed"
        fbs["SF_EmergencyStop"] = broken
    st = "\n\n".join(adapt(fbs[p.peer]) for p in pairs) + program(pairs)
    (w / "peer.st").write_text(st, encoding="utf-8")
    (w / "probe.c").write_text(probe_c(pairs), encoding="utf-8")
    (w / "driver.c").write_text(driver_c(pairs, args.sequences, args.steps, args.seed), encoding="utf-8")
    build_matiec(args, w / "peer.st", gen, [w / "probe.c"], w / "driver.c", w / "peer_diff", opt="-O2")
    r = run([str(w / "peer_diff")])
    records, reached, transitions, compared = [], {}, {}, 0
    for line in r.stdout.splitlines():
        if line.startswith("DIFF "):
            records.append(parse_record(line))
        elif line.startswith("REACHED "):
            parts = line.split()
            reached[parts[1]] = {int(c, 16) for c in parts[2:]}
        elif line.startswith("TRANSITIONS "):
            transitions[line.split()[1]] = int(line.split()[2])
        elif line.startswith("COMPARED "):
            compared = int(line.split()[1])
    print(f"peer: {PEER_REPO} {PEER_PATH} @ {PEER_COMMIT[:12]} (sha256 ok), adapted for matiec; "
          f"{len(pairs)} blocks: {', '.join(f'{p.b.struct.name} ~ {p.peer}' for p in pairs)}")
    print(f"{args.sequences} sequences x {args.steps} calls per block, seed {args.seed:#x}: "
          f"{compared} calls compared (DiagCode v1.0, Ready, Error, {', '.join(sorted({o for p in pairs for o in p.output}))})")
    by_class = defaultdict(list)
    for rec in records:
        by_class[classify(rec)].append(rec)
    per_block = Counter((rec["block"], classify(rec)) for rec in records)
    failed = 0
    print("\n| class | block | disagreements | reading |")
    print("|---|---|---|---|")
    texts = {c[0]: c[3] for c in CLASSES}
    for (blk, cid), n in sorted(per_block.items(), key=lambda x: (str(x[0][1]), x[0][0])):
        print(f"| {cid or 'UNCLASSIFIED'} | {blk} | {n} | {texts.get(cid, 'no reading yet: FAIL')} |")
    for cid, recs in sorted(by_class.items(), key=lambda x: str(x[0])):
        print(f"\nexamples of {cid or 'UNCLASSIFIED'}:")
        for rec in recs[: args.show]:
            print("  ", {k: (f"{v:04X}" if k in ("prev", "peer", "ours") else v) for k, v in rec.items()})
        if cid is None:
            failed += len(recs)
    print()
    for p in pairs:
        got = reached.get(p.b.name, set())
        # The peer's states: its CASE labels (v1.0 numbering, like our profile 1).
        want = {int(c, 16) for c in re.findall(r"(?m)^\s*16#([0-9A-Fa-f]{4})\s*[,:]", fbs[p.peer])}
        missing = want - got
        print(f"{p.b.struct.name}: {transitions.get(p.b.name, 0)} distinct transitions (staying included) on which both "
              f"agreed; our v1.0 DiagCodes reached: {' '.join(f'{c:04X}' for c in sorted(got))}"
              + (f"; the peer's states never reached by ours: {' '.join(f'{c:04X}' for c in sorted(missing))} FAIL"
                 if missing else "; every state of the peer reached"))
        failed += len(missing)
    if args.selftest:
        caught = per_block.get(("SF_EmergencyStop", None), 0)
        print(f"selftest: the broken peer SF_EmergencyStop gave {caught} unclassified disagreements "
              f"({'caught' if caught else 'NOT caught'})")
        failed = 0 if caught else 1
    print(f"{1 if failed == 0 else 0} passed, {1 if failed else 0} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
