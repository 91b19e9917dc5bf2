//! FB EDM (manual §4.9; ABI §9; docs/semantics.md E1–E9, C1–C12): layout, every state
//! (STOP, ERROR, RESET, MONOFF, MONON), switch-on and switch-off monitoring with exact
//! timing, diag bits, configuration errors, negation, invalid BOOLs, acknowledgement,
//! library errors through the envelope, the C functions, group membership, and property
//! tests against a reference model of the manual's description.

mod common;
use common::state_name;
use common::{aligned_tail, null_refused, offsets, output_base};

use proptest::prelude::*;
use safelogic::ffi;
use safelogic::group::{self, Member, SL_GROUP_DIAG_FBERROR};
use safelogic::*;
use std::mem::offset_of;

const MON1: u16 = 1 << 0;
const MON2: u16 = 1 << 1;
const BOTH: u16 = MON1 | MON2;
const ON: u16 = SL_DIAG_EDM_SWITCH_ON;
const OFF: u16 = SL_DIAG_EDM_SWITCH_OFF;

fn edm(on: u32, off: u32, negated: u16) -> FB_EDM {
    common::ready(FB_EDM {
        tSwitchOnTime: on,
        tSwitchOffTime: off,
        wInputActive: BOTH,
        wInputNegated: negated,
        ..Default::default()
    })
}

/// An EDM started at `t` with the given Mon1/Mon2 bytes.
fn started(on: u32, off: u32, mon1: u8, mon2: u8, t: u32) -> FB_EDM {
    let mut e = edm(on, off, 0);
    e.bMon1 = mon1;
    e.bMon2 = mon2;
    e.bRun = 1;
    assert_eq!(e.cycle(t), SL_OK);
    e
}

fn at(e: &mut FB_EDM, t: u32, mon1: u8, mon2: u8) -> i32 {
    e.bMon1 = mon1;
    e.bMon2 = mon2;
    e.cycle(t)
}

fn assert_running(e: &FB_EDM, state: u8) {
    assert_eq!((e.nState, e.bError, e.nDiag), (state, 0, 0));
}

fn assert_error(e: &FB_EDM, diag: u16) {
    assert_eq!((e.nState, e.bError, e.nDiag), (SL_STATE_ERROR, 1, diag));
}

const MONON: u8 = SL_STATE_EDM_MONON;
const MONOFF: u8 = SL_STATE_EDM_MONOFF;

#[test]
fn layout_states_and_diag_values() {
    // ABI §9: bMon1 (8), bMon2 (9), bError (+0).
    offsets!(FB_EDM; bMon1 => 8, bMon2 => 9, bRun => 16, bErrAck => 17);
    let base = output_base!(FB_EDM);
    assert!(base >= offset_of!(FB_EDM, wInputNegated) + 2);
    aligned_tail!(FB_EDM);
    // Manual §4.9.2: states 14 MONOFF, 15 MONON; diag bit 0 switch-OFF, bit 1 switch-ON.
    assert_eq!((MONOFF, MONON), (14, 15));
    assert_eq!((OFF, ON), (1 << 0, 1 << 1));
    assert_eq!(SL_EDM_TIME_MAX, 10_000);
}

/// E1: times ≤ 10000 ms, at least one monitoring on, both inputs active.
#[test]
fn configuration_errors() {
    let bad = [
        (0, 0, BOTH, 0),
        (10_001, 0, BOTH, 0),
        (0, 10_001, BOTH, 0),
        (10_000, 10_001, BOTH, 0),
        (u32::MAX, 100, BOTH, 0),
        (100, 0, MON1, 0),
        (100, 0, MON2, 0),
        (100, 0, 0, 0),
        (100, 0, 0b111, 0),
        (100, 100, BOTH, 0b100),
    ];
    for (on, off, active, negated) in bad {
        let mut e = common::refused(
            FB_EDM {
                tSwitchOnTime: on,
                tSwitchOffTime: off,
                wInputActive: active,
                wInputNegated: negated,
                bRun: 1,
                bMon1: 1,
                bMon2: 1,
                ..Default::default()
            },
            &[],
        );
        for t in [0, 20_000] {
            assert_eq!(e.cycle(t), SL_E_CONFIG);
            assert_eq!((e.nState, e.bError), (SL_STATE_STOP, 0));
        }
    }
    for (on, off) in [(10_000, 0), (0, 10_000), (10_000, 10_000), (1, 1)] {
        edm(on, off, 0);
        edm(on, off, BOTH);
    }
}

