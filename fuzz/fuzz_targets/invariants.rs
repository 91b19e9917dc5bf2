//! The invariants the fuzz targets check after every call (the same reading as
//! tests/conformance.rs): no panic (SL_E_INTERNAL never returned), a documented status,
//! BOOL outputs 0/1, no output TRUE in STOP / ERROR / RESET or after a refusal
//! (SL_E_CONFIG / SL_E_CORRUPT / SL_E_CLOCK / SL_E_PARAM_CHANGED), `bError` exactly in
//! ERROR.

#![allow(dead_code)] // each target uses a part

use safelogic::registry::{BlockType, Dir, Kind};
use safelogic::*;

pub fn read(bytes: &[u8], offset: u16, kind: Kind) -> u32 {
    let o = usize::from(offset);
    match kind.size() {
        1 => u32::from(bytes[o]),
        2 => u32::from(u16::from_ne_bytes([bytes[o], bytes[o + 1]])),
        _ => u32::from_ne_bytes([bytes[o], bytes[o + 1], bytes[o + 2], bytes[o + 3]]),
    }
}

pub const DOCUMENTED: [i32; 7] = [
    SL_OK,
    SL_E_CONFIG,
    SL_E_PARAM_CHANGED,
    SL_E_CORRUPT,
    SL_E_INVALID_BOOL,
    SL_E_CLOCK,
    SL_E_RESTORE,
];

/// Checks one block after a call with `status`; returns its state.
pub fn check_block(t: &BlockType, bytes: &[u8], status: i32) -> u8 {
    let name = t.info.name;
    assert!(DOCUMENTED.contains(&status), "{name}: status {status}");
    let state = bytes[usize::from(t.field("nState").unwrap().offset)];
    assert!(
        t.info.states.iter().any(|(v, _)| *v == state),
        "{name}: state {state} is not one of the block's"
    );
    let safe_state = matches!(state, SL_STATE_STOP | SL_STATE_ERROR | SL_STATE_RESET);
    let refused = matches!(
        status,
        SL_E_CONFIG | SL_E_CORRUPT | SL_E_CLOCK | SL_E_PARAM_CHANGED
    );
    for f in t.fields.iter().filter(|f| f.dir == Dir::Output) {
        let v = read(bytes, f.offset, f.kind);
        if f.kind == Kind::Bool {
            assert!(v <= 1, "{name}: {} = {v}", f.name);
        }
        if f.name == "bError" {
            assert_eq!(
                v == 1,
                state == SL_STATE_ERROR,
                "{name}: bError in state {state}"
            );
        } else if safe_state || refused {
            assert_eq!(
                v, 0,
                "{name}: {} = {v} in state {state}, status {status}",
                f.name
            );
        }
    }
    state
}

/// Every BOOL output except `bError` is FALSE (a member of a group that is not in RUN).
pub fn check_outputs_false(t: &BlockType, bytes: &[u8], why: &str) {
    for f in t
        .fields
        .iter()
        .filter(|f| f.dir == Dir::Output && f.kind == Kind::Bool)
    {
        let v = read(bytes, f.offset, f.kind);
        assert!(v <= 1, "{}: {} = {v}", t.info.name, f.name);
        if f.name != "bError" {
            assert_eq!(v, 0, "{}: {} TRUE while {why}", t.info.name, f.name);
        }
    }
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
