//! FB COMPARE — manual §4.20; layout ABI-2 §11.3, rules ABI-2 §12.
//!
//! Compares 2, 3 or 5 analog inputs (architecture 1oo2, 2oo3, 3oo5) for equality within
//! `nAllowedDeviation`: ValuesEqual ⇔ 2 (1oo2, 2oo3) or 3 (3oo5) evaluated inputs pairwise
//! differ by at most the deviation (exact differences). RUN: IsValid, CompOut = CompInX,
//! X the smallest input of such a set. ValuesEqual FALSE → DELAYOUT for `tToleranceTime`
//! (IsValid stays TRUE, CompOut unchanged), then SAFE (IsValid FALSE, CompOut 0); back to
//! RUN automatically once ValuesEqual. States RUN (1), STOP (2), SAFE (3), ERROR (4),
//! RESET (5), DELAYOUT (8). Readings: docs/semantics.md CP1–CP4. One implementation for the
//! four integer types.

#![allow(non_camel_case_types)] // the ABI's names (FB_COMPARE_INT …)

use super::{magic, Analog};
use crate::base::block::{Private, Registered};
use crate::base::envelope::{params_map, Block};
use crate::base::header::{crc_words, param_crc};
use crate::base::reason::rule;
use crate::base::reason::{when, Rule, RuleDef, Unit};
use crate::base::time;
use crate::base::types::*;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/analog/compare.rs"));

// The ABI-2 §11.3 numbers of the two layouts (parameters, output base).
const _: () = {
    use core::mem::{offset_of, size_of};
    assert!(
        offset_of!(FB_COMPARE_INT, tToleranceTime) == 36
            && offset_of!(FB_COMPARE_UINT, bError) == 48
    );
    assert!(
        offset_of!(FB_COMPARE_DINT, tToleranceTime) == 44
            && offset_of!(FB_COMPARE_UDINT, bError) == 56
    );
    assert!(size_of::<SL_COMPARE_PRIVATE>() == 48);
};

/// Diag value texts (manual §4.20.2).
const DIAG_VALUES: &[(u16, &str)] =
    super::range_diag_values!("CompOut", "The output CompOut is correct", "");

crate::impl_member!([T: Analog, const P1: usize, const P2: usize] FB_COMPARE<T, P1, P2> {
    info: crate::blocks::analog::variant_info!(T, "COMPARE", CompareState, DIAG_VALUES;
        INT = SL_TYPE_COMPARE_INT, UINT = SL_TYPE_COMPARE_UINT, DINT = SL_TYPE_COMPARE_DINT, UDINT = SL_TYPE_COMPARE_UDINT),
    state: CompareState,
    private: SL_COMPARE_PRIVATE,
    input: [nCompIn1, nCompIn2, nCompIn3, nCompIn4, nCompIn5],
    param: [tToleranceTime, nAllowedDeviation, nArchitecture, wInputActive],
    output: [bError, bIsValid, nCompOut],
    info_fields: [nDiagTextId, dwDiagPar2, dwDiagPar3],
});

/// Parameters as the user wrote them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CompareParams {
    tolerance: u32,
    deviation: u32,
    architecture: u16,
    active: u16,
}

/// One cycle's comparison: the index (0-based) of CompInX when ValuesEqual, and the inputs
/// as 32-bit patterns.
#[derive(Clone, Copy, Debug)]
pub struct CompareIn {
    x: Option<usize>,
    values: [u32; 5],
}

/// The smallest input that is in a set of `k` evaluated inputs (the first `n`) whose values
/// pairwise differ by at most `dev` (semantics CP1); `None` when there is no such set.
/// In a set of pairwise-close values the extremes decide, so a set exists containing input
/// `i` iff some window `[v, v + dev]` with `v` one of the values holds input `i` and at
/// least `k` inputs.
pub fn consensus(values: &[i128], k: usize, dev: i128) -> Option<usize> {
    let mut best: Option<usize> = None;
    for lo in values {
        let inside = |v: &i128| *lo <= *v && *v - *lo <= dev;
        if values.iter().filter(|v| inside(v)).count() >= k {
            let first = values.iter().position(inside);
            best = match (best, first) {
                (Some(b), Some(f)) => Some(b.min(f)),
                (None, f) => f,
                (b, None) => b,
            };
        }
    }
    best
}

impl<T: Analog, const P1: usize, const P2: usize> Block for FB_COMPARE<T, P1, P2> {
    const MAGIC: u16 = magic(<Self as Registered>::INFO.tag);
    params_map!(CompareParams {
        tolerance: tToleranceTime => tTolerance,
        deviation: nAllowedDeviation => dwDeviation,
        architecture: nArchitecture => wArchitecture,
        active: wInputActive => wActive,
    });
    type In = CompareIn;

