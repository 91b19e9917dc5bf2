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

super::analog_variants! {
    FB_SCALE:
        INT SL_TYPE_SCALE_INT = 40 => FB_SCALE_INT[i16, i32, 2, 6], UINT SL_TYPE_SCALE_UINT = 41 => FB_SCALE_UINT[u16, u32, 2, 6],
        DINT SL_TYPE_SCALE_DINT = 42 => FB_SCALE_DINT[i32, i32, 0, 4], UDINT SL_TYPE_SCALE_UDINT = 43 => FB_SCALE_UDINT[u32, u32, 0, 4]
}

/// `dwOptions`: "Multiplication First" FALSE — divide by `nDenominator` before multiplying
/// by `nNumerator` (default: multiplication first).
pub const SL_OPT_SCALE_DIVISION_FIRST: u32 = 1 << 8;

/// Diag value 3: "A 32-bit overflow occurred during the multiplication."
pub const SL_DIAG_SCALE_MUL_OVERFLOW: u16 = 3;
/// Diag value 4: "A 32-bit overflow occurred during the division due to rounding."
pub const SL_DIAG_SCALE_DIV_OVERFLOW: u16 = 4;

/// Diag message "The output AnalogOut has an underflow" (parameter 2: AnalogIn).
pub const SL_TEXT_SCALE_UNDERFLOW: u16 = 0x40B0;
/// Diag message "The output AnalogOut has an overflow" (parameter 2: AnalogIn).
pub const SL_TEXT_SCALE_OVERFLOW: u16 = 0x40B1;
/// Diag message "A 32-bit overflow occurred during the multiplication." (parameter 2: AnalogIn).
pub const SL_TEXT_SCALE_MUL_OVERFLOW: u16 = 0x40B2;
/// Diag message "A 32-bit overflow occurred during the division due to rounding."
/// (parameter 2: AnalogIn).
pub const SL_TEXT_SCALE_DIV_OVERFLOW: u16 = 0x40B3;

/// `wInputActive` bit of AnalogIn (required, the only bit).
pub const SL_SCALE_ACTIVE_ANALOGIN: u16 = 1 << 8;
/// `wInputNegated` bit of AnalogIn: INT/DINT ×(−1), UINT/UDINT XOR all ones.
pub const SL_SCALE_NEGATE_ANALOGIN: u16 = 1 << 8;

crate::base::layout::private_struct! {
    /// Private state of FB SCALE (72 bytes). Never written by the user. The header's `tPhase`
    /// is the start of the StuckAt watchdog, `wAux` bit 0 its expiry.
    SL_SCALE_PRIVATE {
        /// Latched `tWatchdog`.
        pub tWatchdog: u32,
        /// Latched `nNumerator`, `nDenominator`, `nOffset` as 32-bit patterns.
        pub adwFactor: [u32; 3],
        /// Latched `dwOptions`.
        pub dwOptions: u32,
        /// Latched `nRounding`.
        pub wRounding: u16,
        /// Latched `wInputActive`.
        pub wActive: u16,
        /// Latched `wInputNegated`.
        pub wNegated: u16,
        /// Reserved.
        pub aReserved0: [u8; 2],
        /// The result of the last RUN cycle as a 32-bit pattern.
        pub dwOut: u32,
        /// AnalogIn of the previous RUN cycle (the watchdog restarts when it changes).
        pub dwLastIn: u32,
        /// Diag message parameter 2 (AnalogIn) latched at the ERROR entry.
        pub dwPar: u32,
        /// Reserved.
        pub aReserved1: [u8; 4],
    }
}

crate::base::layout::block_struct! {
    /// FB SCALE instance (ABI-2 §11.6), generic over the signal type `T` and the type `T32` of
    /// the scaling parameters (ABI-2 §10.3); `P1` (after AnalogIn) and `P2` (after AnalogOut)
    /// are the reserved gaps that make the 16- and 32-bit layouts differ.
    FB_SCALE[T: Analog, T32: Analog; P1, P2] {
        no_bool_inputs;
        /// Offset 24. AnalogIn, the value scaled (active bit 8, required).
        pub nAnalogIn: T,
        /// Reserved up to 28 (16-bit: 2 bytes, 32-bit: none).
        pub aReserved2: [u8; P1],
        /// Offset 28. "watchdog (ms)": StuckAtError after this time without a change of
        /// AnalogIn; 0 = off, at most SL_TIME_PARAM_MAX.
        pub tWatchdog: u32,
        /// Offset 32. "Nominator": the multiplication factor.
        pub nNumerator: T32,
        /// Offset 36. "Denominator": the division factor, not 0.
        pub nDenominator: T32,
        /// Offset 40. The scaling offset, added last.
        pub nOffset: T32,
        /// Offset 44. SL_OPT_SCALE_DIVISION_FIRST, no other bit.
        pub dwOptions: u32,
        /// Offset 48. "Division Rounding": SL_ROUNDING_FLOOR, _CEIL, _ROUND.
        pub nRounding: u16,
        /// Offset 50. Bit 8 (AnalogIn) must be set, no other.
        pub wInputActive: u16,
        /// Offset 52. Bit 8: AnalogIn negated; no other.
        pub wInputNegated: u16,
        /// Offset 54. Reserved.
        pub aReserved3: [u8; 2],
        /// Offset 56, the output base. Error, TRUE in ERROR only.
        pub bError: SL_BOOL,
        /// Offset 57. StuckAtError: in RUN, AnalogIn unchanged for `tWatchdog` (no FB error).
        pub bStuckAtError: SL_BOOL,
        /// Offset 58. Reserved.
        pub aReserved4: [u8; 6],
        /// Offset 64. AnalogOut, the scaled value in RUN, else 0.
        pub nAnalogOut: T,
        /// Reserved up to the info data (16-bit: 6 bytes, 32-bit: 4).
        pub aReserved5: [u8; P2],
    } info [aReserved6, aReserved7] SL_SCALE_PRIVATE, "72 bytes":
        "The manual's status value (RUN, STOP, ERROR, RESET).",
        "Diag value (1 underflow, 2 overflow, 3 multiplication, 4 division) + library bits 13-15.",
        "Text ID of the latched diag message (0x40B0–0x40B3), 0 = none.",
        "Message parameter 2 (AnalogIn as a 32-bit pattern).",
        "Message parameter 3 (always 0: \"-\" in the manual)."
}

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

crate::base::block::block_states!(
    /// The states of FB SCALE, every variant (manual §4.23.2): no SAFE.
    ScaleState: Run, Stop, Error, Reset
);

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
