//! SF_EnableSwitch — PLCopen TC5 Part 1 (research `plcopen_safety.md` §4.9, DiagCodes §5): a
//! three-position enabling switch suspends the safeguarding while a safe operation mode
//! (reduced speed …) is active. Only the switch-over position 1 → position 2 enables; 3 → 2
//! is an error. Exists in v1.0 and v2.x (not SF_EnableSwitch_2).
//!
//! The positions from the two contact pairs (research §4.9, an inference there; semantics QN2): position 1
//! (released) = Ch1 FALSE, Ch2 TRUE; position 2 (enable) = both TRUE; position 3 (panic) =
//! both FALSE; Ch1 TRUE with Ch2 FALSE and an invalid byte on either channel read as
//! position 3.

use crate::base::bools;
use crate::base::sf::{ResetIn, SfOut, SL_SF_PRIVATE};
use crate::base::types::SL_BOOL;

include!(concat!(
    env!("OUT_DIR"),
    "/abi/blocks/plcopen/enableswitch.rs"
));

/// A switch position.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Position {
    /// Position 1: released (Ch1 FALSE, Ch2 TRUE).
    P1,
    /// Position 2: enable (Ch1 TRUE, Ch2 TRUE).
    P2,
    /// Position 3 (both FALSE, panic), or the invalid combination Ch1 TRUE / Ch2 FALSE, or
    /// an invalid channel byte.
    #[default]
    P3,
}

/// One call's inputs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct EnableSwitchIn {
    /// S_SafetyActive: the safe operation mode is active.
    pub safety_active: bool,
    /// The switch position from S_EnableSwitchCh1 / S_EnableSwitchCh2.
    pub position: Position,
    /// S_AutoReset: errors ERR_OPERATION_2 / _4 are left without Reset.
    pub auto_reset: bool,
}

/// Research §4.9's table (v2.01 codes), first matching guard wins; `NOT S_SafetyActive` comes
/// first in every state, the errors included (semantics QN1). IDLE → BASIC_OPMODE is the
/// envelope's (Activate).
pub fn enable_switch_next(
    s: EnableSwitchState,
    i: &EnableSwitchIn,
    r: ResetIn,
) -> EnableSwitchState {
    use EnableSwitchState::*;
    use Position::*;
    let p = i.position;
    match s {
        Idle => Idle,
        _ if !i.safety_active => BasicOpMode,
        BasicOpMode => SafeOpMode,
        SafeOpMode if p != P1 => ErrOperation1,
        SafeOpMode => Position1,
        Position1 if p == P2 => Position2,
        Position1 if p == P3 => Position3,
        Position2 if p == P3 => Position3,
        Position2 if p == P1 => Position1,
        Position3 if p == P2 => ErrOperation3,
        Position3 if p == P1 => Position1,
        ErrOperation1 if p == P1 => ErrOperation2,
        ErrOperation2 if p != P1 => ErrOperation1,
        ErrOperation2 if r.held() && !i.auto_reset => ErrReset1,
        ErrOperation2 if r.rising || i.auto_reset => Position1,
        ErrReset1 if !r.level => ErrOperation2,
        ErrOperation3 if p != P2 => ErrOperation4,
        ErrOperation4 if p == P2 => ErrOperation3,
        ErrOperation4 if r.held() && !i.auto_reset => ErrReset2,
        ErrOperation4 if r.rising || i.auto_reset => Position3,
        ErrReset2 if !r.level => ErrOperation4,
        Position1 | Position2 | Position3 | ErrOperation1 | ErrOperation2 | ErrOperation3
        | ErrOperation4 | ErrReset1 | ErrReset2 => s,
    }
}

crate::impl_sf_member!(SF_EnableSwitch {
    tag: SL_TYPE_SF_ENABLESWITCH,
    input: [
        Activate,
        S_SafetyActive,
        S_EnableSwitchCh1,
        S_EnableSwitchCh2,
        S_AutoReset,
        Reset
    ],
    param: [nDiagProfile],
    output: [Ready, S_EnableSwitchOut, SafetyDemand, ResetRequest, Error],
});

crate::impl_sf_block!(SF_EnableSwitch {
    tag: SL_TYPE_SF_ENABLESWITCH,
    diag: EnableSwitchState,
    input: EnableSwitchIn,
    reset: Reset,
    consts(s): [],
    next: |s, inp, reset, _in_state, _t| enable_switch_next(s, inp, reset),
} {
    #[inline(always)]
    fn decode(&self) -> (Self::In, bool) {
        let p = bools::pack([
            self.S_SafetyActive,
            self.S_EnableSwitchCh1,
            self.S_EnableSwitchCh2,
            self.S_AutoReset,
        ]);
        let v = bools::logical(p, 0b1111, 0);
        // An invalid channel byte: the position is unknown, read as position 3 (QN2).
        let position = match (v >> 1 & 0b11, p.invalid & 0b110 != 0) {
            (_, true) => Position::P3,
            (0b10, false) => Position::P1,
            (0b11, false) => Position::P2,
            _ => Position::P3,
        };
        (
            EnableSwitchIn {
                safety_active: v & 1 != 0,
                position,
                auto_reset: v & 0b1000 != 0,
            },
            p.invalid != 0,
        )
    }
    #[inline(always)]
    fn write_outputs(&mut self, o: &SfOut) {
        crate::sf_outputs!(self, o, S_EnableSwitchOut, SafetyDemand, ResetRequest);
    }
});

/// The private state's size is part of the struct's layout (56 bytes, no implicit padding).
const _: () = assert!(core::mem::size_of::<SF_EnableSwitch>() == 56);

// The steady-state fast path (`base::sf::SfSteady`): the key is the six BOOL inputs; no
// state reads the time.
crate::sf_steady!(
    SF_EnableSwitch: [Activate, S_SafetyActive, S_EnableSwitchCh1,
        S_EnableSwitchCh2, S_AutoReset, Reset]
);
