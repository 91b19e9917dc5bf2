//! SF_TestableSafetySensor (PLCopen TC5 Part 1; research `plcopen_safety.md` §4.15, §5,
//! §8.4): every transition in first-match order, both test phases with TestTime at its
//! limit (T − 1 ms no error, T ms error; T#0 at the first evaluation), the manual test after
//! a failed automatic test (NoExternalTest FALSE) or none (TRUE), static-reset errors, every
//! DiagCode in both profiles with the block's own outputs, Activate FALSE from every state,
//! start-up with and without S_StartReset, ERR_PARAM (TestTime > 150 ms), texts, the block
//! in a group, and 10,000 random sequences per profile against an independent model.
//! Expected codes: research §4.15 (CS-LIB FBS_TESTSEN, ABB) and semantics QT2/QT3.

mod common;
use common::cgroup::*;
use common::plcopen::*;
use common::*;
use safelogic::*;
use std::collections::BTreeSet;

codes! {
    IDLE = 0x0000 / 0x0000, INIT = 0x8401 / 0x8001, INT1 = 0x8802 / 0x8011,
    WAIT1 = 0x8402 / 0x8012, FREE_NO_TEST = 0x8010 / 0x8010, TEST_REQ = 0x8020 / 0x8020,
    TEST_ACT = 0x8030 / 0x8030, OK = 0x8000 / 0x8000, INT2 = 0x8806 / 0x8014,
    WAIT2 = 0x8406 / 0x8015, EXT = 0x8002 / 0x8021, EXT_INT = 0x8804 / 0x8022,
    EXT_END = 0x8404 / 0x8023, ERR_PARAM = 0xC000 / 0xC000, ERR_RESET_1 = 0xC001 / 0xC001,
    ERR_TEST_1 = 0xC010 / 0xC010, ERR_TEST_2 = 0xC020 / 0xC020, ERR_RESET_2 = 0xC011 / 0xC011,
    ERR_RESET_3 = 0xC021 / 0xC021, ERR_RESET_4 = 0xC031 / 0xC031,
}

#[derive(Clone, Copy, Debug, Default)]
struct In {
    activate: bool,
    ossd: bool,
    start_test: bool,
    start_reset: bool,
    auto_reset: bool,
    reset: bool,
}

struct Rig {
    fb: SF_TestableSafetySensor,
    now: u32,
    profile: u8,
    i: In,
}

