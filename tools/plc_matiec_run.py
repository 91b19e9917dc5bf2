#!/usr/bin/env python3
"""Runs the IEC 61131-3 bindings under the real matiec compiler (iec2c) and checks them cycle by
cycle against direct C calls.

    python3 tools/plc_matiec_run.py --iec2c DIR/iec2c --matiec-lib DIR/lib --workdir build/plc-check/matiec

1. Writes a test project: plc_bindings/iec/safelogic_iec.st, unchanged, followed by a PROGRAM
   that drives every block through its ST function block FB_<NAME> with a script (CASE on the
   cycle number): configure, run (restart pulse where the block has one), change a parameter
   while running (every block: SL_E_PARAM_CHANGED, ERROR), restore it, ErrAck rising and
   falling edge (RESET, then out of it), run again. It also runs FB_SL_SELFTEST and calls
   SL_TIME_NOW_MS.
2. iec2c -f -l -p -r -R -a (OpenPLC's options) compiles it to C; gcc compiles that C (as C,
   with matiec's lib/C headers) and links it with target/release/libsafelogic.a and a driver.
3. The driver runs the PLC cycles. After every cycle it reads, for every block, the VAR_INPUTs
   the ST program passed to FB_<NAME>, applies them to its own struct FB_<NAME> (the C header's),
   calls sl_<name>_cycle directly with the same tNow, and compares the ST FB's status, every
   VAR_OUTPUT (outputs, nState, nDiag) and every byte of the ST FB's C instance (stData) with
   the direct call. It asserts that every block reached its run-like state, ERROR, RESET and
   the run-like state again after the ErrAck.
Prints "N passed, M failed". Standard library only (plus gcc).
"""
from __future__ import annotations

import argparse
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tools"))
import plcgen  # noqa: E402

CYCLE_MS = 10
# What FB_TWOHAND's sReason must say with tDiscTimePairs 3000 ms (library reason 0xE001).
REFUSED_SENTENCE = "TWOHAND: tDiscTimePairs (3000 ms) must be <= 2500 ms [reason 0xE001]"
WALK = 28  # from this cycle on, every BOOL input in turn is inverted for one cycle
N_CYCLES = WALK + 2 * 17
ERROR = 4
RESET = 5

# Per block: a valid configuration with its "go" inputs, the input pulsed to (re)start it (or
# None), the parameter changed while running, and the states that count as running.
# Everything else (script, checks) is generic.
BLOCKS = {
    "ESTOP": dict(cfg=dict(wInputActive=0x3, tDiscTime12=100, bEStopIn1=1, bEStopIn2=1),
                  pulse="bRestart", change=("tDiscTime12", 101), run={1}),
    "MON": dict(cfg=dict(wInputActive=0x3, tDiscTime12=100, bMonIn1=1, bMonIn2=1),
                pulse="bRestart", change=("tDiscTime12", 101), run={1}),
    "AND": dict(cfg=dict(wInputActive=0x3, bAndIn1=1, bAndIn2=1), pulse=None,
                change=("wInputNegated", 0x1), run={1}),
    "OR": dict(cfg=dict(wInputActive=0x3, bOrIn1=1), pulse=None,
               change=("wInputNegated", 0x2), run={1}),
    "OPMODE": dict(cfg=dict(wInputActive=0x3, tDiscTime=100, bOpIn1=1), pulse=None,
                   change=("tDiscTime", 101), run={1}),
    "TWOHAND": dict(cfg=dict(wInputActive=0xF, tDiscTime12=50, tDiscTime34=50, tDiscTimePairs=500),
                    pulse=("bTwoHand1", "bTwoHand2", "bTwoHand3", "bTwoHand4"), hold=True,
                    change=("tDiscTimePairs", 501), run={1}),
    "XOR": dict(cfg=dict(wInputActive=0x1, bXor1In1=1), pulse=None,
                change=("wInputActive", 0x3), run={1}),
    "DECOUPLE": dict(cfg=dict(wInputActive=0x1, bDecIn1=1), pulse=None,
                     change=("wInputActive", 0x3), run={1}),
    "EDM": dict(cfg=dict(wInputActive=0x3, tSwitchOnTime=100, tSwitchOffTime=100, bMon1=1, bMon2=1),
                pulse=None, change=("tSwitchOnTime", 101), run={14, 15}),
    "RS": dict(cfg=dict(wInputActive=0x3), pulse=("bSet",), change=("wInputNegated", 0x1), run={9}),
    "SR": dict(cfg=dict(wInputActive=0x3), pulse=("bSet",), change=("wInputNegated", 0x1), run={9}),
    "TON": dict(cfg=dict(wInputActive=0x1, tDelay=30, bTonIn1=1), pulse=None,
                change=("tDelay", 31), run={1}),
    "TON2": dict(cfg=dict(wInputActive=0x1, tDelay=30, bTonIn1=1, bEnable=1), pulse=None,
                 change=("tDelay", 31), run={1}),
    "TOF": dict(cfg=dict(wInputActive=0x1, tDelay=30, bTofIn1=1), pulse=None,
                change=("tDelay", 31), run={1}),
    "MUTING": dict(cfg=dict(wInputActive=0x3F, bMutingEnable=1, bEDM1=1, bEDM2=1, bOSSDIn1=1, bOSSDIn2=1),
                   pulse=None, change=("tFilterTime", 1), run={1}),
}

# The arithmetic blocks in every variant: two analog inputs, no BOOL input; a parameter
# change while running (DIV: the rounding, the others: the active mask) is the error.
for _op in ("ADD", "SUB", "MUL", "DIV"):
    for _v in ("INT", "UINT", "DINT", "UDINT"):
        BLOCKS[f"{_op}_{_v}"] = dict(
            cfg=dict(wInputActive=0x300, nAnalogIn1=7, nAnalogIn2=3), pulse=None,
            change=("nRounding", 1) if _op == "DIV" else ("wInputActive", 0x301), run={1})

# LIMIT in every variant: AnalogIn between the parameter limits (RUN); changing the maximum
# while running is the error.
for _v in ("INT", "UINT", "DINT", "UDINT"):
    BLOCKS[f"LIMIT_{_v}"] = dict(
        cfg=dict(wInputActive=0x100, nMinimumValue=1, nMaximumValue=10, nAnalogIn=5), pulse=None,
        change=("nMaximumValue", 11), run={1})

# COUNTER in every variant: counting edges from the walk; changing the limit while running
# is the error.
for _v in ("INT", "UINT", "DINT", "UDINT"):
    BLOCKS[f"COUNTER_{_v}"] = dict(
        cfg=dict(wInputActive=0x7, nPresetValue=3, nCounterLimit=5), pulse=("bCountUp",),
        change=("nCounterLimit", 6), run={1})

# VIOLATIONCOUNTER (UINT, UDINT): enabled with a good input; changing the limit while
# running is the error.
for _v in ("UINT", "UDINT"):
    BLOCKS[f"VIOLATIONCOUNTER_{_v}"] = dict(
        cfg=dict(wInputActive=0x3, nIncrementError=3, nDecrementNoError=1, nCounterLimit=10,
                 bInput=1, bEnable=1), pulse=None, change=("nCounterLimit", 11), run={1})

# COMPARE in every variant (2oo3): two agreeing inputs; changing the deviation while running
# is the error.
for _v in ("INT", "UINT", "DINT", "UDINT"):
    BLOCKS[f"COMPARE_{_v}"] = dict(
        cfg=dict(nArchitecture=3, wInputActive=0x700, nAllowedDeviation=2, tToleranceTime=30,
                 nCompIn1=10, nCompIn2=11, nCompIn3=40), pulse=None,
        change=("nAllowedDeviation", 3), run={1, 8})

# SCALE in every variant: 5 · 3 ÷ 2 + 1 (RUN); changing the offset while running is the error.
for _v in ("INT", "UINT", "DINT", "UDINT"):
    BLOCKS[f"SCALE_{_v}"] = dict(
        cfg=dict(wInputActive=0x100, nNumerator=3, nDenominator=2, nOffset=1, nAnalogIn=5),
        pulse=None, change=("nOffset", 2), run={1})

