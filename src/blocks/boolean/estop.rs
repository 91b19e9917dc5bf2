//! FB ESTOP — manual §4.4 (functional description 4.4.1, signals, states and diag bits
//! 4.4.2, restart behaviour and samples 1–4 4.4.4, EL6910 EDM reset time 4.4.5).
//!
//! Up to eight emergency stop inputs, pairs 1/2, 3/4, 5/6, 7/8 with discrepancy times,
//! EStopOut switching off immediately and EStopDelOut after `tEStopDelOutDelay`, EDM1/EDM2
//! feedback loops; restart is always manual. The state machine is shared with FB MON
//! (`guard`).

use super::guard::{GuardBlock, GuardParams, GuardRaw, SL_GUARD_PRIVATE};
use crate::base::block::BlockInfo;
use crate::base::types::*;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/boolean/estop.rs"));

/// Type tag, name and diag texts (manual §4.4.2).
const INFO: BlockInfo = BlockInfo {
    tag: SL_TYPE_ESTOP,
    name: "ESTOP",
    states: <EstopState as crate::base::block::BlockState>::TABLE,
    diag: &[
        (SL_DIAG_DISC1, "discrepancy error input group 1"),
        (SL_DIAG_DISC2, "discrepancy error input group 2"),
        (SL_DIAG_DISC3, "discrepancy error input group 3"),
        (SL_DIAG_DISC4, "discrepancy error input group 4"),
        (SL_DIAG_EDM1, "EDM monitoring error EDM1"),
        (SL_DIAG_EDM2, "EDM monitoring error EDM2"),
        (
            SL_DIAG_SAFE_IN_DISC1,
            "group 1 with Safe Inputs after Disc Error",
        ),
        (
            SL_DIAG_SAFE_IN_DISC2,
            "group 2 with Safe Inputs after Disc Error",
        ),
        (
            SL_DIAG_SAFE_IN_DISC3,
            "group 3 with Safe Inputs after Disc Error",
        ),
        (
            SL_DIAG_SAFE_IN_DISC4,
            "group 4 with Safe Inputs after Disc Error",
        ),
    ],
    diag_values: &[],
};

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
    const DISC_NAMES: [&'static str; 4] =
        ["tDiscTime12", "tDiscTime34", "tDiscTime56", "tDiscTime78"];
    const DELAY_NAME: &'static str = "tEStopDelOutDelay";
    const TEST_INPUTS: u8 = 0;
    const ERROR_DELAY: bool = false;
    const ALWAYS_MANUAL: bool = true;

    fn params(&self) -> GuardParams {
        GuardParams {
            disc: [
                self.tDiscTime12,
                self.tDiscTime34,
                self.tDiscTime56,
                self.tDiscTime78,
            ],
            edm_reset: [self.tEDM1ResetTime, self.tEDM2ResetTime],
            delay: self.tEStopDelOutDelay,
            active: self.wInputActive,
            negated: self.wInputNegated,
            options: self.dwOptions,
        }
    }

    fn raw(&self) -> GuardRaw {
        GuardRaw {
            restart: self.bRestart,
            edm: [self.bEDM1, self.bEDM2],
            inputs: [
                self.bEStopIn1,
                self.bEStopIn2,
                self.bEStopIn3,
                self.bEStopIn4,
                self.bEStopIn5,
                self.bEStopIn6,
                self.bEStopIn7,
                self.bEStopIn8,
            ],
        }
    }

    /// Any active input requesting the safe state (logical FALSE).
    fn request(logical: u8, active: u8) -> bool {
        logical != active
    }

    fn set_outputs(&mut self, error: bool, out: bool, del_out: bool, state: u8, diag: u16) {
        self.bError = u8::from(error);
        self.bEStopOut = u8::from(out);
        self.bEStopDelOut = u8::from(del_out);
        self.nState = state;
        self.nDiag = diag;
    }
}

super::guard::guard_block!(FB_ESTOP);
