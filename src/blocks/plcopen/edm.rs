//! SF_EDM — PLCopen TC5 Part 1 (research `plcopen_safety.md` §4.10, §5, §8.3): external
//! device monitoring. Switches `S_EDM_Out` with `S_OutControl` and monitors the feedback
//! contacts EDM1/EDM2 of the actuators (TRUE = released): released before switching on,
//! switched within MonitoringTime after switching on, released within MonitoringTime after
//! switching off. The feedback checks are the TwinSAFE EDM primitive's (`base::edm`); the
//! codes missing from the research (C070–C090, the static-reset variants) are chosen in
//! docs/semantics.md QD1–QD8.

use crate::base::edm::Edm;
use crate::base::sf::{self, ResetIn, SL_SF_PRIVATE};
use crate::base::time;
use crate::base::types::{SL_BOOL, SL_DIAG_EDM1, SL_DIAG_EDM2};

/// Block type tag of SF_EDM (`SL_MEMBER.nType`, `sl_diag_text`).
pub const SL_TYPE_SF_EDM: u16 = 521;

crate::sf_states!(
    /// The states of SF_EDM: values = v2.01 DiagCodes (CS-LIB FBS_EDM up to C060; the rest
    /// chosen, semantics QD2), with the v1.0 codes (B&R list, research §4.10).
    SfEdmState, init: Init {
        Idle = 0x0000, 0x0000, "IDLE", "FB not activated";
        Init = 0x8401, 0x8001, "INIT", "activated; start-up inhibit: waiting for a rising edge of Reset (or S_StartReset)";
        OutDisable = 0x8810, 0x8010, "OUT_DISABLE", "output FALSE; feedback monitored for release from the entry";
        OutEnable = 0x8000, 0x8000, "OUT_ENABLE", "output TRUE; feedback monitored for switching from the entry";
        ErrReset1 = 0xC001, 0xC001, "ERR_RESET_1", "static Reset while waiting for the reset after activation";
        ErrInit = 0xC100, 0xC111, "ERR_INIT", "rising edges of S_OutControl and Reset in the same call";
        ErrEdm11 = 0xC010, 0xC010, "ERR_EDM_11", "S_OutControl TRUE while EDM1 is not released";
        ErrEdm12 = 0xC020, 0xC020, "ERR_EDM_12", "S_OutControl TRUE while EDM2 is not released";
        ErrEdm13 = 0xC030, 0xC030, "ERR_EDM_13", "S_OutControl TRUE while EDM1 and EDM2 are not released";
        ErrEdm21 = 0xC040, 0xC040, "ERR_EDM_21", "MonitoringTime elapsed after switching off, EDM1 not released";
        ErrEdm22 = 0xC050, 0xC050, "ERR_EDM_22", "MonitoringTime elapsed after switching off, EDM2 not released";
        ErrEdm23 = 0xC060, 0xC060, "ERR_EDM_23", "MonitoringTime elapsed after switching off, EDM1 and EDM2 not released";
        ErrEdm31 = 0xC070, 0xC070, "ERR_EDM_31", "MonitoringTime elapsed after switching on, EDM1 not switched";
        ErrEdm32 = 0xC080, 0xC080, "ERR_EDM_32", "MonitoringTime elapsed after switching on, EDM2 not switched";
        ErrEdm33 = 0xC090, 0xC090, "ERR_EDM_33", "MonitoringTime elapsed after switching on, EDM1 and EDM2 not switched";
        ErrEdm11R = 0xC011, 0xC011, "ERR_EDM_11_RESET", "static Reset in ERR_EDM_11";
        ErrEdm12R = 0xC021, 0xC021, "ERR_EDM_12_RESET", "static Reset in ERR_EDM_12";
        ErrEdm13R = 0xC031, 0xC031, "ERR_EDM_13_RESET", "static Reset in ERR_EDM_13";
        ErrEdm21R = 0xC041, 0xC041, "ERR_EDM_21_RESET", "static Reset in ERR_EDM_21";
        ErrEdm22R = 0xC051, 0xC051, "ERR_EDM_22_RESET", "static Reset in ERR_EDM_22";
        ErrEdm23R = 0xC061, 0xC061, "ERR_EDM_23_RESET", "static Reset in ERR_EDM_23";
        ErrEdm31R = 0xC071, 0xC071, "ERR_EDM_31_RESET", "static Reset in ERR_EDM_31";
        ErrEdm32R = 0xC081, 0xC081, "ERR_EDM_32_RESET", "static Reset in ERR_EDM_32";
        ErrEdm33R = 0xC091, 0xC091, "ERR_EDM_33_RESET", "static Reset in ERR_EDM_33";
    }
);

/// One call's inputs.
#[derive(Clone, Copy, Debug, Default)]
pub struct SfEdmIn {
    /// S_OutControl.
    pub control: bool,
    /// R_TRIG(S_OutControl).Q.
    pub control_rising: bool,
    /// S_StartReset (v1.0 input): no reset needed after activation.
    pub start_reset: bool,
    /// The feedback loops EDM1, EDM2 (both monitored).
    pub edm: Edm,
}

