//! FB EDM — manual §4.9 (External Device Monitor): time monitoring of Mon1 and Mon2.
//! Switch-on monitoring: after Mon1 switches 0 → 1, Mon2 must be 0 within tSwitchOnTime.
//! Switch-off monitoring: after Mon1 switches 1 → 0, Mon2 must be 1 within tSwitchOffTime.
//! Each time at most 10000 ms, 0 = that monitoring off, at least one on. A time exceeded →
//! ERROR (4) with bError TRUE, left only through the group's ErrAck (RESET, 5).
//! States: STOP (2), ERROR (4), RESET (5), MONOFF (14: Mon1 FALSE, switch-off monitoring),
//! MONON (15: Mon1 TRUE, switch-on monitoring). Diag bit 0: switch-off timer elapsed,
//! bit 1: switch-on timer elapsed. Its own state machine (docs/semantics.md E1–E9).

use crate::base::block::BlockInfo;
use crate::base::envelope::Block;
use crate::base::header::param_crc;
use crate::base::reason::rule;
use crate::base::reason::{when, Rule, RuleDef, Unit};
use crate::base::types::*;
use crate::base::{bools, time};

include!(concat!(env!("OUT_DIR"), "/abi/blocks/boolean/edm.rs"));

/// Type tag, name and diag texts (manual §4.9.2).
const INFO: BlockInfo = BlockInfo::of::<EdmState>(SL_TYPE_EDM, "EDM").diag(&[
    (SL_DIAG_EDM_SWITCH_OFF, "Switch-OFF timer elapsed"),
    (SL_DIAG_EDM_SWITCH_ON, "Switch-ON timer elapsed"),
]);

crate::impl_member!([] FB_EDM {
    info: INFO,
    state: EdmState,
    private: SL_EDM_PRIVATE,
    input: [bMon1, bMon2],
    param: [tSwitchOnTime, tSwitchOffTime, wInputActive, wInputNegated],
    output: [bError],
    info_fields: [],
});

const T_ON: usize = 0;
const T_OFF: usize = 1;
/// Both inputs: bit 0 Mon1, bit 1 Mon2.
const INPUTS: u16 = 0b11;
/// `wAux` bit: the current monitoring still waits for Mon2.
const PENDING: u16 = 1 << 0;

/// Parameters as the user wrote them.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct EdmParams {
    pub on: u32,
    pub off: u32,
    pub active: u16,
    pub negated: u16,
}

/// Decoded inputs of one cycle.
#[derive(Clone, Copy, Debug, Default)]
pub struct EdmIn {
    /// Logical Mon1; an invalid byte reads FALSE, the switched-off command (semantics E7).
    pub mon1: bool,
    /// Logical Mon2; `None` for an invalid byte, which satisfies no monitoring (E7).
    pub mon2: Option<bool>,
}

impl EdmIn {
    /// The state Mon1 asks for (manual: "If the input MonIn1=TRUE … MONON").
    fn state(&self) -> u8 {
        if self.mon1 {
            SL_STATE_EDM_MONON
        } else {
            SL_STATE_EDM_MONOFF
        }
    }

    /// Mon2 has the value opposite to Mon1 (what the monitoring of this state waits for).
    fn settled(&self) -> bool {
        self.mon2 == Some(!self.mon1)
    }
}

/// Monitoring time and diag bit of a state.
fn monitoring(p: &SL_EDM_PRIVATE, state: u8) -> (u32, u16) {
    if state == SL_STATE_EDM_MONON {
        (u32::from(p.awTime[T_ON]), SL_DIAG_EDM_SWITCH_ON)
    } else {
        (u32::from(p.awTime[T_OFF]), SL_DIAG_EDM_SWITCH_OFF)
    }
}

/// Enters `state` after a switch of Mon1 (or at start): its monitoring starts now if its
/// time is not 0 (semantics E2, E3).
fn enter(p: &mut SL_EDM_PRIVATE, state: u8, now: u32) {
    let (t, _) = monitoring(p, state);
    let h = &mut p.stHeader;
    h.nState = state;
    h.tPhase = now;
    h.wAux = if t != 0 { PENDING } else { 0 };
}

/// One cycle of the current monitoring: done the first cycle Mon2 has the value opposite
/// to Mon1; ERROR with the state's diag bit when the time is reached first (E4).
fn check(p: &mut SL_EDM_PRIVATE, inp: &EdmIn, now: u32) {
    if p.stHeader.wAux & PENDING == 0 {
        return;
    }
    let (t, diag) = monitoring(p, p.stHeader.nState);
    let h = &mut p.stHeader;
    if inp.settled() {
        h.wAux &= !PENDING;
    } else if time::reached(now, h.tPhase, t) {
        h.enter_error(diag);
    }
}