/// STOP: "If the input FbRun=FALSE ... Error=0"; E3: the state Mon1 asks for at start-up.
#[test]
fn start_up_states() {
    let mut e = edm(100, 100, 0);
    assert_eq!((e.nState, e.bError, e.nDiag), (SL_STATE_STOP, 0, 0));
    at(&mut e, 0, 0, 1);
    assert_running(&e, SL_STATE_STOP);
    e.bRun = 1;
    at(&mut e, 1, 0, 1);
    assert_running(&e, MONOFF);
    // "If the input MonIn1=TRUE, the FB EDM module assumes the MONON state" — same call.
    at(&mut e, 2, 1, 0);
    assert_running(&e, MONON);
    let e = started(100, 100, 1, 0, 5);
    assert_running(&e, MONON);
    // Settled at start-up: stays without error however long.
    let mut e = started(100, 100, 0, 1, 0);
    at(&mut e, 60_000, 0, 1);
    assert_running(&e, MONOFF);
}

/// E3: the monitoring of the start state runs as if Mon1 had just switched.
#[test]
fn start_up_monitoring() {
    let mut e = started(100, 300, 1, 1, 1000);
    assert_running(&e, MONON);
    at(&mut e, 1099, 1, 1);
    assert_running(&e, MONON);
    at(&mut e, 1100, 1, 1);
    assert_error(&e, ON);

    let mut e = started(100, 300, 0, 0, 1000);
    at(&mut e, 1299, 0, 0);
    assert_running(&e, MONOFF);
    at(&mut e, 1300, 0, 0);
    assert_error(&e, OFF);

    // That state's monitoring off: nothing to wait for.
    let mut e = started(0, 300, 1, 1, 1000);
    at(&mut e, 30_000, 1, 1);
    assert_running(&e, MONON);
}

/// "Switch-on monitoring checks whether signal Mon2 is set to 0 within the set time
/// following a switch from 0 to 1 of signal Mon1" (E2, E4).
#[test]
fn switch_on_monitoring() {
    // Mon2 stays 1: the error when the time is reached, diag bit 1, Error=1.
    let mut e = started(100, 200, 0, 1, 0);
    assert_eq!(at(&mut e, 1000, 1, 1), SL_OK);
    assert_running(&e, MONON);
    at(&mut e, 1050, 1, 1);
    at(&mut e, 1099, 1, 1);
    assert_running(&e, MONON);
    assert_eq!(at(&mut e, 1100, 1, 1), SL_OK);
    assert_error(&e, ON);
    at(&mut e, 1200, 1, 0);
    assert_error(&e, ON);

    // Mon2 goes 0 in time: no error, and later changes of Mon2 are not watched.
    let mut e = started(100, 200, 0, 1, 0);
    at(&mut e, 1000, 1, 1);
    at(&mut e, 1099, 1, 0);
    at(&mut e, 1150, 1, 1);
    at(&mut e, 5000, 1, 1);
    assert_running(&e, MONON);

    // Mon2 at 0 in the very call the time is reached counts as in time.
    let mut e = started(100, 200, 0, 1, 0);
    at(&mut e, 1000, 1, 1);
    at(&mut e, 1100, 1, 0);
    assert_running(&e, MONON);

    // Mon2 at 0 already in the switch call.
    let mut e = started(100, 200, 0, 1, 0);
    at(&mut e, 1000, 1, 0);
    at(&mut e, 1001, 1, 1);
    at(&mut e, 2000, 1, 1);
    assert_running(&e, MONON);

    // A long cycle: the first call after the time is the error.
    let mut e = started(100, 200, 0, 1, 0);
    at(&mut e, 1000, 1, 1);
    at(&mut e, 1500, 1, 1);
    assert_error(&e, ON);
}

