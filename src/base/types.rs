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
/// FSoE (ABI-2 §13.1): a length or capacity does not fit (frame length, SafeData length,
/// transmit buffer capacity); nothing was written.
pub const SL_E_LENGTH: i32 = -11;
/// FSoE (ABI-2 §13.6): a frame was rejected by `sl_fsoe_frame_decode` (the reason is in
/// its `nResetCode`: 2 unknown command, 4 CRC).
pub const SL_E_FRAME: i32 = -12;

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

/// FB_MUTING "Sequential Inputs": the four muting inputs are single-channel sensors checked
/// one after the other (clear: two two-channel groups MutingIn1/2 and MutingIn3/4, parallel).
pub const SL_OPT_MUTING_SEQUENTIAL: u32 = 1 << 8;

/// FB_MUTING "Backwards Mode" (EL6910): a sequence may also run backwards, starting at MutingIn4.
pub const SL_OPT_MUTING_BACKWARDS: u32 = 1 << 9;

/// FB_MUTING "OSSD Check Optional" (EL6910): the protective field is not part of the sequence
/// check; it may be interrupted at any step of a running sequence.
pub const SL_OPT_MUTING_OSSD_CHECK_OPTIONAL: u32 = 1 << 10;

/// Diag bit 6 (FB_MUTING): the muting sequence was violated.
pub const SL_DIAG_MUTING_SEQUENCE: u16 = 1 << 6;

/// Diag bit 7 (FB_MUTING): the maximum muting time was exceeded.
pub const SL_DIAG_MUTING_MAX_TIME: u16 = 1 << 7;

/// FB_TWOHAND diag bit 6: two-hand error (the second group was actuated while the first was
/// no longer actuated, manual §4.7.2).
pub const SL_DIAG_TWOHAND_ERROR: u16 = 1 << 6;

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
/// Diag bit 8: bit 0 with "Safe Inputs after Disc Error" active (set in addition to bit 0).
pub const SL_DIAG_SAFE_IN_DISC1: u16 = 1 << 8;
/// Diag bit 9: bit 1 with "Safe Inputs after Disc Error" active.
pub const SL_DIAG_SAFE_IN_DISC2: u16 = 1 << 9;
/// Diag bit 10: bit 2 with "Safe Inputs after Disc Error" active.
pub const SL_DIAG_SAFE_IN_DISC3: u16 = 1 << 10;
/// Diag bit 11: bit 3 with "Safe Inputs after Disc Error" active.
pub const SL_DIAG_SAFE_IN_DISC4: u16 = 1 << 11;
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

/// Largest time parameter of FB_ESTOP and FB_MON, and largest discrepancy time of FB_OPMODE
/// and FB_TWOHAND, in ms (see docs/semantics.md C10, O3, H3).
pub const SL_TIME_PARAM_MAX: u32 = 65_535;

/// The status of a call inside the library; the C ABI returns its [`Status::code`]
/// (SL_OK, SL_E_*), the Rust face `Ok(())` or `Err(status)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Status {
    /// SL_OK.
    Ok,
    /// SL_E_NULL: a required pointer is NULL.
    Null,
    /// SL_E_CONFIG: invalid parameters; the block stays in STOP with safe outputs.
    Config,
    /// SL_E_PARAM_CHANGED: a parameter changed outside STOP; the block is in ERROR.
    ParamChanged,
    /// SL_E_CORRUPT: the private state failed its integrity check; ERROR.
    Corrupt,
    /// SL_E_INVALID_BOOL: an input byte was neither 0 nor 1 (read as the safe value).
    InvalidBool,
    /// SL_E_CLOCK: the time went backwards; ERROR.
    Clock,
    /// SL_E_INTERNAL: an internal fault was caught; ERROR.
    Internal,
    /// SL_E_ALIGNMENT: a pointer is misaligned.
    Alignment,
    /// SL_E_FULL: group storage full.
    Full,
    /// SL_E_RESTORE: a restored elapsed time was refused; ERROR.
    Restore,
    /// SL_E_LENGTH: a length or capacity does not fit (FSoE).
    Length,
    /// SL_E_FRAME: a frame was rejected (FSoE codec).
    Frame,
}

