//! SF_Guard (v1.0: SF_GuardMonitoring; PLCopen TC5 Part 1, research `plcopen_safety.md`
//! §4.4, §5): every transition of §4.4's table in first-match order, every DiagCode in both
//! profiles, the discrepancy time at its limit (T − 1 ms no error, T ms error, T#0 at the
//! first evaluation, across the clock wrap), the static-reset error, Activate FALSE from
//! every state, start-up with and without S_StartReset, the constants, the texts, a group
//! with a link, and 10,000 random sequences per profile against an independent model with
//! every state reached. Expected codes are the research table's, never read back.

mod common;
use common::cgroup::*;
use common::plcopen::*;
use common::*;
use safelogic::base::member::Member;
use safelogic::*;
use std::collections::BTreeSet;

// (v2.01, v1.0) codes of §4.4's DiagCode table.
codes! {
    IDLE = 0x0000 / 0x0000, INIT = 0x8001 / 0x8001, NORMAL = 0x8000 / 0x8000,
    OPEN_START = 0x8802 / 0x8002, OPENED = 0x8804 / 0x8012, WAIT_S2 = 0x8806 / 0x8004,
    WAIT_S1 = 0x8808 / 0x8014, CLOSED = 0x8002 / 0x8005, WAIT_RESET = 0x8402 / 0x8003,
    ERR_RESET = 0xC001 / 0xC001, ERR_DISC_1 = 0xC010 / 0xC011, ERR_DISC_2 = 0xC020 / 0xC012,
}

/// One call's inputs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct In {
    activate: bool,
    s1: bool,
    s2: bool,
    start_reset: bool,
    auto_reset: bool,
    reset: bool,
}

const ON: In = In {
    activate: true,
    s1: false,
    s2: false,
    start_reset: false,
    auto_reset: false,
    reset: false,
};

/// The independent model: §4.4's table with the v1.0 codes, written from the research
/// text (guards top to bottom, first match), R_TRIG on Reset in every call, Activate first,
/// the discrepancy timer started on the entry into 8004 / 8014.
#[derive(Default)]
struct Model {
    state: u16,
    reset_prev: bool,
    since: u32,
}

impl Model {
    fn step(&mut self, i: In, now: u32, t: u32) -> u16 {
        let (rt, static_reset) = edges(&mut self.reset_prev, i.reset);
        let q = now.wrapping_sub(self.since) >= t;
        let (s1, s2) = (i.s1, i.s2);
        let next = if !i.activate {
            0x0000
        } else {
            match self.state {
                0x0000 => 0x8001,
                0x8001 if !s1 || !s2 => 0x8002,
                0x8001 if !i.start_reset => 0x8003,
                0x8001 => 0x8000,
                0x8002 if !s1 && !s2 => 0x8012,
                0x8012 if s1 => 0x8004,
                0x8012 if s2 => 0x8014,
                0x8004 if q => 0xC011,
                0x8004 if !s1 => 0x8002,
                0x8004 if s2 => 0x8005,
                0x8014 if q => 0xC012,
                0x8014 if !s2 => 0x8002,
                0x8014 if s1 => 0x8005,
                0x8005 if !s1 || !s2 => 0x8002,
                0x8005 if !i.auto_reset => 0x8003,
                0x8005 => 0x8000,
                0x8003 if static_reset => 0xC001,
                0x8003 if !s1 || !s2 => 0x8002,
                0x8003 if rt => 0x8000,
                0xC001 if !i.reset => 0x8003,
                0xC011 | 0xC012 if !s1 && !s2 => 0x8012,
                0x8000 if !s1 || !s2 => 0x8002,
                s => s,
            }
        };
        common::plcopen::enter(&mut self.state, &mut self.since, next, now)
    }
}

/// A driven instance.
struct Rig {
    fb: SF_Guard,
    now: u32,
    profile: u8,
}