/// "Switch-off monitoring checks whether signal Mon2 is set to 1 within the set time
/// following a switch from 1 to 0 of signal Mon1" (E2, E4).
#[test]
fn switch_off_monitoring() {
    let mut e = started(100, 200, 1, 0, 0);
    assert_eq!(at(&mut e, 1000, 0, 0), SL_OK);
    assert_running(&e, MONOFF);
    at(&mut e, 1199, 0, 0);
    assert_running(&e, MONOFF);
    at(&mut e, 1200, 0, 0);
    assert_error(&e, OFF);

    let mut e = started(100, 200, 1, 0, 0);
    at(&mut e, 1000, 0, 0);
    at(&mut e, 1199, 0, 1);
    at(&mut e, 1300, 0, 0);
    at(&mut e, 9000, 0, 0);
    assert_running(&e, MONOFF);

    // Maximum time, exactly.
    let mut e = started(100, 10_000, 1, 0, 0);
    at(&mut e, 1000, 0, 0);
    at(&mut e, 10_999, 0, 0);
    assert_running(&e, MONOFF);
    at(&mut e, 11_000, 0, 0);
    assert_error(&e, OFF);
}

/// "Monitoring is disabled if the value is set to 0 ms."
#[test]
fn disabled_monitoring() {
    let mut e = started(0, 100, 0, 1, 0);
    at(&mut e, 1000, 1, 1);
    at(&mut e, 20_000, 1, 1);
    assert_running(&e, MONON);
    // The other one still works.
    at(&mut e, 20_001, 0, 0);
    at(&mut e, 20_101, 0, 0);
    assert_error(&e, OFF);

    let mut e = started(100, 0, 1, 0, 0);
    at(&mut e, 1000, 0, 0);
    at(&mut e, 20_000, 0, 0);
    assert_running(&e, MONOFF);
    at(&mut e, 20_001, 1, 1);
    at(&mut e, 20_101, 1, 1);
    assert_error(&e, ON);
}

/// E2: a switch of Mon1 ends the other state's monitoring and starts its own from scratch.
#[test]
fn a_switch_ends_the_other_monitoring() {
    // Switched back on before the device released: the switch-off monitoring ends.
    let mut e = started(100, 100, 1, 0, 0);
    at(&mut e, 1000, 0, 0);
    at(&mut e, 1050, 1, 0);
    assert_running(&e, MONON);
    at(&mut e, 1500, 1, 0);
    assert_running(&e, MONON);
    // Switched back off before the device pulled in: the switch-on monitoring ends.
    let mut e = started(100, 100, 0, 1, 0);
    at(&mut e, 1000, 1, 1);
    at(&mut e, 1050, 0, 1);
    at(&mut e, 1500, 0, 1);
    assert_running(&e, MONOFF);
    // Each switch starts the time again.
    let mut e = started(100, 0, 0, 1, 0);
    at(&mut e, 1000, 1, 1);
    at(&mut e, 1050, 0, 1);
    at(&mut e, 1080, 1, 1);
    at(&mut e, 1100, 1, 1);
    at(&mut e, 1179, 1, 1);
    assert_running(&e, MONON);
    at(&mut e, 1180, 1, 1);
    assert_error(&e, ON);
}

/// "The input can be parameterized as a break contact or a make contact" (negation bits).
#[test]
fn negated_inputs() {
    // Mon1 a make contact: raw 0 is logical TRUE → MONON.
    let mut e = edm(100, 100, MON1);
    e.bRun = 1;
    at(&mut e, 0, 0, 0);
    assert_running(&e, MONON);
    at(&mut e, 200, 0, 0);
    assert_running(&e, MONON);
    at(&mut e, 201, 1, 1);
    assert_running(&e, MONOFF);
    at(&mut e, 400, 1, 1);
    assert_running(&e, MONOFF);
    // Once satisfied, Mon2 is not watched until Mon1 switches again (E4).
    at(&mut e, 401, 1, 0);
    at(&mut e, 900, 1, 0);
    assert_running(&e, MONOFF);
    at(&mut e, 901, 0, 0);
    assert_running(&e, MONON);
    at(&mut e, 902, 1, 0);
    at(&mut e, 1001, 1, 0);
    assert_running(&e, MONOFF);
    at(&mut e, 1002, 1, 0);
    assert_error(&e, OFF);
    // Mon2 a make contact: raw 1 is logical FALSE.
    let mut e = edm(100, 100, MON2);
    e.bRun = 1;
    at(&mut e, 0, 1, 1);
    at(&mut e, 1000, 1, 1);
    assert_running(&e, MONON);
    at(&mut e, 1001, 0, 0);
    at(&mut e, 2000, 0, 0);
    assert_running(&e, MONOFF);
    at(&mut e, 2001, 1, 0);
    at(&mut e, 2101, 1, 0);
    assert_error(&e, ON);
}

