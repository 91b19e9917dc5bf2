//! FB OR — manual §4.2: up to eight inputs, each a break or make contact (negated before
//! the OR), OrOut = OR of the active inputs; at least one input active. States RUN (1),
//! STOP (2), SAFE (3); diag always 0. Struct and block from the gate family (`logic`).

use super::logic::{any, gate8_block, gate8_struct};
use crate::base::types::*;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/boolean/or.rs"));

gate8_struct! {
    /// FB OR instance (ABI §3, §9). Inputs at the manual's offsets (§4.2.2), output base 24.
    /// Size: 104 bytes.
    FB_OR: "Or", "OR", "Input 1.", "(at least one)";
    [bOrIn1, bOrIn2, bOrIn3, bOrIn4, bOrIn5, bOrIn6, bOrIn7, bOrIn8] => bOrOut
}

gate8_block! {
    /// The states of FB OR.
    FB_OR: OrState, SL_TYPE_OR, "OR", magic 0x0B01, min 1, any;
    [bOrIn1, bOrIn2, bOrIn3, bOrIn4, bOrIn5, bOrIn6, bOrIn7, bOrIn8] => bOrOut
}
