//! FB ESTOP — manual §4.4 (functional description 4.4.1, signals, states and diag bits
//! 4.4.2, restart behaviour and samples 1–4 4.4.4, EL6910 EDM reset time 4.4.5).
//!
//! Up to eight emergency stop inputs, pairs 1/2, 3/4, 5/6, 7/8 with discrepancy times,
//! EStopOut switching off immediately and EStopDelOut after `tEStopDelOutDelay`, EDM1/EDM2
//! feedback loops; restart is always manual. The state machine is shared with FB MON
//! (`guard`).

use super::guard::{guard_fields, GuardBlock, SL_GUARD_PRIVATE};
use crate::base::block::BlockInfo;
use crate::base::types::*;

/// Block type tag of FB_ESTOP (`SL_MEMBER.nType`, `sl_diag_text`).
pub const SL_TYPE_ESTOP: u16 = 1;

crate::base::layout::block_struct! {
    /// FB ESTOP instance (ABI §3, §8). Inputs at the manual's offsets (§4.4.2), outputs at
    /// output base 56 + the manual's offsets.
    /// Size: 152 bytes.
    FB_ESTOP {
        /// Offset 0. Restart: a falling edge enables the outputs (push button, make contact).
        pub bRestart: SL_BOOL,
        /// Offset 1. Feedback loop of EStopOut.
        pub bEDM1: SL_BOOL,
        /// Offset 2. Feedback loop of EStopDelOut.
        pub bEDM2: SL_BOOL,
        /// Offset 3. Reserved, keep 0.
        pub aReserved0: [u8; 5],
        /// Offset 8. Emergency stop input 1 (pair 1 with input 2).
        pub bEStopIn1: SL_BOOL,
        /// Offset 9.
        pub bEStopIn2: SL_BOOL,
        /// Offset 10. Pair 2 with input 4.
        pub bEStopIn3: SL_BOOL,
        /// Offset 11.
        pub bEStopIn4: SL_BOOL,
        /// Offset 12. Pair 3 with input 6.
        pub bEStopIn5: SL_BOOL,
        /// Offset 13.
        pub bEStopIn6: SL_BOOL,
        /// Offset 14. Pair 4 with input 8.
        pub bEStopIn7: SL_BOOL,
        /// Offset 15.
        pub bEStopIn8: SL_BOOL,
        /// Offset 16. FbRun of the owning group: TRUE = the block executes.
        pub bRun: SL_BOOL,
        /// Offset 17. ErrAck of the owning group.
        pub bErrAck: SL_BOOL,
        /// Offset 18. Reserved, keep 0.
        pub aReserved1: [u8; 2],
        /// Offset 20. Discrepancy time of pair EStopIn1/2 in ms (0 = two single channels).
        pub tDiscTime12: u32,
        /// Offset 24. Discrepancy time of pair EStopIn3/4 in ms.
        pub tDiscTime34: u32,
        /// Offset 28. Discrepancy time of pair EStopIn5/6 in ms.
        pub tDiscTime56: u32,
        /// Offset 32. Discrepancy time of pair EStopIn7/8 in ms.
        pub tDiscTime78: u32,
        /// Offset 36. EDM1 reset time in ms (EL6910; 0 = off).
        pub tEDM1ResetTime: u32,
        /// Offset 40. EDM2 reset time in ms (EL6910; 0 = off).
        pub tEDM2ResetTime: u32,
        /// Offset 44. Delay of EStopDelOut in ms.
        pub tEStopDelOutDelay: u32,
        /// Offset 48. Bit n-1 set: EStopInn is active.
        pub wInputActive: u16,
        /// Offset 50. Bit n-1 set: EStopInn is a make contact (negated).
        pub wInputNegated: u16,
        /// Offset 52. SL_OPT_EDM1 | SL_OPT_EDM2 | SL_OPT_SAFE_INPUTS_AFTER_DISC.
        pub dwOptions: u32,
        /// Offset 56 (output base + 0). TRUE in ERROR.
        pub bError: SL_BOOL,
        /// Offset 57 (output base + 1). Undelayed output.
        pub bEStopOut: SL_BOOL,
        /// Offset 58 (output base + 2). Delayed output.
        pub bEStopDelOut: SL_BOOL,
        /// Offset 59. Reserved.
        pub aReserved2: [u8; 5],
    } tail 64 65 66 68 72 [aReserved3, aReserved4] SL_GUARD_PRIVATE, 80:
        "(SL_STATE_*)", "Diagnostic bits (SL_DIAG_*)."
}

crate::base::block::block_states!(
    /// The states of FB ESTOP.
    EstopState: Run, Stop, Safe, Error, Reset, Start, DelayOut
);

/// Type tag, name and diag texts (manual §4.4.2).
const INFO: BlockInfo = BlockInfo::of::<EstopState>(SL_TYPE_ESTOP, "ESTOP").diag(&[
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
