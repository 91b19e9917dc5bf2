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

super::analog_variants! {
    FB_SLI2:
        INT SL_TYPE_SLI2_INT = 64 => FB_SLI2_INT[i16, i16, 2, 6], UINT SL_TYPE_SLI2_UINT = 65 => FB_SLI2_UINT[u16, i16, 2, 6],
        DINT SL_TYPE_SLI2_DINT = 66 => FB_SLI2_DINT[i32, i32, 0, 4], UDINT SL_TYPE_SLI2_UDINT = 67 => FB_SLI2_UDINT[u32, i32, 0, 4]
}

crate::base::layout::block_struct! {
    /// FB SLI2 instance (ABI-2 §11.10), generic over the Position type `T` and the
    /// PositionDiff type `TS`; `P1` and `P2` are the reserved gaps (after Position, after
    /// PositionDiff) that make the 16- and 32-bit layouts differ. Size: 144 bytes.
    FB_SLI2[T: Analog, TS: Analog; P1, P2] {
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
        /// Offset 36. SL_OPT_SLI2_OVERFLOW_ALLOWED (bit 8), SL_OPT_SLI2_EXCEEDED_SUPPORT (bit 9).
        pub dwOptions: u32,
        /// Offset 40. Exactly bits 0 and 8 (SL_SLI_ACTIVE).
        pub wInputActive: u16,
        /// Offset 42. Reserved.
        pub aReserved3: [u8; 6],
        /// Offset 48 (output base). Error, TRUE in ERROR only.
        pub bError: SL_BOOL,
        /// Offset 49. SLIActive: TRUE in RUN (SLI TRUE, PositionDiff within the limits).
        pub bSLIActive: SL_BOOL,
        /// Offset 50. BelowMin: in EXCEEDED, PositionDiff < −Limit neg.
        pub bBelowMin: SL_BOOL,
        /// Offset 51. AboveMax: in EXCEEDED, PositionDiff > Limit pos.
        pub bAboveMax: SL_BOOL,
        /// Offset 52. Reserved.
        pub aReserved4: [u8; 4],
        /// Offset 56 (analog output base). PositionDiff = Position − LatchPosition in RUN and
        /// (saturated) in EXCEEDED, else 0.
        pub nPositionDiff: TS,
        /// Reserved up to the info data (16-bit: 6 bytes, 32-bit: 4).
        pub aReserved5: [u8; P2],
    } info [aReserved6, aReserved7] SL_SLI_PRIVATE, "64 bytes":
        "The manual's status value (RUN, STOP, SAFE, ERROR, RESET, EXCEEDED).",
        "Diag value (1 underflow, 2 overflow) + library bits 13-15.",
        "Text ID of the latched diag message (0x40C0, 0x40C1), 0 = none.",
        "Message parameter 2: Position as a 32-bit pattern.", "Message parameter 3: LatchPosition."
}

// The ABI-2 §11.10 numbers (identical for both widths).
const _: () = {
    use core::mem::offset_of;
    assert!(offset_of!(FB_SLI2_INT, bError) == 48 && offset_of!(FB_SLI2_UDINT, bError) == 48);
    assert!(offset_of!(FB_SLI2_UINT, nState) == 64 && offset_of!(FB_SLI2_DINT, nState) == 64);
};

crate::base::block::block_states!(
    /// The states of FB SLI2, every variant (manual §4.28.2.3).
    Sli2State: Run, Stop, Safe, Error, Reset, Exceeded = SL_STATE_SLI2_EXCEEDED, "EXCEEDED"
);

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