# SPEED in every variant: a standing position (RUN, Speed 0); changing the interval while
# running is the error.
for _v in ("INT", "UINT", "DINT", "UDINT"):
    BLOCKS[f"SPEED_{_v}"] = dict(
        cfg=dict(wInputActive=0x100, tTimeInterval=20, nPosition=5), pulse=None,
        change=("tTimeInterval", 21), run={1})
# SLI and SLI2 in every variant: SLI held TRUE from its rising edge (the latch) keeps RUN;
# released before the ErrAck, since RESET is only left with SLI FALSE; changing Limit pos
# while running is the error.
for _b in ("SLI", "SLI2"):
    for _v in ("INT", "UINT", "DINT", "UDINT"):
        BLOCKS[f"{_b}_{_v}"] = dict(
            cfg=dict(wInputActive=0x101, nLimitPos=10, nLimitNeg=10, nPosition=5),
            pulse=("bSLI",), hold=True, change=("nLimitPos", 11), run={1})


# ENVELOPE in every variant: SafeFunction TRUE (RUN); the walk's SafeFunction pulse is a
# monitored stop inside the target window (DELAYOUT); changing MaxTime while running is the
# error.
for _v in ("INT", "UINT", "DINT", "UDINT"):
    BLOCKS[f"ENVELOPE_{_v}"] = dict(
        cfg=dict(wInputActive=0x101, tTimeAfterInTarget=30, tMaxTime=1000, nTargetValue=10,
                 nOffset=50, nInValue=5, bSafeFunction=1), pulse=None,
        change=("tMaxTime", 1001), run={1, 8, 9})

# LOADSENSING in every variant: one table row (X 0: Y1 100 <= WY1 110 < WY2 190 <= Y2 200),
# AnalogInX 1 and AnalogInY 150 (RUN); changing the row count while running is the error. The
# row is written through the FB's aRow input (element by element).
for _v in ("INT", "UINT", "DINT", "UDINT"):
    BLOCKS[f"LOADSENSING_{_v}"] = dict(
        cfg={"wInputActive": 0x300, "nRowCount": 1, "aRow[0].nX": 0, "aRow[0].nY1": 100,
             "aRow[0].nY2": 200, "aRow[0].nWY1": 110, "aRow[0].nWY2": 190, "nAnalogInX": 1,
             "nAnalogInY": 150}, pulse=None, change=("nRowCount", 2), run={1, 17})

# SLP: multi-turn, the position between the parameter limits (RUN); changing the upper limit
# while running is the error.
BLOCKS["SLP"] = dict(
    cfg=dict(wInputActive=0x301, nSingleturnPosULFix=100, nSingleturnPos=5, bSafePosValid=1),
    pulse=None, change=("nSingleturnPosULFix", 101), run={1})

# SBT: a test started by the SBT pulse passes at once (MinDuration 0, current 0 >= 0):
# TEST-OK, then RUN; after the ErrAck the block starts afresh in SAFE; changing the deviation
# while running is the error.
BLOCKS["SBT"] = dict(
    cfg=dict(wInputActive=0x303, tBrakeTestInterval=60000, tMinDuration=0, tMaxDuration=1000,
             nMaxPositionDeviation=10), pulse=("bSBT",), change=("nMaxPositionDeviation", 11),
    run={1, 3, 16, 17})

# ADVPOSMON: enabled, referenced, coverage good (RUN, Active); changing a feedback instance
# while running is the error.
BLOCKS["ADVPOSMON"] = dict(
    cfg=dict(wInputActive=0x1, bEnable=1, bPosRefOk=1, bPosCheckOk=1), pulse=None,
    change=("nChAPrimaryFeedback", 1), run={1})

# CAMMONITOR in both variants: excentric, the manual's limits (TDC 8092..100, OverrunMax 800,
# BDC 3896..4296), the press standing at 50; the Reset pulse releases it (START, then RUN);
# after the ErrAck it waits in WAIT-FOR-RESET for the next pulse; changing OverrunMax's fixed
# value while running is the error.
for _v in ("UINT", "UDINT"):
    BLOCKS[f"CAMMONITOR_{_v}"] = dict(
        cfg=dict(wInputActive=0x104, tStopDetectionTime=50, nAllowedPositionJitter=4,
                 nMaxPosition=8192, nTDC1LowerLimitFix=8092, nTDC1UpperLimitFix=100,
                 nBDCLowerLimitFix=3896, nBDCUpperLimitFix=4296, nOverrunMaxFix=800,
                 nPosition=50), pulse="bReset", change=("nOverrunMaxFix", 801), run={1})

# CONNECTION_SHUTDOWN: Deactivate1 requests, the connection reports its shutdown (the input a
# group writes, set by the program here): RUN; changing the Connection ID while running is
# the error.
BLOCKS["CONNECTION_SHUTDOWN"] = dict(
    cfg=dict(wInputActive=0x1, nConnectionId=7, bDeactivate1=1, bConnShutdown=1), pulse=None,
    change=("nConnectionId", 8), run={1, 3})

BLOCK_INPUTS = {}  # block -> its BOOL inputs (filled from the header in main)
PAUSES = {}  # cycle -> ms the driver waits after it (real time, for FBs reading SL_TIME_NOW_MS)


# PLCopen blocks with a script of their own (cycle -> inputs), PLCopen names only.
SF_STEPS = {
    # SF_Guard, DiscrepancyTime left at its default T#0: closed at activation with
    # S_StartReset (8000), opened completely (8802, 8804), switch 1 closing alone (8806, then
    # the discrepancy error C010 at once), both open (8804), Activate FALSE (0000), again
    # with S_StartReset (8000), then without: a Reset edge (8402, 8000).
    "SF_Guard": {0: {"Activate": 0, "S_GuardSwitch1": 0, "S_GuardSwitch2": 0},
                 2: {"Activate": 1, "S_GuardSwitch1": 1, "S_GuardSwitch2": 1, "S_StartReset": 1},
                 4: {"S_GuardSwitch1": 0}, 6: {"S_GuardSwitch2": 0}, 8: {"S_GuardSwitch1": 1},
                 10: {"S_GuardSwitch1": 0}, 12: {"Activate": 0},
                 14: {"Activate": 1, "S_GuardSwitch1": 1, "S_GuardSwitch2": 1}, 16: {"Activate": 0},
                 18: {"Activate": 1, "S_StartReset": 0}, 20: {"Reset": 1}, 22: {"Reset": 0}},
    # SF_SafetyRequest, MonitoringTime 10 s (never elapses in this run): a Reset edge with the
    # operation mode (8802), the safe mode requested (8002) and acknowledged (8000), the
    # acknowledgement lost (C010), Activate FALSE (0000), again with S_StartReset and the
    # actuator acknowledging (8804, 8002, 8000), then operation and safe mode once more.
    "SF_SafetyRequest": {0: {"Activate": 0, "S_OpMode": 0, "S_Acknowledge": 0, "MonitoringTime": 10000},
                         2: {"Activate": 1}, 4: {"Reset": 1, "S_OpMode": 1},
                         6: {"Reset": 0, "S_OpMode": 0}, 8: {"S_Acknowledge": 1},
                         10: {"S_Acknowledge": 0}, 12: {"Activate": 0},
                         14: {"Activate": 1, "S_StartReset": 1, "S_Acknowledge": 1},
                         18: {"S_OpMode": 1}, 20: {"S_Acknowledge": 0}, 22: {"S_OpMode": 0},
                         24: {"S_Acknowledge": 1}},
    # SF_OutControl, StaticControl FALSE: a Reset edge (8006), a ProcessControl edge (8000),
    # the safety function (8802) and its end (8404), a Reset edge with ProcessControl still
    # TRUE (8006, then the static-control error C010), Activate FALSE (0000), again with
    # S_StartReset (8006) and a ProcessControl edge (8000).
    "SF_OutControl": {0: {"Activate": 0, "S_SafeControl": 0, "ProcessControl": 0},
                      2: {"Activate": 1, "S_SafeControl": 1}, 4: {"Reset": 1},
                      6: {"Reset": 0, "ProcessControl": 1}, 8: {"S_SafeControl": 0},
                      10: {"S_SafeControl": 1}, 12: {"Reset": 1}, 14: {"Activate": 0, "Reset": 0},
                      16: {"Activate": 1, "S_StartReset": 1, "ProcessControl": 0},
                      18: {"ProcessControl": 1}, 20: {"ProcessControl": 0}},
}
# Enable switch: position 1 → 2 (8000), panic position 3 then 3 → 2 (C030), back to 1
# (C040), idle, again 1 → 2, a Reset edge while released.
SF_STEPS["SF_EnableSwitch"] = {
        0: {"Activate": 0, "S_SafetyActive": 1, "S_EnableSwitchCh1": 0, "S_EnableSwitchCh2": 1},
        2: {"Activate": 1}, 6: {"S_EnableSwitchCh1": 1},
        8: {"S_EnableSwitchCh1": 0, "S_EnableSwitchCh2": 0},
        10: {"S_EnableSwitchCh1": 1, "S_EnableSwitchCh2": 1},
        12: {"S_EnableSwitchCh1": 0}, 14: {"Activate": 0}, 16: {"Activate": 1},
        20: {"S_EnableSwitchCh1": 1}, 22: {"S_EnableSwitchCh1": 0, "Reset": 1}, 24: {"Reset": 0}}
