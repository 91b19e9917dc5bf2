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

include!(concat!(env!("OUT_DIR"), "/abi/blocks/plcopen/edm.rs"));

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

/// The steady-state fast path (`base::sf::SfSteady`): the key is every BOOL byte the call
/// reads. The states that monitor the contactors read the monitoring time only while a
/// feedback check fails under these bytes (`next`: OUT_DISABLE with a loop not released,
/// OUT_ENABLE with a loop not switched); with the feedback as expected no time decides the
/// next transition of the same bytes.
impl crate::base::sf::SfSteady for SF_EDM {
    #[inline(always)]
    fn steady_key(&self) -> Option<u16> {
        crate::base::sf::key([
            &self.Activate,
            &self.S_OutControl,
            &self.EDM1,
            &self.EDM2,
            &self.S_StartReset,
            &self.Reset,
        ])
    }
    fn timed(&self) -> bool {
        match self.diag_state() {
            Some(SfEdmState::OutDisable) => self.EDM1 != 1 || self.EDM2 != 1,
            Some(SfEdmState::OutEnable) => self.EDM1 != 0 || self.EDM2 != 0,
            _ => false,
        }
    }
}