/// E7: invalid Mon1 reads FALSE (MONOFF, switch-off monitoring); invalid Mon2 satisfies
/// no monitoring.
#[test]
fn invalid_bools() {
    let mut e = started(100, 100, 1, 0, 0);
    assert_eq!(at(&mut e, 1000, 2, 0), SL_E_INVALID_BOOL);
    assert_running(&e, MONOFF);
    assert_eq!(at(&mut e, 1099, 0xFF, 0), SL_E_INVALID_BOOL);
    assert_running(&e, MONOFF);
    assert_eq!(at(&mut e, 1100, 0xFF, 0), SL_E_INVALID_BOOL);
    assert_error(&e, OFF);
    // Whatever the negation.
    let mut e = edm(100, 100, MON1);
    e.bRun = 1;
    assert_eq!(at(&mut e, 0, 9, 1), SL_E_INVALID_BOOL);
    assert_running(&e, MONOFF);

    let mut e = started(100, 100, 0, 1, 0);
    assert_eq!(at(&mut e, 1000, 1, 5), SL_E_INVALID_BOOL);
    assert_eq!(at(&mut e, 1099, 1, 5), SL_E_INVALID_BOOL);
    assert_running(&e, MONON);
    assert_eq!(at(&mut e, 1100, 1, 5), SL_E_INVALID_BOOL);
    assert_error(&e, ON);
    let mut e = started(100, 100, 1, 0, 0);
    at(&mut e, 1000, 0, 0x10);
    at(&mut e, 1100, 0, 0x10);
    assert_error(&e, OFF);
    // Invalid Run / ErrAck bytes.
    let mut e = started(100, 100, 0, 1, 0);
    e.bErrAck = 2;
    assert_eq!(at(&mut e, 1, 0, 1), SL_E_INVALID_BOOL);
    e.bErrAck = 0;
    e.bRun = 2;
    assert_eq!(at(&mut e, 2, 0, 1), SL_E_INVALID_BOOL);
    assert_running(&e, SL_STATE_STOP);
}

