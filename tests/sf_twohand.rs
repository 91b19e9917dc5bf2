//! SF_TwoHandControlTypeII and SF_TwoHandControlTypeIII (PLCopen TC5 Part 1; research
//! `plcopen_safety.md` §4.6, §4.7, §5): every transition of §4.6's table in first-match
//! order for both blocks and both profiles, type III's synchronism time at its limit
//! (500 ms allowed, 501 ms an error, re-armed on every entry), the errors left only with both
//! buttons released, Activate FALSE from every state, start-up with a button held, texts, a
//! group with a link, and 10,000 random sequences per block and profile against an
//! independent model with every state reached. Expected codes are the research table's
//! (v1.0 column; v2.01 states column) and semantics QH1 for the v2.01 error codes.

mod common;
use common::cgroup::*;
use common::plcopen::*;
use common::*;
use safelogic::*;
use std::collections::BTreeSet;

const IDLE: (u16, u16) = (0x0000, 0x0000);
const INIT: (u16, u16) = (0x8001, 0x8001);
const ON: (u16, u16) = (0x8000, 0x8000);
const RELEASED: (u16, u16) = (0x8802, 0x8004);
const B1: (u16, u16) = (0x8804, 0x8005);
const B2: (u16, u16) = (0x8806, 0x8006);
const B2_RELEASED: (u16, u16) = (0x8808, 0x8007);
const B1_RELEASED: (u16, u16) = (0x880A, 0x8008);
const LOCKED_OFF: (u16, u16) = (0x880C, 0x8009);
const LOCKED_ON: (u16, u16) = (0x880E, 0x8019);
const E1: (u16, u16) = (0xC010, 0xC001);
const E2: (u16, u16) = (0xC020, 0xC002);
const E3: (u16, u16) = (0xC030, 0xC003);
const S1: (u16, u16) = (0xC040, 0xC004);
const S2: (u16, u16) = (0xC050, 0xC005);
const S3: (u16, u16) = (0xC060, 0xC006);
const TYPE_II: [(u16, u16); 13] = [
    IDLE,
    INIT,
    ON,
    RELEASED,
    B1,
    B2,
    B2_RELEASED,
    B1_RELEASED,
    LOCKED_OFF,
    LOCKED_ON,
    E1,
    E2,
    E3,
];
const SYNC: [(u16, u16); 3] = [S1, S2, S3];

const NONE: (bool, bool) = (false, false);
const ONLY1: (bool, bool) = (true, false);
const ONLY2: (bool, bool) = (false, true);
const BOTH: (bool, bool) = (true, true);

trait TwoHand: FunctionBlock + Default {
    const NAME: &'static str;
    const TAG: u16;
    const TYPE_III: bool;
    fn apply(&mut self, activate: bool, b: (bool, bool));
    fn out(&self) -> [u8; 4];
    fn code(&self) -> u16;
    fn set_profile(&mut self, p: u8);
    fn states() -> Vec<(u16, u16)> {
        let mut v = TYPE_II.to_vec();
        if Self::TYPE_III {
            v.extend(SYNC);
        }
        v
    }
}

macro_rules! two_hand {
    ($ty:ident, $tag:expr, $iii:expr) => {
        impl TwoHand for $ty {
            const NAME: &'static str = stringify!($ty);
            const TAG: u16 = $tag;
            const TYPE_III: bool = $iii;
            fn apply(&mut self, activate: bool, b: (bool, bool)) {
                (self.Activate, self.S_Button1, self.S_Button2) =
                    (activate.into(), b.0.into(), b.1.into());
            }
            fn out(&self) -> [u8; 4] {
                [self.Ready, self.S_TwoHandOut, self.SafetyDemand, self.Error]
            }
            fn code(&self) -> u16 {
                self.DiagCode
            }
            fn set_profile(&mut self, p: u8) {
                self.nDiagProfile = p;
            }
        }
    };
}
two_hand!(
    SF_TwoHandControlTypeII,
    SL_TYPE_SF_TWOHANDCONTROLTYPEII,
    false
);
two_hand!(
    SF_TwoHandControlTypeIII,
    SL_TYPE_SF_TWOHANDCONTROLTYPEIII,
    true
);

