//! FB RS (manual §4.10; ABI §9; docs/semantics.md R1–R7, C1–C12): layout, the four input
//! combinations with Reset dominant, memory, start-up, negation, inactive inputs, invalid
//! BOOLs, configuration errors, library errors through the envelope, the C functions,
//! group membership, and property tests.

mod common;

use proptest::prelude::*;
use safelogic::base::member::Member;
use safelogic::ffi;
use safelogic::*;
use std::mem::{offset_of, size_of};

#[macro_use]
#[path = "common/flipflop.rs"]
mod flipflop;

use common::state_name;

const RESET: u16 = 1 << 0;
const SET: u16 = 1 << 1;

fn rs(active: u16, negated: u16) -> FB_RS {
    common::ready(FB_RS {
        wInputActive: active,
        wInputNegated: negated,
        ..Default::default()
    })
}

/// A running RS with both inputs active (break contacts).
fn running() -> (FB_RS, u32) {
    let mut b = rs(RESET | SET, 0);
    b.bRun = 1;
    assert_eq!(b.cycle(0), SL_OK);
    assert_eq!(b.nState, SL_STATE_SAFE);
    (b, 1)
}

fn step(b: &mut FB_RS, t: &mut u32, reset: u8, set: u8) -> i32 {
    b.bReset = reset;
    b.bSet = set;
    *t += 10;
    b.cycle(*t)
}

/// One call of a step table: (Run, Reset, Set) written, the call at `t`, its status with
/// (state, output).
fn io(b: &mut FB_RS, [run, reset, set]: [u8; 3], t: u32) -> (i32, u8, u8) {
    (b.bRun, b.bReset, b.bSet) = (run, reset, set);
    let rc = b.cycle(t);
    (rc, b.nState, b.bRsOut)
}

/// Manual §4.10.1, every statement, in the same call (R5).
#[test]
fn manual_statements() {
    let (mut b, mut t) = running();
    // "Logic 1 at input Set and logic 0 at input Reset leads to logic 1 at the output."
    #[rustfmt::skip]
    flipflop::walk(&mut b, &mut t, io, &[
        (1, 0, 1, SL_OK, Some(SL_STATE_RS_SET), Some(1), ""),
        // "If both inputs are logic 0, the output remains in its current state." (1)
        (1, 0, 0, SL_OK, Some(SL_STATE_RS_SET), Some(1), ""),
        // "Logic 0 at input Set and logic 1 at input Reset leads to logic 0 at the output."
        (1, 1, 0, SL_OK, Some(SL_STATE_SAFE), Some(0), ""),
        // ... remains (0).
        (1, 0, 0, SL_OK, Some(SL_STATE_SAFE), Some(0), ""),
        // "If both inputs are set to logic 1, the Reset signal is dominant and leads to logic 0."
        (1, 1, 1, SL_OK, Some(SL_STATE_SAFE), Some(0), ""),
        (1, 0, 1, SL_OK, None, Some(1), ""),
        (1, 1, 1, SL_OK, Some(SL_STATE_SAFE), Some(0), "from SET as well"),
        // Releasing Reset while Set stays TRUE sets again (level, not edge).
        (1, 0, 1, SL_OK, Some(SL_STATE_RS_SET), Some(1), ""),
    ]);
    assert_eq!(b.nDiag, 0, "diag always 0");
}

/// STOP: "If the input FbRun=FALSE ... RsOut=0"; the memory does not survive STOP (R4).
#[test]
fn stop_and_start_up() {
    let (mut b, mut t) = running();
    #[rustfmt::skip]
    flipflop::walk(&mut b, &mut t, io, &[
        (1, 0, 1, SL_OK, None, Some(1), ""),
        (0, 0, 0, SL_OK, Some(SL_STATE_STOP), Some(0), ""),
        (1, 0, 0, SL_OK, Some(SL_STATE_SAFE), Some(0), "starts FALSE"),
        // Set held through a start-up sets in the call Run rises.
        (0, 0, 1, SL_OK, None, Some(0), ""),
        (1, 0, 1, SL_OK, Some(SL_STATE_RS_SET), Some(1), ""),
        // Both TRUE at start-up: Reset dominates.
        (0, 1, 1, SL_OK, None, None, ""),
        (1, 1, 1, SL_OK, Some(SL_STATE_SAFE), Some(0), ""),
    ]);
}

