//! SF_ResetButton (PLCopen TC5 Part 1 v2.x; research `plcopen_safety.md` §4.19, §5):
//! every transition of the table in first-match order, the trailing times at their limits
//! (TrailingMinimum − 1 ms invalid, TrailingMinimum valid, TrailingMaximum − 1 ms valid,
//! TrailingMaximum invalid), ERR_PARAM at activation, the static ResetIn, ResetRequested
//! FALSE from every state, the v1.0 profile refused, library faults, texts, the block in a
//! group with ResetOut linked to an SF_EmergencyStop's Reset, and 10,000 random sequences
//! against an independent model. Expected codes are the research table's (CS-LIB FBS_RESBUT).

mod common;
use common::cgroup::*;
use common::plcopen::{edges, Walk};

use common::*;
use safelogic::*;
use std::collections::BTreeSet;

const IDLE: u16 = 0x0000;
const WAIT_R: u16 = 0x83E2;
const WAIT_F: u16 = 0x83F2;
const DETECTED: u16 = 0x8000;
const ERR_PARAM: u16 = 0xC000;
const ERR_RESET: u16 = 0xC001;
const ERR_MAX: u16 = 0xC3E0;
const ERR_MIN: u16 = 0xC3F0;
const ALL: [u16; 8] = [
    IDLE, WAIT_R, WAIT_F, DETECTED, ERR_PARAM, ERR_RESET, ERR_MAX, ERR_MIN,
];

struct Rig {
    fb: SF_ResetButton,
    now: u32,
}

impl Rig {
    /// TrailingMinimum 350 ms, TrailingMaximum 2 s (the PLCopen defaults) unless given.
    fn new(min: u32, max: u32) -> Self {
        let fb = common::ready(SF_ResetButton {
            TrailingMinimum: min,
            TrailingMaximum: max,
            ..Default::default()
        });
        Self { fb, now: 70_000 }
    }
    fn at(&mut self, dt: u32, requested: bool, button: bool) -> u16 {
        self.fb.ResetRequested = requested.into();
        self.fb.ResetIn = button.into();
        self.now = self.now.wrapping_add(dt);
        assert_eq!(self.fb.cycle(self.now), SL_OK);
        self.check();
        self.fb.DiagCode
    }
    fn press(&mut self, dt: u32, button: bool) -> u16 {
        self.at(dt, true, button)
    }
    /// The outputs from the code (research §3.2, §4.19).
    fn check(&self) {
        let c = self.fb.DiagCode;
        assert_eq!(self.fb.Ready, u8::from(c != 0));
        assert_eq!(self.fb.ResetOut, u8::from(c == DETECTED));
        assert_eq!(self.fb.Error, u8::from(c >= 0xC000));
    }
    /// Activation → 83E2, then the paths of the table to `target`.
    fn reach(&mut self, target: u16) {
        if target == ERR_RESET {
            // Only a ResetIn held across the activation is static in 83E2 (the activating
            // call is IDLE → 83E2 alone).
            assert_eq!(self.at(10, false, true), IDLE);
            assert_eq!(self.press(10, true), WAIT_R);
            assert_eq!(self.press(10, true), ERR_RESET);
            return;
        }
        assert_eq!(self.press(10, false), WAIT_R, "activation");
        match target {
            WAIT_R => {}
            WAIT_F => assert_eq!(self.press(10, true), WAIT_F),
            DETECTED => {
                assert_eq!(self.press(10, true), WAIT_F);
                assert_eq!(self.press(500, false), DETECTED);
            }
            ERR_MAX => {
                assert_eq!(self.press(10, true), WAIT_F);
                assert_eq!(self.press(2_000, true), ERR_MAX);
            }
            ERR_MIN => {
                assert_eq!(self.press(10, true), WAIT_F);
                assert_eq!(self.press(100, false), ERR_MIN);
            }
            other => panic!("{other:04X}"),
        }
    }
}

