//! FB ADVPOSMON (manual §4.31, ABI-2 §11.16, §12; docs/semantics.md AP1–AP5): one test
//! per statement of the manual section, then random sequences (≥ 10,000) against a small
//! model of the block that assert what they reached.

mod common;

use common::{state_names, Rng, CORE_STATES, CORE_STATE_NAMES};
use safelogic::*;

const ENABLE: u16 = SL_ADVPOSMON_ACTIVE_ENABLE;
const RESTART: u16 = SL_ADVPOSMON_ACTIVE_RESTART;
const WFR: u8 = SL_STATE_ADVPOSMON_WAIT_FOR_RESTART;

fn make(active: u16) -> FB_ADVPOSMON {
    FB_ADVPOSMON {
        wInputActive: active,
        ..Default::default()
    }
}

/// Inputs of one call: Enable, Restart, SDFB_ERROR, POS_REF_OK, POS_CHECK_OK.
fn set(fb: &mut FB_ADVPOSMON, enable: u8, restart: u8, sdfb: u8, ref_ok: u8, check_ok: u8) {
    fb.bEnable = enable;
    fb.bRestart = restart;
    fb.bSdfbError = sdfb;
    fb.bPosRefOk = ref_ok;
    fb.bPosCheckOk = check_ok;
}

/// (Error, Active, Wait, OverRange).
fn outs(fb: &FB_ADVPOSMON) -> (u8, u8, u8, u8) {
    (fb.bError, fb.bActive, fb.bWait, fb.bOverRange)
}

fn running(active: u16) -> FB_ADVPOSMON {
    let mut fb = make(active);
    assert_eq!(fb.init(), SL_OK);
    fb.bRun = 1;
    fb
}

/// RUN: "ENABLED = TRUE": Active = POS_REF_OK ∧ POS_CHECK_OK, Wait = ¬POS_REF_OK,
/// OverRange = POS_REF_OK ∧ ¬POS_CHECK_OK (without RESTART_ACTIVE, OverRange stays RUN).
#[test]
fn run_outputs_follow_the_drive_signals() {
    let mut fb = running(ENABLE);
    for (t, (r, c, o)) in [
        (1, 1, (0, 1, 0, 0)),
        (0, 1, (0, 0, 1, 0)),
        (0, 0, (0, 0, 1, 0)),
        (1, 0, (0, 0, 0, 1)),
        (1, 1, (0, 1, 0, 0)),
    ]
    .into_iter()
    .enumerate()
    {
        set(&mut fb, 1, 0, 0, r, c);
        assert_eq!(fb.cycle(t as u32), SL_OK);
        assert_eq!(
            (fb.nState, outs(&fb)),
            (SL_STATE_RUN, o),
            "ref {r} check {c}"
        );
    }
}

/// SAFE: "ENABLED = FALSE": all outputs 0; back to RUN with Enable.
#[test]
fn enable_false_is_safe() {
    let mut fb = running(ENABLE);
    set(&mut fb, 0, 0, 0, 1, 1);
    assert_eq!(fb.cycle(0), SL_OK);
    assert_eq!((fb.nState, outs(&fb)), (SL_STATE_SAFE, (0, 0, 0, 0)));
    set(&mut fb, 1, 0, 0, 1, 1);
    assert_eq!(fb.cycle(1), SL_OK);
    assert_eq!((fb.nState, outs(&fb)), (SL_STATE_RUN, (0, 1, 0, 0)));
    set(&mut fb, 2, 0, 0, 1, 1);
    assert_eq!(fb.cycle(2), SL_E_INVALID_BOOL);
    assert_eq!((fb.nState, outs(&fb)), (SL_STATE_SAFE, (0, 0, 0, 0)));
}

/// STOP: "FbRun = FALSE": all outputs 0.
#[test]
fn run_false_is_stop() {
    let mut fb = running(ENABLE);
    set(&mut fb, 1, 0, 0, 1, 1);
    assert_eq!(fb.cycle(0), SL_OK);
    fb.bRun = 0;
    assert_eq!(fb.cycle(1), SL_OK);
    assert_eq!((fb.nState, outs(&fb)), (SL_STATE_STOP, (0, 0, 0, 0)));
}