impl Rig {
    fn new(profile: u8, t: u32) -> Self {
        let mut fb = SF_Guard {
            nDiagProfile: profile,
            DiscrepancyTime: t,
            ..Default::default()
        };
        // SAFETY: a live, exclusively borrowed instance.
        assert_eq!(unsafe { safelogic::ffi::sl_sf_guard_init(&mut fb) }, SL_OK);
        Self {
            fb,
            now: 7_000,
            profile,
        }
    }
    fn apply(&mut self, i: In) {
        self.fb.Activate = i.activate.into();
        self.fb.S_GuardSwitch1 = i.s1.into();
        self.fb.S_GuardSwitch2 = i.s2.into();
        self.fb.S_StartReset = i.start_reset.into();
        self.fb.S_AutoReset = i.auto_reset.into();
        self.fb.Reset = i.reset.into();
    }
    /// One call `dt` ms after the previous one.
    fn at(&mut self, dt: u32, i: In) -> u16 {
        self.apply(i);
        self.now = self.now.wrapping_add(dt);
        // SAFETY: as above.
        let rc = unsafe { safelogic::ffi::sl_sf_guard_cycle(&mut self.fb, self.now) };
        assert_eq!(rc, SL_OK);
        self.fb.DiagCode
    }
    fn step(&mut self, i: In) -> u16 {
        self.at(1, i)
    }
    fn c(&self, s: Code) -> u16 {
        code(self.profile, s)
    }
    fn outputs(&self) -> [u8; 5] {
        let f = &self.fb;
        [
            f.Ready,
            f.S_GuardOut,
            f.SafetyDemand,
            f.ResetRequest,
            f.Error,
        ]
    }
    /// IDLE → `target` by the table's paths (DiscrepancyTime ≥ 10 ms); the codes on the
    /// way are checked. Returns the inputs of the last call.
    fn reach(&mut self, target: (u16, u16)) -> In {
        let mut i = ON;
        assert_eq!(self.step(i), self.c(INIT));
        if target == INIT {
            return i;
        }
        let closed = In {
            s1: true,
            s2: true,
            ..i
        };
        match target {
            NORMAL => {
                i = In {
                    start_reset: true,
                    ..closed
                };
                assert_eq!(self.step(i), self.c(NORMAL));
                return i;
            }
            WAIT_RESET | ERR_RESET => {
                i = closed;
                if target == ERR_RESET {
                    i.reset = true;
                }
                assert_eq!(self.step(i), self.c(WAIT_RESET));
                if target == ERR_RESET {
                    assert_eq!(self.step(i), self.c(ERR_RESET));
                }
                return i;
            }
            _ => {}
        }
        assert_eq!(self.step(i), self.c(OPEN_START));
        if target == OPEN_START {
            return i;
        }
        assert_eq!(self.step(i), self.c(OPENED));
        match target {
            OPENED => i,
            WAIT_S2 | ERR_DISC_1 | CLOSED => {
                i.s1 = true;
                assert_eq!(self.step(i), self.c(WAIT_S2));
                if target == ERR_DISC_1 {
                    assert_eq!(self.at(1_000_000, i), self.c(ERR_DISC_1));
                }
                if target == CLOSED {
                    i.s2 = true;
                    assert_eq!(self.step(i), self.c(CLOSED));
                }
                i
            }
            WAIT_S1 | ERR_DISC_2 => {
                i.s2 = true;
                assert_eq!(self.step(i), self.c(WAIT_S1));
                if target == ERR_DISC_2 {
                    assert_eq!(self.at(1_000_000, i), self.c(ERR_DISC_2));
                }
                i
            }
            other => panic!("no path to {other:X?}"),
        }
    }
}