impl Status {
    /// The C status code.
    pub const fn code(self) -> i32 {
        match self {
            Status::Ok => SL_OK,
            Status::Null => SL_E_NULL,
            Status::Config => SL_E_CONFIG,
            Status::ParamChanged => SL_E_PARAM_CHANGED,
            Status::Corrupt => SL_E_CORRUPT,
            Status::InvalidBool => SL_E_INVALID_BOOL,
            Status::Clock => SL_E_CLOCK,
            Status::Internal => SL_E_INTERNAL,
            Status::Alignment => SL_E_ALIGNMENT,
            Status::Full => SL_E_FULL,
            Status::Restore => SL_E_RESTORE,
            Status::Length => SL_E_LENGTH,
            Status::Frame => SL_E_FRAME,
        }
    }

    /// The status of a C code; a code the library never returns reads as `Internal`.
    pub const fn from_code(code: i32) -> Status {
        match code {
            SL_OK => Status::Ok,
            SL_E_NULL => Status::Null,
            SL_E_CONFIG => Status::Config,
            SL_E_PARAM_CHANGED => Status::ParamChanged,
            SL_E_CORRUPT => Status::Corrupt,
            SL_E_INVALID_BOOL => Status::InvalidBool,
            SL_E_CLOCK => Status::Clock,
            SL_E_ALIGNMENT => Status::Alignment,
            SL_E_FULL => Status::Full,
            SL_E_RESTORE => Status::Restore,
            SL_E_LENGTH => Status::Length,
            SL_E_FRAME => Status::Frame,
            _ => Status::Internal,
        }
    }

    /// `Ok(())` or `Err(self)`.
    pub fn result(self) -> Result<(), Status> {
        match self {
            Status::Ok => Ok(()),
            e => Err(e),
        }
    }

    /// The more serious of two statuses (several things can go wrong in one call; the call
    /// reports the worst): corrupt/internal > clock > parameter changed / restore refused >
    /// config > invalid BOOL > OK.
    #[inline]
    pub const fn worst(self, other: Status) -> Status {
        const fn rank(s: Status) -> u8 {
            match s {
                Status::Corrupt | Status::Internal => 6,
                Status::Clock => 5,
                Status::ParamChanged | Status::Restore => 4,
                Status::Config | Status::Length | Status::Frame => 3,
                Status::InvalidBool => 2,
                _ => 0,
            }
        }
        // The ranks by discriminant, built from `rank` (one load per call in a group cycle
        // instead of two chains of comparisons).
        const RANK: [u8; 13] = {
            let all = [
                Status::Ok,
                Status::Null,
                Status::Config,
                Status::ParamChanged,
                Status::Corrupt,
                Status::InvalidBool,
                Status::Clock,
                Status::Internal,
                Status::Alignment,
                Status::Full,
                Status::Restore,
                Status::Length,
                Status::Frame,
            ];
            let mut t = [0u8; 13];
            let mut i = 0;
            while i < all.len() {
                t[all[i] as usize] = rank(all[i]);
                i += 1;
            }
            t
        };
        if RANK[other as usize] > RANK[self as usize] {
            other
        } else {
            self
        }
    }
}

impl core::fmt::Display for Status {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(status_str(self.code()))
    }
}

/// A status compares equal to its C code (tests and hosts hold codes as `i32`).
impl PartialEq<i32> for Status {
    fn eq(&self, code: &i32) -> bool {
        self.code() == *code
    }
}

/// Text for a status code without the C terminator.
pub fn status_str(status: i32) -> &'static str {
    status_text(status).trim_end_matches('\0')
}

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
        SL_E_LENGTH => {
            "SL_E_LENGTH: a frame length, SafeData length or buffer capacity does not fit; nothing written\0"
        }
        SL_E_FRAME => "SL_E_FRAME: the FSoE frame was rejected (reason in nResetCode)\0",
        _ => "unknown status code\0",
    }
}
