//! FB MON — manual §4.5 (functional description 4.5.1, signals, states and diag bits
//! 4.5.2, restart behaviour and samples 1–3 4.5.4, EL6910 EDM reset time 4.5.5); PLC naming
//! from `fb-mon-plc-interface.txt`.
//!
//! Up to four monitored inputs (pairs 1/2 and 3/4), two Secure inputs (pair 3) that bypass
//! the MonIn inputs, manual or automatic restart, manual function test, MonOut switching off
//! immediately and MonDelOut after `tMonDelOutDelay`, ERRORDELAY for a discrepancy error
//! while MonDelOut is still on. The state machine is shared with FB ESTOP (`guard`).

use super::guard::{guard_fields, GuardBlock, SL_GUARD_PRIVATE};
use crate::base::block::BlockInfo;
use crate::base::types::*;

/// Block type tag of FB_MON.
pub const SL_TYPE_MON: u16 = 2;

crate::base::layout::block_struct! {
    /// FB MON instance (ABI §3, §8). Inputs at the manual's offsets (§4.5.2), outputs at
    /// output base 56 + the manual's offsets.
    /// Size: 152 bytes.
    FB_MON {
        /// Offset 0. Restart (used with SL_OPT_MANUAL_RESTART): a falling edge enables the outputs.
        pub bRestart: SL_BOOL,
        /// Offset 1. Feedback loop of MonOut.
        pub bEDM1: SL_BOOL,
        /// Offset 2. Feedback loop of MonDelOut.
        pub bEDM2: SL_BOOL,
        /// Offset 3. Reserved, keep 0.
        pub aReserved0: [u8; 5],
        /// Offset 8. Monitored input 1 (pair 1 with input 2).
        pub bMonIn1: SL_BOOL,
        /// Offset 9.
        pub bMonIn2: SL_BOOL,
        /// Offset 10. Pair 2 with input 4.
        pub bMonIn3: SL_BOOL,
        /// Offset 11.
        pub bMonIn4: SL_BOOL,
        /// Offset 12. Secure input 1: bypasses the MonIn inputs while logically TRUE.
        pub bSecure1: SL_BOOL,
        /// Offset 13. Secure input 2 (pair with Secure1).
        pub bSecure2: SL_BOOL,
        /// Offset 14. Reserved, keep 0.
        pub aReserved1: [u8; 2],
        /// Offset 16. FbRun of the owning group: TRUE = the block executes.
        pub bRun: SL_BOOL,
        /// Offset 17. ErrAck of the owning group.
        pub bErrAck: SL_BOOL,
        /// Offset 18. Reserved, keep 0.
        pub aReserved2: [u8; 2],
        /// Offset 20. Discrepancy time of pair MonIn1/2 in ms (0 = two single channels).
        pub tDiscTime12: u32,
        /// Offset 24. Discrepancy time of pair MonIn3/4 in ms.
        pub tDiscTime34: u32,
        /// Offset 28. Discrepancy time of pair Secure1/2 in ms.
        pub tDiscTimeSecure12: u32,
        /// Offset 32. EDM1 reset time in ms (EL6910; 0 = off).
        pub tEDM1ResetTime: u32,
        /// Offset 36. EDM2 reset time in ms (EL6910; 0 = off).
        pub tEDM2ResetTime: u32,
        /// Offset 40. Delay of MonDelOut in ms.
        pub tMonDelOutDelay: u32,
        /// Offset 44. Bits 0-3: MonIn1-4 active, bits 4-5: Secure1-2 active.
        pub wInputActive: u16,
        /// Offset 46. Same bits: input is a make contact (negated).
        pub wInputNegated: u16,
        /// Offset 48. SL_OPT_EDM1 | EDM2 | SAFE_INPUTS_AFTER_DISC | MANUAL_RESTART | FUNCTION_TEST.
        pub dwOptions: u32,
        /// Offset 52. Reserved.
        pub aReserved3: [u8; 4],
        /// Offset 56 (output base + 0). TRUE in ERROR.
        pub bError: SL_BOOL,
        /// Offset 57 (output base + 1). Undelayed output.
        pub bMonOut: SL_BOOL,
        /// Offset 58 (output base + 2). Delayed output.
        pub bMonDelOut: SL_BOOL,
        /// Offset 59. Reserved.
        pub aReserved4: [u8; 5],
    } tail 64 65 66 68 72 [aReserved5, aReserved6] SL_GUARD_PRIVATE, 80:
        "(SL_STATE_*)", "Diagnostic bits (SL_DIAG_*; bit 2 = Secure pair)."
}

const MON_INPUTS: u8 = 0x0F;
const SECURE_INPUTS: u8 = 0x30;

crate::base::block::block_states!(
    /// The states of FB MON.
    MonState:
        Run,
        Stop,
        Safe,
        Error,
        Reset,
        Start,
        ErrorDelay = SL_STATE_ERRORDELAY, "ERRORDELAY",
        DelayOut,
        FuncTest = SL_STATE_FUNCTEST, "FUNCTEST"
);

/// Type tag, name and diag texts (manual §4.5.2).
const INFO: BlockInfo = BlockInfo::of::<MonState>(SL_TYPE_MON, "MON").diag(&[
    (SL_DIAG_DISC1, "discrepancy error input group 1"),
    (SL_DIAG_DISC2, "discrepancy error input group 2"),
    (SL_DIAG_DISC3, "discrepancy error in Secure input group"),
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
