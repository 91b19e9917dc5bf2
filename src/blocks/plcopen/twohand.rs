//! The two-hand machine of SF_TwoHandControlTypeII and SF_TwoHandControlTypeIII (PLCopen
//! TC5 Part 1; research `plcopen_safety.md` §4.6, §4.7, §5; EN 574 / ISO 13851): two
//! buttons → one output, TRUE when both are actuated in the correct order; both must be
//! released before it can be set again; no Reset (an error is left by releasing both).
//! Type III is type II plus the synchronous actuation: the second button within 500 ms of
//! the first ("FUNCTION_BLOCK SF_TwoHandControlTypeIII EXTENDS SF_TwoHandControlTypeII",
//! CS-LIB). The v2.01 error codes were not retrieved (research §8.1): ours are C010/C020/C030
//! and C040/C050/C060 (semantics QH1). Each block's file declares its struct and calls
//! `two_hand_block!`.

use crate::base::sf::DiagState;

include!(concat!(env!("OUT_DIR"), "/abi/blocks/plcopen/twohand.rs"));

/// Declares a two-hand state enum: the states of type II, then `$extra` (type III's
/// synchronism errors).
macro_rules! two_hand_states {
    ($(#[$meta:meta])* $enum:ident { $($extra:tt)* }) => {
        crate::sf_states!(
            $(#[$meta])*
            $enum, init: Init {
                Idle = 0x0000, 0x0000, "IDLE", "FB not activated";
                Init = 0x8001, 0x8001, "INIT", "activated; checks that no button is actuated";
                ButtonsActuated = 0x8000, 0x8000, "BUTTONS_ACTUATED", "both buttons actuated in the correct order, output TRUE";
                ButtonsReleased = 0x8802, 0x8004, "BUTTONS_RELEASED", "no button actuated";
                Button1Actuated = 0x8804, 0x8005, "BUTTON_1_ACTUATED", "only S_Button1 actuated (type III: synchronism time running)";
                Button2Actuated = 0x8806, 0x8006, "BUTTON_2_ACTUATED", "only S_Button2 actuated (type III: synchronism time running)";
                Button2Released = 0x8808, 0x8007, "BUTTON_2_RELEASED", "S_Button2 released after the output was enabled; waiting for both buttons released";
                Button1Released = 0x880A, 0x8008, "BUTTON_1_RELEASED", "S_Button1 released after the output was enabled; waiting for both buttons released";
                LockedOff = 0x880C, 0x8009, "LOCKED_OFF", "both buttons actuated again without both released before; waiting for both buttons released";
                LockedOn = 0x880E, 0x8019, "LOCKED_ON", "incorrect actuation (a button released before the other was actuated); waiting for both buttons released";
                ErrButton1 = 0xC010, 0xC001, "ERR_BUTTON_1", "S_Button1 TRUE at activation; waiting for both buttons released";
                ErrButton2 = 0xC020, 0xC002, "ERR_BUTTON_2", "S_Button2 TRUE at activation; waiting for both buttons released";
                ErrButtons = 0xC030, 0xC003, "ERR_BUTTONS", "S_Button1 and S_Button2 TRUE at activation; waiting for both buttons released";
                $($extra)*
            }
        );
    };
}

two_hand_states!(
    /// The states of SF_TwoHandControlTypeII: values = v2.01 DiagCodes (CS-LIB FBS_TWOHAND;
    /// the error codes ours, semantics QH1), with the v1.0 codes (research §4.6).
    TwoHandIIState {}
);

two_hand_states!(
    /// The states of SF_TwoHandControlTypeIII: type II's and the synchronism errors (v1.0
    /// C004–C006 from PEER-ST, research §4.7; the v2.01 codes ours, semantics QH1, QH3).
    TwoHandIIIState {
        ErrSync1 = 0xC040, 0xC004, "ERR_SYNC_BUTTON_1", "synchronism time (500 ms) elapsed with only S_Button2 actuated (S_Button1 late); waiting for both buttons released";
        ErrSync2 = 0xC050, 0xC005, "ERR_SYNC_BUTTON_2", "synchronism time (500 ms) elapsed with only S_Button1 actuated (S_Button2 late); waiting for both buttons released";
        ErrSyncBoth = 0xC060, 0xC006, "ERR_SYNC_BUTTONS", "synchronism time (500 ms) elapsed, both buttons actuated too late; waiting for both buttons released";
    }
);

/// One call's buttons (an invalid byte reads FALSE: not actuated).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TwoHandIn {
    /// S_Button1 actuated.
    pub b1: bool,
    /// S_Button2 actuated.
    pub b2: bool,
}

/// Research §4.6's table with §4.7's synchronism guards (v2.01 codes), first matching guard
/// wins: in 8804 / 8806 an elapsed synchronism time (`sync_elapsed`, type III only) comes
/// before every other guard. IDLE → INIT is the envelope's (Activate).
pub fn next(s: TwoHandIIIState, i: &TwoHandIn, sync_elapsed: bool) -> TwoHandIIIState {
    use TwoHandIIIState::*;
    let (b1, b2) = (i.b1, i.b2);
    let none = !b1 && !b2;
    let both = b1 && b2;
    let waiting = matches!(s, Button1Actuated | Button2Actuated) && sync_elapsed;
    match s {
        Init if both => ErrButtons,
        Init if b1 => ErrButton1,
        Init if b2 => ErrButton2,
        Init => ButtonsReleased,
        ButtonsReleased if both => ButtonsActuated,
        ButtonsReleased if b1 => Button1Actuated,
        ButtonsReleased if b2 => Button2Actuated,
        Button1Actuated | Button2Actuated if waiting && both => ErrSyncBoth,
        Button1Actuated | Button2Actuated if waiting && b1 => ErrSync2,
        Button1Actuated | Button2Actuated if waiting && b2 => ErrSync1,
        Button1Actuated | Button2Actuated if none => ButtonsReleased,
        Button1Actuated if b2 && !b1 => LockedOn,
        Button2Actuated if b1 && !b2 => LockedOn,
        Button1Actuated | Button2Actuated if both => ButtonsActuated,
        ButtonsActuated if b1 && !b2 => Button2Released,
        ButtonsActuated if b2 && !b1 => Button1Released,
        ButtonsActuated if none => ButtonsReleased,
        Button2Released if both => LockedOff,
        Button2Released if b2 => Button1Released,
        Button1Released if both => LockedOff,
        Button1Released if b1 => Button2Released,
        LockedOff if b2 && !b1 => Button1Released,
        LockedOff if b1 && !b2 => Button2Released,
        Button2Released | Button1Released | LockedOff | LockedOn if none => ButtonsReleased,
        ErrButton1 | ErrButton2 | ErrButtons | ErrSync1 | ErrSync2 | ErrSyncBoth if none => {
            ButtonsReleased
        }
        Idle | ButtonsReleased | Button1Actuated | Button2Actuated | ButtonsActuated
        | Button2Released | Button1Released | LockedOff | LockedOn | ErrButton1 | ErrButton2
        | ErrButtons | ErrSync1 | ErrSync2 | ErrSyncBoth => s,
    }
}

/// Type III: the synchronism time has elapsed `SYNC_TIME_MS` after the entry into 8804 /
/// 8806 ("within 500 ms" allows 500 ms exactly, semantics QH3).
pub fn next_iii(s: TwoHandIIIState, i: &TwoHandIn, in_state: u32) -> TwoHandIIIState {
    next(s, i, in_state > SYNC_TIME_MS)
}

/// Type II: type III's machine without the synchronism time, which never reaches type III's
/// own errors, so every state it returns is one of type II's.
pub fn next_ii(s: TwoHandIIState, i: &TwoHandIn, _in_state: u32) -> TwoHandIIState {
    let s3 = TwoHandIIIState::decode(s.code()).unwrap_or(TwoHandIIIState::Idle);
    TwoHandIIState::decode(next(s3, i, false).code()).unwrap_or(s)
}

/// The struct of SF_TwoHandControlTypeII and SF_TwoHandControlTypeIII, declared once: they
/// differ in the name only.
/// build.rs writes every invocation out for cbindgen (`build_support/expand.rs`).
#[macro_export]
#[doc(hidden)]
macro_rules! two_hand_struct {
    ($(#[doc = $doc:literal])* $name:ident) => {
        $crate::base::layout::block_struct! {
            $(#[doc = $doc])*
            $name {
                /// Offset 0. Activate: FALSE = idle (DiagCode 0000, every output FALSE), highest priority.
                pub Activate: SL_BOOL,
                /// Offset 1. S_Button1: button 1, TRUE = actuated (category 3 or 4: from two antivalent contacts).
                pub S_Button1: SL_BOOL,
                /// Offset 2. S_Button2: button 2, TRUE = actuated.
                pub S_Button2: SL_BOOL,
                /// Offset 3. Reserved, keep 0.
                pub aReserved0: [u8; 4],
                /// Offset 7. Library extension, constant: DiagCode profile, 0 = v2.01 (default), 1 = v1.0; latched at activation.
                pub nDiagProfile: u8,
                /// Offset 8 (output base). Ready: TRUE while activated (DiagCode != 0000).
                pub Ready: SL_BOOL,
                /// Offset 9. S_TwoHandOut: the safety output, TRUE only at DiagCode 8000.
                pub S_TwoHandOut: SL_BOOL,
                /// Offset 10. SafetyDemand: the safety function is demanded (v2.01 code bit 0x0800).
                pub SafetyDemand: SL_BOOL,
                /// Offset 11. Error: DiagCode >= C000.
                pub Error: SL_BOOL,
                /// Offset 12. Reserved.
                pub aReserved1: [u8; 2],
                /// Offset 14. DiagCode: the state or error, in the profile of nDiagProfile.
                pub DiagCode: u16,
            } private 16: $crate::base::sf::SL_SF_PRIVATE, 40
        }
    };
}

/// Declares a two-hand block's envelope plumbing from its struct: tag, name, its state
/// enum and next function (`next_ii` / `next_iii`).
#[macro_export]
#[doc(hidden)]
macro_rules! two_hand_block {
    ($ty:ident, $tag:expr, $diag:ident, $next:ident) => {
        $crate::impl_sf_member!($ty {
            tag: $tag,
            input: [Activate, S_Button1, S_Button2],
            param: [nDiagProfile],
            output: [Ready, S_TwoHandOut, SafetyDemand, Error],
        });

        $crate::impl_sf_block!($ty {
            tag: $tag,
            diag: $crate::blocks::plcopen::twohand::$diag,
            input: $crate::blocks::plcopen::twohand::TwoHandIn,
            reset: none,
            consts(s): [],
            next: |s, inp, _reset, in_state, _times| {
                $crate::blocks::plcopen::twohand::$next(s, inp, in_state)
            },
        } {
            #[inline(always)]
            fn decode(&self) -> (Self::In, bool) {
                let p = $crate::base::bools::pack([self.S_Button1, self.S_Button2]);
                let v = $crate::base::bools::logical(p, 0b11, 0);
                (
                    $crate::blocks::plcopen::twohand::TwoHandIn {
                        b1: v & 1 != 0,
                        b2: v & 2 != 0,
                    },
                    p.invalid != 0,
                )
            }
            #[inline(always)]
            fn write_outputs(&mut self, o: &$crate::base::sf::SfOut) {
                $crate::sf_outputs!(self, o, S_TwoHandOut, SafetyDemand);
            }
        });

        const _: () = assert!(core::mem::size_of::<$ty>() == 56);
    };
}

/// The steady-state fast path of a two-hand block (`base::sf::SfSteady`): the key is
/// Activate and the two buttons; type III's states with one button actuated read the
/// synchronism time (`$timed`), type II has no time.
#[macro_export]
#[doc(hidden)]
macro_rules! two_hand_steady {
    ($ty:ident, $diag:ident, timed: []) => {
        $crate::sf_steady!($ty: [Activate, S_Button1, S_Button2]);
    };
    ($ty:ident, $diag:ident, timed: [$($timed:ident),+]) => {
        $crate::sf_steady!($ty: [Activate, S_Button1, S_Button2], timed: |b| {
            false $(|| b.diag_state() == Some($crate::blocks::plcopen::twohand::$diag::$timed))+
        });
    };
}
