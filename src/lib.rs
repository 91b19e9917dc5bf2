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
//! The block layer (`types`, `base`, `blocks`) is `no_std`, allocation-free and free of
//! `unsafe`; the C ABI (`ffi`, feature `std`) is the only place with `unsafe` code.
//! Not a certified safety component: see README.md.

#![cfg_attr(not(feature = "std"), no_std)]
#![deny(unsafe_code)]

// The layers, each importing only from those listed before it (tests/layers.rs checks it;
// docs/architecture.md draws it).
pub mod any;
pub mod base;
pub mod blocks;
pub mod fsoe;
pub mod group;
pub mod registry;

#[cfg(feature = "std")]
pub mod ffi;

/// The registered blocks at the crate root: each row's module (its struct, variants and
/// constants), generated from the registry rows.
macro_rules! reexport_blocks {
    ($($krate:ident :: blocks :: $fam:ident :: $m:ident :: $ty:ident => $init:ident, $cycle:ident;)*) => {
        $(
            // Integer variants share one module: its repeated glob names the same items.
            #[allow(unused_imports)]
            pub use $krate::blocks::$fam::$m::*;
        )*
    };
}
for_each_block!(reexport_blocks);

pub use base::header::SL_PRIVATE_HEADER;
pub use base::sf::{
    DiagState, SfPhase, SL_SF_DIAG_CLOCK, SL_SF_DIAG_CONFIG, SL_SF_DIAG_CONST_CHANGED,
    SL_SF_DIAG_CORRUPT, SL_SF_PRIVATE, SL_SF_PROFILE_V10, SL_SF_PROFILE_V201, SL_SF_TIME_MAX,
};
pub use base::types::*;
pub use blocks::analog::window::SL_SLI_PRIVATE;
pub use blocks::analog::{SL_DIAG_VALUE_OVERFLOW, SL_DIAG_VALUE_UNDERFLOW};
pub use blocks::boolean::flipflop::{SL_FLIPFLOP_PRIVATE, SL_STATE_RS_SET, SL_STATE_SR_SET};
pub use blocks::boolean::guard::SL_GUARD_PRIVATE;
pub use blocks::boolean::logic::SL_LOGIC_PRIVATE;
pub use blocks::boolean::timer::SL_TIMER_PRIVATE;
pub use blocks::boolean::timer::{
    SL_DIAG_TON2_RESTORE, SL_OPT_TON2_REMAINING_TIME, SL_TIMEBASE_1000MS, SL_TIMEBASE_100MS,
    SL_TIMEBASE_10MS, SL_TIMEBASE_1MS, SL_TIMEBASE_AUTO, SL_TIMER_DELAY_MAX, SL_TIMER_STEPS_MAX,
};
pub use fsoe::conn::{SL_FSOE_CONN, SL_FSOE_CONN_PRIVATE};
pub use fsoe::frame::SL_FSOE_FRAME;
pub use fsoe::{
    SL_FSOE_APPPARA_MAX, SL_FSOE_CMD_CONNECTION, SL_FSOE_CMD_FAILSAFEDATA, SL_FSOE_CMD_PARAMETER,
    SL_FSOE_CMD_PROCESSDATA, SL_FSOE_CMD_RESET, SL_FSOE_CMD_SESSION, SL_FSOE_DATA_MAX,
    SL_FSOE_FRAME_MAX, SL_FSOE_OPT_COMERRACK, SL_FSOE_OPT_MODULE_ERR_IS_COMERR,
    SL_FSOE_OPT_PIN_CONNID, SL_FSOE_ROLE_MASTER, SL_FSOE_ROLE_SLAVE,
};
pub use group::state_name;
pub use group::{SL_GROUP, SL_GROUP_PRIVATE, SL_LINK, SL_MEMBER};

// Every struct of the header at the offsets, size and alignment the header's C declarations
// give (build.rs computes them and checks them against each field's "Offset N." comment).
include!(concat!(env!("OUT_DIR"), "/layout_checks.rs"));

pub use any::FunctionBlock;