/// "The error state can only be exited again by means of an acknowledgement via the
/// ERR_ACK input"; RESET "if no further error is pending" (E5, C8, C9).
#[test]
fn acknowledgement() {
    let mut e = started(100, 100, 0, 1, 0);
    at(&mut e, 1000, 1, 1);
    at(&mut e, 1100, 1, 1);
    assert_error(&e, ON);
    // Mon2 still wrong: the rising edge is consumed.
    e.bErrAck = 1;
    at(&mut e, 1200, 1, 1);
    assert_error(&e, ON);
    // Fixed, but ErrAck still held from before: no new edge, no acknowledgement.
    at(&mut e, 1210, 1, 0);
    assert_error(&e, ON);
    e.bErrAck = 0;
    at(&mut e, 1220, 1, 0);
    assert_error(&e, ON);
    e.bErrAck = 1;
    at(&mut e, 1230, 1, 0);
    assert_eq!((e.nState, e.bError, e.nDiag), (SL_STATE_RESET, 0, 0));
    at(&mut e, 5000, 1, 0);
    assert_eq!(e.nState, SL_STATE_RESET, "RESET until ErrAck falls");
    e.bErrAck = 0;
    at(&mut e, 5001, 1, 0);
    assert_running(&e, MONON);
    at(&mut e, 9000, 1, 0);
    assert_running(&e, MONON);

    // Switching Mon1 off with Mon2 TRUE also clears the condition.
    let mut e = started(100, 100, 0, 1, 0);
    at(&mut e, 1000, 1, 1);
    at(&mut e, 1100, 1, 1);
    at(&mut e, 1110, 0, 1);
    e.bErrAck = 1;
    at(&mut e, 1120, 0, 1);
    assert_eq!(e.nState, SL_STATE_RESET);
    e.bErrAck = 0;
    at(&mut e, 1130, 0, 1);
    assert_running(&e, MONOFF);

    // Mon1 off, Mon2 stuck FALSE: pending with switch-off monitoring on ...
    let mut e = started(100, 100, 0, 1, 0);
    at(&mut e, 1000, 1, 1);
    at(&mut e, 1100, 1, 1);
    e.bErrAck = 1;
    at(&mut e, 1110, 0, 0);
    assert_error(&e, ON);
    // ... and an invalid Mon2 is never "no further error".
    e.bErrAck = 0;
    at(&mut e, 1120, 1, 3);
    e.bErrAck = 1;
    at(&mut e, 1130, 1, 3);
    assert_error(&e, ON);
    // ... not pending without switch-off monitoring.
    let mut e = started(100, 0, 0, 1, 0);
    at(&mut e, 1000, 1, 1);
    at(&mut e, 1100, 1, 1);
    e.bErrAck = 1;
    at(&mut e, 1110, 0, 0);
    assert_eq!(e.nState, SL_STATE_RESET);
    e.bErrAck = 0;
    at(&mut e, 1120, 0, 0);
    assert_running(&e, MONOFF);
}

/// ABI §7 Run: ERROR persists with Run FALSE; RESET is left to STOP when Run is FALSE.
#[test]
fn error_with_run_false() {
    let mut e = started(100, 100, 1, 0, 0);
    at(&mut e, 1000, 0, 0);
    at(&mut e, 1100, 0, 0);
    assert_error(&e, OFF);
    e.bRun = 0;
    at(&mut e, 1200, 0, 1);
    assert_error(&e, OFF);
    e.bErrAck = 1;
    at(&mut e, 1210, 0, 1);
    assert_eq!((e.nState, e.bError), (SL_STATE_RESET, 0));
    e.bErrAck = 0;
    at(&mut e, 1220, 0, 1);
    assert_running(&e, SL_STATE_STOP);
}

/// E8: Run FALSE ends a running monitoring without error; the next start monitors anew.
#[test]
fn run_false_stops_monitoring() {
    let mut e = started(100, 100, 0, 1, 0);
    at(&mut e, 1000, 1, 1);
    e.bRun = 0;
    at(&mut e, 1050, 1, 1);
    assert_running(&e, SL_STATE_STOP);
    at(&mut e, 5000, 1, 1);
    assert_running(&e, SL_STATE_STOP);
    e.bRun = 1;
    at(&mut e, 6000, 1, 1);
    assert_running(&e, MONON);
    at(&mut e, 6099, 1, 1);
    assert_running(&e, MONON);
    at(&mut e, 6100, 1, 1);
    assert_error(&e, ON);
}

