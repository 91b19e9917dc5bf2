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

flipflop_fixtures!(FB_SR, bSrOut, sr);

/// Manual §4.11.1, every statement, in the same call (R5).
#[test]
fn manual_statements() {
    #[rustfmt::skip]
    let b = walk_running(&flipflop::set_and_reset_rows(SL_STATE_SR_SET), &[
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
    #[rustfmt::skip]
    walk_running(&flipflop::stop_and_start_rows(SL_STATE_SR_SET), &[
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
    flipflop::walk(&mut b, &mut t, io, &flipflop::BOTH_NEGATED_ROWS);
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

flipflop_model!(bSrOut, SL_STATE_SR_SET, sr, true);

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