/// Which feedback loops a diag mask of `base::edm` names: 1 = EDM1, 2 = EDM2, 3 = both.
const fn loops(d: u16) -> u8 {
    (if d & SL_DIAG_EDM1 != 0 { 1 } else { 0 }) | (if d & SL_DIAG_EDM2 != 0 { 2 } else { 0 })
}

/// The error of a feedback check: `kind` 1 (before switching on), 2 (after switching
/// off), 3 (after switching on); `which` from [`loops`] (1, 2, 3).
fn edm_error(kind: u8, which: u8) -> SfEdmState {
    use SfEdmState::*;
    match (kind, which) {
        (1, 1) => ErrEdm11,
        (1, 2) => ErrEdm12,
        (1, _) => ErrEdm13,
        (2, 1) => ErrEdm21,
        (2, 2) => ErrEdm22,
        (2, _) => ErrEdm23,
        (_, 1) => ErrEdm31,
        (_, 2) => ErrEdm32,
        _ => ErrEdm33,
    }
}

/// The static-reset variant of a feedback error, and back (`None`: not a feedback error).
fn static_pair(s: SfEdmState) -> Option<(SfEdmState, SfEdmState)> {
    use SfEdmState::*;
    Some(match s {
        ErrEdm11 | ErrEdm11R => (ErrEdm11, ErrEdm11R),
        ErrEdm12 | ErrEdm12R => (ErrEdm12, ErrEdm12R),
        ErrEdm13 | ErrEdm13R => (ErrEdm13, ErrEdm13R),
        ErrEdm21 | ErrEdm21R => (ErrEdm21, ErrEdm21R),
        ErrEdm22 | ErrEdm22R => (ErrEdm22, ErrEdm22R),
        ErrEdm23 | ErrEdm23R => (ErrEdm23, ErrEdm23R),
        ErrEdm31 | ErrEdm31R => (ErrEdm31, ErrEdm31R),
        ErrEdm32 | ErrEdm32R => (ErrEdm32, ErrEdm32R),
        ErrEdm33 | ErrEdm33R => (ErrEdm33, ErrEdm33R),
        _ => return None,
    })
}

/// The transition table of research §4.10 (v2.01 codes) with the disambiguations of
/// semantics QD1–QD8, first matching guard wins. MonitoringTime `t` runs from the entry
/// into 8810 / 8000 (`in_state`, ms). IDLE → INIT is the envelope's (Activate).
fn next(s: SfEdmState, i: &SfEdmIn, r: ResetIn, in_state: u32, t: u32) -> SfEdmState {
    use SfEdmState::*;
    let elapsed = time::reached(in_state, 0, t);
    let not_released = loops(i.edm.not_released());
    let not_switched = loops(i.edm.not_switched());
    let pair = static_pair(s);
    match s {
        Init if i.start_reset => OutDisable,
        Init if r.held() => ErrReset1,
        Init if r.rising && i.control_rising => ErrInit,
        Init if r.rising => OutDisable,
        ErrReset1 if !r.level => Init,
        OutDisable if i.control && not_released != 0 => edm_error(1, not_released),
        OutDisable if elapsed && not_released != 0 => edm_error(2, not_released),
        OutDisable if i.control => OutEnable,
        OutEnable if !i.control => OutDisable,
        OutEnable if elapsed && not_switched != 0 => edm_error(3, not_switched),
        ErrInit if r.rising && !i.control_rising => OutDisable,
        ErrEdm11 | ErrEdm12 | ErrEdm13 | ErrEdm21 | ErrEdm22 | ErrEdm23 | ErrEdm31 | ErrEdm32
        | ErrEdm33
            if r.held() =>
        {
            pair.map_or(s, |p| p.1)
        }
        ErrEdm11 | ErrEdm12 | ErrEdm13 | ErrEdm21 | ErrEdm22 | ErrEdm23 | ErrEdm31 | ErrEdm32
        | ErrEdm33
            if r.rising =>
        {
            OutDisable
        }
        ErrEdm11R | ErrEdm12R | ErrEdm13R | ErrEdm21R | ErrEdm22R | ErrEdm23R | ErrEdm31R
        | ErrEdm32R | ErrEdm33R
            if !r.level =>
        {
            pair.map_or(s, |p| p.0)
        }
        Idle | Init | ErrReset1 | OutDisable | OutEnable | ErrInit | ErrEdm11 | ErrEdm12
        | ErrEdm13 | ErrEdm21 | ErrEdm22 | ErrEdm23 | ErrEdm31 | ErrEdm32 | ErrEdm33
        | ErrEdm11R | ErrEdm12R | ErrEdm13R | ErrEdm21R | ErrEdm22R | ErrEdm23R | ErrEdm31R
        | ErrEdm32R | ErrEdm33R => s,
    }
}

