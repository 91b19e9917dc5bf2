//! SF_ESPE — PLCopen TC5 Part 1 (research `plcopen_safety.md` §4.2, DiagCodes §5): electro-sensitive protective equipment (light curtain): "the functions of SF_ESPE and SF_EmergencyStop FB are identical".
//! The state machine is the restart interlock of `sf_restart`.

use crate::base::sf::SL_SF_PRIVATE;
use crate::base::types::SL_BOOL;

/// Block type tag of SF_ESPE (`SL_MEMBER.nType`, `sl_diag_text`).
pub const SL_TYPE_SF_ESPE: u16 = 513;

/// SF_ESPE instance: the PLCopen VAR_INPUT / VAR_OUTPUT names, BOOL = one byte.
/// Size: 56 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(non_snake_case, non_camel_case_types)]
pub struct SF_ESPE {
    /// Offset 0. Activate: FALSE = idle (DiagCode 0000, every output FALSE), highest priority.
    pub Activate: SL_BOOL,
    /// Offset 1. S_ESPE_In: ESPE output (OSSD), FALSE = protective field interrupted (safety demand).
    pub S_ESPE_In: SL_BOOL,
    /// Offset 2. S_StartReset: TRUE = automatic reset at activation (start-up).
    pub S_StartReset: SL_BOOL,
    /// Offset 3. S_AutoReset: TRUE = automatic reset when the safety demand ends.
    pub S_AutoReset: SL_BOOL,
    /// Offset 4. Reset: a rising edge resets; held TRUE into a wait-for-reset state it is a static-reset error.
    pub Reset: SL_BOOL,
    /// Offset 5. Reserved, keep 0.
    pub aReserved0: [u8; 2],
    /// Offset 7. Library extension, constant: DiagCode profile, 0 = v2.01 (default), 1 = v1.0; latched at activation.
    pub nDiagProfile: u8,
    /// Offset 8 (output base). Ready: TRUE while activated (DiagCode != 0000).
    pub Ready: SL_BOOL,
    /// Offset 9. S_ESPE_Out: the safety output, TRUE only at DiagCode 8000.
    pub S_ESPE_Out: SL_BOOL,
    /// Offset 10. SafetyDemand: the safety function is demanded (v2.01 code bit 0x0800).
    pub SafetyDemand: SL_BOOL,
    /// Offset 11. ResetRequest: a reset is awaited (v2.01 code bit 0x0400) and Reset is FALSE.
    pub ResetRequest: SL_BOOL,
    /// Offset 12. Error: DiagCode >= C000.
    pub Error: SL_BOOL,
    /// Offset 13. Reserved.
    pub aReserved1: [u8; 1],
    /// Offset 14. DiagCode: the state or error, in the profile of nDiagProfile.
    pub DiagCode: u16,
    /// Offset 16. Private state, 40 bytes: never write it.
    pub stPrivate: SL_SF_PRIVATE,
}

crate::restart_interlock_block!(SF_ESPE, SL_TYPE_SF_ESPE, S_ESPE_In, S_ESPE_Out, has_v10: true);
