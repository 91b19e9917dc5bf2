//! The fuzz targets' invariants: the rules of tests/common/invariants.rs (the same file
//! tests/conformance.rs reads them from), checked after every call; and the input reader.

#![allow(dead_code)] // each target uses a part

#[path = "../../tests/common/invariants.rs"]
mod shared;
pub use shared::*;

/// The invariants of `t` after a call that returned `status` (either family).
pub fn check_block(t: &safelogic::registry::BlockType, bytes: &[u8], status: i32) {
    check_any(t, bytes, status, "");
}

/// A little-endian reader over the fuzzer's bytes (zeros when they run out).
pub struct Input<'a>(pub &'a [u8]);

impl Input<'_> {
    pub fn u8(&mut self) -> u8 {
        match self.0.split_first() {
            Some((b, rest)) => {
                self.0 = rest;
                *b
            }
            None => 0,
        }
    }
    pub fn u16(&mut self) -> u16 {
        u16::from_le_bytes([self.u8(), self.u8()])
    }
    pub fn u32(&mut self) -> u32 {
        u32::from_le_bytes([self.u8(), self.u8(), self.u8(), self.u8()])
    }
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
}

/// 8-aligned zeroed storage of at least `n` bytes.
pub fn aligned(n: usize) -> Vec<u64> {
    vec![0u64; n.div_ceil(8)]
}
