//! SF_ModeSelector — PLCopen TC5 Part 1 (research `plcopen_safety.md` §4.8, DiagCodes §5):
//! selects one of up to eight operating modes (manual, automatic …) from S_Mode0…S_Mode7,
//! confirmed by a rising S_SetMode (or automatically with AutoSetMode), lockable with
//! S_Unlock FALSE, with short-circuit (two modes) and open-circuit (no mode for longer than
//! ModeMonitorTime after a falling S_ModeX) monitoring; the v2.01 errors are left by Reset
//! only after the fault is gone (C0y0 → C4y0 → Reset).
//!
//! Memory beyond the state (`track`, in the header's `wAux`): the modes of the previous
//! call (the selection while MODE_SELECTED, the falling edge), the selection held while
//! MODE_LOCKED, the R_TRIG of S_SetMode and whether the open-circuit time runs; its start
//! is the private field `tModesOff`.

use crate::base::bools;
use crate::base::sf::{DiagState, ResetIn, SfOut, SL_SF_PRIVATE};
use crate::base::time;
use crate::base::types::SL_BOOL;

include!(concat!(
    env!("OUT_DIR"),
    "/abi/blocks/plcopen/modeselector.rs"
));

/// `wAux` bits 0–7: the S_ModeX of the last call.
const AUX_MODES: u16 = 0x00FF;
/// `wAux` bits 8–10: the index of the selected mode held while MODE_LOCKED.
const AUX_HELD_SHIFT: u16 = 8;
/// `wAux` bit 11: S_SetMode of the last call (its R_TRIG).
const AUX_SET_PREV: u16 = 1 << 11;
/// `wAux` bit 12: all S_ModeX FALSE since a falling S_ModeX (the open-circuit time runs).
const AUX_OFF_RUNNING: u16 = 1 << 12;

/// One call's inputs, completed by the block's memory (`track`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ModeIn {
    /// S_Mode0…S_Mode7 (bit i = S_ModeI; an invalid byte reads FALSE).
    pub modes: u8,
    /// S_Unlock.
    pub unlock: bool,
    /// S_SetMode.
    pub set_mode: bool,
    /// R_TRIG(S_SetMode).Q.
    pub set_rising: bool,
    /// The selected mode (one bit) of MODE_SELECTED / MODE_LOCKED.
    pub selected: u8,
    /// How long (ms) all S_ModeX have been FALSE since a falling S_ModeX; `None`: a mode is
    /// TRUE, or none has fallen since the activation.
    pub all_off_ms: Option<u32>,
}

/// Research §4.8's table (v2.01 codes), first matching guard wins, with the v2.01 errors'
/// "fault gone" states (semantics QM1–QM4). IDLE → MODE_CHANGED is the envelope's.
/// `auto`: AutoSetMode; `monitor`: ModeMonitorTime (ms).
pub fn mode_selector_next(
    s: ModeState,
    i: &ModeIn,
    r: ResetIn,
    auto: bool,
    monitor: u32,
) -> ModeState {
    use ModeState::*;
    let n = i.modes.count_ones();
    let short = n > 1;
    let open = i.all_off_ms.is_some_and(|t| t > monitor);
    match s {
        ModeChanged if short => ErrShortCircuit,
        ModeChanged if open => ErrOpenCircuit,
        ModeChanged if (auto || i.set_rising) && i.unlock && n == 1 => Selected,
        Selected if short => ErrShortCircuit,
        Selected if i.modes != i.selected => ModeChanged,
        Selected if !i.unlock => Locked,
        Locked if i.unlock && i.modes != i.selected => ModeChanged,
        Locked if i.unlock => Selected,
        ErrShortCircuit if !short => ErrShortCircuitResReq,
        ErrShortCircuitResReq if short => ErrShortCircuit,
        ErrShortCircuitResReq if r.held() => ErrReset1,
        ErrShortCircuitResReq if r.rising => ModeChanged,
        ErrReset1 if !r.level => ErrShortCircuitResReq,
        ErrOpenCircuit if n == 1 => ErrOpenCircuitResReq,
        ErrOpenCircuitResReq if open => ErrOpenCircuit,
        ErrOpenCircuitResReq if r.held() => ErrReset2,
        ErrOpenCircuitResReq if r.rising => ModeChanged,
        ErrReset2 if !r.level => ErrOpenCircuitResReq,
        Idle
        | ModeChanged
        | Selected
        | Locked
        | ErrShortCircuit
        | ErrShortCircuitResReq
        | ErrOpenCircuit
        | ErrOpenCircuitResReq
        | ErrReset1
        | ErrReset2 => s,
    }
}

