#!/usr/bin/env python3
"""Genericity test input for tools/plcgen.py (used by tools/plc_check.sh, step 8).

Writes into --out:
  safelogic.h  a copy of the real header with one extra, synthetic block FB_SYNTH in the
               cbindgen style of the real ones (doc comments, "Offset N (output base + k)",
               reserved fields, a nested private struct, and field shapes the real blocks do
               not have yet: an array input, a signed input, a time output, an array output;
               the prototype of sl_synth_cycle wrapped over two lines), with its layout asserts;
  synth_stub.c a C implementation of sl_synth_init/sl_synth_cycle to link the generated
               CODESYS adapter test against;
  fields.json  the registry's field table (--fields, printed by examples/field_table.rs)
               with FB_SYNTH's entry added, as the registry would give it.
The check then generates the bindings from that header and runs the layout, strict-parse,
adapter check and the matiec compile on them: a new block in the same header style needs no change to
the generator. Stdlib only.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

BLOCK = """
/*
 Type tag of FB_SYNTH (no library type has it: sl_reason_text gives "").
 */
#define SL_TYPE_SYNTH 65535

/*
 FB SYNTH instance (synthetic block of tools/plc_synthetic.py: tests that tools/plcgen.py is
 generic). Inputs at offsets 8.., outputs at output base 40 + offsets.
 */
typedef struct FB_SYNTH {
  /*
   Offset 0. Restart.
   */
  SL_BOOL bRestart;
  /*
   Offset 1. Reserved, keep 0.
   */
  uint8_t aReserved0[7];
  /*
   Offset 8. Input 1.
   */
  SL_BOOL bSynIn1;
  /*
   Offset 9. Input 2.
   */
  SL_BOOL bSynIn2;
  /*
   Offset 10. FbRun of the owning group.
   */
  SL_BOOL bRun;
  /*
   Offset 11. ErrAck of the owning group.
   */
  SL_BOOL bErrAck;
  /*
   Offset 12. A time parameter in ms.
   */
  uint32_t tDelay;
  /*
   Offset 16. Two limits.
   */
  uint16_t awLimit[2];
  /*
   Offset 20. A signed value.
   */
  int16_t nBias;
  /*
   Offset 22. Active inputs.
   */
  uint16_t wInputActive;
  /*
   Offset 24. Options.
   */
  uint32_t dwOptions;
  /*
   Offset 28. Reserved.
   */
  uint8_t aReserved1[12];
  /*
   Offset 40 (output base + 0). TRUE in ERROR.
   */
  SL_BOOL bError;
  /*
   Offset 41 (output base + 1). Output.
   */
  SL_BOOL bSynOut;
  /*
   Offset 42. Status value.
   */
  uint8_t nState;
  /*
   Offset 43. Reserved.
   */
  uint8_t aReserved2[1];
  /*
   Offset 44. Diagnostic bits.
   */
  uint16_t nDiag;
  /*
   Offset 46. Two counters.
   */
  uint16_t awCount[2];
  /*
   Offset 50. Reserved.
   */
  uint8_t aReserved3[2];
  /*
   Offset 52. Elapsed time in ms.
   */
  uint32_t tElapsed;
  /*
   Offset 56. Private state: never write it.
   */
  struct SL_PRIVATE_HEADER stPrivate;
  /*
   Offset 84. Reserved.
   */
  uint8_t aReserved4[4];
} FB_SYNTH;
"""

PROTOS = """int32_t sl_synth_init(struct FB_SYNTH *fb);

int32_t sl_synth_cycle(struct FB_SYNTH *fb,
                       uint32_t tNow);

"""

OFFSETS = [("bRestart", 0), ("aReserved0", 1), ("bSynIn1", 8), ("bSynIn2", 9), ("bRun", 10),
           ("bErrAck", 11), ("tDelay", 12), ("awLimit", 16), ("nBias", 20), ("wInputActive", 22),
           ("dwOptions", 24), ("aReserved1", 28), ("bError", 40), ("bSynOut", 41), ("nState", 42),
           ("aReserved2", 43), ("nDiag", 44), ("awCount", 46), ("aReserved3", 50), ("tElapsed", 52),
           ("stPrivate", 56), ("aReserved4", 84)]

STUB = """/* synthetic block for the genericity test (tools/plc_synthetic.py) */
#include "safelogic.h"