# Two-hand control: button 1 then 2 (8000), idle with both held, activation with both held
# (C030), both released, idle, again 1 then 2, released one by one.
SF_STEPS["SF_TwoHandControlTypeII"] = SF_STEPS["SF_TwoHandControlTypeIII"] = {
    0: {"Activate": 0, "S_Button1": 0, "S_Button2": 0}, 2: {"Activate": 1}, 4: {"S_Button1": 1},
    6: {"S_Button2": 1}, 8: {"Activate": 0}, 10: {"Activate": 1},
    12: {"S_Button1": 0, "S_Button2": 0}, 14: {"Activate": 0}, 16: {"Activate": 1},
    18: {"S_Button1": 1}, 20: {"S_Button2": 1}, 22: {"S_Button1": 0}, 24: {"S_Button2": 0}}
# Mode selector: mode 1 confirmed by S_SetMode (8000), a second mode (C010), back to one
# (C410), idle, again (8000), locked (8010) and unlocked, a Reset edge.
SF_STEPS["SF_ModeSelector"] = {
    0: {"Activate": 0, "S_Unlock": 1, "S_Mode1": 1}, 2: {"Activate": 1}, 4: {"S_SetMode": 1},
    6: {"S_SetMode": 0}, 8: {"S_Mode2": 1}, 10: {"S_Mode2": 0}, 12: {"Activate": 0},
    14: {"Activate": 1}, 16: {"S_SetMode": 1}, 18: {"S_SetMode": 0, "S_Unlock": 0},
    20: {"S_Unlock": 1}, 22: {"Reset": 1}, 24: {"Reset": 0}}


def sf_script(name: str) -> dict:
    """A PLCopen block with one safety input (SF_EmergencyStop, SF_ESPE, SF_PSE) driven as a
    user's program would, with the PLCopen names only: activation without S_StartReset, the
    safety input, a Reset edge (8000), a safety demand and its end with Reset held (the
    static-reset error C011), Reset released, Activate FALSE (0000), then S_StartReset and
    S_AutoReset (8000 again), then the walk over every BOOL input."""
    ins = BLOCK_INPUTS[name]
    safety = ins[1]
    if name in SF_STEPS:
        steps = {c: dict(v) for c, v in SF_STEPS[name].items()}
    elif name == "SF_ResetButton":
        # The press timed by the FB's own clock (SL_TIME_NOW_MS): the driver pauses 150 ms
        # after cycles 34 and 44 (PAUSES), so those presses are valid (8000); a one-cycle
        # press is too short (C3F0); ResetRequested FALSE is idle (0000). The run-like
        # part lies after the walk of the FB's two BOOL inputs (cycles 28-31).
        steps = {0: {"ResetRequested": 0, "ResetIn": 0, "TrailingMinimum": 100, "TrailingMaximum": 2000},
                 2: {"ResetRequested": 1, "ResetIn": 1}, 6: {"ResetIn": 0},
                 34: {"ResetIn": 1}, 35: {"ResetIn": 0}, 38: {"ResetIn": 1}, 39: {"ResetIn": 0},
                 40: {"ResetRequested": 0}, 42: {"ResetRequested": 1}, 44: {"ResetIn": 1}, 45: {"ResetIn": 0}}
        PAUSES.update({34: 150, 44: 150})
    elif name == "SF_EDM":
        # MonitoringTime 1 s (the FB's clock is real time; the cycles run back to back):
        # Reset (8810), S_OutControl (8000), the contactors pick up; switched off and on
        # again before they released (C030); Activate FALSE (0000); S_StartReset and
        # S_OutControl with released contactors (8000 again).
        steps = {0: {"Activate": 0, "S_OutControl": 0, "EDM1": 1, "EDM2": 1, "MonitoringTime": 1000},
                 2: {"Activate": 1}, 4: {"Reset": 1}, 5: {"Reset": 0}, 6: {"S_OutControl": 1},
                 7: {"EDM1": 0, "EDM2": 0}, 10: {"S_OutControl": 0}, 11: {"S_OutControl": 1},
                 12: {"S_OutControl": 0, "EDM1": 1, "EDM2": 1}, 14: {"Activate": 0},
                 16: {"Activate": 1, "S_StartReset": 1}, 18: {"S_OutControl": 1}, 19: {"EDM1": 0, "EDM2": 0}}
    elif name == "SF_TestableSafetySensor":
        # TestTime 150 ms (real time; the cycles run back to back): Reset (8010), a test the
        # sensor answers (8020, 8030, 8000), a safety demand whose end meets a held Reset
        # (8806, 8406, the static-reset error C021), Activate FALSE (0000), S_StartReset and
        # a second test (8000 again).
        steps = {0: {"Activate": 0, "S_OSSD_In": 1, "TestTime": 150, "NoExternalTest": 1},
                 2: {"Activate": 1}, 4: {"Reset": 1}, 5: {"Reset": 0}, 6: {"StartTest": 1},
                 7: {"S_OSSD_In": 0}, 8: {"S_OSSD_In": 1, "StartTest": 0}, 10: {"S_OSSD_In": 0},
                 11: {"Reset": 1}, 12: {"S_OSSD_In": 1}, 14: {"Activate": 0}, 15: {"Reset": 0},
                 16: {"Activate": 1, "S_StartReset": 1}, 19: {"StartTest": 1}, 20: {"S_OSSD_In": 0},
                 21: {"S_OSSD_In": 1}}
    elif "Reset" in ins:
        steps = {0: {"Activate": 0, safety: 0}, 2: {"Activate": 1}, 4: {safety: 1}, 6: {"Reset": 1},
                 8: {"Reset": 0}, 10: {safety: 0, "Reset": 1}, 12: {safety: 1}, 14: {"Reset": 0},
                 16: {"Activate": 0}, 18: {"Activate": 1, "S_StartReset": 1, "S_AutoReset": 1},
                 20: {safety: 0}, 22: {safety: 1}}
    else:
        # Two channels (SF_Equivalent, SF_Antivalent: a NO channel is active FALSE), the
        # DiscrepancyTime (TIME) left at its default T#0ms: both active (8000), one inactive
        # (8806, then the discrepancy error C030), both inactive (8801), Activate FALSE; then
        # DiscrepancyTime := T#93784005ms (1d2h3m4s5ms: the instance must latch 93,784,005,
        # the probe converting matiec's TIME independently) and again.
        a, b = ins[1], ins[2]
        on_b = 0 if b.endswith("NO") else 1
        steps = {0: {"Activate": 0, a: 0, b: 1 - on_b}, 2: {"Activate": 1}, 4: {a: 1, b: on_b},
                 8: {a: 0}, 12: {b: 1 - on_b}, 14: {a: 1, b: on_b},
                 16: {"Activate": 0, "DiscrepancyTime": 93784005},
                 18: {"Activate": 1}, 22: {a: 0, b: 1 - on_b}}
    cur = {f: 0 for f in ins}
    for c in sorted(steps):
        cur.update(steps[c])
    for i, f in enumerate(ins):
        v = cur.get(f, 0)
        steps.setdefault(WALK + 2 * i, {}).update({f: 1 - v})
        steps.setdefault(WALK + 2 * i + 1, {}).update({f: v})
    return steps


