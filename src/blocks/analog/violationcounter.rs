//! FB VIOLATIONCOUNTER (ViolationCnt) — manual §4.33; layout ABI-2 §11.12.
//!
//! A weighted error counter: while Enable is TRUE, every call adds `nIncrementError` when
//! Input is logically FALSE (a violation) and subtracts `nDecrementNoError` when it is TRUE,
//! saturating at 0 and at the type's maximum; InputOK = counter < CounterLimit (RUN), else
//! SAFE; ActViolationCnt shows the counter. Enable FALSE → START (InputOK 0, counter 0).
//! States RUN (1), STOP (2), SAFE (3), START (6); ERROR (4) and RESET (5) only for the
//! library's own faults (no Error output, no diag values). UINT and UDINT variants.
//! Readings: docs/semantics.md V1–V4.

#![allow(non_camel_case_types)] // the ABI's names (FB_VIOLATIONCOUNTER_UINT …)

use super::{magic, Unsigned};
use crate::base::block::{Private, Registered};
use crate::base::bools;
use crate::base::envelope::Block;
use crate::base::header::{crc_words, param_crc};
use crate::base::reason::rule;
use crate::base::reason::RuleDef;
use crate::base::types::*;

include!(concat!(
    env!("OUT_DIR"),
    "/abi/blocks/analog/violationcounter.rs"
));

// The ABI-2 §11.12 numbers of the two layouts (output base).
const _: () = {
    use core::mem::{offset_of, size_of};
    assert!(offset_of!(FB_VIOLATIONCOUNTER_UINT, bInputOK) == 33);
    assert!(offset_of!(FB_VIOLATIONCOUNTER_UDINT, bInputOK) == 41);
    assert!(size_of::<SL_VIOLATIONCOUNTER_PRIVATE>() == 48);
};

crate::impl_member!([T: Unsigned, const P1: usize, const P2: usize] FB_VIOLATIONCOUNTER<T, P1, P2> {
    info: crate::blocks::analog::variant_info!(T, "VIOLATIONCOUNTER", ViolationCounterState, &[(0, "No diagnostic information")];
        UINT = SL_TYPE_VIOLATIONCOUNTER_UINT, UDINT = SL_TYPE_VIOLATIONCOUNTER_UDINT),
    state: ViolationCounterState,
    private: SL_VIOLATIONCOUNTER_PRIVATE,
    input: [bInput, bEnable],
    param: [nIncrementError, nDecrementNoError, nCounterLimit, wInputActive, wInputNegated],
    output: [bInputOK, nActViolationCnt],
    info_fields: [nDiagTextId, dwDiagPar2, dwDiagPar3],
});

/// Parameters as the user wrote them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ViolationParams {
    active: u16,
    negated: u16,
    values: [u32; 3],
}

/// One cycle's inputs after BOOL decoding (invalid bytes read FALSE).
#[derive(Clone, Copy, Debug)]
pub struct ViolationIn {
    input: bool,
    enable: bool,
}

const INCREMENT: usize = 0;
const DECREMENT: usize = 1;
const LIMIT: usize = 2;

impl<T: Unsigned, const P1: usize, const P2: usize> Block for FB_VIOLATIONCOUNTER<T, P1, P2> {
    const MAGIC: u16 = magic(<Self as Registered>::INFO.tag);
    type Params = ViolationParams;
    type In = ViolationIn;

    #[inline(always)]
    fn live_params(&self) -> ViolationParams {
        ViolationParams {
            active: self.wInputActive,
            negated: self.wInputNegated,
            values: [
                self.nIncrementError.to_bits(),
                self.nDecrementNoError.to_bits(),
                self.nCounterLimit.to_bits(),
            ],
        }
    }
    #[inline(always)]
    fn latched_params(&self) -> ViolationParams {
        let p = self.private();
        ViolationParams {
            active: u16::from(p.stHeader.nActive),
            negated: u16::from(p.stHeader.nNegated),
            values: p.adwParam,
        }
    }
    /// Both inputs active, only Input negatable, Counter Limit ≥ 1 (semantics V3).
    const RULES: &'static [RuleDef<ViolationParams>] = &[
        rule!(equals "wInputActive", |p| p.active, SL_VIOLATIONCOUNTER_ACTIVE),
        rule!(no_bits_outside "wInputNegated", |p| p.negated, 1),
        rule!(not_zero "nCounterLimit" in Plain, |p| p.values[LIMIT]),
    ];
    fn store_params(&mut self, p: &ViolationParams) {
        let q = self.private_mut();
        q.stHeader.nActive = p.active as u8;
        q.stHeader.nNegated = p.negated as u8;
        q.adwParam = p.values;
    }
    fn latched_crc(&self) -> u16 {
        let p = self.private();
        let [a, b, c] = p.adwParam;
        param_crc(
            Self::MAGIC,
            p.stHeader.nActive,
            p.stHeader.nNegated,
            0,
            &crc_words![u32 a, u32 b, u32 c],
        )
    }
    /// An invalid Input byte reads logically FALSE (a violation) whatever its negation; an
    /// invalid Enable reads FALSE (ABI §2, ABI-2 §11.12).
    #[inline(always)]
    fn decode(&mut self) -> (ViolationIn, bool) {
        let h = &self.private().stHeader;
        let raw = bools::pack([self.bInput, self.bEnable]);
        let level = bools::logical(raw, h.nActive, h.nNegated);
        (
            ViolationIn {
                input: level & 1 != 0,
                enable: level & 2 != 0,
            },
            raw.invalid != 0,
        )
    }
    /// STOP → run and RESET → run start from a counter of 0, then count this call
    /// (semantics V2).
    fn start(&mut self, inp: &ViolationIn, now: u32) {
        self.private_mut().dwCount = 0;
        self.step(inp, now);
    }
    #[inline(always)]
    fn step(&mut self, inp: &ViolationIn, _now: u32) -> Status {
        let p = self.private();
        if !inp.enable {
            let p = self.private_mut();
            p.dwCount = 0;
            p.stHeader.nState = SL_STATE_START;
            return Status::Ok;
        }
        let count = T::from_bits(p.dwCount).wide();
        let next = if inp.input {
            (count - T::from_bits(p.adwParam[DECREMENT]).wide()).max(0)
        } else {
            (count + T::from_bits(p.adwParam[INCREMENT]).wide()).min(T::MAX)
        };
        let ok = next < T::from_bits(p.adwParam[LIMIT]).wide();
        // InputOK switching on is where the latched parameters are verified (C3).
        if self.corrupt_entering_run(ok) {
            return Status::Corrupt;
        }
        let p = self.private_mut();
        p.dwCount = T::narrow(next).to_bits();
        p.stHeader.nState = if ok { SL_STATE_RUN } else { SL_STATE_SAFE };
        Status::Ok
    }
    // Only the library's faults lead to ERROR; none of them remains: `error_remains` keeps
    // its default (false).
    #[inline(always)]
    fn write_outputs(&mut self) {
        let p = *self.private();
        let h = p.stHeader;
        let counting = h.nState == SL_STATE_RUN || h.nState == SL_STATE_SAFE;
        self.bInputOK = u8::from(h.nState == SL_STATE_RUN);
        self.nActViolationCnt = if counting {
            T::from_bits(p.dwCount)
        } else {
            T::ZERO
        };
        self.nState = h.nState;
        self.nDiag = h.wDiag;
        (self.nDiagTextId, self.dwDiagPar2, self.dwDiagPar3) = (0, 0, 0);
    }
}
