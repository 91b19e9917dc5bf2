//! SF_EDM (PLCopen TC5 Part 1; research `plcopen_safety.md` §4.10, §5, §8.3): every
//! transition in first-match order (NPE's split of the feedback guards), MonitoringTime at
//! its limit after switching off and on (T − 1 ms no error, T ms error; T#0 at the first
//! evaluation), the static-reset variants, every DiagCode in both profiles, Activate FALSE
//! from every state, start-up with and without S_StartReset, invalid feedback bytes, texts,
//! SF_EDM behind an SF_EmergencyStop in a group, and 10,000 random sequences per profile
//! against an independent model. Expected codes are research §4.10's (v2.01 CS-LIB FBS_EDM,
//! v1.0 B&R) and, where the research has none, semantics QD2's.

mod common;
use common::cgroup::*;
use common::plcopen::*;
use common::*;
use safelogic::*;
use std::collections::BTreeSet;

const IDLE: Code = (0x0000, 0x0000);
const INIT: Code = (0x8401, 0x8001);
const DISABLE: Code = (0x8810, 0x8010);
const ENABLE: Code = (0x8000, 0x8000);
const ERR_RESET_1: Code = (0xC001, 0xC001);
const ERR_INIT: Code = (0xC100, 0xC111);

/// The feedback errors C010 … C090 and their static-reset variants (same in both profiles).
fn edm_err(n: u16) -> Code {
    (0xC000 + 0x10 * n, 0xC000 + 0x10 * n)
}
fn edm_err_static(n: u16) -> Code {
    (0xC001 + 0x10 * n, 0xC001 + 0x10 * n)
}

fn all() -> Vec<Code> {
    let mut v = vec![IDLE, INIT, DISABLE, ENABLE, ERR_RESET_1, ERR_INIT];
    for n in 1..=9 {
        v.push(edm_err(n));
        v.push(edm_err_static(n));
    }
    v
}

#[derive(Clone, Copy, Debug, Default)]
struct In {
    activate: bool,
    control: bool,
    edm1: bool,
    edm2: bool,
    start_reset: bool,
    reset: bool,
}

/// Both contactors released, activated.
const REST: In = In {
    activate: true,
    control: false,
    edm1: true,
    edm2: true,
    start_reset: false,
    reset: false,
};

struct Rig {
    fb: SF_EDM,
    now: u32,
    profile: u8,
    i: In,
}

