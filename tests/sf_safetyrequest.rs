//! SF_SafetyRequest (PLCopen TC5 Part 1; research `plcopen_safety.md` §4.14, §5): every
//! transition of §4.14's table in first-match order (with v2.01's static-reset check and
//! S_StartReset in INIT), every DiagCode in both profiles, MonitoringTime at its limit
//! (T − 1 ms, T ms, T#0, across the clock wrap), the static-reset errors, Activate FALSE
//! from every state, start-up with and without S_StartReset, the two safety outputs per
//! state, the constants, the texts, a group with a link, and 10,000 random sequences per
//! profile against an independent model with every state reached. Expected codes are the
//! research table's, never read back.

mod common;
use common::cgroup::*;
use common::plcopen::*;
use common::*;
use safelogic::*;
use std::collections::BTreeSet;

// (v2.01, v1.0) codes of §4.14's DiagCode table (ERR_RESET_1's v1.0 code C001: QR2).
codes! {
    IDLE = 0x0000 / 0x0000, INIT = 0x8401 / 0x8001, SAFE = 0x8000 / 0x8000,
    OP = 0x8802 / 0x8002, CONF_OP = 0x8804 / 0x8012, CONF = 0x8002 / 0x8003,
    WAIT_OP = 0x8004 / 0x8005, ERR_RESET_1 = 0xC001 / 0xC001, ERR_ACK = 0xC010 / 0xC002,
    ERR_TIME = 0xC020 / 0xC003, ERR_RESET_2 = 0xC014 / 0xC004, ERR_RESET_3 = 0xC011 / 0xC005,
}

/// One call's inputs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct In {
    activate: bool,
    op_mode: bool,
    ack: bool,
    start_reset: bool,
    reset: bool,
}

const ON: In = In {
    activate: true,
    op_mode: false,
    ack: false,
    start_reset: false,
    reset: false,
};

/// The independent model: §4.14's table with the v1.0 codes, written from the research
/// text, plus v2.01's INIT rows (S_StartReset, static Reset → the v1.0 code C001 we chose).
#[derive(Default)]
struct Model {
    state: u16,
    reset_prev: bool,
    since: u32,
}

impl Model {
    fn step(&mut self, i: In, now: u32, t: u32) -> u16 {
        let (rt, stat) = edges(&mut self.reset_prev, i.reset);
        let q = now.wrapping_sub(self.since) >= t;
        let next = if !i.activate {
            0
        } else {
            match self.state {
                0x0000 => 0x8001,
                0x8001 if i.start_reset && !i.ack => 0x8002,
                0x8001 if i.start_reset => 0x8012,
                0x8001 if stat => 0xC001,
                0x8001 if rt && !i.ack => 0x8002,
                0x8001 if rt && i.ack => 0x8012,
                0xC001 if !i.reset => 0x8001,
                0x8002 if !i.op_mode => 0x8003,
                0x8002 if i.ack => 0x8012,
                0x8012 if !i.ack => 0x8002,
                0x8012 if !i.op_mode => 0x8003,
                0x8003 if q => 0xC003,
                0x8003 if i.op_mode => 0x8012,
                0x8003 if i.ack => 0x8000,
                0x8000 if !i.ack => 0xC002,
                0x8000 if i.op_mode => 0x8012,
                0xC002 if stat => 0xC004,
                0xC002 if rt => 0x8005,
                0xC003 if stat => 0xC005,
                0xC003 if rt => 0x8005,
                0xC004 if !i.reset => 0xC002,
                0xC005 if !i.reset => 0xC003,
                0x8005 if i.op_mode => 0x8012,
                s => s,
            }
        };
        common::plcopen::enter(&mut self.state, &mut self.since, next, now)
    }
}

struct Rig {
    fb: SF_SafetyRequest,
    now: u32,
    profile: u8,
}

