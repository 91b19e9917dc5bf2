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

pub mod any;
pub mod blocks;
pub mod fsoe;
pub mod group;
pub mod prim;
pub mod registry;
pub mod types;

#[cfg(feature = "std")]
pub mod ffi;

/// The registered blocks at the crate root: each row's module (its struct, variants and
/// constants), generated from the registry rows.
macro_rules! reexport_blocks {
    ($($krate:ident :: blocks :: $m:ident :: $ty:ident => $init:ident, $cycle:ident;)*) => {
        $(
            // Integer variants share one module: its repeated glob names the same items.
            #[allow(unused_imports)]
            pub use $krate::blocks::$m::*;
        )*
    };
}
for_each_block!(reexport_blocks);

pub use blocks::analog::{SL_DIAG_VALUE_OVERFLOW, SL_DIAG_VALUE_UNDERFLOW};
pub use blocks::flipflop::{SL_FLIPFLOP_PRIVATE, SL_STATE_RS_SET, SL_STATE_SR_SET};
pub use blocks::guard::SL_GUARD_PRIVATE;
pub use blocks::logic::SL_LOGIC_PRIVATE;
pub use blocks::state_name;
pub use blocks::timer::SL_TIMER_PRIVATE;
pub use blocks::timer::{
    SL_DIAG_TON2_RESTORE, SL_OPT_TON2_REMAINING_TIME, SL_TIMEBASE_1000MS, SL_TIMEBASE_100MS,
    SL_TIMEBASE_10MS, SL_TIMEBASE_1MS, SL_TIMEBASE_AUTO, SL_TIMER_DELAY_MAX, SL_TIMER_STEPS_MAX,
};
pub use blocks::window::SL_SLI_PRIVATE;
pub use fsoe::conn::{SL_FSOE_CONN, SL_FSOE_CONN_PRIVATE};
pub use fsoe::frame::SL_FSOE_FRAME;
pub use fsoe::{
    SL_FSOE_APPPARA_MAX, SL_FSOE_CMD_CONNECTION, SL_FSOE_CMD_FAILSAFEDATA, SL_FSOE_CMD_PARAMETER,
    SL_FSOE_CMD_PROCESSDATA, SL_FSOE_CMD_RESET, SL_FSOE_CMD_SESSION, SL_FSOE_DATA_MAX,
    SL_FSOE_FRAME_MAX, SL_FSOE_OPT_COMERRACK, SL_FSOE_OPT_MODULE_ERR_IS_COMERR,
    SL_FSOE_ROLE_MASTER, SL_FSOE_ROLE_SLAVE,
};
pub use group::{SL_GROUP, SL_GROUP_PRIVATE, SL_LINK, SL_MEMBER};
pub use prim::header::SL_PRIVATE_HEADER;
pub use prim::sf::{
    DiagState, SfPhase, SL_SF_DIAG_CLOCK, SL_SF_DIAG_CONFIG, SL_SF_DIAG_CONST_CHANGED,
    SL_SF_DIAG_CORRUPT, SL_SF_PRIVATE, SL_SF_PROFILE_V10, SL_SF_PROFILE_V201, SL_SF_TIME_MAX,
};
pub use types::*;

// Every struct of the header at the offsets, size and alignment the header's C declarations
// give (build.rs computes them and checks them against each field's "Offset N." comment).
include!(concat!(env!("OUT_DIR"), "/layout_checks.rs"));

/// The Rust face of every block. `init` / `cycle` return the C status code (the same calls
/// as `sl_<name>_init` / `sl_<name>_cycle`); `try_init` / `try_cycle` return a `Result`.
///
/// ```
/// use safelogic::{EstopState, FunctionBlock, Status, FB_ESTOP};
///
/// let mut estop = FB_ESTOP { wInputActive: 0b11, tDiscTime12: 100, ..Default::default() };
/// estop.try_init()?;
/// (estop.bEStopIn1, estop.bEStopIn2, estop.bRun) = (1, 1, 1);
/// estop.try_cycle(0)?;
/// estop.bRestart = 1;
/// estop.try_cycle(10)?;
/// estop.bRestart = 0; // the falling edge of Restart enables the outputs
/// estop.try_cycle(20)?;
/// assert_eq!((estop.current_state()?, estop.bEStopOut), (EstopState::Run, 1));
/// assert_eq!(estop.state_name(), "RUN");
/// # Ok::<(), Status>(())
/// ```
pub trait FunctionBlock {
    /// The block's states (`EstopState`, `TonState`, …): the manual's status values.
    type State: registry::BlockState;
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
    /// The current state, decoded from `nState`; `Err(Status::Corrupt)` for a value the
    /// block does not have (the next cycle enters ERROR with the corrupt bit).
    fn current_state(&self) -> Result<Self::State, Status>;
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

impl<B: registry::Cyclic + registry::Registered + group::Member> FunctionBlock for B {
    fn init(&mut self) -> i32 {
        self.init_fb().code()
    }
    fn cycle(&mut self, now: u32) -> i32 {
        self.cycle_fb(now).code()
    }
    type State = B::State;
    fn current_state(&self) -> Result<B::State, Status> {
        <B::State as registry::BlockState>::decode(self.state()).ok_or(Status::Corrupt)
    }
    fn state_name(&self) -> &'static str {
        blocks::state_name(B::INFO.tag, self.state())
    }
    fn is_error(&self) -> bool {
        self.in_error()
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
