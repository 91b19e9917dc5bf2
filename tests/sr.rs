//! FB SR (manual §4.11; ABI §9; docs/semantics.md R1–R7, C1–C12): layout, the four input
//! combinations with Set dominant, memory, start-up, negation, inactive inputs, invalid
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

fn sr(active: u16, negated: u16) -> FB_SR {
    common::ready(FB_SR {
        wInputActive: active,
        wInputNegated: negated,
        ..Default::default()
    })
}

/// A running RS with both inputs active (break contacts).
fn running() -> (FB_SR, u32) {
    let mut b = sr(RESET | SET, 0);
    b.bRun = 1;
    assert_eq!(b.cycle(0), SL_OK);
    assert_eq!(b.nState, SL_STATE_SAFE);
    (b, 1)
}

fn step(b: &mut FB_SR, t: &mut u32, reset: u8, set: u8) -> i32 {
    b.bReset = reset;
    b.bSet = set;
    *t += 10;
    b.cycle(*t)
}

/// One call of a step table: (Run, Reset, Set) written, the call at `t`, its status with
/// (state, output).
fn io(b: &mut FB_SR, [run, reset, set]: [u8; 3], t: u32) -> (i32, u8, u8) {
    (b.bRun, b.bReset, b.bSet) = (run, reset, set);
    let rc = b.cycle(t);
    (rc, b.nState, b.bSrOut)
}

/// Manual §4.11.1, every statement, in the same call (R5).
#[test]
fn manual_statements() {
    let (mut b, mut t) = running();
    // "Logic 1 at input Set and logic 0 at input Reset leads to logic 1 at the output."
    #[rustfmt::skip]
    flipflop::walk(&mut b, &mut t, io, &[
        (1, 0, 1, SL_OK, Some(SL_STATE_SR_SET), Some(1), ""),
        // "If both inputs are logic 0, the output remains in its current state." (1)
        (1, 0, 0, SL_OK, Some(SL_STATE_SR_SET), Some(1), ""),
        // "Logic 0 at input Set and logic 1 at input Reset leads to logic 0 at the output."
        (1, 1, 0, SL_OK, Some(SL_STATE_SAFE), Some(0), ""),
        // ... remains (0).
        (1, 0, 0, SL_OK, Some(SL_STATE_SAFE), Some(0), ""),
        // "If both inputs are set to logic 1, the Set signal is dominant and leads to logic 1."
        (1, 1, 1, SL_OK, Some(SL_STATE_SR_SET), Some(1), "from SAFE"),
        (1, 1, 0, SL_OK, None, Some(0), ""),
        (1, 0, 1, SL_OK, None, None, ""),
        (1, 1, 1, SL_OK, Some(SL_STATE_SR_SET), Some(1), "from SET"),
        // SAFE: "If the Reset input is 1 and the Set input is 0": releasing Set while Reset
        // stays TRUE resets (level, not edge).
        (1, 1, 0, SL_OK, Some(SL_STATE_SAFE), Some(0), ""),
    ]);
    assert_eq!(b.nDiag, 0, "diag always 0");
}

/// STOP: "If the input FbRun=FALSE ... SrOut=0"; the memory does not survive STOP (R4).
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
        (1, 0, 1, SL_OK, Some(SL_STATE_SR_SET), Some(1), ""),
        // Both TRUE at start-up: Set dominates.
        (0, 1, 1, SL_OK, Some(SL_STATE_STOP), Some(0), ""),
        (1, 1, 1, SL_OK, Some(SL_STATE_SR_SET), Some(1), ""),
        // Reset alone at start-up.
        (0, 1, 0, SL_OK, None, None, ""),
        (1, 1, 0, SL_OK, Some(SL_STATE_SAFE), Some(0), ""),
    ]);
}

/// Negation bits: a make contact is negated before evaluation.
#[test]
fn negated_inputs() {
    let mut b = sr(RESET | SET, RESET | SET);
    b.bRun = 1;
    let mut t = 0;
    // raw Reset 1 = logical 0, raw Set 0 = logical 1 → SET
    #[rustfmt::skip]
    flipflop::walk(&mut b, &mut t, io, &[
        (1, 1, 0, SL_OK, None, Some(1), ""),
        (1, 1, 1, SL_OK, None, Some(1), "both logical 0: remains"),
        (1, 0, 1, SL_OK, None, Some(0), "logical Reset 1"),
    ]);
    let mut b = sr(RESET | SET, RESET);
    #[rustfmt::skip]
    flipflop::walk(&mut b, &mut t, io, &[
        (1, 1, 1, SL_OK, None, Some(1), "only Reset negated"),
        (1, 0, 1, SL_OK, None, Some(1), "both logical 1: Set dominant"),
        (1, 0, 0, SL_OK, None, Some(0), "logical Reset 1, Set 0"),
    ]);
}