impl Rig {
    fn new(profile: u8, t: u32) -> Self {
        let mut fb = SF_SafetyRequest {
            nDiagProfile: profile,
            MonitoringTime: t,
            ..Default::default()
        };
        // SAFETY: a live, exclusively borrowed instance.
        assert_eq!(
            unsafe { safelogic::ffi::sl_sf_safetyrequest_init(&mut fb) },
            SL_OK
        );
        Self {
            fb,
            now: 3_000,
            profile,
        }
    }
    fn at(&mut self, dt: u32, i: In) -> u16 {
        let f = &mut self.fb;
        f.Activate = i.activate.into();
        f.S_OpMode = i.op_mode.into();
        f.S_Acknowledge = i.ack.into();
        f.S_StartReset = i.start_reset.into();
        f.Reset = i.reset.into();
        self.now = self.now.wrapping_add(dt);
        // SAFETY: as above.
        let rc = unsafe { safelogic::ffi::sl_sf_safetyrequest_cycle(&mut self.fb, self.now) };
        assert_eq!(rc, SL_OK);
        self.fb.DiagCode
    }
    fn step(&mut self, i: In) -> u16 {
        self.at(1, i)
    }
    fn c(&self, s: Code) -> u16 {
        code(self.profile, s)
    }
    /// Ready, S_SafetyActive, S_SafetyRequest, SafetyDemand, ResetRequest, Error.
    fn outputs(&self) -> [u8; 6] {
        let f = &self.fb;
        [
            f.Ready,
            f.S_SafetyActive,
            f.S_SafetyRequest,
            f.SafetyDemand,
            f.ResetRequest,
            f.Error,
        ]
    }
    /// IDLE → `target` by the table's paths (MonitoringTime ≥ 10 ms), checking the codes on
    /// the way; returns the last inputs.
    fn reach(&mut self, target: Code) -> In {
        let mut i = ON;
        if target == ERR_RESET_1 {
            // Reset pressed in the activation call: held in INIT.
            i.reset = true;
            assert_eq!(self.step(i), self.c(INIT), "the activation call's edge");
            assert_eq!(self.step(i), self.c(ERR_RESET_1));
            return i;
        }
        assert_eq!(self.step(i), self.c(INIT));
        if target == INIT {
            return i;
        }
        // Reset edge with the actuator not acknowledging, the operation mode requested.
        i.op_mode = true;
        i.reset = true;
        assert_eq!(self.step(i), self.c(OP));
        i.reset = false;
        if target == OP {
            return i;
        }
        if target == CONF_OP {
            i.ack = true;
            assert_eq!(self.step(i), self.c(CONF_OP));
            return i;
        }
        i.op_mode = false;
        assert_eq!(self.step(i), self.c(CONF));
        match target {
            CONF => i,
            ERR_TIME | ERR_RESET_3 => {
                assert_eq!(self.at(1_000_000, i), self.c(ERR_TIME));
                if target == ERR_RESET_3 {
                    i.reset = true;
                    assert_eq!(self.step(i), self.c(WAIT_OP));
                    i.reset = false;
                    i.op_mode = true;
                    i.ack = true;
                    assert_eq!(self.step(i), self.c(CONF_OP));
                    i.op_mode = false;
                    assert_eq!(self.step(i), self.c(CONF));
                    i.ack = false;
                    i.reset = true;
                    assert_eq!(self.step(i), self.c(CONF));
                    assert_eq!(self.at(1_000_000, i), self.c(ERR_TIME));
                    assert_eq!(self.step(i), self.c(ERR_RESET_3));
                }
                i
            }
            _ => {
                i.ack = true;
                assert_eq!(self.step(i), self.c(SAFE));
                match target {
                    SAFE => i,
                    ERR_ACK | WAIT_OP => {
                        i.ack = false;
                        assert_eq!(self.step(i), self.c(ERR_ACK));
                        if target == WAIT_OP {
                            i.reset = true;
                            assert_eq!(self.step(i), self.c(WAIT_OP));
                        }
                        i
                    }
                    ERR_RESET_2 => {
                        i.reset = true;
                        assert_eq!(self.step(i), self.c(SAFE));
                        i.ack = false;
                        assert_eq!(self.step(i), self.c(ERR_ACK));
                        assert_eq!(self.step(i), self.c(ERR_RESET_2));
                        i
                    }
                    other => panic!("no path to {other:X?}"),
                }
            }
        }
    }
}

