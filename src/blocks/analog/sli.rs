//! FB SLI — manual §4.27; layout ABI-2 §11.9, rules ABI-2 §12.
//!
//! Safely limited increment: a rising edge of SLI saves Position (LatchPosition) and enters
//! RUN; while SLI stays TRUE, SLIActive = −Limit neg ≤ PositionDiff ≤ Limit pos with
//! PositionDiff = Position − LatchPosition (exact, INT16 / INT32 output). Leaving the window
//! is an ERROR: diag value 1 underflow / 2 overflow, message 0x40C0 / 0x40C1 (parameters 2
//! and 3: Position, LatchPosition), PositionDiff 0; an event, acknowledged by the next ErrAck
//! edge, and RESET is left only while SLI is FALSE. SLI FALSE → SAFE. States RUN (1),
//! STOP (2), SAFE (3), ERROR (4), RESET (5); never EXCEEDED (7), which the manual's table
//! copies from SLI2 (ABI-2 §14 row 14). Readings: docs/semantics.md SI1–SI8. The state
//! machine is shared with FB SLI2 (`window`); one implementation for the four types.

#![allow(non_camel_case_types)] // the ABI's names (FB_SLI_INT …)

use super::window::SL_SLI_PRIVATE;
pub use super::window::{SL_SLI_ACTIVE, SL_TEXT_SLI_OVERFLOW, SL_TEXT_SLI_UNDERFLOW};
use super::{Analog, SL_DIAG_VALUE_OVERFLOW, SL_DIAG_VALUE_UNDERFLOW};
use crate::base::types::*;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/analog/sli.rs"));

// The ABI-2 §11.9 numbers (identical for both widths).
const _: () = {
    use core::mem::offset_of;
    assert!(offset_of!(FB_SLI_INT, bError) == 40 && offset_of!(FB_SLI_UDINT, bError) == 40);
    assert!(offset_of!(FB_SLI_UINT, nState) == 56 && offset_of!(FB_SLI_DINT, nState) == 56);
};

/// Diag value texts (manual §4.27.2), shared with FB SLI2 (§4.28 has no table of its own).
pub(crate) const DIAG_VALUES: &[(u16, &str)] = &[
    (0, "No diagnostic information"),
    (
        SL_DIAG_VALUE_UNDERFLOW,
        "Underflow (PositionDiff < -NegLimit)",
    ),
    (SL_DIAG_VALUE_OVERFLOW, "Overflow (PositionDiff > PosLimit)"),
];

crate::impl_member!([T: Analog, TS: Analog, const P1: usize, const P2: usize] FB_SLI<T, TS, P1, P2> {
    info: crate::blocks::analog::variant_info!(T, "SLI", SliState, DIAG_VALUES;
        INT = SL_TYPE_SLI_INT, UINT = SL_TYPE_SLI_UINT, DINT = SL_TYPE_SLI_DINT, UDINT = SL_TYPE_SLI_UDINT),
    state: SliState,
    private: SL_SLI_PRIVATE,
    input: [bSLI, nPosition],
    param: [nLimitPos, nLimitNeg, wInputActive],
    output: [bError, bSLIActive, nPositionDiff],
    info_fields: [nDiagTextId, dwDiagPar2, dwDiagPar3],
});

super::window::window_block!(
    [T: Analog, TS: Analog, const P1: usize, const P2: usize] FB_SLI<T, TS, P1, P2>; T, TS;
    options 0 => 0;
    outputs []
);