#[test]
fn every_transition_in_first_match_order() {
    // 83E2: static ResetIn first (held across the activation), then the rising edge.
    let mut r = Rig::new(350, 2_000);
    assert_eq!(
        r.press(10, true),
        WAIT_R,
        "the activating call: IDLE → 83E2 only"
    );
    assert_eq!(
        r.press(10, true),
        ERR_RESET,
        "ResetIn held since the activation"
    );
    assert_eq!(r.press(10, true), ERR_RESET, "stays while TRUE");
    assert_eq!(r.press(10, false), WAIT_R, "C001 → 83E2 on ResetIn FALSE");
    assert_eq!(r.press(10, false), WAIT_R);
    assert_eq!(r.press(10, true), WAIT_F, "rising edge");
    assert_eq!(r.fb.ResetOut, 0);
    // 83F2: TrailingMaximum first (even released in that call), then too short, then valid.
    let mut r = Rig::new(350, 2_000);
    r.reach(WAIT_F);
    assert_eq!(r.press(1_999, true), WAIT_F);
    assert_eq!(
        r.press(1, false),
        ERR_MAX,
        "2000 ms: max before the falling edge"
    );
    let mut r = Rig::new(350, 2_000);
    r.reach(WAIT_F);
    assert_eq!(r.press(2_000, true), ERR_MAX);
    assert_eq!(r.press(100, true), ERR_MAX, "still held: waits");
    assert_eq!(
        r.press(100, false),
        ERR_MAX,
        "released: waits for a rising edge"
    );
    assert_eq!(r.press(100, true), WAIT_F, "a new press");
    assert_eq!(r.press(400, false), DETECTED);
    let mut r = Rig::new(350, 2_000);
    r.reach(WAIT_F);
    assert_eq!(r.press(349, false), ERR_MIN, "349 ms < TrailingMinimum");
    assert_eq!(r.press(100, false), ERR_MIN);
    assert_eq!(r.press(100, true), WAIT_F, "a new press");
    assert_eq!(r.press(350, false), DETECTED, "350 ms");
    let mut r = Rig::new(350, 2_000);
    r.reach(WAIT_F);
    assert_eq!(r.press(1_999, false), DETECTED, "1999 ms < TrailingMaximum");
    // 8000: one call, then 83E2 — or straight into 83F2 on a new rising edge.
    assert_eq!(r.fb.ResetOut, 1);
    assert_eq!(r.press(1, false), WAIT_R);
    assert_eq!(r.fb.ResetOut, 0);
    let mut r = Rig::new(350, 2_000);
    r.reach(DETECTED);
    assert_eq!(r.press(10, true), WAIT_F, "pressed again in the next call");
    // Errors are left only by their own exits.
    for e in [ERR_MAX, ERR_MIN] {
        let mut r = Rig::new(350, 2_000);
        r.reach(e);
        assert_eq!(r.press(10_000, false), e, "no time limit");
    }
    let mut r = Rig::new(350, 2_000);
    r.reach(ERR_RESET);
    assert_eq!(r.press(10, false), WAIT_R);
}

/// ERR_PARAM in the activating call: TrailingMinimum < 100 ms or > TrailingMaximum; it is
/// left only through ResetRequested FALSE (the times are constants).
#[test]
fn err_param_at_activation() {
    for (min, max, want) in [
        (99, 2_000, ERR_PARAM),
        (100, 2_000, WAIT_R),
        (0, 0, ERR_PARAM),
        (351, 350, ERR_PARAM),
        (350, 350, WAIT_R),
        (100, 100, WAIT_R),
    ] {
        let mut r = Rig::new(min, max);
        assert_eq!(r.press(10, false), want, "{min} {max}");
        if want == ERR_PARAM {
            for b in [true, false, true] {
                assert_eq!(r.press(5_000, b), ERR_PARAM);
            }
            assert_eq!(r.at(10, false, false), IDLE);
        }
    }
    // TrailingMinimum == TrailingMaximum: every press is too short or too long.
    let mut r = Rig::new(100, 100);
    r.reach(WAIT_F);
    assert_eq!(r.press(99, false), ERR_MIN);
    r.press(10, true);
    assert_eq!(r.press(100, false), ERR_MAX);
    // A time above SL_SF_TIME_MAX is the library's C3FC.
    let mut fb = SF_ResetButton {
        ResetRequested: 1,
        TrailingMinimum: 350,
        TrailingMaximum: SL_SF_TIME_MAX + 1,
        ..Default::default()
    };
    assert_eq!(fb.cycle(0), SL_E_CONFIG);
    assert_eq!(
        (fb.DiagCode, fb.Error, fb.ResetOut),
        (SL_SF_DIAG_CONFIG, 1, 0)
    );
}