/// SF_ModeSelector instance: the PLCopen VAR_INPUT / VAR_OUTPUT names, BOOL = one byte.
/// Size: 80 bytes.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[allow(non_snake_case, non_camel_case_types)]
pub struct SF_ModeSelector {
    /// Offset 0. Activate: FALSE = idle (DiagCode 0000, every output FALSE), highest priority.
    pub Activate: SL_BOOL,
    /// Offset 1. S_Mode0: mode 0 requested (TRUE).
    pub S_Mode0: SL_BOOL,
    /// Offset 2. S_Mode1: mode 1 requested.
    pub S_Mode1: SL_BOOL,
    /// Offset 3. S_Mode2: mode 2 requested.
    pub S_Mode2: SL_BOOL,
    /// Offset 4. S_Mode3: mode 3 requested.
    pub S_Mode3: SL_BOOL,
    /// Offset 5. S_Mode4: mode 4 requested.
    pub S_Mode4: SL_BOOL,
    /// Offset 6. S_Mode5: mode 5 requested.
    pub S_Mode5: SL_BOOL,
    /// Offset 7. S_Mode6: mode 6 requested.
    pub S_Mode6: SL_BOOL,
    /// Offset 8. S_Mode7: mode 7 requested.
    pub S_Mode7: SL_BOOL,
    /// Offset 9. S_Unlock: FALSE = the selected mode is locked (S_ModeX changes and S_SetMode ignored).
    pub S_Unlock: SL_BOOL,
    /// Offset 10. S_SetMode: a rising edge confirms the requested mode (not needed with AutoSetMode).
    pub S_SetMode: SL_BOOL,
    /// Offset 11. AutoSetMode (constant): TRUE = a valid S_ModeX change selects without S_SetMode; latched at activation.
    pub AutoSetMode: SL_BOOL,
    /// Offset 12. ModeMonitorTime (constant, ms): how long all S_ModeX may be FALSE after a falling S_ModeX; latched at activation.
    pub ModeMonitorTime: u32,
    /// Offset 16. Reset: a rising edge resets an error once its fault is gone; held TRUE there it is a static-reset error.
    pub Reset: SL_BOOL,
    /// Offset 17. Reserved, keep 0.
    pub aReserved0: [u8; 2],
    /// Offset 19. Library extension, constant: DiagCode profile, 0 = v2.01 (default), 1 = v1.0; latched at activation.
    pub nDiagProfile: u8,
    /// Offset 20 (output base). Ready: TRUE while activated (DiagCode != 0000).
    pub Ready: SL_BOOL,
    /// Offset 21. S_Mode0Sel: mode 0 selected (TRUE only at DiagCode 8000 and in MODE_LOCKED).
    pub S_Mode0Sel: SL_BOOL,
    /// Offset 22. S_Mode1Sel: mode 1 selected.
    pub S_Mode1Sel: SL_BOOL,
    /// Offset 23. S_Mode2Sel: mode 2 selected.
    pub S_Mode2Sel: SL_BOOL,
    /// Offset 24. S_Mode3Sel: mode 3 selected.
    pub S_Mode3Sel: SL_BOOL,
    /// Offset 25. S_Mode4Sel: mode 4 selected.
    pub S_Mode4Sel: SL_BOOL,
    /// Offset 26. S_Mode5Sel: mode 5 selected.
    pub S_Mode5Sel: SL_BOOL,
    /// Offset 27. S_Mode6Sel: mode 6 selected.
    pub S_Mode6Sel: SL_BOOL,
    /// Offset 28. S_Mode7Sel: mode 7 selected.
    pub S_Mode7Sel: SL_BOOL,
    /// Offset 29. S_AnyModeSel: a mode is selected (DiagCode 8000 or MODE_LOCKED).
    pub S_AnyModeSel: SL_BOOL,
    /// Offset 30. SafetyDemand: the safety function is demanded (v2.01 code bit 0x0800).
    pub SafetyDemand: SL_BOOL,
    /// Offset 31. ResetRequest: a reset is awaited (v2.01 code bit 0x0400) and Reset is FALSE.
    pub ResetRequest: SL_BOOL,
    /// Offset 32. Error: DiagCode >= C000.
    pub Error: SL_BOOL,
    /// Offset 33. Reserved.
    pub aReserved1: [u8; 1],
    /// Offset 34. DiagCode: the state or error, in the profile of nDiagProfile.
    pub DiagCode: u16,
    /// Offset 36. Private state, 40 bytes: never write it.
    pub stPrivate: SL_SF_PRIVATE,
    /// Offset 76. Private: the time all S_ModeX became FALSE after a falling S_ModeX (ms); never write it.
    pub tModesOff: u32,
}

crate::impl_sf_member!(SF_ModeSelector {
    tag: SL_TYPE_SF_MODESELECTOR,
    input: [
        Activate, S_Mode0, S_Mode1, S_Mode2, S_Mode3, S_Mode4, S_Mode5, S_Mode6, S_Mode7, S_Unlock,
        S_SetMode, Reset,
    ],
    param: [AutoSetMode, ModeMonitorTime, nDiagProfile],
    output: [
        Ready,
        S_Mode0Sel,
        S_Mode1Sel,
        S_Mode2Sel,
        S_Mode3Sel,
        S_Mode4Sel,
        S_Mode5Sel,
        S_Mode6Sel,
        S_Mode7Sel,
        S_AnyModeSel,
        SafetyDemand,
        ResetRequest,
        Error,
    ],
});

