//! Shared primitives, written once and composed by every block (ABI.md §2, §7):
//! BOOL decoding, wrapping millisecond timers, edges, two-channel pairs, the restart
//! sequence, EDM checks, the private-state header with its integrity checks, and the
//! cycle envelope (Run / STOP / ERROR / RESET / parameter latching / clock check), and the
//! PLCopen envelope of the `SF_` blocks (`sf`: Activate, Reset R_TRIG, DiagCodes).

pub mod bools;
pub mod edm;
pub mod envelope;
pub mod header;
pub mod pair;
pub mod restart;
pub mod sf;
pub mod time;