/// C5: a parameter changed while running → ERROR with Error=1 and diag bit 13.
#[test]
fn parameter_change_while_running() {
    let mut e = started(100, 100, 0, 1, 0);
    e.tSwitchOffTime = 200;
    assert_eq!(at(&mut e, 10, 0, 1), SL_E_PARAM_CHANGED);
    assert_error(&e, SL_DIAG_PARAM_CHANGED);
    e.bErrAck = 1;
    assert_eq!(at(&mut e, 20, 0, 1), SL_E_PARAM_CHANGED);
    assert_error(&e, SL_DIAG_PARAM_CHANGED);
    e.tSwitchOffTime = 100;
    e.bErrAck = 0;
    assert_eq!(at(&mut e, 30, 0, 1), SL_OK);
    e.bErrAck = 1;
    at(&mut e, 40, 0, 1);
    assert_eq!(e.nState, SL_STATE_RESET);
    e.bErrAck = 0;
    at(&mut e, 50, 0, 1);
    assert_running(&e, MONOFF);
    // An invalid value set while running is a change as well.
    e.tSwitchOnTime = 20_000;
    assert_eq!(at(&mut e, 60, 0, 1), SL_E_PARAM_CHANGED);
    assert_error(&e, SL_DIAG_PARAM_CHANGED);
    // With Run FALSE the change is still reported (not in STOP: ABI §5, §7), but it no
    // longer blocks the acknowledgement: acknowledged to STOP, then latched at the next
    // start, and rejected there (C5, C6).
    e.bRun = 0;
    assert_eq!(at(&mut e, 70, 0, 1), SL_E_PARAM_CHANGED);
    assert_error(&e, SL_DIAG_PARAM_CHANGED);
    e.bErrAck = 1;
    at(&mut e, 80, 0, 1);
    assert_eq!(e.nState, SL_STATE_RESET);
    e.bErrAck = 0;
    at(&mut e, 90, 0, 1);
    assert_running(&e, SL_STATE_STOP);
    e.bRun = 1;
    assert_eq!(at(&mut e, 100, 0, 1), SL_E_CONFIG);
    assert_running(&e, SL_STATE_STOP);
}

/// C4: the clock going backwards → ERROR, Error=1, diag bit 14; it does not remain, and
/// the restarted monitoring (E3) still finds a real fault.
#[test]
fn clock_backwards() {
    let mut e = started(100, 100, 1, 1, 1000);
    assert_eq!(at(&mut e, 999, 1, 1), SL_E_CLOCK);
    assert_error(&e, SL_DIAG_CLOCK);
    e.bErrAck = 1;
    at(&mut e, 1000, 1, 1);
    assert_eq!(e.nState, SL_STATE_RESET);
    e.bErrAck = 0;
    at(&mut e, 1001, 1, 1);
    assert_running(&e, MONON);
    at(&mut e, 1101, 1, 1);
    assert_error(&e, ON);
    // Across the 2^32 wrap: no clock error, timers keep working.
    let mut e = started(100, 100, 0, 1, u32::MAX - 49);
    at(&mut e, u32::MAX - 10, 1, 1);
    at(&mut e, 88, 1, 1);
    assert_running(&e, MONON);
    assert_eq!(at(&mut e, 89, 1, 1), SL_OK);
    assert_error(&e, ON);
}

#[test]
fn corruption() {
    let mut e = started(100, 100, 0, 1, 0);
    let h = &mut e.stPrivate.stHeader;
    h.nState = SL_STATE_RUN;
    h.dwCtrlCheck =
        !(u32::from(h.nState) | (u32::from(h.nFlags) << 8) | (u32::from(h.wDiag) << 16));
    assert_eq!(at(&mut e, 1, 0, 1), SL_E_CORRUPT);
    assert_eq!((e.nState, e.bError), (SL_STATE_ERROR, 1));
    assert_eq!(e.nDiag & SL_DIAG_CORRUPT, SL_DIAG_CORRUPT);
    let mut e = started(100, 100, 0, 1, 0);
    e.stPrivate.stHeader.wAuxCheck ^= 4;
    assert_eq!(at(&mut e, 1, 0, 1), SL_E_CORRUPT);
    assert_eq!((e.nState, e.bError), (SL_STATE_ERROR, 1));
}

#[test]
fn c_functions_names_diag_text() {
    null_refused!(ffi::sl_edm_init, ffi::sl_edm_cycle);
    let mut e = FB_EDM {
        tSwitchOnTime: 50,
        wInputActive: BOTH,
        bMon1: 1,
        bMon2: 1,
        bRun: 1,
        ..Default::default()
    };
    assert_eq!(unsafe { ffi::sl_edm_init(&mut e) }, SL_OK);
    assert_eq!(unsafe { ffi::sl_edm_cycle(&mut e, 0) }, SL_OK);
    assert_eq!(unsafe { ffi::sl_edm_cycle(&mut e, 50) }, SL_OK);
    assert_error(&e, ON);
    assert_eq!(state_name(SL_TYPE_EDM, SL_STATE_STOP), "STOP");
    assert_eq!(state_name(SL_TYPE_EDM, SL_STATE_ERROR), "ERROR");
    assert_eq!(state_name(SL_TYPE_EDM, SL_STATE_RESET), "RESET");
    assert_eq!(state_name(SL_TYPE_EDM, MONOFF), "MONOFF");
    assert_eq!(state_name(SL_TYPE_EDM, MONON), "MONON");
    assert_eq!(state_name(SL_TYPE_EDM, SL_STATE_RUN), "?");
    assert_eq!(
        common::diag_text(SL_TYPE_EDM, OFF | ON),
        "Switch-OFF timer elapsed; Switch-ON timer elapsed"
    );
}