impl Rig {
    fn new(profile: u8, t: u32, no_ext: bool) -> Self {
        let fb = common::ready(SF_TestableSafetySensor {
            nDiagProfile: profile,
            TestTime: t,
            NoExternalTest: no_ext.into(),
            ..Default::default()
        });
        Self {
            fb,
            now: 30_000,
            profile,
            i: In {
                activate: true,
                ossd: true,
                ..In::default()
            },
        }
    }
    fn c(&self, s: Code) -> u16 {
        code(self.profile, s)
    }
    fn at(&mut self, dt: u32, f: impl FnOnce(&mut In)) -> u16 {
        f(&mut self.i);
        let i = self.i;
        let fb = &mut self.fb;
        (
            fb.Activate,
            fb.S_OSSD_In,
            fb.StartTest,
            fb.S_StartReset,
            fb.S_AutoReset,
            fb.Reset,
        ) = (
            i.activate.into(),
            i.ossd.into(),
            i.start_test.into(),
            i.start_reset.into(),
            i.auto_reset.into(),
            i.reset.into(),
        );
        self.now = self.now.wrapping_add(dt);
        assert_eq!(self.fb.cycle(self.now), SL_OK);
        self.check();
        self.fb.DiagCode
    }
    fn step(&mut self, f: impl FnOnce(&mut In)) -> u16 {
        self.at(1, f)
    }
    /// The outputs of the v2.01 state, from research §4.15 (ABB's table, PLCN).
    fn check(&self) {
        let fb = &self.fb;
        let s = ALL
            .iter()
            .find(|s| self.c(**s) == fb.DiagCode)
            .expect("a code of the block")
            .0;
        assert_eq!(fb.Ready, u8::from(s != 0));
        assert_eq!(
            fb.S_OSSD_Out,
            u8::from([0x8000, 0x8010, 0x8020, 0x8030].contains(&s)),
            "{s:04X}"
        );
        assert_eq!(fb.S_TestOut, u8::from(s != 0x8020), "{s:04X}");
        assert_eq!(fb.TestPossible, u8::from(s == 0x8000 || s == 0x8010));
        assert_eq!(fb.TestExecuted, u8::from(s == 0x8000));
        assert_eq!(fb.SafetyDemand, u8::from(s & 0x0800 != 0));
        assert_eq!(fb.ResetRequest, u8::from(s & 0x0400 != 0 && fb.Reset == 0));
        assert_eq!(fb.Error, u8::from(s >= 0xC000));
    }
    /// A rising edge of StartTest (released in the next call).
    fn start_test(&mut self) -> u16 {
        self.step(|i| i.start_test = false);
        self.step(|i| i.start_test = true)
    }
    /// Reset pulse: returns the code after the rising edge.
    fn reset(&mut self) -> u16 {
        let c = self.step(|i| i.reset = true);
        self.step(|i| i.reset = false);
        c
    }
    /// The path to `s` (TestTime ≥ 10).
    fn reach(&mut self, s: Code) {
        let c = |r: &Self, s| r.c(s);
        match s {
            INIT => assert_eq!(self.step(|_| {}), c(self, INIT)),
            ERR_RESET_1 => {
                self.step(|i| i.reset = true);
                assert_eq!(self.step(|_| {}), c(self, ERR_RESET_1));
            }
            INT1 => {
                self.step(|_| {});
                assert_eq!(self.step(|i| i.ossd = false), c(self, INT1));
            }
            WAIT1 => {
                self.reach(INT1);
                assert_eq!(self.step(|i| i.ossd = true), c(self, WAIT1));
            }
            ERR_RESET_2 => {
                self.reach(INT1);
                self.step(|i| i.reset = true);
                assert_eq!(self.step(|i| i.ossd = true), c(self, WAIT1));
                assert_eq!(self.step(|_| {}), c(self, ERR_RESET_2));
            }
            FREE_NO_TEST => {
                self.step(|_| {});
                assert_eq!(self.reset(), c(self, FREE_NO_TEST));
            }
            TEST_REQ => {
                self.reach(FREE_NO_TEST);
                assert_eq!(self.start_test(), c(self, TEST_REQ));
            }
            TEST_ACT => {
                self.reach(TEST_REQ);
                assert_eq!(self.step(|i| i.ossd = false), c(self, TEST_ACT));
            }
            OK => {
                self.reach(TEST_ACT);
                assert_eq!(self.step(|i| i.ossd = true), c(self, OK));
            }
            INT2 => {
                self.reach(OK);
                assert_eq!(self.step(|i| i.ossd = false), c(self, INT2));
            }
            WAIT2 => {
                self.reach(INT2);
                assert_eq!(self.step(|i| i.ossd = true), c(self, WAIT2));
            }
            ERR_RESET_3 => {
                self.reach(INT2);
                self.step(|i| i.reset = true);
                assert_eq!(self.step(|i| i.ossd = true), c(self, WAIT2));
                assert_eq!(self.step(|_| {}), c(self, ERR_RESET_3));
            }
            ERR_TEST_1 => {
                self.reach(TEST_REQ);
                assert_eq!(self.at(1_000, |_| {}), c(self, ERR_TEST_1));
            }
            ERR_TEST_2 => {
                self.reach(TEST_ACT);
                assert_eq!(self.at(1_000, |_| {}), c(self, ERR_TEST_2));
            }
            EXT => {
                self.reach(ERR_TEST_2);
                self.step(|i| i.ossd = true);
                assert_eq!(self.reset(), c(self, EXT));
            }
            EXT_INT => {
                self.reach(EXT);
                assert_eq!(self.step(|i| i.ossd = false), c(self, EXT_INT));
            }
            EXT_END => {
                self.reach(EXT_INT);
                assert_eq!(self.step(|i| i.ossd = true), c(self, EXT_END));
            }
            ERR_RESET_4 => {
                self.reach(EXT_INT);
                self.step(|i| i.reset = true);
                assert_eq!(self.step(|i| i.ossd = true), c(self, EXT_END));
                assert_eq!(self.step(|_| {}), c(self, ERR_RESET_4));
            }
            other => panic!("{other:X?}"),
        }
    }
}