#[test]
fn every_transition_in_first_match_order() {
    for p in profiles() {
        let r = |t| {
            let mut rig = Rig::new(p, 100);
            let i = rig.reach(t);
            (rig, i)
        };
        // INIT: S_StartReset first (before a static Reset), by S_Acknowledge.
        let mut rig = Rig::new(p, 100);
        let held = In { reset: true, ..ON };
        assert_eq!(rig.step(held), rig.c(INIT));
        let auto = In {
            start_reset: true,
            ack: true,
            ..held
        };
        assert_eq!(
            rig.step(auto),
            rig.c(CONF_OP),
            "S_StartReset before the static Reset"
        );
        #[rustfmt::skip]
        let cases: &[Case<In>] = &[
            (INIT, &[(|i| i.start_reset = true, OP, "")]),
            (INIT, &[(|i| (i.start_reset, i.ack) = (true, true), CONF_OP, "")]),
            (INIT, &[(|i| i.reset = true, OP, "")]),
        ];
        step_table(&format!("profile {p}"), cases, r, |rig, i, want| {
            (rig.step(i), rig.c(want))
        });
        // INIT: static Reset → C001; RT(Reset) by S_Acknowledge; nothing else leaves INIT.
        let (mut rig, mut i) = r(INIT);
        i.op_mode = true;
        i.ack = true;
        assert_eq!(rig.at(1_000_000, i), rig.c(INIT));
        i.reset = true;
        assert_eq!(rig.step(i), rig.c(CONF_OP));
        #[rustfmt::skip]
        let cases: &[Case<In>] = &[
            (ERR_RESET_1, &[
                (|i| i.ack = true, ERR_RESET_1, ""),
                (|i| i.reset = false, INIT, ""),
                (|i| i.reset = true, CONF_OP, ""),
            ]),
            // OP_MODE: NOT S_OpMode before S_Acknowledge.
            (OP, &[(|i| (i.op_mode, i.ack) = (false, true), CONF, "NOT S_OpMode first")]),
        ];
        step_table(&format!("profile {p}"), cases, r, |rig, i, want| {
            (rig.step(i), rig.c(want))
        });
        let (mut rig, mut i) = r(OP);
        i.reset = true;
        assert_eq!(
            rig.at(1_000_000, i),
            rig.c(OP),
            "no time limit, Reset ignored"
        );
        i.ack = true;
        assert_eq!(rig.step(i), rig.c(CONF_OP));
        // WAIT_FOR_CONF_OPMODE: NOT S_Acknowledge before NOT S_OpMode.
        let (mut rig, mut i) = r(CONF_OP);
        i.ack = false;
        i.op_mode = false;
        assert_eq!(rig.step(i), rig.c(OP), "NOT S_Acknowledge first");
        let (mut rig, mut i) = r(CONF_OP);
        i.op_mode = false;
        assert_eq!(rig.step(i), rig.c(CONF));
        assert_eq!(rig.fb.S_SafetyRequest, 0, "the safe state requested");
        // WAIT_FOR_CONF: the time first (T since the entry), then S_OpMode, then S_Acknowledge.
        for (op, ack) in [(true, true), (false, true), (false, false)] {
            let (mut rig, mut i) = r(CONF);
            i.op_mode = op;
            i.ack = ack;
            assert_eq!(rig.at(100, i), rig.c(ERR_TIME), "time first ({op}, {ack})");
        }
        let (mut rig, i) = r(CONF);
        assert_eq!(rig.at(99, i), rig.c(CONF), "99 ms < 100 ms");
        assert_eq!(rig.at(1, i), rig.c(ERR_TIME), "100 ms");
        let (mut rig, mut i) = r(CONF);
        i.op_mode = true;
        i.ack = true;
        assert_eq!(
            rig.at(99, i),
            rig.c(CONF_OP),
            "S_OpMode before S_Acknowledge"
        );
        let (mut rig, mut i) = r(CONF);
        i.ack = true;
        assert_eq!(rig.at(99, i), rig.c(SAFE));
        // SAFE_MODE: NOT S_Acknowledge (an error) before S_OpMode; no time limit.
        let (mut rig, mut i) = r(SAFE);
        assert_eq!(rig.at(1_000_000, i), rig.c(SAFE));
        i.ack = false;
        i.op_mode = true;
        assert_eq!(rig.step(i), rig.c(ERR_ACK), "NOT S_Acknowledge first");
        let (mut rig, mut i) = r(SAFE);
        i.op_mode = true;
        assert_eq!(rig.step(i), rig.c(CONF_OP));
        // ERR_ACK_LOST / ERR_MONTIME: static Reset → C014 / C011; RT(Reset) → 8004; the
        // inputs alone change nothing.
        for (e, stat) in [(ERR_ACK, ERR_RESET_2), (ERR_TIME, ERR_RESET_3)] {
            let (mut rig, mut i) = r(e);
            i.op_mode = true;
            i.ack = true;
            assert_eq!(rig.at(1_000_000, i), rig.c(e));
            i.reset = true;
            assert_eq!(rig.step(i), rig.c(WAIT_OP));
            let (mut rig, mut i) = r(stat);
            i.op_mode = true;
            assert_eq!(rig.step(i), rig.c(stat), "stays while Reset is TRUE");
            i.reset = false;
            assert_eq!(rig.step(i), rig.c(e));
            i.reset = true;
            assert_eq!(rig.step(i), rig.c(WAIT_OP));
        }
        // WAIT_FOR_OPMODE: only S_OpMode leaves it (S_Acknowledge, Reset do not).
        let (mut rig, mut i) = r(WAIT_OP);
        i.ack = true;
        i.reset = false;
        assert_eq!(rig.step(i), rig.c(WAIT_OP));
        i.reset = true;
        assert_eq!(rig.step(i), rig.c(WAIT_OP));
        i.op_mode = true;
        assert_eq!(rig.step(i), rig.c(CONF_OP));
    }
}