def is_sf(name: str) -> bool:
    return name.startswith("SF_")


def script(name: str) -> dict:
    """cycle -> {input: value}: the ST program's inputs for that cycle (unchanged otherwise)."""
    if is_sf(name):
        return sf_script(name)
    b = BLOCKS[name]
    steps = {0: dict(b["cfg"], bRun=0, bErrAck=0), 2: {"bRun": 1}}
    pulse = b["pulse"]
    if isinstance(pulse, str):
        pulse = (pulse,)
    change, value = b["change"]
    old = b["cfg"].get(change, 0)

    def press(c0: int) -> None:
        if pulse:
            steps.setdefault(c0, {}).update({p: 1 for p in pulse})
            if not b.get("hold"):
                steps.setdefault(c0 + 2, {}).update({p: 0 for p in pulse})

    press(4)
    steps.setdefault(12, {}).update({change: value})            # parameter changed while running
    if b.get("hold"):
        steps[14] = {p: 0 for p in pulse}                       # release (a two-hand restart needs it)
    steps.setdefault(14, {}).update({change: old})              # restored
    steps[16] = {"bErrAck": 1}
    steps[18] = {"bErrAck": 0}
    press(22)
    # the walk: every input byte must reach the C instance through the ST FB (stData compared)
    cur = dict(b["cfg"], bRun=1, bErrAck=0)
    bools = [f for f in BLOCK_INPUTS[name] if f not in ("bRun", "bErrAck")]
    for i, f in enumerate(bools):
        v = cur.get(f, 0)
        steps.setdefault(WALK + 2 * i, {}).update({f: 1 - v})
        steps.setdefault(WALK + 2 * i + 1, {}).update({f: v})
    return steps


def st_literal(hdr, fl, blk, field: str, value: int) -> str:
    if "[" in field:
        # A member of a table element, "aRow[0].nX": the member's type.
        table, member = field.split("[")[0], field.split(".")[-1]
        f = [x for x in blk.inputs if x.name == table]
        if not f:
            raise SystemExit(f"{blk.name}: no input {table}")
        f = [m for m in hdr.structs[f[0].ctype].fields if m.name == member]
        if not f:
            raise SystemExit(f"{blk.name}: no member {field}")
        return f"{plcgen.dut_type(hdr, f[0])}#{value}"
    f = [x for x in blk.inputs if x.name == field]
    if not f:
        raise SystemExit(f"{blk.name}: no input {field}")
    t, _, _ = fl.fb_type(hdr, f[0], blk.is_sf)
    if t == "BOOL":
        return "TRUE" if value else "FALSE"
    if t == "TIME":
        return f"T#{value}ms"
    return f"{t}#{value}"


def st_program(hdr) -> str:
    fl = plcgen.Flavour("iec")
    out = ["", "(* ==== test program (tools/plc_matiec_run.py) ==== *)", "PROGRAM prog0", "VAR",
           "    nCycle : UDINT := UDINT#0;", "    nNow : UDINT := UDINT#1000;", "    nClock : UDINT := UDINT#0;",
           "    fbSelfTest : FB_SL_SELFTEST;"]
    for b in hdr.blocks:
        out.append(f"    fb{b.name} : {b.fb_name};")
    out.append("    fbRefused : FB_TWOHAND; (* refused: tDiscTimePairs above 500 ms *)")
    out += GROUP_VARS
    out += ["END_VAR", "nNow := nNow + UDINT#%d;" % CYCLE_MS, "nClock := SL_TIME_NOW_MS(EN := TRUE);",
            "IF nCycle = UDINT#0 THEN", "    fbSelfTest();", "END_IF;"]
    out += group_body(hdr)
    two = [b for b in hdr.blocks if b.name == "TWOHAND"][0]
    refused = dict(BLOCKS["TWOHAND"]["cfg"], tDiscTimePairs=3000, bRun=1)
    out.append("fbRefused(" + ", ".join(f"{k} := {st_literal(hdr, fl, two, k, v)}" for k, v in refused.items())
               + ", tNow := nNow);")
    for b in hdr.blocks:
        steps = script(b.name)
        out.append(f"CASE nCycle OF")
        for c in sorted(steps):
            # Table members are written into the instance's input before the call.
            sets = "".join(f"fb{b.name}.{k} := {st_literal(hdr, fl, b, k, v)}; "
                           for k, v in steps[c].items() if "[" in k)
            args = ", ".join(f"{k} := {st_literal(hdr, fl, b, k, v)}" for k, v in steps[c].items() if "[" not in k)
            # A PLCopen FB reads its time itself: the call has the PLCopen names only.
            now = "" if b.is_sf else ", tNow := nNow"
            out.append(f"    {c}: {sets}fb{b.name}({args}{now});")
        out.append("ELSE")
        out.append(f"    fb{b.name}({'' if b.is_sf else 'tNow := nNow'});")
        out.append("END_CASE;")
    out += ["nCycle := nCycle + UDINT#1;", "END_PROGRAM", "",
            "CONFIGURATION Config0", "  RESOURCE Res0 ON PLC",
            "    TASK task0(INTERVAL := T#10ms, PRIORITY := 0);",
            "    PROGRAM instance0 WITH task0 : prog0;", "  END_RESOURCE", "END_CONFIGURATION", ""]
    return "\n".join(out)


# ---- the group (ESTOP and MON feeding an AND through links), TON2 elapsed time, texts ----------
GROUP_VARS = [
    "    stGroup : SL_GROUP;", "    stMembers : SL_MEMBER_STORAGE;", "    stLinks : SL_LINK_STORAGE;",
    "    stGEStop : ST_FB_ESTOP;", "    stGMon : ST_FB_MON;", "    stGAnd : ST_FB_AND;", "    fbGroup : FB_SL_GROUP;",
    "    nGroupSetup : DINT := DINT#0;", "    sState : STRING;", "    sDiag : STRING;",
    "    stTon2 : ST_FB_TON2;", "    nTon2Rc : DINT := DINT#0;", "    nTon2Get : DINT := DINT#0;",
    "    nTon2Elapsed : UDINT := UDINT#0;", "    nTon2Restore : DINT := DINT#0;",
]
GROUP_MEMBERS = [("ESTOP", "stGEStop"), ("MON", "stGMon"), ("AND", "stGAnd")]
TON2_RESTORED = 40


def off(hdr, struct: str, field: str) -> int:
    return [f for f in hdr.structs[struct].fields if f.name == field][0].offset


def group_links(hdr):
    return [(0, off(hdr, "FB_ESTOP", "bEStopOut"), 2, off(hdr, "FB_AND", "bAndIn1")),
            (1, off(hdr, "FB_MON", "bMonOut"), 2, off(hdr, "FB_AND", "bAndIn2"))]


