//! FB SCALE — manual §4.23; layout ABI-2 §11.6, rules ABI-2 §12.
//!
//! `AnalogOut = round((±AnalogIn) · Numerator ÷ Denominator) + Offset` in the manual's
//! processing order (negation, multiplication, division, offset; with
//! `SL_OPT_SCALE_DIVISION_FIRST` the division before the multiplication), every step exact.
//! The factors are 32-bit (T32): a negation or product outside T32 is ERROR diag value 3
//! (message 0x40B2), a quotient outside T32 diag value 4 (0x40B3), the result outside the
//! variant's type diag value 1 / 2 (0x40B0 / 0x40B1); parameter 2 of every message is
//! AnalogIn. The quotient is rounded per `nRounding` with FB DIV's rounding
//! (`arith::divide`). The error remains while the current input still computes out of
//! range. StuckAtError (`tWatchdog` ≠ 0): AnalogIn unchanged for `tWatchdog` ms in RUN; not
//! an FB error. States RUN (1), STOP (2), ERROR (4), RESET (5): no SAFE.
//! Readings: docs/semantics.md SC1–SC5. One implementation for the four integer types.

#![allow(non_camel_case_types)] // the ABI's names (FB_SCALE_INT …)

use super::arith::{divide, SL_ROUNDING_ROUND};
use super::{diag_message, in_range, magic, set_computed, Analog};
use super::{SL_DIAG_VALUE_OVERFLOW, SL_DIAG_VALUE_UNDERFLOW};
use crate::base::block::{Private, Registered};
use crate::base::envelope::{params_map, Block};
use crate::base::header::{crc_words, param_crc};
use crate::base::reason::rule;
use crate::base::reason::RuleDef;
use crate::base::time;
use crate::base::types::*;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/analog/scale.rs"));

// The ABI-2 §11.6 numbers (identical for both widths).
const _: () = {
    use core::mem::{offset_of, size_of};
    assert!(offset_of!(FB_SCALE_INT, nNumerator) == 32 && offset_of!(FB_SCALE_INT, nOffset) == 40);
    assert!(offset_of!(FB_SCALE_DINT, dwOptions) == 44);
    assert!(offset_of!(FB_SCALE_DINT, nRounding) == 48);
    assert!(offset_of!(FB_SCALE_UINT, wInputNegated) == 52);
    assert!(offset_of!(FB_SCALE_UINT, bError) == 56 && offset_of!(FB_SCALE_UINT, nAnalogOut) == 64);
    assert!(
        offset_of!(FB_SCALE_INT, stPrivate) == 88 && offset_of!(FB_SCALE_UDINT, stPrivate) == 88
    );
    assert!(size_of::<SL_SCALE_PRIVATE>() == 72);
};

/// Diag value texts (manual §4.23.2).
const DIAG_VALUES: &[(u16, &str)] = super::range_diag_values!(
    "AnalogOut",
    "No diagnostic information",
    ".",
    (
        SL_DIAG_SCALE_MUL_OVERFLOW,
        "A 32-bit overflow occurred during the multiplication."
    ),
    (
        SL_DIAG_SCALE_DIV_OVERFLOW,
        "A 32-bit overflow occurred during the division due to rounding."
    ),
);

/// Diag value → Text ID (manual §4.23.2 "Diag Message").
const TEXTS: &[(u16, u16)] = &[
    (SL_DIAG_VALUE_UNDERFLOW, SL_TEXT_SCALE_UNDERFLOW),
    (SL_DIAG_VALUE_OVERFLOW, SL_TEXT_SCALE_OVERFLOW),
    (SL_DIAG_SCALE_MUL_OVERFLOW, SL_TEXT_SCALE_MUL_OVERFLOW),
    (SL_DIAG_SCALE_DIV_OVERFLOW, SL_TEXT_SCALE_DIV_OVERFLOW),
];

crate::impl_member!([T: Analog, T32: Analog, const P1: usize, const P2: usize] FB_SCALE<T, T32, P1, P2> {
    info: crate::blocks::analog::variant_info!(T, "SCALE", ScaleState, DIAG_VALUES;
        INT = SL_TYPE_SCALE_INT, UINT = SL_TYPE_SCALE_UINT, DINT = SL_TYPE_SCALE_DINT, UDINT = SL_TYPE_SCALE_UDINT),
    state: ScaleState,
    private: SL_SCALE_PRIVATE,
    input: [nAnalogIn],
    param: [tWatchdog, nNumerator, nDenominator, nOffset, dwOptions, nRounding, wInputActive, wInputNegated],
    output: [bError, bStuckAtError, nAnalogOut],
    info_fields: [nDiagTextId, dwDiagPar2, dwDiagPar3],
});

/// Parameters as the user wrote them (the factors as 32-bit patterns of `T32`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ScaleParams {
    watchdog: u32,
    factors: [u32; 3],
    options: u32,
    rounding: u16,
    active: u16,
    negated: u16,
}

/// One cycle's input: AnalogIn as a pattern and what it scales to.
#[derive(Clone, Copy, Debug)]
pub struct ScaleIn {
    raw: u32,
    /// The result in range (as a pattern), or the diag value of the error.
    result: Result<u32, u16>,
}

/// `wAux`: the watchdog expired since the last change of AnalogIn.
const STUCK: u16 = 1;

