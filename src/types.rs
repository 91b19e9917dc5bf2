//! Scalar types, status codes, option bits, diagnostic bits and state values of the C ABI
//! (`shared/design/ABI.md` §2, §5, §6; manual §4.4.2 and §4.5.2 for states and diag bits).
//!
//! Every value here is part of the binding contract: the numbers never change.

/// IEC 61131-3 BOOL: 0 = FALSE, 1 = TRUE, any other byte is an invalid BOOL (ABI §2).
#[allow(non_camel_case_types)]
pub type SL_BOOL = u8;

/// Success.
pub const SL_OK: i32 = 0;
/// A required pointer is NULL; nothing was written.
pub const SL_E_NULL: i32 = -1;
/// Invalid parameters; outputs safe (all FALSE), nState = STOP (2).
pub const SL_E_CONFIG: i32 = -2;
/// A parameter changed while the block was not in STOP; nState = ERROR (4), bError TRUE.
pub const SL_E_PARAM_CHANGED: i32 = -3;
/// The private state failed its integrity check; nState = ERROR (4), bError TRUE.
pub const SL_E_CORRUPT: i32 = -4;
/// An input byte was not 0 or 1; it was read as the value that demands the safe state.
pub const SL_E_INVALID_BOOL: i32 = -5;
/// tNow went backwards (wrapping difference to the last call >= 2^31); nState = ERROR (4).
pub const SL_E_CLOCK: i32 = -6;
/// Library extension: an internal fault was caught at the C boundary; the instance was put
/// into ERROR (4) with every output FALSE except bError.
pub const SL_E_INTERNAL: i32 = -7;
/// Library extension: the instance pointer is not aligned to 4 bytes; nothing was written.
pub const SL_E_ALIGNMENT: i32 = -8;
/// Library extension: the caller's member or link storage of a group is full.
pub const SL_E_FULL: i32 = -9;
/// Library extension (FB_TON2, "Starts with remaining time"): a restored elapsed time was
/// refused, because it is greater than the latched tDelay (the manual's global shutdown,
/// error code 0x3510) or because `sl_ton2_restore_elapsed` was called while the block was
/// not in STOP. nState = ERROR (4), output FALSE, diag bit 12 (SL_DIAG_TON2_RESTORE); the
/// stored elapsed time is discarded (0), so one ErrAck sequence leaves the error.
pub const SL_E_RESTORE: i32 = -10;

/// EDM1 feedback loop active.
pub const SL_OPT_EDM1: u32 = 1 << 0;
/// EDM2 feedback loop active.
pub const SL_OPT_EDM2: u32 = 1 << 1;
/// "Safe Inputs after Disc Error".
pub const SL_OPT_SAFE_INPUTS_AFTER_DISC: u32 = 1 << 2;
/// Manual (active) restart (MON; ESTOP always restarts manually).
pub const SL_OPT_MANUAL_RESTART: u32 = 1 << 3;
/// Manual function test (MON).
pub const SL_OPT_FUNCTION_TEST: u32 = 1 << 4;
/// FB_TON2 "Starts with remaining time" (manual §4.13): with Enable TRUE when TonIn rises,
/// the timer starts with tDelay minus the stored elapsed time.
pub const SL_OPT_TON2_REMAINING_TIME: u32 = 1 << 8;
/// FB_MUTING "Sequential Inputs": the four muting inputs are single-channel sensors checked
/// one after the other (clear: two two-channel groups MutingIn1/2 and MutingIn3/4, parallel).
pub const SL_OPT_MUTING_SEQUENTIAL: u32 = 1 << 8;
/// FB_MUTING "Backwards Mode" (EL6910): a sequence may also run backwards, starting at MutingIn4.
pub const SL_OPT_MUTING_BACKWARDS: u32 = 1 << 9;
/// FB_MUTING "OSSD Check Optional" (EL6910): the protective field is not part of the sequence
/// check; it may be interrupted at any step of a running sequence.
pub const SL_OPT_MUTING_OSSD_CHECK_OPTIONAL: u32 = 1 << 10;