def group_body(hdr):
    g = "pGroup := REF(stGroup), pMembers := REF(stMembers)"
    out = ["(* the group: set up once, then one FB_SL_GROUP call per cycle *)",
           "IF nCycle = UDINT#0 THEN",
           "    stGEStop.wInputActive := WORD#16#3; stGEStop.tDiscTime12 := UDINT#100;",
           "    stGEStop.bEStopIn1 := TRUE; stGEStop.bEStopIn2 := TRUE;",
           "    stGMon.wInputActive := WORD#16#3; stGMon.tDiscTime12 := UDINT#100;",
           "    stGMon.bMonIn1 := TRUE; stGMon.bMonIn2 := TRUE;",
           "    stGAnd.wInputActive := WORD#16#3;",
           f"    nGroupSetup := SL_GROUP_INIT({g}, pLinks := REF(stLinks));"]
    for name, var in GROUP_MEMBERS:
        out.append(f"    nGroupSetup := nGroupSetup + SL_GROUP_ADD_{name}({g}, pBlock := REF({var}));")
    for sm, so, dm, do in group_links(hdr):
        out.append(f"    nGroupSetup := nGroupSetup + SL_GROUP_ADD_LINK({g}, pLinks := REF(stLinks), nSrcMember := UINT#{sm}, "
                   f"nSrcOffset := UINT#{so}, nDstMember := UINT#{dm}, nDstOffset := UINT#{do});")
    out += ["    (* TON2 through the function API: restore a persisted elapsed time before the start *)",
            "    stTon2.wInputActive := WORD#16#1; stTon2.tDelay := UDINT#100; stTon2.dwOptions := DWORD#16#100;",
            "    nTon2Rc := SL_TON2_INIT(pFb := REF(stTon2));",
            f"    nTon2Restore := SL_TON2_RESTORE_ELAPSED(pFb := REF(stTon2), nElapsedMs := UDINT#{TON2_RESTORED});",
            "END_IF;",
            "CASE nCycle OF",
            "    4, 22: stGEStop.bRestart := TRUE; stGMon.bRestart := TRUE;",
            "    6, 24: stGEStop.bRestart := FALSE; stGMon.bRestart := FALSE;",
            "    12: stGEStop.tDiscTime12 := UDINT#101;   (* parameter change: ESTOP ERROR, the group ERROR *)",
            "    14: stGEStop.tDiscTime12 := UDINT#100;",
            "    2: stTon2.bRun := TRUE; stTon2.bEnable := TRUE; stTon2.bTonIn1 := TRUE;",
            "    9: stTon2.bTonIn1 := FALSE;",
            "    30: stTon2.bTonIn1 := TRUE;",
            "END_CASE;",
            "fbGroup(pGroup := REF(stGroup), pMembers := REF(stMembers), pLinks := REF(stLinks),",
            "        bRun := nCycle >= UDINT#2, bErrAck := nCycle >= UDINT#16 AND nCycle < UDINT#18, tNow := nNow);",
            "sState := SL_STATE_STR(nType := UINT#1, nState := stGEStop.nState);",
            "sDiag := SL_DIAG_TEXT(nType := UINT#1, nDiag := stGEStop.nDiag);",
            "nTon2Rc := SL_TON2_CYCLE(pFb := REF(stTon2), tNow := nNow);",
            "nTon2Get := SL_TON2_GET_ELAPSED(pFb := REF(stTon2), nElapsedMs => nTon2Elapsed);"]
    return out


def group_probe_c(hdr) -> str:
    gs = hdr.structs["SL_GROUP"]
    ins = [f.name for f in gs.fields if f.offset < 8 and not plcgen.is_reserved(f)]
    outs = [f.name for f in gs.fields if f.offset >= 8 and not plcgen.is_reserved(f) and not f.is_struct]
    P = "RES0__INSTANCE0"
    out = ["void probe_group(MIR_GROUP *m)", "{"]
    for n, v in GROUP_MEMBERS:
        out.append(f"    memcpy(m->{v}, &{P}.{v.upper()}.value, sizeof m->{v});")
    out.append(f"    memcpy(m->stGroup, &{P}.STGROUP.value, sizeof m->stGroup);")
    out.append(f"    memcpy(m->stLinks, &{P}.STLINKS.value, sizeof m->stLinks);")
    for n in ins:
        out.append(f"    m->in_{n} = {P}.FBGROUP.{n.upper()}.value;")
    for n in outs:
        out.append(f"    m->out_{n} = {P}.FBGROUP.{n.upper()}.value;")
    out += [f"    m->tNow = {P}.FBGROUP.TNOW.value;", f"    m->nStatus = {P}.FBGROUP.NSTATUS.value;",
            f"    m->nSetup = {P}.NGROUPSETUP.value;",
            f"    memcpy(m->sState, {P}.SSTATE.value.body, {P}.SSTATE.value.len); m->sState[{P}.SSTATE.value.len] = 0;",
            f"    memcpy(m->sDiag, {P}.SDIAG.value.body, {P}.SDIAG.value.len); m->sDiag[{P}.SDIAG.value.len] = 0;",
            f"    memcpy(m->stTon2, &{P}.STTON2.value, sizeof m->stTon2);",
            f"    m->nTon2Rc = {P}.NTON2RC.value; m->nTon2Get = {P}.NTON2GET.value;",
            f"    m->nTon2Elapsed = {P}.NTON2ELAPSED.value; m->nTon2Restore = {P}.NTON2RESTORE.value;", "}", ""]
    return "\n".join(out)


def group_mirror_h(hdr) -> str:
    gs = hdr.structs["SL_GROUP"]
    out = ["typedef struct {"]
    for n, v in GROUP_MEMBERS:
        out.append(f"    unsigned char {v}[{hdr.structs['FB_' + n].size}];")
    out.append(f"    unsigned char stGroup[{gs.size}];")
    out.append(f"    unsigned char stLinks[{hdr.structs['SL_LINK'].size} * 32];")
    for f in gs.fields:
        if plcgen.is_reserved(f) or f.is_struct:
            continue
        out.append(f"    {c_type(f)} {'in_' if f.offset < 8 else 'out_'}{f.name};")
    out += ["    uint32_t tNow;", "    int32_t nStatus, nSetup, nTon2Rc, nTon2Get, nTon2Restore;", "    uint32_t nTon2Elapsed;",
            "    char sState[130], sDiag[130];", f"    unsigned char stTon2[{hdr.structs['FB_TON2'].size}];",
            "} MIR_GROUP;", "void probe_group(MIR_GROUP *m);", ""]
    return "\n".join(out)