int32_t sl_synth_init(struct FB_SYNTH *fb)
{
    if (fb == 0) {
        return SL_E_NULL;
    }
    fb->nState = SL_STATE_STOP;
    fb->stPrivate.wMagic = 0x5359u;
    return SL_OK;
}

int32_t sl_synth_cycle(struct FB_SYNTH *fb, uint32_t tNow)
{
    if (fb == 0) {
        return SL_E_NULL;
    }
    if (fb->stPrivate.wMagic == 0u) {
        (void)sl_synth_init(fb);
        fb->stPrivate.tPhase = tNow;
    }
    fb->bSynOut = (uint8_t)(fb->bRun && fb->bSynIn1 && !fb->bSynIn2);
    fb->bError = (uint8_t)(fb->bSynIn1 && fb->bSynIn2);
    fb->nState = fb->bError ? SL_STATE_ERROR : (fb->bSynOut ? SL_STATE_RUN : SL_STATE_SAFE);
    fb->nDiag = (uint16_t)(fb->awLimit[0] ^ fb->awLimit[1] ^ (uint16_t)fb->nBias);
    fb->awCount[0]++;
    fb->awCount[1] = (uint16_t)(fb->awCount[1] + fb->bSynIn1);
    fb->tElapsed = tNow - fb->stPrivate.tPhase + fb->tDelay;
    return fb->wInputActive == 0u ? SL_E_CONFIG : SL_OK;
}
"""


# FB_SYNTH's field table, as a registry entry would declare it: (name, offset, C type, direction).
SYNTH_FIELDS = [
    ("bRestart", 0, "SL_BOOL", "input"), ("bSynIn1", 8, "SL_BOOL", "input"),
    ("bSynIn2", 9, "SL_BOOL", "input"), ("bRun", 10, "SL_BOOL", "control"),
    ("bErrAck", 11, "SL_BOOL", "control"), ("tDelay", 12, "uint32_t", "param"),
    ("awLimit", 16, "uint16_t", "param"), ("nBias", 20, "int16_t", "param"),
    ("wInputActive", 22, "uint16_t", "param"), ("dwOptions", 24, "uint32_t", "param"),
    ("bError", 40, "SL_BOOL", "output"), ("bSynOut", 41, "SL_BOOL", "output"),
    ("nState", 42, "uint8_t", "info"), ("nDiag", 44, "uint16_t", "info"),
    ("awCount", 46, "uint16_t", "output"), ("tElapsed", 52, "uint32_t", "output"),
]


def main() -> int:
    ap = argparse.ArgumentParser()
    ap.add_argument("--header", type=Path, required=True)
    ap.add_argument("--out", type=Path, required=True)
    ap.add_argument("--fields", type=Path, required=True, help="the real field table (JSON)")
    args = ap.parse_args()
    text = args.header.read_text(encoding="utf-8")
    anchor = '#ifdef __cplusplus\nextern "C" {'
    if anchor not in text or "const char *sl_status_str" not in text or "#endif  /* SAFELOGIC_H */" not in text:
        raise SystemExit("plc_synthetic: the header no longer has the expected cbindgen shape")
    text = text.replace(anchor, BLOCK.lstrip("\n") + "\n" + anchor, 1)
    text = text.replace("const char *sl_status_str", PROTOS + "const char *sl_status_str", 1)
    asserts = "".join(f'SL_STATIC_ASSERT(offsetof(FB_SYNTH, {f}) == {o}, "offset of FB_SYNTH.{f}");\n'
                      for f, o in OFFSETS)
    asserts += 'SL_STATIC_ASSERT(sizeof(FB_SYNTH) == 88, "size of FB_SYNTH");\n'
    text = text.replace("#endif  /* SAFELOGIC_H */", asserts + "\n#endif  /* SAFELOGIC_H */", 1)
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / "safelogic.h").write_text(text, encoding="utf-8")
    (args.out / "synth_stub.c").write_text(STUB, encoding="utf-8")
    table = json.loads(args.fields.read_text(encoding="utf-8"))
    table["blocks"].append({"name": "SYNTH", "struct": "FB_SYNTH", "tag": 0xFFFF, "size": 88, "fields": [
        {"name": n, "offset": o, "ctype": c, "dir": d} for n, o, c, d in SYNTH_FIELDS]})
    (args.out / "fields.json").write_text(json.dumps(table), encoding="utf-8")
    print(f"plc_synthetic: wrote {args.out}/safelogic.h (with FB_SYNTH) and synth_stub.c")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