#[test]
fn every_transition_in_first_match_order() {
    for p in profiles() {
        let r = |s: Code| {
            let mut rig = Rig::new(p, 100, false);
            rig.reach(s);
            rig
        };
        // 8401: OSSD FALSE first (even with S_StartReset), then S_StartReset, then static
        // Reset, then the Reset edge.
        let mut rig = r(INIT);
        assert_eq!(rig.at(5_000, |_| {}), rig.c(INIT));
        assert_eq!(
            rig.step(|i| (i.ossd, i.start_reset) = (false, true)),
            rig.c(INT1)
        );
        let mut rig = Rig::new(p, 100, false);
        rig.step(|i| (i.reset, i.start_reset) = (true, true));
        assert_eq!(
            rig.step(|_| {}),
            rig.c(FREE_NO_TEST),
            "S_StartReset before static Reset"
        );
        let mut rig = r(ERR_RESET_1);
        assert_eq!(rig.step(|i| i.ossd = false), rig.c(ERR_RESET_1));
        assert_eq!(rig.step(|i| i.reset = false), rig.c(INIT));
        // 8802: S_AutoReset → 8010, else → 8402.
        let mut rig = r(INT1);
        assert_eq!(rig.step(|i| i.reset = true), rig.c(INT1));
        assert_eq!(
            rig.step(|i| (i.ossd, i.auto_reset) = (true, true)),
            rig.c(FREE_NO_TEST)
        );
        // 8402: static Reset first, then OSSD FALSE, then the Reset edge.
        let mut rig = r(WAIT1);
        rig.step(|i| i.reset = true);
        assert_eq!(rig.c(FREE_NO_TEST), rig.fb.DiagCode);
        let mut rig = r(ERR_RESET_2);
        assert_eq!(
            rig.step(|i| i.ossd = false),
            rig.c(ERR_RESET_2),
            "held first"
        );
        assert_eq!(rig.step(|i| i.reset = false), rig.c(WAIT1));
        assert_eq!(rig.step(|_| {}), rig.c(INT1));
        // 8010: OSSD FALSE before StartTest; StartTest edge → 8020; a held StartTest is no edge.
        let mut rig = r(FREE_NO_TEST);
        rig.step(|i| i.start_test = false);
        assert_eq!(
            rig.step(|i| (i.ossd, i.start_test) = (false, true)),
            rig.c(INT1)
        );
        let mut rig = r(FREE_NO_TEST);
        rig.step(|i| i.start_test = true);
        assert_eq!(rig.fb.DiagCode, rig.c(TEST_REQ));
        let mut rig = r(INT1);
        rig.step(|i| i.start_test = true);
        rig.step(|i| (i.ossd, i.auto_reset) = (true, true));
        assert_eq!(
            rig.at(1_000, |_| {}),
            rig.c(FREE_NO_TEST),
            "StartTest held since 8802"
        );
        // 8020: TestTime first (even with the OSSD FALSE), then the OSSD FALSE.
        let mut rig = r(TEST_REQ);
        assert_eq!(rig.at(99, |_| {}), rig.c(TEST_REQ));
        assert_eq!(rig.at(1, |i| i.ossd = false), rig.c(ERR_TEST_1), "100 ms");
        let mut rig = r(TEST_REQ);
        assert_eq!(rig.at(99, |i| i.ossd = false), rig.c(TEST_ACT));
        // 8030: TestTime first, then the OSSD TRUE.
        assert_eq!(rig.at(99, |_| {}), rig.c(TEST_ACT));
        assert_eq!(rig.at(1, |i| i.ossd = true), rig.c(ERR_TEST_2), "100 ms");
        let mut rig = r(TEST_ACT);
        assert_eq!(rig.at(99, |i| i.ossd = true), rig.c(OK));
        // 8000: OSSD FALSE before StartTest; StartTest → 8020 (a new test).
        let mut rig = r(OK);
        rig.step(|i| i.start_test = false);
        assert_eq!(
            rig.step(|i| (i.ossd, i.start_test) = (false, true)),
            rig.c(INT2)
        );
        let mut rig = r(OK);
        assert_eq!(rig.start_test(), rig.c(TEST_REQ));
        // 8806: S_AutoReset → 8000, else → 8406; 8406 as 8402, back to 8000.
        let mut rig = r(INT2);
        assert_eq!(
            rig.step(|i| (i.ossd, i.auto_reset) = (true, true)),
            rig.c(OK)
        );
        let mut rig = r(WAIT2);
        assert_eq!(rig.step(|i| i.ossd = false), rig.c(INT2));
        assert_eq!(rig.step(|i| i.ossd = true), rig.c(WAIT2));
        assert_eq!(rig.reset(), rig.c(OK));
        let mut rig = r(ERR_RESET_3);
        assert_eq!(rig.step(|i| i.reset = false), rig.c(WAIT2));
        // Test errors: left by a Reset edge with the OSSD TRUE only; NoExternalTest FALSE →
        // the manual test 8002 → 8804 → 8404 → Reset → 8010.
        for e in [ERR_TEST_1, ERR_TEST_2] {
            let mut rig = r(e);
            assert_eq!(
                rig.step(|i| (i.ossd, i.reset) = (false, true)),
                rig.c(e),
                "OSSD FALSE"
            );
            rig.step(|i| i.reset = false);
            assert_eq!(rig.at(10_000, |i| i.ossd = true), rig.c(e), "no Reset");
            assert_eq!(rig.start_test(), rig.c(e));
            assert_eq!(rig.reset(), rig.c(EXT));
            assert_eq!(rig.reset(), rig.c(EXT), "only the sensor leaves 8002");
            assert_eq!(rig.step(|i| i.ossd = false), rig.c(EXT_INT));
            assert_eq!(rig.step(|i| i.ossd = true), rig.c(EXT_END));
            assert_eq!(rig.step(|i| i.ossd = false), rig.c(EXT_INT));
            assert_eq!(rig.step(|i| i.ossd = true), rig.c(EXT_END));
            assert_eq!(rig.reset(), rig.c(FREE_NO_TEST));
            let mut rig = Rig::new(p, 100, true);
            rig.reach(e);
            rig.step(|i| i.ossd = true);
            assert_eq!(rig.reset(), rig.c(FREE_NO_TEST), "NoExternalTest");
        }
        let mut rig = r(ERR_RESET_4);
        assert_eq!(rig.step(|i| i.ossd = false), rig.c(ERR_RESET_4));
        assert_eq!(rig.step(|i| i.reset = false), rig.c(EXT_END));
        assert_eq!(rig.step(|_| {}), rig.c(EXT_INT));
    }
}

