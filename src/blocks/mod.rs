//! The TwinSAFE function blocks, one folder per family of the manual's chapter 4: the
//! Boolean and time blocks (`boolean`: §4.1–§4.14), the analog blocks (`analog`:
//! §4.15–§4.31, every integer variant from one generic implementation), the press and
//! motion monitors (`motion`) and the connection block (`connection`). One file per block,
//! citing its manual section; blocks that share a state machine share its file (ESTOP and
//! MON in `boolean::guard`, AND/OR/XOR/DECOUPLE in `boolean::logic`, RS/SR in
//! `boolean::flipflop`, TON/TON2/TOF in `boolean::timer`, SLI/SLI2 in `analog::window`).
//! Blocks build on `crate::base` only; the registry lists them.

pub mod analog;
pub mod boolean;
pub mod connection;
pub mod motion;
pub mod plcopen;
