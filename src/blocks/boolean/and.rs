//! FB AND — manual §4.1: up to eight inputs, each a break or make contact (negated before
//! the AND), AndOut = AND of the active inputs; at least two inputs active. States RUN (1),
//! STOP (2), SAFE (3); diag always 0. Struct and block from the gate family (`logic`).

use super::logic::{all, gate8_block, gate8_struct};
use crate::base::types::*;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/boolean/and.rs"));

gate8_struct! {
    /// FB AND instance (ABI §3, §9). Inputs at the manual's offsets (§4.1.2), output base 24.
    /// Size: 104 bytes.
    FB_AND: "And", "AND", "Input 1 (may be a standard signal: it can only switch off).", "(at least two)";
    [bAndIn1, bAndIn2, bAndIn3, bAndIn4, bAndIn5, bAndIn6, bAndIn7, bAndIn8] => bAndOut
}

gate8_block! {
    /// The states of FB AND.
    FB_AND: AndState, SL_TYPE_AND, "AND", magic 0xA2D1, min 2, all;
    [bAndIn1, bAndIn2, bAndIn3, bAndIn4, bAndIn5, bAndIn6, bAndIn7, bAndIn8] => bAndOut
}
