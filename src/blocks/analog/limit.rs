//! FB LIMIT — manual §4.21; layout ABI-2 §11.4, rules ABI-2 §12.
//!
//! Checks AnalogIn against a minimum and a maximum, each taken from an input (active bit 9
//! / 10 set: "If the FB inputs are active, they are used") or from a parameter (bit clear).
//! RUN ⇔ Min ≤ AnalogIn ≤ Max (InLimit); otherwise SAFE with BelowMin = AnalogIn < Min and
//! AboveMax = AnalogIn > Max; both directions automatic. Min > Max from the parameters
//! alone is a configuration error (`SL_E_CONFIG`, ABI-2 §12.8); with an input involved it
//! is the manual's ERROR, diag value 1, message 0x4090 (parameters 2 and 3: Min, Max), and
//! it remains while Min > Max. States RUN (1), STOP (2), SAFE (3), ERROR (4), RESET (5).
//! Readings: docs/semantics.md L1–L4. One implementation for the four integer types.

#![allow(non_camel_case_types)] // the ABI's names (FB_LIMIT_INT …)

use super::{diag_message, limit_outputs, magic, Analog, LIMIT_ABOVE, LIMIT_BELOW};
use crate::base::block::{Private, Registered};
use crate::base::envelope::{params_map, Block};
use crate::base::header::F_CFG_INVALID;
use crate::base::header::{crc_words, param_crc};
use crate::base::reason::rule;
use crate::base::reason::{check, when, Rule, RuleDef, Unit};
use crate::base::types::*;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/analog/limit.rs"));

// The ABI-2 §11.4 numbers of the two layouts.
const _: () = {
    use core::mem::{offset_of, size_of};
    assert!(offset_of!(FB_LIMIT_INT, wInputActive) == 34 && offset_of!(FB_LIMIT_INT, bError) == 40);
    assert!(offset_of!(FB_LIMIT_UDINT, wInputActive) == 44);
    assert!(offset_of!(FB_LIMIT_UDINT, bError) == 48);
    assert!(offset_of!(FB_LIMIT_INT, stPrivate) == 64);
    assert!(offset_of!(FB_LIMIT_DINT, stPrivate) == 72);
    assert!(size_of::<SL_LIMIT_PRIVATE>() == 48);
};

/// Diag value texts (manual §4.21.2).
const DIAG_VALUES: &[(u16, &str)] = &[
    (0, "No diagnostic information"),
    (
        SL_DIAG_LIMIT_MIN_ABOVE_MAX,
        "MinValue is greater than MaxValue",
    ),
];

crate::impl_member!([T: Analog, const P1: usize] FB_LIMIT<T, P1> {
    info: crate::blocks::analog::variant_info!(T, "LIMIT", LimitState, DIAG_VALUES;
        INT = SL_TYPE_LIMIT_INT, UINT = SL_TYPE_LIMIT_UINT, DINT = SL_TYPE_LIMIT_DINT, UDINT = SL_TYPE_LIMIT_UDINT),
    state: LimitState,
    private: SL_LIMIT_PRIVATE,
    input: [nAnalogIn, nMinValue, nMaxValue],
    param: [nMinimumValue, nMaximumValue, wInputActive],
    output: [bError, bInLimit, bBelowMin, bAboveMax],
    info_fields: [nDiagTextId, dwDiagPar2, dwDiagPar3],
});

/// Parameters as the user wrote them (the limits as 32-bit patterns of `T`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LimitParams {
    active: u16,
    limits: [u32; 2],
}

/// One cycle's inputs: AnalogIn and the effective limits, exact.
#[derive(Clone, Copy, Debug)]
pub struct LimitIn {
    value: i128,
    min: i128,
    max: i128,
}

/// The value of a `T` stored as its pattern.
fn wide<T: Analog>(bits: u32) -> i128 {
    T::from_bits(bits).wide()
}

impl<T: Analog, const P1: usize> Block for FB_LIMIT<T, P1> {
    const MAGIC: u16 = magic(<Self as Registered>::INFO.tag);
    params_map!(LimitParams {
        active: wInputActive => wActive,
        limits: bits [nMinimumValue, nMaximumValue] => adwLimit,
    });
    type In = LimitIn;