bitflags::bitflags! {
    /// The option bits of `dwOptions` (ABI §6) as a typed set.
    #[derive(Clone, Copy, Debug, PartialEq, Eq)]
    pub struct Options: u32 {
        const EDM1 = SL_OPT_EDM1;
        const EDM2 = SL_OPT_EDM2;
        const SAFE_INPUTS_AFTER_DISC = SL_OPT_SAFE_INPUTS_AFTER_DISC;
        const MANUAL_RESTART = SL_OPT_MANUAL_RESTART;
        const FUNCTION_TEST = SL_OPT_FUNCTION_TEST;
        const MUTING_SEQUENTIAL = SL_OPT_MUTING_SEQUENTIAL;
        const MUTING_BACKWARDS = SL_OPT_MUTING_BACKWARDS;
        const MUTING_OSSD_CHECK_OPTIONAL = SL_OPT_MUTING_OSSD_CHECK_OPTIONAL;
    }
}

/// Diag bit 0: discrepancy error input group 1.
pub const SL_DIAG_DISC1: u16 = 1 << 0;
/// Diag bit 1: discrepancy error input group 2.
pub const SL_DIAG_DISC2: u16 = 1 << 1;
/// Diag bit 2: discrepancy error input group 3 (MON: the Secure input group).
pub const SL_DIAG_DISC3: u16 = 1 << 2;
/// Diag bit 3: discrepancy error input group 4.
pub const SL_DIAG_DISC4: u16 = 1 << 3;
/// Diag bit 4: EDM monitoring error EDM1.
pub const SL_DIAG_EDM1: u16 = 1 << 4;
/// Diag bit 5: EDM monitoring error EDM2.
pub const SL_DIAG_EDM2: u16 = 1 << 5;
/// Diag bit 6 (FB_MUTING): the muting sequence was violated.
pub const SL_DIAG_MUTING_SEQUENCE: u16 = 1 << 6;
/// Diag bit 7 (FB_MUTING): the maximum muting time was exceeded.
pub const SL_DIAG_MUTING_MAX_TIME: u16 = 1 << 7;
/// Diag bit 8: bit 0 with "Safe Inputs after Disc Error" active (set in addition to bit 0).
pub const SL_DIAG_SAFE_IN_DISC1: u16 = 1 << 8;
/// Diag bit 9: bit 1 with "Safe Inputs after Disc Error" active.
pub const SL_DIAG_SAFE_IN_DISC2: u16 = 1 << 9;
/// Diag bit 10: bit 2 with "Safe Inputs after Disc Error" active.
pub const SL_DIAG_SAFE_IN_DISC3: u16 = 1 << 10;
/// Diag bit 11: bit 3 with "Safe Inputs after Disc Error" active.
pub const SL_DIAG_SAFE_IN_DISC4: u16 = 1 << 11;
/// FB_OPMODE diag bit 0: discrepancy monitoring error (no mode or more than one mode selected
/// for tDiscTime, manual §4.3.2).
pub const SL_DIAG_OPMODE_DISC: u16 = 1 << 0;
/// FB_TWOHAND diag bit 2: discrepancy error between the two input pairs (the second group was
/// not actuated within tDiscTimePairs, manual §4.7.2). Bits 0/1 are SL_DIAG_DISC1/2.
pub const SL_DIAG_TWOHAND_PAIRS: u16 = 1 << 2;
/// FB_TWOHAND diag bit 6: two-hand error (the second group was actuated while the first was
/// no longer actuated, manual §4.7.2).
pub const SL_DIAG_TWOHAND_ERROR: u16 = 1 << 6;
/// FB_TWOHAND diag bit 10: bit 2 with "Safe Inputs after Disc Error" active (set in addition
/// to bit 2). Bits 8/9 are SL_DIAG_SAFE_IN_DISC1/2.
pub const SL_DIAG_TWOHAND_SAFE_IN_PAIRS: u16 = 1 << 10;
/// Library extension, FB_TON2 diag bit 12: the restored elapsed time was refused
/// (SL_E_RESTORE; the manual's global shutdown 0x3510).
pub const SL_DIAG_TON2_RESTORE: u16 = 1 << 12;
/// Library extension, diag bit 13: a parameter changed outside STOP (SL_E_PARAM_CHANGED).
pub const SL_DIAG_PARAM_CHANGED: u16 = 1 << 13;
/// Library extension, diag bit 14: the clock went backwards (SL_E_CLOCK).
pub const SL_DIAG_CLOCK: u16 = 1 << 14;
/// Library extension, diag bit 15: the private state was corrupt (SL_E_CORRUPT / SL_E_INTERNAL).
pub const SL_DIAG_CORRUPT: u16 = 1 << 15;