/// "transmits the corresponding diag message to the GROUP module": an EDM error stops the
/// group (FBERROR). An AND drives Mon1 through a link; Mon2 is the device feedback.
#[test]
fn in_a_group() {
    let mut a = common::ready(FB_AND {
        wInputActive: 0b11,
        ..Default::default()
    });
    let mut e = edm(100, 100, 0);
    e.bMon2 = 1;
    let mut g = SL_GROUP::default();
    let mut members = [SL_MEMBER::default(); 2];
    let mut links = [SL_LINK::default(); 1];
    common::c_group_init(&mut g, (members.as_mut_ptr(), 2), (links.as_mut_ptr(), 1));
    let null = std::ptr::null_mut();
    let tm = members.as_mut_ptr();
    common::c_add_member(
        &mut g,
        tm,
        SL_TYPE_AND,
        std::ptr::addr_of_mut!(a).cast(),
        null,
    );
    let tm = members.as_mut_ptr();
    common::c_add_member(
        &mut g,
        tm,
        SL_TYPE_EDM,
        std::ptr::addr_of_mut!(e).cast(),
        null,
    );
    let (src, dst) = (offset_of!(FB_AND, bAndOut), offset_of!(FB_EDM, bMon1));
    common::c_add_link(&mut g, &mut members, &mut links, (0, src), (1, dst));
    g.bRun = 1;
    c_group_cycle!(g, members, links, 0; a, e);
    assert_running(&e, MONOFF);
    a.bAndIn1 = 1;
    a.bAndIn2 = 1;
    c_group_cycle!(g, members, links, 10; a, e);
    assert_running(&e, MONON);
    e.bMon2 = 0;
    c_group_cycle!(g, members, links, 50; a, e);
    a.bAndIn2 = 0;
    c_group_cycle!(g, members, links, 60; a, e);
    assert_running(&e, MONOFF);
    // The device does not release.
    c_group_cycle!(g, members, links, 159; a, e);
    assert_eq!(g.nState, SL_STATE_RUN);
    c_group_cycle!(g, members, links, 160; a, e);
    assert_error(&e, OFF);
    assert_eq!(
        (g.nState, g.nDiag, g.nFailedMember),
        (SL_STATE_ERROR, SL_GROUP_DIAG_FBERROR, 1)
    );
    assert_eq!(a.nState, SL_STATE_STOP, "the other member is stopped");

    let m: &mut dyn Member = &mut e;
    assert!(m.input_mut(offset_of!(FB_EDM, bMon2) as u16).is_some());
    assert!(m.output(offset_of!(FB_EDM, bError) as u16).is_some());
    let _ = group::SL_LINK_BOOL;
}

/// The reference model of E2–E4 for one run without acknowledgement: the expected state,
/// or the expected error diag.
struct Model {
    on: u32,
    off: u32,
    /// (Mon1 level, start of the monitoring, still waiting) while running.
    run: Option<(bool, u32, bool)>,
}

impl Model {
    fn time(&self, level: bool) -> u32 {
        if level {
            self.on
        } else {
            self.off
        }
    }

    /// One call with Run TRUE: Ok(state) or Err(diag).
    fn call(&mut self, mon1: bool, mon2: Option<bool>, now: u32) -> Result<u8, u16> {
        let (level, t0, waiting) = match self.run {
            Some((level, t0, waiting)) if level == mon1 => (level, t0, waiting),
            // Start-up or a switch of Mon1.
            _ => (mon1, now, self.time(mon1) != 0),
        };
        let mut waiting = waiting;
        if waiting {
            if mon2 == Some(!mon1) {
                waiting = false;
            } else if now.wrapping_sub(t0) >= self.time(level) {
                return Err(if level { ON } else { OFF });
            }
        }
        self.run = Some((level, t0, waiting));
        Ok(if level { MONON } else { MONOFF })
    }
}

