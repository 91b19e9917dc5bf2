//! SF_TwoHandControlTypeIII — PLCopen TC5 Part 1 (research `plcopen_safety.md` §4.7, DiagCodes §5): two-hand control type III (EN 574 / ISO 13851): type II plus synchronous actuation, the second button within 500 ms of the first; no Reset.
//! The state machine is the two-hand machine of `sf_twohand`.

use crate::base::types::SL_BOOL;

include!(concat!(
    env!("OUT_DIR"),
    "/abi/blocks/plcopen/twohandcontroltypeiii.rs"
));

crate::two_hand_struct! {
    /// SF_TwoHandControlTypeIII instance: the PLCopen VAR_INPUT / VAR_OUTPUT names, BOOL = one byte.
    /// Size: 56 bytes.
    SF_TwoHandControlTypeIII
}

crate::two_hand_block!(
    SF_TwoHandControlTypeIII,
    SL_TYPE_SF_TWOHANDCONTROLTYPEIII,
    TwoHandIIIState,
    next_iii
);

crate::two_hand_steady!(
    SF_TwoHandControlTypeIII,
    TwoHandIIIState,
    timed: [Button1Actuated, Button2Actuated]
);