/// Every row of §4.4's table in both profiles, with the earlier guards of a row made to
/// match too where they can (first match wins).
#[test]
fn every_transition_in_first_match_order() {
    for p in profiles() {
        let r = |t| {
            let mut rig = Rig::new(p, 100);
            let i = rig.reach(t);
            (rig, i)
        };
        // 0000 --Activate--> 8001 only.
        let mut rig = Rig::new(p, 100);
        let closed = In {
            s1: true,
            s2: true,
            start_reset: true,
            ..ON
        };
        assert_eq!(
            rig.step(In {
                activate: false,
                ..closed
            }),
            0
        );
        assert_eq!(rig.step(closed), rig.c(INIT));
        // 8001: a switch open → 8802 (even with S_StartReset); closed without / with
        // S_StartReset → 8402 / 8000.
        for (s1, s2) in [(true, false), (false, true), (false, false)] {
            let (mut rig, i) = r(INIT);
            let i = In {
                s1,
                s2,
                start_reset: true,
                ..i
            };
            assert_eq!(rig.step(i), rig.c(OPEN_START));
        }
        let (mut rig, i) = r(INIT);
        assert_eq!(
            rig.step(In {
                s1: true,
                s2: true,
                ..i
            }),
            rig.c(WAIT_RESET)
        );
        // 8802: only both open leaves it (a switch closing again, Reset edges change nothing).
        let (mut rig, mut i) = r(OPEN_START);
        i.s1 = true;
        i.reset = true;
        assert_eq!(rig.step(i), rig.c(OPEN_START));
        i.s2 = true;
        assert_eq!(rig.step(i), rig.c(OPEN_START), "not closed without opening");
        i.s1 = false;
        assert_eq!(rig.step(i), rig.c(OPEN_START));
        i.s2 = false;
        assert_eq!(rig.step(i), rig.c(OPENED));
        // 8804: S1 first (both closing in one call go to 8806), then S2.
        let (mut rig, mut i) = r(OPENED);
        assert_eq!(rig.at(1_000_000, i), rig.c(OPENED), "no time limit open");
        i.s1 = true;
        i.s2 = true;
        assert_eq!(rig.step(i), rig.c(WAIT_S2), "S1 before S2");
        assert_eq!(rig.step(i), rig.c(CLOSED));
        let (mut rig, mut i) = r(OPENED);
        i.s2 = true;
        assert_eq!(rig.step(i), rig.c(WAIT_S1));
        // 8806: the timer first (T ms since the entry), then NOT S1, then S2.
        for (s1, s2) in [(true, false), (false, false), (true, true)] {
            let (mut rig, i) = r(WAIT_S2);
            assert_eq!(rig.at(100, In { s1, s2, ..i }), rig.c(ERR_DISC_1));
        }
        let (mut rig, i) = r(WAIT_S2);
        assert_eq!(rig.at(99, i), rig.c(WAIT_S2), "99 ms < 100 ms");
        assert_eq!(rig.at(1, i), rig.c(ERR_DISC_1), "100 ms");
        let (mut rig, i) = r(WAIT_S2);
        assert_eq!(
            rig.at(
                99,
                In {
                    s1: false,
                    s2: true,
                    ..i
                }
            ),
            rig.c(OPEN_START),
            "NOT S1 before S2"
        );
        let (mut rig, i) = r(WAIT_S2);
        assert_eq!(rig.at(99, In { s2: true, ..i }), rig.c(CLOSED));
        // 8808 symmetric.
        for (s1, s2) in [(false, true), (false, false), (true, true)] {
            let (mut rig, i) = r(WAIT_S1);
            assert_eq!(rig.at(100, In { s1, s2, ..i }), rig.c(ERR_DISC_2));
        }
        let (mut rig, i) = r(WAIT_S1);
        assert_eq!(rig.at(99, i), rig.c(WAIT_S1));
        assert_eq!(rig.at(1, i), rig.c(ERR_DISC_2));
        let (mut rig, i) = r(WAIT_S1);
        assert_eq!(
            rig.at(
                50,
                In {
                    s1: true,
                    s2: false,
                    ..i
                }
            ),
            rig.c(OPEN_START),
            "NOT S2 before S1"
        );
        let (mut rig, i) = r(WAIT_S1);
        assert_eq!(rig.at(99, In { s1: true, ..i }), rig.c(CLOSED));
        // 8002 (guard closed): a switch open first (even with S_AutoReset), then
        // NOT S_AutoReset → 8402, S_AutoReset → 8000.
        for (s1, s2) in [(true, false), (false, true)] {
            let (mut rig, i) = r(CLOSED);
            let i = In {
                s1,
                s2,
                auto_reset: true,
                ..i
            };
            assert_eq!(rig.step(i), rig.c(OPEN_START));
        }
        let (mut rig, i) = r(CLOSED);
        assert_eq!(rig.step(i), rig.c(WAIT_RESET));
        let (mut rig, i) = r(CLOSED);
        assert_eq!(
            rig.step(In {
                auto_reset: true,
                ..i
            }),
            rig.c(NORMAL)
        );
        // 8402: static Reset first (before a switch open), then a switch open, then RT(Reset).
        #[rustfmt::skip]
        let cases: &[Case<In>] = &[
            (WAIT_RESET, &[
                (|i| (i.s1, i.reset) = (false, true), OPEN_START, "a switch open before RT(Reset)"),
            ]),
            (OPENED, &[
                (|i| i.reset = true, OPENED, ""),
                (|i| (i.s1, i.s2) = (true, true), WAIT_S2, ""),
                (|_| {}, CLOSED, ""),
                (|_| {}, WAIT_RESET, ""),
                (|i| i.s2 = false, ERR_RESET, "static Reset first"),
            ]),
            (WAIT_RESET, &[
                (|i| i.auto_reset = true, WAIT_RESET, "S_AutoReset does not reset here"),
                (|i| i.reset = true, NORMAL, ""),
            ]),
            // C001: stays while Reset is TRUE (a switch opening changes nothing), then 8402.
            (ERR_RESET, &[
                (|i| i.s1 = false, ERR_RESET, ""),
                (|i| (i.s1, i.reset) = (true, false), WAIT_RESET, ""),
                (|i| i.reset = true, NORMAL, ""),
            ]),
        ];
        step_table(&format!("profile {p}"), cases, r, |rig, i, want| {
            (rig.step(i), rig.c(want))
        });
        // C010 / C020: left only with both switches open, to 8804 (no Reset needed).
        for e in [ERR_DISC_1, ERR_DISC_2] {
            let (mut rig, mut i) = r(e);
            for (s1, s2) in [(true, false), (false, true), (true, true)] {
                i.s1 = s1;
                i.s2 = s2;
                i.reset = !i.reset;
                assert_eq!(rig.at(1_000, i), rig.c(e));
                assert_eq!(rig.fb.S_GuardOut, 0);
            }
            i.s1 = false;
            i.s2 = false;
            assert_eq!(rig.step(i), rig.c(OPENED));
        }
        // 8000: a switch open → 8802 with the output FALSE in the same call.
        for (s1, s2) in [(true, false), (false, true)] {
            let (mut rig, mut i) = r(NORMAL);
            assert_eq!(rig.fb.S_GuardOut, 1);
            i.reset = true;
            i.start_reset = false;
            assert_eq!(rig.at(1_000_000, i), rig.c(NORMAL));
            i.s1 = s1;
            i.s2 = s2;
            assert_eq!(rig.step(i), rig.c(OPEN_START));
            assert_eq!(rig.fb.S_GuardOut, 0, "output FALSE in the same call");
        }
    }
}

