//! The function blocks. One file per block, citing its manual section; blocks that share a
//! state machine (ESTOP and MON, manual §4.4 and §4.5) share it in `guard`.

pub mod estop;
pub mod guard;
pub mod mon;
