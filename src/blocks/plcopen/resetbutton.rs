//! SF_ResetButton — PLCopen TC5 Part 1 v2.x (research `plcopen_safety.md` §4.19, §5): the
//! trailing-edge reset of ISO 13849-1:2015 §5.2.2. A press of `ResetIn` lasting at least
//! TrailingMinimum and less than TrailingMaximum gives a one-call pulse at `ResetOut` after
//! its falling edge, for any rising-edge `Reset` input. PLCopen v2.x only: the v1.0 profile
//! is refused (SL_E_CONFIG). `ResetRequested` activates the block (it has no `Activate`);
//! the envelope's R_TRIG of `Reset` runs on `ResetIn` (docs/semantics.md QB1–QB6).

use crate::base::reason::{when, Rule, RuleDef, Unit};
use crate::base::sf::{ResetIn, SL_SF_PRIVATE};
use crate::base::time;
use crate::base::types::SL_BOOL;

include!(concat!(
    env!("OUT_DIR"),
    "/abi/blocks/plcopen/resetbutton.rs"
));

/// The transition table of research §4.19 (v2.01 codes), first matching guard wins.
/// `r` is the R_TRIG of ResetIn; the press runs from the entry into 83F2 (`in_state`, ms);
/// `t` = [TrailingMinimum, TrailingMaximum]. IDLE → 83E2 / C000 is the envelope's
/// (`SfBlock::first`).
fn next(s: ResetButtonState, r: ResetIn, in_state: u32, t: [u32; 2]) -> ResetButtonState {
    use ResetButtonState::*;
    match s {
        WaitRTrig if r.held() => ErrReset,
        WaitRTrig if r.rising => WaitFTrig,
        WaitFTrig if time::reached(in_state, 0, t[1]) => ErrTrailMax,
        WaitFTrig if !r.level && !time::reached(in_state, 0, t[0]) => ErrTrailMin,
        WaitFTrig if !r.level => ResetDetected,
        ResetDetected if r.rising => WaitFTrig,
        ResetDetected => WaitRTrig,
        ErrReset if !r.level => WaitRTrig,
        ErrTrailMax | ErrTrailMin if r.rising => WaitFTrig,
        Idle | WaitRTrig | WaitFTrig | ErrParam | ErrReset | ErrTrailMax | ErrTrailMin => s,
    }
}

crate::impl_sf_member!(SF_ResetButton {
    tag: SL_TYPE_SF_RESETBUTTON,
    input: [ResetRequested, ResetIn],
    param: [nDiagProfile, TrailingMinimum, TrailingMaximum],
    output: [Ready, ResetOut, Error],
    activate: ResetRequested,
});

crate::impl_sf_block!(SF_ResetButton {
    tag: SL_TYPE_SF_RESETBUTTON,
    diag: ResetButtonState,
    input: (),
    reset: ResetIn,
    // ResetIn runs through the envelope's R_TRIG, evaluated in every call.
    consts(s): [s.TrailingMinimum, s.TrailingMaximum],
    rules: [
        crate::base::sf::time0_rule("TrailingMinimum"),
        crate::base::sf::time1_rule("TrailingMaximum"),
    ],
    next: |s, _inp, reset, in_state, times| next(s, reset, in_state, times),
} {
    const HAS_V10: bool = false;
    /// The trailing times are usable (C000 otherwise).
    const PARAM_RULES: &'static [RuleDef<crate::base::sf::SfConsts>] = &[
        RuleDef::new("TrailingMinimum", Rule::AtLeast, Unit::Ms, |c| {
            let min = SF_RESETBUTTON_MIN_TRAILING;
            when(c.times[0] < min, c.times[0], min)
        }),
        RuleDef::new(
            "TrailingMinimum",
            Rule::NotAbove("TrailingMaximum"),
            Unit::Ms,
            |c| when(c.times[0] > c.times[1], c.times[0], c.times[1]),
        ),
    ];
    #[inline(always)]
    fn decode(&self) -> (Self::In, bool) {
        ((), false)
    }
    fn first(times: [u32; 2]) -> Self::Diag {
        crate::base::sf::first_checked::<Self>(
            times,
            ResetButtonState::WaitRTrig,
            ResetButtonState::ErrParam,
        )
    }
    #[inline(always)]
    fn write_outputs(&mut self, o: &crate::base::sf::SfOut) {
        crate::sf_outputs!(self, o, ResetOut);
    }
});

impl SF_ResetButton {
    /// An instance with PLCopen's initial values (`sl_sf_resetbutton_defaults`):
    /// ResetRequested TRUE, TrailingMinimum T#350ms, TrailingMaximum T#2s, everything else
    /// zero. The all-zero struct stays "not configured" (TrailingMinimum 0 is the block's
    /// parameter error, semantics PO12): the defaults are written on purpose, visibly.
    pub const fn plcopen_defaults() -> Self {
        Self {
            ResetRequested: 1,
            TrailingMinimum: SF_RESETBUTTON_DEFAULT_TRAILING_MIN,
            TrailingMaximum: SF_RESETBUTTON_DEFAULT_TRAILING_MAX,
            ..Self::zeroed()
        }
    }
}

// The steady-state fast path (`base::sf::SfSteady`): the key is every BOOL byte the call
// reads; the wait for the falling edge reads the trailing times.
crate::sf_steady!(SF_ResetButton: [ResetRequested, ResetIn], timed: ResetButtonState::{WaitFTrig});