def group_driver_c(hdr) -> str:
    gs = hdr.structs["SL_GROUP"]
    outs = [f.name for f in gs.fields if f.offset >= 8 and not plcgen.is_reserved(f) and not f.is_struct]
    ins = [f.name for f in gs.fields if f.offset < 8 and not plcgen.is_reserved(f)]
    base = {n: min(f.offset for f in hdr.blocks[[b.name for b in hdr.blocks].index(n)].outputs) for n, _ in GROUP_MEMBERS}
    out = ["static SL_GROUP dg;", "static SL_MEMBER dmembers[32];", "static SL_LINK dlinks[32];"]
    for n, v in GROUP_MEMBERS:
        out.append(f"static FB_{n} d{v};")
    out += ["static FB_TON2 dton2;", "static unsigned seen_group;", "static int32_t dton2_restore;", "",
            "static void group_setup(void)", "{", "    int32_t rc;",
            "    dstGEStop.wInputActive = 3; dstGEStop.tDiscTime12 = 100; dstGEStop.bEStopIn1 = 1; dstGEStop.bEStopIn2 = 1;",
            "    dstGMon.wInputActive = 3; dstGMon.tDiscTime12 = 100; dstGMon.bMonIn1 = 1; dstGMon.bMonIn2 = 1;",
            "    dstGAnd.wInputActive = 3;",
            "    rc = sl_group_init(&dg, dmembers, 32, dlinks, 32);"]
    for n, v in GROUP_MEMBERS:
        out.append(f"    rc += sl_group_add_member(&dg, dmembers, SL_TYPE_{n}, &d{v}, NULL);")
    for sm, so, dm, do in group_links(hdr):
        out.append(f"    rc += sl_group_add_link(&dg, dmembers, dlinks, {sm}, {so}, {dm}, {do});")
    out += ['    CHECK(rc == 0, "direct group setup returned %d", (int)rc);',
            f"    dton2.wInputActive = 1; dton2.tDelay = 100; dton2.dwOptions = SL_OPT_TON2_REMAINING_TIME;",
            "    sl_ton2_init(&dton2);", f"    dton2_restore = sl_ton2_restore_elapsed(&dton2, {TON2_RESTORED});", "}", "",
            "static void step_group(int k)", "{", "    MIR_GROUP m;", "    int32_t rc;", "    uint32_t el = 0;",
            "    char diag[130];", "    probe_group(&m);", "    if (k == 0) {",
            '        CHECK(m.nSetup == 0, "ST group setup (SL_GROUP_INIT, SL_GROUP_ADD_*, SL_GROUP_ADD_LINK) returned %d", (int)m.nSetup);',
            '        CHECK(m.nTon2Restore == dton2_restore && dton2_restore == 0, "SL_TON2_RESTORE_ELAPSED %d, direct %d", (int)m.nTon2Restore, (int)dton2_restore);',
            "    }"]
    for n, v in GROUP_MEMBERS:
        out.append(f"    memcpy(&d{v}, m.{v}, {base[n]}); /* the inputs and parameters the ST program wrote */")
    for n in ins:
        out.append(f"    dg.{n} = m.in_{n};")
    out += ["    rc = sl_group_cycle(&dg, dmembers, dlinks, m.tNow);",
            '    CHECK(rc == m.nStatus, "group cycle %d: FB_SL_GROUP nStatus %d, direct %d", k, (int)m.nStatus, (int)rc);']
    for n in outs:
        out.append(f'    CHECK(m.out_{n} == dg.{n}, "group cycle %d: {n} ST %ld, direct %ld", k, (long)m.out_{n}, (long)dg.{n});')
    # Every byte but the fields the library keeps for itself outside stPrivate ("Private:",
    # SL_GROUP.awSchedule): that check binds the group's and the tables' addresses, which
    # differ between the ST program's group and this one by construction.
    private = [f.name for f in gs.fields if "Private:" in f.doc and not f.is_struct]
    out.append("    {")
    out.append("        SL_GROUP sg;")
    out.append("        memcpy(&sg, m.stGroup, sizeof sg);")
    for n in private:
        out.append(f"        memcpy(&sg.{n}, &dg.{n}, sizeof dg.{n}); /* address-bound, private */")
    out.append('        CHECK(memcmp(&sg, &dg, sizeof dg) == 0, "group cycle %d: SL_GROUP bytes differ", k);')
    out.append("    }")
    out.append('    CHECK(memcmp(m.stLinks, dlinks, sizeof dlinks) == 0, "group cycle %d: link storage differs", k);')
    for n, v in GROUP_MEMBERS:
        out.append(f'    CHECK(memcmp(m.{v}, &d{v}, sizeof d{v}) == 0, "group cycle %d: member {n} bytes differ", k);')
    out += ['    CHECK(strcmp(m.sState, sl_state_str(SL_TYPE_ESTOP, dstGEStop.nState)) == 0, "cycle %d: SL_STATE_STR \'%s\'", k, m.sState);',
            "    sl_diag_text(SL_TYPE_ESTOP, dstGEStop.nDiag, diag, 127);",
            '    CHECK(strcmp(m.sDiag, diag) == 0, "cycle %d: SL_DIAG_TEXT \'%s\', C \'%s\'", k, m.sDiag, diag);',
            "    if (k == 2) { dton2.bRun = 1; dton2.bEnable = 1; dton2.bTonIn1 = 1; }",
            "    if (k == 9) dton2.bTonIn1 = 0;", "    if (k == 30) dton2.bTonIn1 = 1;",
            "    rc = sl_ton2_cycle(&dton2, m.tNow);",
            '    CHECK(rc == m.nTon2Rc && memcmp(m.stTon2, &dton2, sizeof dton2) == 0, "cycle %d: SL_TON2_CYCLE differs", k);',
            "    rc = sl_ton2_get_elapsed(&dton2, &el);",
            '    CHECK(rc == m.nTon2Get && el == m.nTon2Elapsed, "cycle %d: SL_TON2_GET_ELAPSED %d/%u, direct %d/%u", k, (int)m.nTon2Get, (unsigned)m.nTon2Elapsed, (int)rc, (unsigned)el);',
            "    if (dg.nState == 1) seen_group |= (seen_group & 4) ? 9u : 1u;",
            "    if (dg.nState == 4 && (seen_group & 1)) seen_group |= 2u;",
            "    if (dg.nState == 5 && (seen_group & 2)) seen_group |= 4u;",
            '    if (getenv_trace()) printf("GROUP %2d rc %3d state %u diag %u failed %u; AND out %u; ESTOP %s / %s; TON2 elapsed %u\\n", k, (int)m.nStatus, (unsigned)dg.nState, (unsigned)dg.nDiag, (unsigned)dg.nFailedMember, (unsigned)dstGAnd.bAndOut, m.sState, m.sDiag, (unsigned)el);',
            "}", ""]
    return "\n".join(out)


def c_type(f) -> str:
    return plcgen.C_TYPE_FOR_PARAM(f.ctype)


def mirror_h(hdr) -> str:
    out = ["/* generated by tools/plc_matiec_run.py: neutral mirror of every ST FB's interface */",
           "#include <stdint.h>", "#include <stddef.h>",
           "/* matiec's STRING body (STR_MAX_LEN of iec_types.h; probe.c checks it) */",
           "#define REASON_BODY 126", ""]
    for b in hdr.blocks:
        out.append("typedef struct {")
        for f in b.inputs + b.outputs:
            if plcgen.is_table(f):
                out.append(f"    unsigned char {f.name}[{f.size}];")
            else:
                out.append(f"    {c_type(f)} {f.name}{'[%d]' % f.count if f.count else ''};")
        out.append("    uint32_t tNow;")
        out.append("    int32_t nStatus;")
        out.append("    char sReason[REASON_BODY + 1]; /* the FB's sReason, NUL-terminated */")
        out.append(f"    unsigned char stData[{b.struct.size}];")
        out.append(f"}} MIR_{b.name};")
        out.append(f"void probe_{b.lower}(MIR_{b.name} *m);")
    out += ["int probe_selftest(uint32_t *nChecked, uint32_t *nFailed);", "uint32_t probe_clock(void);",
            "void probe_reason_refused(char *s, size_t n);", ""]
    return "\n".join(out) + group_mirror_h(hdr)


def probe_c(hdr) -> str:
    """Reads the ST program's FB instances (matiec's C structs); compiled with POUS.h."""
    out = ["/* generated by tools/plc_matiec_run.py */", "#include <string.h>", '#include "iec_std_lib.h"',
           '#include "POUS.h"', '#include "mirror.h"', "extern PROG0 RES0__INSTANCE0;",
           "_Static_assert(STR_MAX_LEN == REASON_BODY, \"matiec's STRING body\");",
           "static void copy_string(char *d, size_t n, const IEC_STRING *s)", "{",
           "    size_t k = s->len < n - 1 ? s->len : n - 1;", "    memcpy(d, s->body, k);", "    d[k] = 0;", "}",
           "void probe_reason_refused(char *s, size_t n)",
           "{", "    copy_string(s, n, &RES0__INSTANCE0.FBREFUSED.SREASON.value);", "}", ""]
    for b in hdr.blocks:
        out.append(f"void probe_{b.lower}(MIR_{b.name} *m)")
        out.append("{")
        out.append(f"    {b.fb_name.upper()} *fb = &RES0__INSTANCE0.FB{b.name.upper()};")
        for f in b.inputs + b.outputs:
            if f.count:
                out.append(f"    memcpy(m->{f.name}, fb->{f.name.upper()}.value.table, sizeof m->{f.name});")
            elif b.is_sf and plcgen.is_time_ms(f):
                # a PLCopen TIME input: matiec's timespec in ms, converted here independently
                out.append(f"    m->{f.name} = (uint32_t)(fb->{f.name.upper()}.value.tv_sec * 1000L"
                           f" + fb->{f.name.upper()}.value.tv_nsec / 1000000L);")
            else:
                out.append(f"    m->{f.name} = fb->{f.name.upper()}.value;")
        out.append("    m->tNow = fb->TNOW.value;")
        out.append("    m->nStatus = fb->NSTATUS.value;")
        out.append("    copy_string(m->sReason, sizeof m->sReason, &fb->SREASON.value);")
        out.append("    memcpy(m->stData, &fb->STDATA.value, sizeof m->stData);")
        out.append("}")
    out += ["int probe_selftest(uint32_t *nChecked, uint32_t *nFailed)", "{",
            "    *nChecked = RES0__INSTANCE0.FBSELFTEST.NCHECKED.value;",
            "    *nFailed = RES0__INSTANCE0.FBSELFTEST.NFAILED.value;",
            "    return RES0__INSTANCE0.FBSELFTEST.BOK.value;", "}",
            "uint32_t probe_clock(void) { return RES0__INSTANCE0.NCLOCK.value; }", ""]
    return "\n".join(out) + group_probe_c(hdr)


