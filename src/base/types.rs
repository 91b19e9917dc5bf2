//! Scalar types, status codes, option bits, diagnostic bits and state values of the C ABI
//! (`shared/design/ABI.md` §2, §5, §6; manual §4.4.2 and §4.5.2 for states and diag bits).
//!
//! Every value here is part of the binding contract: the numbers never change.

/// IEC 61131-3 BOOL: 0 = FALSE, 1 = TRUE, any other byte is an invalid BOOL (ABI §2).
#[allow(non_camel_case_types)]
pub type SL_BOOL = u8;

include!(concat!(env!("OUT_DIR"), "/abi/base/types.rs"));

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
