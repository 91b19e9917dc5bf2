//! FB RS — manual §4.10: reset / set memory, Reset dominant.
//! Logic 1 at Set with logic 0 at Reset → output 1; logic 0 at Set with logic 1 at Reset →
//! output 0; both 1 → Reset dominant (output 0); both 0 → the output keeps its state.
//! States STOP (2), SAFE (3), SET (9); diag always 0; no error output.
//! The state machine is shared with FB SR (`flipflop`).

use super::flipflop::{SL_FLIPFLOP_PRIVATE, SL_STATE_RS_SET};
use crate::base::block::BlockInfo;
use crate::base::types::*;

/// Block type tag of FB_RS.
pub const SL_TYPE_RS: u16 = 11;

/// FB RS instance (ABI §3, §9). Inputs at the manual's offsets (§4.10.2), output base 24.
/// Size: 104 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[allow(non_snake_case, non_camel_case_types)]
pub struct FB_RS {
    /// Offset 0. Reserved, keep 0.
    pub aReserved0: [u8; 8],
    /// Offset 8. Reset: logic 1 switches the output off (dominant).
    pub bReset: SL_BOOL,
    /// Offset 9. Set: logic 1 switches the output on.
    pub bSet: SL_BOOL,
    /// Offset 10. Reserved, keep 0.
    pub aReserved1: [u8; 6],
    /// Offset 16. FbRun of the owning group.
    pub bRun: SL_BOOL,
    /// Offset 17. ErrAck of the owning group.
    pub bErrAck: SL_BOOL,
    /// Offset 18. Reserved, keep 0.
    pub aReserved2: [u8; 2],
    /// Offset 20. Bit 0: Reset is active, bit 1: Set is active (at least one).
    pub wInputActive: u16,
    /// Offset 22. Same bits: the input is a make contact (negated before evaluation).
    pub wInputNegated: u16,
    /// Offset 24 (output base + 0). Reserved.
    pub aReserved3: [u8; 1],
    /// Offset 25 (output base + 1). TRUE in SET; the safe state is FALSE.
    pub bRsOut: SL_BOOL,
    /// Offset 26. Reserved.
    pub aReserved4: [u8; 6],
    /// Offset 32. The manual's status value (SL_STATE_*).
    pub nState: u8,
    /// Offset 33. Reserved.
    pub aReserved5: [u8; 1],
    /// Offset 34. Diagnostic bits (only the library bits 13-15).
    pub nDiag: u16,
    /// Offset 36. Reserved.
    pub aReserved6: [u8; 4],
    /// Offset 40. Private state, 64 bytes: never write it.
    pub stPrivate: SL_FLIPFLOP_PRIVATE,
}

crate::base::block::block_states!(
    /// The states of FB RS.
    RsState: Stop, Safe, Error, Reset, Set = SL_STATE_RS_SET, "SET"
);

/// Type tag, name and diag texts (manual §4.10.2: diag always 0).
const INFO: BlockInfo = BlockInfo {
    tag: SL_TYPE_RS,
    name: "RS",
    states: <RsState as crate::base::block::BlockState>::TABLE,
    diag: &[],
    diag_values: &[],
};

crate::impl_member!([] FB_RS {
    info: INFO,
    state: RsState,
    private: SL_FLIPFLOP_PRIVATE,
    input: [bReset, bSet],
    param: [wInputActive, wInputNegated],
    output: [bRsOut],
    info_fields: [],
});

super::flipflop::flipflop_block!(FB_RS {
    tag: 0x5E75,
    set_dominant: false,
    output: bRsOut,
});