def driver_c(hdr) -> str:
    out = ["/* generated by tools/plc_matiec_run.py: runs the matiec-compiled program and replays every",
           "   block's inputs on directly called structs */",
           "#include <stdio.h>", "#include <string.h>", '#include "safelogic.h"', '#include "mirror.h"', "",
           "void config_init__(void);", "void config_run__(unsigned long tick);",
           "/* what matiec's runtime (OpenPLC, Beremiz) defines */",
           "typedef struct { long int tv_sec; long int tv_nsec; } IEC_TIMESPEC_;",
           "IEC_TIMESPEC_ __CURRENT_TIME;", "unsigned char __DEBUG;", "",
           "static int passed, failed;",
           "#define CHECK(c, ...) do { if (c) { passed++; } else { failed++; if (failed < 40) { "
           "printf(\"FAIL: \"); printf(__VA_ARGS__); printf(\"\\n\"); } } } while (0)", ""]
    for b in hdr.blocks:
        out.append(f"static {b.struct.name} d_{b.lower};")
        out.append(f"static unsigned seen_{b.lower}; /* 1 run, 2 error after run, 4 reset, 8 run after reset */")
        out.append(f"static int ok_{b.lower};")
        out.append(f"static int reasons_{b.lower}; /* cycles whose sReason held a sentence */")
    out.append("")
    for b in hdr.blocks:
        if b.is_sf:
            # run-like: 0x8000; error: DiagCode >= C000; "reset": idle (0000) after the error
            run, err, rst = "m.DiagCode == 0x8000u", "m.DiagCode >= 0xC000u", "m.DiagCode == 0u"
        else:
            run = " || ".join(f"m.nState == {s}" for s in sorted(BLOCKS[b.name]["run"]))
            err, rst = f"m.nState == {ERROR}", f"m.nState == {RESET}"
        out.append(f"static void step_{b.lower}(int k)")
        out.append("{")
        out.append(f"    MIR_{b.name} m;")
        out.append("    int32_t rc;")
        out.append(f"    probe_{b.lower}(&m);")
        for f in b.inputs:
            if f.count:
                out.append(f"    memcpy(d_{b.lower}.{f.name}, m.{f.name}, sizeof m.{f.name});")
            else:
                out.append(f"    d_{b.lower}.{f.name} = m.{f.name};")
        out.append(f"    rc = {b.cycle.name}(&d_{b.lower}, m.tNow);")
        out.append(f'    CHECK(rc == m.nStatus, "{b.name} cycle %d: ST nStatus %d, direct %d", k, (int)m.nStatus, (int)rc);')
        for f in b.outputs:
            if f.count:
                out.append(f'    CHECK(memcmp(m.{f.name}, d_{b.lower}.{f.name}, sizeof m.{f.name}) == 0, "{b.name} cycle %d: {f.name}", k);')
            else:
                out.append(f'    CHECK(m.{f.name} == d_{b.lower}.{f.name}, "{b.name} cycle %d: {f.name} ST %ld, direct %ld", k, '
                           f'(long)m.{f.name}, (long)d_{b.lower}.{f.name});')
        out.append(f'    CHECK(memcmp(m.stData, &d_{b.lower}, sizeof m.stData) == 0, "{b.name} cycle %d: the ST instance bytes differ from the direct call", k);')
        # sReason: sl_reason_text on the same bytes after a refusal or in ERROR, '' otherwise
        cond = "rc == SL_E_CONFIG" + (f" || d_{b.lower}.Error" if b.is_sf else f" || d_{b.lower}.nState == SL_STATE_ERROR")
        out.append("    {")
        out.append("        char want[REASON_BODY + 1];")
        out.append("        want[0] = 0;")
        out.append(f"        if ({cond}) {{")
        out.append(f"            (void)sl_reason_text(SL_TYPE_{b.name.upper()}, &d_{b.lower}, want, sizeof want);")
        out.append(f"            reasons_{b.lower}++;")
        out.append("        }")
        out.append(f'        CHECK(strcmp(m.sReason, want) == 0, "{b.name} cycle %d: sReason \'%s\', sl_reason_text \'%s\'", '
                   f'k, m.sReason, want);')
        out.append("    }")
        out.append(f"    if (rc == 0) ok_{b.lower}++;")
        out.append(f"    if ({run}) seen_{b.lower} |= (seen_{b.lower} & 4) ? 9u : 1u;")
        out.append(f"    if (({err}) && (seen_{b.lower} & 1)) seen_{b.lower} |= 2u;")
        out.append(f"    if (({rst}) && (seen_{b.lower} & 2)) seen_{b.lower} |= 4u;")
        state, diag = ("m.DiagCode", "m.DiagCode") if b.is_sf else ("m.nState", "m.nDiag")
        out.append("    if (getenv_trace()) printf(\"%s %2d rc %3d state %2u diag %04x\\n\", \"" + b.name +
                   f"\", k, (int)rc, (unsigned){state}, (unsigned){diag});")
        out.append("}")
        out.append("")
    out.insert(out.index("static int passed, failed;"),
               "#include <stdlib.h>\nstatic int getenv_trace(void) { return getenv(\"SL_MATIEC_TRACE\") != NULL; }")
    out.append(group_driver_c(hdr))
    out += ["int main(void)", "{", "    int k;", "    uint32_t nChecked = 0, nFailed = 0, t0;", "    config_init__();",
            "    group_setup();",
            f"    for (k = 0; k < {N_CYCLES}; k++) {{", "        t0 = sl_time_now_ms();", "        config_run__((unsigned long)k);",
            "        step_group(k);"]
    for b in hdr.blocks:
        out.append(f"        step_{b.lower}(k);")
    for c, ms in sorted(PAUSES.items()):
        out.append(f"        if (k == {c}) {{ uint32_t tp = sl_time_now_ms(); while ((uint32_t)(sl_time_now_ms() - tp) < {ms}u) {{ }} }}")
    out += ['        CHECK((uint32_t)(probe_clock() - t0) < 1000u, "SL_TIME_NOW_MS = %u, sl_time_now_ms = %u", '
            '(unsigned)probe_clock(), (unsigned)t0);', "    }",
            '    CHECK(probe_selftest(&nChecked, &nFailed) && nFailed == 0 && nChecked > 0, '
            '"FB_SL_SELFTEST: bOk FALSE, %u of %u checks failed", (unsigned)nFailed, (unsigned)nChecked);',
            '    printf("FB_SL_SELFTEST under matiec: %u layout checks, %u failed\\n", (unsigned)nChecked, (unsigned)nFailed);']
    for b in hdr.blocks:
        out.append(f'    CHECK(seen_{b.lower} == 15u, "{b.name}: run-like state, ERROR, RESET, run-like again: reached %s%s%s%s", '
                   f'(seen_{b.lower} & 1) ? "run " : "", (seen_{b.lower} & 2) ? "error " : "", '
                   f'(seen_{b.lower} & 4) ? "reset " : "", (seen_{b.lower} & 8) ? "run-again" : "");')
        out.append(f'    printf("{b.name}: %d cycles through {b.fb_name}, %d returned SL_OK; run, ERROR, RESET, run again: %s\\n", '
                   f'{N_CYCLES}, ok_{b.lower}, seen_{b.lower} == 15u ? "yes" : "NO");')
        out.append(f'    CHECK(reasons_{b.lower} > 0, "{b.name}: sReason never held a sentence");')
    out += ["    {", "        char s[REASON_BODY + 1];", "        probe_reason_refused(s, sizeof s);",
            f'        CHECK(strstr(s, "{REFUSED_SENTENCE}") != NULL, "FB_TWOHAND refused: sReason \'%s\'", s);',
            '        printf("FB_TWOHAND with tDiscTimePairs 3000 ms: sReason \'%s\'\\n", s);', "    }"]
    out.append('    CHECK(seen_group == 15u, "group (ESTOP, MON -> AND): RUN, ERROR, RESET, RUN again not all reached (%u)", seen_group);')
    out.append(f'    printf("group (ESTOP, MON -> AND, 2 links) through FB_SL_GROUP: {N_CYCLES} cycles; RUN, ERROR, RESET, RUN again: %s\\n", seen_group == 15u ? "yes" : "NO");')
    out += ['    printf("%d passed, %d failed\\n", passed, failed);', "    return failed == 0 ? 0 : 1;", "}", ""]
    return "\n".join(out)


