//! The text of a block's diag word: the manual's text of each bit (TwinSAFE), of its value
//! (the analog blocks' `nDiag` values) or of a PLCopen DiagCode, for `sl_diag_text`.

use crate::base::block::{family, BlockInfo, Family};
use crate::base::types::*;

/// Library diag bits common to every block (docs/semantics.md C11).
pub const LIBRARY_DIAG: &[(u16, &str)] = &[
    (SL_DIAG_PARAM_CHANGED, "parameter changed while running"),
    (SL_DIAG_CLOCK, "clock went backwards"),
    (SL_DIAG_CORRUPT, "private state corrupt"),
];

/// Writes the names of the bits set in `diag` into `out` (a PLCopen block: the text of the
/// DiagCode `diag`), separated by "; ", truncated to
/// fit; returns the number of bytes written (no NUL).
pub fn diag_text(block: &BlockInfo, diag: u16, out: &mut [u8]) -> usize {
    let mut w = Writer { out, len: 0 };
    // A PLCopen DiagCode is one value (state or error) of either profile, never bits.
    if family(block.tag) == Family::PlcOpen {
        w.push(crate::base::sf::diag_text(block.diag_values, diag).unwrap_or("unknown DiagCode"));
        return w.len;
    }
    let mut bits = diag;
    if !block.diag_values.is_empty() {
        let value = diag & !LIBRARY_DIAG_BITS;
        match block.diag_values.iter().find(|(v, _)| *v == value) {
            Some((_, text)) => w.push(text),
            None => w.push("unknown diag value"),
        }
        bits &= LIBRARY_DIAG_BITS;
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
