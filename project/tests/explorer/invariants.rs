//! The invariants every transition must keep: the manual's safety rules written once per
//! block family (with the per-block tables below), the ABI rules (status codes, state
//! values, BOOL bytes, time-shift invariance), checked by `check`.

use super::{documented_status, Instance, Transition, EDGE_INPUTS};
use safelogic::registry::{family, BlockType, Dir, Family, Kind};
use safelogic::{
    SL_E_PARAM_CHANGED, SL_SF_DIAG_CLOCK, SL_SF_DIAG_CONFIG, SL_SF_DIAG_CONST_CHANGED,
    SL_SF_DIAG_CORRUPT,
};

/// The manual's name of the block's state (`?<value>` for a value outside its list).
/// A PLCopen block's state is its DiagCode (IDLE 0x0000, ACTIVE 0x8xxx, FAULT 0xCxxx).
pub fn state_name(ty: &BlockType, b: &Instance) -> String {
    if let Some(d) = ty.field("DiagCode").map(|f| b.get(f) as u16) {
        return match d {
            0 => "IDLE",
            d if d & 0xC000 == 0xC000 => "FAULT",
            _ => "ACTIVE",
        }
        .into();
    }
    let v = state_value(ty, b);
    ty.info
        .states
        .iter()
        .find(|(s, _)| u16::from(*s) == v)
        .map_or(format!("?{v}"), |(_, n)| {
            n.trim_end_matches('\0').to_string()
        })
}

/// The state value: `nState`, or a PLCopen block's DiagCode.
pub fn state_value(ty: &BlockType, b: &Instance) -> u16 {
    ty.field("nState")
        .or_else(|| ty.field("DiagCode"))
        .map_or(0, |f| b.get(f) as u16)
}

/// The manual's state values with the profile they belong to: `nState`'s list (profile
/// 0), or a PLCopen block's DiagCodes: its `TEXTS` table lists every state's v2.01 code
/// (profile 0), then every state's v1.0 code (profile 1, `nDiagProfile` = 1).
pub fn state_list(ty: &BlockType) -> Vec<(i64, u16, String)> {
    if family(ty.info.tag) == Family::PlcOpen {
        let half = ty.info.diag_values.len() / 2;
        ty.info
            .diag_values
            .iter()
            .enumerate()
            .map(|(i, (v, n))| (i64::from(i >= half), *v, n.to_string()))
            .collect()
    } else {
        ty.info
            .states
            .iter()
            .map(|(v, n)| (0, u16::from(*v), n.trim_end_matches('\0').to_string()))
            .collect()
    }
}

/// Every BOOL output and its byte.
pub fn bool_outputs(ty: &BlockType, b: &Instance) -> Vec<(&'static str, i64)> {
    ty.fields
        .iter()
        .filter(|f| f.dir == Dir::Output && f.kind == Kind::Bool)
        .map(|f| (f.name, b.get(f)))
        .collect()
}

/// The outputs that report a fault or request the safe state rather than enable anything
/// (CONNECTION SHUTDOWN's bShutdownRequest shuts connections down: TRUE in SAFE, §4.15).
fn is_indicator(name: &str) -> bool {
    matches!(
        name,
        "bError"
            | "Error"
            | "Ready"
            | "SafetyDemand"
            | "ResetRequest"
            | "bTestError"
            | "bWait"
            | "bShutdownRequest"
            // LIMIT, SLI2, SLP: which side the value left on (TRUE in SAFE by design).
            | "bBelowMin"
            | "bAboveMax"
    )
}

/// TwinSAFE blocks: the states in which an enabling output may be TRUE, where the manual
/// restricts it beyond "not in STOP, SAFE or ERROR" (manual §4.4.2 ESTOP, §4.5 MON, the
/// timers, TWOHAND).
fn allowed_states(block: &str, output: &str) -> Option<&'static [&'static str]> {
    Some(match (block, output) {
        ("ESTOP", "bEStopOut") | ("MON", "bMonOut") => &["RUN"],
        ("ESTOP", "bEStopDelOut") => &["RUN", "DELAYOUT"],
        // MON: a discrepancy error first waits out the delayed output (ERRORDELAY, §4.5).
        ("MON", "bMonDelOut") => &["RUN", "DELAYOUT", "ERRORDELAY"],
        ("TWOHAND", "bTwoHandOut") => &["RUN"],
        ("TON" | "TON2", "bTonOut") => &["RUN"],
        ("TOF", "bTofOut") => &["RUN", "DELAYOUT"],
        _ => return None,
    })
}

