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

/// The Rust face of every block: the same calls as `sl_<name>_init` / `sl_<name>_cycle`.
pub trait FunctionBlock {
    /// Validates and latches the parameters and resets the block to power-up (STOP).
    fn init(&mut self) -> i32;
    /// One task cycle at `now` (monotonic ms, wrapping).
    fn cycle(&mut self, now: u32) -> i32;
}

impl<B: prim::envelope::Block> FunctionBlock for B {
    fn init(&mut self) -> i32 {
        prim::envelope::init(self)
    }
    fn cycle(&mut self, now: u32) -> i32 {
        prim::envelope::cycle(self, now)
    }
}
