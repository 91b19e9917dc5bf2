//! FB SLI2 — manual §4.28 (and §4.27 for everything it does not restate); layout ABI-2
//! §11.10, rules ABI-2 §12.
//!
//! FB SLI with two more outputs and two options. BelowMin / AboveMax show, in EXCEEDED only,
//! on which side the position left the window. `SL_OPT_SLI2_EXCEEDED_SUPPORT`: leaving the
//! window in RUN enters EXCEEDED (7: Error 0, SLIActive 0, PositionDiff = Position −
//! LatchPosition saturated to the output type) instead of ERROR; EXCEEDED is left only by
//! SLI FALSE (→ SAFE). `SL_OPT_SLI2_OVERFLOW_ALLOWED`: PositionDiff is the difference
//! modulo 2^W in the signed range (a wrap of the position counter is a short move);
//! without it the exact difference. Diag values and messages as FB SLI (0x40C0 / 0x40C1).
//! States RUN (1), STOP (2), SAFE (3), ERROR (4), RESET (5), EXCEEDED (7). Readings:
//! docs/semantics.md SI1–SI8. The state machine is shared with FB SLI (`window`).

#![allow(non_camel_case_types)] // the ABI's names (FB_SLI2_INT …)

use super::window::SL_SLI_PRIVATE;
pub use super::window::{
    SL_OPT_SLI2_EXCEEDED_SUPPORT, SL_OPT_SLI2_OVERFLOW_ALLOWED, SL_STATE_SLI2_EXCEEDED,
};
use super::Analog;
use crate::base::types::*;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/analog/sli2.rs"));

// The ABI-2 §11.10 numbers (identical for both widths).
const _: () = {
    use core::mem::offset_of;
    assert!(offset_of!(FB_SLI2_INT, bError) == 48 && offset_of!(FB_SLI2_UDINT, bError) == 48);
    assert!(offset_of!(FB_SLI2_UINT, nState) == 64 && offset_of!(FB_SLI2_DINT, nState) == 64);
};

crate::impl_member!([T: Analog, TS: Analog, const P1: usize, const P2: usize] FB_SLI2<T, TS, P1, P2> {
    info: crate::blocks::analog::variant_info!(T, "SLI2", Sli2State, super::sli::DIAG_VALUES;
        INT = SL_TYPE_SLI2_INT, UINT = SL_TYPE_SLI2_UINT, DINT = SL_TYPE_SLI2_DINT, UDINT = SL_TYPE_SLI2_UDINT),
    state: Sli2State,
    private: SL_SLI_PRIVATE,
    input: [bSLI, nPosition],
    param: [nLimitPos, nLimitNeg, dwOptions, wInputActive],
    output: [bError, bSLIActive, bBelowMin, bAboveMax, nPositionDiff],
    info_fields: [nDiagTextId, dwDiagPar2, dwDiagPar3],
});

super::window::window_block!(
    [T: Analog, TS: Analog, const P1: usize, const P2: usize] FB_SLI2<T, TS, P1, P2>; T, TS;
    options SL_OPT_SLI2_OVERFLOW_ALLOWED | SL_OPT_SLI2_EXCEEDED_SUPPORT => dwOptions;
    outputs [bBelowMin = below, bAboveMax = above]
);