/// PLCopen blocks: an S_ output TRUE at a DiagCode other than 0x8000, as the PLCopen
/// specification documents it for that block.
fn sf_output_exception(block: &str, output: &str, diag: u16, profile: i64) -> bool {
    match (block, output) {
        // S_SafetyRequest TRUE = operation mode requested from the actuator: OP_MODE and
        // WAIT_FOR_CONF_OPMODE (v2.01 0x8802 / 0x8804, v1.0 0x8002 / 0x8012); semantics QR3.
        ("SF_SafetyRequest", "S_SafetyRequest") => match profile {
            1 => matches!(diag, 0x8002 | 0x8012),
            _ => matches!(diag, 0x8802 | 0x8804),
        },
        // The sensor is free (output TRUE) also untested and during the automatic test:
        // ESPE_FREE_NO_TEST, TEST_REQUEST, TEST_ACTIVE (same codes in both profiles);
        // semantics QT4, QT5.
        ("SF_TestableSafetySensor", "S_OSSD_Out") => matches!(diag, 0x8010 | 0x8020 | 0x8030),
        // S_TestOut drives the sensor's test input: TRUE whenever no test runs (QT4, QT5).
        ("SF_TestableSafetySensor", "S_TestOut") => true,
        // The mode selected stays TRUE while the selector waits (0x8005) or is locked
        // (semantics QM2, QM3).
        ("SF_ModeSelector", _) => (0x8000..0x9000).contains(&diag),
        // S_SafetyActive reports the drive's safe state, TRUE at 0x8012 (safe) as well
        // (semantics QR3).
        ("SF_SafetyRequest", "S_SafetyActive") => (0x8000..0x9000).contains(&diag),
        _ => false,
    }
}

