//! SF_EmergencyStop — PLCopen TC5 Part 1 (research `plcopen_safety.md` §4.1, DiagCodes §5): monitors an emergency stop button (stop category 0, or 1/2 with peripheral support).
//! The state machine is the restart interlock of `sf_restart`.

use crate::base::types::SL_BOOL;

include!(concat!(
    env!("OUT_DIR"),
    "/abi/blocks/plcopen/emergencystop.rs"
));

crate::restart_interlock_struct! {
    /// SF_EmergencyStop instance: the PLCopen VAR_INPUT / VAR_OUTPUT names, BOOL = one byte.
    /// Size: 56 bytes.
    SF_EmergencyStop: S_EStopIn "emergency stop button, FALSE = pressed (safety demand)." => S_EStopOut
}

crate::restart_interlock_block!(SF_EmergencyStop, SL_TYPE_SF_EMERGENCYSTOP, S_EStopIn, S_EStopOut, has_v10: true);
crate::restart_interlock_steady!(SF_EmergencyStop, S_EStopIn);
