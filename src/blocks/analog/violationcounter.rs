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

super::analog_variants! {
    FB_VIOLATIONCOUNTER:
        UINT SL_TYPE_VIOLATIONCOUNTER_UINT = 68 => FB_VIOLATIONCOUNTER_UINT[u16, 2, 6], UDINT SL_TYPE_VIOLATIONCOUNTER_UDINT = 69 => FB_VIOLATIONCOUNTER_UDINT[u32, 4, 4]
}

/// `wInputActive` of FB VIOLATIONCOUNTER: Input (bit 0) and Enable (bit 1), both required.
pub const SL_VIOLATIONCOUNTER_ACTIVE: u16 = 0x0003;

crate::base::layout::private_struct! {
    /// Private state of FB VIOLATIONCOUNTER (48 bytes). Never written by the user.
    SL_VIOLATIONCOUNTER_PRIVATE {
        /// Common head (`nActive`, `nNegated`: the latched bit sets).
        stHeader;
        /// Latched Increment Error, Decrement No Error, Counter Limit as 32-bit patterns.
        pub adwParam: [u32; 3],
        /// The error counter.
        pub dwCount: u32,
        /// Reserved.
        pub aReserved: [u8; 4],
    }
}

crate::base::layout::block_struct! {
    /// FB VIOLATIONCOUNTER instance (ABI-2 §11.12), generic over the unsigned type `T`; `P1`
    /// (after `wInputNegated`) and `P2` (after ActViolationCnt) are the reserved gaps that make
    /// the two layouts differ.
    FB_VIOLATIONCOUNTER[T: Unsigned; P1, P2] {
        /// Offset 0. Input: logically TRUE decrements, FALSE increments (active bit 0,
        /// negation bit 0).
        pub bInput: SL_BOOL,
        /// Offset 1. Enable: FALSE = START, counter 0 (active bit 1).
        pub bEnable: SL_BOOL,
        /// Offset 2. Reserved, keep 0.
        pub aReserved0: [u8; 14],
        /// Offset 16. FbRun of the owning group: TRUE = the block executes.
        pub bRun: SL_BOOL,
        /// Offset 17. ErrAck of the owning group.
        pub bErrAck: SL_BOOL,
        /// Offset 18. Reserved, keep 0.
        pub aReserved1: [u8; 2],
        /// At 20: "Increment Error", added per call with a violation.
        pub nIncrementError: T,
        /// At 20 + W: "Decrement No Error", subtracted per call without one.
        pub nDecrementNoError: T,
        /// At 20 + 2W: "Counter Limit" (≥ 1): InputOK = counter < limit.
        pub nCounterLimit: T,
        /// At 20 + 3W: bits 0 and 1 must be set (SL_VIOLATIONCOUNTER_ACTIVE).
        pub wInputActive: u16,
        /// At 22 + 3W: bit 0 set = Input is negated; no other bit.
        pub wInputNegated: u16,
        /// Reserved up to the output base (16-bit 32, 32-bit 40).
        pub aReserved2: [u8; P1],
        /// Output base + 0. Reserved (the block has no Error output).
        pub aReserved3: [u8; 1],
        /// Output base + 1: InputOK, TRUE in RUN only.
        pub bInputOK: SL_BOOL,
        /// Output base + 2. Reserved.
        pub aReserved4: [u8; 6],
        /// Output base + 8: ActViolationCnt, the counter in RUN and SAFE, else 0.
        pub nActViolationCnt: T,
        /// Reserved up to the info data.
        pub aReserved5: [u8; P2],
    } info [aReserved6, aReserved7] SL_VIOLATIONCOUNTER_PRIVATE, "48 bytes":
        "the manual's status value (RUN, STOP, SAFE, START; ERROR, RESET).",
        "0 (no diag values) + library bits 13-15.", "always 0 (the block has no diag message).",
        "always 0.", "always 0."
}

// The ABI-2 §11.12 numbers of the two layouts (output base).
const _: () = {
    use core::mem::{offset_of, size_of};
    assert!(offset_of!(FB_VIOLATIONCOUNTER_UINT, bInputOK) == 33);
    assert!(offset_of!(FB_VIOLATIONCOUNTER_UDINT, bInputOK) == 41);
    assert!(size_of::<SL_VIOLATIONCOUNTER_PRIVATE>() == 48);
};

crate::base::block::block_states!(
    /// The states of FB VIOLATIONCOUNTER, both variants (manual §4.33.2; ERROR and RESET
    /// for the library's faults).
    ViolationCounterState: Run, Stop, Safe, Error, Reset, Start
);

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