/// The first invariant the transition breaks, as a sentence.
pub fn check(tr: &Transition) -> Option<String> {
    let ty = tr.ty;
    let name = ty.info.name;
    let (before, after) = (tr.before, tr.after);
    if let Some(m) = &tr.shift_mismatch {
        return Some(format!(
            "time-shift invariance: the same transition 2^30 ms later (away from the clock wrap) differs: {m}"
        ));
    }
    let input = |n: &str| {
        tr.cfg
            .driven
            .iter()
            .position(|(f, _)| f.name == n)
            .map(|i| tr.step.inputs[i])
    };
    let invalid = tr
        .cfg
        .driven
        .iter()
        .zip(&tr.step.inputs)
        .any(|((f, _), v)| f.kind == Kind::Bool && *v > 1);
    // A PLCopen block's constant inputs (S_StartReset, S_AutoReset, NoExternalTest) are
    // latched at activation: changing one while activated is SL_E_PARAM_CHANGED with its
    // library DiagCode (header: "a constant input changed while the block was activated").
    let constant_changed = family(ty.info.tag) == Family::PlcOpen && tr.rc == SL_E_PARAM_CHANGED;
    if !documented_status(tr.rc, invalid) && !constant_changed {
        return Some(format!(
            "status {} is not a documented cycle status here",
            tr.rc
        ));
    }
    let st = state_value(ty, after);
    // A PLCopen block may also show the library's own DiagCodes (SL_SF_DIAG_*: corrupt,
    // clock, constant changed, constant invalid), each documented in the header.
    let library = family(ty.info.tag) == Family::PlcOpen
        && [
            SL_SF_DIAG_CORRUPT,
            SL_SF_DIAG_CLOCK,
            SL_SF_DIAG_CONST_CHANGED,
            SL_SF_DIAG_CONFIG,
        ]
        .contains(&st);
    // The configuration's profile: a v1.0 code under v2.01 (or the reverse) is foreign.
    let profile = tr
        .cfg
        .params
        .iter()
        .find(|(f, _)| f.name == "nDiagProfile")
        .map_or(0, |(_, v)| *v);
    if !library
        && !state_list(ty)
            .iter()
            .any(|(p, s, _)| *p == profile && *s == st)
    {
        return Some(format!(
            "state value 0x{st:04X} is not one of the manual's states (profile {profile})"
        ));
    }
    let outs = bool_outputs(ty, after);
    if let Some((o, v)) = outs.iter().find(|(_, v)| *v > 1) {
        return Some(format!("output {o} is the byte {v}, not a BOOL"));
    }
    let s_after = state_name(ty, after);
    let s_before = state_name(ty, before);
    // An invalid input byte never makes an enabling output TRUE: the call gives no
    // output TRUE that the same call with that byte FALSE leaves FALSE (ABI §2: an
    // invalid byte reads as its safe value).
    if let Some(safe) = &tr.safe_reading {
        for ((o, v), (_, s)) in outs.iter().zip(bool_outputs(ty, safe)) {
            if !is_indicator(o) && *v == 1 && s == 0 {
                return Some(format!(
                    "{o} is TRUE after a call with an invalid input byte, FALSE with that byte FALSE"
                ));
            }
        }
    }
    let prev_edge = |n: &str| {
        EDGE_INPUTS
            .iter()
            .position(|e| *e == n)
            .map_or(0, |i| tr.prev_edges[i])
    };
    match family(ty.info.tag) {
        Family::TwinSafe => {
            let off_state = matches!(s_after.as_str(), "ERROR" | "STOP" | "SAFE");
            for (o, v) in &outs {
                if *o == "bError" {
                    if (*v == 1) != (s_after == "ERROR") {
                        return Some(format!("bError is {v} in state {s_after}"));
                    }
                    continue;
                }
                if is_indicator(o) || *v == 0 {
                    continue;
                }
                if off_state && !off_state_exception(name, o) {
                    return Some(format!("{o} is TRUE in state {s_after}"));
                }
                if let Some(ok) = allowed_states(name, o) {
                    if !ok.contains(&s_after.as_str()) {
                        return Some(format!(
                            "{o} is TRUE in state {s_after}, allowed only in {ok:?}"
                        ));
                    }
                }
            }
            // ERROR is left only through an ErrAck edge, or when the group stops the
            // block (bRun FALSE or invalid).
            if s_before == "ERROR" && s_after != "ERROR" {
                let ack = input("bErrAck").unwrap_or(0);
                let ack_edge = (ack == 1) != (prev_edge("bErrAck") == 1);
                let run = input("bRun").unwrap_or(1) == 1;
                if !ack_edge && run {
                    return Some(format!(
                        "ERROR left for {s_after} without an ErrAck edge while bRun is TRUE"
                    ));
                }
            }
        }
        Family::PlcOpen => {
            let diag = ty.field("DiagCode").map_or(0, |f| after.get(f)) as u16;
            let diag_before = ty.field("DiagCode").map_or(0, |f| before.get(f)) as u16;
            let act_name = if name == "SF_ResetButton" {
                "ResetRequested"
            } else {
                "Activate"
            };
            let act = input(act_name).unwrap_or(0);
            let profile = tr
                .cfg
                .params
                .iter()
                .find(|(f, _)| f.name == "nDiagProfile")
                .map_or(0, |p| p.1);
            for (o, v) in &outs {
                if *v == 0 {
                    continue;
                }
                // S_TestOut stays TRUE while idle (the transmitter on).
                if act != 1 && !(name == "SF_TestableSafetySensor" && *o == "S_TestOut") {
                    return Some(format!("{o} is TRUE with {act_name} = {act}"));
                }
                if (o.starts_with("S_") || *o == "ResetOut")
                    && diag != 0x8000
                    && !sf_output_exception(name, o, diag, profile)
                {
                    return Some(format!(
                        "{o} is TRUE at DiagCode 0x{diag:04X} (only at 0x8000)"
                    ));
                }
            }
            let error = ty.field("Error").map_or(0, |f| after.get(f));
            if (error == 1) != (diag & 0xC000 == 0xC000) {
                return Some(format!("Error is {error} at DiagCode 0x{diag:04X}"));
            }
            // After an error (0xC...) the output is enabled (0x8000) only through a Reset
            // rising edge or a new activation; the restart-interlock blocks leave an error
            // only with a Reset edge (rising: acknowledged; falling: the Reset held at the
            // wrong time released, C001/C011) or Activate FALSE.
            if diag_before & 0xC000 == 0xC000 && diag & 0xC000 != 0xC000 && act == 1 {
                let reset = input("Reset").map(|r| u8::from(r == 1));
                let reset_rise = reset == Some(1) && prev_edge("Reset") == 0;
                let reset_edge = reset.is_some_and(|r| r != prev_edge("Reset"));
                if diag == 0x8000 && !reset_rise {
                    return Some(format!(
                        "error 0x{diag_before:04X} left straight to 0x8000 without a Reset rising edge"
                    ));
                }
                if restart_interlock(name) && !reset_edge {
                    return Some(format!(
                        "error 0x{diag_before:04X} left for 0x{diag:04X} without a Reset edge"
                    ));
                }
            }
        }
    }
    None
}

/// TwinSAFE outputs the manual lets be TRUE in STOP, SAFE or ERROR: none.
fn off_state_exception(_block: &str, _output: &str) -> bool {
    false
}

/// The blocks whose errors are the static-Reset errors alone (C001 / C011), left only
/// when Reset is released (PLCopen SF_EmergencyStop, SF_ESPE, SF_PSE): the other blocks'
/// errors are also left when their inputs are released (discrepancy: SF_Equivalent and
/// SF_Antivalent leave C010/C020/C030 to 8801 with both channels inactive, semantics PP1;
/// two-hand, QH4; guard, QG1).
fn restart_interlock(block: &str) -> bool {
    matches!(block, "SF_EmergencyStop" | "SF_ESPE" | "SF_PSE")
}
