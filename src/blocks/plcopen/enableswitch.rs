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

/// Block type tag of SF_EnableSwitch (`SL_MEMBER.nType`, `sl_diag_text`).
pub const SL_TYPE_SF_ENABLESWITCH: u16 = 523;

crate::sf_states!(
    /// The states of SF_EnableSwitch: values = v2.01 DiagCodes (CS-LIB FBS_ENSWITCH), with
    /// the v1.0 codes (research §4.9). Note v1.0 8004 is BASIC_OPMODE, v2.01 8004 SAFE_OPMODE
    /// (semantics QN4).
    EnableSwitchState, init: BasicOpMode {
        Idle = 0x0000, 0x0000, "IDLE", "FB not activated";
        BasicOpMode = 0x8002, 0x8004, "BASIC_OPMODE", "safe operation mode not active (S_SafetyActive FALSE)";
        SafeOpMode = 0x8004, 0x8005, "SAFE_OPMODE", "safe operation mode active, checking the switch is in position 1 (v1.0 code 8005; v1.0 8004 is BASIC_OPMODE)";
        Position1 = 0x8802, 0x8006, "POSITION_1", "safe operation mode active, enable switch in position 1";
        Position3 = 0x8804, 0x8007, "POSITION_3", "safe operation mode active, enable switch in position 3";
        Position2 = 0x8000, 0x8000, "POSITION_2", "enable switch in position 2 after position 1, output TRUE";
        ErrOperation1 = 0xC010, 0xC010, "ERR_OPERATION_1", "enable switch not in position 1 when S_SafetyActive became TRUE";
        ErrOperation2 = 0xC020, 0xC020, "ERR_OPERATION_2", "enable switch in position 1 after ERR_OPERATION_1, waiting for Reset (or S_AutoReset)";
        ErrOperation3 = 0xC030, 0xC030, "ERR_OPERATION_3", "enable switch in position 2 after position 3";
        ErrOperation4 = 0xC040, 0xC040, "ERR_OPERATION_4", "enable switch not in position 2 after ERR_OPERATION_3, waiting for Reset (or S_AutoReset)";
        ErrReset1 = 0xC001, 0xC001, "ERR_RESET_1", "static Reset in ERR_OPERATION_2";
        ErrReset2 = 0xC011, 0xC002, "ERR_RESET_2", "static Reset in ERR_OPERATION_4";
    }
);

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

crate::base::layout::block_struct! {
    /// SF_EnableSwitch instance: the PLCopen VAR_INPUT / VAR_OUTPUT names, BOOL = one byte.
    /// Size: 56 bytes.
    SF_EnableSwitch {
        /// Offset 0. Activate: FALSE = idle (DiagCode 0000, every output FALSE), highest priority.
        pub Activate: SL_BOOL,
        /// Offset 1. S_SafetyActive: the safe operation mode (reduced speed …) is active; FALSE = basic mode, output FALSE.
        pub S_SafetyActive: SL_BOOL,
        /// Offset 2. S_EnableSwitchCh1: contacts E1 and E2 of the enable switch (TRUE in position 2 only).
        pub S_EnableSwitchCh1: SL_BOOL,
        /// Offset 3. S_EnableSwitchCh2: contacts E3 and E4 of the enable switch (TRUE in positions 1 and 2).
        pub S_EnableSwitchCh2: SL_BOOL,
        /// Offset 4. S_AutoReset: TRUE = the operation errors are left without Reset once the switch is back.
        pub S_AutoReset: SL_BOOL,
        /// Offset 5. Reset: a rising edge resets an operation error; held TRUE there it is a static-reset error.
        pub Reset: SL_BOOL,
        /// Offset 6. Reserved, keep 0.
        pub aReserved0: [u8; 1],
        /// Offset 7. Library extension, constant: DiagCode profile, 0 = v2.01 (default), 1 = v1.0; latched at activation.
        pub nDiagProfile: u8,
        /// Offset 8 (output base). Ready: TRUE while activated (DiagCode != 0000).
        pub Ready: SL_BOOL,
        /// Offset 9. S_EnableSwitchOut: the safety output (suspension of the guard), TRUE only at DiagCode 8000.
        pub S_EnableSwitchOut: SL_BOOL,
        /// Offset 10. SafetyDemand: the safety function is demanded (v2.01 code bit 0x0800).
        pub SafetyDemand: SL_BOOL,
        /// Offset 11. ResetRequest: a reset is awaited (v2.01 code bit 0x0400, which no state of this block has) and Reset is FALSE.
        pub ResetRequest: SL_BOOL,
        /// Offset 12. Error: DiagCode >= C000.
        pub Error: SL_BOOL,
        /// Offset 13. Reserved.
        pub aReserved1: [u8; 1],
        /// Offset 14. DiagCode: the state or error, in the profile of nDiagProfile.
        pub DiagCode: u16,
    } private 16: SL_SF_PRIVATE, 40
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
