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

/// Block type tag of SF_ResetButton (`SL_MEMBER.nType`, `sl_diag_text`).
pub const SL_TYPE_SF_RESETBUTTON: u16 = 520;

/// The least TrailingMinimum (ms): "absolute minimum 100 ms" (research §4.19, NPE).
pub const SF_RESETBUTTON_MIN_TRAILING: u32 = 100;
/// PLCopen's initial value of TrailingMinimum (ms): T#350ms.
pub const SF_RESETBUTTON_DEFAULT_TRAILING_MIN: u32 = 350;
/// PLCopen's initial value of TrailingMaximum (ms): T#2s.
pub const SF_RESETBUTTON_DEFAULT_TRAILING_MAX: u32 = 2_000;

crate::sf_states!(
    /// The states of SF_ResetButton: values = v2.01 DiagCodes (CS-LIB FBS_RESBUT). The block
    /// has no v1.0 codes (v2.x only); the v1.0 column repeats the v2.01 code and is never
    /// shown (the v1.0 profile is refused).
    ResetButtonState, init: WaitRTrig {
        Idle = 0x0000, 0x0000, "IDLE", "FB not activated (ResetRequested FALSE)";
        WaitRTrig = 0x83E2, 0x83E2, "WAIT_R_TRIG", "enabled; waiting for a rising edge of ResetIn";
        WaitFTrig = 0x83F2, 0x83F2, "WAIT_F_TRIG", "ResetIn TRUE; waiting for its falling edge";
        ResetDetected = 0x8000, 0x8000, "RESET_DETECTED", "valid reset: ResetOut TRUE for one call";
        ErrParam = 0xC000, 0xC000, "ERR_PARAM", "TrailingMinimum > TrailingMaximum or TrailingMinimum < 100 ms";
        ErrReset = 0xC001, 0xC001, "ERR_RESET", "static ResetIn: TRUE without a rising edge; waiting for ResetIn FALSE";
        ErrTrailMax = 0xC3E0, 0xC3E0, "ERR_TRAIL_MAX", "TrailingMaximum elapsed before the falling edge of ResetIn; waiting for a rising edge";
        ErrTrailMin = 0xC3F0, 0xC3F0, "ERR_TRAIL_MIN", "falling edge of ResetIn before TrailingMinimum elapsed; waiting for a rising edge";
    }
);

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

crate::base::layout::block_struct! {
    /// SF_ResetButton instance: the PLCopen VAR_INPUT / VAR_OUTPUT names, BOOL = one byte.
    /// Size: 64 bytes.
    SF_ResetButton {
        /// Offset 0. ResetRequested: the activation of this block (it has no Activate); connect the paired FB's ResetRequest. FALSE = idle (DiagCode 0000, ResetOut FALSE), highest priority. PLCopen initial value TRUE.
        pub ResetRequested: SL_BOOL,
        /// Offset 1. ResetIn: the reset button, TRUE = pressed.
        pub ResetIn: SL_BOOL,
        /// Offset 2. Reserved, keep 0.
        pub aReserved0: [u8; 1],
        /// Offset 3. Library extension, constant: DiagCode profile, only 0 = v2.01 (1 is refused: v2.x block); latched at activation.
        pub nDiagProfile: u8,
        /// Offset 4. TrailingMinimum (constant, ms; PLCopen default T#350ms): shortest valid press, at least 100 ms; latched at activation.
        pub TrailingMinimum: u32,
        /// Offset 8. TrailingMaximum (constant, ms; PLCopen default T#2s): a press this long is invalid; latched at activation.
        pub TrailingMaximum: u32,
        /// Offset 12 (output base). Ready: TRUE while activated (DiagCode != 0000).
        pub Ready: SL_BOOL,
        /// Offset 13. ResetOut: TRUE for one call after the falling edge of a valid press (DiagCode 8000).
        pub ResetOut: SL_BOOL,
        /// Offset 14. Error: DiagCode >= C000.
        pub Error: SL_BOOL,
        /// Offset 15. Reserved.
        pub aReserved1: [u8; 1],
        /// Offset 16. DiagCode: the state or error (v2.01).
        pub DiagCode: u16,
        /// Offset 18. Reserved.
        pub aReserved2: [u8; 6],
    } private 24: SL_SF_PRIVATE, 40
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
