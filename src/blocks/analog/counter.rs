//! FB COUNTER — manual §4.22; layout ABI-2 §11.5, rules ABI-2 §12.
//!
//! An up/down counter: Reset TRUE (level) sets ActValue to PresetValue; otherwise a rising
//! edge of CountUp adds 1 and one of CountDown subtracts 1 (both in one cycle: unchanged).
//! CounterOut = ActValue ≥ CounterLimit, CounterZero = ActValue == 0. A step beyond the
//! range of the variant's type is an ERROR: diag value 1 / 2, message 0x40B8 / 0x40B9
//! (parameters 2 and 3: ActValue, the smallest / largest permitted value), ActValue 0.
//! STOP sets ActValue to 0; starting (STOP → run, RESET → RUN) sets it to PresetValue when
//! Reset is TRUE, else 0. States RUN (1), STOP (2), ERROR (4), RESET (5): no SAFE.
//! Readings: docs/semantics.md K1–K4. One implementation for the four integer types.

#![allow(non_camel_case_types)] // the ABI's names (FB_COUNTER_INT …)

use super::{
    magic, range_message, value_if, Analog, SL_DIAG_VALUE_OVERFLOW, SL_DIAG_VALUE_UNDERFLOW,
};
use crate::base::block::{Private, Registered};
use crate::base::bools;
use crate::base::envelope::Block;
use crate::base::header::{crc_words, param_crc};
use crate::base::reason::rule;
use crate::base::reason::RuleDef;
use crate::base::types::*;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/analog/counter.rs"));

// The ABI-2 §11.5 layout, every variant: parameters from 20, output base 32, ActValue at
// 40, info at 48, private at 64.
const _: () = assert!(core::mem::size_of::<SL_COUNTER_PRIVATE>() == 56);

/// Diag value texts (manual §4.22.2).
const DIAG_VALUES: &[(u16, &str)] =
    super::range_diag_values!("ActValue", "No diagnostic information", "");

crate::impl_member!([T: Analog, const P1: usize, const P2: usize] FB_COUNTER<T, P1, P2> {
    info: crate::blocks::analog::variant_info!(T, "COUNTER", CounterState, DIAG_VALUES;
        INT = SL_TYPE_COUNTER_INT, UINT = SL_TYPE_COUNTER_UINT, DINT = SL_TYPE_COUNTER_DINT, UDINT = SL_TYPE_COUNTER_UDINT),
    state: CounterState,
    private: SL_COUNTER_PRIVATE,
    input: [bReset, bCountUp, bCountDown],
    param: [nPresetValue, nCounterLimit, wInputActive],
    output: [bError, bCounterOut, bCounterZero, nActValue],
    info_fields: [nDiagTextId, dwDiagPar2, dwDiagPar3],
});

/// Parameters as the user wrote them (preset and limit as 32-bit patterns of `T`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CounterParams {
    active: u16,
    values: [u32; 2],
}

/// One cycle's inputs after BOOL decoding: Reset's level, the count edges.
#[derive(Clone, Copy, Debug)]
pub struct CounterIn {
    reset: bool,
    up: bool,
    down: bool,
}

/// `wAux`: the previous levels of CountUp and CountDown.
const PREV_UP: u8 = 1;
const PREV_DOWN: u8 = 2;

impl<T: Analog, const P1: usize, const P2: usize> FB_COUNTER<T, P1, P2> {
    /// The counter after a start (STOP → run, RESET → RUN): PresetValue when Reset is TRUE,
    /// else 0 (semantics K2).
    fn start_value(&self, inp: &CounterIn) -> u32 {
        if inp.reset {
            self.private().adwParam[0]
        } else {
            0
        }
    }
}

impl<T: Analog, const P1: usize, const P2: usize> Block for FB_COUNTER<T, P1, P2> {
    const MAGIC: u16 = magic(<Self as Registered>::INFO.tag);
    type Params = CounterParams;
    type In = CounterIn;

