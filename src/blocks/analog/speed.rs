//! FB SPEED — manual §4.24; layout ABI-2 §11.7, rules ABI-2 §12.
//!
//! Latches Position and the time when it starts (STOP → run, RESET → RUN; Speed 0); at the
//! first call at least `tTimeInterval` ms after the latch, Speed = Position − latched
//! Position ("increments per time interval", not rescaled to the elapsed time) and the latch
//! moves to this call. The difference is exact; with `SL_OPT_SPEED_OVERFLOW_CHECK` it is
//! first reduced modulo 2^W (a wrapped position counter counts the short way round). Outside
//! the variant's type: ERROR, diag value 1 / 2, message 0x4088 / 0x4089 (parameters 2 and
//! 3: current position, latched position), an event that nothing keeps. Speed is 0 in STOP,
//! ERROR and RESET. Timing by the wrapping millisecond clock (`base::time`). States RUN (1),
//! STOP (2), ERROR (4), RESET (5): no SAFE. Readings: docs/semantics.md SP1–SP4. One
//! implementation for the four integer types.

#![allow(non_camel_case_types)] // the ABI's names (FB_SPEED_INT …)

use super::{in_range, magic, range_message, value_if, Analog};
use crate::base::block::{Private, Registered};
use crate::base::envelope::{params_map, Block};
use crate::base::header::{crc_words, param_crc};
use crate::base::reason::rule;
use crate::base::reason::RuleDef;
use crate::base::time;
use crate::base::types::*;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/analog/speed.rs"));

// The ABI-2 §11.7 numbers (identical for both widths).
const _: () = {
    use core::mem::{offset_of, size_of};
    assert!(offset_of!(FB_SPEED_INT, tTimeInterval) == 28);
    assert!(offset_of!(FB_SPEED_DINT, dwOptions) == 32);
    assert!(offset_of!(FB_SPEED_UINT, wInputActive) == 36);
    assert!(offset_of!(FB_SPEED_UDINT, bError) == 40 && offset_of!(FB_SPEED_UDINT, nSpeed) == 48);
    assert!(
        offset_of!(FB_SPEED_INT, stPrivate) == 72 && offset_of!(FB_SPEED_DINT, stPrivate) == 72
    );
    assert!(size_of::<SL_SPEED_PRIVATE>() == 56);
};

/// Diag value texts (manual §4.24.2).
const DIAG_VALUES: &[(u16, &str)] =
    super::range_diag_values!("Speed", "No diagnostic information", "");

crate::impl_member!([T: Analog, const P1: usize, const P2: usize] FB_SPEED<T, P1, P2> {
    info: crate::blocks::analog::variant_info!(T, "SPEED", SpeedState, DIAG_VALUES;
        INT = SL_TYPE_SPEED_INT, UINT = SL_TYPE_SPEED_UINT, DINT = SL_TYPE_SPEED_DINT, UDINT = SL_TYPE_SPEED_UDINT),
    state: SpeedState,
    private: SL_SPEED_PRIVATE,
    input: [nPosition],
    param: [tTimeInterval, dwOptions, wInputActive],
    output: [bError, nSpeed],
    info_fields: [nDiagTextId, dwDiagPar2, dwDiagPar3],
});

/// Parameters as the user wrote them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SpeedParams {
    interval: u32,
    options: u32,
    active: u16,
}

/// The position difference `d` as a speed of type `T`: with the overflow check reduced
/// modulo 2^W into [−2^(W−1), 2^(W−1)) first; then range-checked (ABI-2 §11.7, §12.1).
fn speed<T: Analog>(d: i128, overflow_check: bool) -> Result<T, u16> {
    if overflow_check {
        let modulus = T::MAX - T::MIN + 1;
        let half = modulus / 2;
        in_range::<T>((d + half).rem_euclid(modulus) - half)
    } else {
        in_range::<T>(d)
    }
}

impl<T: Analog, const P1: usize, const P2: usize> Block for FB_SPEED<T, P1, P2> {
    const MAGIC: u16 = magic(<Self as Registered>::INFO.tag);
    params_map!(SpeedParams {
        interval: tTimeInterval => tInterval,
        options: dwOptions => dwOptions,
        active: wInputActive => wActive,
    });
    type In = T;

    /// Position active and nothing else, the one option, Time Interval 1 … 65,535 ms
    /// (ABI-2 §11.7 "≥ 1", §12.9).
    const RULES: &'static [RuleDef<SpeedParams>] = &[
        rule!(equals "wInputActive", |p| p.active, SL_SPEED_ACTIVE_POSITION),
        rule!(no_bits_outside "dwOptions", |p| p.options, SL_OPT_SPEED_OVERFLOW_CHECK),
        rule!(not_zero "tTimeInterval" in Ms, |p| p.interval),
        rule!(at_most "tTimeInterval" in Ms, |p| p.interval, SL_TIME_PARAM_MAX),
    ];
    fn latched_crc(&self) -> u16 {
        let p = self.private();
        param_crc(
            Self::MAGIC,
            0,
            0,
            0,
            &crc_words![u32 p.tInterval, u32 p.dwOptions, u16 p.wActive],
        )
    }
    #[inline(always)]
    fn decode(&mut self) -> (T, bool) {
        (self.nPosition, false)
    }
    /// Latch Position and the time; Speed 0 until the first interval ends (semantics SP1).
    fn start(&mut self, position: &T, now: u32) {
        // Entering RUN is where the output starts to carry values: verify the latched
        // parameters first (C3).
        if self.corrupt_at_switch_on(true) {
            return;
        }
        let p = self.private_mut();
        p.dwLatch = position.to_bits();
        p.dwSpeed = 0;
        p.stHeader.tPhase = now;
        p.stHeader.nState = SL_STATE_RUN;
    }
    #[inline(always)]
    fn step(&mut self, position: &T, now: u32) -> Status {
        let p = self.private_mut();
        if !time::reached(now, p.stHeader.tPhase, p.tInterval) {
            return Status::Ok;
        }
        let d = position.wide() - T::from_bits(p.dwLatch).wide();
        match speed::<T>(d, p.dwOptions & SL_OPT_SPEED_OVERFLOW_CHECK != 0) {
            Ok(v) => {
                p.dwSpeed = v.to_bits();
                p.dwLatch = position.to_bits();
                p.stHeader.tPhase = now;
            }
            Err(diag) => {
                p.adwPar = [position.to_bits(), p.dwLatch];
                p.dwSpeed = 0;
                p.stHeader.enter_error(diag);
            }
        }
        Status::Ok
    }
    // A range error is an event: nothing remains after it (ABI-2 §11.7, §12.5).
    // `error_remains` keeps its default (false).
    #[inline(always)]
    fn write_outputs(&mut self) {
        let p = *self.private();
        let h = p.stHeader;
        let run = h.nState == SL_STATE_RUN;
        self.bError = u8::from(h.nState == SL_STATE_ERROR);
        self.nSpeed = value_if::<T>(run, p.dwSpeed);
        self.nState = h.nState;
        self.nDiag = h.wDiag;
        (self.nDiagTextId, self.dwDiagPar2, self.dwDiagPar3) = range_message(
            &h,
            [SL_TEXT_SPEED_UNDERFLOW, SL_TEXT_SPEED_OVERFLOW],
            p.adwPar,
        );
    }
}