struct Rig<B: TwoHand> {
    fb: B,
    now: u32,
    profile: u8,
}

impl<B: TwoHand> Rig<B> {
    fn new(profile: u8) -> Self {
        let mut fb = B::default();
        fb.set_profile(profile);
        assert_eq!(fb.init(), SL_OK);
        Self {
            fb,
            now: 7_000,
            profile,
        }
    }
    fn at(&mut self, dt: u32, b: (bool, bool)) -> u16 {
        self.fb.apply(true, b);
        self.now = self.now.wrapping_add(dt);
        assert_eq!(self.fb.cycle(self.now), SL_OK, "{}", B::NAME);
        self.fb.code()
    }
    fn step(&mut self, b: (bool, bool)) -> u16 {
        self.at(10, b)
    }
    fn c(&self, s: Code) -> u16 {
        code(self.profile, s)
    }
    fn go(&mut self, dt: u32, b: (bool, bool), s: (u16, u16)) -> (bool, bool) {
        assert_eq!(self.at(dt, b), self.c(s), "{} towards {s:X?}", B::NAME);
        b
    }
    /// IDLE → `target` by the table's paths; returns the last buttons.
    fn reach(&mut self, target: (u16, u16)) -> (bool, bool) {
        let first = match target {
            E1 => ONLY1,
            E2 => ONLY2,
            E3 => BOTH,
            _ => NONE,
        };
        let mut last = self.go(10, first, INIT);
        match target {
            INIT => {}
            E1 | E2 | E3 => last = self.go(10, first, target),
            _ => {
                last = self.go(10, NONE, RELEASED);
                match target {
                    RELEASED => {}
                    B1 => last = self.go(10, ONLY1, B1),
                    B2 => last = self.go(10, ONLY2, B2),
                    ON => last = self.go(10, BOTH, ON),
                    B2_RELEASED | B1_RELEASED | LOCKED_OFF => {
                        self.go(10, BOTH, ON);
                        last = if target == B1_RELEASED {
                            self.go(10, ONLY2, B1_RELEASED)
                        } else {
                            self.go(10, ONLY1, B2_RELEASED)
                        };
                        if target == LOCKED_OFF {
                            last = self.go(10, BOTH, LOCKED_OFF);
                        }
                    }
                    LOCKED_ON => {
                        self.go(10, ONLY1, B1);
                        last = self.go(10, ONLY2, LOCKED_ON);
                    }
                    S1 => {
                        self.go(10, ONLY2, B2);
                        last = self.go(501, ONLY2, S1);
                    }
                    S2 => {
                        self.go(10, ONLY1, B1);
                        last = self.go(501, ONLY1, S2);
                    }
                    S3 => {
                        self.go(10, ONLY1, B1);
                        last = self.go(501, BOTH, S3);
                    }
                    other => panic!("{other:X?}"),
                }
            }
        }
        last
    }
}

fn t<B: TwoHand>(p: u8, from: (u16, u16), b: (bool, bool), to: (u16, u16)) {
    let mut rig = Rig::<B>::new(p);
    rig.reach(from);
    assert_eq!(
        rig.step(b),
        rig.c(to),
        "{} profile {p}: {from:X?} --{b:?}--> {to:X?}",
        B::NAME
    );
}

