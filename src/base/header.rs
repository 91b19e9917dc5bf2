//! The common head of every block's private state (ABI §3.6) and its integrity checks.
//!
//! Why these checks and not a CRC over everything on every call: a CRC-16/32 over ~60 bytes
//! costs 15–30 ns with the `crc` crate, several times a whole block cycle. So each call checks
//! cheaply but exactly what decides the outputs: a per-block magic word, a complement copy
//! of the control word (state, flags, diagnosis) and of the auxiliary bits, and the live
//! parameters against the latched copy. The latched copy itself carries a CRC-16, computed
//! when it is latched and verified whenever the outputs are about to be enabled and whenever
//! a live parameter differs from it (to tell a changed parameter from a corrupted copy).
//! The guards' timer start values carry no redundancy; docs/semantics.md says what a
//! corrupted one can do (at most delay a timer by its own parameter). The timer blocks
//! (TON, TOF, TON2) keep a complement of their start, since it decides when an output
//! switches on (T9).

use crc::{Crc, CRC_16_IBM_3740};

/// Common head of the private state. All fields are plain integers, so any byte pattern is
/// a valid value of this type; whether it is a *consistent* one is what [`Self::intact`]
/// decides. Never written by the user.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, Eq)]
#[allow(non_snake_case, non_camel_case_types)]
pub struct SL_PRIVATE_HEADER {
    /// Block type tag; 0 in a never-initialised instance.
    pub wMagic: u16,
    /// Block-specific auxiliary bits (pair timers running, latches, test progress).
    pub wAux: u16,
    /// Current state (the manual's status value).
    pub nState: u8,
    /// Edge memories and internal flags (`F_*`).
    pub nFlags: u8,
    /// Latched diagnostic bits.
    pub wDiag: u16,
    /// CRC-16 of the latched parameters (seeded with the magic).
    pub wParamCrc: u16,
    /// Complement of `wAux`.
    pub wAuxCheck: u16,
    /// Complement of the control word (`nState`, `nFlags`, `wDiag`).
    pub dwCtrlCheck: u32,
    /// `tNow` of the previous call.
    pub tLast: u32,
    /// Start of the current phase timer (output delay, EDM reset time, state timers).
    pub tPhase: u32,
    /// Latched `wInputActive` (low byte).
    pub nActive: u8,
    /// Latched `wInputNegated` (low byte).
    pub nNegated: u8,
    /// Latched `dwOptions` (low word).
    pub wOptions: u16,
}

/// Previous level of Restart.
pub(crate) const F_RESTART_PREV: u8 = 1;
/// Previous level of ErrAck.
pub(crate) const F_ERRACK_PREV: u8 = 1 << 1;
/// `tLast` holds a time from an earlier call.
pub(crate) const F_TIME_VALID: u8 = 1 << 2;
/// EDM1 / EDM2 reset-time checks pending (bits 3, 4: the pending mask of
/// `Edm::reset_time_check` shifted by `EDM_PENDING_SHIFT`). One mask for both, so clearing
/// them is one operation (no `|` of two disjoint bits, docs/testing.md "Mutation testing").
pub(crate) const F_EDM_PENDING: u8 = 0b11 << EDM_PENDING_SHIFT;
/// The latched parameters are invalid: the block may only be in STOP or ERROR/RESET.
pub(crate) const F_CFG_INVALID: u8 = 1 << 5;
/// In RESET: ErrAck has fallen but the block may not start yet (`Block::may_leave_reset`).
pub(crate) const F_RESET_HELD: u8 = 1 << 6;

/// Shift from bit 0 of an EDM pending mask to bit 3 of `nFlags` (`F_EDM_PENDING`).
pub(crate) const EDM_PENDING_SHIFT: u32 = 3;

static CRC16: Crc<u16> = Crc::<u16>::new(&CRC_16_IBM_3740);

/// CRC-16 over a block's latched parameter words, seeded with its magic.
///
/// The bytes go to the digest in runs of up to 64 (one `update` per run: each call has a
/// fixed cost several times that of a byte), in the same order as one word at a time.
pub fn param_crc(magic: u16, active: u8, negated: u8, options: u16, times: &[u16]) -> u16 {
    let mut d = CRC16.digest();
    let ([m0, m1], [o0, o1]) = (magic.to_le_bytes(), options.to_le_bytes());
    d.update(&[m0, m1, active, negated, o0, o1]);
    for run in times.chunks(32) {
        let mut bytes = [0u8; 64];
        for (b, t) in bytes.chunks_exact_mut(2).zip(run) {
            b.copy_from_slice(&t.to_le_bytes());
        }
        d.update(bytes.get(..2 * run.len()).unwrap_or(&bytes));
    }
    d.finalize()
}

/// The CRC words of a list of latched parameters, in order: `u16 x` is one word, `u32 x`
/// two (low half first), as [`param_crc`] reads them: `crc_words![u16 p.wActive, u32 min]`.
macro_rules! crc_words {
    (@ [$($w:expr),*]) => { [$($w),*] };
    (@ [$($w:expr),*] u16 $v:expr $(, $($rest:tt)*)?) => {
        $crate::base::header::crc_words!(@ [$($w,)* $v] $($($rest)*)?)
    };
    (@ [$($w:expr),*] u32 $v:expr $(, $($rest:tt)*)?) => {
        $crate::base::header::crc_words!(@ [$($w,)* ($v) as u16, (($v) >> 16) as u16] $($($rest)*)?)
    };
    ($($t:tt)*) => { $crate::base::header::crc_words!(@ [] $($t)*) };
}
pub(crate) use crc_words;