impl Rig {
    fn new(profile: u8, t: u32) -> Self {
        let fb = common::ready(SF_EDM {
            nDiagProfile: profile,
            MonitoringTime: t,
            ..Default::default()
        });
        Self {
            fb,
            now: 90_000,
            profile,
            i: REST,
        }
    }
    fn c(&self, s: Code) -> u16 {
        code(self.profile, s)
    }
    /// One call `dt` ms later with the inputs changed by `f`.
    fn at(&mut self, dt: u32, f: impl FnOnce(&mut In)) -> u16 {
        f(&mut self.i);
        let i = self.i;
        (
            self.fb.Activate,
            self.fb.S_OutControl,
            self.fb.EDM1,
            self.fb.EDM2,
            self.fb.S_StartReset,
            self.fb.Reset,
        ) = (
            i.activate.into(),
            i.control.into(),
            i.edm1.into(),
            i.edm2.into(),
            i.start_reset.into(),
            i.reset.into(),
        );
        self.now = self.now.wrapping_add(dt);
        assert_eq!(self.fb.cycle(self.now), SL_OK);
        self.fb.DiagCode
    }
    fn step(&mut self, f: impl FnOnce(&mut In)) -> u16 {
        self.at(1, f)
    }
    /// Activation and a Reset edge: 8810 (reset released again).
    fn go_disable(&mut self) {
        assert_eq!(self.step(|_| {}), self.c(INIT));
        assert_eq!(self.step(|i| i.reset = true), self.c(DISABLE));
        assert_eq!(self.step(|i| i.reset = false), self.c(DISABLE));
    }
    /// 8810 → 8000 with the contactors picking up in the same call (t ≥ 10).
    fn go_enable(&mut self) {
        self.go_disable();
        assert_eq!(self.step(|i| i.control = true), self.c(ENABLE));
        assert_eq!(
            self.step(|i| (i.edm1, i.edm2) = (false, false)),
            self.c(ENABLE)
        );
    }
    /// The path to `s` (t ≥ 10).
    fn reach(&mut self, s: Code) {
        let e = |n: u16| edm_err(n);
        match s {
            INIT => assert_eq!(self.step(|_| {}), self.c(INIT)),
            DISABLE => self.go_disable(),
            ENABLE => self.go_enable(),
            ERR_RESET_1 => {
                self.step(|i| i.reset = true);
                assert_eq!(self.step(|_| {}), self.c(ERR_RESET_1));
            }
            ERR_INIT => {
                assert_eq!(self.step(|_| {}), self.c(INIT));
                assert_eq!(
                    self.step(|i| (i.reset, i.control) = (true, true)),
                    self.c(ERR_INIT)
                );
            }
            _ => {
                // A feedback error: C0n0 (n = 1 … 9) or its static variant C0n1.
                let n = (s.0 - 0xC000) >> 4;
                let held = s.0 & 1 == 1;
                let which = (n - 1) % 3 + 1; // 1 EDM1, 2 EDM2, 3 both
                let stuck = |i: &mut In, v: bool| {
                    if which & 1 != 0 {
                        i.edm1 = v;
                    }
                    if which & 2 != 0 {
                        i.edm2 = v;
                    }
                };
                match n {
                    1..=3 => {
                        self.go_disable();
                        // Reset pressed before the error (no guard of 8810 / 8000 reads it).
                        self.step(|i| i.reset = held);
                        self.step(|i| stuck(i, false));
                        assert_eq!(self.step(|i| i.control = true), self.c(e(n)));
                    }
                    4..=6 => {
                        self.go_enable();
                        self.step(|i| i.reset = held);
                        assert_eq!(self.step(|i| i.control = false), self.c(DISABLE));
                        self.step(|i| (i.edm1, i.edm2) = (true, true));
                        self.step(|i| stuck(i, false));
                        assert_eq!(self.at(1_000_000, |_| {}), self.c(e(n)));
                    }
                    _ => {
                        self.go_disable();
                        self.step(|i| i.reset = held);
                        assert_eq!(self.step(|i| i.control = true), self.c(ENABLE));
                        self.step(|i| (i.edm1, i.edm2) = (false, false));
                        self.step(|i| stuck(i, true));
                        assert_eq!(self.at(1_000_000, |_| {}), self.c(e(n)));
                    }
                }
                if held {
                    assert_eq!(self.step(|_| {}), self.c(s), "Reset held into the error");
                }
            }
        }
    }
}