    /// Architecture 2, 3 or 5 with exactly its inputs active; Tolerance Time ≤ 65,535 ms
    /// (ABI-2 §12.9); any deviation (semantics CP4).
    const RULES: &'static [RuleDef<CompareParams>] = &[
        RuleDef::new(
            "nArchitecture",
            Rule::OneOf("2 (1oo2), 3 (2oo3), 5 (3oo5)"),
            Unit::Plain,
            |p| {
                let known = matches!(p.architecture, SL_ARCH_1OO2 | SL_ARCH_2OO3 | SL_ARCH_3OO5);
                when(!known, p.architecture, 0)
            },
        ),
        RuleDef::new("wInputActive", Rule::Equals, Unit::Hex, |p| {
            // One input per channel of the architecture (checked after it).
            let want = ((1u16 << p.architecture.min(15)) - 1) << 8;
            when(p.active != want, p.active, want)
        }),
        rule!(at_most "tToleranceTime" in Ms, |p| p.tolerance, SL_TIME_PARAM_MAX),
    ];
    fn latched_crc(&self) -> u16 {
        let p = self.private();
        param_crc(
            Self::MAGIC,
            0,
            0,
            p.wArchitecture,
            &crc_words![u32 p.tTolerance, u32 p.dwDeviation, u16 p.wActive],
        )
    }
    #[inline(always)]
    fn decode(&mut self) -> (CompareIn, bool) {
        let p = self.private();
        let inputs = [
            self.nCompIn1,
            self.nCompIn2,
            self.nCompIn3,
            self.nCompIn4,
            self.nCompIn5,
        ];
        let n = usize::from(p.wArchitecture).min(5);
        let k = if n == 5 { 3 } else { 2 };
        let mut wide = [0i128; 5];
        for (w, v) in wide.iter_mut().zip(inputs) {
            *w = v.wide();
        }
        let x = wide
            .get(..n)
            .and_then(|v| consensus(v, k, i128::from(p.dwDeviation)));
        (
            CompareIn {
                x,
                values: inputs.map(|v| v.to_bits()),
            },
            false,
        )
    }
    /// The start state is SAFE, decided again in the same call (semantics CP2).
    fn start(&mut self, inp: &CompareIn, now: u32) {
        self.private_mut().stHeader.nState = SL_STATE_SAFE;
        self.step(inp, now);
    }
    #[inline(always)]
    fn step(&mut self, inp: &CompareIn, now: u32) -> Status {
        let state = self.private().stHeader.nState;
        if let Some(x) = inp.x {
            // IsValid switching on (from SAFE) is where the latched parameters are verified (C3).
            if self.corrupt_at_switch_on(state == SL_STATE_SAFE) {
                return Status::Corrupt;
            }
            let p = self.private_mut();
            p.dwOut = inp.values.get(x).copied().unwrap_or(0);
            p.stHeader.nState = SL_STATE_RUN;
            return Status::Ok;
        }
        let p = self.private_mut();
        let tolerance = p.tTolerance;
        let h = &mut p.stHeader;
        match state {
            SL_STATE_RUN => {
                h.tPhase = now;
                h.nState = SL_STATE_DELAYOUT;
            }
            SL_STATE_DELAYOUT => {}
            _ => h.nState = SL_STATE_SAFE,
        }
        if h.nState == SL_STATE_DELAYOUT && time::reached(now, h.tPhase, tolerance) {
            h.nState = SL_STATE_SAFE;
        }
        if h.nState == SL_STATE_SAFE {
            p.dwOut = 0;
        }
        Status::Ok
    }
    // Only the library's faults lead to ERROR (CompOut cannot leave its type); none remains.
    // `error_remains` keeps its default (false).
    #[inline(always)]
    fn write_outputs(&mut self) {
        let p = *self.private();
        let h = p.stHeader;
        let valid = h.nState == SL_STATE_RUN || h.nState == SL_STATE_DELAYOUT;
        self.bError = u8::from(h.nState == SL_STATE_ERROR);
        self.bIsValid = u8::from(valid);
        self.nCompOut = if valid {
            T::from_bits(p.dwOut)
        } else {
            T::ZERO
        };
        self.nState = h.nState;
        self.nDiag = h.wDiag;
        (self.nDiagTextId, self.dwDiagPar2, self.dwDiagPar3) = (0, 0, 0);
    }
}