    #[inline(always)]
    fn live_params(&self) -> CounterParams {
        CounterParams {
            active: self.wInputActive,
            values: [self.nPresetValue.to_bits(), self.nCounterLimit.to_bits()],
        }
    }
    #[inline(always)]
    fn latched_params(&self) -> CounterParams {
        let p = self.private();
        CounterParams {
            active: u16::from(p.stHeader.nActive),
            values: p.adwParam,
        }
    }
    /// Bits 0–2 only (ABI-2 §11.5); PresetValue and CounterLimit take every value of `T`.
    const RULES: &'static [RuleDef<CounterParams>] =
        &[rule!(no_bits_outside "wInputActive", |p| p.active, SL_COUNTER_ACTIVE_INPUTS)];
    fn store_params(&mut self, p: &CounterParams) {
        let q = self.private_mut();
        q.stHeader.nActive = p.active as u8;
        q.adwParam = p.values;
    }
    fn latched_crc(&self) -> u16 {
        let p = self.private();
        let [preset, limit] = p.adwParam;
        param_crc(
            Self::MAGIC,
            p.stHeader.nActive,
            0,
            0,
            &crc_words![u32 preset, u32 limit],
        )
    }
    /// Inactive inputs read FALSE; an invalid byte reads FALSE and makes no edge (ABI-2
    /// §12.7, semantics C7). The edge memories follow the levels in every state, so an
    /// input already TRUE when the block starts is not an edge.
    #[inline(always)]
    fn decode(&mut self) -> (CounterIn, bool) {
        let active = self.private().stHeader.nActive;
        // An inactive input reads 0 whatever its byte holds.
        let byte = |raw: u8, bit: u8| if active & bit != 0 { raw } else { 0 };
        let raw = [
            byte(self.bReset, 1),
            byte(self.bCountUp, 2),
            byte(self.bCountDown, 4),
        ];
        let h = &mut self.private_mut().stHeader;
        let mut prev = h.wAux as u8;
        let up = bools::edge(raw[1], &mut prev, PREV_UP);
        let down = bools::edge(raw[2], &mut prev, PREV_DOWN);
        h.wAux = u16::from(prev);
        (
            CounterIn {
                reset: bools::is_true(raw[0]),
                up: up.rising,
                down: down.rising,
            },
            bools::any_invalid(&raw),
        )
    }
    fn start(&mut self, inp: &CounterIn, _now: u32) {
        // Entering RUN is where the outputs start to carry values: verify the latched
        // parameters first (C3).
        if self.corrupt_at_switch_on(true) {
            return;
        }
        let v = self.start_value(inp);
        let p = self.private_mut();
        p.dwCount = v;
        p.stHeader.nState = SL_STATE_RUN;
    }
    #[inline(always)]
    fn step(&mut self, inp: &CounterIn, _now: u32) -> Status {
        let p = self.private();
        let count = T::from_bits(p.dwCount).wide();
        let next = if inp.reset {
            T::from_bits(p.adwParam[0]).wide()
        } else {
            count + i128::from(inp.up) - i128::from(inp.down)
        };
        let p = self.private_mut();
        if next < T::MIN {
            p.adwPar = [p.dwCount, T::narrow(T::MIN).to_bits()];
            p.dwCount = 0;
            p.stHeader.enter_error(SL_DIAG_VALUE_UNDERFLOW);
        } else if next > T::MAX {
            p.adwPar = [p.dwCount, T::narrow(T::MAX).to_bits()];
            p.dwCount = 0;
            p.stHeader.enter_error(SL_DIAG_VALUE_OVERFLOW);
        } else {
            p.dwCount = T::narrow(next).to_bits();
        }
        Status::Ok
    }
    // A range error is an event: nothing remains after it (ABI-2 §11.5, semantics K3).
    // `error_remains` keeps its default (false).
    crate::base::envelope::steady_hooks!();

    #[inline(always)]
    fn write_outputs(&mut self) {
        let p = *self.private();
        let h = p.stHeader;
        let run = h.nState == SL_STATE_RUN;
        let count = value_if::<T>(run, p.dwCount);
        let limit = T::from_bits(p.adwParam[1]);
        self.bError = u8::from(h.nState == SL_STATE_ERROR);
        self.bCounterOut = u8::from(run && count.wide() >= limit.wide());
        self.bCounterZero = u8::from(run && count.wide() == 0);
        self.nActValue = count;
        self.nState = h.nState;
        self.nDiag = h.wDiag;
        (self.nDiagTextId, self.dwDiagPar2, self.dwDiagPar3) = range_message(
            &h,
            [SL_TEXT_COUNTER_UNDERFLOW, SL_TEXT_COUNTER_OVERFLOW],
            p.adwPar,
        );
    }
}

// The fast-path slot (`base::envelope`) in the private part's first reserved word.
crate::base::envelope::steady_private!(SL_COUNTER_PRIVATE, aReserved0, bytes u16);

impl<T: Analog, const P1: usize, const P2: usize> crate::base::envelope::Steady
    for FB_COUNTER<T, P1, P2>
{
    /// Reset, CountUp, CountDown, bRun and bErrAck gathered into bits (the edge memories
    /// are in the private header, which the stored key is bound to). The counter word is
    /// not in the key: a full call with these bytes keeps it, but writes it in its
    /// canonical form (the value's bits, sign-extended) and, while Reset is TRUE, as the
    /// preset. A counter word that a full call would rewrite so has no key: the call is
    /// full.
    #[inline(always)]
    fn steady_key(&self) -> Option<u16> {
        let p = &self.stPrivate;
        if T::from_bits(p.dwCount).to_bits() != p.dwCount
            || self.bReset != 0 && p.dwCount != p.adwParam[0]
        {
            return None;
        }
        bools::key([
            self.bReset,
            self.bCountUp,
            self.bCountDown,
            self.bRun,
            self.bErrAck,
        ])
    }
    /// No timer: the outcome depends on the time only through the clock check.
    #[inline(always)]
    fn quiet(&self) -> bool {
        true
    }
}
