//! FB ESTOP — manual §4.4 (functional description 4.4.1, signals, states and diag bits
//! 4.4.2, restart behaviour and samples 1–4 4.4.4, EL6910 EDM reset time 4.4.5).
//!
//! Up to eight emergency stop inputs, pairs 1/2, 3/4, 5/6, 7/8 with discrepancy times,
//! EStopOut switching off immediately and EStopDelOut after `tEStopDelOutDelay`, EDM1/EDM2
//! feedback loops; restart is always manual. The state machine is shared with FB MON
//! (`guard`).

use super::guard::{guard_diag, guard_fields, GuardBlock, SL_GUARD_PRIVATE};
use crate::base::block::BlockInfo;
use crate::base::types::*;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/boolean/estop.rs"));

/// Type tag, name and diag texts (manual §4.4.2).
const INFO: BlockInfo = BlockInfo::of::<EstopState>(SL_TYPE_ESTOP, "ESTOP").diag(guard_diag![
    (SL_DIAG_DISC3, "discrepancy error input group 3"),
    (SL_DIAG_DISC4, "discrepancy error input group 4"),
    (
        SL_DIAG_SAFE_IN_DISC3,
        "group 3 with Safe Inputs after Disc Error",
    ),
    (
        SL_DIAG_SAFE_IN_DISC4,
        "group 4 with Safe Inputs after Disc Error",
    ),
]);

crate::impl_member!([] FB_ESTOP {
    info: INFO,
    state: EstopState,
    private: SL_GUARD_PRIVATE,
    input: [bRestart, bEDM1, bEDM2, bEStopIn1, bEStopIn2, bEStopIn3, bEStopIn4, bEStopIn5, bEStopIn6, bEStopIn7, bEStopIn8],
    param: [tDiscTime12, tDiscTime34, tDiscTime56, tDiscTime78, tEDM1ResetTime, tEDM2ResetTime, tEStopDelOutDelay, wInputActive, wInputNegated, dwOptions],
    output: [bError, bEStopOut, bEStopDelOut],
    info_fields: [],
});

impl GuardBlock for FB_ESTOP {
    const TAG: u16 = 0xE570;
    // A set union, not `|` on the constants: the bits are disjoint, so `|` would give
    // mutation testing equivalent `^` mutants (docs/testing.md).
    const OPTIONS: u32 = Options::EDM1
        .union(Options::EDM2)
        .union(Options::SAFE_INPUTS_AFTER_DISC)
        .union(Options::MANUAL_RESTART)
        .bits();
    const INPUTS: u16 = 0xFF;
    const REQUIRED: u16 = 0xFF;
    const PAIRS: u8 = 0b1111;
    const TEST_INPUTS: u8 = 0;
    const ERROR_DELAY: bool = false;
    const ALWAYS_MANUAL: bool = true;

    /// Any active input requesting the safe state (logical FALSE).
    fn request(logical: u8, active: u8) -> bool {
        logical != active
    }

    guard_fields! {
        disc: [tDiscTime12, tDiscTime34, tDiscTime56, tDiscTime78],
        delay: tEStopDelOutDelay,
        inputs: [bEStopIn1, bEStopIn2, bEStopIn3, bEStopIn4, bEStopIn5, bEStopIn6, bEStopIn7, bEStopIn8],
        outputs: [bEStopOut, bEStopDelOut],
    }
}

super::guard::guard_block!(FB_ESTOP);