/// Outputs of every state: S_SafetyActive only in SAFE_MODE, S_SafetyRequest only in OP_MODE
/// and WAIT_FOR_CONF_OPMODE, SafetyDemand / ResetRequest from the v2.01 bits; then Activate
/// FALSE from the state: 0000, every output FALSE.
#[test]
fn outputs_per_state_and_activate_false_from_every_state() {
    let expect = |s: Code| -> [u8; 6] {
        match s {
            INIT => [1, 0, 0, 0, 1, 0],
            SAFE => [1, 1, 0, 0, 0, 0],
            OP | CONF_OP => [1, 0, 1, 1, 0, 0],
            CONF | WAIT_OP => [1, 0, 0, 0, 0, 0],
            ERR_RESET_1 | ERR_ACK | ERR_TIME | ERR_RESET_2 | ERR_RESET_3 => [1, 0, 0, 0, 0, 1],
            _ => [0; 6],
        }
    };
    for p in profiles() {
        for s in ALL.into_iter().filter(|s| *s != IDLE) {
            let mut rig = Rig::new(p, 100);
            let mut i = rig.reach(s);
            let mut want = expect(s);
            if i.reset {
                want[4] = 0;
            }
            assert_eq!(rig.outputs(), want, "{s:X?} profile {p}");
            assert_eq!(rig.fb.DiagCode, rig.c(s));
            i.activate = false;
            assert_eq!(rig.step(i), 0);
            assert_eq!(rig.outputs(), [0; 6], "{s:X?}");
            i.activate = true;
            assert_eq!(rig.step(i), rig.c(INIT));
        }
    }
}

/// Start-up: without S_StartReset a Reset edge is needed (ResetRequest meanwhile); with it
/// the block goes on by S_Acknowledge in the second call; a Reset held through the
/// activation is C001.
#[test]
fn start_up_with_and_without_s_start_reset() {
    let mut rig = Rig::new(0, 100);
    let mut i = In { ack: true, ..ON };
    assert_eq!(rig.step(i), 0x8401);
    assert_eq!(rig.fb.ResetRequest, 1);
    assert_eq!(rig.at(5_000, i), 0x8401);
    i.reset = true;
    assert_eq!(rig.step(i), 0x8804);
    assert_eq!(rig.fb.S_SafetyRequest, 1);
    i.op_mode = false;
    assert_eq!(rig.step(i), 0x8002);
    assert_eq!(rig.step(i), 0x8000);
    assert_eq!((rig.fb.S_SafetyActive, rig.fb.S_SafetyRequest), (1, 0));

    let mut rig = Rig::new(0, 100);
    let auto = In {
        start_reset: true,
        ..ON
    };
    assert_eq!(rig.step(auto), 0x8401);
    assert_eq!(rig.step(auto), 0x8802);

    let held = In { reset: true, ..ON };
    let mut rig = Rig::new(1, 100);
    assert_eq!(
        rig.step(In {
            activate: false,
            ..held
        }),
        0
    );
    assert_eq!(rig.step(held), 0x8001);
    assert_eq!(rig.step(held), 0xC001);
    assert_eq!(rig.fb.Error, 1);
}