/// The library's own diag bits (13-15); the rest of `nDiag` is the manual's bits or value.
pub const LIBRARY_DIAG_BITS: u16 = SL_DIAG_PARAM_CHANGED | SL_DIAG_CLOCK | SL_DIAG_CORRUPT;

bitflags::bitflags! {
    /// The diagnostic bits of `nDiag` as a typed set.
    #[derive(Clone, Copy, Debug, PartialEq, Eq)]
    pub struct Diag: u16 {
        const DISC1 = SL_DIAG_DISC1;
        const DISC2 = SL_DIAG_DISC2;
        const DISC3 = SL_DIAG_DISC3;
        const DISC4 = SL_DIAG_DISC4;
        const EDM1 = SL_DIAG_EDM1;
        const EDM2 = SL_DIAG_EDM2;
        const MUTING_SEQUENCE = SL_DIAG_MUTING_SEQUENCE;
        const MUTING_MAX_TIME = SL_DIAG_MUTING_MAX_TIME;
        const SAFE_IN_DISC1 = SL_DIAG_SAFE_IN_DISC1;
        const SAFE_IN_DISC2 = SL_DIAG_SAFE_IN_DISC2;
        const SAFE_IN_DISC3 = SL_DIAG_SAFE_IN_DISC3;
        const SAFE_IN_DISC4 = SL_DIAG_SAFE_IN_DISC4;
        const TWOHAND_ERROR = SL_DIAG_TWOHAND_ERROR;
        const PARAM_CHANGED = SL_DIAG_PARAM_CHANGED;
        const CLOCK = SL_DIAG_CLOCK;
        const CORRUPT = SL_DIAG_CORRUPT;
    }
}

/// State RUN (manual: status value 1).
pub const SL_STATE_RUN: u8 = 1;
/// State STOP (2).
pub const SL_STATE_STOP: u8 = 2;
/// State SAFE (3).
pub const SL_STATE_SAFE: u8 = 3;
/// State ERROR (4).
pub const SL_STATE_ERROR: u8 = 4;
/// State RESET (5).
pub const SL_STATE_RESET: u8 = 5;
/// State START (6).
pub const SL_STATE_START: u8 = 6;
/// State ERRORDELAY (7, MON).
pub const SL_STATE_ERRORDELAY: u8 = 7;
/// State DELAYOUT (8).
pub const SL_STATE_DELAYOUT: u8 = 8;
/// State FUNCTEST (9, MON).
pub const SL_STATE_FUNCTEST: u8 = 9;
/// FB_TWOHAND state 1BUTTON (11): every active input of the first group is TRUE, the second
/// group is not actuated yet (manual §4.7.2).
pub const SL_STATE_TWOHAND_1BUTTON: u8 = 11;
/// FB_TWOHAND state 2BUTTON (12): every active input of the second group is TRUE, the first
/// group is not actuated yet.
pub const SL_STATE_TWOHAND_2BUTTON: u8 = 12;
/// FB_TWOHAND state RELEASE (13): waiting until every active input is FALSE before the output
/// can be set again.
pub const SL_STATE_TWOHAND_RELEASE: u8 = 13;
/// FB_TON state DELAYIN (9): TonIn is TRUE and the delay has not yet expired.
pub const SL_STATE_TON_DELAYIN: u8 = 9;
/// FB_TON2 state DELAYIN (9): TonIn is TRUE and the delay has not yet expired.
pub const SL_STATE_TON2_DELAYIN: u8 = 9;
/// FB_MUTING state MUTING1 (9): first step of the muting sequence (docs/semantics.md M1).
pub const SL_STATE_MUTING_MUTING1: u8 = 9;
/// FB_MUTING state MUTING2 (10).
pub const SL_STATE_MUTING_MUTING2: u8 = 10;
/// FB_MUTING state MUTING3 (11).
pub const SL_STATE_MUTING_MUTING3: u8 = 11;
/// FB_MUTING state MUTING4 (12).
pub const SL_STATE_MUTING_MUTING4: u8 = 12;
/// FB_MUTING state MUTING5 (13).
pub const SL_STATE_MUTING_MUTING5: u8 = 13;
/// FB_MUTING state MUTING6 (14).
pub const SL_STATE_MUTING_MUTING6: u8 = 14;
/// FB_MUTING state MUTING7 (15).
pub const SL_STATE_MUTING_MUTING7: u8 = 15;
/// FB_MUTING state MUTING8 (16).
pub const SL_STATE_MUTING_MUTING8: u8 = 16;
/// FB_MUTING state MUTING9 (17): last step of the muting sequence.
pub const SL_STATE_MUTING_MUTING9: u8 = 17;