/// R3: invalid Reset reads TRUE (reset), invalid Set reads FALSE (no set); Set dominates.
#[test]
fn invalid_bools() {
    let (mut b, mut t) = running();
    step(&mut b, &mut t, 0, 1);
    assert_eq!(b.bSrOut, 1);
    assert_eq!(step(&mut b, &mut t, 2, 1), SL_E_INVALID_BOOL);
    assert_eq!(
        (b.nState, b.bSrOut),
        (SL_STATE_SR_SET, 1),
        "Set TRUE dominates any Reset value"
    );
    assert_eq!(step(&mut b, &mut t, 2, 0), SL_E_INVALID_BOOL);
    assert_eq!(
        (b.nState, b.bSrOut),
        (SL_STATE_SAFE, 0),
        "invalid Reset resets"
    );
    #[rustfmt::skip]
    flipflop::walk(&mut b, &mut t, io, &[
        (1, 0, 0x7F, SL_E_INVALID_BOOL, None, Some(0), "invalid Set does not set"),
        (1, 2, 0x7F, SL_E_INVALID_BOOL, None, Some(0), ""),
        (1, 0, 1, SL_OK, None, Some(1), ""),
        (1, 0, 0xFF, SL_E_INVALID_BOOL, None, None, ""),
    ]);
    assert_eq!(
        b.bSrOut, 1,
        "invalid Set reads FALSE: both FALSE keeps the state"
    );
    // Whatever the negation bits.
    let mut b = sr(RESET | SET, RESET | SET);
    #[rustfmt::skip]
    flipflop::walk(&mut b, &mut t, io, &[
        (1, 1, 0, SL_OK, None, Some(1), ""),
        (1, 3, 0, SL_E_INVALID_BOOL, None, Some(1), "logical Set 1 dominates the invalid Reset"),
        (1, 3, 1, SL_E_INVALID_BOOL, None, Some(0), "invalid negated Reset resets"),
        (1, 1, 3, SL_E_INVALID_BOOL, None, Some(0), "invalid negated Set does not set"),
    ]);
}

flipflop_shared_tests!(
    FB_SR,
    bSrOut,
    SL_TYPE_SR,
    SL_STATE_SR_SET,
    sl_sr_init,
    sl_sr_cycle,
    sr
);

common::property! {
    cases: common::depth_cases(10_000), reach: [SL_STATE_SR_SET, SL_STATE_SAFE, SL_STATE_STOP];
    /// Reference model from manual §4.11.1 and R2–R4: the output is TRUE only in SET; in the
    /// running states it follows the inputs in the same call with Set dominant.
    fn follows_the_manual_model(
        active in 1u16..=3,
        negated in 0u16..=3,
        steps in proptest::collection::vec((0u8..4, 0u8..3, 0u8..3, 0u8..3, 0u32..20, 0u8..30), 1..80)
    ) {
        let mut b = sr(active, negated);
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
            prop_assert!([SL_STATE_STOP, SL_STATE_SAFE, SL_STATE_SR_SET, SL_STATE_ERROR, SL_STATE_RESET].contains(&b.nState));
            prop_assert_eq!(b.bSrOut, u8::from(b.nState == SL_STATE_SR_SET));
            if matches!(b.nState, SL_STATE_SAFE | SL_STATE_SR_SET) {
                // Logical values: inactive → FALSE; invalid Reset → TRUE; invalid Set → FALSE.
                let logical = |raw: u8, bit: u16, invalid_reads: bool| {
                    if active & bit == 0 { false }
                    else if raw > 1 { invalid_reads }
                    else { (raw == 1) != (negated & bit != 0) }
                };
                let r = logical(reset, RESET, true);
                let s = logical(set, SET, false);
                let was_set = before == SL_STATE_SR_SET && model_set;
                model_set = if s { true } else if r { false } else { was_set };
                prop_assert_eq!(b.nState == SL_STATE_SR_SET, model_set);
            } else {
                model_set = false;
            }
        }
    }
}

common::property! {
    cases: common::depth_cases(10_000), reach: [SL_STATE_SR_SET, SL_STATE_SAFE];
    /// RS and SR differ only in the dominant input (R5): fed the same inputs, never both TRUE
    /// at once, they show the same state and output in every call.
    fn sr_equals_rs_unless_both_inputs_are_true(
        steps in proptest::collection::vec((0u8..4, 0u8..3, 0u8..3, 0u32..20), 1..80)
    ) {
        let mut s = sr(RESET | SET, 0);
        let mut r = FB_RS { wInputActive: RESET | SET, ..Default::default() };
        prop_assert_eq!(r.init(), SL_OK);
        let mut t = 0u32;
        for (run, ack, inputs, dt) in steps {
            let (reset, set) = [(0, 0), (1, 0), (0, 1)][usize::from(inputs)];
            s.bRun = u8::from(run != 0);
            s.bErrAck = u8::from(ack == 1);
            s.bReset = reset;
            s.bSet = set;
            r.bRun = s.bRun;
            r.bErrAck = s.bErrAck;
            r.bReset = reset;
            r.bSet = set;
            t = t.wrapping_add(dt);
            prop_assert_eq!(s.cycle(t), r.cycle(t));
            common::saw(s.nState);
            prop_assert_eq!((s.nState, s.bSrOut), (r.nState, r.bRsOut));
        }
    }
}