/// DiscrepancyTime T#0: no discrepancy allowed, the error at the first evaluation of
/// 8806 / 8808 (semantics QG2) — both switches closing in one call pass through 8806, so a
/// guard with T#0 closes only through activation (S_StartReset or Reset).
#[test]
fn a_zero_discrepancy_time() {
    let mut rig = Rig::new(0, 0);
    let mut i = rig.reach(OPENED);
    i.s1 = true;
    i.s2 = true;
    assert_eq!(rig.step(i), 0x8806);
    assert_eq!(rig.at(0, i), 0xC010, "same ms, first evaluation");
    i.s1 = false;
    i.s2 = false;
    assert_eq!(rig.step(i), 0x8804);
    // The timer across the clock wrap.
    let mut rig = Rig::new(0, 100);
    rig.now = u32::MAX - 60;
    let mut i = rig.reach(OPENED);
    i.s2 = true;
    assert_eq!(rig.at(50, i), 0x8808);
    assert_eq!(rig.at(99, i), 0x8808);
    assert!(rig.now < 100, "wrapped: {}", rig.now);
    assert_eq!(rig.at(1, i), 0xC020);
}

/// Outputs of every state (research §3.2, §9.3), then Activate FALSE from it: DiagCode 0000
/// and every output FALSE; activating again starts at INIT.
#[test]
fn outputs_per_state_and_activate_false_from_every_state() {
    let expect = |s: (u16, u16)| -> [u8; 5] {
        match s {
            INIT | CLOSED => [1, 0, 0, 0, 0],
            NORMAL => [1, 1, 0, 0, 0],
            OPEN_START | OPENED | WAIT_S2 | WAIT_S1 => [1, 0, 1, 0, 0],
            WAIT_RESET => [1, 0, 0, 1, 0],
            ERR_RESET | ERR_DISC_1 | ERR_DISC_2 => [1, 0, 0, 0, 1],
            _ => [0; 5],
        }
    };
    for p in profiles() {
        for s in ALL.into_iter().filter(|s| *s != IDLE) {
            let mut rig = Rig::new(p, 100);
            let mut i = rig.reach(s);
            let mut want = expect(s);
            if i.reset {
                want[3] = 0;
            }
            assert_eq!(rig.outputs(), want, "{s:X?} profile {p}");
            assert_eq!(rig.fb.DiagCode, rig.c(s));
            i.activate = false;
            assert_eq!(rig.step(i), 0, "{s:X?}");
            assert_eq!(rig.outputs(), [0; 5]);
            i.activate = true;
            assert_eq!(rig.step(i), rig.c(INIT));
        }
    }
    // The GUARD_CLOSED state (8002) of a guard with S_AutoReset lasts one call.
    let mut rig = Rig::new(0, 100);
    rig.reach(CLOSED);
    assert_eq!(rig.fb.SafetyDemand, 0);
}

