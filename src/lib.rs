//! safelogic — TwinSAFE-style safety logic function blocks behind a C ABI.
//!
//! Every block is a caller-allocated struct (`FB_ESTOP`, `FB_ADD_DINT`, …) with the C
//! layout; Rust code drives it through [`FunctionBlock`]:
//!
//! ```
//! use safelogic::{FunctionBlock, Status, FB_ADD_INT, FB_ESTOP};
//!
//! // E-stop with one two-channel pair; the falling edge of Restart enables the output.
//! let mut estop = FB_ESTOP { wInputActive: 0b11, tDiscTime12: 100, ..Default::default() };
//! estop.try_init()?;
//! for (name, value) in [("bEStopIn1", 1), ("bEStopIn2", 1), ("bRun", 1)] {
//!     estop.set(name, value)?;
//! }
//! for (t, restart) in [(0, 0), (10, 1), (20, 0)] {
//!     estop.set("bRestart", restart)?;
//!     estop.try_cycle(t)?;
//! }
//! assert_eq!((estop.state_name(), estop.get_bool("bEStopOut")), ("RUN", Some(true)));
//!
//! // Exact integer arithmetic: an overflow is an ERROR with the output 0, never a wrap.
//! let mut add = FB_ADD_INT { wInputActive: 0x0300, nAnalogIn1: 30_000, nAnalogIn2: 2_768, ..Default::default() };
//! add.try_init()?;
//! add.bRun = 1;
//! add.try_cycle(0)?;
//! assert!(add.is_error() && add.nAnalogOut == 0 && add.nDiagTextId == 0x4081);
//! # Ok::<(), Status>(())
//! ```
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
pub use blocks::and::SL_TYPE_AND;
pub use blocks::arith::{
    FB_ADD_DINT, FB_ADD_INT, FB_ADD_UDINT, FB_ADD_UINT, FB_DIV_DINT, FB_DIV_INT, FB_DIV_UDINT,
    FB_DIV_UINT, FB_MUL_DINT, FB_MUL_INT, FB_MUL_UDINT, FB_MUL_UINT, FB_SUB_DINT, FB_SUB_INT,
    FB_SUB_UDINT, FB_SUB_UINT,
};
pub use blocks::decouple::FB_DECOUPLE;
pub use blocks::decouple::SL_TYPE_DECOUPLE;
pub use blocks::edm::{FB_EDM, SL_EDM_PRIVATE};
pub use blocks::edm::{
    SL_DIAG_EDM_SWITCH_OFF, SL_DIAG_EDM_SWITCH_ON, SL_EDM_TIME_MAX, SL_STATE_EDM_MONOFF,
    SL_STATE_EDM_MONON, SL_TYPE_EDM,
};
pub use blocks::estop::FB_ESTOP;
pub use blocks::estop::SL_TYPE_ESTOP;
pub use blocks::flipflop::SL_FLIPFLOP_PRIVATE;
pub use blocks::guard::SL_GUARD_PRIVATE;
pub use blocks::logic::SL_LOGIC_PRIVATE;
pub use blocks::mon::FB_MON;
pub use blocks::mon::SL_TYPE_MON;
pub use blocks::muting::{FB_MUTING, SL_MUTING_PRIVATE};
pub use blocks::muting::{
    SL_DIAG_MUTING_MAX_TIME, SL_DIAG_MUTING_SEQUENCE, SL_MUTING_DELOUT_DELAY_MAX,
    SL_MUTING_FILTER_TIME_MAX, SL_MUTING_MAX_MUTING_TIME_MAX, SL_OPT_MUTING_BACKWARDS,
    SL_OPT_MUTING_OSSD_CHECK_OPTIONAL, SL_OPT_MUTING_SEQUENTIAL, SL_STATE_MUTING_MUTING1,
    SL_STATE_MUTING_MUTING2, SL_STATE_MUTING_MUTING3, SL_STATE_MUTING_MUTING4,
    SL_STATE_MUTING_MUTING5, SL_STATE_MUTING_MUTING6, SL_STATE_MUTING_MUTING7,
    SL_STATE_MUTING_MUTING8, SL_STATE_MUTING_MUTING9, SL_TYPE_MUTING,
};
pub use blocks::opmode::{FB_OPMODE, SL_OPMODE_PRIVATE};
pub use blocks::opmode::{SL_DIAG_OPMODE_DISC, SL_TYPE_OPMODE};
pub use blocks::or::FB_OR;
pub use blocks::or::SL_TYPE_OR;
pub use blocks::rs::FB_RS;
pub use blocks::rs::SL_TYPE_RS;
pub use blocks::sr::FB_SR;
pub use blocks::sr::SL_TYPE_SR;
pub use blocks::state_name;
pub use blocks::timer::SL_TIMER_PRIVATE;
pub use blocks::timer::{
    SL_DIAG_TON2_RESTORE, SL_OPT_TON2_REMAINING_TIME, SL_TIMEBASE_1000MS, SL_TIMEBASE_100MS,
    SL_TIMEBASE_10MS, SL_TIMEBASE_1MS, SL_TIMEBASE_AUTO, SL_TIMER_DELAY_MAX, SL_TIMER_STEPS_MAX,
};
pub use blocks::tof::FB_TOF;
pub use blocks::tof::SL_TYPE_TOF;
pub use blocks::ton::FB_TON;
pub use blocks::ton::{SL_STATE_TON_DELAYIN, SL_TYPE_TON};
pub use blocks::ton2::FB_TON2;
pub use blocks::ton2::{SL_STATE_TON2_DELAYIN, SL_TYPE_TON2};
pub use blocks::twohand::{FB_TWOHAND, SL_TWOHAND_PRIVATE};
pub use blocks::twohand::{
    SL_DIAG_TWOHAND_ERROR, SL_DIAG_TWOHAND_PAIRS, SL_DIAG_TWOHAND_SAFE_IN_PAIRS,
    SL_STATE_TWOHAND_1BUTTON, SL_STATE_TWOHAND_2BUTTON, SL_STATE_TWOHAND_RELEASE,
    SL_TWOHAND_PAIRS_TIME_MAX, SL_TYPE_TWOHAND,
};
pub use blocks::xor::FB_XOR;
pub use blocks::xor::SL_TYPE_XOR;
pub use group::{SL_GROUP, SL_GROUP_PRIVATE, SL_LINK, SL_MEMBER};
pub use prim::header::SL_PRIVATE_HEADER;
pub use types::*;

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
        Status::from_code(self.init()).result()
    }
    /// [`Self::cycle`] as a `Result`.
    fn try_cycle(&mut self, now: u32) -> Result<(), Status> {
        Status::from_code(self.cycle(now)).result()
    }
    /// The manual's name of the current state ("RUN", "DELAYOUT", …).
    fn state_name(&self) -> &'static str;
    /// The block is in ERROR.
    fn is_error(&self) -> bool;
    /// A field by its name in the field table (`"bEStopOut"`, `"nAnalogOut"`, `"tDelay"`):
    /// its value as a 32-bit pattern (signed types sign-extended), `None` for an unknown name.
    fn get(&self, name: &str) -> Option<u32>;
    /// A BOOL field by name as `bool` (`None`: unknown, not a BOOL, or not 0/1).
    fn get_bool(&self, name: &str) -> Option<bool> {
        let f = self.field(name)?;
        match (f.kind, self.get(name)?) {
            (registry::Kind::Bool, 0) => Some(false),
            (registry::Kind::Bool, 1) => Some(true),
            _ => None,
        }
    }
    /// Writes an input or a parameter by name; `Err(Status::Config)` for an unknown name, an
    /// output or info field, or a value outside the field's type.
    fn set(&mut self, name: &str, value: i64) -> Result<(), Status>;
    /// The field-table entry of a name.
    fn field(&self, name: &str) -> Option<&'static registry::Field>;
}