    /// AnalogIn active, no bit beyond 8–10 (ABI-2 §10.5); both limits from the parameters
    /// with Minimum > Maximum is a parameter-only check (ABI-2 §12.8, semantics L2), with the
    /// manual's Text ID 0x4090.
    const RULES: &'static [RuleDef<LimitParams>] = &[
        rule!(no_bits_outside "wInputActive", |p| p.active, SL_LIMIT_ACTIVE_ANALOGIN | SL_LIMIT_ACTIVE_MINVALUE | SL_LIMIT_ACTIVE_MAXVALUE),
        RuleDef::new("wInputActive", Rule::BitsSet, Unit::Hex, |p| {
            let need = SL_LIMIT_ACTIVE_ANALOGIN;
            when(p.active & need == 0, p.active, need)
        }),
        RuleDef::new(
            "nMinimumValue",
            Rule::NotAbove("nMaximumValue"),
            Unit::Plain,
            |p| {
                let [min, max] = min_max::<T>(p);
                let from_params =
                    p.active & (SL_LIMIT_ACTIVE_MINVALUE | SL_LIMIT_ACTIVE_MAXVALUE) == 0;
                when(from_params && min > max, min, max)
            },
        )
        .text_id(SL_TEXT_LIMIT_MIN_ABOVE_MAX),
    ];
    fn latched_crc(&self) -> u16 {
        let p = self.private();
        let [min, max] = p.adwLimit;
        param_crc(
            Self::MAGIC,
            0,
            0,
            0,
            &crc_words![u16 p.wActive, u32 min, u32 max],
        )
    }
    #[inline(always)]
    fn decode(&mut self) -> (LimitIn, bool) {
        let p = self.private();
        let pick = |bit: u16, input: T, param: u32| {
            if p.wActive & bit != 0 {
                input.wide()
            } else {
                wide::<T>(param)
            }
        };
        (
            LimitIn {
                value: self.nAnalogIn.wide(),
                min: pick(SL_LIMIT_ACTIVE_MINVALUE, self.nMinValue, p.adwLimit[0]),
                max: pick(SL_LIMIT_ACTIVE_MAXVALUE, self.nMaxValue, p.adwLimit[1]),
            },
            false,
        )
    }
    fn start(&mut self, inp: &LimitIn, now: u32) {
        self.step(inp, now);
    }
    #[inline(always)]
    fn step(&mut self, inp: &LimitIn, _now: u32) -> Status {
        if inp.min > inp.max {
            let p = self.private_mut();
            p.adwPar = [T::narrow(inp.min).to_bits(), T::narrow(inp.max).to_bits()];
            p.stHeader.enter_error(SL_DIAG_LIMIT_MIN_ABOVE_MAX);
            return Status::Ok;
        }
        let in_limit = inp.min <= inp.value && inp.value <= inp.max;
        // InLimit switching on is where the latched parameters are verified (C3).
        if self.corrupt_entering_run(in_limit) {
            return Status::Corrupt;
        }
        let h = &mut self.private_mut().stHeader;
        if in_limit {
            h.nState = SL_STATE_RUN;
            h.wAux = 0;
        } else {
            h.nState = SL_STATE_SAFE;
            h.wAux = if inp.value < inp.min {
                LIMIT_BELOW
            } else {
                LIMIT_ABOVE
            };
        }
        Status::Ok
    }
    /// The limits still cross (ABI-2 §12.5).
    fn error_remains(&mut self, inp: &LimitIn) -> bool {
        inp.min > inp.max
    }
    #[inline(always)]
    fn write_outputs(&mut self) {
        let p = *self.private();
        let h = p.stHeader;
        [self.bError, self.bInLimit, self.bBelowMin, self.bAboveMax] = limit_outputs(&h);
        self.nState = h.nState;
        self.nDiag = h.wDiag;
        (self.nDiagTextId, self.dwDiagPar2, self.dwDiagPar3) = diag_message(
            &h,
            &[(SL_DIAG_LIMIT_MIN_ABOVE_MAX, SL_TEXT_LIMIT_MIN_ABOVE_MAX)],
            p.adwPar,
        );
        // Refused because Minimum > Maximum from the parameters: the manual's message with
        // its diag value, as in ERROR (ABI-2 §12.8, semantics L2, C15).
        if h.nState == SL_STATE_STOP && h.flag(F_CFG_INVALID) {
            let refusal = check(Self::RULES, &self.latched_params());
            if let Some(r) = refusal.filter(|r| r.info.text_id == SL_TEXT_LIMIT_MIN_ABOVE_MAX) {
                let bits = |v: i64| T::narrow(i128::from(v)).to_bits();
                self.nDiag = h.wDiag | SL_DIAG_LIMIT_MIN_ABOVE_MAX;
                (self.nDiagTextId, self.dwDiagPar2, self.dwDiagPar3) =
                    (SL_TEXT_LIMIT_MIN_ABOVE_MAX, bits(r.hit.a), bits(r.hit.b));
            }
        }
    }
}

/// The parameters' Minimum and Maximum as values of `T`.
fn min_max<T: Analog>(p: &LimitParams) -> [i64; 2] {
    p.limits.map(|l| wide::<T>(l) as i64)
}