impl Block for FB_EDM {
    const MAGIC: u16 = 0xED4D;
    type Params = EdmParams;
    type In = EdmIn;

    fn live_params(&self) -> EdmParams {
        EdmParams {
            on: self.tSwitchOnTime,
            off: self.tSwitchOffTime,
            active: self.wInputActive,
            negated: self.wInputNegated,
        }
    }

    fn latched_params(&self) -> EdmParams {
        let p = &self.stPrivate;
        EdmParams {
            on: u32::from(p.awTime[T_ON]),
            off: u32::from(p.awTime[T_OFF]),
            active: u16::from(p.stHeader.nActive),
            negated: u16::from(p.stHeader.nNegated),
        }
    }

    /// Manual §4.9.1: each time ≤ 10000 ms, at least one monitoring on; both inputs are
    /// needed for any monitoring (semantics E1).
    const RULES: &'static [RuleDef<EdmParams>] = &[
        rule!(at_most "tSwitchOnTime" in Ms, |p| p.on, SL_EDM_TIME_MAX),
        rule!(at_most "tSwitchOffTime" in Ms, |p| p.off, SL_EDM_TIME_MAX),
        RuleDef::new(
            "tSwitchOnTime or tSwitchOffTime",
            Rule::NotZero,
            Unit::Ms,
            |p| when(p.on == 0 && p.off == 0, 0, 0),
        ),
        rule!(equals "wInputActive", |p| p.active, INPUTS),
        rule!(no_bits_outside "wInputNegated", |p| p.negated, INPUTS),
    ];

    fn store_params(&mut self, p: &EdmParams) {
        let q = &mut self.stPrivate;
        // Exact for valid parameters (≤ 10000); an invalid set is stored truncated and never
        // runs (F_CFG_INVALID).
        q.awTime = [p.on as u16, p.off as u16];
        q.stHeader.nActive = p.active as u8;
        q.stHeader.nNegated = p.negated as u8;
    }

    fn latched_crc(&self) -> u16 {
        let p = &self.stPrivate;
        let h = &p.stHeader;
        param_crc(Self::MAGIC, h.nActive, h.nNegated, h.wOptions, &p.awTime)
    }

    fn decode(&mut self) -> (EdmIn, bool) {
        let h = &self.stPrivate.stHeader;
        let p = bools::pack([self.bMon1, self.bMon2]);
        let logical = bools::logical(p, h.nActive, h.nNegated);
        let inp = EdmIn {
            mon1: logical & 1 != 0,
            mon2: (p.invalid & 2 == 0).then_some(logical & 2 != 0),
        };
        (inp, p.invalid & h.nActive != 0)
    }

    /// STOP → run and RESET → run: the state Mon1 asks for, its monitoring started as if
    /// Mon1 had just switched (semantics E3).
    fn start(&mut self, inp: &EdmIn, now: u32) {
        enter(&mut self.stPrivate, inp.state(), now);
        check(&mut self.stPrivate, inp, now);
    }

    fn step(&mut self, inp: &EdmIn, now: u32) -> Status {
        let p = &mut self.stPrivate;
        let state = p.stHeader.nState;
        if state != SL_STATE_EDM_MONON && state != SL_STATE_EDM_MONOFF {
            // A state value this block never takes: the private state cannot be trusted.
            p.stHeader.enter_error(SL_DIAG_CORRUPT);
            return Status::Corrupt;
        }
        // A switch of Mon1 ends the other state's monitoring and starts this one's (E2).
        if inp.state() != state {
            enter(p, inp.state(), now);
        }
        check(p, inp, now);
        Status::Ok
    }

    /// A monitoring error remains while the monitoring of Mon1's present level is on and
    /// Mon2 does not have the value opposite to Mon1 (semantics E5).
    fn error_remains(&mut self, inp: &EdmIn) -> bool {
        let p = &self.stPrivate;
        let timer_error = p.stHeader.wDiag & (SL_DIAG_EDM_SWITCH_ON | SL_DIAG_EDM_SWITCH_OFF) != 0;
        let (t, _) = monitoring(p, inp.state());
        timer_error && t != 0 && !inp.settled()
    }

    fn write_outputs(&mut self) {
        let h = self.stPrivate.stHeader;
        self.bError = u8::from(h.nState == SL_STATE_ERROR);
        self.nState = h.nState;
        self.nDiag = h.wDiag;
    }
}