crate::base::layout::block_struct! {
    /// SF_EDM instance: the PLCopen v2.01 VAR_INPUT / VAR_OUTPUT names (plus v1.0's
    /// S_StartReset), BOOL = one byte. Size: 64 bytes.
    SF_EDM {
        /// Offset 0. Activate: FALSE = idle (DiagCode 0000, every output FALSE), highest priority.
        pub Activate: SL_BOOL,
        /// Offset 1. S_OutControl: the control signal of the preceding safety FB, TRUE = switch the actuators on.
        pub S_OutControl: SL_BOOL,
        /// Offset 2. EDM1: feedback of actuator 1, TRUE = released (de-energised); v1.0 name S_EDM1.
        pub EDM1: SL_BOOL,
        /// Offset 3. EDM2: feedback of actuator 2, TRUE = released; bridge it to EDM1 for one feedback; v1.0 name S_EDM2.
        pub EDM2: SL_BOOL,
        /// Offset 4. MonitoringTime (constant, ms): the actuators' longest response time; latched at activation.
        pub MonitoringTime: u32,
        /// Offset 8. S_StartReset (v1.0 input; FALSE in v2.01): TRUE = no reset needed after activation.
        pub S_StartReset: SL_BOOL,
        /// Offset 9. Reset: a rising edge leaves INIT and the errors; held TRUE it is a static-reset error.
        pub Reset: SL_BOOL,
        /// Offset 10. Reserved, keep 0.
        pub aReserved0: [u8; 1],
        /// Offset 11. Library extension, constant: DiagCode profile, 0 = v2.01 (default), 1 = v1.0; latched at activation.
        pub nDiagProfile: u8,
        /// Offset 12 (output base). Ready: TRUE while activated (DiagCode != 0000).
        pub Ready: SL_BOOL,
        /// Offset 13. S_EDM_Out: the safety output to the actuators, TRUE only at DiagCode 8000.
        pub S_EDM_Out: SL_BOOL,
        /// Offset 14. SafetyDemand: the output is switched off (v2.01 code bit 0x0800).
        pub SafetyDemand: SL_BOOL,
        /// Offset 15. ResetRequest: a reset is awaited (v2.01 code bit 0x0400) and Reset is FALSE.
        pub ResetRequest: SL_BOOL,
        /// Offset 16. Error: DiagCode >= C000.
        pub Error: SL_BOOL,
        /// Offset 17. Reserved.
        pub aReserved1: [u8; 1],
        /// Offset 18. DiagCode: the state or error, in the profile of nDiagProfile.
        pub DiagCode: u16,
        /// Offset 20. Reserved.
        pub aReserved2: [u8; 4],
    } private 24: SL_SF_PRIVATE, 40
}

crate::impl_sf_member!(SF_EDM {
    tag: SL_TYPE_SF_EDM,
    input: [Activate, S_OutControl, EDM1, EDM2, S_StartReset, Reset],
    param: [nDiagProfile, MonitoringTime],
    output: [Ready, S_EDM_Out, SafetyDemand, ResetRequest, Error],
});

crate::impl_sf_block!(SF_EDM {
    tag: SL_TYPE_SF_EDM,
    diag: SfEdmState,
    input: SfEdmIn,
    reset: Reset,
    consts(s): [s.MonitoringTime],
    rules: [sf::time0_rule("MonitoringTime")],
    next: |s, inp, reset, in_state, times| next(s, inp, reset, in_state, times[0]),
} {
    /// An invalid S_OutControl / S_StartReset byte reads FALSE; an invalid feedback byte
    /// is neither released nor switched (an error wherever the feedback is checked).
    #[inline(always)]
    fn decode(&self) -> (Self::In, bool) {
        let p =
            crate::base::bools::pack([self.S_OutControl, self.S_StartReset, self.EDM1, self.EDM2]);
        let v = crate::base::bools::logical(p, 0b1111, 0);
        let raw = [self.EDM1, self.EDM2];
        (
            SfEdmIn {
                control: v & 1 != 0,
                control_rising: sf::trigger_rising(&self.stPrivate, self.S_OutControl),
                start_reset: v & 2 != 0,
                edm: Edm {
                    active: [true; 2],
                    is_true: raw.map(|b| b == 1),
                    is_false: raw.map(|b| b == 0),
                },
            },
            p.invalid != 0,
        )
    }
    #[inline(always)]
    fn write_outputs(&mut self, o: &sf::SfOut) {
        crate::sf_outputs!(self, o, S_EDM_Out, SafetyDemand, ResetRequest);
        // The end of every call: the R_TRIG memory of S_OutControl.
        sf::store_trigger(&mut self.stPrivate, self.S_OutControl);
    }
});

// The steady-state fast path (`base::sf::SfSteady`): the key is every BOOL byte the call
// reads; the states that monitor the contactors read the monitoring time.
crate::sf_steady!(
    SF_EDM: [Activate, S_OutControl, EDM1, EDM2, S_StartReset, Reset],
    timed: SfEdmState::{OutDisable, OutEnable}
);
