//! safelogic — TwinSAFE-style safety logic function blocks behind a C ABI.
//!
//! The block layer (`types`, `prim`, `blocks`) is `no_std`, allocation-free and free of
//! `unsafe`; the C ABI (`ffi`, feature `std`) is the only place with `unsafe` code.
//! Not a certified safety component: see README.md.

#![cfg_attr(not(feature = "std"), no_std)]
#![deny(unsafe_code)]

pub mod blocks;
pub mod group;
pub mod prim;
pub mod registry;
pub mod types;

#[cfg(feature = "std")]
pub mod ffi;

pub use blocks::and::FB_AND;
pub use blocks::arith::{
    FB_ADD_DINT, FB_ADD_INT, FB_ADD_UDINT, FB_ADD_UINT, FB_DIV_DINT, FB_DIV_INT, FB_DIV_UDINT,
    FB_DIV_UINT, FB_MUL_DINT, FB_MUL_INT, FB_MUL_UDINT, FB_MUL_UINT, FB_SUB_DINT, FB_SUB_INT,
    FB_SUB_UDINT, FB_SUB_UINT,
};
pub use blocks::decouple::FB_DECOUPLE;
pub use blocks::edm::{FB_EDM, SL_EDM_PRIVATE};
pub use blocks::estop::FB_ESTOP;
pub use blocks::flipflop::SL_FLIPFLOP_PRIVATE;
pub use blocks::guard::SL_GUARD_PRIVATE;
pub use blocks::logic::SL_LOGIC_PRIVATE;
pub use blocks::mon::FB_MON;
pub use blocks::muting::{FB_MUTING, SL_MUTING_PRIVATE};
pub use blocks::opmode::{FB_OPMODE, SL_OPMODE_PRIVATE};
pub use blocks::or::FB_OR;
pub use blocks::rs::FB_RS;
pub use blocks::sr::FB_SR;
pub use blocks::state_name;
pub use blocks::timer::SL_TIMER_PRIVATE;
pub use blocks::tof::FB_TOF;
pub use blocks::ton::FB_TON;
pub use blocks::ton2::FB_TON2;
pub use blocks::twohand::{FB_TWOHAND, SL_TWOHAND_PRIVATE};
pub use blocks::xor::FB_XOR;
pub use group::{SL_GROUP, SL_GROUP_PRIVATE, SL_LINK, SL_MEMBER};
pub use prim::header::SL_PRIVATE_HEADER;
pub use types::*;

/// A refusal or fault reported by a block call: the C ABI's negative status codes as a Rust
/// value (`SL_OK` is `Ok(())`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Status {
    /// SL_E_NULL.
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
    /// SL_E_ALIGNMENT.
    Alignment,
    /// SL_E_FULL: group storage full.
    Full,
    /// SL_E_RESTORE: a restored elapsed time was refused; ERROR.
    Restore,
    /// A code this library version does not know.
    Unknown(i32),
}

impl Status {
    /// `Ok(())` for `SL_OK`, else the status.
    pub fn check(code: i32) -> Result<(), Status> {
        Err(match code {
            SL_OK => return Ok(()),
            SL_E_NULL => Status::Null,
            SL_E_CONFIG => Status::Config,
            SL_E_PARAM_CHANGED => Status::ParamChanged,
            SL_E_CORRUPT => Status::Corrupt,
            SL_E_INVALID_BOOL => Status::InvalidBool,
            SL_E_CLOCK => Status::Clock,
            SL_E_INTERNAL => Status::Internal,
            SL_E_ALIGNMENT => Status::Alignment,
            SL_E_FULL => Status::Full,
            SL_E_RESTORE => Status::Restore,
            other => Status::Unknown(other),
        })
    }

    /// The C status code.
    pub fn code(self) -> i32 {
        match self {
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
            Status::Unknown(c) => c,
        }
    }
}

impl core::fmt::Display for Status {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(status_str(self.code()))
    }
}

/// The Rust face of every block. `init` / `cycle` return the C status code (the same calls
/// as `sl_<name>_init` / `sl_<name>_cycle`); `try_init` / `try_cycle` return a `Result`.
///
/// ```
/// use safelogic::{FunctionBlock, Status, FB_ESTOP, SL_STATE_RUN};
///
/// let mut estop = FB_ESTOP { wInputActive: 0b11, tDiscTime12: 100, ..Default::default() };
/// estop.try_init()?;
/// (estop.bEStopIn1, estop.bEStopIn2, estop.bRun) = (1, 1, 1);
/// estop.try_cycle(0)?;
/// estop.bRestart = 1;
/// estop.try_cycle(10)?;
/// estop.bRestart = 0; // the falling edge of Restart enables the outputs
/// estop.try_cycle(20)?;
/// assert_eq!((estop.state_name(), estop.bEStopOut), ("RUN", 1));
/// # Ok::<(), Status>(())
/// ```
pub trait FunctionBlock {
    /// Validates and latches the parameters and resets the block to power-up (STOP).
    fn init(&mut self) -> i32;
    /// One task cycle at `now` (monotonic ms, wrapping).
    fn cycle(&mut self, now: u32) -> i32;
    /// [`Self::init`] as a `Result`.
    fn try_init(&mut self) -> Result<(), Status> {
        Status::check(self.init())
    }
    /// [`Self::cycle`] as a `Result`.
    fn try_cycle(&mut self, now: u32) -> Result<(), Status> {
        Status::check(self.cycle(now))
    }
    /// The manual's name of the current state ("RUN", "DELAYOUT", …).
    fn state_name(&self) -> &'static str;
    /// The block is in ERROR.
    fn is_error(&self) -> bool;
}

impl<B: prim::envelope::Block + registry::Registered + group::Member> FunctionBlock for B {
    fn init(&mut self) -> i32 {
        prim::envelope::init(self)
    }
    fn cycle(&mut self, now: u32) -> i32 {
        prim::envelope::cycle(self, now)
    }
    fn state_name(&self) -> &'static str {
        blocks::state_name(B::INFO.tag, self.state())
    }
    fn is_error(&self) -> bool {
        self.state() == SL_STATE_ERROR
    }
}