/// ERROR: "SDFB_ERROR = TRUE … transfers the Diag message 0x38D1": Error 1, diag = the
/// instance (bits 0-2); remains while SDFB_ERROR; RESET on ErrAck (outputs 0), then RUN.
#[test]
fn sdfb_error_is_error_38d1_until_acknowledged() {
    for instance in 0..=6u8 {
        let mut fb = running(ENABLE | RESTART);
        set(&mut fb, 1, 0, 0, 1, 1);
        assert_eq!(fb.cycle(0), SL_OK);
        fb.bSdfbError = 1;
        fb.nSdfbInstance = instance;
        assert_eq!(fb.cycle(1), SL_OK);
        assert_eq!((fb.nState, outs(&fb)), (SL_STATE_ERROR, (1, 0, 0, 0)));
        let diag = if (1..=4).contains(&instance) {
            u16::from(instance)
        } else {
            0
        };
        assert_eq!(
            (fb.nDiag, fb.nDiagTextId, fb.dwDiagPar2, fb.dwDiagPar3),
            (diag, 0x38D1, 0, 0)
        );
        fb.bErrAck = 1;
        assert_eq!(fb.cycle(2), SL_OK);
        assert_eq!(fb.nState, SL_STATE_ERROR, "SDFB_ERROR remains");
        fb.bErrAck = 0;
        fb.bSdfbError = 0;
        assert_eq!(fb.cycle(3), SL_OK);
        fb.bErrAck = 1;
        assert_eq!(fb.cycle(4), SL_OK);
        assert_eq!((fb.nState, outs(&fb)), (SL_STATE_RESET, (0, 0, 0, 0)));
        assert_eq!((fb.nDiag, fb.nDiagTextId), (0, 0));
        fb.bErrAck = 0;
        assert_eq!(fb.cycle(5), SL_OK);
        assert_eq!((fb.nState, outs(&fb)), (SL_STATE_RUN, (0, 1, 0, 0)));
    }
}

/// An invalid SDFB_ERROR byte reads TRUE (ABI-2 §12.7); Enable FALSE does not hide it.
#[test]
fn an_invalid_sdfb_error_byte_is_an_error() {
    let mut fb = running(ENABLE);
    set(&mut fb, 0, 0, 7, 1, 1);
    assert_eq!(fb.cycle(0), SL_E_INVALID_BOOL);
    assert_eq!((fb.nState, fb.nDiagTextId), (SL_STATE_ERROR, 0x38D1));
}

/// WAIT-FOR-RESTART (16): "in the RUN state OverRange = 1 and RESTART_ACTIVE": OverRange 1;
/// START: "Restart = TRUE": OverRange 1; the falling edge of Restart → RUN (AP3).
#[test]
fn over_range_with_restart_waits_for_the_restart_sequence() {
    let mut fb = running(ENABLE | RESTART);
    set(&mut fb, 1, 0, 0, 1, 1);
    assert_eq!(fb.cycle(0), SL_OK);
    assert_eq!(fb.nState, SL_STATE_RUN);
    set(&mut fb, 1, 0, 0, 1, 0);
    assert_eq!(fb.cycle(1), SL_OK);
    assert_eq!((fb.nState, outs(&fb)), (WFR, (0, 0, 0, 1)));
    // The coverage comes back: still waiting for the restart.
    set(&mut fb, 1, 0, 0, 1, 1);
    assert_eq!(fb.cycle(2), SL_OK);
    assert_eq!((fb.nState, outs(&fb)), (WFR, (0, 0, 0, 1)));
    set(&mut fb, 1, 1, 0, 1, 1);
    assert_eq!(fb.cycle(3), SL_OK);
    assert_eq!((fb.nState, outs(&fb)), (SL_STATE_START, (0, 0, 0, 1)));
    assert_eq!(fb.cycle(4), SL_OK);
    assert_eq!(
        fb.nState, SL_STATE_START,
        "START holds while Restart is TRUE"
    );
    set(&mut fb, 1, 0, 0, 1, 1);
    assert_eq!(fb.cycle(5), SL_OK);
    assert_eq!((fb.nState, outs(&fb)), (SL_STATE_RUN, (0, 1, 0, 0)));
    // Still over range at the falling edge: back to waiting at once.
    set(&mut fb, 1, 0, 0, 1, 0);
    assert_eq!(fb.cycle(6), SL_OK);
    set(&mut fb, 1, 1, 0, 1, 0);
    assert_eq!(fb.cycle(7), SL_OK);
    assert_eq!(fb.nState, SL_STATE_START);
    set(&mut fb, 1, 0, 0, 1, 0);
    assert_eq!(fb.cycle(8), SL_OK);
    assert_eq!((fb.nState, outs(&fb)), (WFR, (0, 0, 0, 1)));
    // An invalid Restart byte is no edge.
    set(&mut fb, 1, 1, 0, 1, 1);
    assert_eq!(fb.cycle(9), SL_OK);
    set(&mut fb, 1, 5, 0, 1, 1);
    assert_eq!(fb.cycle(10), SL_E_INVALID_BOOL);
    assert_eq!(fb.nState, WFR);
    // Enable FALSE leaves the sequence for SAFE.
    set(&mut fb, 0, 0, 0, 1, 1);
    assert_eq!(fb.cycle(11), SL_OK);
    assert_eq!(fb.nState, SL_STATE_SAFE);
}