impl<B: prim::envelope::Block + registry::Registered + group::Member> FunctionBlock for B {
    fn init(&mut self) -> i32 {
        prim::envelope::init(self).code()
    }
    fn cycle(&mut self, now: u32) -> i32 {
        prim::envelope::cycle(self, now).code()
    }
    fn state_name(&self) -> &'static str {
        blocks::state_name(B::INFO.tag, self.state())
    }
    fn is_error(&self) -> bool {
        self.state() == SL_STATE_ERROR
    }
    fn get(&self, name: &str) -> Option<u32> {
        self.field_bits(self.field(name)?.offset)
    }
    fn set(&mut self, name: &str, value: i64) -> Result<(), Status> {
        use registry::{Dir, Kind};
        let f = self.field(name).ok_or(Status::Config)?;
        let (min, max) = match f.kind {
            Kind::Bool => (0, 1),
            Kind::U8 => (0, i64::from(u8::MAX)),
            Kind::U16 => (0, i64::from(u16::MAX)),
            Kind::I16 => (i64::from(i16::MIN), i64::from(i16::MAX)),
            Kind::U32 => (0, i64::from(u32::MAX)),
            Kind::I32 => (i64::from(i32::MIN), i64::from(i32::MAX)),
        };
        if !(min..=max).contains(&value) {
            return Err(Status::Config);
        }
        let bits = value as u32;
        let written = match f.dir {
            Dir::Input => self.set_input_bits(f.offset, bits),
            Dir::Param => self.set_param_bits(f.offset, bits),
            Dir::Control => {
                let bit = |n: &str| self.get(n).unwrap_or(0) as u8;
                let (run, ack) = if f.name == "bRun" {
                    (bits as u8, bit("bErrAck"))
                } else {
                    (bit("bRun"), bits as u8)
                };
                self.drive(run, ack);
                true
            }
            Dir::Output | Dir::Info => false,
        };
        if written {
            Ok(())
        } else {
            Err(Status::Config)
        }
    }
    fn field(&self, name: &str) -> Option<&'static registry::Field> {
        B::FIELDS.iter().find(|f| f.name == name)
    }
}
pub use blocks::flipflop::{SL_STATE_RS_SET, SL_STATE_SR_SET};
