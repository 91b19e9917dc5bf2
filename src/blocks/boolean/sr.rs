//! FB SR — manual §4.11: set / reset memory, Set dominant.
//! Logic 1 at Set with logic 0 at Reset → output 1; logic 0 at Set with logic 1 at Reset →
//! output 0; both 1 → Set dominant (output 1); both 0 → the output keeps its state.
//! States STOP (2), SAFE (3), SET (9); diag always 0; no error output.
//! Struct and state machine are shared with FB RS (`flipflop`).

use super::flipflop::{flipflop_block, flipflop_struct, SL_STATE_SR_SET};
use crate::base::types::*;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/boolean/sr.rs"));

flipflop_struct! {
    /// FB SR instance (ABI §3, §9). Inputs at the manual's offsets (§4.11.2), output base 24.
    /// Size: 104 bytes.
    FB_SR: "", " (dominant)" => bSrOut
}

flipflop_block! {
    /// The states of FB SR.
    FB_SR: SrState, SL_TYPE_SR, "SR", SL_STATE_SR_SET; magic 0x5E5A, set_dominant true, output bSrOut
}