/// Restart held TRUE is no restart: START is left only by the falling edge.
#[test]
fn a_held_restart_does_not_restart() {
    let mut fb = running(ENABLE | RESTART);
    set(&mut fb, 1, 1, 0, 1, 0);
    assert_eq!(fb.cycle(0), SL_OK);
    assert_eq!(fb.nState, WFR, "entering RUN over range waits at once");
    assert_eq!(fb.cycle(1), SL_OK);
    assert_eq!(fb.nState, SL_STATE_START);
    fb.bPosCheckOk = 1;
    for t in 2..5 {
        assert_eq!(fb.cycle(t), SL_OK);
        assert_eq!(fb.nState, SL_STATE_START);
    }
}

/// Parameters: Enable bit required, bits 0-1 only, feedback instances 0-3 (boundary 3/4).
#[test]
fn parameters_at_their_limits() {
    assert_eq!(make(ENABLE).init(), SL_OK);
    assert_eq!(make(ENABLE | RESTART).init(), SL_OK);
    assert_eq!(make(RESTART).init(), SL_E_CONFIG);
    for bit in 2..16 {
        assert_eq!(make(ENABLE | 1 << bit).init(), SL_E_CONFIG, "bit {bit}");
    }
    for i in 0..4 {
        for (v, rc) in [(3, SL_OK), (4, SL_E_CONFIG), (u16::MAX, SL_E_CONFIG)] {
            let mut fb = make(ENABLE);
            match i {
                0 => fb.nChAPrimaryFeedback = v,
                1 => fb.nChASecondaryFeedback = v,
                2 => fb.nChBPrimaryFeedback = v,
                _ => fb.nChBSecondaryFeedback = v,
            }
            assert_eq!(fb.init(), rc, "feedback {i} = {v}");
        }
    }
}

/// State names of the registry, WAIT-FOR-RESTART included.
#[test]
fn names() {
    let t = registry::block_type(SL_TYPE_ADVPOSMON).unwrap();
    let names = state_names(&t.info);
    assert_eq!(names[..5], CORE_STATE_NAMES);
    assert_eq!(names[5..], [(6, "START"), (16, "WAIT-FOR-RESTART")]);
}

struct Model {
    restart_active: bool,
    state: u8,
    ack: bool,
    restart: bool,
    restart_invalid: bool,
    aux: (u8, u8, u8),
    diag: u16,
}

impl Model {
    fn evaluate(
        &mut self,
        enable: bool,
        restart_fall: bool,
        restart: bool,
        ref_ok: bool,
        check_ok: bool,
    ) {
        let over = ref_ok && !check_ok;
        let mut next = if !enable {
            SL_STATE_SAFE
        } else if self.state == WFR || self.state == SL_STATE_START {
            if self.state == SL_STATE_START && restart_fall {
                SL_STATE_RUN
            } else if restart {
                SL_STATE_START
            } else {
                WFR
            }
        } else {
            SL_STATE_RUN
        };
        if next == SL_STATE_RUN && over && self.restart_active {
            next = WFR;
        }
        self.state = next;
        self.aux = if next == SL_STATE_RUN {
            (
                u8::from(ref_ok && check_ok),
                u8::from(!ref_ok),
                u8::from(over),
            )
        } else {
            (0, 0, 0)
        };
    }