/// Writes 32-bit values as CRC words from the start of `dst`, two each, low half first
/// (the order of `crc_words!`).
#[inline]
pub fn put_crc_words(dst: &mut [u16], values: impl IntoIterator<Item = u32>) {
    for (w, v) in dst.chunks_exact_mut(2).zip(values) {
        w[0] = v as u16;
        w[1] = (v >> 16) as u16;
    }
}

/// Equal when every field is, as the derived comparison would say, but always inline: the
/// fixed-point test of the full cycle compares whole private states, and the compiler merges
/// the field compares of the header with those of the fields after it only when it sees
/// them all (an out-of-line header compare made a TON full cycle 2.5 ns slower).
impl PartialEq for SL_PRIVATE_HEADER {
    #[inline(always)]
    fn eq(&self, o: &Self) -> bool {
        self.wMagic == o.wMagic
            && self.wAux == o.wAux
            && self.nState == o.nState
            && self.nFlags == o.nFlags
            && self.wDiag == o.wDiag
            && self.wParamCrc == o.wParamCrc
            && self.wAuxCheck == o.wAuxCheck
            && self.dwCtrlCheck == o.dwCtrlCheck
            && self.tLast == o.tLast
            && self.tPhase == o.tPhase
            && self.nActive == o.nActive
            && self.nNegated == o.nNegated
            && self.wOptions == o.wOptions
    }
}

impl SL_PRIVATE_HEADER {
    /// All zero: a never-initialised instance.
    pub const ZERO: Self = Self {
        wMagic: 0,
        wAux: 0,
        nState: 0,
        nFlags: 0,
        wDiag: 0,
        wParamCrc: 0,
        wAuxCheck: 0,
        dwCtrlCheck: 0,
        tLast: 0,
        tPhase: 0,
        nActive: 0,
        nNegated: 0,
        wOptions: 0,
    };

    /// The control word: state, flags and diag (its complement is `dwCtrlCheck`).
    #[inline]
    pub fn ctrl(&self) -> u32 {
        u32::from(self.nState) | (u32::from(self.nFlags) << 8) | (u32::from(self.wDiag) << 16)
    }

    /// All bytes zero: a never-initialised instance (ABI §3.6).
    #[inline]
    pub fn is_zero(&self) -> bool {
        *self == Self::default()
    }

    /// Magic and complement copies agree. The checked words and their complements are the
    /// header's first and second 8 bytes (magic, aux, control word; CRC, their complements):
    /// one XOR of the two decides all complements at once.
    #[inline]
    pub fn intact(&self, magic: u16) -> bool {
        let word =
            u64::from(self.wMagic) | u64::from(self.wAux) << 16 | u64::from(self.ctrl()) << 32;
        let check = u64::from(self.wParamCrc)
            | u64::from(self.wAuxCheck) << 16
            | u64::from(self.dwCtrlCheck) << 32;
        word ^ check == u64::from(magic ^ self.wParamCrc) | 0xFFFF_FFFF_FFFF_0000
    }

    /// Refreshes the complement copies after the cycle changed the control word.
    #[inline]
    pub fn seal(&mut self) {
        self.wAuxCheck = !self.wAux;
        self.dwCtrlCheck = !self.ctrl();
    }

    #[inline]
    pub fn flag(&self, f: u8) -> bool {
        self.nFlags & f != 0
    }

    #[inline]
    pub fn set_flag(&mut self, f: u8, on: bool) {
        if on {
            self.nFlags |= f;
        } else {
            self.nFlags &= !f;
        }
    }

    /// Enters ERROR (4) with `diag` added. Pair timers, latches and pending checks of the
    /// running states end here; a block already in ERROR only gains the new bits.
    #[inline]
    pub fn enter_error(&mut self, diag: u16) {
        if self.nState != crate::base::types::SL_STATE_ERROR {
            self.wAux = 0;
            self.nFlags &= !F_EDM_PENDING;
        }
        self.nState = crate::base::types::SL_STATE_ERROR;
        self.wDiag |= diag;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seal_and_check() {
        let mut h = SL_PRIVATE_HEADER {
            wMagic: 0x1234,
            nState: 3,
            ..Default::default()
        };
        assert!(!h.intact(0x1234));
        h.seal();
        assert!(h.intact(0x1234));
        assert!(!h.intact(0x4321));
        h.nFlags ^= 1;
        assert!(!h.intact(0x1234));
    }

    #[test]
    fn crc_depends_on_every_word() {
        let base = param_crc(1, 3, 0, 4, &[10, 20]);
        assert_ne!(base, param_crc(2, 3, 0, 4, &[10, 20]));
        assert_ne!(base, param_crc(1, 3, 0, 4, &[20, 10]));
        assert_ne!(base, param_crc(1, 3, 1, 4, &[10, 20]));
    }

    /// The CRC is that of the bytes magic, active, negated, options, then every word, all
    /// little-endian, in one piece — for every length, across the 64-byte runs.
    #[test]
    fn crc_is_that_of_the_whole_byte_sequence() {
        for len in 0..100u16 {
            let words: Vec<u16> = (0..len).map(|i| i.wrapping_mul(0x9E37) ^ len).collect();
            let mut bytes = vec![0x34, 0x12, 7, 1, 0xCD, 0xAB];
            words.iter().for_each(|w| bytes.extend(w.to_le_bytes()));
            assert_eq!(
                param_crc(0x1234, 7, 1, 0xABCD, &words),
                CRC16.checksum(&bytes),
                "{len} words"
            );
        }
    }
}
