//! SF_Antivalent — PLCopen TC5 Part 1 (research `plcopen_safety.md` §4.12, DiagCodes §5): an NC/NO contact pair → one output with discrepancy-time monitoring; active when NC is TRUE and NO is FALSE.
//! The state machine is the two-channel machine of `sf_pair`.

use crate::base::sf::SL_SF_PRIVATE;
use crate::base::types::SL_BOOL;

/// Block type tag of SF_Antivalent (`SL_MEMBER.nType`, `sl_diag_text`).
pub const SL_TYPE_SF_ANTIVALENT: u16 = 516;

/// SF_Antivalent instance: the PLCopen VAR_INPUT / VAR_OUTPUT names, BOOL = one byte.
/// Size: 56 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(non_snake_case, non_camel_case_types)]
pub struct SF_Antivalent {
    /// Offset 0. Activate: FALSE = idle (DiagCode 0000, every output FALSE), highest priority.
    pub Activate: SL_BOOL,
    /// Offset 1. S_ChannelNC: NC contact (break), TRUE = active.
    pub S_ChannelNC: SL_BOOL,
    /// Offset 2. S_ChannelNO: NO contact (make), FALSE = active (PLCopen's initial value is TRUE: connect it).
    pub S_ChannelNO: SL_BOOL,
    /// Offset 3. Library extension, constant: DiagCode profile, 0 = v2.01 (default), 1 = v1.0; latched at activation.
    pub nDiagProfile: u8,
    /// Offset 4. DiscrepancyTime (constant, ms): how long the channels may differ; latched at activation.
    pub DiscrepancyTime: u32,
    /// Offset 8 (output base). Ready: TRUE while activated (DiagCode != 0000).
    pub Ready: SL_BOOL,
    /// Offset 9. S_AntivalentOut: the safety output, TRUE only at DiagCode 8000.
    pub S_AntivalentOut: SL_BOOL,
    /// Offset 10. SafetyDemand: the safety function is demanded (v2.01 code bit 0x0800).
    pub SafetyDemand: SL_BOOL,
    /// Offset 11. Error: DiagCode >= C000.
    pub Error: SL_BOOL,
    /// Offset 12. Reserved.
    pub aReserved1: [u8; 2],
    /// Offset 14. DiagCode: the state or error, in the profile of nDiagProfile.
    pub DiagCode: u16,
    /// Offset 16. Private state, 40 bytes: never write it.
    pub stPrivate: SL_SF_PRIVATE,
}

crate::pair_block!(SF_Antivalent, SL_TYPE_SF_ANTIVALENT, S_ChannelNC, S_ChannelNO, b_negated: true, S_AntivalentOut);
