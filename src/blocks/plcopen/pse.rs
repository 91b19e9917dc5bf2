//! SF_PSE — PLCopen TC5 Part 1 (research `plcopen_safety.md` §4.3, DiagCodes §5): pressure-sensitive equipment (safety mats, bumpers), PLCopen v2.x only: the v1.0 profile is refused (SL_E_CONFIG).
//! The state machine is the restart interlock of `sf_restart`.

use crate::base::types::SL_BOOL;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/plcopen/pse.rs"));

crate::restart_interlock_struct! {
    /// SF_PSE instance: the PLCopen VAR_INPUT / VAR_OUTPUT names, BOOL = one byte.
    /// Size: 56 bytes.
    SF_PSE: S_PSE_In "pressure-sensitive equipment, FALSE = actuated (safety demand)." => S_PSE_Out
}

crate::restart_interlock_block!(SF_PSE, SL_TYPE_SF_PSE, S_PSE_In, S_PSE_Out, has_v10: false);

crate::restart_interlock_steady!(SF_PSE, S_PSE_In);
