//! FB RS — manual §4.10: reset / set memory, Reset dominant.
//! Logic 1 at Set with logic 0 at Reset → output 1; logic 0 at Set with logic 1 at Reset →
//! output 0; both 1 → Reset dominant (output 0); both 0 → the output keeps its state.
//! States STOP (2), SAFE (3), SET (9); diag always 0; no error output.
//! Struct and state machine are shared with FB SR (`flipflop`).

use super::flipflop::{flipflop_block, flipflop_struct, SL_STATE_RS_SET};
use crate::base::types::*;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/boolean/rs.rs"));

flipflop_struct! {
    /// FB RS instance (ABI §3, §9). Inputs at the manual's offsets (§4.10.2), output base 24.
    /// Size: 104 bytes.
    FB_RS: " (dominant)", "" => bRsOut
}

flipflop_block! {
    /// The states of FB RS.
    FB_RS: RsState, SL_TYPE_RS, "RS", SL_STATE_RS_SET; magic 0x5E75, set_dominant false, output bRsOut
}