/// Start-up (research §3.1): without S_StartReset a closed guard waits for a Reset edge;
/// with it the output is TRUE in the second call; a Reset held through the activation is
/// the static-reset error; a guard open at start-up needs the complete opening first.
#[test]
fn start_up_with_and_without_s_start_reset() {
    let closed = In {
        s1: true,
        s2: true,
        ..ON
    };
    let mut rig = Rig::new(0, 100);
    assert_eq!(rig.step(closed), 0x8001);
    assert_eq!(rig.step(closed), 0x8402);
    assert_eq!(rig.fb.ResetRequest, 1);
    assert_eq!(rig.step(closed), 0x8402);
    assert_eq!(
        rig.step(In {
            reset: true,
            ..closed
        }),
        0x8000
    );
    assert_eq!(rig.fb.S_GuardOut, 1);

    let auto = In {
        start_reset: true,
        ..closed
    };
    let mut rig = Rig::new(0, 100);
    assert_eq!(rig.step(auto), 0x8001);
    assert_eq!(rig.fb.S_GuardOut, 0);
    assert_eq!(rig.step(auto), 0x8000);

    let held = In {
        reset: true,
        ..closed
    };
    let mut rig = Rig::new(1, 100);
    assert_eq!(
        rig.step(In {
            activate: false,
            ..held
        }),
        0
    );
    assert_eq!(rig.step(held), 0x8001);
    assert_eq!(rig.step(held), 0x8003);
    assert_eq!(rig.step(held), 0xC001);
    assert_eq!(rig.fb.Error, 1);
    assert_eq!(rig.step(closed), 0x8003);
    assert_eq!(rig.step(held), 0x8000);

    // One switch open at start-up, S_StartReset and S_AutoReset TRUE: the complete
    // opening, the closing in time, then the output.
    let mut i = In {
        s1: true,
        start_reset: true,
        auto_reset: true,
        ..ON
    };
    let mut rig = Rig::new(0, 100);
    assert_eq!(rig.step(i), 0x8001);
    assert_eq!(rig.step(i), 0x8802);
    i.s2 = true;
    assert_eq!(rig.step(i), 0x8802);
    i.s1 = false;
    i.s2 = false;
    assert_eq!(rig.step(i), 0x8804);
    i.s2 = true;
    assert_eq!(rig.step(i), 0x8808);
    i.s1 = true;
    assert_eq!(rig.at(10, i), 0x8002);
    assert_eq!(rig.step(i), 0x8000);
    assert_eq!(rig.fb.S_GuardOut, 1);
}