/// Block type tag of FB_ESTOP (`SL_MEMBER.nType`, `sl_diag_text`).
pub const SL_TYPE_ESTOP: u16 = 1;
/// Block type tag of FB_MON.
pub const SL_TYPE_MON: u16 = 2;
/// Block type tag of FB_AND.
pub const SL_TYPE_AND: u16 = 3;
/// Block type tag of FB_OR.
pub const SL_TYPE_OR: u16 = 4;
/// Block type tag of FB_OPMODE.
pub const SL_TYPE_OPMODE: u16 = 7;
/// Block type tag of FB_TWOHAND.
pub const SL_TYPE_TWOHAND: u16 = 8;
/// Block type tag of FB_TON.
pub const SL_TYPE_TON: u16 = 13;
/// Block type tag of FB_TON2.
pub const SL_TYPE_TON2: u16 = 14;
/// Block type tag of FB_TOF.
pub const SL_TYPE_TOF: u16 = 15;
/// Block type tag of FB_MUTING.
pub const SL_TYPE_MUTING: u16 = 9;

/// Block type tag of FB_XOR.
pub const SL_TYPE_XOR: u16 = 5;
/// Block type tag of FB_DECOUPLE.
pub const SL_TYPE_DECOUPLE: u16 = 6;
/// Block type tag of FB_EDM.
pub const SL_TYPE_EDM: u16 = 10;
/// Block type tag of FB_RS.
pub const SL_TYPE_RS: u16 = 11;
/// Block type tag of FB_SR.
pub const SL_TYPE_SR: u16 = 12;

/// FB_EDM state MONOFF (manual §4.9.2: 14): Mon1 is FALSE, switch-off monitoring.
pub const SL_STATE_EDM_MONOFF: u8 = 14;
/// FB_EDM state MONON (manual §4.9.2: 15): Mon1 is TRUE, switch-on monitoring.
pub const SL_STATE_EDM_MONON: u8 = 15;
/// FB_RS state SET (manual §4.10.2: 9): the output RsOut is TRUE.
pub const SL_STATE_RS_SET: u8 = 9;
/// FB_SR state SET (manual §4.11.2: 9): the output SrOut is TRUE.
pub const SL_STATE_SR_SET: u8 = 9;

/// FB_EDM diag bit 0 (manual §4.9.2): switch-off timer elapsed.
pub const SL_DIAG_EDM_SWITCH_OFF: u16 = 1 << 0;
/// FB_EDM diag bit 1 (manual §4.9.2): switch-on timer elapsed.
pub const SL_DIAG_EDM_SWITCH_ON: u16 = 1 << 1;

/// Largest tSwitchOnTime / tSwitchOffTime of FB_EDM in ms (manual §4.9.1: "maximum 10000 ms").
pub const SL_EDM_TIME_MAX: u32 = 10_000;

/// Largest time parameter of FB_ESTOP and FB_MON, and largest discrepancy time of FB_OPMODE
/// and FB_TWOHAND, in ms (see docs/semantics.md C10, O3, H3).
pub const SL_TIME_PARAM_MAX: u32 = 65_535;
/// Largest tDiscTimePairs of FB_TWOHAND in ms (manual §4.7.1: "up to 2500 ms").
pub const SL_TWOHAND_PAIRS_TIME_MAX: u32 = 2_500;