    #[allow(clippy::too_many_arguments)]
    fn call(
        &mut self,
        run: bool,
        ack: bool,
        enable: bool,
        restart: bool,
        sdfb: bool,
        instance: u8,
        ref_ok: bool,
        check_ok: bool,
    ) {
        let (rise, fall) = (ack && !self.ack, !ack && self.ack);
        // An invalid Restart byte reads FALSE and makes no edge (restart_invalid).
        let restart_fall = !restart && self.restart && !self.restart_invalid;
        self.ack = ack;
        self.restart = restart;
        let eval = |m: &mut Model| {
            if sdfb {
                m.state = SL_STATE_ERROR;
                m.diag = if (1..=4).contains(&instance) {
                    u16::from(instance)
                } else {
                    0
                };
            } else {
                m.evaluate(enable, restart_fall, restart, ref_ok, check_ok);
            }
        };
        match self.state {
            SL_STATE_STOP => {
                if run {
                    eval(self);
                }
            }
            SL_STATE_ERROR => {
                if rise && !sdfb {
                    self.state = SL_STATE_RESET;
                    self.diag = 0;
                }
            }
            SL_STATE_RESET => {
                if fall {
                    if run {
                        eval(self);
                    } else {
                        self.state = SL_STATE_STOP;
                    }
                }
            }
            _ => {
                if run {
                    eval(self);
                } else {
                    self.state = SL_STATE_STOP;
                }
            }
        }
    }

    fn shown(&self) -> (u8, (u8, u8, u8, u8), u16, u16) {
        let err = self.state == SL_STATE_ERROR;
        let o = match self.state {
            SL_STATE_RUN => (0, self.aux.0, self.aux.1, self.aux.2),
            SL_STATE_START => (0, 0, 0, 1),
            s if s == WFR => (0, 0, 0, 1),
            SL_STATE_ERROR => (1, 0, 0, 0),
            _ => (0, 0, 0, 0),
        };
        (
            self.state,
            o,
            if err { self.diag } else { 0 },
            if err { 0x38D1 } else { 0 },
        )
    }
}

/// ≥ 10,000 random sequences against the model; every state is reached.
#[test]
fn random_sequences_match_the_model() {
    let mut rng = Rng(0x0AD5_050B);
    let mut reached = std::collections::BTreeSet::new();
    let mut invalid_calls = 0u32;
    for seq in 0..12_000 {
        let restart_active = seq % 2 == 0;
        let mut fb = make(ENABLE | if restart_active { RESTART } else { 0 });
        assert_eq!(fb.init(), SL_OK);
        let mut model = Model {
            restart_active,
            state: SL_STATE_STOP,
            ack: false,
            restart: false,
            restart_invalid: false,
            aux: (0, 0, 0),
            diag: 0,
        };
        for step in 0..24u32 {
            let r = rng.next();
            let bit = |k: u32, n: u64| (r >> k) % n == 0;
            let (run, ack, enable, restart) = (!bit(0, 20), bit(5, 3), !bit(10, 5), bit(15, 2));
            let (sdfb, ref_ok, check_ok) = (bit(20, 12), !bit(25, 4), !bit(30, 3));
            let instance = ((r >> 35) % 6) as u8;
            let mut raw = [enable, restart, sdfb, ref_ok, check_ok].map(u8::from);
            // One call in 25 has an invalid byte in one BOOL input: Enable, Restart,
            // POS_REF_OK, POS_CHECK_OK read FALSE, SDFB_ERROR reads TRUE.
            let invalid = bit(40, 25).then_some(((r >> 45) % 5) as usize);
            let (mut enable, mut restart, mut sdfb, mut ref_ok, mut check_ok) =
                (enable, restart, sdfb, ref_ok, check_ok);
            if let Some(i) = invalid {
                raw[i] = 2 + (r >> 50) as u8 % 254;
                match i {
                    0 => enable = false,
                    1 => restart = false,
                    2 => sdfb = true,
                    3 => ref_ok = false,
                    _ => check_ok = false,
                }
                invalid_calls += 1;
            }
            model.restart_invalid = invalid == Some(1);
            set(&mut fb, raw[0], raw[1], raw[2], raw[3], raw[4]);
            fb.nSdfbInstance = instance;
            fb.bRun = u8::from(run);
            fb.bErrAck = u8::from(ack);
            let rc = if invalid.is_some() {
                SL_E_INVALID_BOOL
            } else {
                SL_OK
            };
            assert_eq!(fb.cycle(step), rc);
            model.call(run, ack, enable, restart, sdfb, instance, ref_ok, check_ok);
            assert_eq!(
                (fb.nState, outs(&fb), fb.nDiag, fb.nDiagTextId),
                model.shown(),
                "sequence {seq} step {step}"
            );
            reached.insert(fb.nState);
        }
    }
    for s in CORE_STATES.into_iter().chain([SL_STATE_START, WFR]) {
        assert!(reached.contains(&s), "never reached {s}: {reached:?}");
    }
    assert!(
        invalid_calls > 5_000,
        "{invalid_calls} calls with an invalid byte"
    );
}
