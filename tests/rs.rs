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

flipflop_fixtures!(FB_RS, bRsOut, rs);

/// Manual §4.10.1, every statement, in the same call (R5).
#[test]
fn manual_statements() {
    #[rustfmt::skip]
    let b = walk_running(&flipflop::set_and_reset_rows(SL_STATE_RS_SET), &[
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
    #[rustfmt::skip]
    walk_running(&flipflop::stop_and_start_rows(SL_STATE_RS_SET), &[
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
    flipflop::walk(&mut b, &mut t, io, &flipflop::BOTH_NEGATED_ROWS);
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

flipflop_model!(bRsOut, SL_STATE_RS_SET, rs, false);