fn transitions<B: TwoHand>() {
    for p in profiles() {
        // (from, [to for NONE, ONLY1, ONLY2, BOTH]) — the table of §4.6, one row per state.
        let rows = [
            (INIT, [RELEASED, E1, E2, E3]),
            (RELEASED, [RELEASED, B1, B2, ON]),
            (B1, [RELEASED, B1, LOCKED_ON, ON]),
            (B2, [RELEASED, LOCKED_ON, B2, ON]),
            (ON, [RELEASED, B2_RELEASED, B1_RELEASED, ON]),
            (
                B2_RELEASED,
                [RELEASED, B2_RELEASED, B1_RELEASED, LOCKED_OFF],
            ),
            (
                B1_RELEASED,
                [RELEASED, B2_RELEASED, B1_RELEASED, LOCKED_OFF],
            ),
            (LOCKED_OFF, [RELEASED, B2_RELEASED, B1_RELEASED, LOCKED_OFF]),
            (LOCKED_ON, [RELEASED, LOCKED_ON, LOCKED_ON, LOCKED_ON]),
            (E1, [RELEASED, E1, E1, E1]),
            (E2, [RELEASED, E2, E2, E2]),
            (E3, [RELEASED, E3, E3, E3]),
        ];
        for (from, to) in rows {
            for (b, want) in [NONE, ONLY1, ONLY2, BOTH].into_iter().zip(to) {
                t::<B>(p, from, b, want);
            }
        }
        if B::TYPE_III {
            for s in SYNC {
                for b in [ONLY1, ONLY2, BOTH] {
                    t::<B>(p, s, b, s);
                }
                t::<B>(p, s, NONE, RELEASED);
            }
        }
    }
}

#[test]
fn every_transition_in_first_match_order() {
    transitions::<SF_TwoHandControlTypeII>();
    transitions::<SF_TwoHandControlTypeIII>();
}

/// Type III: 500 ms after the first button the second may still come (semantics QH3); at
/// 501 ms the synchronism error comes before every other guard of 8804 / 8806 (the error
/// names the late button, QH2); releasing both first is no error. Type II has no limit.
#[test]
fn the_synchronism_time_of_type_iii() {
    for p in profiles() {
        type T3 = SF_TwoHandControlTypeIII;
        for (first, second) in [(B1, ONLY1), (B2, ONLY2)] {
            let mut rig = Rig::<T3>::new(p);
            rig.reach(RELEASED);
            rig.go(10, second, first);
            assert_eq!(rig.at(500, BOTH), rig.c(ON), "500 ms is within");
            let mut rig = Rig::<T3>::new(p);
            rig.reach(RELEASED);
            rig.go(10, second, first);
            assert_eq!(rig.at(499, second), rig.c(first));
            assert_eq!(rig.at(2, BOTH), rig.c(S3), "501 ms: both too late");
            for (b, want) in [(ONLY1, S2), (ONLY2, S1), (NONE, RELEASED)] {
                let mut rig = Rig::<T3>::new(p);
                rig.reach(RELEASED);
                rig.go(10, second, first);
                assert_eq!(rig.at(501, b), rig.c(want), "{first:X?} {b:?}");
            }
        }
        // The timer is re-armed on every entry (PEER-ST's timer never is, research §4.7).
        let mut rig = Rig::<T3>::new(p);
        rig.reach(RELEASED);
        rig.go(10, ONLY1, B1);
        rig.go(400, NONE, RELEASED);
        rig.go(10, ONLY2, B2);
        assert_eq!(rig.at(450, BOTH), rig.c(ON));
        // The output enabled stays enabled: no time limit in 8000.
        assert_eq!(rig.at(100_000, BOTH), rig.c(ON));
        assert_eq!(rig.fb.S_TwoHandOut, 1);
        // Type II: no synchronism time.
        let mut rig = Rig::<SF_TwoHandControlTypeII>::new(p);
        rig.reach(B1);
        assert_eq!(rig.at(100_000, ONLY1), rig.c(B1));
        assert_eq!(rig.step(BOTH), rig.c(ON));
    }
}

/// The time runs across the wrap of the ms clock.
#[test]
fn the_synchronism_time_across_the_clock_wrap() {
    let mut rig = Rig::<SF_TwoHandControlTypeIII>::new(0);
    rig.now = u32::MAX - 100;
    rig.reach(B1);
    assert_eq!(rig.at(500, ONLY1), 0x8804);
    assert_eq!(rig.at(1, ONLY1), 0xC050);
}

