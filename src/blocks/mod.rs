//! The function blocks. One file per block, citing its manual section; blocks that share a
//! state machine share it: ESTOP and MON (manual §4.4, §4.5) in `guard`, the
//! combinational blocks (AND, OR, …) in `logic`.

pub mod and;
pub mod estop;
pub mod guard;
pub mod logic;
pub mod mon;
pub mod or;