/// Negation bits: a make contact is negated before evaluation.
#[test]
fn negated_inputs() {
    let mut b = rs(RESET | SET, RESET | SET);
    b.bRun = 1;
    let mut t = 0;
    // raw Reset 1 = logical 0, raw Set 0 = logical 1 → SET
    #[rustfmt::skip]
    flipflop::walk(&mut b, &mut t, io, &[
        (1, 1, 0, SL_OK, None, Some(1), ""),
        (1, 1, 1, SL_OK, None, Some(1), "both logical 0: remains"),
        (1, 0, 1, SL_OK, None, Some(0), "logical Reset 1"),
    ]);
    let mut b = rs(RESET | SET, RESET);
    b.bRun = 1;
    step(&mut b, &mut t, 1, 1);
    assert_eq!(b.bRsOut, 1, "only Reset negated");
    step(&mut b, &mut t, 0, 1);
    assert_eq!(b.bRsOut, 0, "Reset dominant");
}

/// R3: invalid Reset reads TRUE (reset), invalid Set reads FALSE (no set).
#[test]
fn invalid_bools() {
    let (mut b, mut t) = running();
    #[rustfmt::skip]
    flipflop::walk(&mut b, &mut t, io, &[
        (1, 0, 1, SL_OK, None, Some(1), ""),
        (1, 2, 1, SL_E_INVALID_BOOL, Some(SL_STATE_SAFE), Some(0), ""),
        (1, 0, 0x7F, SL_E_INVALID_BOOL, None, Some(0), "invalid Set does not set"),
        (1, 0, 1, SL_OK, None, Some(1), ""),
        (1, 0, 0xFF, SL_E_INVALID_BOOL, None, None, ""),
    ]);
    assert_eq!(
        b.bRsOut, 1,
        "invalid Set reads FALSE: both FALSE keeps the state"
    );
    // Whatever the negation: an invalid negated Reset still resets.
    let mut b = rs(RESET | SET, RESET | SET);
    #[rustfmt::skip]
    flipflop::walk(&mut b, &mut t, io, &[
        (1, 1, 0, SL_OK, None, Some(1), ""),
        (1, 3, 0, SL_E_INVALID_BOOL, None, Some(0), ""),
        (1, 1, 3, SL_E_INVALID_BOOL, None, Some(0), "invalid negated Set does not set"),
    ]);
}

flipflop_shared_tests!(
    FB_RS,
    bRsOut,
    SL_TYPE_RS,
    SL_STATE_RS_SET,
    sl_rs_init,
    sl_rs_cycle,
    rs
);

common::property! {
    cases: common::depth_cases(10_000), reach: [SL_STATE_RS_SET, SL_STATE_SAFE, SL_STATE_STOP];
    /// Reference model from manual §4.10.1 and R2–R4: the output is TRUE only in SET; in the
    /// running states it follows the inputs in the same call with Reset dominant.
    fn follows_the_manual_model(
        active in 1u16..=3,
        negated in 0u16..=3,
        steps in proptest::collection::vec((0u8..4, 0u8..3, 0u8..3, 0u8..3, 0u32..20, 0u8..30), 1..80)
    ) {
        let mut b = rs(active, negated);
        let mut t = 0u32;
        let mut model_set = false;
        for (run, ack, reset, set, dt, mode) in steps {
            b.bRun = u8::from(run != 0);
            b.bErrAck = u8::from(ack == 1);
            b.bReset = reset;
            b.bSet = set;
            t = if mode == 0 { t.wrapping_sub(1) } else { t.wrapping_add(dt) };
            let before = b.nState;
            b.cycle(t);
            common::saw(b.nState);
            prop_assert!([SL_STATE_STOP, SL_STATE_SAFE, SL_STATE_RS_SET, SL_STATE_ERROR, SL_STATE_RESET].contains(&b.nState));
            prop_assert_eq!(b.bRsOut, u8::from(b.nState == SL_STATE_RS_SET));
            if matches!(b.nState, SL_STATE_SAFE | SL_STATE_RS_SET) {
                // Logical values: inactive → FALSE; invalid Reset → TRUE; invalid Set → FALSE.
                let logical = |raw: u8, bit: u16, invalid_reads: bool| {
                    if active & bit == 0 { false }
                    else if raw > 1 { invalid_reads }
                    else { (raw == 1) != (negated & bit != 0) }
                };
                let r = logical(reset, RESET, true);
                let s = logical(set, SET, false);
                let was_set = before == SL_STATE_RS_SET && model_set;
                model_set = if r { false } else if s { true } else { was_set };
                prop_assert_eq!(b.nState == SL_STATE_RS_SET, model_set);
            } else {
                model_set = false;
            }
        }
    }
}
