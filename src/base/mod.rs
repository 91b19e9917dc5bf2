//! The core layer: what every block, the registry, the group, FSoE and the C boundary build
//! on, and which imports nothing above itself. Status codes and scalar types (`types`), the
//! private header and its integrity check (`header`), the integrity envelopes of the two
//! block families (`envelope` for TwinSAFE, `sf` for PLCopen), what a block declares about
//! itself (`block`) and how the group runs it (`member`), and the shared primitives that
//! blocks compose (`bools`: BOOL bytes and edges, `time`: the wrapping millisecond clock,
//! `pair`: two-channel discrepancy, `restart`: restart interlock, `edm`: external device
//! monitoring).

pub mod block;
pub mod bools;
pub mod diag;
pub mod edm;
pub mod envelope;
pub mod header;
pub mod layout;
pub mod member;
pub mod pair;
pub mod reason;
pub mod restart;
pub mod sf;
pub mod time;
pub mod types;
