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

super::analog_variants! {
    FB_SLI:
        INT SL_TYPE_SLI_INT = 60 => FB_SLI_INT[i16, i16, 2, 6], UINT SL_TYPE_SLI_UINT = 61 => FB_SLI_UINT[u16, i16, 2, 6],
        DINT SL_TYPE_SLI_DINT = 62 => FB_SLI_DINT[i32, i32, 0, 4], UDINT SL_TYPE_SLI_UDINT = 63 => FB_SLI_UDINT[u32, i32, 0, 4]
}

crate::base::layout::block_struct! {
    /// FB SLI instance (ABI-2 §11.9), generic over the Position type `T` and the PositionDiff
    /// type `TS`; `P1` and `P2` are the reserved gaps (after Position, after PositionDiff) that
    /// make the 16- and 32-bit layouts differ. Size: 136 bytes.
    FB_SLI[T: Analog, TS: Analog; P1, P2] {
        /// Offset 0. SLI: a rising edge saves Position and starts the monitoring; TRUE keeps it
        /// on (active bit 0, required).
        pub bSLI: SL_BOOL,
        /// Offset 1. Reserved, keep 0.
        pub aReserved0: [u8; 15],
        /// Offset 16. FbRun of the owning group: TRUE = the block executes.
        pub bRun: SL_BOOL,
        /// Offset 17. ErrAck of the owning group.
        pub bErrAck: SL_BOOL,
        /// Offset 18. Reserved, keep 0.
        pub aReserved1: [u8; 6],
        /// Offset 24 (analog input base). Position (active bit 8, required).
        pub nPosition: T,
        /// Reserved up to the parameters (16-bit: 2 bytes, 32-bit: none).
        pub aReserved2: [u8; P1],
        /// Offset 28. "Limit pos": permitted deviation above LatchPosition, ≤ the maximum of TS.
        pub nLimitPos: u32,
        /// Offset 32. "Limit neg": permitted deviation below LatchPosition (a magnitude), ≤ the
        /// maximum of TS.
        pub nLimitNeg: u32,
        /// Offset 36. Exactly bits 0 and 8 (SL_SLI_ACTIVE).
        pub wInputActive: u16,
        /// Offset 38. Reserved.
        pub aReserved3: [u8; 2],
        /// Offset 40 (output base). Error, TRUE in ERROR only.
        pub bError: SL_BOOL,
        /// Offset 41. SLIActive: TRUE in RUN (SLI TRUE, PositionDiff within the limits).
        pub bSLIActive: SL_BOOL,
        /// Offset 42. Reserved.
        pub aReserved4: [u8; 6],
        /// Offset 48 (analog output base). PositionDiff = Position − LatchPosition in RUN,
        /// else 0.
        pub nPositionDiff: TS,
        /// Reserved up to the info data (16-bit: 6 bytes, 32-bit: 4).
        pub aReserved5: [u8; P2],
    } info [aReserved6, aReserved7] SL_SLI_PRIVATE, "64 bytes":
        "The manual's status value (RUN, STOP, SAFE, ERROR, RESET).",
        "Diag value (1 underflow, 2 overflow) + library bits 13-15.",
        "Text ID of the latched diag message (0x40C0, 0x40C1), 0 = none.",
        "Message parameter 2: Position as a 32-bit pattern.", "Message parameter 3: LatchPosition."
}

// The ABI-2 §11.9 numbers (identical for both widths).
const _: () = {
    use core::mem::offset_of;
    assert!(offset_of!(FB_SLI_INT, bError) == 40 && offset_of!(FB_SLI_UDINT, bError) == 40);
    assert!(offset_of!(FB_SLI_UINT, nState) == 56 && offset_of!(FB_SLI_DINT, nState) == 56);
};

crate::base::block::block_states!(
    /// The states of FB SLI, every variant (manual §4.27.2; no EXCEEDED, semantics SI1).
    SliState: Run, Stop, Safe, Error, Reset
);

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