/// T#0: each test phase fails at its first evaluation unless the sensor switched in the
/// call that entered it (research §8.13, semantics QT6).
#[test]
fn a_zero_test_time() {
    let mut rig = Rig::new(0, 0, false);
    rig.reach(FREE_NO_TEST);
    assert_eq!(rig.start_test(), 0x8020);
    assert_eq!(rig.at(0, |i| i.ossd = false), 0xC010, "same ms");
}

#[test]
fn every_code_and_activate_false_from_every_state() {
    for p in profiles() {
        for s in ALL.into_iter().filter(|s| *s != IDLE && *s != ERR_PARAM) {
            let mut rig = Rig::new(p, 100, false);
            rig.reach(s);
            assert_eq!(rig.fb.DiagCode, rig.c(s));
            assert_eq!(rig.step(|i| i.activate = false), 0, "{s:X?}");
            assert_eq!(
                (
                    rig.fb.S_OSSD_Out,
                    rig.fb.S_TestOut,
                    rig.fb.Ready,
                    rig.fb.Error
                ),
                (0, 1, 0, 0),
                "idle: S_TestOut TRUE"
            );
        }
        // C000: TestTime above 150 ms, in the activating call; 150 ms is valid.
        let mut fb = SF_TestableSafetySensor {
            Activate: 1,
            S_OSSD_In: 1,
            nDiagProfile: p,
            TestTime: 151,
            ..Default::default()
        };
        assert_eq!(fb.cycle(0), SL_OK);
        assert_eq!((fb.DiagCode, fb.Error, fb.S_TestOut), (0xC000, 1, 1));
        fb.Reset = 1;
        fb.cycle(1);
        fb.Reset = 0;
        assert_eq!(fb.cycle(2), SL_OK);
        assert_eq!(fb.DiagCode, 0xC000, "only Activate FALSE leaves it");
        fb.Activate = 0;
        fb.cycle(3);
        fb.TestTime = 150;
        fb.Activate = 1;
        fb.cycle(4);
        assert_eq!(fb.DiagCode, if p == 0 { 0x8401 } else { 0x8001 });
    }
}