#[test]
fn reset_requested_false_is_idle_from_every_state() {
    for s in ALL.into_iter().filter(|s| *s != IDLE && *s != ERR_PARAM) {
        for b in [false, true] {
            let mut r = Rig::new(350, 2_000);
            r.reach(s);
            assert_eq!(r.at(1, false, b), IDLE, "{s:04X}");
            assert_eq!(
                (r.fb.Ready, r.fb.ResetOut, r.fb.Error),
                (0, 0, 0),
                "{s:04X}"
            );
        }
    }
    let mut r = Rig::new(10, 2_000);
    assert_eq!(r.press(1, false), ERR_PARAM);
    assert_eq!(r.at(1, false, false), IDLE);
    // A valid press with ResetRequested FALSE gives nothing.
    let mut r = Rig::new(350, 2_000);
    r.at(1, false, true);
    assert_eq!(r.at(400, false, false), IDLE);
    assert_eq!(r.fb.ResetOut, 0);
}

/// The trailing times are constants (C3FD when changed while activated) and v2.x only.
#[test]
fn constants_profile_and_library_faults() {
    let mut r = Rig::new(350, 2_000);
    r.reach(WAIT_R);
    r.fb.TrailingMaximum = 3_000;
    r.now += 1;
    assert_eq!(r.fb.cycle(r.now), SL_E_PARAM_CHANGED);
    assert_eq!((r.fb.DiagCode, r.fb.Error), (SL_SF_DIAG_CONST_CHANGED, 1));
    r.fb.ResetRequested = 0;
    r.fb.cycle(r.now + 1);
    assert_eq!(r.fb.DiagCode, 0);
    let fb = common::refused(
        SF_ResetButton {
            ResetRequested: 1,
            nDiagProfile: SL_SF_PROFILE_V10,
            TrailingMinimum: 350,
            TrailingMaximum: 2_000,
            ..Default::default()
        },
        &[0],
    );
    assert_eq!(fb.DiagCode, SL_SF_DIAG_CONFIG);
    // The clock going backwards; an invalid ResetIn byte reads FALSE.
    let mut r = Rig::new(350, 2_000);
    r.reach(WAIT_F);
    r.fb.ResetIn = 7;
    r.now += 400;
    assert_eq!(r.fb.cycle(r.now), SL_E_INVALID_BOOL);
    assert_eq!(r.fb.DiagCode, DETECTED, "an invalid byte is a release");
    r.now -= 5;
    assert_eq!(r.fb.cycle(r.now), SL_E_CLOCK);
    assert_eq!((r.fb.DiagCode, r.fb.ResetOut), (SL_SF_DIAG_CLOCK, 0));
    // An invalid ResetRequested byte is not TRUE: idle.
    r.fb.ResetRequested = 2;
    assert_eq!(r.fb.cycle(r.now + 1), SL_E_INVALID_BOOL);
    assert_eq!(r.fb.DiagCode, 0);
    // SAFETY: NULL is the documented refusal.
    assert_eq!(
        unsafe { safelogic::ffi::sl_sf_resetbutton_cycle(std::ptr::null_mut(), 0) },
        SL_E_NULL
    );
}

#[test]
fn texts_for_every_diag_code() {
    let text = |code: u16| diag_text(SL_TYPE_SF_RESETBUTTON, code);
    let seen: BTreeSet<String> = ALL.iter().map(|c| text(*c)).collect();
    assert_eq!(seen.len(), ALL.len());
    assert!(!seen.contains("unknown DiagCode"));
    assert_eq!(
        text(0x8001),
        "unknown DiagCode",
        "not the SIL2 table's 8001"
    );
    assert!(text(SL_SF_DIAG_CORRUPT).starts_with("library: "));
}

