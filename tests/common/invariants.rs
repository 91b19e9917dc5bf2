//! The invariants every block keeps after every call, read from its bytes through the
//! registry's field table (research §0.2, §3.2; ABI §5, §7): a documented status; BOOL
//! outputs 0/1; for the TwinSAFE blocks no output TRUE in STOP / ERROR / RESET or after a
//! refusal (SL_E_CONFIG / SL_E_CORRUPT / SL_E_CLOCK / SL_E_PARAM_CHANGED) and `bError`
//! exactly in ERROR; for the PLCopen `SF_` blocks the DiagCode rules of [`check_sf`].
//! One file for tests/conformance.rs and the fuzz targets (`fuzz/fuzz_targets`, which
//! include it by path), so both read the rules the same way.

#![allow(dead_code)] // each includer uses a part

use safelogic::registry::{BlockType, Dir, Kind};
use safelogic::*;

pub fn read(bytes: &[u8], offset: u16, kind: Kind) -> u32 {
    let o = usize::from(offset);
    match kind.size() {
        1 => u32::from(bytes[o]),
        2 => u32::from(u16::from_ne_bytes([bytes[o], bytes[o + 1]])),
        _ => u32::from_ne_bytes([bytes[o], bytes[o + 1], bytes[o + 2], bytes[o + 3]]),
    }
}

pub const DOCUMENTED: [i32; 7] = [
    SL_OK,
    SL_E_CONFIG,
    SL_E_PARAM_CHANGED,
    SL_E_CORRUPT,
    SL_E_INVALID_BOOL,
    SL_E_CLOCK,
    SL_E_RESTORE,
];

/// The invariants after one call, read from the instance's bytes.
pub fn check(t: &BlockType, bytes: &[u8], status: i32, what: &str) -> u8 {
    let name = t.info.name;
    assert!(
        DOCUMENTED.contains(&status),
        "{name} {what}: status {status}"
    );
    let state = bytes[usize::from(t.field("nState").unwrap().offset)];
    assert!(
        t.info.states.iter().any(|(v, _)| *v == state),
        "{name} {what}: state {state} is not one of the block's"
    );
    let safe_state = matches!(state, SL_STATE_STOP | SL_STATE_ERROR | SL_STATE_RESET);
    let refused = matches!(
        status,
        SL_E_CONFIG | SL_E_CORRUPT | SL_E_CLOCK | SL_E_PARAM_CHANGED
    );
    for f in t.fields.iter().filter(|f| f.dir == Dir::Output) {
        let v = read(bytes, f.offset, f.kind);
        if f.kind == Kind::Bool {
            assert!(v <= 1, "{name} {what}: {} = {v}", f.name);
        }
        if f.name == "bError" {
            assert_eq!(
                v == 1,
                state == SL_STATE_ERROR,
                "{name} {what}: bError in state {state}"
            );
        } else if safe_state || refused {
            assert_eq!(
                v, 0,
                "{name} {what}: {} TRUE/non-zero in state {state}, status {status}",
                f.name
            );
        }
    }
    state
}

/// The PLCopen invariants after one call (research §0.2, §3.2; issue 15 item 3), read from
/// the instance's bytes through the field table: a documented status; a DiagCode of the
/// block (either profile) or of the library; `Ready == (DiagCode != 0)`, `Error ==
/// (DiagCode >= 0xC000)`, the safety output TRUE only at 0x8000 and never after a refusing
/// status; in the v2.01 profile SafetyDemand = bit 0x0800 and ResetRequest = bit 0x0400
/// with Reset FALSE; Activate not TRUE → DiagCode 0000 and every output FALSE. Returns the
/// DiagCode.
pub fn check_sf(t: &BlockType, bytes: &[u8], status: i32, what: &str) -> u16 {
    let name = t.info.name;
    assert!(
        DOCUMENTED.contains(&status),
        "{name} {what}: status {status}"
    );
    let get = |n: &str| t.field(n).map(|f| read(bytes, f.offset, f.kind));
    let code = get("DiagCode").unwrap() as u16;
    let library = [
        SL_SF_DIAG_CORRUPT,
        SL_SF_DIAG_CLOCK,
        SL_SF_DIAG_CONST_CHANGED,
        SL_SF_DIAG_CONFIG,
    ];
    assert!(
        code == 0 || library.contains(&code) || t.info.diag_values.iter().any(|(c, _)| *c == code),
        "{name} {what}: DiagCode {code:04X} is not one of the block's"
    );
    let flag = |n: &str| {
        get(n).map(|v| {
            assert!(v <= 1, "{name} {what}: {n} = {v}");
            v == 1
        })
    };
    assert_eq!(
        flag("Ready"),
        Some(code != 0),
        "{name} {what}: Ready at {code:04X}"
    );
    assert_eq!(
        flag("Error"),
        Some(code >= 0xC000),
        "{name} {what}: Error at {code:04X}"
    );
    let refused = matches!(
        status,
        SL_E_CONFIG | SL_E_CORRUPT | SL_E_CLOCK | SL_E_PARAM_CHANGED
    );
    let generic = ["Ready", "Error", "SafetyDemand", "ResetRequest"];
    for f in t
        .fields
        .iter()
        .filter(|f| f.dir == Dir::Output && !generic.contains(&f.name))
    {
        let on = flag(f.name).unwrap();
        if let Some(want) = sf_sensor_output(name, f.name, code, library.contains(&code)) {
            assert_eq!(on, want, "{name} {what}: {} at {code:04X}", f.name);
            continue;
        }
        assert!(
            !on || allowed_on(name, f.name, get("nDiagProfile"), code),
            "{name} {what}: {} TRUE at {code:04X}",
            f.name
        );
        assert!(
            !on || !refused,
            "{name} {what}: {} TRUE after status {status}",
            f.name
        );
    }
    if get("nDiagProfile") == Some(u32::from(SL_SF_PROFILE_V201)) && !library.contains(&code) {
        if let Some(d) = flag("SafetyDemand") {
            assert_eq!(
                d,
                code & 0x0800 != 0,
                "{name} {what}: SafetyDemand at {code:04X}"
            );
        }
        if let Some(r) = flag("ResetRequest") {
            let reset = get("Reset") == Some(1);
            assert_eq!(
                r,
                code & 0x0400 != 0 && !reset,
                "{name} {what}: ResetRequest at {code:04X}"
            );
        }
    }
    if get(sf_activate_name(t)) != Some(1) {
        assert_eq!(code, 0, "{name} {what}: Activate not TRUE");
        for f in t
            .fields
            .iter()
            .filter(|f| f.dir == Dir::Output && sf_sensor_output(name, f.name, 0, false).is_none())
        {
            assert_eq!(
                read(bytes, f.offset, f.kind),
                0,
                "{name} {what}: {} idle",
                f.name
            );
        }
    }
    code
}

