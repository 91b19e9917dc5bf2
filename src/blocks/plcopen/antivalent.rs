//! SF_Antivalent — PLCopen TC5 Part 1 (research `plcopen_safety.md` §4.12, DiagCodes §5): an NC/NO contact pair → one output with discrepancy-time monitoring; active when NC is TRUE and NO is FALSE.
//! The state machine is the two-channel machine of `sf_pair`.

use crate::base::types::SL_BOOL;

include!(concat!(
    env!("OUT_DIR"),
    "/abi/blocks/plcopen/antivalent.rs"
));

crate::pair_struct! {
    /// SF_Antivalent instance: the PLCopen VAR_INPUT / VAR_OUTPUT names, BOOL = one byte.
    /// Size: 56 bytes.
    SF_Antivalent: S_ChannelNC "NC contact (break), TRUE = active.", S_ChannelNO "NO contact (make), FALSE = active (PLCopen's initial value is TRUE: connect it)." => S_AntivalentOut
}

crate::pair_block!(SF_Antivalent, SL_TYPE_SF_ANTIVALENT, S_ChannelNC, S_ChannelNO, b_negated: true, S_AntivalentOut);

impl SF_Antivalent {
    /// An instance with PLCopen's initial values (`sl_sf_antivalent_defaults`): S_ChannelNO
    /// TRUE (its SAFEBOOL initial value), everything else zero. The all-zero struct keeps
    /// S_ChannelNO FALSE, as every other input of the library starts (semantics PO12).
    pub const fn plcopen_defaults() -> Self {
        Self {
            S_ChannelNO: 1,
            ..Self::zeroed()
        }
    }
}

crate::pair_steady!(SF_Antivalent, S_ChannelNC, S_ChannelNO);