/// SF_ResetButton in front of an SF_EmergencyStop, both in a group: the E-stop's
/// ResetRequest linked to ResetRequested, ResetOut to the E-stop's Reset. A valid press
/// resets the E-stop on its falling edge; a press held into the wait is no static-reset
/// error of the E-stop any more (that is the point of the block).
#[test]
fn in_a_group_in_front_of_an_emergency_stop() {
    let mut es = RawBox::new(SF_EmergencyStop {
        Activate: 1,
        S_EStopIn: 1,
        ..Default::default()
    });
    let mut rb = RawBox::new(SF_ResetButton {
        TrailingMinimum: 350,
        TrailingMaximum: 2_000,
        ..Default::default()
    });
    let mut grp = CGroup::new(2, 2);
    grp.add_estop(&es);
    grp.add_init(
        SL_TYPE_SF_RESETBUTTON,
        &rb,
        safelogic::ffi::sl_sf_resetbutton_init,
    );
    let (es_t, rb_t) = (SL_TYPE_SF_EMERGENCYSTOP, SL_TYPE_SF_RESETBUTTON);
    grp.link(
        0,
        field(es_t, "ResetRequest"),
        1,
        field(rb_t, "ResetRequested"),
    );
    grp.link(1, field(rb_t, "ResetOut"), 0, field(es_t, "Reset"));

    grp.g.bRun = 1;
    for k in 0..3 {
        assert_eq!(grp.cycle(10), SL_OK, "group call {k}");
    }
    assert_eq!((es.DiagCode, es.ResetRequest), (0x8402, 1));
    assert_eq!(rb.DiagCode, WAIT_R, "activated by ResetRequest");
    rb.ResetIn = 1;
    grp.cycle(10);
    grp.cycle(400);
    assert_eq!((rb.DiagCode, es.DiagCode), (WAIT_F, 0x8402));
    rb.ResetIn = 0;
    grp.cycle(10);
    assert_eq!((rb.DiagCode, rb.ResetOut), (DETECTED, 1));
    grp.cycle(10);
    assert_eq!((es.DiagCode, es.S_EStopOut), (0x8000, 1));
    assert_eq!(rb.DiagCode, IDLE, "no reset requested any more");
    // A press too short: no reset, ERR_TRAIL_MIN, the group runs on.
    es.S_EStopIn = 0;
    grp.cycle(10);
    es.S_EStopIn = 1;
    grp.cycle(10);
    grp.cycle(10);
    assert_eq!(es.DiagCode, 0x8404);
    rb.ResetIn = 1;
    grp.cycle(10);
    rb.ResetIn = 0;
    grp.cycle(50);
    assert_eq!((rb.DiagCode, es.DiagCode), (ERR_MIN, 0x8404));
    assert_eq!(grp.g.nState, SL_STATE_RUN);
}

/// The model, written from research §4.19's table: an R_TRIG of ResetIn called in every
/// call, the press timed from the rising edge.
#[derive(Default)]
struct Model {
    state: u16,
    prev: bool,
    since: u32,
}

impl Model {
    fn step(&mut self, req: bool, button: bool, now: u32, min: u32, max: u32) -> u16 {
        let (rt, _) = edges(&mut self.prev, button);
        let d = now.wrapping_sub(self.since);
        let next = if !req {
            IDLE
        } else {
            match self.state {
                IDLE if min < 100 || min > max => ERR_PARAM,
                IDLE => WAIT_R,
                WAIT_R if button && !rt => ERR_RESET,
                WAIT_R if rt => WAIT_F,
                WAIT_F if d >= max => ERR_MAX,
                WAIT_F if !button && d < min => ERR_MIN,
                WAIT_F if !button => DETECTED,
                DETECTED if rt => WAIT_F,
                DETECTED => WAIT_R,
                ERR_RESET if !button => WAIT_R,
                ERR_MAX | ERR_MIN if rt => WAIT_F,
                s => s,
            }
        };
        common::plcopen::enter(&mut self.state, &mut self.since, next, now)
    }
}

#[test]
fn random_sequences_agree_with_the_model() {
    // No diagnostic profile: one walk, from the seed itself (0 ^ seed).
    let walk = Walk {
        profiles: vec![0],
        ..Walk::new("SF_ResetButton", 0x5F52_B077, ALL)
    };
    walk.run(
        |_, _, rng| {
            let min = [90, 100, 120, 150][(rng.next() % 4) as usize];
            let max = [100, 200, 400][(rng.next() % 3) as usize];
            (min, max, Rig::new(min, max), Model::default(), true, false)
        },
        |(min, max, r, model, req, b), _, rng| {
            let x = rng.next();
            if x % 29 == 0 {
                *req = !*req;
            }
            *b ^= (x >> 8) % 3 == 0;
            let dt = ((x >> 16) % 80) as u32;
            let code = r.at(dt, *req, *b);
            let want = model.step(*req, *b, r.now, *min, *max);
            assert_eq!(code, want, "min {min} max {max}");
            want
        },
    );
}