fn outputs_and_idle<B: TwoHand>() {
    for p in profiles() {
        for s in B::states().into_iter().filter(|s| *s != IDLE) {
            let mut rig = Rig::<B>::new(p);
            let last = rig.reach(s);
            let o = rig.fb.out();
            let want = [
                1,
                u8::from(s == ON),
                u8::from(s.0 & 0x0800 != 0),
                u8::from(s.0 >= 0xC000),
            ];
            assert_eq!(o, want, "{} {s:X?}", B::NAME);
            rig.fb.apply(false, last);
            rig.now += 10;
            assert_eq!(rig.fb.cycle(rig.now), SL_OK);
            assert_eq!((rig.fb.code(), rig.fb.out()), (0, [0; 4]));
        }
    }
}

#[test]
fn outputs_per_state_and_activate_false_from_every_state() {
    outputs_and_idle::<SF_TwoHandControlTypeII>();
    outputs_and_idle::<SF_TwoHandControlTypeIII>();
}

/// Start-up: no S_StartReset (research §4.6: no Reset, no S_StartReset); a button held
/// through the activation is an error until both are released, then a fresh actuation.
#[test]
fn start_up_with_a_button_held() {
    let mut rig = Rig::<SF_TwoHandControlTypeII>::new(0);
    assert_eq!(rig.step(BOTH), 0x8001);
    assert_eq!(rig.step(BOTH), 0xC030);
    assert_eq!(rig.fb.S_TwoHandOut, 0);
    assert_eq!(rig.step(ONLY1), 0xC030);
    assert_eq!(rig.step(NONE), 0x8802);
    assert_eq!(rig.step(BOTH), 0x8000);
    // An invalid byte reads "not actuated" (SL_E_INVALID_BOOL): the output drops.
    rig.fb.S_Button2 = 2;
    assert_eq!(rig.fb.cycle(rig.now + 10), SL_E_INVALID_BOOL);
    assert_eq!((rig.fb.DiagCode, rig.fb.S_TwoHandOut), (0x8808, 0));
}

#[test]
fn texts_for_every_diag_code() {
    fn check<B: TwoHand>() {
        let text = |code: u16| diag_text(B::TAG, code);
        let states = B::states();
        let mut seen = BTreeSet::new();
        for (v2, v1) in &states {
            for c in [*v2, *v1] {
                let t = text(c);
                assert!(!t.is_empty() && t != "unknown DiagCode", "{c:04X}");
                seen.insert(t);
            }
        }
        assert_eq!(seen.len(), states.len(), "{}", B::NAME);
        let sync = text(0xC040);
        assert_eq!(sync == "unknown DiagCode", !B::TYPE_III, "{}", B::NAME);
    }
    check::<SF_TwoHandControlTypeII>();
    check::<SF_TwoHandControlTypeIII>();
}

/// Type II's private state never holds a type III code: C040 forged into it is corrupt.
#[test]
fn type_ii_has_no_synchronism_codes() {
    use safelogic::base::sf::SfInstance;
    let mut fb = SF_TwoHandControlTypeII::default();
    assert_eq!(fb.init(), SL_OK);
    let h = &mut fb.sf_private_mut().stHeader;
    h.wDiag = 0xC040;
    h.nState = SL_STATE_RUN;
    h.seal();
    fb.Activate = 1;
    assert_eq!(fb.cycle(0), SL_E_CORRUPT);
    assert_eq!(fb.DiagCode, SL_SF_DIAG_CORRUPT);
}

#[test]
fn in_a_group_with_a_link() {
    let mut w = WithAnd::of(SF_TwoHandControlTypeIII::default(), "S_TwoHandOut");
    w.fb.Activate = 1;
    w.run(3);
    assert_eq!(w.fb.DiagCode, 0x8802);
    w.fb.S_Button1 = 1;
    w.grp.cycle(10);
    w.fb.S_Button2 = 1;
    w.grp.cycle(10);
    w.expect(0x8000, 1);
    // Both released, then button 1 alone for 600 ms: the synchronism error, group runs.
    (w.fb.S_Button1, w.fb.S_Button2) = (0, 0);
    w.grp.cycle(10);
    w.fb.S_Button1 = 1;
    w.grp.cycle(10);
    w.grp.cycle(600);
    w.expect_group(0xC050, 0, SL_STATE_RUN);
    w.stop_group();
}

