//! SF_TwoHandControlTypeII — PLCopen TC5 Part 1 (research `plcopen_safety.md` §4.6, DiagCodes §5): two-hand control type II (EN 574 / ISO 13851): the output TRUE while both buttons are actuated in the correct order, both released before the next actuation; no Reset.
//! The state machine is the two-hand machine of `sf_twohand`.

use crate::base::sf::SL_SF_PRIVATE;
use crate::base::types::SL_BOOL;

/// Block type tag of SF_TwoHandControlTypeII (`SL_MEMBER.nType`, `sl_diag_text`).
pub const SL_TYPE_SF_TWOHANDCONTROLTYPEII: u16 = 524;

/// SF_TwoHandControlTypeII instance: the PLCopen VAR_INPUT / VAR_OUTPUT names, BOOL = one byte.
/// Size: 56 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[allow(non_snake_case, non_camel_case_types)]
pub struct SF_TwoHandControlTypeII {
    /// Offset 0. Activate: FALSE = idle (DiagCode 0000, every output FALSE), highest priority.
    pub Activate: SL_BOOL,
    /// Offset 1. S_Button1: button 1, TRUE = actuated (category 3 or 4: from two antivalent contacts).
    pub S_Button1: SL_BOOL,
    /// Offset 2. S_Button2: button 2, TRUE = actuated.
    pub S_Button2: SL_BOOL,
    /// Offset 3. Reserved, keep 0.
    pub aReserved0: [u8; 4],
    /// Offset 7. Library extension, constant: DiagCode profile, 0 = v2.01 (default), 1 = v1.0; latched at activation.
    pub nDiagProfile: u8,
    /// Offset 8 (output base). Ready: TRUE while activated (DiagCode != 0000).
    pub Ready: SL_BOOL,
    /// Offset 9. S_TwoHandOut: the safety output, TRUE only at DiagCode 8000.
    pub S_TwoHandOut: SL_BOOL,
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

crate::two_hand_block!(
    SF_TwoHandControlTypeII,
    SL_TYPE_SF_TWOHANDCONTROLTYPEII,
    TwoHandIIState,
    next_ii
);
