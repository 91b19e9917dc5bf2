//! FB ENVELOPE — manual §4.32 and `fb-envelope-states.txt`; layout ABI-2 §11.11, rules
//! ABI-2 §12.
//!
//! SafeFunctionOut follows SafeFunction TRUE at once (RUN). When SafeFunction falls in RUN
//! the block latches |InValue| and monitors the stop: MONITOR while |InValue| is above
//! TargetValue, where |InValue| must stay within the envelope E(t) falling linearly from
//! |InValue| + Offset to TargetValue at MaxTime (else ERROR, diag 1 or 2 with messages
//! 0x40C8 / 0x40C9); DELAYOUT while |InValue| is within ±TargetValue, until "Time after in
//! Target" has run in the window (reset when InValue leaves it); SAFE when that time or
//! MaxTime (at the latest) has elapsed. States RUN (1), STOP (2), SAFE (3), ERROR (4), RESET
//! (5), DELAYOUT (8), MONITOR (9). Readings: docs/semantics.md EV1–EV7. One implementation
//! for the four integer types.

#![allow(non_camel_case_types)] // the ABI's names (FB_ENVELOPE_INT …)

use super::{diag_message, magic, Analog};
use crate::base::block::{Private, Registered};
use crate::base::bools;
use crate::base::envelope::{params_map, Block};
use crate::base::header::{crc_words, param_crc};
use crate::base::reason::rule;
use crate::base::reason::{when, Rule, RuleDef, Unit};
use crate::base::time;
use crate::base::types::*;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/analog/envelope.rs"));

/// Diag value texts (manual §4.32.2).
const DIAG_VALUES: &[(u16, &str)] = &[
    (0, "No diagnostic information"),
    (
        SL_DIAG_ENVELOPE_UNDERFLOW,
        "Underflow (InValue below the envelope)",
    ),
    (
        SL_DIAG_ENVELOPE_OVERFLOW,
        "Overflow (InValue above the envelope)",
    ),
    (SL_DIAG_ENVELOPE_INVALUE_ERROR, "InValue Error"),
    (SL_DIAG_ENVELOPE_MAX_TIME, "MaxTimeExpired"),
];

crate::impl_member!([T: Analog, const P1: usize] FB_ENVELOPE<T, P1> {
    info: crate::blocks::analog::variant_info!(T, "ENVELOPE", EnvelopeState, DIAG_VALUES;
        INT = SL_TYPE_ENVELOPE_INT, UINT = SL_TYPE_ENVELOPE_UINT, DINT = SL_TYPE_ENVELOPE_DINT, UDINT = SL_TYPE_ENVELOPE_UDINT),
    state: EnvelopeState,
    private: SL_ENVELOPE_PRIVATE,
    input: [bSafeFunction, nInValue],
    param: [tTimeAfterInTarget, tMaxTime, nTargetValue, nOffset, wInputActive],
    output: [bError, bSafeFunctionOut],
    info_fields: [nDiagTextId, dwDiagPar2, dwDiagPar3],
});

/// Parameters as the user wrote them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EnvelopeParams {
    active: u16,
    values: [u32; 4],
}

/// Indices of the latched values (`adwParam`): the two times, then TargetValue and Offset.
const IN_TARGET_TIME: usize = 0;
const MAX_TIME: usize = 1;

/// One cycle's inputs: SafeFunction after decoding, InValue exact.
#[derive(Clone, Copy, Debug)]
pub struct EnvelopeIn {
    safe_function: bool,
    value: i128,
}

/// The envelope at `t` ms after the SafeFunction edge (ABI-2 §11.11, semantics EV3): the
/// straight line from `start` at 0 to `target` at `max_time`, as one quotient rounded down
/// (never above the exact line), never below `target`.
fn envelope_at(start: u64, target: u64, t: u32, max_time: u32) -> u64 {
    let (t, max) = (u64::from(t.min(max_time)), u64::from(max_time.max(1)));
    // start, target < 2^33 and t ≤ max < 2^16: the products stay below 2^50.
    ((start * (max - t) + target * t) / max).max(target)
}

impl<T: Analog, const P1: usize> FB_ENVELOPE<T, P1> {
    /// The next state with SafeFunction FALSE after the edge (MONITOR or DELAYOUT, or the
    /// state being entered from RUN): MaxTime first, then the target window and its timer,
    /// then the envelope (semantics EV2–EV5). A violation enters ERROR here, with its diag
    /// value and message parameters, and returns ERROR.
    fn monitor(&mut self, value: i128, now: u32) -> u8 {
        let p = self.private();
        let [in_target_time, max_time, target, offset] = p.adwParam;
        let t = time::elapsed(now, p.stHeader.tPhase);
        if t >= max_time {
            return SL_STATE_SAFE;
        }
        let magnitude = value.unsigned_abs();
        if magnitude <= u128::from(target) {
            if p.stHeader.nState != SL_STATE_DELAYOUT {
                self.private_mut().tInTarget = now;
            }
            let start = self.private().tInTarget;
            return if time::reached(now, start, in_target_time) {
                SL_STATE_SAFE
            } else {
                SL_STATE_DELAYOUT
            };
        }
        let start = u64::from(p.dwInValueLatch) + u64::from(offset);
        let limit = envelope_at(start, u64::from(target), t, max_time);
        if magnitude <= u128::from(limit) {
            return SL_STATE_ENVELOPE_MONITOR;
        }
        // |InValue| > E(t) ≥ 0, so InValue ≠ 0 and ∓E(t) lies within the range of T.
        let (diag, bound) = if value < 0 {
            (SL_DIAG_ENVELOPE_UNDERFLOW, -i128::from(limit))
        } else {
            (SL_DIAG_ENVELOPE_OVERFLOW, i128::from(limit))
        };
        let p = self.private_mut();
        p.adwPar = [T::narrow(value).to_bits(), T::narrow(bound).to_bits()];
        p.stHeader.enter_error(diag);
        SL_STATE_ERROR
    }
}

