//! SF_ESPE — PLCopen TC5 Part 1 (research `plcopen_safety.md` §4.2, DiagCodes §5): electro-sensitive protective equipment (light curtain): "the functions of SF_ESPE and SF_EmergencyStop FB are identical".
//! The state machine is the restart interlock of `sf_restart`.

use crate::base::types::SL_BOOL;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/plcopen/espe.rs"));

crate::restart_interlock_struct! {
    /// SF_ESPE instance: the PLCopen VAR_INPUT / VAR_OUTPUT names, BOOL = one byte.
    /// Size: 56 bytes.
    SF_ESPE: S_ESPE_In "ESPE output (OSSD), FALSE = protective field interrupted (safety demand)." => S_ESPE_Out
}

crate::restart_interlock_block!(SF_ESPE, SL_TYPE_SF_ESPE, S_ESPE_In, S_ESPE_Out, has_v10: true);

crate::restart_interlock_steady!(SF_ESPE, S_ESPE_In);