/// The manual's processing order on the latched parameters, every step exact: negation,
/// multiplication and division (either order) within T32, offset, range of `T`.
fn scale<T: Analog, T32: Analog>(x: T, p: &SL_SCALE_PRIVATE) -> Result<u32, u16> {
    let t32 = |v: i128, diag: u16| {
        if (T32::MIN..=T32::MAX).contains(&v) {
            Ok(v)
        } else {
            Err(diag)
        }
    };
    let [num, den, off] = p.adwFactor.map(|f| T32::from_bits(f).wide());
    if den == 0 {
        // Refused when latched (SL_E_CONFIG): only a corrupted copy holds it.
        return Err(SL_DIAG_CORRUPT);
    }
    let mut x = x.wide();
    if p.wNegated & SL_SCALE_NEGATE_ANALOGIN != 0 {
        // Signed: a multiplication by −1 (−(−2³¹) leaves T32: diag 3); unsigned: XOR with
        // all ones, which is MAX − x.
        x = t32(
            if T::MIN < 0 { -x } else { T::MAX - x },
            SL_DIAG_SCALE_MUL_OVERFLOW,
        )?;
    }
    let mul = |v: i128| t32(v * num, SL_DIAG_SCALE_MUL_OVERFLOW);
    let div = |v: i128| t32(divide(v, den, p.wRounding), SL_DIAG_SCALE_DIV_OVERFLOW);
    let scaled = if p.dwOptions & SL_OPT_SCALE_DIVISION_FIRST != 0 {
        mul(div(x)?)?
    } else {
        div(mul(x)?)?
    };
    in_range::<T>(scaled + off).map(|y| y.to_bits())
}

impl<T: Analog, T32: Analog, const P1: usize, const P2: usize> Block for FB_SCALE<T, T32, P1, P2> {
    const MAGIC: u16 = magic(<Self as Registered>::INFO.tag);
    params_map!(ScaleParams {
        watchdog: tWatchdog => tWatchdog,
        factors: bits [nNumerator, nDenominator, nOffset] => adwFactor,
        options: dwOptions => dwOptions,
        rounding: nRounding => wRounding,
        active: wInputActive => wActive,
        negated: wInputNegated => wNegated,
    });
    type In = ScaleIn;

    /// AnalogIn active and nothing else, negation of AnalogIn only, the one option, a
    /// known rounding, watchdog ≤ 65,535 ms (ABI-2 §12.9) and Denominator ≠ 0 (a
    /// parameter-only check, ABI-2 §12.8, semantics SC2).
    const RULES: &'static [RuleDef<ScaleParams>] = &[
        rule!(equals "wInputActive", |p| p.active, SL_SCALE_ACTIVE_ANALOGIN),
        rule!(no_bits_outside "wInputNegated", |p| p.negated, SL_SCALE_NEGATE_ANALOGIN),
        rule!(no_bits_outside "dwOptions", |p| p.options, SL_OPT_SCALE_DIVISION_FIRST),
        rule!(at_most "nRounding" in Plain, |p| p.rounding, SL_ROUNDING_ROUND),
        rule!(at_most "tWatchdog" in Ms, |p| p.watchdog, SL_TIME_PARAM_MAX),
        rule!(not_zero "nDenominator" in Plain, |p| p.factors[1]),
    ];
    fn latched_crc(&self) -> u16 {
        let p = self.private();
        let [num, den, off] = p.adwFactor;
        param_crc(
            Self::MAGIC,
            0,
            0,
            0,
            &crc_words![
                u32 p.tWatchdog, u32 num, u32 den, u32 off, u32 p.dwOptions,
                u16 p.wRounding, u16 p.wActive, u16 p.wNegated
            ],
        )
    }
    #[inline(always)]
    fn decode(&mut self) -> (ScaleIn, bool) {
        let x = self.nAnalogIn;
        (
            ScaleIn {
                raw: x.to_bits(),
                result: scale::<T, T32>(x, self.private()),
            },
            false,
        )
    }
    /// STOP → run and RESET → RUN restart the watchdog (semantics SC4).
    fn start(&mut self, inp: &ScaleIn, now: u32) {
        let p = self.private_mut();
        p.dwLastIn = inp.raw;
        p.stHeader.tPhase = now;
        p.stHeader.wAux = 0;
        self.step(inp, now);
    }
    #[inline(always)]
    fn step(&mut self, inp: &ScaleIn, now: u32) -> Status {
        // Entering RUN is where the output starts to carry a value: verify the latched
        // parameters first (C3).
        if self.corrupt_entering_run(inp.result.is_ok()) {
            return Status::Corrupt;
        }
        let p = self.private_mut();
        match set_computed(&mut p.stHeader, &mut p.dwOut, inp.result) {
            Ok(()) => {
                if inp.raw != p.dwLastIn {
                    p.dwLastIn = inp.raw;
                    p.stHeader.tPhase = now;
                    p.stHeader.wAux = 0;
                } else if p.tWatchdog != 0 && time::reached(now, p.stHeader.tPhase, p.tWatchdog) {
                    // Latched, not recomputed: it holds across a wrap of the elapsed time.
                    p.stHeader.wAux = STUCK;
                }
            }
            Err(diag) => {
                p.dwPar = inp.raw;
                if diag == SL_DIAG_CORRUPT {
                    return Status::Corrupt;
                }
            }
        }
        Status::Ok
    }
    /// The current input still computes out of range (ABI-2 §12.5).
    fn error_remains(&mut self, inp: &ScaleIn) -> bool {
        inp.result.is_err()
    }
    #[inline(always)]
    fn write_outputs(&mut self) {
        let p = *self.private();
        let h = p.stHeader;
        let run = h.nState == SL_STATE_RUN;
        self.bError = u8::from(h.nState == SL_STATE_ERROR);
        self.bStuckAtError = u8::from(run && h.wAux == STUCK);
        self.nAnalogOut = if run { T::from_bits(p.dwOut) } else { T::ZERO };
        self.nState = h.nState;
        self.nDiag = h.wDiag;
        (self.nDiagTextId, self.dwDiagPar2, self.dwDiagPar3) =
            diag_message(&h, TEXTS, [p.dwPar, 0]);
    }
}
