//! Press and motion monitors: CAMMONITOR, SLP (safe load protection), SBT (safe brake test)
//! and ADVPOSMON (advanced position monitoring).

pub mod advposmon;
pub mod cammonitor;
pub mod sbt;
pub mod slp;
