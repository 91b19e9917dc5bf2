//! Boolean and time blocks (manual §4.1–§4.14): logic (AND, OR, XOR, DECOUPLE), OPMODE,
//! ESTOP and MON (the shared `guard` machine), TWOHAND, MUTING, EDM, the RS/SR flip-flops
//! (`flipflop`) and the timers TON, TON2, TOF (`timer`).

pub mod and;
pub mod decouple;
pub mod edm;
pub mod estop;
pub mod flipflop;
pub mod guard;
pub mod logic;
pub mod mon;
pub mod muting;
pub mod opmode;
pub mod or;
pub mod rs;
pub mod sr;
pub mod timer;
pub mod tof;
pub mod ton;
pub mod ton2;
pub mod twohand;
pub mod xor;