#[test]
fn start_up_with_and_without_s_start_reset() {
    let mut rig = Rig::new(0, 10, false);
    assert_eq!(rig.step(|_| {}), 0x8401);
    assert_eq!(rig.fb.ResetRequest, 1);
    assert_eq!(rig.at(1_000, |_| {}), 0x8401);
    assert_eq!(rig.reset(), 0x8010);
    let mut rig = Rig::new(1, 10, false);
    rig.i.start_reset = true;
    assert_eq!(rig.step(|_| {}), 0x8001, "one transition per call");
    assert_eq!(rig.step(|_| {}), 0x8010);
    assert_eq!(rig.fb.S_OSSD_Out, 1);
}

/// NoExternalTest and TestTime are constants; an invalid S_OSSD_In byte is a demand, an
/// invalid StartTest no test; library faults switch S_TestOut FALSE too.
#[test]
fn constants_invalid_bytes_and_library_faults() {
    let mut rig = Rig::new(0, 100, false);
    rig.reach(FREE_NO_TEST);
    rig.fb.NoExternalTest = 1;
    rig.now += 1;
    assert_eq!(rig.fb.cycle(rig.now), SL_E_PARAM_CHANGED);
    assert_eq!(
        (rig.fb.DiagCode, rig.fb.S_OSSD_Out, rig.fb.S_TestOut),
        (SL_SF_DIAG_CONST_CHANGED, 0, 0)
    );
    let mut rig = Rig::new(0, 100, false);
    rig.reach(OK);
    rig.fb.StartTest = 5;
    rig.now += 1;
    assert_eq!(rig.fb.cycle(rig.now), SL_E_INVALID_BOOL);
    assert_eq!(rig.fb.DiagCode, 0x8000, "no test");
    rig.fb.StartTest = 0;
    rig.fb.S_OSSD_In = 7;
    rig.now += 1;
    assert_eq!(rig.fb.cycle(rig.now), SL_E_INVALID_BOOL);
    assert_eq!((rig.fb.DiagCode, rig.fb.S_OSSD_Out), (0x8806, 0));
    rig.fb.stPrivate.stHeader.wDiag ^= 0x40;
    rig.now += 1;
    assert_eq!(rig.fb.cycle(rig.now), SL_E_CORRUPT);
    assert_eq!(
        (rig.fb.DiagCode, rig.fb.S_TestOut, rig.fb.S_OSSD_Out),
        (SL_SF_DIAG_CORRUPT, 0, 0)
    );
}

#[test]
fn texts_for_every_diag_code() {
    let text = |code: u16| diag_text(SL_TYPE_SF_TESTABLESAFETYSENSOR, code);
    let mut seen = BTreeSet::new();
    for (v2, v1) in ALL {
        assert_eq!(text(v2), text(v1), "one text per state in both profiles");
        seen.insert(text(v2));
    }
    assert_eq!(seen.len(), ALL.len());
    assert!(!seen.contains("unknown DiagCode"));
}

/// In a group: S_OSSD_Out linked to an FB_AND; a failed test does not stop the group.
#[test]
fn in_a_group_with_a_link() {
    let mut w = WithAnd::of(
        SF_TestableSafetySensor {
            Activate: 1,
            S_OSSD_In: 1,
            S_StartReset: 1,
            TestTime: 50,
            ..Default::default()
        },
        "S_OSSD_Out",
    );
    w.run(3);
    w.expect(0x8010, 1);
    // A test the sensor answers: 8020, 8030 with the output TRUE throughout, 8000.
    w.fb.StartTest = 1;
    w.grp.cycle(10);
    assert_eq!(
        (w.fb.DiagCode, w.fb.S_TestOut, w.and.bAndOut),
        (0x8020, 0, 1)
    );
    w.fb.S_OSSD_In = 0;
    w.grp.cycle(10);
    assert_eq!(
        (w.fb.DiagCode, w.fb.S_TestOut, w.and.bAndOut),
        (0x8030, 1, 1)
    );
    w.fb.S_OSSD_In = 1;
    w.grp.cycle(10);
    assert_eq!((w.fb.DiagCode, w.fb.TestExecuted), (0x8000, 1));
    // A test the sensor does not answer: C010 after 50 ms; the group runs on.
    w.fb.StartTest = 0;
    w.grp.cycle(10);
    w.fb.StartTest = 1;
    for _ in 0..6 {
        w.grp.cycle(10);
    }
    w.expect(0xC010, 0);
    assert_eq!(w.grp.g.nState, SL_STATE_RUN);
}