/// Where a block's own output may be TRUE: at 0x8000, except an `S_` output whose table says
/// otherwise — SF_SafetyRequest's S_SafetyRequest asks the actuator for the operation mode
/// in OP_MODE and WAIT_FOR_CONF_OPMODE (research §4.14, semantics QR3), and only there.
fn allowed_on(block: &str, output: &str, profile: Option<u32>, code: u16) -> bool {
    match (block, output) {
        ("SF_SafetyRequest", "S_SafetyRequest") => {
            let op = if profile == Some(u32::from(SL_SF_PROFILE_V10)) {
                [0x8002, 0x8012]
            } else {
                [0x8802, 0x8804]
            };
            op.contains(&code)
        }
        _ => code == 0x8000 || sf_holds_outputs(block, profile, code),
    }
}

/// A state other than 0x8000 in which a block's safety outputs may be TRUE: SF_ModeSelector's
/// MODE_LOCKED (v2.01 8010, v1.0 8004) holds the selected mode (research §9.3, semantics QM2).
fn sf_holds_outputs(name: &str, profile: Option<u32>, code: u16) -> bool {
    let locked = if profile == Some(u32::from(SL_SF_PROFILE_V10)) {
        0x8004
    } else {
        0x8010
    };
    name == "SF_ModeSelector" && code == locked
}

/// SF_TestableSafetySensor's own outputs, written from research §4.15 (ABB's per-state
/// output table, PLCN; semantics QT5): S_OSSD_Out TRUE while the sensor is free (8010,
/// 8000) and during the automatic test (8020, 8030); S_TestOut TRUE except in test phase 1
/// (8020) and in a library fault (idle included: PLCN "S_TestOut = SAFETRUE"); TestPossible
/// in 8010 and 8000; TestExecuted in 8000. `None`: not such an output (the generic rule).
fn sf_sensor_output(block: &str, field: &str, code: u16, library: bool) -> Option<bool> {
    if block != "SF_TestableSafetySensor" {
        return None;
    }
    Some(match field {
        "S_OSSD_Out" => [0x8000, 0x8010, 0x8020, 0x8030].contains(&code),
        "S_TestOut" => !library && code != 0x8020,
        "TestPossible" => code == 0x8000 || code == 0x8010,
        "TestExecuted" => code == 0x8000,
        _ => return None,
    })
}

/// The input that activates a PLCopen block: `Activate`; SF_ResetButton has none, its
/// `ResetRequested` plays the part (research §4.19).
pub fn sf_activate_name(t: &BlockType) -> &'static str {
    if t.field("Activate").is_some() {
        "Activate"
    } else {
        "ResetRequested"
    }
}

/// A PLCopen `SF_` block (its field table has a DiagCode), not a TwinSAFE one.
pub fn is_sf(t: &BlockType) -> bool {
    t.field("DiagCode").is_some()
}

/// [`check`] or [`check_sf`], whichever family `t` belongs to.
pub fn check_any(t: &BlockType, bytes: &[u8], status: i32, what: &str) {
    if is_sf(t) {
        check_sf(t, bytes, status, what);
    } else {
        check(t, bytes, status, what);
    }
}

/// Every BOOL output FALSE but the error status (a member of a group that is not in RUN).
/// A TwinSAFE block's `bError`; an `SF_` block's `Ready` and `Error`, which mirror its
/// DiagCode ([`check_sf`]): the block whose library fault stopped the group reports it in
/// that cycle, and the group halts it from the next one on (DiagCode 0000, semantics PO8),
/// where it keeps only the outputs its table defines in idle (SF_TestableSafetySensor's
/// S_TestOut).
pub fn check_outputs_false(t: &BlockType, bytes: &[u8], why: &str) {
    let name = t.info.name;
    let status = |f: &str| f == "bError" || (is_sf(t) && (f == "Ready" || f == "Error"));
    for f in t
        .fields
        .iter()
        .filter(|f| f.dir == Dir::Output && f.kind == Kind::Bool)
    {
        let v = read(bytes, f.offset, f.kind);
        assert!(v <= 1, "{name}: {} = {v}", f.name);
        if status(f.name) {
            continue;
        }
        let code = if is_sf(t) {
            read(bytes, t.field("DiagCode").unwrap().offset, Kind::U16) as u16
        } else {
            0
        };
        let idle = code == 0 && sf_sensor_output(name, f.name, 0, false).unwrap_or(false);
        assert_eq!(v == 1, idle, "{name}: {} while {why}", f.name);
    }
}
