//! SF_TwoHandControlTypeII — PLCopen TC5 Part 1 (research `plcopen_safety.md` §4.6, DiagCodes §5): two-hand control type II (EN 574 / ISO 13851): the output TRUE while both buttons are actuated in the correct order, both released before the next actuation; no Reset.
//! The state machine is the two-hand machine of `sf_twohand`.

use crate::base::types::SL_BOOL;

include!(concat!(
    env!("OUT_DIR"),
    "/abi/blocks/plcopen/twohandcontroltypeii.rs"
));

crate::two_hand_struct! {
    /// SF_TwoHandControlTypeII instance: the PLCopen VAR_INPUT / VAR_OUTPUT names, BOOL = one byte.
    /// Size: 56 bytes.
    SF_TwoHandControlTypeII
}

crate::two_hand_block!(
    SF_TwoHandControlTypeII,
    SL_TYPE_SF_TWOHANDCONTROLTYPEII,
    TwoHandIIState,
    next_ii
);

crate::two_hand_steady!(SF_TwoHandControlTypeII, TwoHandIIState, timed: []);