/// The model: §4.6's table with the v1.0 codes, written from the research text, plus §4.7's
/// 500 ms timer (TON started on the entry into 8005 / 8006, IN FALSE elsewhere; elapsed when
/// more than 500 ms have passed, QH3) and PEER-ST's C004/C005/C006 assignment.
#[derive(Default)]
struct Model {
    state: u16,
    since: u32,
}

impl Model {
    fn step(&mut self, activate: bool, b1: bool, b2: bool, now: u32, iii: bool) -> u16 {
        let q = iii && now.wrapping_sub(self.since) > 500;
        let next = if !activate {
            0
        } else {
            match self.state {
                0x0000 => 0x8001,
                0x8001 if b1 && b2 => 0xC003,
                0x8001 if b1 => 0xC001,
                0x8001 if b2 => 0xC002,
                0x8001 => 0x8004,
                0x8004 if b1 && b2 => 0x8000,
                0x8004 if b1 => 0x8005,
                0x8004 if b2 => 0x8006,
                0x8005 | 0x8006 if q && b1 && b2 => 0xC006,
                0x8005 | 0x8006 if q && b1 => 0xC005,
                0x8005 | 0x8006 if q && b2 => 0xC004,
                0x8005 if !b1 && !b2 => 0x8004,
                0x8005 if !b1 && b2 => 0x8019,
                0x8005 if b1 && b2 => 0x8000,
                0x8006 if !b1 && !b2 => 0x8004,
                0x8006 if b1 && !b2 => 0x8019,
                0x8006 if b1 && b2 => 0x8000,
                0x8000 if b1 && !b2 => 0x8007,
                0x8000 if !b1 && b2 => 0x8008,
                0x8000 if !b1 && !b2 => 0x8004,
                0x8007 if b1 && b2 => 0x8009,
                0x8007 if !b1 && b2 => 0x8008,
                0x8007 if !b1 && !b2 => 0x8004,
                0x8008 if b1 && b2 => 0x8009,
                0x8008 if b1 && !b2 => 0x8007,
                0x8008 if !b1 && !b2 => 0x8004,
                0x8009 if !b1 && b2 => 0x8008,
                0x8009 if b1 && !b2 => 0x8007,
                0x8009 if !b1 && !b2 => 0x8004,
                0x8019 | 0xC001..=0xC006 if !b1 && !b2 => 0x8004,
                s => s,
            }
        };
        common::plcopen::enter(&mut self.state, &mut self.since, next, now)
    }
}

fn against_the_model<B: TwoHand>(seed: u64) {
    let states = B::states();
    let walk = Walk::new(B::NAME, seed, states.iter().map(|s| s.1));
    walk.run(
        |p, _, rng| {
            let rig = Rig::<B>::new(p);
            let rate = 2 + rng.next() % 6;
            (rig, Model::default(), rate, true, false, false)
        },
        |(rig, model, rate, act, b1, b2), p, rng| {
            let r = rng.next();
            if r % 29 == 0 {
                *act = !*act;
            }
            *b1 ^= (r >> 8) % *rate == 0;
            *b2 ^= (r >> 16) % *rate == 0;
            let dt = if (r >> 24) % 5 == 0 {
                ((r >> 32) % 700) as u32
            } else {
                ((r >> 32) % 120) as u32
            };
            rig.fb.apply(*act, (*b1, *b2));
            rig.now = rig.now.wrapping_add(dt);
            assert_eq!(rig.fb.cycle(rig.now), SL_OK);
            let v1 = model.step(*act, *b1, *b2, rig.now, B::TYPE_III);
            let want = states.iter().find(|s| s.1 == v1).map(|s| rig.c(*s));
            assert_eq!(Some(rig.fb.code()), want, "{} profile {p}", B::NAME);
            let o = rig.fb.out();
            assert_eq!(o[1] == 1, v1 == 0x8000);
            assert!(
                o[1] == 0 || (*b1 && *b2),
                "output TRUE with a button released"
            );
            v1
        },
    );
}

#[test]
fn random_sequences_agree_with_the_model() {
    against_the_model::<SF_TwoHandControlTypeII>(0x5F24);
    against_the_model::<SF_TwoHandControlTypeIII>(0x5F25);
}