/// The model, written from research §4.15 with semantics QT1–QT9 (v2.01 codes): R_TRIGs of
/// Reset and StartTest in every call; TestTime from the entry into 8020 / 8030.
#[derive(Default)]
struct Model {
    state: u16,
    since: u32,
    reset: bool,
    test: bool,
}

impl Model {
    fn step(&mut self, i: In, now: u32, t: u32, no_ext: bool) -> u16 {
        let (rt, held) = edges(&mut self.reset, i.reset);
        let (st, _) = edges(&mut self.test, i.start_test);
        let q = now.wrapping_sub(self.since) >= t;
        let o = i.ossd;
        let next = if !i.activate {
            0
        } else {
            match self.state {
                0x0000 if t > 150 => 0xC000,
                0x0000 => 0x8401,
                0x8401 if !o => 0x8802,
                0x8401 if i.start_reset => 0x8010,
                0x8401 if held => 0xC001,
                0x8401 if rt => 0x8010,
                0xC001 if !i.reset => 0x8401,
                0x8802 if o && i.auto_reset => 0x8010,
                0x8802 if o => 0x8402,
                0x8402 if held => 0xC011,
                0x8402 if !o => 0x8802,
                0x8402 if rt => 0x8010,
                0xC011 if !i.reset => 0x8402,
                0x8010 if !o => 0x8802,
                0x8000 if !o => 0x8806,
                0x8010 | 0x8000 if st => 0x8020,
                0x8020 if q => 0xC010,
                0x8020 if !o => 0x8030,
                0x8030 if q => 0xC020,
                0x8030 if o => 0x8000,
                0x8806 if o && i.auto_reset => 0x8000,
                0x8806 if o => 0x8406,
                0x8406 if held => 0xC021,
                0x8406 if !o => 0x8806,
                0x8406 if rt => 0x8000,
                0xC021 if !i.reset => 0x8406,
                0xC010 | 0xC020 if o && rt && no_ext => 0x8010,
                0xC010 | 0xC020 if o && rt => 0x8002,
                0x8002 if !o => 0x8804,
                0x8804 if o => 0x8404,
                0x8404 if held => 0xC031,
                0x8404 if !o => 0x8804,
                0x8404 if rt => 0x8010,
                0xC031 if !i.reset => 0x8404,
                s => s,
            }
        };
        common::plcopen::enter(&mut self.state, &mut self.since, next, now)
    }
}

#[test]
fn random_sequences_agree_with_the_model() {
    let walk = Walk {
        calls: 48,
        ..Walk::new(
            "SF_TestableSafetySensor",
            0x5F75_5E50,
            ALL.iter().map(|s| s.0),
        )
    };
    walk.run(
        |p, _, rng| {
            let t = [0, 20, 60, 150, 151][(rng.next() % 5) as usize];
            let no_ext = rng.next() % 2 == 0;
            let mut rig = Rig::new(p, t, no_ext);
            rig.i.start_reset = rng.next() % 4 == 0;
            rig.i.auto_reset = rng.next() % 4 == 0;
            (t, no_ext, rig, Model::default())
        },
        |(t, no_ext, rig, model), p, rng| {
            let r = rng.next();
            let dt = ((r >> 40) % 30) as u32;
            let code = rig.at(dt, |i| {
                i.activate ^= r % 41 == 0;
                // The sensor: mostly follows its test input, sometimes interrupted.
                i.ossd = if (r >> 8) % 3 == 0 { !i.ossd } else { i.ossd };
                i.start_test ^= (r >> 16) % 4 == 0;
                i.reset ^= (r >> 24) % 4 == 0;
            });
            let want2 = model.step(rig.i, rig.now, *t, *no_ext);
            let want = ALL
                .iter()
                .find(|s| s.0 == want2)
                .map(|s| rig.c(*s))
                .unwrap();
            assert_eq!(code, want, "profile {p} t {t} no_ext {no_ext}");
            want2
        },
    );
}