fn logical(raw: u8, negated: bool) -> Option<bool> {
    (raw <= 1).then_some((raw == 1) != negated)
}

common::property! {
    cases: common::depth_cases(10_000), reach: [MONOFF, MONON, SL_STATE_ERROR];
    /// The block against the model of the manual's description (E2–E4, E7), call by call:
    /// the state follows Mon1 in the same call, the error comes exactly when the model says.
    fn matches_the_reference_model(
        on in prop_oneof![Just(0u32), 1u32..300, Just(10_000u32)],
        off in prop_oneof![Just(0u32), 1u32..300, Just(10_000u32)],
        negated in 0u16..=3,
        t0 in any::<u32>(),
        steps in proptest::collection::vec((0u8..3, 0u8..3, 0u32..200), 1..80)
    ) {
        prop_assume!(on != 0 || off != 0);
        let mut e = edm(on, off, negated);
        e.bRun = 1;
        let mut model = Model { on, off, run: None };
        let mut t = t0;
        for (m1, m2, dt) in steps {
            t = t.wrapping_add(dt);
            let rc = at(&mut e, t, m1, m2);
            common::saw(e.nState);
            prop_assert_eq!(rc == SL_E_INVALID_BOOL, m1 > 1 || m2 > 1);
            let mon1 = logical(m1, negated & MON1 != 0).unwrap_or(false);
            let mon2 = logical(m2, negated & MON2 != 0);
            match model.call(mon1, mon2, t) {
                Ok(state) => {
                    prop_assert_eq!((e.nState, e.bError, e.nDiag), (state, 0, 0));
                }
                Err(diag) => {
                    prop_assert_eq!((e.nState, e.bError, e.nDiag), (SL_STATE_ERROR, 1, diag));
                    break;
                }
            }
        }
    }
}

common::property! {
    cases: common::depth_cases(10_000), reach: [SL_STATE_STOP, SL_STATE_ERROR, SL_STATE_RESET, MONOFF, MONON];
    /// Error=1 exactly in ERROR; diag only in ERROR; only the manual's states; a Mon2 that
    /// always follows Mon1 inverted never gives an error, whatever Run, ErrAck and timing.
    fn error_output_and_states(
        on in 0u32..300,
        off in 1u32..300,
        steps in proptest::collection::vec((0u8..4, 0u8..3, 0u8..4, 0u8..3, 0u32..400), 1..100)
    ) {
        let mut e = edm(on, off, 0);
        let mut t = 0u32;
        let mut follower_ok = true;
        for (run, ack, m1, m2, dt) in steps {
            e.bRun = u8::from(run != 0);
            e.bErrAck = u8::from(ack == 1);
            t = t.wrapping_add(dt);
            // m2 == 0: a healthy device (Mon2 = NOT Mon1); otherwise anything.
            let mon1 = m1 & 1;
            let mon2 = if m2 == 0 { 1 - mon1 } else { m2 - 1 };
            follower_ok &= m2 == 0;
            at(&mut e, t, mon1, mon2);
            common::saw(e.nState);
            prop_assert!([SL_STATE_STOP, SL_STATE_ERROR, SL_STATE_RESET, MONOFF, MONON].contains(&e.nState));
            prop_assert_eq!(e.bError, u8::from(e.nState == SL_STATE_ERROR));
            if e.nState != SL_STATE_ERROR {
                prop_assert_eq!(e.nDiag, 0);
            } else {
                prop_assert!(e.nDiag & (ON | OFF) != 0 && e.nDiag & !(ON | OFF) == 0);
            }
            if matches!(e.nState, MONON | MONOFF) {
                prop_assert_eq!(e.nState == MONON, mon1 == 1, "state follows Mon1 in the same call");
            }
            if follower_ok {
                prop_assert_ne!(e.nState, SL_STATE_ERROR);
            }
        }
    }
}