/// DiscrepancyTime and the profile are constants: latched at activation, a change while
/// activated is C3FD; a time above SL_SF_TIME_MAX or an unknown profile is C3FC.
#[test]
fn the_constants() {
    let mut fb = SF_Guard {
        DiscrepancyTime: 100,
        Activate: 1,
        ..Default::default()
    };
    assert_eq!(fb.cycle(0), SL_OK);
    fb.DiscrepancyTime = 200;
    assert_eq!(fb.cycle(1), SL_E_PARAM_CHANGED);
    assert_eq!(
        (fb.DiagCode, fb.Error, fb.S_GuardOut),
        (SL_SF_DIAG_CONST_CHANGED, 1, 0)
    );
    fb.Activate = 0;
    assert_eq!(fb.cycle(2), SL_OK);
    assert_eq!(fb.DiagCode, 0);
    fb.Activate = 1;
    assert_eq!(fb.cycle(3), SL_OK);
    assert_eq!(fb.cycle(4), SL_OK);
    assert_eq!(fb.DiagCode, 0x8802);
    fb.cycle(5);
    assert_eq!(fb.DiagCode, 0x8804);
    fb.S_GuardSwitch1 = 1;
    fb.cycle(6);
    assert_eq!(fb.cycle(205), SL_OK);
    assert_eq!(fb.DiagCode, 0x8806, "199 ms");
    assert_eq!(fb.cycle(206), SL_OK);
    assert_eq!(fb.DiagCode, 0xC010, "the new time, 200 ms");
    for (t, p) in [(SL_SF_TIME_MAX + 1, 0), (100, 2)] {
        let bad = common::refused(
            SF_Guard {
                DiscrepancyTime: t,
                nDiagProfile: p,
                Activate: 1,
                ..Default::default()
            },
            &[0],
        );
        assert_eq!((bad.DiagCode, bad.Ready), (SL_SF_DIAG_CONFIG, 1));
    }
    // An invalid switch byte reads FALSE (open): the output drops.
    let mut fb = SF_Guard {
        Activate: 1,
        S_GuardSwitch1: 1,
        S_GuardSwitch2: 1,
        S_StartReset: 1,
        ..Default::default()
    };
    fb.cycle(0);
    fb.cycle(1);
    assert_eq!(fb.DiagCode, 0x8000);
    fb.S_GuardSwitch2 = 0x80;
    assert_eq!(fb.cycle(2), SL_E_INVALID_BOOL);
    assert_eq!((fb.DiagCode, fb.S_GuardOut), (0x8802, 0));
}