/// The more serious of two status codes (several things can go wrong in one call; the
/// call reports the worst): corrupt/internal > clock > parameter changed / restore refused >
/// config > invalid BOOL > OK.
pub const fn worst_status(a: i32, b: i32) -> i32 {
    const fn rank(s: i32) -> u8 {
        match s {
            SL_E_CORRUPT | SL_E_INTERNAL => 6,
            SL_E_CLOCK => 5,
            SL_E_PARAM_CHANGED | SL_E_RESTORE => 4,
            SL_E_CONFIG => 3,
            SL_E_INVALID_BOOL => 2,
            _ => 0,
        }
    }
    if rank(b) > rank(a) {
        b
    } else {
        a
    }
}

/// Text for a status code without the C terminator.
pub fn status_str(status: i32) -> &'static str {
    status_text(status).trim_end_matches('\0')
}

/// `nTimeBase` of FB_TON/FB_TON2/FB_TOF: automatic, the smallest timebase whose range
/// holds tDelay (the manual: "automatically selected ... according to the set time").
pub const SL_TIMEBASE_AUTO: u16 = 0;
/// `nTimeBase` 1 ms: tDelay 1 to 60,000 ms in 1 ms steps.
pub const SL_TIMEBASE_1MS: u16 = 1;
/// `nTimeBase` 10 ms: tDelay 10 to 600,000 ms in 10 ms steps.
pub const SL_TIMEBASE_10MS: u16 = 10;
/// `nTimeBase` 100 ms (EL6910 SW 04): tDelay 100 ms to 6,000 s in 100 ms steps.
pub const SL_TIMEBASE_100MS: u16 = 100;
/// `nTimeBase` 1000 ms (EL6910 SW 04): tDelay 1 s to 60,000 s in 1 s steps.
pub const SL_TIMEBASE_1000MS: u16 = 1000;
/// Most timebase steps in a timer delay (tDelay / timebase).
pub const SL_TIMER_STEPS_MAX: u32 = 60_000;
/// Largest timer delay in ms (60,000 s; 60,000 steps of 1000 ms).
pub const SL_TIMER_DELAY_MAX: u32 = 60_000_000;

/// Largest `tFilterTime` of FB_MUTING in ms (manual §4.8.1: "up to 500 ms").
pub const SL_MUTING_FILTER_TIME_MAX: u32 = 500;
/// Largest `tMaxMutingTime` of FB_MUTING in ms (manual §4.8.1: "a maximum of 10 minutes").
pub const SL_MUTING_MAX_MUTING_TIME_MAX: u32 = 600_000;
/// Largest `tMuteDelOutDelay` of FB_MUTING in ms (manual §4.8.1: "delayed by up to 30 seconds").
pub const SL_MUTING_DELOUT_DELAY_MAX: u32 = 30_000;

/// Text for a status code (for `sl_status_str`); NUL-terminated so C can use it directly.
pub const fn status_text(status: i32) -> &'static str {
    match status {
        SL_OK => "SL_OK: success\0",
        SL_E_NULL => "SL_E_NULL: a required pointer is NULL\0",
        SL_E_CONFIG => "SL_E_CONFIG: invalid parameters; block held in STOP with safe outputs\0",
        SL_E_PARAM_CHANGED => {
            "SL_E_PARAM_CHANGED: a parameter changed outside STOP; block in ERROR\0"
        }
        SL_E_CORRUPT => "SL_E_CORRUPT: private state failed its integrity check; block in ERROR\0",
        SL_E_INVALID_BOOL => {
            "SL_E_INVALID_BOOL: an input byte was neither 0 nor 1; read as the safe value\0"
        }
        SL_E_CLOCK => "SL_E_CLOCK: tNow went backwards; block in ERROR\0",
        SL_E_INTERNAL => "SL_E_INTERNAL: internal fault caught at the C boundary; block in ERROR\0",
        SL_E_ALIGNMENT => "SL_E_ALIGNMENT: instance pointer not aligned to 4 bytes\0",
        SL_E_FULL => "SL_E_FULL: the group's member or link storage is full\0",
        SL_E_RESTORE => {
            "SL_E_RESTORE: restored elapsed time refused (greater than tDelay, or block not in STOP); block in ERROR\0"
        }
        _ => "unknown status code\0",
    }
}