#[test]
fn every_transition_in_first_match_order() {
    for p in profiles() {
        let r = |s: Code| {
            let mut rig = Rig::new(p, 100);
            rig.reach(s);
            rig
        };
        // 8401: S_StartReset first (even with Reset held), then static Reset, then both edges
        // (C100), then the Reset edge; nothing else leaves it.
        let mut rig = r(INIT);
        assert_eq!(rig.step(|i| i.control = true), rig.c(INIT), "no Reset");
        assert_eq!(rig.at(10_000, |i| i.edm1 = false), rig.c(INIT));
        let mut rig = Rig::new(p, 100);
        rig.step(|i| (i.reset, i.start_reset) = (true, true));
        assert_eq!(rig.step(|_| {}), rig.c(DISABLE), "S_StartReset first");
        let mut rig = r(ERR_RESET_1);
        assert_eq!(rig.step(|_| {}), rig.c(ERR_RESET_1));
        assert_eq!(rig.step(|i| i.reset = false), rig.c(INIT));
        assert_eq!(rig.step(|i| i.reset = true), rig.c(DISABLE));
        let mut rig = r(ERR_INIT);
        assert_eq!(rig.step(|_| {}), rig.c(ERR_INIT), "held: no static error");
        assert_eq!(
            rig.step(|i| (i.reset, i.control) = (false, false)),
            rig.c(ERR_INIT)
        );
        assert_eq!(
            rig.step(|i| (i.reset, i.control) = (true, true)),
            rig.c(ERR_INIT),
            "both edges again"
        );
        rig.step(|i| i.reset = false);
        assert_eq!(
            rig.step(|i| i.reset = true),
            rig.c(DISABLE),
            "S_OutControl held"
        );
        let mut rig = r(INIT);
        rig.step(|i| i.control = true);
        assert_eq!(
            rig.step(|i| i.reset = true),
            rig.c(DISABLE),
            "S_OutControl TRUE without an edge"
        );
        // 8810: S_OutControl with feedback not released, split by loop (before the
        // elapsed time), then the elapsed time, then S_OutControl → 8000.
        for (which, n) in [((false, true), 1), ((true, false), 2), ((false, false), 3)] {
            let mut rig = r(DISABLE);
            rig.step(|i| (i.edm1, i.edm2) = which);
            assert_eq!(
                rig.at(1_000, |i| i.control = true),
                rig.c(edm_err(n)),
                "control first"
            );
            assert_eq!(rig.fb.S_EDM_Out, 0);
            // r(DISABLE) ends 1 ms after the entry into 8810.
            let mut rig = r(DISABLE);
            assert_eq!(rig.at(98, |i| (i.edm1, i.edm2) = which), rig.c(DISABLE));
            assert_eq!(rig.at(1, |_| {}), rig.c(edm_err(n + 3)), "100 ms");
        }
        let mut rig = r(DISABLE);
        assert_eq!(rig.at(10_000, |_| {}), rig.c(DISABLE), "released: no limit");
        assert_eq!(rig.step(|i| i.control = true), rig.c(ENABLE));
        assert_eq!(rig.fb.S_EDM_Out, 1);
        // 8000: NOT S_OutControl first, then the elapsed time with a loop not switched.
        let mut rig = r(DISABLE);
        rig.step(|i| i.control = true);
        assert_eq!(rig.at(99, |_| {}), rig.c(ENABLE), "99 ms, not switched yet");
        assert_eq!(
            rig.at(1, |i| i.control = false),
            rig.c(DISABLE),
            "switch-off first"
        );
        for (which, n) in [((true, false), 7), ((false, true), 8), ((true, true), 9)] {
            let mut rig = r(DISABLE);
            rig.step(|i| i.control = true);
            assert_eq!(rig.at(99, |i| (i.edm1, i.edm2) = which), rig.c(ENABLE));
            assert_eq!(rig.at(1, |_| {}), rig.c(edm_err(n)), "100 ms, {which:?}");
            assert_eq!(rig.fb.S_EDM_Out, 0);
        }
        // A contactor dropping out after the time: the same error.
        let mut rig = r(ENABLE);
        assert_eq!(rig.at(5_000, |_| {}), rig.c(ENABLE));
        assert_eq!(rig.step(|i| i.edm2 = true), rig.c(edm_err(8)));
        // 8000 → 8810 restarts the time; 8810 → 8000 again.
        let mut rig = r(ENABLE);
        assert_eq!(rig.at(500, |i| i.control = false), rig.c(DISABLE));
        assert_eq!(
            rig.at(99, |_| {}),
            rig.c(DISABLE),
            "99 ms since the switch-off"
        );
        assert_eq!(rig.at(1, |_| {}), rig.c(edm_err(6)));
        // Errors: static Reset → Cxx1 first, Reset edge → 8810; Cxx1 → Cxx0 on Reset FALSE.
        for n in 1..=9 {
            let mut rig = r(edm_err(n));
            assert_eq!(rig.at(10_000, |_| {}), rig.c(edm_err(n)), "no time limit");
            assert_eq!(rig.step(|i| i.reset = true), rig.c(DISABLE), "C0{n}0");
            let mut rig = r(edm_err_static(n));
            assert_eq!(rig.step(|_| {}), rig.c(edm_err_static(n)));
            assert_eq!(rig.step(|i| i.reset = false), rig.c(edm_err(n)));
            assert_eq!(rig.step(|i| i.reset = true), rig.c(DISABLE));
        }
    }
}

