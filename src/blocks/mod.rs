//! The function blocks. One file per block, citing its manual section; blocks that share a
//! state machine share it: ESTOP and MON (manual §4.4, §4.5) in `guard`, the
//! combinational blocks (AND, OR, XOR, DECOUPLE) in `logic`, RS and SR (§4.10, §4.11) in
//! `flipflop`, the timers TON, TON2 and TOF (§4.12–§4.14) in `timer`. OPMODE (§4.3),
//! TWOHAND (§4.7), MUTING (§4.8) and EDM (§4.9) have state machines of their own.

pub mod and;
pub mod arith;
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

/// The names a family's `Block` impl uses, for its expansion in a member's file.
macro_rules! family_prelude {
    ($family:ident) => {
        use $crate::blocks::$family::*;
        use $crate::prim::envelope::Block;
        #[allow(unused_imports)]
        use $crate::prim::{
            bools, bools::Edge, edm, edm::Edm, header::*, pair, restart, restart::Restart, time,
        };
        use $crate::registry::Private;
        use $crate::types::*;
    };
}
pub(crate) use family_prelude;

/// What the C ABI and HMIs need to know about a block type without an instance.
#[derive(Clone, Copy, Debug)]
pub struct BlockInfo {
    /// `SL_TYPE_<NAME>` (group member tag).
    pub tag: u16,
    /// The manual's block name.
    pub name: &'static str,
    /// The block's states (the manual's status values) with NUL-terminated names.
    pub states: &'static [(u8, &'static str)],
    /// Diagnostic bits the manual defines for the block, with their manual text.
    pub diag: &'static [(u16, &'static str)],
    /// For blocks whose `nDiag` carries a value (ADD …): the values with their manual
    /// text; the library bits 13-15 are bits in every block.
    pub diag_values: &'static [(u16, &'static str)],
}

/// State names shared by most blocks (manual status values 1–6, 8).
pub const RUN: (u8, &str) = (crate::types::SL_STATE_RUN, "RUN\0");
pub const STOP: (u8, &str) = (crate::types::SL_STATE_STOP, "STOP\0");
pub const SAFE: (u8, &str) = (crate::types::SL_STATE_SAFE, "SAFE\0");
pub const ERROR: (u8, &str) = (crate::types::SL_STATE_ERROR, "ERROR\0");
pub const RESET: (u8, &str) = (crate::types::SL_STATE_RESET, "RESET\0");
pub const START: (u8, &str) = (crate::types::SL_STATE_START, "START\0");
pub const DELAYOUT: (u8, &str) = (crate::types::SL_STATE_DELAYOUT, "DELAYOUT\0");

/// The block type with this tag.
pub fn info(tag: u16) -> Option<&'static BlockInfo> {
    crate::registry::block_type(tag).map(|b| &b.info)
}

/// Name of state `state` of block type `tag` ("?" for a value the block does not have).
pub fn state_name(tag: u16, state: u8) -> &'static str {
    info(tag)
        .and_then(|b| b.states.iter().find(|(v, _)| *v == state))
        .map_or("?", |(_, name)| name.trim_end_matches('\0'))
}

/// Library diag bits common to every block (docs/semantics.md C11).
pub const LIBRARY_DIAG: &[(u16, &str)] = &[
    (
        crate::types::SL_DIAG_PARAM_CHANGED,
        "parameter changed while running",
    ),
    (crate::types::SL_DIAG_CLOCK, "clock went backwards"),
    (crate::types::SL_DIAG_CORRUPT, "private state corrupt"),
];

/// Writes the names of the bits set in `diag` into `out`, separated by "; ", truncated to
/// fit; returns the number of bytes written (no NUL).
pub fn diag_text(block: &BlockInfo, diag: u16, out: &mut [u8]) -> usize {
    let mut w = Writer { out, len: 0 };
    let mut bits = diag;
    if !block.diag_values.is_empty() {
        let value = diag & !crate::types::LIBRARY_DIAG_BITS;
        match block.diag_values.iter().find(|(v, _)| *v == value) {
            Some((_, text)) => w.push(text),
            None => w.push("unknown diag value"),
        }
        bits &= crate::types::LIBRARY_DIAG_BITS;
    }
    for bit in 0..16u16 {
        let mask = 1u16 << bit;
        if bits & mask == 0 {
            continue;
        }
        if w.len > 0 {
            w.push("; ");
        }
        match block
            .diag
            .iter()
            .chain(LIBRARY_DIAG)
            .find(|(m, _)| *m == mask)
        {
            Some((_, text)) => w.push(text),
            None => {
                w.push("bit ");
                w.push(DIGITS[usize::from(bit)]);
            }
        }
    }
    w.len
}

const DIGITS: [&str; 16] = [
    "0", "1", "2", "3", "4", "5", "6", "7", "8", "9", "10", "11", "12", "13", "14", "15",
];

struct Writer<'a> {
    out: &'a mut [u8],
    len: usize,
}

impl Writer<'_> {
    fn push(&mut self, s: &str) {
        let room = self.out.len().saturating_sub(self.len);
        let n = s.len().min(room);
        if let (Some(dst), Some(src)) = (
            self.out.get_mut(self.len..self.len + n),
            s.as_bytes().get(..n),
        ) {
            dst.copy_from_slice(src);
            self.len += n;
        }
    }
}
