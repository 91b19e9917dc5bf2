//! SF_Equivalent — PLCopen TC5 Part 1 (research `plcopen_safety.md` §4.11, DiagCodes §5): two equivalent channels (both NC or both NO) → one output with discrepancy-time monitoring; no restart interlock, so not to be used alone.
//! The state machine is the two-channel machine of `sf_pair`.

use crate::base::types::SL_BOOL;

include!(concat!(
    env!("OUT_DIR"),
    "/abi/blocks/plcopen/equivalent.rs"
));

crate::pair_struct! {
    /// SF_Equivalent instance: the PLCopen VAR_INPUT / VAR_OUTPUT names, BOOL = one byte.
    /// Size: 56 bytes.
    SF_Equivalent: S_ChannelA "channel A, TRUE = active.", S_ChannelB "channel B, TRUE = active." => S_EquivalentOut
}

crate::pair_block!(SF_Equivalent, SL_TYPE_SF_EQUIVALENT, S_ChannelA, S_ChannelB, b_negated: false, S_EquivalentOut);

crate::pair_steady!(SF_Equivalent, S_ChannelA, S_ChannelB);