/// T#0: the first evaluation of 8810 / 8000 after the entry checks the feedback.
#[test]
fn a_zero_monitoring_time_allows_no_delay() {
    let mut rig = Rig::new(0, 0);
    rig.go_disable();
    assert_eq!(rig.step(|i| i.control = true), 0x8000);
    assert_eq!(rig.at(0, |_| {}), 0xC090, "same ms, first evaluation");
    let mut rig = Rig::new(0, 0);
    rig.go_disable();
    rig.step(|i| i.control = true);
    assert_eq!(
        rig.at(0, |i| (i.edm1, i.edm2) = (false, false)),
        0x8000,
        "switched in time"
    );
    assert_eq!(rig.step(|i| i.control = false), 0x8810);
    assert_eq!(rig.step(|_| {}), 0xC060);
}

#[test]
fn every_code_outputs_and_activate_false_from_every_state() {
    for p in profiles() {
        for s in all().into_iter().filter(|s| *s != IDLE) {
            for reset in [false, true] {
                let mut rig = Rig::new(p, 100);
                rig.reach(s);
                let code = rig.c(s);
                assert_eq!(rig.fb.DiagCode, code);
                assert_eq!(rig.fb.S_EDM_Out, u8::from(s == ENABLE));
                assert_eq!(rig.fb.Ready, 1);
                assert_eq!(rig.fb.Error, u8::from(s.0 >= 0xC000));
                assert_eq!(rig.fb.SafetyDemand, u8::from(s.0 & 0x0800 != 0));
                assert_eq!(
                    rig.fb.ResetRequest,
                    u8::from(s.0 & 0x0400 != 0 && rig.fb.Reset == 0)
                );
                rig.step(|i| (i.activate, i.reset, i.control) = (false, reset, true));
                assert_eq!(rig.fb.DiagCode, 0, "{s:X?}");
                assert_eq!(
                    (
                        rig.fb.Ready,
                        rig.fb.S_EDM_Out,
                        rig.fb.SafetyDemand,
                        rig.fb.ResetRequest,
                        rig.fb.Error
                    ),
                    (0, 0, 0, 0, 0)
                );
            }
        }
    }
}

#[test]
fn start_up_with_and_without_s_start_reset() {
    let mut rig = Rig::new(0, 100);
    assert_eq!(rig.step(|_| {}), 0x8401);
    assert_eq!((rig.fb.ResetRequest, rig.fb.SafetyDemand), (1, 0));
    assert_eq!(rig.at(5_000, |_| {}), 0x8401, "waits for Reset");
    assert_eq!(rig.step(|i| i.reset = true), 0x8810);
    assert_eq!(rig.fb.SafetyDemand, 1);
    let mut rig = Rig::new(1, 100);
    rig.i.start_reset = true;
    rig.i.control = true;
    assert_eq!(rig.step(|_| {}), 0x8001, "one transition per call");
    assert_eq!(rig.step(|_| {}), 0x8010);
    assert_eq!(rig.step(|_| {}), 0x8000);
}