/// sl_diag_text names every DiagCode of both profiles; a code both profiles use for
/// different states (8002: v1.0 OPEN_START, v2.01 GUARD_CLOSED) reads as the v2.01 state's
/// (semantics QG5).
#[test]
fn texts_for_every_diag_code() {
    let text = |code: u16| diag_text(SL_TYPE_SF_GUARD, code);
    let mut v2_texts = BTreeSet::new();
    for (v2, v1) in ALL {
        let t = text(v2);
        assert!(!t.is_empty() && t != "unknown DiagCode", "{v2:04X}");
        v2_texts.insert(t.clone());
        if !ALL.iter().any(|s| s.0 == v1) {
            assert_eq!(text(v1), t, "v1.0 {v1:04X}");
        }
    }
    assert_eq!(v2_texts.len(), ALL.len(), "one text per state");
    assert_eq!(text(0x8002), text(CLOSED.0));
    assert!(text(0x8806).contains("S_GuardSwitch2"));
    assert_eq!(text(0x8123), "unknown DiagCode");
    assert!(text(SL_SF_DIAG_CORRUPT).starts_with("library: "));
}

/// 10,000 random sequences of 40 calls per profile against the model: the same DiagCode
/// after every call, the outputs from it, and every state reached.
#[test]
fn random_sequences_agree_with_the_model() {
    let walk = Walk::new("SF_Guard", 0x5F17, ALL.iter().map(|s| s.1));
    walk.run(
        |p, _, rng| {
            let t = [0, 5, 20, 50][(rng.next() % 4) as usize];
            let rig = Rig::new(p, t);
            (t, rig, Model::default(), rates::<6>(rng), In::default())
        },
        |(t, rig, model, rates, i), p, rng| {
            let f = flips(rng, rates, &mut i.activate);
            i.s1 ^= f[1];
            i.s2 ^= f[2];
            i.start_reset ^= f[3];
            i.auto_reset ^= f[4];
            i.reset ^= f[5];
            let dt = (rng.next() % 12) as u32;
            let got = rig.at(dt, *i);
            let v1 = model.step(*i, rig.now, *t);
            let want = ALL.iter().find(|s| s.1 == v1).map(|s| rig.c(*s)).unwrap();
            assert_eq!(got, want, "profile {p} t {t}: {i:?}");
            let o = rig.outputs();
            assert_eq!(o[0] == 1, got != 0);
            assert_eq!(o[1] == 1, got == 0x8000);
            assert_eq!(o[4] == 1, got >= 0xC000);
            assert!(
                o[1] == 0 || (i.s1 && i.s2),
                "output TRUE with a switch open"
            );
            v1
        },
    );
}

/// SF_Guard as a group member: its output linked to an FB_AND; a discrepancy error does not
/// stop the group; group STOP halts it (DiagCode 0000).
#[test]
fn in_a_group_with_a_link() {
    let mut w = WithAnd::of(
        SF_Guard {
            DiscrepancyTime: 50,
            ..Default::default()
        },
        "S_GuardOut",
    );
    w.fb.Activate = 1;
    w.fb.S_GuardSwitch1 = 1;
    w.fb.S_GuardSwitch2 = 1;
    w.fb.S_StartReset = 1;
    w.run(3);
    w.expect(0x8000, 1);
    // Open both, close switch 1 only: C010 after 50 ms, the group runs on.
    w.fb.S_GuardSwitch1 = 0;
    w.fb.S_GuardSwitch2 = 0;
    w.grp.cycle(10);
    w.expect(0x8802, 0);
    w.grp.cycle(10);
    w.fb.S_GuardSwitch1 = 1;
    for _ in 0..7 {
        w.grp.cycle(10);
    }
    assert_eq!((w.fb.DiagCode, w.grp.g.nState), (0xC010, SL_STATE_RUN));
    assert_eq!(w.fb.state(), SL_STATE_RUN);
    w.stop_group();
    assert_eq!(w.and.bAndOut, 0);
}