def add_matiec_args(ap: argparse.ArgumentParser) -> None:
    """The options of every tool that compiles ST with matiec and links our library."""
    ap.add_argument("--iec2c", required=True)
    ap.add_argument("--matiec-lib", required=True)
    ap.add_argument("--workdir", required=True, type=Path)
    ap.add_argument("--lib", default=str(ROOT / "target/release/libsafelogic.a"))


def build_matiec(args, st_file: Path, gen: Path, st_side: list, driver: Path, exe: Path, opt: str = "-O0") -> None:
    """iec2c with OpenPLC's options (-f -l -p -r -R -a) on `st_file` into `gen`; the generated C
    and the `st_side` sources compiled as C with matiec's lib/C headers (matiec's code is not
    warning-free: -w, errors still fail); `driver` compiled warning-free against our header;
    linked with the library into `exe`."""
    run([args.iec2c, "-f", "-l", "-p", "-r", "-R", "-a", "-I", args.matiec_lib, "-T", str(gen), str(st_file)])
    w = exe.parent
    inc = ["-I", str(Path(args.matiec_lib) / "C"), "-I", str(gen), "-I", str(w)]
    objs = []
    for src in [gen / "Config0.c", gen / "Res0.c", *st_side]:
        o = w / (src.stem + ".o")
        run(["gcc", "-std=gnu11", opt, "-w", *inc, "-c", str(src), "-o", str(o)])
        objs.append(str(o))
    o = w / (driver.stem + ".o")
    run(["gcc", "-std=c11", opt, "-Wall", "-Wextra", "-Werror", "-I", str(ROOT / "include"), "-I", str(w),
         "-c", str(driver), "-o", str(o)])
    run(["gcc", str(o), *objs, args.lib, "-lpthread", "-ldl", "-lm", "-o", str(exe)])


def run(cmd, **kw):
    r = subprocess.run(cmd, capture_output=True, text=True, **kw)
    if r.returncode != 0:
        sys.stdout.write(r.stdout[-4000:] + r.stderr[-4000:])
        print(f"FAIL: {' '.join(map(str, cmd))} exited with {r.returncode}")
        print("0 passed, 1 failed")
        sys.exit(1)
    return r


def compile_only(args, hdr) -> int:
    w = args.workdir
    gen = w / "gen"
    gen.mkdir(parents=True, exist_ok=True)
    for p in gen.iterdir():
        p.unlink()
    prog = ["", "PROGRAM prog0", "VAR", "    fbSelfTest : FB_SL_SELFTEST;"]
    prog += [f"    fb{b.name} : {b.fb_name};" for b in hdr.blocks]
    prog += ["END_VAR", "fbSelfTest();"] + [f"fb{b.name}({'' if b.is_sf else 'tNow := UDINT#0'});" for b in hdr.blocks]
    prog += ["END_PROGRAM", "", "CONFIGURATION Config0", "  RESOURCE Res0 ON PLC",
             "    TASK task0(INTERVAL := T#10ms, PRIORITY := 0);", "    PROGRAM instance0 WITH task0 : prog0;",
             "  END_RESOURCE", "END_CONFIGURATION", ""]
    (w / "test.st").write_text(args.st.read_text(encoding="utf-8") + "\n".join(prog), encoding="utf-8")
    run([args.iec2c, "-f", "-l", "-p", "-r", "-R", "-a", "-I", args.matiec_lib, "-T", str(gen), str(w / "test.st")])
    for src in (gen / "Config0.c", gen / "Res0.c"):
        run(["gcc", "-std=gnu11", "-w", "-I", str(Path(args.matiec_lib) / "C"), "-I", str(gen), "-c", str(src),
             "-o", str(w / (src.stem + ".o"))])
    print(f"{args.st}: iec2c -f -l -p -r -R -a and gcc -c passed for {len(hdr.blocks)} blocks")
    print("1 passed, 0 failed")
    return 0


def main() -> int:
    ap = argparse.ArgumentParser()
    add_matiec_args(ap)
    ap.add_argument("--header", type=Path, default=ROOT / "include/safelogic.h")
    ap.add_argument("--st", type=Path, default=ROOT / "plc_bindings/iec/safelogic_iec.st")
    ap.add_argument("--compile-only", action="store_true",
                    help="only compile (iec2c, then gcc -c) the IEC file with a program that calls every FB once "
                         "(for the synthetic header of the genericity check)")
    args = ap.parse_args()
    hdr = plcgen.parse_header(args.header.read_text(encoding="utf-8"))
    if args.compile_only:
        return compile_only(args, hdr)
    for b in hdr.blocks:
        BLOCK_INPUTS[b.name] = [f.name for f in b.inputs if f.ctype == "SL_BOOL" and not f.count]
    missing = [b.name for b in hdr.blocks if b.name not in BLOCKS and not b.is_sf]
    if missing:
        print(f"FAIL: no run script for {', '.join(missing)} in tools/plc_matiec_run.py BLOCKS")
        print("0 passed, 1 failed")
        return 1
    w = args.workdir
    w.mkdir(parents=True, exist_ok=True)
    gen = w / "gen"
    gen.mkdir(exist_ok=True)
    for p in gen.iterdir():
        p.unlink()
    iec = args.st.read_text(encoding="utf-8")
    (w / "test.st").write_text(iec + st_program(hdr), encoding="utf-8")
    (w / "mirror.h").write_text(mirror_h(hdr), encoding="utf-8")
    (w / "probe.c").write_text(probe_c(hdr), encoding="utf-8")
    (w / "driver.c").write_text(driver_c(hdr), encoding="utf-8")
    build_matiec(args, w / "test.st", gen, [w / "probe.c"], w / "driver.c", w / "matiec_run")
    print(f"iec2c -f -l -p -r -R -a: plc_bindings/iec/safelogic_iec.st (unchanged) + test program compiled to "
          f"{', '.join(sorted(p.name for p in gen.glob('*.c')))}")
    print("gcc: generated C compiled as C with matiec's lib/C headers, linked with libsafelogic.a")
    r = subprocess.run([str(w / "matiec_run")], capture_output=True, text=True)
    sys.stdout.write(r.stdout)
    sys.stdout.write(r.stderr)
    return r.returncode


if __name__ == "__main__":
    sys.exit(main())