/// An invalid feedback byte is neither released nor switched; an invalid S_OutControl reads
/// FALSE (switch-off).
#[test]
fn invalid_bytes() {
    // (case, the way to the state, the bytes written, ms to the call, DiagCode and S_EDM_Out after)
    type Case = (&'static str, fn(&mut Rig), fn(&mut SF_EDM), u32, (u16, u8));
    let cases: [Case; 3] = [
        (
            "EDM1 invalid: not released",
            Rig::go_disable,
            |fb| (fb.EDM1, fb.S_OutControl) = (0x55, 1),
            1,
            (0xC010, 0),
        ),
        (
            "EDM2 invalid: not switched",
            Rig::go_enable,
            |fb| fb.EDM2 = 0x80,
            100,
            (0xC080, 0),
        ),
        (
            "S_OutControl invalid: reads FALSE",
            Rig::go_enable,
            |fb| fb.S_OutControl = 9,
            1,
            (0x8810, 0),
        ),
    ];
    let mut rig = Rig::new(0, 100);
    for (case, reach, write, dt, after) in cases {
        rig = Rig::new(0, 100);
        reach(&mut rig);
        write(&mut rig.fb);
        rig.now += dt;
        assert_eq!(rig.fb.cycle(rig.now), SL_E_INVALID_BOOL, "{case}");
        assert_eq!((rig.fb.DiagCode, rig.fb.S_EDM_Out), after, "{case}");
    }
    // MonitoringTime is a constant.
    rig.fb.MonitoringTime = 101;
    rig.now += 1;
    assert_eq!(rig.fb.cycle(rig.now), SL_E_PARAM_CHANGED);
    assert_eq!(rig.fb.DiagCode, SL_SF_DIAG_CONST_CHANGED);
}

#[test]
fn texts_for_every_diag_code() {
    let text = |code: u16| diag_text(SL_TYPE_SF_EDM, code);
    let mut seen = BTreeSet::new();
    for (v2, v1) in all() {
        for c in [v2, v1] {
            let t = text(c);
            assert!(t != "unknown DiagCode", "{c:04X}");
            seen.insert(t);
        }
    }
    assert_eq!(seen.len(), all().len(), "one text per state");
    assert_eq!(text(0xC0A0), "unknown DiagCode");
}

/// SF_EDM behind an SF_EmergencyStop in a group: S_EStopOut linked to S_OutControl, the
/// EDM's output to an FB_AND; an EDM error does not stop the group.
#[test]
fn in_a_group_behind_an_emergency_stop() {
    let mut es = RawBox::new(SF_EmergencyStop {
        Activate: 1,
        S_EStopIn: 1,
        S_StartReset: 1,
        ..Default::default()
    });
    let mut edm = RawBox::new(SF_EDM {
        Activate: 1,
        EDM1: 1,
        EDM2: 1,
        S_StartReset: 1,
        MonitoringTime: 50,
        ..Default::default()
    });
    let and = and_following_in1();
    let mut grp = CGroup::new(3, 2);
    grp.add_estop(&es);
    grp.add_init(SL_TYPE_SF_EDM, &edm, safelogic::ffi::sl_sf_edm_init);
    grp.add_init(SL_TYPE_AND, &and, safelogic::ffi::sl_and_init);
    let es_out = field(SL_TYPE_SF_EMERGENCYSTOP, "S_EStopOut");
    grp.link(0, es_out, 1, field(SL_TYPE_SF_EDM, "S_OutControl"));
    grp.link(
        1,
        field(SL_TYPE_SF_EDM, "S_EDM_Out"),
        2,
        field(SL_TYPE_AND, "bAndIn1"),
    );

    grp.g.bRun = 1;
    for k in 0..4 {
        assert_eq!(grp.cycle(10), SL_OK, "group call {k}");
    }
    assert_eq!((edm.DiagCode, and.bAndOut), (0x8000, 1));
    edm.EDM1 = 0;
    edm.EDM2 = 0;
    for _ in 0..10 {
        grp.cycle(10);
    }
    assert_eq!(edm.DiagCode, 0x8000, "switched in time");
    // The E-stop pressed: the EDM switches off in the next group call (link order);
    // contactor 1 welded: C040 after 50 ms; the group runs on.
    es.S_EStopIn = 0;
    grp.cycle(10);
    assert_eq!((edm.DiagCode, and.bAndOut), (0x8810, 0));
    edm.EDM2 = 1;
    for _ in 0..5 {
        grp.cycle(10);
    }
    assert_eq!((edm.DiagCode, edm.Error), (0xC040, 1));
    assert_eq!(grp.g.nState, SL_STATE_RUN);
}

/// The model, written from research §4.10 (v2.01 column) with NPE's split and the codes of
/// semantics QD2: R_TRIGs of Reset and S_OutControl in every call; the monitoring time
/// from the entry into 8810 / 8000.
#[derive(Default)]
struct Model {
    state: u16,
    since: u32,
    reset: bool,
    control: bool,
}

impl Model {
    fn step(&mut self, i: In, now: u32, t: u32) -> u16 {
        let (rt_reset, static_reset) = edges(&mut self.reset, i.reset);
        let (rt_control, _) = edges(&mut self.control, i.control);
        let q = now.wrapping_sub(self.since) >= t;
        // Which loops are wrong: 1 EDM1, 2 EDM2, 3 both.
        let open = u16::from(!i.edm1) | (u16::from(!i.edm2) << 1);
        let closed = u16::from(i.edm1) | (u16::from(i.edm2) << 1);
        let next = if !i.activate {
            0
        } else {
            match self.state {
                0x0000 => 0x8401,
                0x8401 if i.start_reset => 0x8810,
                0x8401 if static_reset => 0xC001,
                0x8401 if rt_reset && rt_control => 0xC100,
                0x8401 if rt_reset => 0x8810,
                0xC001 if !i.reset => 0x8401,
                0x8810 if i.control && open != 0 => 0xC000 + 0x10 * open,
                0x8810 if q && open != 0 => 0xC030 + 0x10 * open,
                0x8810 if i.control => 0x8000,
                0x8000 if !i.control => 0x8810,
                0x8000 if q && closed != 0 => 0xC060 + 0x10 * closed,
                0xC100 if rt_reset && !rt_control => 0x8810,
                s @ 0xC010..=0xC090 if s & 0xF == 0 && static_reset => s + 1,
                s @ 0xC010..=0xC090 if s & 0xF == 0 && rt_reset => 0x8810,
                s @ 0xC011..=0xC091 if s & 0xF == 1 && !i.reset => s - 1,
                s => s,
            }
        };
        common::plcopen::enter(&mut self.state, &mut self.since, next, now)
    }
}

#[test]
fn random_sequences_agree_with_the_model() {
    let walk = Walk::new("SF_EDM", 0x5FED_0001, all().iter().map(|s| s.0));
    walk.run(
        |p, _, rng| {
            let t = [0, 10, 30, 60][(rng.next() % 4) as usize];
            let mut rig = Rig::new(p, t);
            rig.i.start_reset = rng.next() % 4 == 0;
            (t, rig, Model::default())
        },
        |(t, rig, model), p, rng| {
            let r = rng.next();
            let dt = ((r >> 40) % 25) as u32;
            let code = rig.at(dt, |i| {
                i.activate ^= r % 31 == 0;
                i.control ^= (r >> 8) % 4 == 0;
                // The contactors mostly follow the output.
                if (r >> 16) % 3 == 0 {
                    i.edm1 = !i.control;
                } else if (r >> 16) % 7 == 1 {
                    i.edm1 = !i.edm1;
                }
                if (r >> 24) % 3 == 0 {
                    i.edm2 = !i.control;
                } else if (r >> 24) % 7 == 1 {
                    i.edm2 = !i.edm2;
                }
                i.reset ^= (r >> 32) % 4 == 0;
            });
            let want2 = model.step(rig.i, rig.now, *t);
            let want = all()
                .into_iter()
                .find(|s| s.0 == want2)
                .map(|s| rig.c(s))
                .unwrap();
            assert_eq!(code, want, "profile {p} t {t}");
            assert_eq!(rig.fb.S_EDM_Out == 1, want2 == 0x8000);
            want2
        },
    );
}
