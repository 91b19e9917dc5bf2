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

super::analog_variants! {
    FB_COUNTER:
        INT SL_TYPE_COUNTER_INT = 56 => FB_COUNTER_INT[i16, 6, 6], UINT SL_TYPE_COUNTER_UINT = 57 => FB_COUNTER_UINT[u16, 6, 6],
        DINT SL_TYPE_COUNTER_DINT = 58 => FB_COUNTER_DINT[i32, 2, 4], UDINT SL_TYPE_COUNTER_UDINT = 59 => FB_COUNTER_UDINT[u32, 2, 4]
}

/// Diag message "An underflow has occurred" (parameters: ActValue, smallest permitted value).
pub const SL_TEXT_COUNTER_UNDERFLOW: u16 = 0x40B8;
/// Diag message "An overflow has occurred" (parameters: ActValue, largest permitted value).
pub const SL_TEXT_COUNTER_OVERFLOW: u16 = 0x40B9;

/// `wInputActive` bits of Reset, CountUp, CountDown (optional: an inactive input reads FALSE).
pub const SL_COUNTER_ACTIVE_INPUTS: u16 = 0x0007;

crate::base::layout::private_struct! {
    /// Private state of FB COUNTER (56 bytes). Never written by the user.
    SL_COUNTER_PRIVATE {
        /// Common head (`nActive`: latched `wInputActive`; `wAux`: previous CountUp (bit 0) and
        /// CountDown (bit 1) levels for the edges).
        stHeader;
        /// Reserved.
        pub aReserved0: [u8; 4],
        /// Latched `nPresetValue`, `nCounterLimit` as 32-bit patterns.
        pub adwParam: [u32; 2],
        /// The counter (ActValue) as a 32-bit pattern.
        pub dwCount: u32,
        /// Diag message parameters 2 and 3 latched at the ERROR entry.
        pub adwPar: [u32; 2],
        /// Reserved.
        pub aReserved1: [u8; 4],
    }
}

crate::base::layout::block_struct! {
    /// FB COUNTER instance (ABI-2 §11.5), generic over the type `T` of its values; `P1` and
    /// `P2` are the reserved gaps (after `wInputActive`, after ActValue) that make the 16- and
    /// 32-bit layouts differ.
    FB_COUNTER[T: Analog; P1, P2] {
        /// Offset 0. Reset: TRUE (level) sets ActValue to PresetValue (active bit 0).
        pub bReset: SL_BOOL,
        /// Offset 1. CountUp: a rising edge adds 1 (active bit 1).
        pub bCountUp: SL_BOOL,
        /// Offset 2. CountDown: a rising edge subtracts 1 (active bit 2).
        pub bCountDown: SL_BOOL,
        /// Offset 3. Reserved, keep 0.
        pub aReserved0: [u8; 13],
        /// Offset 16. FbRun of the owning group: TRUE = the block executes.
        pub bRun: SL_BOOL,
        /// Offset 17. ErrAck of the owning group.
        pub bErrAck: SL_BOOL,
        /// Offset 18. Reserved, keep 0.
        pub aReserved1: [u8; 2],
        /// At 20: "Preset Value", ActValue while Reset is TRUE.
        pub nPresetValue: T,
        /// At 20 + W: "Counter Limit": CounterOut = ActValue ≥ CounterLimit.
        pub nCounterLimit: T,
        /// At 20 + 2W: bits 0–2 (Reset, CountUp, CountDown), no other.
        pub wInputActive: u16,
        /// Reserved up to the output base 32 (16-bit: 6 bytes, 32-bit: 2).
        pub aReserved2: [u8; P1],
        /// Output base 32: Error, TRUE in ERROR only.
        pub bError: SL_BOOL,
        /// 33: CounterOut, in RUN: ActValue ≥ CounterLimit.
        pub bCounterOut: SL_BOOL,
        /// 34: CounterZero, in RUN: ActValue == 0.
        pub bCounterZero: SL_BOOL,
        /// 35. Reserved.
        pub aReserved3: [u8; 5],
        /// Analog output base 40: ActValue, the counter in RUN, else 0.
        pub nActValue: T,
        /// Reserved up to the info data 48 (16-bit: 6 bytes, 32-bit: 4).
        pub aReserved4: [u8; P2],
    } info [aReserved5, aReserved6] SL_COUNTER_PRIVATE, "56 bytes":
        "the manual's status value (RUN, STOP, ERROR, RESET).",
        "diag value (1 underflow, 2 overflow) + library bits 13-15.",
        "Text ID of the latched diag message (0x40B8, 0x40B9), 0 = none.",
        "message parameter 2 (ActValue before the step, as a 32-bit pattern).",
        "message parameter 3 (the smallest / largest value of the type)."
}

// The ABI-2 §11.5 layout, every variant: parameters from 20, output base 32, ActValue at
// 40, info at 48, private at 64.
const _: () = assert!(core::mem::size_of::<SL_COUNTER_PRIVATE>() == 56);

crate::base::block::block_states!(
    /// The states of FB COUNTER, every variant (manual §4.22.2): no SAFE.
    CounterState: Run, Stop, Error, Reset
);

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
            raw.iter().any(|&b| b > 1),
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
