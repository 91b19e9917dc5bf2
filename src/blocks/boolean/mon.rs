//! FB MON — manual §4.5 (functional description 4.5.1, signals, states and diag bits
//! 4.5.2, restart behaviour and samples 1–3 4.5.4, EL6910 EDM reset time 4.5.5); PLC naming
//! from `fb-mon-plc-interface.txt`.
//!
//! Up to four monitored inputs (pairs 1/2 and 3/4), two Secure inputs (pair 3) that bypass
//! the MonIn inputs, manual or automatic restart, manual function test, MonOut switching off
//! immediately and MonDelOut after `tMonDelOutDelay`, ERRORDELAY for a discrepancy error
//! while MonDelOut is still on. The state machine is shared with FB ESTOP (`guard`).

use super::guard::{guard_diag, guard_fields, GuardBlock, SL_GUARD_PRIVATE};
use crate::base::block::BlockInfo;
use crate::base::types::*;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/boolean/mon.rs"));

const MON_INPUTS: u8 = 0x0F;
const SECURE_INPUTS: u8 = 0x30;

/// Type tag, name and diag texts (manual §4.5.2).
const INFO: BlockInfo = BlockInfo::of::<MonState>(SL_TYPE_MON, "MON").diag(guard_diag![
    (SL_DIAG_DISC3, "discrepancy error in Secure input group"),
    (
        SL_DIAG_SAFE_IN_DISC3,
        "Secure group with Safe Inputs after Disc Error",
    ),
]);

crate::impl_member!([] FB_MON {
    info: INFO,
    state: MonState,
    private: SL_GUARD_PRIVATE,
    input: [bRestart, bEDM1, bEDM2, bMonIn1, bMonIn2, bMonIn3, bMonIn4, bSecure1, bSecure2],
    param: [tDiscTime12, tDiscTime34, tDiscTimeSecure12, tEDM1ResetTime, tEDM2ResetTime, tMonDelOutDelay, wInputActive, wInputNegated, dwOptions],
    output: [bError, bMonOut, bMonDelOut],
    info_fields: [],
});

impl GuardBlock for FB_MON {
    const TAG: u16 = 0x3011;
    const OPTIONS: u32 = SL_OPT_EDM1
        | SL_OPT_EDM2
        | SL_OPT_SAFE_INPUTS_AFTER_DISC
        | SL_OPT_MANUAL_RESTART
        | SL_OPT_FUNCTION_TEST;
    const INPUTS: u16 = 0x3F;
    const REQUIRED: u16 = MON_INPUTS as u16;
    const PAIRS: u8 = 0b111;
    const TEST_INPUTS: u8 = MON_INPUTS;
    const ERROR_DELAY: bool = true;
    const ALWAYS_MANUAL: bool = false;

    /// An active MonIn input requests the safe state and the Secure inputs do not bypass
    /// the MonIn inputs: a bypass needs at least one active Secure input and every active
    /// Secure input logically TRUE (ABI §8).
    fn request(logical: u8, active: u8) -> bool {
        let mon = active & MON_INPUTS;
        let secure = active & SECURE_INPUTS;
        let bypass = secure != 0 && logical & secure == secure;
        logical & mon != mon && !bypass
    }

    guard_fields! {
        disc: [tDiscTime12, tDiscTime34, tDiscTimeSecure12, 0],
        delay: tMonDelOutDelay,
        inputs: [bMonIn1, bMonIn2, bMonIn3, bMonIn4, bSecure1, bSecure2, 0, 0],
        outputs: [bMonOut, bMonDelOut],
    }
}

super::guard::guard_block!(FB_MON);