/// SafeFunctionOut is on in these states.
const fn output_on(state: u8) -> bool {
    state == SL_STATE_RUN || state == SL_STATE_DELAYOUT || state == SL_STATE_ENVELOPE_MONITOR
}

impl<T: Analog, const P1: usize> Block for FB_ENVELOPE<T, P1> {
    const MAGIC: u16 = magic(<Self as Registered>::INFO.tag);
    params_map!(EnvelopeParams {
        active: wInputActive => wActive,
        values: [tTimeAfterInTarget, tMaxTime, nTargetValue, nOffset] => adwParam,
    });
    type In = EnvelopeIn;

    /// Both inputs active and nothing else (ABI-2 §10.5); both times ≤ 65 535 ms, MaxTime
    /// ≥ 1 (ABI-2 §11.11, §12.9).
    const RULES: &'static [RuleDef<EnvelopeParams>] = &[
        rule!(equals "wInputActive", |p| p.active, SL_ENVELOPE_ACTIVE),
        RuleDef::new("tTimeAfterInTarget", Rule::AtMost, Unit::Ms, |p| {
            let t = p.values[IN_TARGET_TIME];
            when(t > SL_ENVELOPE_TIME_MAX, t, SL_ENVELOPE_TIME_MAX)
        }),
        rule!(not_zero "tMaxTime" in Ms, |p| p.values[MAX_TIME]),
        RuleDef::new("tMaxTime", Rule::AtMost, Unit::Ms, |p| {
            let t = p.values[MAX_TIME];
            when(t > SL_ENVELOPE_TIME_MAX, t, SL_ENVELOPE_TIME_MAX)
        }),
    ];
    fn latched_crc(&self) -> u16 {
        let p = self.private();
        let [a, b, c, d] = p.adwParam;
        param_crc(
            Self::MAGIC,
            p.wActive as u8,
            (p.wActive >> 8) as u8,
            0,
            &crc_words![u32 a, u32 b, u32 c, u32 d],
        )
    }
    /// An invalid SafeFunction byte reads FALSE, the request for the monitored stop (ABI-2
    /// §12.7).
    #[inline(always)]
    fn decode(&mut self) -> (EnvelopeIn, bool) {
        let raw = bools::pack([self.bSafeFunction]);
        (
            EnvelopeIn {
                safe_function: bools::logical(raw, 1, 0) != 0,
                value: self.nInValue.wide(),
            },
            raw.invalid != 0,
        )
    }
    /// STOP → run and RESET → run: SafeFunction TRUE → RUN, else SAFE (there was no edge to
    /// monitor, semantics EV1).
    fn start(&mut self, inp: &EnvelopeIn, now: u32) {
        self.private_mut().stHeader.nState = SL_STATE_SAFE;
        self.step(inp, now);
    }
    #[inline(always)]
    fn step(&mut self, inp: &EnvelopeIn, now: u32) -> Status {
        let state = self.private().stHeader.nState;
        let next = if inp.safe_function {
            SL_STATE_RUN
        } else {
            match state {
                SL_STATE_RUN => {
                    let p = self.private_mut();
                    p.dwInValueLatch = inp.value.unsigned_abs() as u32;
                    p.stHeader.tPhase = now;
                    self.monitor(inp.value, now)
                }
                SL_STATE_DELAYOUT | SL_STATE_ENVELOPE_MONITOR => self.monitor(inp.value, now),
                _ => SL_STATE_SAFE,
            }
        };
        if next == SL_STATE_ERROR {
            return Status::Ok;
        }
        // SafeFunctionOut switching on is where the latched parameters are verified (C3).
        if self.corrupt_at_switch_on(output_on(next) && !output_on(state)) {
            return Status::Corrupt;
        }
        self.private_mut().stHeader.nState = next;
        Status::Ok
    }
    // Envelope violations are events: nothing remains (ABI-2 §12.5); `error_remains` keeps
    // its default (false).
    #[inline(always)]
    fn write_outputs(&mut self) {
        let p = *self.private();
        let h = p.stHeader;
        self.bError = u8::from(h.nState == SL_STATE_ERROR);
        self.bSafeFunctionOut = u8::from(output_on(h.nState));
        self.nState = h.nState;
        self.nDiag = h.wDiag;
        (self.nDiagTextId, self.dwDiagPar2, self.dwDiagPar3) = diag_message(
            &h,
            &[
                (SL_DIAG_ENVELOPE_UNDERFLOW, SL_TEXT_ENVELOPE_UNDERFLOW),
                (SL_DIAG_ENVELOPE_OVERFLOW, SL_TEXT_ENVELOPE_OVERFLOW),
            ],
            p.adwPar,
        );
    }
}