/// MonitoringTime T#0: the error at the first evaluation of WAIT_FOR_CONF (semantics QR4);
/// the time across the clock wrap; the time is a constant.
#[test]
fn the_monitoring_time() {
    let mut rig = Rig::new(0, 0);
    let mut i = rig.reach(OP);
    i.op_mode = false;
    i.ack = true;
    assert_eq!(rig.step(i), 0x8002);
    assert_eq!(rig.at(0, i), 0xC020, "T#0: the first evaluation, same ms");

    let mut rig = Rig::new(0, 100);
    rig.now = u32::MAX - 30;
    let mut i = rig.reach(OP);
    i.op_mode = false;
    assert_eq!(rig.step(i), 0x8002);
    assert_eq!(rig.at(99, i), 0x8002);
    assert!(rig.now < 100, "wrapped");
    assert_eq!(rig.at(1, i), 0xC020);

    let mut fb = SF_SafetyRequest {
        MonitoringTime: 100,
        Activate: 1,
        ..Default::default()
    };
    assert_eq!(fb.cycle(0), SL_OK);
    fb.MonitoringTime = 101;
    assert_eq!(fb.cycle(1), SL_E_PARAM_CHANGED);
    assert_eq!((fb.DiagCode, fb.Error), (SL_SF_DIAG_CONST_CHANGED, 1));
    let bad = common::refused(
        SF_SafetyRequest {
            MonitoringTime: SL_SF_TIME_MAX + 1,
            Activate: 1,
            ..Default::default()
        },
        &[0],
    );
    assert_eq!((bad.DiagCode, bad.S_SafetyRequest), (SL_SF_DIAG_CONFIG, 0));
    // An invalid S_Acknowledge byte reads FALSE: the acknowledgement is lost.
    let mut rig = Rig::new(0, 100);
    rig.reach(SAFE);
    rig.fb.S_Acknowledge = 9;
    rig.now += 1;
    assert_eq!(rig.fb.cycle(rig.now), SL_E_INVALID_BOOL);
    assert_eq!((rig.fb.DiagCode, rig.fb.S_SafetyActive), (0xC010, 0));
}

/// sl_diag_text names every code of both profiles; a code both profiles use for different
/// states (8002: v2.01 WAIT_FOR_CONF, v1.0 OP_MODE; 8004: v2.01 WAIT_FOR_OPMODE, v1.0
/// unused) reads as the v2.01 state's (semantics QR6).
#[test]
fn texts_for_every_diag_code() {
    let text = |code: u16| diag_text(SL_TYPE_SF_SAFETYREQUEST, code);
    let mut seen = BTreeSet::new();
    for (v2, v1) in ALL {
        let t = text(v2);
        assert!(!t.is_empty() && t != "unknown DiagCode", "{v2:04X}");
        seen.insert(t.clone());
        if !ALL.iter().any(|s| s.0 == v1) {
            assert_eq!(text(v1), t, "v1.0 {v1:04X}");
        }
    }
    assert_eq!(seen.len(), ALL.len());
    assert!(text(0x8002).contains("waiting for S_Acknowledge"));
    assert!(text(0xC014).contains("ERR_ACK_LOST"));
    assert!(text(0xC011).contains("ERR_MONTIME"));
    assert_eq!(text(0x8123), "unknown DiagCode");
}

#[test]
fn random_sequences_agree_with_the_model() {
    let walk = Walk::new("SF_SafetyRequest", 0x5F18, ALL.iter().map(|s| s.1));
    walk.run(
        |p, _, rng| {
            let t = [0, 5, 20, 50][(rng.next() % 4) as usize];
            let rig = Rig::new(p, t);
            (t, rig, Model::default(), rates::<5>(rng), In::default())
        },
        |(t, rig, model, rates, i), p, rng| {
            let f = flips(rng, rates, &mut i.activate);
            i.op_mode ^= f[1];
            i.ack ^= f[2];
            i.start_reset ^= f[3] && rng.next() % 3 == 0;
            i.reset ^= f[4];
            let dt = (rng.next() % 12) as u32;
            let got = rig.at(dt, *i);
            let v1 = model.step(*i, rig.now, *t);
            let want = ALL.iter().find(|s| s.1 == v1).map(|s| rig.c(*s)).unwrap();
            assert_eq!(got, want, "profile {p} t {t}: {i:?}");
            let o = rig.outputs();
            assert_eq!(o[0] == 1, got != 0);
            assert_eq!(o[1] == 1, got == 0x8000);
            assert_eq!(o[2] == 1, v1 == 0x8002 || v1 == 0x8012);
            assert_eq!(o[5] == 1, got >= 0xC000);
            assert!(o[1] == 0 || i.ack, "S_SafetyActive without S_Acknowledge");
            v1
        },
    );
}

/// SF_SafetyRequest in a group: S_SafetyActive linked to an FB_AND; an acknowledgement
/// lost (C010) does not stop the group; group STOP halts it.
#[test]
fn in_a_group_with_a_link() {
    let mut w = WithAnd::of(
        SF_SafetyRequest {
            MonitoringTime: 100,
            ..Default::default()
        },
        "S_SafetyActive",
    );
    w.fb.Activate = 1;
    w.fb.S_StartReset = 1;
    w.fb.S_Acknowledge = 1;
    w.run(4);
    w.expect(0x8000, 1);
    w.fb.S_Acknowledge = 0;
    w.grp.cycle(10);
    w.expect_group(0xC010, 0, SL_STATE_RUN);
    w.stop_group();
}