crate::impl_sf_block!(SF_ModeSelector {
    tag: SL_TYPE_SF_MODESELECTOR,
    diag: ModeState,
    input: ModeIn,
    reset: Reset,
    // ModeMonitorTime and AutoSetMode, the two constants: AutoSetMode as the second
    // latched word (0 / 1; an invalid byte is out of range: C3FC, semantics QM5).
    consts(s): [s.ModeMonitorTime, crate::base::sf::bool_const(s.AutoSetMode)],
    rules: [
        crate::base::sf::time0_rule("ModeMonitorTime"),
        crate::base::sf::bool1_rule("AutoSetMode"),
    ],
    next: |s, inp, reset, _in_state, t| mode_selector_next(s, inp, reset, t[1] == 1, t[0]),
} {
    #[inline(always)]
    fn decode(&self) -> (Self::In, bool) {
        let m = bools::pack([
            self.S_Mode0,
            self.S_Mode1,
            self.S_Mode2,
            self.S_Mode3,
            self.S_Mode4,
            self.S_Mode5,
            self.S_Mode6,
            self.S_Mode7,
        ]);
        let c = bools::pack([self.S_Unlock, self.S_SetMode]);
        let v = bools::logical(c, 0b11, 0);
        (
            ModeIn {
                modes: bools::logical(m, 0xFF, 0),
                unlock: v & 1 != 0,
                set_mode: v & 2 != 0,
                ..ModeIn::default()
            },
            m.invalid | c.invalid != 0,
        )
    }
    /// The selection: in MODE_SELECTED the last call's modes (the state was entered or
    /// kept with exactly those), in MODE_LOCKED the held one; the R_TRIG of S_SetMode; the
    /// open-circuit time from the call in which all S_ModeX became FALSE (while activated).
    fn track(&mut self, inp: &mut ModeIn, now: u32) {
        let h = self.stPrivate.stHeader;
        let last = (h.wAux & AUX_MODES) as u8;
        let held = if h.wDiag == ModeState::Selected.code() {
            (last.trailing_zeros() & 7) as u16
        } else {
            h.wAux >> AUX_HELD_SHIFT & 7
        };
        inp.selected = 1 << held;
        inp.set_rising = inp.set_mode && h.wAux & AUX_SET_PREV == 0;
        // Only a fall seen while activated counts (the last call was activated: the state
        // before this call is not IDLE; IDLE clears `wAux`).
        let active = h.wDiag != ModeState::Idle.code();
        let fell = last != 0 && inp.modes == 0;
        if fell {
            self.tModesOff = now;
        }
        let running = active && inp.modes == 0 && (fell || h.wAux & AUX_OFF_RUNNING != 0);
        inp.all_off_ms = running.then(|| time::elapsed(now, self.tModesOff));
        let mut aux = u16::from(inp.modes) | held << AUX_HELD_SHIFT;
        if inp.set_mode {
            aux |= AUX_SET_PREV;
        }
        if running {
            aux |= AUX_OFF_RUNNING;
        }
        self.stPrivate.stHeader.wAux = aux;
    }
    fn write_outputs(&mut self, o: &SfOut) {
        let h = self.stPrivate.stHeader;
        // MODE_SELECTED: this call's modes (exactly the selection); MODE_LOCKED: the held one.
        let sel: u8 = if h.wDiag == ModeState::Selected.code() {
            (h.wAux & AUX_MODES) as u8
        } else if h.wDiag == ModeState::Locked.code() {
            1 << (h.wAux >> AUX_HELD_SHIFT & 7)
        } else {
            0
        };
        let bit = |i: u8| sel >> i & 1;
        self.Ready = u8::from(o.ready);
        self.S_Mode0Sel = bit(0);
        self.S_Mode1Sel = bit(1);
        self.S_Mode2Sel = bit(2);
        self.S_Mode3Sel = bit(3);
        self.S_Mode4Sel = bit(4);
        self.S_Mode5Sel = bit(5);
        self.S_Mode6Sel = bit(6);
        self.S_Mode7Sel = bit(7);
        self.S_AnyModeSel = u8::from(sel != 0);
        self.SafetyDemand = u8::from(o.safety_demand);
        self.ResetRequest = u8::from(o.reset_request);
        self.Error = u8::from(o.error);
        self.DiagCode = o.diag_code;
    }
});

/// The layout: 80 bytes, no implicit padding.
const _: () = assert!(core::mem::size_of::<SF_ModeSelector>() == 80);

// The steady-state fast path (`base::sf::SfSteady`): the key is every BOOL byte the call
// reads; the open-circuit time runs while every S_ModeX is FALSE.
crate::sf_steady!(
    SF_ModeSelector: [Activate, S_Mode0, S_Mode1, S_Mode2, S_Mode3, S_Mode4,
        S_Mode5, S_Mode6, S_Mode7, S_Unlock, S_SetMode, AutoSetMode, Reset],
    timed: |b| b.stPrivate.stHeader.wAux & AUX_OFF_RUNNING != 0
);
